// Copyright (c) 2026 Rigid_incidence contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The reduced polynomial system of a scene (optimized_incidence_tree_parametrization.txt,
// Section 4.1 Part 2; elimination_generically_rigid_3d.txt, Section 3): the equations left
// after the incidence tree's eliminations, as polynomials in the tree's parameters.

#ifndef CGAL_RIGID_INCIDENCE_REDUCED_SYSTEM_H
#define CGAL_RIGID_INCIDENCE_REDUCED_SYSTEM_H

#include <CGAL/Rigid_incidence/Input_error.h>
#include <CGAL/Rigid_incidence/Polynomial_system.h>
#include <CGAL/Rigid_incidence/Rigid_body_collection.h>
#include <CGAL/Rigid_incidence/incidence_tree_parametrization.h>
#include <CGAL/Rigid_incidence/optimal_incidence_tree.h>
#include <CGAL/Rigid_incidence/rigidity_matroid.h>
#include <CGAL/Rigid_incidence/well_formed_incidences.h>

#include <algorithm>
#include <array>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace CGAL {
namespace Rigid_incidence {

/// \ingroup PkgRigidIncidenceRef
/// One equation of a `Reduced_system`.
template <class NT>
struct Reduced_equation
{
  Constraint origin;                   ///< the incidence or distance it stands for
  std::string label;                   ///< the origin in words
  Sparse_polynomial<NT> polynomial;    ///< the numerator: polynomial = 0
  std::vector<std::size_t> variables;  ///< the variables it involves
  std::vector<unsigned> degrees;       ///< the degree in each of `variables`
  unsigned total_degree = 0;           ///< its total degree
  std::size_t frame = 0;               ///< the body whose frame it is written in (the lowest common ancestor)
  /// per tree edge, the degree of `polynomial` as a form in the edge's homogeneous rotation
  /// coordinates (a hinge's (a, b), a free rotation's q0..q3): twice the power of the edge's
  /// \f$D_e\f$ it was multiplied by, 0 for an edge it does not involve (what a change of chart
  /// needs, see `Reduced_system::changes_charts()`)
  std::vector<unsigned> rotation_degree;
};

/*!
\ingroup PkgRigidIncidenceRef
\brief `true` if body `b`, outside the covering set of `tree`, holds two points that the
covering set places (and no covering body holds both) at a distance it knows only through a
placement from distances: the reduced system's equation for that pair then depends on the
body's placement (`solve_scene()` enumerates them) and needs interval coefficients.
*/
template <class Traits>
bool holds_pair_through_placement(const Rigid_body_collection<Traits>& c, const Incidence_tree& tree, std::size_t b)
{
  const auto& body = c.body(b);
  if (body.all_coordinates()) return false;
  std::vector<bool> covered(c.number_of_points(), false);
  for (std::size_t x : tree.covering_set) for (std::size_t p : c.body(x).points) covered[p] = true;
  for (std::size_t i = 0; i < body.points.size(); ++i)
    for (std::size_t j = i + 1; j < body.points.size(); ++j) {
      if (!covered[body.points[i]] || !covered[body.points[j]]) continue;
      bool one = false;
      for (std::size_t x : tree.covering_set) one = one || (c.body(x).contains(body.points[i]) && c.body(x).contains(body.points[j]));
      if (!one && !body.squared(i, j)) return true;
    }
  return false;
}

/*!
\ingroup PkgRigidIncidenceRef
\brief `true` if the reduced system of `c` and `tree` can have exact rational coefficients
(`NT = CGAL::Gmpq`): every covering body has coordinates, and no body outside the covering
set holds a pair of covered points through a placement (`holds_pair_through_placement()`).
Otherwise use `CGAL::Interval_nt<false>` or `CGAL::Gmpfi`.
*/
template <class Traits>
bool exact_coefficients(const Rigid_body_collection<Traits>& c, const Incidence_tree& tree)
{
  for (std::size_t b : tree.covering_set) if (!c.body(b).all_coordinates()) return false;
  for (std::size_t b : tree.non_covering) if (holds_pair_through_placement(c, tree, b)) return false;
  return true;
}

/// \ingroup PkgRigidIncidenceRef
/// The constraints a reduced system keeps (`reduced_constraints()`).
struct Reduced_constraints
{
  Constraint_independence independence; ///< the rank test of the system's constraints
  std::vector<Constraint> equations;     ///< the ones written as equations, in order
  std::vector<Constraint> left_out;      ///< dependent ones in conflict (an over-constrained scene)
  std::vector<std::size_t> loose;        ///< bodies outside the covering set held by fewer than 3 covered points
};

/// \ingroup PkgRigidIncidenceRef
/// The constraints of `system_constraints()` the reduced system writes as equations: the
/// independent ones (`constraint_independence()`) but the incidences the tree eliminates; the
/// dependent ones in conflict (a body's own surplus distance is left out silently); and the
/// bodies outside the covering set that fewer than three covered points hold. Shared by
/// `Reduced_system` and `Tree_system`, so that both write the same equations.
template <class Traits>
Reduced_constraints reduced_constraints(const Rigid_body_collection<Traits>& c, const Incidence_tree& tree, const Well_formed_selection& selection)
{
  Reduced_constraints r;
  const std::vector<Constraint> ks = system_constraints(c, tree, selection);
  r.independence = constraint_independence(c, tree.covering_set, ks);
  for (std::size_t i = 0; i < ks.size(); ++i) {
    if (!r.independence.independent[i]) {
      if (!r.independence.follows_from_its_body(i)) r.left_out.push_back(ks[i]);
      continue;
    }
    if (ks[i].origin != Constraint::TREE_INCIDENCE) r.equations.push_back(ks[i]);
  }
  std::vector<bool> covered(c.number_of_points(), false);
  for (std::size_t b : tree.covering_set) for (std::size_t q : c.body(b).points) covered[q] = true;
  for (std::size_t b : tree.non_covering) {
    std::size_t n = 0;
    for (std::size_t q : c.body(b).points) n += covered[q];
    if (n < 3) r.loose.push_back(b);
  }
  return r;
}

/*!
\ingroup PkgRigidIncidenceRef
\brief The reduced system of a standard collection for an incidence tree, a chart per tree edge
and a placement per body known by distances.

Equations, in this order (each the numerator of a rational function whose denominator is a
product of the tree edges' D_e, which never vanish on the charts' boxes, so clearing them
neither adds nor loses a root in the box):
- every well-formed incidence marked REMAINING (coordinate p of the difference of the point's
  positions in its two bodies, written in the frame of their lowest common ancestor, so the
  variables above it do not appear);
- the distances that hold the bodies outside the covering set, chosen by the rank test of the
  rigidity matroid (`constraint_independence()`): a minimal set, each between two points of
  the covering set;
- the collection's remaining distances, unless dependent (in conflict).
A distance is written with `Incidence_tree_parametrization::squared_distance()`, through the
bodies (among those containing its points) that give the fewest variables, then the lowest
total degree.

The system is square for a well-constrained scene; `diagnostic()` says otherwise.

\tparam Traits a model of `RigidIncidenceTraits`
\tparam NT `CGAL::Gmpq` (exact; every body of the covering set must have coordinates),
`CGAL::Interval_nt<false>` or `CGAL::Gmpfi` (certified enclosures of the exact coefficients).
*/
template <class Traits, class NT>
class Reduced_system
{
public:
  typedef Incidence_tree_parametrization<Traits, NT> Parametrization; ///< the elimination
  typedef Sparse_polynomial<NT> Polynomial;                            ///< polynomial type

