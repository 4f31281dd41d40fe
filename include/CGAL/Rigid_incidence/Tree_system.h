// Copyright (c) 2026 Rigid_incidence contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The reduced system of a hinged scene evaluated along its incidence tree, never expanded.

#ifndef CGAL_RIGID_INCIDENCE_TREE_SYSTEM_H
#define CGAL_RIGID_INCIDENCE_TREE_SYSTEM_H

#include <CGAL/Interval_nt.h>
#include <CGAL/Rigid_incidence/Input_error.h>
#include <CGAL/Rigid_incidence/Reduced_system.h>
#include <CGAL/Rigid_incidence/Rigid_body_collection.h>
#include <CGAL/Rigid_incidence/incidence_tree_parametrization.h>
#include <CGAL/Rigid_incidence/optimal_incidence_tree.h>
#include <CGAL/Rigid_incidence/rigidity_matroid.h>
#include <CGAL/Rigid_incidence/well_formed_incidences.h>
#include <algorithm>
#include <array>
#include <memory>
#include <string>
#include <vector>

namespace CGAL {
namespace Rigid_incidence {

/*!
\ingroup PkgRigidIncidenceSolver
\brief The equations of the reduced system of a scene whose incidence tree is made of hinges
(every tree edge shares two points), each kept as the composition of the tree's maps it stands
for and evaluated over a box with interval arithmetic and forward differentiation, in any chart
of each hinge, instead of being expanded into a polynomial.

The equations are those of `Reduced_system` (the same constraints, kept by the same rank
test): a remaining incidence is coordinate p of the difference of the point's positions in its
two bodies, in the frame of their lowest common ancestor; a distance
\f$|X_a - X_b|^2 - d^2\f$ between its points, through the carrier bodies that give the shortest
path in the tree. Each is the rational function whose numerator `Reduced_system` expands
(its denominator, a product of the hinges' \f$D_e > 0\f$, never vanishes), so the two have the
same roots, and a root is simple for one exactly when it is simple for the other. Expanded, the
closing distance of a chain of k hinged bodies has \f$3^{k-1}\f$ terms (177,147 for k = 12,
13 s to build; k = 14 needs 17 GB); here it costs k small matrix products per evaluation.

A hinge's variable is t in chart 0 and s = 1/t (up to the pair's length) in chart 1, both in
[-1, 1] (`Incidence_tree_parametrization`), and `WHOLE` (chart -1): the whole circle, both
charts at once, for which the rotation is enclosed by the hull of the two charts and the
derivative is not computed (a branch-and-prune chooses the chart of a hinge only when it must,
see `solve_tree_system()`).

\tparam Traits a model of `RigidIncidenceTraits`
*/
template <class Traits>
class Tree_system
{
public:
  typedef CGAL::Interval_nt<false> IT;  ///< the interval type (double, rounded outward)
  typedef Incidence_tree_parametrization<Traits, IT> Parametrization; ///< the tree's maps, per chart
  static constexpr int WHOLE = -1;      ///< a hinge whose chart is not chosen: the whole circle

  /// One equation, as the tree evaluates it.
  struct Equation
  {
    Constraint origin;                    ///< the incidence or distance it stands for
    std::string label;                    ///< the origin in words
    bool distance = false;                ///< a squared distance minus its square, else an incidence coordinate
    std::size_t body_a = 0;               ///< the body carrying its first point
    std::size_t body_b = 0;               ///< the body carrying its second point
    std::array<IT, 3> local_a;            ///< the first point in its body's frame
    std::array<IT, 3> local_b;            ///< the second point in its body's frame
    std::size_t frame = 0;                ///< the lowest common ancestor of the two bodies
    int coordinate = 1;                   ///< for an incidence: which coordinate (1..3)
    IT squared = IT(0);                   ///< for a distance: d^2
    std::vector<std::size_t> path_a;      ///< tree edges from `body_a` up to `frame`
    std::vector<std::size_t> path_b;      ///< tree edges from `body_b` up to `frame`
    std::vector<std::size_t> variables;   ///< the variables it involves (sorted)
  };

