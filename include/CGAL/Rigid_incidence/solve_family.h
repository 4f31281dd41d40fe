// Copyright (c) 2026 Rigid_incidence contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Solution families: a scene with one distance declared free, solved as curves over that
// distance (decomposition_subdivision_solver.txt, Section 3.4, applied to a family of scenes;
// the quad gallery of elimination_generically_rigid_3d.txt drawn by the program).
//
// The free distance's squared length enters every reduced equation affinely (a distance
// equation is num - d^2 den; subtracting the sphere of a translation keeps that), so the
// squared length r becomes one more variable: the reduced system in (x, r) has one equation
// fewer than variables, and its real curves, traced with certified topology, are the family.
// The lengths where the number of configurations changes are the folds of r along the curves,
// the points where det(dF/dx) = 0: the square system {F(x, r) = 0, det(dF/dx) = 0}, solved
// and certified by the subdivision solver, gives each fold's length in a certified interval.

#ifndef CGAL_RIGID_INCIDENCE_SOLVE_FAMILY_H
#define CGAL_RIGID_INCIDENCE_SOLVE_FAMILY_H

#include <CGAL/Rigid_incidence/solve_scene.h>
#include <CGAL/Rigid_incidence/optimal_incidence_tree.h>
#include <CGAL/Rigid_incidence/standardize.h>
#include <CGAL/Rigid_incidence/well_formed_incidences.h>

#include <CGAL/Gmpq.h>
#include <CGAL/Interval_nt.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Rigid_incidence {

/// \ingroup PkgRigidIncidenceSolver
/// Parameters of `solve_family()`.
struct Family_parameters
{
  /// the solver's parameters for the fold systems (`scene.solver`), and the tolerances of
  /// merging and of the verification in the original system
  Scene_solve_parameters scene;
  /// the tracer's parameters for the curves of the family
  Curve_tracer_parameters tracer;
  /// the fold system's determinant is not formed when it would have more terms than this
  /// (the folds are then not computed, and the result says so)
  std::size_t maximal_determinant_terms = 100000;
  /// the count of configurations is sampled at this many lengths to check that it changes
  /// only at a fold
  std::size_t count_checks = 400;
};

/// \ingroup PkgRigidIncidenceSolver
/// A fold of a family: a length of the free distance where branches of configurations meet
/// and the number of configurations changes (generically by 2).
struct Family_fold
{
  std::pair<double, double> length{0, 0}; ///< certified enclosure of the free distance's length at the fold
  bool certified = false;                 ///< a root of {F = 0, det(dF/dx) = 0} proved (Krawczyk)
  /// configurations just above the fold's length minus just below (from the branches; all the
  /// folds at that length together: a scene and its mirror image fold at the same length)
  int change = 0;
  Configuration configuration;            ///< the configuration at the fold
  double max_residual = 0;                ///< its residual in the original system
  std::vector<int> charts;                ///< the chart combination it was found in (first)
  std::size_t found = 1;                  ///< chart combinations it was found in
};

/// \ingroup PkgRigidIncidenceSolver
/// The number of configurations on an open interval of lengths between two folds.
struct Family_count
{
  double lo = 0;          ///< from this length
  double hi = 0;          ///< to this one
  std::size_t count = 0;  ///< configurations for every length strictly inside
};

/// \ingroup PkgRigidIncidenceSolver
/// One branch of a family: a curve of configurations, with the free distance's length at each.
struct Family_branch
{
  Scene_curve curve;               ///< the configurations along the branch (`BOUNDARY` ends lie on the range's ends)
  std::vector<double> lengths;     ///< per configuration of `curve`: the free distance's length
};