  /*!
  \param c a standard collection
  \param tree an incidence tree of `c`
  \param selection the well-formed incidences for `tree` (`select_well_formed_incidences()`)
  \param charts one chart index per tree edge (empty: chart 0 everywhere)
  \param form the rotation form
  \param placements per body, the placement variant of a body known by distances
  */
  Reduced_system(const Rigid_body_collection<Traits>& c, const Incidence_tree& tree, const Well_formed_selection& selection,
                 const std::vector<int>& charts = {}, Rotation_form form = Rotation_form::QUATERNION_CHARTS,
                 const std::vector<int>& placements = {})
    : c_(c), tree_(tree), p_(new Parametrization(c, tree, charts, form, placements)), placements_(placements)
  {
    internal::Rounding_guard<NT> guard;
    (void)guard;
    Reduced_constraints k = reduced_constraints(c, tree, selection);
    independence_ = std::move(k.independence);
    left_out_ = std::move(k.left_out);
    loose_ = std::move(k.loose);
    for (const Constraint& x : k.equations) equations_.push_back(make_equation(x));
    linearize_translations();
  }

  /*!
  The reduced system of the chart combination `charts` made from `base` (chart 0 on every
  edge, `base.changes_charts()`) by a change of chart of each equation, not a new reduction:
  an equation is a form in each edge's homogeneous rotation coordinates (degree
  `Reduced_equation::rotation_degree`), written with the chart's coordinate set to 1. For a
  hinge, \f$q = (L a, b u)\f$ with chart 0 at \f$a = 1, b = t\f$ and chart 1 at \f$a = s, b = 1\f$, a
  term \f$c\,t^i\f$ of degree \f$d\f$ becomes \f$c\,s^{d-i}\f$; for a free rotation, chart 0 at
  \f$q_0 = 1\f$ and chart \f$j\f$ at \f$q_j = 1\f$, a term \f$c\,q_1^{a_1} q_2^{a_2} q_3^{a_3}\f$ would get
  \f$q_0^{d - a_1 - a_2 - a_3}\f$ and lose \f$q_j\f$ (not done: see `changes_charts()`). The coefficients move, none is computed:
  the same equations as a direct build up to the choice between equivalent forms (a direct
  build multiplies the maps along the tree again: for a chain of ten tetrahedra, whose closing
  equation has 3^9 terms, 0.13 s a combination against 0.07 s, both mostly the sparse
  polynomial's map). The parametrization, for the configurations, is that of `charts`.
  \throws Input_error if `base` does not change charts, or an equation is not a form of its
  `rotation_degree` (an internal error).
  */
  Reduced_system(const Reduced_system& base, const std::vector<int>& charts)
    : c_(base.c_), tree_(base.tree_),
      p_(new Parametrization(base.c_, base.tree_, charts, Rotation_form::QUATERNION_CHARTS, base.placements_)),
      placements_(base.placements_), independence_(base.independence_), left_out_(base.left_out_), loose_(base.loose_)
  {
    if (!base.changes_charts()) throw Input_error("reduced system: a change of chart needs a system of chart 0 in quaternion charts, without translations");
    internal::Rounding_guard<NT> guard;
    (void)guard;
    for (const auto& e : base.equations_) equations_.push_back(change_chart(e));
  }