  /// Whether a scene can be evaluated along its tree, and why not.
  static std::string unsupported(const Rigid_body_collection<Traits>& c, const Incidence_tree& tree)
  {
    if (tree.edges.empty()) return "the incidence tree has no edge";
    for (const auto& te : tree.edges)
      if (c.common_points(te.parent, te.child).size() != 2)
        return "tree edge '" + c.body(te.parent).name + "'-'" + c.body(te.child).name + "' is not a hinge (two shared points)";
    if (!c.free_points().empty()) return "the scene has free points";
    for (std::size_t b : tree.covering_set)
      if (!c.body(b).all_coordinates()) return "body '" + c.body(b).name + "' of the covering set is known by distances";
    return std::string();
  }

  /*!
  \param c a standard collection
  \param tree its incidence tree (hinges only: `unsupported()` empty)
  \param selection the well-formed incidences for `tree`
  \throws Input_error if `unsupported()` is not empty
  */
  Tree_system(const Rigid_body_collection<Traits>& c, const Incidence_tree& tree, const Well_formed_selection& selection)
    : c_(c), tree_(tree)
  {
    const std::string why = unsupported(c, tree);
    if (!why.empty()) throw Input_error("tree system: " + why);
    CGAL::Protect_FPU_rounding<true> guard;
    const std::size_t n = tree.edges.size();
    for (int ch = 0; ch < 2; ++ch) p_[ch] = std::make_shared<Parametrization>(c, tree, std::vector<int>(n, ch));
    const Parametrization& P = *p_[0];
    if (P.number_of_variables() != n) throw Input_error("tree system: one variable per hinge expected (internal error)");
    for (std::size_t k = 0; k < n; ++k)
      if (P.edges()[k].rotation.size() != 1 || P.edges()[k].rotation[0] != k)
        throw Input_error("tree system: hinge variables out of order (internal error)");
    // per edge and chart: M (9 entries) and D as polynomials of degree <= 2 in the edge's variable
    maps_.resize(n);
    for (std::size_t k = 0; k < n; ++k) {
      for (int ch = 0; ch < 2; ++ch) {
        Map& m = maps_[k].chart[ch];
        for (int i = 0; i < 9; ++i) m.M[std::size_t(i)] = coefficients(p_[ch]->rotation_numerator(k)[std::size_t(i)], k);
        m.D = coefficients(p_[ch]->denominator(k), k);
        for (int i = 0; i < 9; ++i) {
          const auto& a = m.M[std::size_t(i)];
          const auto& d = m.D;
          m.N[std::size_t(i)] = {a[1] * d[0] - a[0] * d[1], 2 * (a[2] * d[0] - a[0] * d[2]), a[2] * d[1] - a[1] * d[2]};
        }
      }
      for (int i = 0; i < 3; ++i) {
        const auto& o = P.offset(k)[std::size_t(i)];
        if (o.total_degree() > 0) throw Input_error("tree system: a hinge's offset depends on the parameters (internal error)");
        maps_[k].o[std::size_t(i)] = o.template evaluate<IT>(std::vector<IT>(n, IT(0)));
        maps_[k].s[std::size_t(i)] = P.pivot(k)[std::size_t(i)];
      }
      // the whole circle: the hull of both charts' rotations over [-1, 1]
      for (int i = 0; i < 9; ++i) {
        IT r0 = rotation_entry(maps_[k].chart[0], i, IT(-1, 1)), r1 = rotation_entry(maps_[k].chart[1], i, IT(-1, 1));
        maps_[k].whole[std::size_t(i)] = IT((std::min)(r0.inf(), r1.inf()), (std::max)(r0.sup(), r1.sup()));
      }
    }
    // the equations: the constraints Reduced_system keeps, in its order
    Reduced_constraints k = reduced_constraints(c, tree, selection);
    independence_ = std::move(k.independence);
    left_out_ = std::move(k.left_out);
    loose_ = std::move(k.loose);
    for (const Constraint& x : k.equations) equations_.push_back(make_equation(x));
  }