/// \ingroup PkgRigidIncidenceSolver
/// Statistics of `solve_family()`.
struct Family_statistics
{
  std::size_t chart_combinations = 0;  ///< systems traced (and fold systems solved)
  std::size_t curve_boxes = 0;         ///< boxes of the tracer, all systems
  std::size_t fold_boxes = 0;          ///< boxes of the fold solver, all systems
  std::size_t determinant_terms = 0;   ///< terms of the largest fold determinant
  double reduce_seconds = 0;           ///< building the reduced systems and the fold systems
  double trace_seconds = 0;            ///< the curve tracer
  double fold_seconds = 0;             ///< the fold solver
  double verify_seconds = 0;           ///< back-substitution, residuals, joining
};

/// \ingroup PkgRigidIncidenceSolver
/// What `solve_family()` found.
struct Family_result
{
  std::string a;                                  ///< the free distance's first point
  std::string b;                                  ///< its second point
  std::pair<double, double> range{0, 0};          ///< the range of its length
  std::vector<std::string> variables;             ///< the reduced system's parameters, then the scaled squared length
  std::vector<Family_branch> branches;            ///< the curves of configurations
  std::vector<Family_fold> folds;                 ///< by increasing length
  std::vector<Family_count> counts;               ///< between consecutive folds (and the range's ends)
  std::vector<Scene_unresolved> unresolved;       ///< regions the tracer or the fold solver could not decide
  /// empty, or what limits the result ("under_constrained: ...", "folds not computed: ...",
  /// "the count changes near length ... where no fold was found")
  std::string diagnosis;
  Family_statistics statistics;                   ///< counters and times

  /// The number of configurations at `length`, counted on the traced branches (the crossings of
  /// the branches' polylines with that length: exact between folds, where the polylines are
  /// close to the curves; near a fold, within the tracer's sampling step, it may miss a pair).
  std::size_t count_at(double length) const
  {
    std::size_t n = 0;
    for (const auto& br : branches) {
      const auto& d = br.lengths;
      const std::size_t m = d.size();
      if (m == 0) continue;
      // a crossing: the polyline passes from below the length to at or above it, or back
      const std::size_t segments = br.curve.closed ? m : m - 1;
      for (std::size_t i = 0; i < segments; ++i) n += (d[i] < length) != (d[(i + 1) % m] < length);
    }
    return n;
  }

  /// every branch and fold certified, nothing unresolved, no diagnosis
  bool complete() const
  {
    if (!diagnosis.empty() || !unresolved.empty()) return false;
    for (const auto& b : branches) if (!b.curve.certified) return false;
    for (const auto& f : folds) if (!f.certified) return false;
    return true;
  }
};

namespace internal {

// p in n + 1 variables: the same terms, none in the last variable.
template <class NT>
Sparse_polynomial<NT> append_variable(const Sparse_polynomial<NT>& p)
{
  Sparse_polynomial<NT> q(p.number_of_variables() + 1);
  for (const auto& t : p.terms()) {
    typename Sparse_polynomial<NT>::Exponent e = t.first;
    e.push_back(0);
    q.add_term(e, t.second);
  }
  return q;
}

// The length of the distance between labels a and b in a configuration (NaN if unplaced).
inline double configuration_length(const Configuration& c, const std::string& a, const std::string& b)
{
  std::size_t ia = c.labels.size(), ib = c.labels.size();
  for (std::size_t i = 0; i < c.labels.size(); ++i) {
    if (c.labels[i] == a) ia = i;
    if (c.labels[i] == b) ib = i;
  }
  if (ia == c.labels.size() || ib == c.labels.size() || !c.placed[ia] || !c.placed[ib]) return std::numeric_limits<double>::quiet_NaN();
  double s = 0;
  for (int k = 0; k < 3; ++k) s += (c.points[ia][k] - c.points[ib][k]) * (c.points[ia][k] - c.points[ib][k]);
  return std::sqrt(s);
}

} // namespace internal