  /// `true` if the systems of the other chart combinations can be made from this one by a
  /// change of chart (the constructor above): quaternion charts, chart 0 on every edge, and
  /// every edge a hinge. (A free rotation, q0 = 1 to qj = 1, is the same homogenization, but
  /// the standardization leaves one only beside a translation in the scenes tried, whose
  /// equations `linearize_translations()` mixes: such systems are built directly.)
  bool changes_charts() const
  {
    if (p_->form() != Rotation_form::QUATERNION_CHARTS) return false;
    for (const auto& e : p_->edges())
      if (e.chart != 0 || !e.translation.empty() || e.rotation.size() != 1) return false;
    for (const auto& e : equations_)
      if (e.rotation_degree.size() != p_->edges().size()) return false;
    return true;
  }

  /// The collection.
  const Rigid_body_collection<Traits>& collection() const { return c_; }
  /// The incidence tree.
  const Incidence_tree& tree() const { return tree_; }
  /// The parametrization (the Table 1 maps along the tree).
  const Parametrization& parametrization() const { return *p_; }
  /// The equations.
  const std::vector<Reduced_equation<NT>>& equations() const { return equations_; }
  /// Number of variables.
  std::size_t number_of_variables() const { return p_->number_of_variables(); }
  /// Number of equations.
  std::size_t number_of_equations() const { return equations_.size(); }
  /// Dependent constraints left out because they conflict (`Constraint_independence::conflicts()`:
  /// an over-constrained scene); a body's surplus distances are left out silently.
  const std::vector<Constraint>& left_out() const { return left_out_; }
  /// The rigidity-matroid test behind the choice of equations.
  const Constraint_independence& independence() const { return independence_; }
  /// The number of chart combinations a full solve visits: the product over the tree edges of
  /// their chart counts (2 for a shared pair, 4 for a free rotation).
  std::size_t number_of_chart_combinations() const
  {
    std::size_t n = 1;
    for (const auto& e : p_->edges()) n *= std::size_t(e.number_of_charts);
    return n;
  }
  /// `true` if as many equations as variables, no constraint left out and every body outside
  /// the covering set held by three or more of its points.
  bool is_square() const { return number_of_equations() == number_of_variables() && left_out_.empty() && loose_.empty(); }
  /// The bodies outside the covering set that fewer than three covered points hold: they keep
  /// a rotation the reduced system does not see (an under-constrained scene).
  const std::vector<std::size_t>& loose_bodies() const { return loose_; }
  /// Empty for a square system, else what is wrong, in words.
  std::string diagnostic() const
  {
    std::string d;
    if (number_of_equations() < number_of_variables())
      d = std::to_string(number_of_variables() - number_of_equations()) + " equation(s) fewer than variables: the scene is"
          " under-constrained (generic dof " + std::to_string(independence_.generic_dof()) + "); its solutions are not isolated";
    else if (number_of_equations() > number_of_variables())
      d = "more equations than variables (internal error: the equations are independent)";
    if (!loose_.empty()) {
      d += std::string(d.empty() ? "" : "; ") + "bodies outside the covering set held by fewer than 3 points (free to turn):";
      for (std::size_t b : loose_) d += " '" + c_.body(b).name + "'";
    }
    if (!left_out_.empty())
      d += std::string(d.empty() ? "" : "; ") + std::to_string(left_out_.size()) +
           " dependent constraint(s) left out: the scene is over-constrained and has configurations only if their values agree";
    return d;
  }
  /*!
  The numerator of the orientation \f$\det(X_b - X_a, X_c - X_a, X_d - X_a)\f$ of four points
  (global indices, in this order) in the reduced system's world frame (the tree root's): every
  point of the covering set is a rational function whose denominator is a product of the tree
  edges' \f$D_e = |q|^2\f$, positive on every chart's box, so with the four brought to one
  denominator \f$D\f$ the determinant is this polynomial over \f$D^3 > 0\f$ and has its sign.
  A rotation keeps the sign, so it is the orientation in any body's frame.
  \throws Input_error if a point is not placed by the parameters (a point only of a body
  outside the covering set).
  */
  Polynomial orientation_numerator(const std::array<std::size_t, 4>& points) const
  {
    typedef typename Parametrization::Rational Rational;
    const std::size_t n = p_->number_of_variables();
    std::array<std::array<Rational, 3>, 4> X;
    for (std::size_t k = 0; k < 4; ++k) {
      const std::size_t q = points[k];
      std::vector<std::size_t> ca = carriers(q);
      if (!ca.empty()) X[k] = p_->position(ca.front(), q, tree_.root);
      else if (p_->free_point_variable(q) != Parametrization::npos) {
        for (std::size_t i = 0; i < 3; ++i) X[k][i] = Rational{Polynomial::variable(n, p_->free_point_variable(q) + i), {}};
      } else
        throw Input_error("inequality: point '" + c_.label(q) + "' is only on bodies outside the covering set: the parameters do not place it");
    }
    std::map<std::size_t, unsigned> den;  // per edge, the highest power among the 12 coordinates
    for (const auto& x : X)
      for (const auto& r : x)
        for (const auto& e : r.den) den[e.first] = (std::max)(den[e.first], e.second);
    std::array<std::array<Polynomial, 3>, 4> P;
    for (std::size_t k = 0; k < 4; ++k)
      for (std::size_t i = 0; i < 3; ++i) {
        const Rational& r = X[k][i];
        Polynomial f = r.num;
        for (const auto& e : den) {
          auto it = r.den.find(e.first);
          for (unsigned j = it == r.den.end() ? 0 : it->second; j < e.second; ++j) f = f * p_->denominator(e.first);
        }
        P[k][i] = f;
      }
    std::array<Polynomial, 3> U, V, W;
    for (std::size_t i = 0; i < 3; ++i) { U[i] = P[1][i] - P[0][i]; V[i] = P[2][i] - P[0][i]; W[i] = P[3][i] - P[0][i]; }
    return U[0] * (V[1] * W[2] - V[2] * W[1]) - U[1] * (V[0] * W[2] - V[2] * W[0]) + U[2] * (V[0] * W[1] - V[1] * W[0]);
  }