  /// Number of variables (one per hinge, in the order of the tree's edges).
  std::size_t number_of_variables() const { return tree_.edges.size(); }
  /// Number of equations.
  std::size_t number_of_equations() const { return equations_.size(); }
  /// The equations.
  const std::vector<Equation>& equations() const { return equations_; }
  /// Square: as many equations as variables, no constraint in conflict, no loose body.
  bool is_square() const { return equations_.size() == number_of_variables() && left_out_.empty() && loose_.empty(); }
  /// The constraints left out because they conflict (an over-constrained scene).
  const std::vector<Constraint>& left_out() const { return left_out_; }
  /// The collection.
  const Rigid_body_collection<Traits>& collection() const { return c_; }
  /// The incidence tree.
  const Incidence_tree& tree() const { return tree_; }
  /// The parametrization of chart `chart` (0 or 1) on every edge.
  const Parametrization& parametrization(int chart) const { return *p_[chart]; }
  /// The variable names of chart 0 (`<child>.t`) or 1 (`<child>.s`).
  std::vector<std::string> variable_names(const std::vector<int>& charts) const
  {
    std::vector<std::string> v = p_[0]->variable_names();
    for (std::size_t k = 0; k < v.size() && k < charts.size(); ++k)
      if (charts[k] == 1) v[k] = p_[1]->variable_names()[k];
    return v;
  }

  /// Scratch space and the hinges' rotations over the current box, kept between evaluations
  /// (one per thread; `evaluate()` makes its own when given none).
  struct Workspace
  {
    /// a hinge's rotation over an interval, as the first-order enclosures use it
    struct Rotation
    {
      int chart = -2;          ///< its chart (-2: not computed yet)
      double lo = 0;           ///< the interval's lower bound
      double hi = 0;           ///< the interval's upper bound
      std::array<IT, 9> c;     ///< the entries' constants (the rotation at the interval's centre)
      std::array<IT, 9> a;     ///< the entries' coefficients of the hinge's eps
    };
    std::vector<Rotation> rotations;  ///< per hinge, the last rotation computed
    std::vector<IT> P;                ///< scratch: the first point's position
    std::vector<IT> Q;                ///< scratch: the second point's position
    std::vector<IT> Y;                ///< scratch: a position one edge up
    std::vector<std::size_t> active;  ///< scratch: the coefficients not zero along a path
  };

  /*!
  \brief A first-order enclosure of equation `e` over the box `x` (per variable an interval,
  in chart `charts[v]`; the interval of a `WHOLE` variable is ignored): with each variable of
  `Equation::variables` written \f$x_j = \mathrm{mid}(x_j) + \mathrm{rad}(x_j)\,\varepsilon_j\f$,
  \f$\varepsilon_j \in [-1, 1]\f$, the equation's value at every point of the box lies in
  \f$C + \sum_j A_j \varepsilon_j\f$ (affine arithmetic with interval coefficients: the
  composition of the tree's maps keeps its first-order dependence on each variable, so a chain
  of rotations does not widen the enclosure at every step as plain intervals do). `A` gets one
  coefficient per variable of the equation (0 for a `WHOLE` one, whose whole circle goes into
  C). The caller keeps a `CGAL::Protect_FPU_rounding<true>` alive.
  */
  IT evaluate(std::size_t e, const std::vector<int>& charts, const std::vector<IT>& x, std::vector<IT>& A, Workspace* ws = nullptr) const
  {
    Workspace own;
    Workspace& w = ws ? *ws : own;
    const Equation& q = equations_[e];
    const std::size_t m = q.variables.size();
    position(q.local_a, q.path_a, q, charts, x, w, w.P);
    position(q.local_b, q.path_b, q, charts, x, w, w.Q);
    const std::size_t s = m + 1;  // per coordinate: the constant, then m coefficients
    A.assign(m, IT(0));
    if (!q.distance) {
      const std::size_t i = std::size_t(q.coordinate - 1);
      for (std::size_t j = 0; j < m; ++j) A[j] = w.P[i * s + 1 + j] - w.Q[i * s + 1 + j];
      return w.P[i * s] - w.Q[i * s];
    }
    // sum of u_i^2 - d^2, u = P - Q = c + l: c^2 + 2 c l + l^2 with l^2 in [0, spread^2]
    IT value = -q.squared;
    for (std::size_t i = 0; i < 3; ++i) {
      const IT c = w.P[i * s] - w.Q[i * s];
      IT spread(0);
      for (std::size_t j = 0; j < m; ++j) {
        const IT l = w.P[i * s + 1 + j] - w.Q[i * s + 1 + j];
        A[j] += 2 * c * l;
        spread += CGAL::abs(l);
      }
      value += CGAL::square(c) + IT(0, CGAL::square(IT(spread.sup())).sup());
    }
    return value;
  }
  /// The range of `C + sum_j A_j [-1, 1]`.
  static IT range(const IT& C, const std::vector<IT>& A)
  {
    IT r = C;
    for (const IT& a : A) r += CGAL::abs(a).sup() * IT(-1, 1);
    return r;
  }
  /// Equation `e` at a point of the box (every variable of the equation in its chart): an
  /// enclosure of its value.
  IT value(std::size_t e, const std::vector<int>& charts, const std::vector<double>& point) const
  {
    std::vector<IT> x(point.size());
    for (std::size_t i = 0; i < x.size(); ++i) x[i] = IT(point[i]);
    std::vector<IT> A;
    return range(evaluate(e, charts, x, A), A);
  }


