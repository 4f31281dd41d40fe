// Copyright (c) 2026 Rigid_incidence contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The Table 1 maps of optimized_incidence_tree_parametrization.txt, one per tree edge, in
// homogeneous quaternion charts, and the elimination leaves-to-root along the rooted tree:
// every point of every body of the covering set as a rational function of the parameters.

#ifndef CGAL_RIGID_INCIDENCE_INCIDENCE_TREE_PARAMETRIZATION_H
#define CGAL_RIGID_INCIDENCE_INCIDENCE_TREE_PARAMETRIZATION_H

#include <CGAL/Gmpq.h>
#include <CGAL/Interval_nt.h>
#include <CGAL/Rigid_incidence/Input_error.h>
#include <CGAL/Rigid_incidence/Polynomial_system.h>
#include <CGAL/Rigid_incidence/Rigid_body_collection.h>
#include <CGAL/Rigid_incidence/enclose_coordinates.h>
#include <CGAL/Rigid_incidence/optimal_incidence_tree.h>

#include <boost/graph/adjacency_list.hpp>
#include <boost/graph/dijkstra_shortest_paths.hpp>

#include <array>
#include <cmath>
#include <optional>
#include <limits>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Rigid_incidence {

/// \ingroup PkgRigidIncidenceRef
/// How the rotation of a tree edge is parametrized.
enum class Rotation_form
{
  /// Homogeneous quaternion coordinates, one chart per largest component: every chart a box
  /// [-1,1]^w, entries of degree 2 over degree 2 (the default).
  QUATERNION_CHARTS,
  /// The papers' stereographic form: one unbounded chart; a free rotation of degree 4 over 4.
  STEREOGRAPHIC
};

namespace internal {

// Coefficient conversions and square roots for the number types of the reduced system.
template <class NT> struct Coefficient_ops
{
  static constexpr bool is_interval = std::is_same<typename CGAL::Interval_traits<NT>::Is_interval, CGAL::Tag_true>::value;
  static NT from_rational(const CGAL::Gmpq& q)
  {
    if constexpr (std::is_same<NT, CGAL::Gmpq>::value) return q;
    else if constexpr (is_interval_nt<NT>::value) return NT(CGAL::to_interval(q));
    else return NT(q);
  }
  // An upper bound of |x| as a double.
  static double magnitude(const NT& x)
  {
    std::pair<double, double> i = CGAL::to_interval(x);
    return (std::max)(std::abs(i.first), std::abs(i.second));
  }
};

// A rational function whose denominator is a product of the edges' denominators D_e^k
// (kept as exponents, so that common denominators need no polynomial gcd).
template <class NT> struct Rational_function
{
  Sparse_polynomial<NT> num;
  std::map<std::size_t, unsigned> den; // edge -> power
};

} // namespace internal

/// \ingroup PkgRigidIncidenceRef
/// The parameters of one tree edge (Table 1): which map, which chart, which variables.
struct Edge_parameters
{
  std::size_t parent = 0;                 ///< body index of the parent
  std::size_t child = 0;                  ///< body index of the child
  std::vector<std::size_t> shared;        ///< the points they share (0, 1 or 2)
  int chart = 0;                          ///< the chart used
  int number_of_charts = 1;               ///< 2 for a shared pair, 4 for a free rotation (1 stereographic)
  std::vector<std::size_t> rotation;      ///< variable indices of the rotation (1 or 3)
  std::vector<std::size_t> translation;   ///< variable indices of the translation (3 for an edge sharing nothing)
  std::size_t pivot = std::size_t(-1);    ///< the child point the rotation turns about (global index): a shared point, or for an edge sharing nothing the one nearest the parent
  std::size_t anchor = std::size_t(-1);   ///< edge sharing nothing: the parent point nearest to the pivot (global index)
};

/*!
\ingroup PkgRigidIncidenceRef
\brief The incidence-tree parametrization: the Table 1 map of every tree edge and every point
of every body of the covering set as a rational function of the parameters, in the frame of
any ancestor body (the root's frame is the reduced system's world frame).

Each edge (parent p, child c) maps c's frame into p's: x -> o + M(q) (x - s) / D(q), where
M(q) / D(q) is a rotation written in homogeneous quaternion coordinates q = (q0, q1, q2, q3):
M(q) is the usual quadratic form (R(q) |q|^2) and D(q) = |q|^2.
- Shared pair {v, w} (k = 2, one parameter): q = (L a, b u) with u = w_p - v_p the pair's
  direction in p's frame, left unnormalized so that rational data give rational
  coefficients, and L the power of two nearest |u| (so that the parameter does not depend
  on the scene's scale); chart 0 is a = 1, b = t in [-1, 1], chart 1 is b = 1, a = s in
  [-1, 1] (tan(theta / 2) = t |u| / L and |u| / (L s): both charts together reach every
  angle). The
  constant rotation A that takes c's direction w_c - v_c onto u is a product of two
  reflections (rational when the two lengths agree exactly); o = v_p, s = v_c, M = M_u A.
- Shared point v (k = 1, three parameters): chart j has q_j = 1 and the other three
  components in [-1, 1]; every rotation has a largest component, so the 4 charts reach all
  of them; D = |q|^2 >= 1. o = v_p, s = v_c.
- Nothing shared (k = 0, six parameters): a free rotation as above about a pivot point s of
  the child, and the translation T = o, where s lands in the parent's frame. The pivot is the
  child point with the shortest chain of known lengths to a point a of the parent (its
  anchor, `reach()`), so T lies in the ball of radius r = reach(a, s) around a, and each
  coordinate of T in a +- r: for a Stewart-Gough platform, a leg's length around its base
  point (the whole scene's diameter, the bound before, made the box 13 times wider there and
  the platform's 40 assembly modes out of the solver's reach). A free point's coordinates
  lie likewise in a ball around the root point nearest to it.
With `Rotation_form::STEREOGRAPHIC`, a free rotation is the papers' q = (1 - |t|^2, 2 t) /
(1 + |t|^2) (degree 4 over 4, t unbounded) and a hinge the single chart a = 1, b = t with t
unbounded.

Bodies whose points all have coordinates enter with them, converted exactly (an exact `NT`)
or enclosed (an interval `NT`); a body known by distances (an implied body) is placed by
`enclose_coordinates()`, which needs square roots: `NT` must then be an interval type.

\tparam Traits a model of `RigidIncidenceTraits`
\tparam NT the coefficient type: `CGAL::Gmpq` (exact), `CGAL::Interval_nt<false>` or
`CGAL::Gmpfi` (certified enclosures). With `CGAL::Interval_nt<false>`, the caller keeps a
`CGAL::Protect_FPU_rounding<true>` alive while using the results (the constructor protects itself).
*/
template <class Traits, class NT>
class Incidence_tree_parametrization
{
public:
  typedef Sparse_polynomial<NT> Polynomial;               ///< polynomial type
  typedef internal::Rational_function<NT> Rational;        ///< numerator and denominator exponents
  typedef std::array<NT, 3> Point;                         ///< constant coordinates
  typedef std::array<Polynomial, 3> Polynomial_vector;     ///< a vector of polynomials
  static constexpr std::size_t npos = std::size_t(-1);     ///< "none"