  /// The system as a general `Polynomial_system` (for the solver).
  Polynomial_system<NT> system() const
  {
    Polynomial_system<NT> s;
    s.variable_names = p_->variable_names();
    s.box = p_->box();
    for (const auto& e : equations_) { s.equations.push_back(e.polynomial); s.labels.push_back(e.label); }
    return s;
  }

private:
  NT to_nt(const typename Traits::FT& x) const
  {
    return internal::Coefficient_ops<NT>::from_rational(internal::exact_rational(x));
  }
  // the covering bodies containing point p (none for a free point)
  std::vector<std::size_t> carriers(std::size_t p) const
  {
    std::vector<std::size_t> r;
    for (std::size_t b : tree_.covering_set) if (c_.body(b).contains(p)) r.push_back(b);
    return r;
  }
  // den: the powers of the edges' D_e the polynomial was multiplied by (null: not known, as
  // after the linearization of a translation, which mixes equations; no change of chart then)
  Reduced_equation<NT> finish(const Constraint& k, Polynomial poly, std::size_t frame, const std::map<std::size_t, unsigned>* den) const
  {
    Reduced_equation<NT> e;
    e.origin = k;
    e.label = describe(c_, k);
    e.polynomial = std::move(poly);
    e.frame = frame;
    if (den) {
      e.rotation_degree.assign(p_->edges().size(), 0);
      for (const auto& d : *den) if (d.first < e.rotation_degree.size()) e.rotation_degree[d.first] = 2 * d.second;
    }
    set_support(e);
    return e;
  }
  static void set_support(Reduced_equation<NT>& e)
  {
    const std::vector<unsigned> d = e.polynomial.degrees();
    e.variables.clear();
    e.degrees.clear();
    for (std::size_t v = 0; v < d.size(); ++v)
      if (d[v] > 0) { e.variables.push_back(v); e.degrees.push_back(d[v]); }
    e.total_degree = e.polynomial.total_degree();
  }
  // equation `e` of chart 0 on every edge, in this system's charts (see the constructor)
  Reduced_equation<NT> change_chart(const Reduced_equation<NT>& e) const
  {
    Reduced_equation<NT> out;  // (not a copy of e: its polynomial can have 3^9 terms)
    out.origin = e.origin;
    out.label = e.label;
    out.frame = e.frame;
    out.rotation_degree = e.rotation_degree;
    Polynomial q(e.polynomial.number_of_variables());
    for (const auto& t : e.polynomial.terms()) {
      typename Polynomial::Exponent x = t.first;
      for (std::size_t k = 0; k < p_->edges().size(); ++k) {
        const auto& edge = p_->edges()[k];
        if (edge.chart == 0) continue;
        const auto& v = edge.rotation;  // (chart 0: the variables of b, or of q1, q2, q3)
        unsigned used = 0;
        for (std::size_t i : v) used += t.first[i];
        if (used > e.rotation_degree[k])
          throw Input_error("reduced system: equation '" + e.label + "' is not a form of degree " + std::to_string(e.rotation_degree[k]) +
                            " in the rotation of tree edge " + std::to_string(k) + " (internal error)");
        const unsigned rest = e.rotation_degree[k] - used;  // the exponent of a (hinge) or q0
        x[v[0]] = rest;  // a = s, b = 1 (changes_charts(): hinges only)
      }
      q.add_term(x, t.second);
    }
    out.polynomial = std::move(q);
    set_support(out);
    return out;
  }
  Reduced_equation<NT> make_equation(const Constraint& k) const
  {
    const std::size_t npos = Parametrization::npos;
    if (!k.is_distance()) {
      const Incidence& i = k.incidence;
      auto r = p_->incidence_difference(i.point, i.body_a, i.body_b, i.coordinate);
      return finish(k, std::move(r.num), p_->lowest_common_ancestor(i.body_a, i.body_b), &r.den);
    }
    NT d2;
    if (k.origin == Constraint::BODY_DISTANCE) {
      const auto& body = c_.body(k.body);
      auto sq = body.squared(body.local(k.a), body.local(k.b));
      if (sq) {
        d2 = to_nt(*sq);
      } else if constexpr (internal::Coefficient_ops<NT>::is_interval) {
        // a pair the body holds through a placement from distances (its distance is not known
        // exactly, and differs between placements): its distance in this system's placement
        const int v = k.body < placements_.size() ? placements_[k.body] : 0;
        Body_enclosure<NT> e = enclose_coordinates<NT>(c_, k.body, v);
        if (!e.consistent) throw Input_error("reduced system: body '" + body.name + "': placement " + std::to_string(v) + " admits no placement");
        const auto &A = e.coordinates[body.local(k.a)], &B = e.coordinates[body.local(k.b)];
        d2 = (A[0] - B[0]) * (A[0] - B[0]) + (A[1] - B[1]) * (A[1] - B[1]) + (A[2] - B[2]) * (A[2] - B[2]);
      } else {
        throw Input_error("reduced system: body '" + body.name + "' fixes the distance " + c_.label(k.a) + "-" + c_.label(k.b) +
                          " only through a placement from distances: use interval coefficients (see exact_coefficients())");
      }
    } else {
      d2 = to_nt(c_.distances()[k.distance].squared);
    }
    std::vector<std::size_t> ca = carriers(k.a), cb = carriers(k.b);
    if (ca.empty()) ca.push_back(npos);
    if (cb.empty()) cb.push_back(npos);
    bool have = false;
    Reduced_equation<NT> best;
    std::pair<std::size_t, unsigned> best_size;
    for (std::size_t a : ca)
      for (std::size_t b : cb) {
        auto r = p_->squared_distance_of_points(a, k.a, b, k.b);
        // |X_a - X_b|^2 - d^2 = (num - d^2 * den) / den
        Polynomial den = Polynomial::constant(p_->number_of_variables(), NT(1));
        for (const auto& x : r.den)
          for (unsigned j = 0; j < x.second; ++j) den = den * p_->denominator(x.first);
        Polynomial f = r.num - d2 * den;
        std::size_t frame = (a == npos || b == npos) ? tree_.root : p_->lowest_common_ancestor(a, b);
        Reduced_equation<NT> e = finish(k, f, frame, &r.den);
        const std::pair<std::size_t, unsigned> size = certain_size(e.polynomial);
        if (!have || size < best_size) {
          best = e;
          best_size = size;
          have = true;
        }
      }
    return best;
  }