  /// The centre and radius the first-order enclosures use for a variable's interval x: the
  /// variable is \f$t_0 + r\,\varepsilon\f$ with \f$\varepsilon \in [-1, 1]\f$ (r rounded up).
  static void centre_radius(const IT& x, double& t0, double& r)
  {
    t0 = 0.5 * x.inf() + 0.5 * x.sup();
    const IT T0(t0);
    r = (std::max)((x - T0).sup(), (T0 - x).sup());
  }

  /// Equation `e` over the box `x` with every variable of the equation in a chart: an
  /// enclosure of its value and of its partial derivatives over the whole box (forward
  /// differentiation in interval arithmetic; one per variable of `Equation::variables`), for
  /// the Krawczyk test's uniqueness.
  IT gradient(std::size_t e, const std::vector<int>& charts, const std::vector<IT>& x, std::vector<IT>& g) const
  {
    const Equation& q = equations_[e];
    const std::size_t m = q.variables.size();
    Jet3 P = jet(q.local_a, q.path_a, q, charts, x), Q = jet(q.local_b, q.path_b, q, charts, x);
    g.assign(m, IT(0));
    if (!q.distance) {
      const std::size_t i = std::size_t(q.coordinate - 1);
      for (std::size_t j = 0; j < m; ++j) g[j] = P.d[i][j] - Q.d[i][j];
      return P.v[i] - Q.v[i];
    }
    IT value = -q.squared;
    for (std::size_t i = 0; i < 3; ++i) {
      const IT u = P.v[i] - Q.v[i];
      value += CGAL::square(u);
      for (std::size_t j = 0; j < m; ++j) g[j] += 2 * u * (P.d[i][j] - Q.d[i][j]);
    }
    return value;
  }

private:
  struct Jet3 { std::array<IT, 3> v; std::array<std::vector<IT>, 3> d; };
  Jet3 jet(const std::array<IT, 3>& y, const std::vector<std::size_t>& path, const Equation& q, const std::vector<int>& charts,
           const std::vector<IT>& x) const
  {
    const std::size_t m = q.variables.size();
    Jet3 X;
    X.v = y;
    for (auto& d : X.d) d.assign(m, IT(0));
    std::array<IT, 9> R, dR;
    std::vector<std::size_t> act;  // (the derivatives not zero, in increasing order: as position())
    for (std::size_t k : path) {
      const Edge_maps& E = maps_[k];
      if (charts[k] == WHOLE) throw Input_error("tree system: a derivative in a hinge without chart (internal error)");
      const Map& M = E.chart[charts[k]];
      double t0, rad;
      centre_radius(x[k], t0, rad);
      const IT T0(t0), D = horner(M.D, x[k]), D0 = horner(M.D, T0), D2 = CGAL::square(D);  // (D^2 once for the nine entries)
      for (int i = 0; i < 9; ++i) {
        dR[std::size_t(i)] = horner(M.N[std::size_t(i)], x[k]) / D2;
        // the narrower of M / D and the mean-value form M(t0) / D(t0) + dR [-r, r]
        const IT r1 = horner(M.M[std::size_t(i)], x[k]) / D;
        const IT r2 = horner(M.M[std::size_t(i)], T0) / D0 + dR[std::size_t(i)] * IT(-rad, rad);
        IT r = (r1.sup() - r1.inf() < r2.sup() - r2.inf()) ? r1 : r2;
        R[std::size_t(i)] = IT((std::max)(r.inf(), -1.0), (std::min)(r.sup(), 1.0));
      }
      std::array<IT, 3> Z;
      for (std::size_t i = 0; i < 3; ++i) Z[i] = X.v[i] - E.s[i];
      Jet3 Y;
      const std::size_t j = std::size_t(std::lower_bound(q.variables.begin(), q.variables.end(), k) - q.variables.begin());
      for (int i = 0; i < 3; ++i) {
        IT v = E.o[std::size_t(i)];
        for (int l = 0; l < 3; ++l) v += R[std::size_t(3 * i + l)] * Z[std::size_t(l)];
        Y.v[std::size_t(i)] = v;
        Y.d[std::size_t(i)].assign(m, IT(0));
        for (std::size_t h : act) {
          IT s(0);
          for (int l = 0; l < 3; ++l) s += R[std::size_t(3 * i + l)] * X.d[std::size_t(l)][h];
          Y.d[std::size_t(i)][h] = s;
        }
        IT s(0);
        for (int l = 0; l < 3; ++l) s += dR[std::size_t(3 * i + l)] * Z[std::size_t(l)];
        Y.d[std::size_t(i)][j] += s;
      }
      if (!std::binary_search(act.begin(), act.end(), j)) act.insert(std::upper_bound(act.begin(), act.end(), j), j);
      X = std::move(Y);
    }
    return X;
  }
  // M (9 entries) and D of degree <= 2 in t, and N = M' D - M D' (its t^3 terms cancel): the
  // derivative of an entry of M / D is N / D^2, without the cancellation of M' D - M D'
  struct Map { std::array<std::array<IT, 3>, 9> M; std::array<IT, 3> D; std::array<std::array<IT, 3>, 9> N; };
  struct Edge_maps { Map chart[2]; std::array<IT, 3> o, s; std::array<IT, 9> whole; };