  /*!
  \param c a standard collection
  \param tree an incidence tree of `c` (the optimal one, or any)
  \param charts one chart index per tree edge (empty: chart 0 everywhere)
  \param form the rotation form
  \param placements per body of `c` the placement variant of a body known by distances
         (empty: 0 everywhere)
  */
  Incidence_tree_parametrization(const Rigid_body_collection<Traits>& c, const Incidence_tree& tree, std::vector<int> charts = {},
                                 Rotation_form form = Rotation_form::QUATERNION_CHARTS, std::vector<int> placements = {})
    : c_(c), tree_(tree), form_(form)
  {
    Guard guard;
    const std::size_t nb = c.number_of_bodies();
    if (charts.empty()) charts.assign(tree.edges.size(), 0);
    if (charts.size() != tree.edges.size())
      throw Input_error("incidence tree parametrization: " + std::to_string(charts.size()) + " chart indices for " +
                        std::to_string(tree.edges.size()) + " tree edges");
    if (placements.empty()) placements.assign(nb, 0);
    edge_of_child_.assign(nb, npos);
    coordinates_.resize(nb);
    for (std::size_t b : tree.covering_set) coordinates_[b] = body_coordinates(b, placements.size() > b ? placements[b] : 0);
    // variables: per edge its rotation, then its translation
    for (std::size_t k = 0; k < tree.edges.size(); ++k) {
      const auto& te = tree.edges[k];
      Edge_parameters e;
      e.parent = te.parent;
      e.child = te.child;
      e.shared = c.common_points(te.parent, te.child);
      if (e.shared.size() > 2)
        throw Input_error("incidence tree parametrization: bodies '" + c.body(te.parent).name + "' and '" + c.body(te.child).name +
                          "' share 3 or more points (not a standard collection)");
      e.chart = charts[k];
      const std::string who = c.body(te.child).name;
      if (e.shared.size() == 2) {
        e.number_of_charts = form == Rotation_form::STEREOGRAPHIC ? 1 : 2;
        check_chart(e, k);
        e.rotation.push_back(new_variable(who + (e.chart == 0 ? ".t" : ".s"), form == Rotation_form::STEREOGRAPHIC));
      } else {
        e.number_of_charts = form == Rotation_form::STEREOGRAPHIC ? 1 : 4;
        check_chart(e, k);
        for (int i = 0; i < 4; ++i)
          if (form == Rotation_form::STEREOGRAPHIC ? i > 0 : i != e.chart)
            e.rotation.push_back(new_variable(who + ".q" + std::to_string(i), form == Rotation_form::STEREOGRAPHIC));
        if (e.shared.empty())
          for (const char* x : {".Tx", ".Ty", ".Tz"}) e.translation.push_back(new_variable(who + x, false, true));
      }
      if (!e.shared.empty()) e.pivot = e.shared[0];
      edge_of_child_[te.child] = k;
      edges_.push_back(e);
    }
    // free points: 3 variables each, in the root's frame
    free_variable_.assign(c.number_of_points(), npos);
    for (std::size_t p : c.free_points()) {
      free_variable_[p] = names_.size();
      for (const char* x : {".x", ".y", ".z"}) new_variable(c.label(p) + x, false, true);
    }
    // boxes of the translations and free points: a ball around a parent (root) point
    build_link_graph();
    for (std::size_t k = 0; k < edges_.size(); ++k) {
      Edge_parameters& e = edges_[k];
      if (!e.shared.empty()) continue;
      const auto& child = c.body(e.child);
      const auto& parent = c.body(e.parent);
      std::size_t best_s = 0, best_a = 0;
      double best = std::numeric_limits<double>::infinity();
      for (std::size_t i = 0; i < child.points.size(); ++i)
        for (std::size_t j = 0; j < parent.points.size(); ++j) {
          double r = reach(parent.points[j], child.points[i]);
          if (r < best) { best = r; best_s = i; best_a = j; }
        }
      e.pivot = child.points[best_s];
      e.anchor = parent.points[best_a];
      set_ball(e.translation, coordinates_[e.parent][best_a], best, "body '" + child.name + "'", "its parent '" + parent.name + "'");
    }
    for (std::size_t p : c.free_points()) {
      const auto& root = c.body(tree.root);
      std::size_t best_a = 0;
      double best = std::numeric_limits<double>::infinity();
      for (std::size_t j = 0; j < root.points.size(); ++j) {
        double r = reach(root.points[j], p);
        if (r < best) { best = r; best_a = j; }
      }
      set_ball({free_variable_[p], free_variable_[p] + 1, free_variable_[p] + 2}, coordinates_[tree.root][best_a], best,
               "free point '" + c.label(p) + "'", "the root body '" + root.name + "'");
    }
    // the maps
    const NT I[9] = {NT(1), NT(0), NT(0), NT(0), NT(1), NT(0), NT(0), NT(0), NT(1)};
    A_.assign(edges_.size(), {I[0], I[1], I[2], I[3], I[4], I[5], I[6], I[7], I[8]});
    for (std::size_t k = 0; k < edges_.size(); ++k) build_map(k);
  }