  // The variables and the total degree of the terms whose coefficients are certainly not 0:
  // with interval coefficients, terms that cancel exactly stay as enclosures of 0, and choosing
  // the carriers of a distance by the whole support would choose other carriers than the exact
  // system does (another equation of the same solutions, not an enclosure of the exact one)
  static std::pair<std::size_t, unsigned> certain_size(const Polynomial& f)
  {
    std::vector<char> used(f.number_of_variables(), 0);
    unsigned total = 0;
    for (const auto& t : f.terms()) {
      if (internal::may_be_zero(t.second)) continue;
      unsigned d = 0;
      for (std::size_t v = 0; v < t.first.size(); ++v) {
        d += t.first[v];
        if (t.first[v] > 0) used[v] = 1;
      }
      total = (std::max)(total, d);
    }
    return {std::size_t(std::count(used.begin(), used.end(), char(1))), total};
  }

  // A translation T (edge sharing nothing) enters a distance from its child as
  // c(x) |T|^2 + (terms of degree <= 1 in T), with c = D_e (or 1 for the pivot's own
  // distance, a sphere k |T|^2 + ...). Subtracting c / k times the sphere leaves every other
  // such equation linear in T (as the legs of a Stewart-Gough platform are written after
  // subtracting the first leg): the same solutions, lower degree, and the solver's clipping
  // then cuts T down to what the rotation box allows.
  void linearize_translations()
  {
    typedef typename Polynomial::Exponent Exponent;
    for (const auto& edge : p_->edges()) {
      if (edge.translation.size() != 3) continue;
      const std::vector<std::size_t>& T = edge.translation;
      auto t_degree = [&](const Exponent& e) { return e[T[0]] + e[T[1]] + e[T[2]]; };
      auto square_of = [&](const Exponent& e) -> int { // the index i if the T-part of e is T_i^2
        for (int i = 0; i < 3; ++i) if (e[T[std::size_t(i)]] == 2) return i;
        return -1;
      };
      // the part of p multiplying T_i^2, as a polynomial in the other variables; false if p has
      // a term of degree > 2 in T, or a product T_i T_j
      auto split = [&](const Polynomial& p, std::array<Polynomial, 3>& sq) {
        for (auto& q : sq) q = Polynomial(p.number_of_variables());
        for (const auto& t : p.terms()) {
          const unsigned d = t_degree(t.first);
          if (d > 2) return false;
          if (d < 2) continue;
          const int i = square_of(t.first);
          // (a product T_i T_j: its coefficient cancels exactly where the translation enters
          // through a rotation, to an enclosure of 0 with interval coefficients, kept)
          if (i < 0 && internal::may_be_zero(t.second)) continue;
          if (i < 0) return false;
          Exponent e = t.first;
          e[T[std::size_t(i)]] = 0;
          sq[std::size_t(i)].add_term(e, t.second);
        }
        return true;
      };
      // the same coefficients (interval coefficients: the same bounds; the three squares come
      // from one computation, and soundness does not depend on it: p - mu S is a valid
      // replacement for any mu, this only decides whether it is worth it)
      // (interval coefficients: bounds that meet, a term of one absent from the other an
      // enclosure of 0, as the exact coefficients they enclose are equal; the exact system
      // then linearizes the same equations)
      auto same = [](const Polynomial& a, const Polynomial& b) {
        if constexpr (internal::Coefficient_ops<NT>::is_interval) {
          typename CGAL::Interval_traits<NT>::Lower lower;
          typename CGAL::Interval_traits<NT>::Upper upper;
          for (const auto& t : a.terms()) {
            auto j = b.terms().find(t.first);
            if (j == b.terms().end() ? !internal::may_be_zero(t.second) : (upper(t.second) < lower(j->second) || upper(j->second) < lower(t.second)))
              return false;
          }
          for (const auto& t : b.terms())
            if (!a.terms().count(t.first) && !internal::may_be_zero(t.second)) return false;
          return true;
        } else {
          if (a.terms().size() != b.terms().size()) return false;
          for (auto i = a.terms().begin(), j = b.terms().begin(); i != a.terms().end(); ++i, ++j)
            if (i->first != j->first || !same_bounds(i->second, j->second)) return false;
          return true;
        }
      };
      // the sphere: T only, k (T_x^2 + T_y^2 + T_z^2) + lower terms, k a number known exactly
      std::size_t sphere = equations_.size();
      NT k(0);
      for (std::size_t i = 0; i < equations_.size() && sphere == equations_.size(); ++i) {
        const Polynomial& p = equations_[i].polynomial;
        bool only_t = !p.is_zero();
        for (std::size_t v : equations_[i].variables) only_t = only_t && (v == T[0] || v == T[1] || v == T[2]);
        std::array<Polynomial, 3> sq;
        if (!only_t || !split(p, sq) || sq[0].terms().size() != 1 || !same(sq[0], sq[1]) || !same(sq[0], sq[2])) continue;
        k = sq[0].terms().begin()->second;
        if (internal::certainly_same(k, k) && !internal::certainly_zero(k)) sphere = i;  // k known exactly
      }
      if (sphere == equations_.size()) continue;
      const Polynomial& S = equations_[sphere].polynomial;
      for (std::size_t i = 0; i < equations_.size(); ++i) {
        if (i == sphere) continue;
        const Polynomial& p = equations_[i].polynomial;
        std::array<Polynomial, 3> sq;
        if (!split(p, sq) || sq[0].is_zero() || !same(sq[0], sq[1]) || !same(sq[0], sq[2])) continue;
        // p - (c / k) S: its T^2 terms cancel (exactly with exact coefficients; with interval
        // coefficients to enclosures of 0, kept: the result encloses the exact p - (c / k) S)
        Polynomial mu(p.number_of_variables());
        for (const auto& ct : sq[0].terms()) mu.add_term(ct.first, ct.second / k);
        Polynomial r = p - mu * S;
        Reduced_equation<NT> e = finish(equations_[i].origin, std::move(r), equations_[i].frame, nullptr);
        e.label = equations_[i].label + ", minus " + (sq[0].terms().size() == 1 && sq[0].total_degree() == 0 ? "a multiple" : "D") +
                  " x (" + equations_[sphere].label + "): linear in " + p_->variable_names()[T[0]].substr(0, p_->variable_names()[T[0]].size() - 1);
        equations_[i] = std::move(e);
      }
    }
  }

  static bool same_bounds(const NT& a, const NT& b)
  {
    if constexpr (internal::Coefficient_ops<NT>::is_interval) {
      typename CGAL::Interval_traits<NT>::Lower lower;
      typename CGAL::Interval_traits<NT>::Upper upper;
      return lower(a) == lower(b) && upper(a) == upper(b);
    } else {
      return a == b;
    }
  }

  const Rigid_body_collection<Traits>& c_;
  Incidence_tree tree_;
  std::shared_ptr<Parametrization> p_;
  std::vector<int> placements_;
  Constraint_independence independence_;
  std::vector<Reduced_equation<NT>> equations_;
  std::vector<Constraint> left_out_;
  std::vector<std::size_t> loose_;
};

} // namespace Rigid_incidence
} // namespace CGAL

#endif