  // a polynomial of degree <= 2 in variable k alone, as its three coefficients
  static std::array<IT, 3> coefficients(const Sparse_polynomial<IT>& p, std::size_t k)
  {
    std::array<IT, 3> a = {IT(0), IT(0), IT(0)};
    for (const auto& t : p.terms()) {
      for (std::size_t v = 0; v < t.first.size(); ++v)
        if (v != k && t.first[v] != 0) throw Input_error("tree system: a hinge's map involves another variable (internal error)");
      const unsigned d = t.first.empty() ? 0 : t.first[k];
      if (d > 2) throw Input_error("tree system: a hinge's map of degree above 2 (internal error)");
      a[d] += t.second;
    }
    return a;
  }
  // a0 + a1 t + a2 t^2 over an interval, in centred form about its midpoint t0 (h = t - t0):
  // q(t0) + q'(t0) h + a2 h^2, with h^2 in [0, max h^2]
  static IT horner(const std::array<IT, 3>& a, const IT& t)
  {
    if (t.inf() == t.sup()) return a[0] + t * (a[1] + t * a[2]);
    const IT t0(0.5 * t.inf() + 0.5 * t.sup());
    const IT h = t - t0;
    const double h2 = (std::max)(CGAL::square(IT(h.inf())).sup(), CGAL::square(IT(h.sup())).sup());
    return a[0] + t0 * (a[1] + t0 * a[2]) + (a[1] + 2 * a[2] * t0) * h + a[2] * IT(0, h2);
  }
  // an entry of M(t) / D(t), a rotation: also in [-1, 1]
  static IT rotation_entry(const Map& m, int i, const IT& t)
  {
    IT r = horner(m.M[std::size_t(i)], t) / horner(m.D, t);
    return IT((std::max)(r.inf(), -1.0), (std::min)(r.sup(), 1.0));
  }