  /// Number of variables.
  std::size_t number_of_variables() const { return names_.size(); }
  /// Variable names: `<child body>.t` (or `.s`) for a hinge, `.q0`..`.q3` (three of them) for a
  /// free rotation, `.Tx`, `.Ty`, `.Tz` for a translation, `<point>.x` .. for a free point.
  const std::vector<std::string>& variable_names() const { return names_; }
  /// The box of each variable.
  const std::vector<std::pair<double, double>>& box() const { return box_; }
  /// The rotation form.
  Rotation_form form() const { return form_; }
  /// The edges' parameters, in the order of `Incidence_tree::edges`.
  const std::vector<Edge_parameters>& edges() const { return edges_; }
  /// The tree edge (index) whose child is `body`, or `npos` (the root, or a body outside the tree).
  std::size_t edge_of_child(std::size_t body) const { return edge_of_child_[body]; }
  /// The first variable of free point `p` (then y, z), or `npos`.
  std::size_t free_point_variable(std::size_t p) const { return free_variable_[p]; }
  /// D_e: the denominator of edge `k`'s rotation (never zero on its chart's box).
  const Polynomial& denominator(std::size_t k) const { return D_[k]; }
  /// The rotation numerator M_e (3 x 3, row-major) of edge `k`, including the alignment of a hinge.
  const std::array<Polynomial, 9>& rotation_numerator(std::size_t k) const { return M_[k]; }
  /// The constant rotation A (row-major) that a hinge edge `k` applies before turning about its
  /// axis (it takes the child's direction of the shared pair onto the parent's); the identity
  /// for other edges.
  const std::array<NT, 9>& alignment_matrix(std::size_t k) const { return A_[k]; }
  /// The offset o_e (in the parent's frame) of edge `k`.
  const Polynomial_vector& offset(std::size_t k) const { return o_[k]; }
  /// The point s_e (in the child's frame) that edge `k`'s rotation turns about.
  const Point& pivot(std::size_t k) const { return s_[k]; }
  /// The coordinates the parametrization uses for body `b` of the covering set, per local point.
  const std::vector<Point>& coordinates(std::size_t b) const { return coordinates_[b]; }

  /*!
  \brief An upper bound on the distance between the points `p` and `q` (global indices) in
  every configuration of the scene: the shortest chain from `p` to `q` whose links are the
  scene's distances and the pairs of points of one body (Dijkstra's algorithm, Boost.Graph),
  each link's length rounded up. It bounds the translations and free points (their boxes).
  */
  double reach(std::size_t p, std::size_t q) const
  {
    auto it = reach_.find(p);
    if (it == reach_.end()) it = reach_.emplace(p, shortest_chains(p)).first;
    return it->second[q];
  }

  /// A rigid motion x -> R x + T (R row-major).
  template <class T>
  struct Pose
  {
    std::array<T, 9> R;  ///< rotation, row-major
    std::array<T, 3> t;  ///< translation
    bool known = false;  ///< false for a body outside the tree
  };