/*!
\ingroup PkgRigidIncidenceSolver
\brief A family of scenes: `original` with the distance between the points labelled `a` and
`b` free, its length running over [`lo`, `hi`]; the configurations as curves over that
length, and the folds where their number changes.

The collection with the free distance added at squared lengths 1, 2 and 3 is standardized and
reduced in every chart combination; each equation must be affine in the squared length (it is
for a distance equation, and stays so when a translation's sphere is subtracted; checked exactly,
so `original` must have exact coordinates for the covering bodies: a free distance closing a
triangle of distances, whose body would be placed by square roots of it, is refused). The
squared length, scaled to [0, 1] over the range, is appended as a variable; the system then
has one equation fewer than variables and `trace_curves()` traces it. The folds are the roots
of the square system {F = 0, det(dF/dx) = 0} (the curve is tangent to a level of the length),
found and certified by `Subdivision_solver<IT>`; their lengths are certified intervals.

Every configuration along a branch and at a fold is verified in `original` (which must not
hold the free distance). The count of configurations between folds comes from the branches,
and is checked at `Family_parameters::count_checks` lengths to change only at a fold.

\tparam IT the interval type (`CGAL::Interval_nt<false>` or `CGAL::Gmpfi`)
\throws Input_error when a point is unknown, both points lie in one body, the range is empty,
`original` already fixes the distance, or the length does not enter the system affinely.
*/
template <class IT, class Traits>
Family_result solve_family(const Rigid_body_collection<Traits>& original, const std::string& a, const std::string& b,
                           const CGAL::Gmpq& lo, const CGAL::Gmpq& hi, const Family_parameters& parameters = Family_parameters())
{
  typedef CGAL::Gmpq Q;
  typedef Sparse_polynomial<Q> Poly;
  typedef std::chrono::steady_clock Clock;
  auto since = [](Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); };
  const std::string what = "free distance " + a + "-" + b;
  Family_result out;
  out.a = a;
  out.b = b;
  out.range = {CGAL::to_double(lo), CGAL::to_double(hi)};
  Family_statistics& st = out.statistics;
  const std::size_t npos = Rigid_body_collection<Traits>::npos;
  // (a label made one point with another by a distance of 0 stands for that point)
  const std::string& ra = original.resolve_alias(a);
  const std::string& rb = original.resolve_alias(b);
  const std::size_t ia = original.point_index(ra), ib = original.point_index(rb);
  if (ia == npos) throw Input_error(what + ": no point '" + a + "' in the scene");
  if (ib == npos) throw Input_error(what + ": no point '" + b + "' in the scene");
  if (ia == ib) throw Input_error(what + ": a distance must join two different points");
  if (!(lo >= 0) || !(lo < hi)) throw Input_error(what + ": the range of lengths must have 0 <= smallest < largest");
  for (const auto& body : original.bodies())
    if (std::find(body.points.begin(), body.points.end(), ia) != body.points.end() &&
        std::find(body.points.begin(), body.points.end(), ib) != body.points.end())
      throw Input_error(what + ": both points are in body '" + body.name + "', which fixes their distance");
  for (const auto& d : original.distances())
    if ((d.a == ia && d.b == ib) || (d.a == ib && d.b == ia))
      throw Input_error(what + ": the scene already fixes this distance (" + d.name + ")");

  auto t0 = Clock::now();
  // the collection with the free distance at squared lengths 1, 2, 3, standardized
  std::vector<Rigid_body_collection<Traits>> cs;
  for (int k = 1; k <= 3; ++k) {
    Rigid_body_collection<Traits> ck = original;
    try {
      ck.add_distance(ra, rb, typename Traits::FT(k), what);
      cs.push_back(standardize(ck));
    } catch (const Input_error& e) {
      throw Input_error(what + ": " + e.what());
    }
  }
  for (int k = 1; k < 3; ++k) {
    bool same = cs[std::size_t(k)].number_of_bodies() == cs[0].number_of_bodies() && cs[std::size_t(k)].number_of_points() == cs[0].number_of_points();
    for (std::size_t i = 0; same && i < cs[0].number_of_bodies(); ++i) same = cs[std::size_t(k)].body(i).points == cs[0].body(i).points;
    if (!same) throw Input_error(what + ": its length changes the scene's structure (the bodies standardize() finds)");
  }
  const Incidence_tree tree = optimal_incidence_tree(cs[0]);
  const Well_formed_selection selection = select_well_formed_incidences(cs[0], tree);
  std::vector<int> radix;
  {
    std::unique_ptr<Reduced_system<Traits, Q>> first;
    try {
      first.reset(new Reduced_system<Traits, Q>(cs[0], tree, selection));
    } catch (const Input_error& e) {
      throw Input_error(what + ": " + e.what() + " (a family needs the reduced system with exact coefficients)");
    }
    out.variables = first->parametrization().variable_names();
    if (!first->is_square()) {
      out.diagnosis = std::string(first->number_of_equations() < first->number_of_variables() || !first->loose_bodies().empty()
                                      ? "under_constrained: "
                                      : "over_constrained: ") +
                      "with the free distance fixed, " + first->diagnostic();
      return out;
    }
    for (const auto& e : first->parametrization().edges()) radix.push_back(e.number_of_charts);
  }
  out.variables.push_back("rho(" + a + "-" + b + ")");
  st.reduce_seconds += since(t0);

  const Q lo2 = lo * lo, span = hi * hi - lo * lo;
  std::vector<internal::Scene_piece> pieces;
  std::vector<Family_fold> folds;
  std::vector<double> fold_size;
  std::vector<int> charts(radix.size(), 0);
  bool folds_computed = true;
  do {
    auto t1 = Clock::now();
    Reduced_system<Traits, Q> r1(cs[0], tree, selection, charts), r2(cs[1], tree, selection, charts), r3(cs[2], tree, selection, charts);
    const Polynomial_system<Q> s1 = r1.system(), s2 = r2.system(), s3 = r3.system();
    const std::size_t n = s1.number_of_variables();
    if (s2.number_of_variables() != n || s3.number_of_variables() != n || s1.number_of_equations() != n ||
        s2.number_of_equations() != n || s3.number_of_equations() != n)
      throw Input_error(what + ": its length changes the reduced system's shape");
    for (std::size_t j = 0; j < n; ++j)
      if (s1.box[j] != s2.box[j] || s1.box[j] != s3.box[j])
        throw Input_error(what + ": its length changes the box of the variable " + s1.variable_names[j] + " (not supported)");
    // F(x, rho) = P(1) + (lo^2 + rho (hi^2 - lo^2) - 1) (P(2) - P(1)), rho in [0, 1]
    Polynomial_system<Q> fam;
    fam.variable_names = out.variables;
    fam.box = s1.box;
    fam.box.push_back({0.0, 1.0});
    fam.labels = s1.labels;
    const Poly rho = Poly::variable(n + 1, n);
    for (std::size_t i = 0; i < n; ++i) {
      const Poly& p1 = s1.equations[i];
      const Poly d = s2.equations[i] - p1;
      if (!(s3.equations[i] - s2.equations[i] - d).is_zero())
        throw Input_error(what + ": equation " + std::to_string(i + 1) + " (" + (i < s1.labels.size() ? s1.labels[i] : std::string()) +
                          ") is not affine in the squared length (not supported)");
      const Poly D = internal::append_variable(d);
      fam.equations.push_back(internal::append_variable(p1) + (lo2 - Q(1)) * D + span * (rho * D));
    }
    // the fold system: F = 0 and det(dF/dx) = 0
    Polynomial_system<Q> fold = fam;
    if (folds_computed) {
      std::vector<std::vector<Poly>> J(n, std::vector<Poly>(n));
      std::size_t largest = 0;
      for (std::size_t i = 0; i < n; ++i)
        for (std::size_t j = 0; j < n; ++j) {
          J[i][j] = fam.equations[i].derivative(j);
          largest = (std::max)(largest, J[i][j].terms().size());
        }
      // a cheap estimate before the expansion: the product of the rows' largest entries
      double estimate = 1;
      for (std::size_t i = 0; i < n; ++i) estimate *= double(largest);
      Poly det(n + 1);
      if (estimate <= 1e3 * double(parameters.maximal_determinant_terms)) det = determinant(J);
      if (det.terms().size() > parameters.maximal_determinant_terms || (det.is_zero() && estimate > 1e3 * double(parameters.maximal_determinant_terms))) {
        folds_computed = false;
        out.diagnosis = "folds not computed: the fold determinant is too large";
      } else if (det.is_zero()) {
        folds_computed = false;
        out.diagnosis = "folds not computed: det(dF/dx) vanishes identically (every configuration is singular)";
      } else {
        st.determinant_terms = (std::max)(st.determinant_terms, det.terms().size());
        fold.equations.push_back(det);
        fold.labels.push_back("det(dF/dx)");
      }
    }
    st.reduce_seconds += since(t1);
    ++st.chart_combinations;

    auto unresolved = [&](const Solver_unresolved<IT>& u, const std::string& prefix) {
      Scene_unresolved x;
      x.kind = u.kind;
      x.reason = prefix + u.reason;
      x.charts = charts;
      std::vector<double> centre;
      for (const auto& e : u.box) {
        x.box.push_back(CGAL::to_interval(e));
        centre.push_back(0.5 * x.box.back().first + 0.5 * x.box.back().second);
      }
      x.boxes = u.boxes;
      centre.pop_back();
      x.at_centre = configuration(r1, centre);
      out.unresolved.push_back(x);
    };

    // the curves
    auto t2 = Clock::now();
    Curve_result<IT> cr = trace_curves<IT>(fam, parameters.tracer);
    st.trace_seconds += since(t2);
    st.curve_boxes += cr.statistics.boxes;
    auto t3 = Clock::now();
    for (const auto& u : cr.unresolved) unresolved(u, "tracer: ");
    for (const auto& c : cr.curves) {
      internal::Scene_piece q;
      q.piece.charts = charts;
      q.piece.parameters = c.points;
      q.ends[0] = c.ends[0];
      q.ends[1] = c.ends[1];
      q.closed = c.closed;
      q.certified = c.certified;
      for (int s = 0; s < 2; ++s) {
        const double r = s == 0 ? c.points.front().back() : c.points.back().back();
        q.range_end[s] = c.ends[s] == Curve_end::BOUNDARY && (r <= 1e-9 || r >= 1 - 1e-9);
      }
      if (internal::add_configurations(q, c.points, r1, original, parameters.scene.residual_threshold)) pieces.push_back(std::move(q));
    }
    st.verify_seconds += since(t3);

    // the folds
    if (folds_computed && fold.equations.size() == n + 1) {
      auto t4 = Clock::now();
      Solver_result<IT> fr = Subdivision_solver<IT>(parameters.scene.solver).solve(fold);
      st.fold_seconds += since(t4);
      st.fold_boxes += fr.statistics.boxes;
      auto t5 = Clock::now();
      for (const auto& u : fr.unresolved) unresolved(u, "fold system: ");
      for (const auto& root : fr.roots) {
        Family_fold f;
        f.certified = root.certified;
        f.charts = charts;
        {
          CGAL::Protect_FPU_rounding<true> guard;
          typedef CGAL::Interval_nt<false> I;
          const std::pair<double, double> e = CGAL::to_interval(root.enclosure[n]);
          I r2 = CGAL::to_interval(lo2) + I(e.first, e.second) * I(CGAL::to_interval(span));
          r2 = I((std::max)(0.0, r2.inf()), (std::max)(0.0, r2.sup()));
          const I len = CGAL::sqrt(r2);
          f.length = {len.inf(), len.sup()};
        }
        std::vector<double> x(root.approximation.begin(), root.approximation.end() - 1);
        f.configuration = configuration(r1, x);
        Residual_report rep = residuals(original, f.configuration);
        f.max_residual = rep.max();
        const double size = internal::configuration_size(f.configuration);
        if (!internal::verified(rep, parameters.scene.residual_threshold, size)) {
          if (internal::mirror_image(rep, parameters.scene.residual_threshold, size)) continue;  // a mirror image: not a configuration
          Scene_unresolved un;
          un.reason = "fold not verified in the original system (residual " + std::to_string(f.max_residual) + ")";
          un.charts = charts;
          for (const auto& e : root.enclosure) un.box.push_back(CGAL::to_interval(e));
          un.at_centre = f.configuration;
          out.unresolved.push_back(un);
          continue;
        }
        bool merged = false;
        for (std::size_t k = 0; k < folds.size() && !merged; ++k)
          if (internal::configuration_distance(folds[k].configuration, f.configuration) <=
              parameters.scene.merge_tolerance * (std::max)(size, fold_size[k])) {
            ++folds[k].found;
            if (!folds[k].certified && f.certified) { std::size_t m = folds[k].found; folds[k] = f; folds[k].found = m; }
            merged = true;
          }
        if (!merged) { folds.push_back(f); fold_size.push_back(size); }
      }
      st.verify_seconds += since(t5);
    }
  } while (internal::next_combination(charts, radix));

  auto t6 = Clock::now();
  std::vector<Scene_curve> curves = internal::join_pieces(pieces, 1e-7);
  for (auto& c : curves) {
    Family_branch br;
    for (const auto& conf : c.configurations) br.lengths.push_back(internal::configuration_length(conf, a, b));
    br.curve = std::move(c);
    out.branches.push_back(std::move(br));
  }
  std::sort(out.branches.begin(), out.branches.end(), [](const Family_branch& x, const Family_branch& y) {
    return *std::min_element(x.lengths.begin(), x.lengths.end()) < *std::min_element(y.lengths.begin(), y.lengths.end());
  });
  std::sort(folds.begin(), folds.end(), [](const Family_fold& x, const Family_fold& y) { return x.length.first < y.length.first; });
  // the distinct fold lengths (mirror-image folds share theirs), the counts between them, and
  // the change of the count across each
  std::vector<double> cuts{out.range.first};
  for (const auto& f : folds) {
    const double d = 0.5 * (f.length.first + f.length.second);
    if (f.length.first > cuts.back() + 1e-12 * (out.range.second - out.range.first) && d < out.range.second) cuts.push_back(d);
  }
  cuts.push_back(out.range.second);
  for (std::size_t k = 0; k + 1 < cuts.size(); ++k) {
    Family_count c;
    c.lo = cuts[k];
    c.hi = cuts[k + 1];
    c.count = out.count_at(0.5 * (c.lo + c.hi));
    out.counts.push_back(c);
  }
  for (auto& f : folds) {
    for (std::size_t k = 0; k + 1 < out.counts.size(); ++k)
      if (out.counts[k].hi >= f.length.first && out.counts[k].hi <= f.length.second + 1e-12 * (out.range.second - out.range.first)) {
        f.change = int(out.counts[k + 1].count) - int(out.counts[k].count);
        break;
      }
  }
  out.folds = std::move(folds);
  // the count may change only at a fold: sampled
  if (folds_computed && parameters.count_checks > 1) {
    const double w = out.range.second - out.range.first;
    std::size_t previous = out.count_at(out.range.first + 0.5 * w / double(parameters.count_checks));
    double previous_at = out.range.first;
    for (std::size_t k = 1; k < parameters.count_checks; ++k) {
      const double at = out.range.first + (double(k) + 0.5) * w / double(parameters.count_checks);
      const std::size_t now = out.count_at(at);
      if (now != previous) {
        bool explained = false;
        for (const auto& f : out.folds) explained = explained || (f.length.second >= previous_at - 1e-9 * w && f.length.first <= at + 1e-9 * w);
        if (!explained) {
          out.diagnosis = "the count of configurations changes near length " + std::to_string(at) + " where no fold was found";
          break;
        }
      }
      previous = now;
      previous_at = at;
    }
  }
  st.verify_seconds += since(t6);
  return out;
}

} // namespace Rigid_incidence
} // namespace CGAL

#endif