  // the position of local point y, carried up the edges of `path`, as affine forms in the
  // equation's variables, into `out` (3 (m + 1): per coordinate its constant, then its m
  // coefficients). A hinge's rotation over its interval T (centre t0, radius r) is
  // R(t0) + R'(T) r eps (mean value theorem), each entry also within [-1, 1].
  void position(const std::array<IT, 3>& y, const std::vector<std::size_t>& path, const Equation& q, const std::vector<int>& charts,
                const std::vector<IT>& x, Workspace& w, std::vector<IT>& out) const
  {
    const std::size_t m = q.variables.size(), s = m + 1;
    out.assign(3 * s, IT(0));
    for (std::size_t i = 0; i < 3; ++i) out[i * s] = y[i];
    if (w.rotations.size() != maps_.size()) w.rotations.assign(maps_.size(), typename Workspace::Rotation());
    // the coefficients not zero: those of the path's edges taken so far, in increasing order
    // (the others stay exactly 0, so skipping them changes no bit of the result: a long path
    // costs its length squared, not its length times the equation's variables)
    std::vector<std::size_t>& act = w.active;
    act.clear();
    for (std::size_t k : path) {
      const Edge_maps& E = maps_[k];
      const int ch = charts[k];
      typename Workspace::Rotation& R = w.rotations[k];
      if (R.chart != ch || (ch != WHOLE && (R.lo != x[k].inf() || R.hi != x[k].sup()))) {
        R.chart = ch;
        R.lo = x[k].inf();
        R.hi = x[k].sup();
        if (ch == WHOLE) {
          R.c = E.whole;
          R.a.fill(IT(0));
        } else {
          const Map& M = E.chart[ch];
          double t0, rad;
          centre_radius(x[k], t0, rad);
          const IT T0(t0), r(rad);
          const IT D0 = horner(M.D, T0), D = horner(M.D, x[k]), D2 = CGAL::square(D);  // (D^2 once for the nine entries)
          for (int i = 0; i < 9; ++i) {
            IT c = horner(M.M[std::size_t(i)], T0) / D0, a = horner(M.N[std::size_t(i)], x[k]) / D2 * r;
            // the entry lies in [-1, 1]: where the form says more, a constant may be narrower
            const double sp = CGAL::abs(a).sup();
            if ((c - IT(sp)).inf() < -1 || (c + IT(sp)).sup() > 1) {
              IT direct = horner(M.M[std::size_t(i)], x[k]) / D;
              direct = IT((std::max)(direct.inf(), -1.0), (std::min)(direct.sup(), 1.0));
              if (direct.sup() - direct.inf() < 2 * sp + (c.sup() - c.inf())) { c = direct; a = IT(0); }
            }
            R.c[std::size_t(i)] = c;
            R.a[std::size_t(i)] = a;
          }
        }
      }
      const std::size_t j = ch == WHOLE ? m : std::size_t(std::lower_bound(q.variables.begin(), q.variables.end(), k) - q.variables.begin());
      // Z = X - s; its spread
      std::array<IT, 3> zc;
      std::array<double, 3> zs;
      for (std::size_t l = 0; l < 3; ++l) {
        zc[l] = out[l * s] - E.s[l];
        IT t(0);
        for (std::size_t h : act) t += CGAL::abs(out[l * s + 1 + h]);
        zs[l] = t.sup();
      }
      w.Y.assign(3 * s, IT(0));
      for (std::size_t i = 0; i < 3; ++i) {
        IT c = E.o[i];
        double quad = 0;
        for (std::size_t l = 0; l < 3; ++l) {
          c += R.c[3 * i + l] * zc[l];
          quad = (IT(quad) + CGAL::abs(R.a[3 * i + l]) * IT(zs[l])).sup();
        }
        w.Y[i * s] = c + IT(-quad, quad);
        for (std::size_t h : act) {
          IT v(0);
          for (std::size_t l = 0; l < 3; ++l) v += R.c[3 * i + l] * out[l * s + 1 + h];
          w.Y[i * s + 1 + h] = v;
        }
        if (j < m)
          for (std::size_t l = 0; l < 3; ++l) w.Y[i * s + 1 + j] += R.a[3 * i + l] * zc[l];
      }
      if (j < m && !std::binary_search(act.begin(), act.end(), j)) act.insert(std::upper_bound(act.begin(), act.end(), j), j);
      std::swap(out, w.Y);
    }
  }