  /*!
  \brief Back-substitution: the pose of every body of the tree in the root's frame for the
  parameter values `x` (one per variable), in the type `T` (`double`, an interval type to
  carry a box, or `NT`): body b's point y sits at R_b y + T_b. Bodies outside the tree get
  `known == false`.
  */
  template <class T>
  std::vector<Pose<T>> poses(const std::vector<T>& x) const
  {
    Guard guard;
    std::vector<Pose<T>> out(c_.number_of_bodies());
    Pose<T>& root = out[tree_.root];
    root.R = {T(1), T(0), T(0), T(0), T(1), T(0), T(0), T(0), T(1)};
    root.t = {T(0), T(0), T(0)};
    root.known = true;
    auto conv = [](const NT& v) {
      if constexpr (std::is_same<T, NT>::value) return v;
      else return Polynomial::constant(0, v).template evaluate<T>(std::vector<T>());
    };
    for (std::size_t k = 0; k < edges_.size(); ++k) { // parents come before their children
      const Pose<T>& P = out[edges_[k].parent];
      if (!P.known) throw Input_error("incidence tree parametrization: tree edges out of order");
      const T D = D_[k].template evaluate<T>(x);
      std::array<T, 9> Re;
      for (int i = 0; i < 9; ++i) Re[std::size_t(i)] = M_[k][std::size_t(i)].template evaluate<T>(x) / D;
      std::array<T, 3> o, s;
      for (int i = 0; i < 3; ++i) { o[std::size_t(i)] = o_[k][std::size_t(i)].template evaluate<T>(x); s[std::size_t(i)] = conv(s_[k][std::size_t(i)]); }
      // child: y -> P.R (o + Re (y - s)) + P.t
      Pose<T>& C = out[edges_[k].child];
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
          T v(0);
          for (int l = 0; l < 3; ++l) v = v + P.R[std::size_t(3 * i + l)] * Re[std::size_t(3 * l + j)];
          C.R[std::size_t(3 * i + j)] = v;
        }
      std::array<T, 3> inner;
      for (int i = 0; i < 3; ++i) {
        T v = o[std::size_t(i)];
        for (int l = 0; l < 3; ++l) v = v - Re[std::size_t(3 * i + l)] * s[std::size_t(l)];
        inner[std::size_t(i)] = v;
      }
      for (int i = 0; i < 3; ++i) {
        T v = P.t[std::size_t(i)];
        for (int l = 0; l < 3; ++l) v = v + P.R[std::size_t(3 * i + l)] * inner[std::size_t(l)];
        C.t[std::size_t(i)] = v;
      }
      C.known = true;
    }
    return out;
  }

  /// The lowest common ancestor of two bodies of the tree.
  std::size_t lowest_common_ancestor(std::size_t a, std::size_t b) const
  {
    std::vector<bool> up(c_.number_of_bodies(), false);
    for (std::size_t x = a; x != npos; x = parent_of(x)) up[x] = true;
    for (std::size_t x = b; x != npos; x = parent_of(x)) if (up[x]) return x;
    throw Input_error("incidence tree parametrization: bodies '" + c_.body(a).name + "' and '" + c_.body(b).name + "' are not in one tree");
  }

  /// The position of local point `y` (constant coordinates in body `b`'s frame) in the frame
  /// of `ancestor`, as three rational functions.
  std::array<Rational, 3> position(std::size_t b, const Point& y, std::size_t ancestor) const
  {
    return position(b, y, ancestor, npos);
  }
  /// The position of point `p` of body `b` in the frame of `ancestor`.
  std::array<Rational, 3> position(std::size_t b, std::size_t p, std::size_t ancestor) const
  {
    return position(b, local_point(b, p), ancestor, p);
  }

  /// The squared distance between local point `ya` of body `a` and local point `yb` of body
  /// `b`, in the lowest form the tree allows: with L their lowest common ancestor and e, f the
  /// edges just below L towards a and b, |X_a - X_b|^2 = |o_e - o_f|^2 + |Z_a|^2 + |Z_b|^2 +
  /// 2 (o_e - o_f).(R_e Z_a - R_f Z_b) - 2 (R_e Z_a).(R_f Z_b) with Z = Y - s, where
  /// |R Z|^2 = |Z|^2 (a rotation keeps lengths) and |Z_a|^2 is the same problem one level
  /// down. Only the products R_e R_f need the denominator D_e D_f: a distance between two
  /// hinged bodies has degree 2 in each hinge parameter, not 4.
  Rational squared_distance(std::size_t a, const Point& ya, std::size_t b, const Point& yb) const
  {
    Guard guard;
    return sqdist(Side{a, ya, npos, npos}, Side{b, yb, npos, npos});
  }
  /// The squared distance between point `p` of body `a` (or a free point: `a` = npos) and
  /// point `q` of body `b` (or a free point).
  Rational squared_distance_of_points(std::size_t a, std::size_t p, std::size_t b, std::size_t q) const
  {
    Guard guard;
    Side sa{a, a == npos ? Point() : local_point(a, p), a == npos ? p : npos, p};
    Side sb{b, b == npos ? Point() : local_point(b, q), b == npos ? q : npos, q};
    return sqdist(sa, sb);
  }

  /// Coordinate `coordinate` (1..3) of the difference of the positions of point `p` in bodies
  /// `a` and `b`, in the frame of their lowest common ancestor (an incidence equation).
  Rational incidence_difference(std::size_t p, std::size_t a, std::size_t b, int coordinate) const
  {
    Guard guard;
    const std::size_t L = lowest_common_ancestor(a, b);
    std::array<Rational, 3> Xa = position(a, p, L), Xb = position(b, p, L);
    return sub(Xa[std::size_t(coordinate - 1)], Xb[std::size_t(coordinate - 1)]);
  }

  /// The parent of body `b` in the tree, or `npos`.
  std::size_t parent_of(std::size_t b) const
  {
    std::size_t e = edge_of_child_[b];
    return e == npos ? npos : edges_[e].parent;
  }
  /// The local coordinates of global point `p` in body `b`.
  Point local_point(std::size_t b, std::size_t p) const
  {
    std::size_t l = c_.body(b).local(p);
    if (l == npos || b >= coordinates_.size() || coordinates_[b].empty())
      throw Input_error("incidence tree parametrization: point '" + (p < c_.number_of_points() ? c_.label(p) : std::to_string(p)) +
                        "' is not a point of a covering body '" + c_.body(b).name + "'");
    return coordinates_[b][l];
  }

private:
  static constexpr double kTranslation = 1e300; // placeholder box until the bound is known
  typedef internal::Rounding_guard<NT> Guard; // FPU rounding upward while double intervals compute
  struct Side
  {
    std::size_t body;  // npos for a free point
    Point y;           // local coordinates in the body
    std::size_t free;  // the free point, or npos
    std::size_t point; // the global point at y, or npos: a point at an edge's pivot is there
                       // exactly, even when interval coordinates cannot show it
  };

  std::size_t new_variable(const std::string& name, bool unbounded, bool translation = false)
  {
    names_.push_back(name);
    if (translation) box_.push_back({-kTranslation, kTranslation});
    else if (unbounded) box_.push_back({-1e6, 1e6});
    else box_.push_back({-1.0, 1.0});
    return names_.size() - 1;
  }
  void check_chart(const Edge_parameters& e, std::size_t k) const
  {
    if (e.chart < 0 || e.chart >= e.number_of_charts)
      throw Input_error("incidence tree parametrization: chart " + std::to_string(e.chart) + " of tree edge " + std::to_string(k) +
                        " ('" + c_.body(e.parent).name + "' -> '" + c_.body(e.child).name + "'), which has " +
                        std::to_string(e.number_of_charts) + " chart(s)");
  }

  std::vector<Point> body_coordinates(std::size_t b, int variant) const
  {
    const auto& body = c_.body(b);
    std::vector<Point> out(body.points.size());
    if (body.all_coordinates()) {
      for (std::size_t i = 0; i < body.points.size(); ++i) {
        const auto& p = body.coordinates[i];
        out[i] = {internal::Coefficient_ops<NT>::from_rational(internal::exact_rational(Traits::x(p))),
                  internal::Coefficient_ops<NT>::from_rational(internal::exact_rational(Traits::y(p))),
                  internal::Coefficient_ops<NT>::from_rational(internal::exact_rational(Traits::z(p)))};
      }
      return out;
    }
    if constexpr (!internal::Coefficient_ops<NT>::is_interval) {
      throw Input_error("body '" + body.name + "' is known by distances: placing it needs square roots; use interval "
                        "coefficients (CGAL::Interval_nt<false> or CGAL::Gmpfi)");
    } else {
      Body_enclosure<NT> e = enclose_coordinates<NT>(c_, b, variant);
      if (!e.consistent) throw Input_error("body '" + body.name + "': its distances admit no placement");
      for (std::size_t i = 0; i < body.points.size(); ++i) out[i] = {e.coordinates[i][0], e.coordinates[i][1], e.coordinates[i][2]};
      return out;
    }
  }

  Polynomial var(std::size_t i) const { return Polynomial::variable(names_.size(), i); }
  Polynomial cst(const NT& x) const { return Polynomial::constant(names_.size(), x); }
  Rational constant(const NT& x) const { return Rational{cst(x), {}}; }

  // M(q) (= |q|^2 R(q)) for a quaternion of polynomials
  std::array<Polynomial, 9> quaternion_matrix(const std::array<Polynomial, 4>& q) const
  {
    const Polynomial &a = q[0], &b = q[1], &c = q[2], &d = q[3];
    const NT two(2);
    return {a * a + b * b - c * c - d * d, two * (b * c - a * d), two * (b * d + a * c),
            two * (b * c + a * d), a * a - b * b + c * c - d * d, two * (c * d - a * b),
            two * (b * d - a * c), two * (c * d + a * b), a * a - b * b - c * c + d * d};
  }

  // The rotation A (3 x 3 constants) taking direction a onto direction u (|a| = |u|, or scaled
  // to it): a product of two reflections, rational in the data.
  std::array<NT, 9> alignment(Point a, const Point& u, const std::string& what) const
  {
    auto dot = [](const Point& x, const Point& y) { return x[0] * y[0] + x[1] * y[1] + x[2] * y[2]; };
    NT aa = dot(a, a), uu = dot(u, u);
    if constexpr (internal::Coefficient_ops<NT>::is_interval) {
      NT f = CGAL::sqrt(uu / aa); // lengths that agree only up to the kernel's tolerance
      for (auto& x : a) x = x * f;
    } else {
      if (aa != uu)
        throw Input_error("incidence tree parametrization: " + what + ": the shared pair has different lengths in the two bodies");
    }
    auto reflect = [&](const Point& n) { // I - 2 n n^T / |n|^2
      NT nn = dot(n, n);
      std::array<NT, 9> H;
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
          H[std::size_t(3 * i + j)] = NT(i == j ? 1 : 0) - NT(2) * n[std::size_t(i)] * n[std::size_t(j)] / nn;
      return H;
    };
    auto mul = [](const std::array<NT, 9>& X, const std::array<NT, 9>& Y) {
      std::array<NT, 9> Z;
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
          NT s(0);
          for (int k = 0; k < 3; ++k) s = s + X[std::size_t(3 * i + k)] * Y[std::size_t(3 * k + j)];
          Z[std::size_t(3 * i + j)] = s;
        }
      return Z;
    };
    Point dm{a[0] - u[0], a[1] - u[1], a[2] - u[2]}, dp{a[0] + u[0], a[1] + u[1], a[2] + u[2]};
    double mm = CGAL::to_interval(dot(dm, dm)).first, pp = CGAL::to_interval(dot(dp, dp)).first;
    if (pp >= mm) { // H_u H_{a+u}: a -> -u -> u (|a + u|^2 >= 2 |a|^2 > 0 here)
      return mul(reflect(u), reflect(dp));
    }
    // H_n H_{a-u} with n orthogonal to u: a -> u -> u
    int i = 0;
    for (int k = 1; k < 3; ++k)
      if (internal::Coefficient_ops<NT>::magnitude(u[std::size_t(k)]) < internal::Coefficient_ops<NT>::magnitude(u[std::size_t(i)])) i = k;
    Point e{NT(0), NT(0), NT(0)};
    e[std::size_t(i)] = NT(1);
    Point n{u[1] * e[2] - u[2] * e[1], u[2] * e[0] - u[0] * e[2], u[0] * e[1] - u[1] * e[0]};
    return mul(reflect(n), reflect(dm));
  }

  void build_map(std::size_t k)
  {
    const Edge_parameters& e = edges_[k];
    const std::size_t n = names_.size();
    Polynomial one = cst(NT(1)), zero(n);
    std::array<Polynomial, 9> M;
    Polynomial D(n);
    Polynomial_vector o{zero, zero, zero};
    Point s{NT(0), NT(0), NT(0)};
    const std::string what = "tree edge '" + c_.body(e.parent).name + "' -> '" + c_.body(e.child).name + "'";
    if (e.shared.size() == 2) {
      const Point vp = local_point(e.parent, e.shared[0]), wp = local_point(e.parent, e.shared[1]);
      const Point vc = local_point(e.child, e.shared[0]), wc = local_point(e.child, e.shared[1]);
      Point u{wp[0] - vp[0], wp[1] - vp[1], wp[2] - vp[2]}, a{wc[0] - vc[0], wc[1] - vc[1], wc[2] - vc[2]};
      std::array<NT, 9> A = alignment(a, u, what);
      A_[k] = A;
      Polynomial qa = one, qb = var(e.rotation[0]);
      if (form_ == Rotation_form::QUATERNION_CHARTS) {
        // q = (L a, b u) with L a power of two near |u| (exact in any number type): then
        // tan(theta / 2) = (b / a) |u| / L is within a factor sqrt(2) of b / a whatever the
        // scene's scale, so the roots stay in the middle of the chart boxes
        const double len = std::sqrt(CGAL::to_double(u[0] * u[0] + u[1] * u[1] + u[2] * u[2]));
        const int ex = (len > 0 && std::isfinite(len)) ? int(std::lround(std::log2(len))) : 0;
        qa = cst(NT(std::ldexp(1.0, ex)));
        if (e.chart == 1) qa = qa * qb, qb = one;
      }
      std::array<Polynomial, 4> q{qa, u[0] * qb, u[1] * qb, u[2] * qb};
      std::array<Polynomial, 9> Mu = quaternion_matrix(q);
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
          Polynomial sum(n);
          for (int l = 0; l < 3; ++l) sum = sum + A[std::size_t(3 * l + j)] * Mu[std::size_t(3 * i + l)];
          M[std::size_t(3 * i + j)] = sum;
        }
      NT uu = u[0] * u[0] + u[1] * u[1] + u[2] * u[2];
      D = qa * qa + uu * (qb * qb);
      for (int i = 0; i < 3; ++i) o[std::size_t(i)] = cst(vp[std::size_t(i)]);
      s = vc;
    } else {
      std::array<Polynomial, 4> q;
      if (form_ == Rotation_form::STEREOGRAPHIC) {
        Polynomial t2(n);
        for (std::size_t v : e.rotation) t2 = t2 + var(v) * var(v);
        q[0] = one - t2;
        for (int i = 0; i < 3; ++i) q[std::size_t(i + 1)] = NT(2) * var(e.rotation[std::size_t(i)]);
        D = (one + t2) * (one + t2);
      } else {
        std::size_t next = 0;
        for (int i = 0; i < 4; ++i) q[std::size_t(i)] = i == e.chart ? one : var(e.rotation[next++]);
        D = q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3];
      }
      M = quaternion_matrix(q);
      if (e.shared.size() == 1) {
        const Point vp = local_point(e.parent, e.shared[0]);
        for (int i = 0; i < 3; ++i) o[std::size_t(i)] = cst(vp[std::size_t(i)]);
        s = local_point(e.child, e.shared[0]);
      } else { // T is where the pivot lands in the parent's frame
        for (int i = 0; i < 3; ++i) o[std::size_t(i)] = var(e.translation[std::size_t(i)]);
        s = local_point(e.child, e.pivot);
      }
    }
    M_.push_back(M);
    D_.push_back(D);
    o_.push_back(o);
    s_.push_back(s);
  }

  // --- rational function arithmetic (denominators: products of D_e)
  Rational lift(const Rational& r, const std::map<std::size_t, unsigned>& den) const
  {
    Rational out{r.num, den};
    for (const auto& d : den) {
      unsigned have = 0;
      auto it = r.den.find(d.first);
      if (it != r.den.end()) have = it->second;
      for (unsigned k = have; k < d.second; ++k) out.num = out.num * D_[d.first];
    }
    return out;
  }
  static std::map<std::size_t, unsigned> common(const Rational& a, const Rational& b)
  {
    std::map<std::size_t, unsigned> d = a.den;
    for (const auto& x : b.den) d[x.first] = (std::max)(d[x.first], x.second);
    return d;
  }
  // A zero term adds nothing, not even its denominator (a point at an edge's pivot, or at a
  // child's frame origin, would otherwise drag a D_e the equation does not depend on).
  Rational add(const Rational& a, const Rational& b) const
  {
    if (a.num.is_zero()) return b;
    if (b.num.is_zero()) return a;
    auto d = common(a, b);
    return Rational{lift(a, d).num + lift(b, d).num, d};
  }
  // A constant polynomial's value, if the polynomial is constant.
  static bool constant_value(const Rational& r, NT& v)
  {
    if (!r.den.empty()) return false;
    if (r.num.is_zero()) { v = NT(0); return true; }
    if (r.num.terms().size() != 1) return false;
    const auto& t = *r.num.terms().begin();
    for (unsigned e : t.first) if (e) return false;
    v = t.second;
    return true;
  }
  Rational sub(const Rational& a, const Rational& b) const
  {
    NT va, vb;
    if (constant_value(a, va) && constant_value(b, vb) && internal::certainly_same(va, vb)) return Rational{Polynomial(names_.size()), {}};
    if (b.num.is_zero()) return a;
    if (a.num.is_zero()) return scale(NT(-1), b);
    auto d = common(a, b);
    return Rational{lift(a, d).num - lift(b, d).num, d};
  }
  Rational mul(const Rational& a, const Rational& b) const
  {
    if (a.num.is_zero() || b.num.is_zero()) return Rational{Polynomial(names_.size()), {}};
    Rational r{a.num * b.num, a.den};
    for (const auto& x : b.den) r.den[x.first] += x.second;
    return r;
  }
  Rational scale(const NT& f, const Rational& a) const { return Rational{f * a.num, a.den}; }
  Rational poly(const Polynomial& p) const { return Rational{p, {}}; }

  // Y in the child's frame of edge k -> o + M (Y - s) / D in the parent's
  // `point`: the global index of the point at `y`, or npos. The pivot of b's own edge lands at
  // the edge's translation whatever the rotation: told by its index, not by comparing its
  // coordinates with the pivot's (interval coordinates of an implied body are not certainly
  // equal to themselves, and the rotation and its denominator would enter for nothing)
  std::array<Rational, 3> position(std::size_t b, const Point& y, std::size_t ancestor, std::size_t point) const
  {
    Guard guard;
    std::array<Rational, 3> X;
    std::size_t x = b;
    if (point != npos && b != ancestor && b != npos && edge_of_child_[b] != npos && edges_[edge_of_child_[b]].pivot == point) {
      for (int i = 0; i < 3; ++i) X[std::size_t(i)] = poly(o_[edge_of_child_[b]][std::size_t(i)]);
      x = parent_of(b);
    } else {
      for (int i = 0; i < 3; ++i) X[std::size_t(i)] = constant(y[std::size_t(i)]);
    }
    for (; x != ancestor; x = parent_of(x)) {
      if (x == npos) throw Input_error("incidence tree parametrization: not an ancestor");
      X = apply(edge_of_child_[x], X);
    }
    return X;
  }
  std::array<Rational, 3> apply(std::size_t k, const std::array<Rational, 3>& Y) const
  {
    std::array<Rational, 3> Z;
    for (int i = 0; i < 3; ++i) Z[std::size_t(i)] = sub(Y[std::size_t(i)], constant(s_[k][std::size_t(i)]));
    std::array<Rational, 3> RZ = rotate(k, Z);
    std::array<Rational, 3> X;
    for (int i = 0; i < 3; ++i) X[std::size_t(i)] = add(poly(o_[k][std::size_t(i)]), RZ[std::size_t(i)]);
    return X;
  }
  // M_k Z / D_k
  std::array<Rational, 3> rotate(std::size_t k, const std::array<Rational, 3>& Z) const
  {
    std::array<Rational, 3> out;
    for (int i = 0; i < 3; ++i) {
      Rational s = mul(poly(M_[k][std::size_t(3 * i)]), Z[0]);
      s = add(s, mul(poly(M_[k][std::size_t(3 * i + 1)]), Z[1]));
      s = add(s, mul(poly(M_[k][std::size_t(3 * i + 2)]), Z[2]));
      if (!s.num.is_zero()) s.den[k] += 1;
      out[std::size_t(i)] = s;
    }
    return out;
  }
  Rational dot(const std::array<Rational, 3>& a, const std::array<Rational, 3>& b) const
  {
    Rational s = mul(a[0], b[0]);
    s = add(s, mul(a[1], b[1]));
    return add(s, mul(a[2], b[2]));
  }

  // One side of a squared distance seen from frame L: offset o (in L) + rotated part R Z,
  // with |Z|^2 known; a side at L itself (or a free point) has no rotated part.
  struct Split
  {
    std::array<Rational, 3> o;
    bool rotated = false;
    std::array<Rational, 3> RZ;
    Rational ZZ;
  };
  Split split(const Side& s, std::size_t L) const
  {
    Split r;
    if (s.body == npos) { // a free point: its variables, in the root's frame
      for (int i = 0; i < 3; ++i) r.o[std::size_t(i)] = poly(var(free_variable_[s.free] + std::size_t(i)));
      return r;
    }
    if (s.body == L) {
      for (int i = 0; i < 3; ++i) r.o[std::size_t(i)] = constant(s.y[std::size_t(i)]);
      return r;
    }
    std::size_t top = s.body;
    while (parent_of(top) != L) top = parent_of(top);
    const std::size_t k = edge_of_child_[top];
    std::array<Rational, 3> Y = position(s.body, s.y, top, s.point), Z;
    const bool at_pivot = s.body == top && s.point != npos && s.point == edges_[k].pivot;
    for (int i = 0; i < 3; ++i)
      Z[std::size_t(i)] = at_pivot ? Rational{Polynomial(names_.size()), {}} : sub(Y[std::size_t(i)], constant(s_[k][std::size_t(i)]));
    for (int i = 0; i < 3; ++i) r.o[std::size_t(i)] = poly(o_[k][std::size_t(i)]);
    r.rotated = true;
    r.RZ = rotate(k, Z);
    r.ZZ = sqdist(s, Side{top, s_[k], npos, edges_[k].pivot}); // |Y - s|^2 one level down
    return r;
  }
  Rational sqdist(const Side& a, const Side& b) const
  {
    if (a.body != npos && a.body == b.body) {
      if (a.point != npos && a.point == b.point) return Rational{Polynomial(names_.size()), {}};
      NT s(0);
      for (int i = 0; i < 3; ++i) s = s + (a.y[std::size_t(i)] - b.y[std::size_t(i)]) * (a.y[std::size_t(i)] - b.y[std::size_t(i)]);
      return constant(s);
    }
    const std::size_t root = tree_.root;
    std::size_t L = (a.body == npos || b.body == npos) ? root : lowest_common_ancestor(a.body, b.body);
    Split A = split(a, L), B = split(b, L);
    std::array<Rational, 3> d;
    for (int i = 0; i < 3; ++i) d[std::size_t(i)] = sub(A.o[std::size_t(i)], B.o[std::size_t(i)]);
    Rational r = dot(d, d);
    if (A.rotated) r = add(add(r, A.ZZ), scale(NT(2), dot(d, A.RZ)));
    if (B.rotated) r = sub(add(r, B.ZZ), scale(NT(2), dot(d, B.RZ)));
    if (A.rotated && B.rotated) r = sub(r, scale(NT(2), dot(A.RZ, B.RZ)));
    return r;
  }

  // The graph of links for reach(): one vertex per point; an edge per distance and per pair
  // of points of a body, weighted by an upper bound on its length.
  typedef boost::adjacency_list<boost::vecS, boost::vecS, boost::undirectedS, boost::no_property,
                                boost::property<boost::edge_weight_t, double>> Link_graph;
  void build_link_graph()
  {
    links_ = Link_graph(c_.number_of_points());
    auto up_sqrt = [](double x) { return std::nextafter(std::sqrt((std::max)(x, 0.0)), std::numeric_limits<double>::infinity()); };
    for (const auto& d : c_.distances()) boost::add_edge(d.a, d.b, up_sqrt(CGAL::to_interval(d.squared).second), links_);
    for (std::size_t b = 0; b < c_.number_of_bodies(); ++b) {
      const auto& body = c_.body(b);
      std::optional<Body_enclosure<CGAL::Interval_nt<false>>> enc; // for pairs the body does not know exactly
      // the body's distances by pair, the first of each as Body::squared() takes it (looked up
      // pair by pair, a merged body's list made this loop a tenth of a tree's solve)
      const std::size_t m = body.points.size();
      std::map<std::pair<std::size_t, std::size_t>, std::size_t> first;
      for (std::size_t k = 0; k < body.squared_distances.size(); ++k) {
        const auto& d = body.squared_distances[k];
        first.emplace(std::make_pair((std::min)(d.a, d.b), (std::max)(d.a, d.b)), k);
      }
      for (std::size_t i = 0; i < m; ++i)
        for (std::size_t j = i + 1; j < m; ++j) {
          double d2;
          const auto f = first.find(std::make_pair(i, j));
          if (body.has_coordinates[i] && body.has_coordinates[j])
            d2 = CGAL::to_interval(Traits::squared_distance(body.coordinates[i], body.coordinates[j])).second;
          else if (f != first.end()) d2 = CGAL::to_interval(body.squared_distances[f->second].squared).second;
          else {
            CGAL::Protect_FPU_rounding<true> guard;
            if (!enc) {
              enc = enclose_coordinates<CGAL::Interval_nt<false>>(c_, b, 0);
              if (!enc->consistent) throw Input_error("body '" + body.name + "': its distances admit no placement");
            }
            CGAL::Interval_nt<false> s(0);
            for (int k = 0; k < 3; ++k) s += CGAL::square(enc->coordinates[i][std::size_t(k)] - enc->coordinates[j][std::size_t(k)]);
            d2 = s.sup();
          }
          boost::add_edge(body.points[i], body.points[j], up_sqrt(d2), links_);
        }
    }
  }
  std::vector<double> shortest_chains(std::size_t p) const
  {
    std::vector<double> d(boost::num_vertices(links_), std::numeric_limits<double>::infinity());
    boost::dijkstra_shortest_paths(links_, p, boost::distance_map(boost::make_iterator_property_map(d.begin(), boost::get(boost::vertex_index, links_))));
    return d;
  }
  // The box of three variables (x, y, z of one point) for a ball of radius r around centre
  // a; r carries a relative margin for the rounding of the sums along the chain.
  void set_ball(const std::vector<std::size_t>& v, const Point& a, double r, const std::string& who, const std::string& to)
  {
    if (!std::isfinite(r))
      throw Input_error("incidence tree parametrization: " + who + " is not linked to " + to +
                        " by any chain of known lengths (the scene is not connected): its translation has no bound");
    for (int i = 0; i < 3; ++i) {
      std::pair<double, double> ai = CGAL::to_interval(a[std::size_t(i)]);
      const double m = r * (1 + 1e-9) + 1e-12 * (std::max)(std::abs(ai.first), std::abs(ai.second));
      box_[v[std::size_t(i)]] = {ai.first - m, ai.second + m};
    }
  }

  const Rigid_body_collection<Traits>& c_;
  Incidence_tree tree_;
  Rotation_form form_;
  std::vector<std::string> names_;
  std::vector<std::pair<double, double>> box_;
  std::vector<Edge_parameters> edges_;
  std::vector<std::size_t> edge_of_child_, free_variable_;
  std::vector<std::vector<Point>> coordinates_;
  std::vector<std::array<Polynomial, 9>> M_;
  std::vector<std::array<NT, 9>> A_;
  std::vector<Polynomial> D_;
  std::vector<Polynomial_vector> o_;
  std::vector<Point> s_;
  Link_graph links_;
  mutable std::map<std::size_t, std::vector<double>> reach_;
};

} // namespace Rigid_incidence
} // namespace CGAL

#endif