  std::vector<std::size_t> path_up(std::size_t b, std::size_t ancestor) const
  {
    std::vector<std::size_t> path;
    for (std::size_t x = b; x != ancestor; x = p_[0]->parent_of(x)) {
      if (x == Parametrization::npos) throw Input_error("tree system: not an ancestor (internal error)");
      path.push_back(p_[0]->edge_of_child(x));
    }
    return path;
  }
  std::vector<std::size_t> carriers(std::size_t p) const
  {
    std::vector<std::size_t> r;
    for (std::size_t b : tree_.covering_set) if (c_.body(b).contains(p)) r.push_back(b);
    return r;
  }
  std::array<IT, 3> local(std::size_t b, std::size_t p) const { return p_[0]->local_point(b, p); }

  void finish(Equation& q) const
  {
    q.frame = p_[0]->lowest_common_ancestor(q.body_a, q.body_b);
    q.path_a = path_up(q.body_a, q.frame);
    q.path_b = path_up(q.body_b, q.frame);
    q.variables = q.path_a;
    q.variables.insert(q.variables.end(), q.path_b.begin(), q.path_b.end());
    std::sort(q.variables.begin(), q.variables.end());
    q.variables.erase(std::unique(q.variables.begin(), q.variables.end()), q.variables.end());
  }

  Equation make_equation(const Constraint& k) const
  {
    Equation q;
    q.origin = k;
    q.label = describe(c_, k);
    if (!k.is_distance()) {
      const Incidence& i = k.incidence;
      q.body_a = i.body_a;
      q.body_b = i.body_b;
      q.local_a = local(i.body_a, i.point);
      q.local_b = local(i.body_b, i.point);
      q.coordinate = i.coordinate;
      finish(q);
      return q;
    }
    q.distance = true;
    if (k.origin == Constraint::BODY_DISTANCE) {
      const auto& body = c_.body(k.body);
      auto sq = body.squared(body.local(k.a), body.local(k.b));
      if (!sq) throw Input_error("tree system: body '" + body.name + "' fixes a distance only through a placement from distances");
      q.squared = IT(CGAL::to_interval(internal::exact_rational(*sq)));
    } else {
      q.squared = IT(CGAL::to_interval(internal::exact_rational(c_.distances()[k.distance].squared)));
    }
    // the carriers with the fewest variables
    bool have = false;
    Equation best;
    for (std::size_t a : carriers(k.a))
      for (std::size_t b : carriers(k.b)) {
        Equation e = q;
        e.body_a = a;
        e.body_b = b;
        e.local_a = local(a, k.a);
        e.local_b = local(b, k.b);
        finish(e);
        if (!have || e.variables.size() < best.variables.size()) { best = e; have = true; }
      }
    if (!have) throw Input_error("tree system: distance " + q.label + " has a point outside the covering set (internal error)");
    return best;
  }

  const Rigid_body_collection<Traits>& c_;
  Incidence_tree tree_;
  std::shared_ptr<Parametrization> p_[2];
  std::vector<Edge_maps> maps_;
  Constraint_independence independence_;
  std::vector<Equation> equations_;
  std::vector<Constraint> left_out_;
  std::vector<std::size_t> loose_;
};

} // namespace Rigid_incidence
} // namespace CGAL

#endif
