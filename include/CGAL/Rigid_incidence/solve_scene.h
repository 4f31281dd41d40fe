// Copyright (c) 2026 Rigid_incidence contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The whole pipeline after the analysis: the reduced system in every chart combination (and
// every placement of a body known only by distances), the subdivision solver on each,
// back-substitution, verification in the original system, and one list of configurations in
// which roots found twice (on chart borders) are merged by comparing configurations. A scene
// with one degree of freedom (one equation fewer than parameters), and a scene the dof count
// calls finite whose solver finds a curve of solutions (the symmetric quad), gives curves of
// configurations instead: traced per chart combination by trace_curves and joined across
// chart borders by comparing configurations.

#ifndef CGAL_RIGID_INCIDENCE_SOLVE_SCENE_H
#define CGAL_RIGID_INCIDENCE_SOLVE_SCENE_H

#include <CGAL/Gmpz.h>
#include <CGAL/Rigid_incidence/Configuration.h>
#include <CGAL/Rigid_incidence/Curve_tracer.h>
#include <CGAL/Rigid_incidence/Reduced_system.h>
#include <CGAL/Rigid_incidence/Solution_plan.h>
#include <CGAL/Rigid_incidence/Subdivision_solver.h>
#include <CGAL/Rigid_incidence/enclose_coordinates.h>
#include <CGAL/Rigid_incidence/solve_tree_system.h>
#include <CGAL/Rigid_incidence/solve_with_plan.h>

#include <boost/graph/adjacency_list.hpp>
#include <boost/graph/connected_components.hpp>

#include <iterator>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <functional>
#include <iomanip>
#include <limits>
#include <map>
#include <mutex>
#include <cmath>
#include <array>
#include <optional>
#include <sstream>
#include <set>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Rigid_incidence {

/// \ingroup PkgRigidIncidenceSolver
/// An inequality constraint of a scene: the orientation of four labelled points A, B, C, D,
/// \f$\det(B - A, C - A, D - A) \ge 0\f$ (D on the side of the plane through A, B, C that
/// \f$(B - A) \times (C - A)\f$ points to), or \f$\le 0\f$ when `negative`.
struct Orientation_inequality
{
  std::array<std::string, 4> points;  ///< the labels A, B, C, D
  bool negative = false;              ///< the other side
};

/// \ingroup PkgRigidIncidenceSolver
/// How far a `solve_scene()` has got, as `Scene_solve_parameters::progress` is told.
struct Scene_solve_progress
{
  std::size_t combinations_done = 0;   ///< combinations of charts and placements solved (at this precision)
  std::size_t combinations_total = 0;  ///< how many there are (0: more than \f$2^{62}\f$)
  std::size_t boxes = 0;               ///< boxes the solver has examined so far (at this precision)
  std::size_t configurations = 0;      ///< configurations found so far (at this precision)
  unsigned coefficient_precision = 53; ///< bits of the coefficients of this pass (0: exact)
  double seconds = 0;                  ///< since the solve began (all precisions)
};

/// \ingroup PkgRigidIncidenceSolver
/// Parameters of `solve_scene()`.
struct Scene_solve_parameters
{
  /// inequality constraints: configurations that violate one are not returned, and boxes where
  /// one fails are discarded during the solve; a configuration on an inequality's boundary is
  /// kept and marked
  std::vector<Orientation_inequality> inequalities;
  /// parameters of the solver, for each chart combination
  Subdivision_solver_parameters solver;
  /// two roots of two chart combinations (with the same placements) are one configuration if no
  /// point moves more than this, relative to the size of the scene (the bounding box diagonal
  /// of the configuration); roots of one system, and of two placements of a body, are never merged
  double merge_tolerance = 1e-9;
  /// a root whose configuration has a residual above this in the original system (relative
  /// to the size of the scene for incidences, to its square for squared distances) is not a
  /// configuration of the scene (a body outside the covering set that only fits mirrored);
  /// it is counted in `Scene_solve_statistics::spurious`
  double residual_threshold = 1e-6;
  /// the most placements enumerated for one body known by distances (see
  /// `enumerate_placements()`); a body with more is solved for the first ones only and the
  /// result is not complete (`Scene_solve_result::limits` says so)
  std::size_t maximal_placements = default_maximal_placements;
  /// the most bits the reduced system's coefficients are raised to, when they are enclosed in
  /// intervals (`NT` = `CGAL::Interval_nt<false>` or `CGAL::Gmpfi`) and the answer is not
  /// complete for a reason wide coefficients can cause (a positive-dimensional diagnosis, an
  /// unknown region, a configuration not certified): the scene is solved again with
  /// `CGAL::Gmpfi` coefficients and solver at 128, 256, ... bits, up to this, until the
  /// answer is complete (needs MPFI; below 128: never). `Scene_solve_result::precision_history`
  /// says what each lower precision gave.
  unsigned maximal_coefficient_precision = 256;
  /// Wall-clock limit in seconds for the whole solve, precision retries included (0: none).
  /// When it is reached the combinations of charts and placements not yet solved are left
  /// out, the solve under way keeps what it certified and leaves the rest pending, and
  /// `Scene_solve_result::limits` says "time limit of S s reached ..." (the answer is not
  /// complete); a precision retry it cuts short is dropped for the answer before it. The
  /// placements are enumerated before it is looked at (see the manual's table of limits).
  double maximal_seconds = 0;
  /// A flag another thread or a signal handler may set (null: none): the solve stops as the
  /// time limit does, and `limits` says "interrupted".
  const std::atomic<bool>* interrupt = nullptr;
  /// Build the reduced systems of a placement combination's chart combinations by a change of
  /// chart of the one of chart 0 (`Reduced_system(base, charts)`: coefficients moved, not
  /// computed again), where the scene allows it (quaternion charts, no free body); false: a
  /// new reduction for each (the tests' oracle).
  bool change_charts = true;
  /// Solve a reduced system whose solution plan (`Solution_plan`) has more than one block
  /// along it, with `solve_with_plan()`: the blocks one after the other, each root of a block
  /// substituted, as its certified enclosure, into the blocks after it (two stacked platforms:
  /// two blocks of 6 variables, where the whole system of 12 is beyond the dense arrays). A
  /// plan whose solve ends with a diagnosis (a block not zero-dimensional) or throws is
  /// dropped and the system solved whole. false: always whole (the tests' oracle).
  bool solve_with_plan = true;
  /// With `solve_with_plan`: the plan's blocks choose the charts of their own tree edges
  /// (`solve_with_plan_over_charts()`: a block is solved once per chart of its own edges and
  /// root of the blocks before it, not once per combination of every edge's charts), where the
  /// reduced system is square with more than one block, in a first pass. false: each chart
  /// combination solved along its plan alone (the tests' oracle).
  bool plan_over_charts = true;
  /// With `plan_over_charts`: a reduced system that falls into independent parts (no
  /// equation, inequality or tree edge joins them: `independent_parts()`, e.g. one per plate of
  /// stacked platforms) is solved part by part, each over its own edges' charts, and answered
  /// factored: the scene's configurations are the product of the parts' solutions
  /// (`Scene_solve_result::parts`), counted exactly and listed up to
  /// `maximal_listed_configurations`. Not where a body outside the covering set has several
  /// placements (its fit depends on every part). false: every full chart assignment listed
  /// from one plan over the charts (the tests' oracle).
  bool factor_parts = true;
  /// The most configurations `Scene_solve_result::configurations` lists (0: no limit). The
  /// count (`Scene_solve_result::configuration_count`) stays exact and the answer complete when
  /// the list is cut; `Scene_solve_result::listing` says so. A factored answer's product is
  /// expanded only up to it (and, in time, up to `maximal_seconds`).
  std::size_t maximal_listed_configurations = 10000;
  /// Before the chart combinations of a scene whose incidence tree is made of hinges (and
  /// whose covering bodies all have coordinates) are built, choose the hinges' charts lazily
  /// along the tree (`solve_tree_system()` with `Tree_solver_parameters::charts_only`: the
  /// equations evaluated through the tree, never expanded, each contracting the hinges it
  /// involves): a combination every box of which that propagation excludes is never built nor
  /// solved (`Scene_solve_statistics::excluded_by_propagation`). false: every combination
  /// (the tests' oracle).
  bool chart_propagation = true;
  /// A scene whose incidence tree is made of hinges (covering bodies with coordinates, no
  /// bodies known by distances, no free points), whose system is square and has a sweep order
  /// with a driver (`sweep_order()`: a chain of hinges braced by distances between near
  /// neighbours) and at least `sweep_from` chart combinations is solved along its tree
  /// (`solve_tree_system()`: the driver hinge bisected, every other hinge found from its
  /// equation in turn, the charts chosen per box) instead of combination by combination: no
  /// equation is expanded (a chain's closing distance has 3^(k-1) terms) and the work follows
  /// the real branches, not the 2^(k-1) chart combinations (`Scene_solve_statistics::swept`).
  /// false: never (the tests' oracle).
  bool sweep = true;
  /// the fewest chart combinations for which `sweep` is used (below, the expanded systems are
  /// solved faster: chain of 6 tetrahedra, 32 combinations, 0.09 s expanded and 0.12 s swept)
  std::size_t sweep_from = 64;
  /// the cells per chart of a hinge of the arc consistency that `solve_tree_system()` runs
  /// before the sweep and the chart propagation (`Tree_solver_parameters::consistency_cells`; 0:
  /// none; anything but 0 or a power of 2 from 2 to 65536: `solve_scene()` throws an
  /// `Input_error` before it starts)
  std::size_t consistency_cells = 512;
  /// Called once before the first combination of charts and placements is solved and after each
  /// one (empty: never), one call
  /// at a time and in the order of the combinations, from the thread that called
  /// `solve_scene()` or, with `solver.threads` other than 1, from any thread of the solve; the
  /// command-line tool prints it on a terminal.
  std::function<void(const Scene_solve_progress&)> progress;
};

/// \ingroup PkgRigidIncidenceSolver
/// One configuration of a scene.
struct Scene_configuration
{
  bool certified = false;                             ///< the root is certified (Krawczyk)
  bool on_chart_border = false;                       ///< the root lies on the border of its chart's box
  bool on_inequality_boundary = false;                ///< some inequality may be 0 there (kept)
  std::vector<int> charts;                            ///< chart combination it was found in (first)
  std::vector<int> placements;                        ///< placement variant per body
  std::vector<std::string> variables;                 ///< names of the parameters
  std::vector<std::pair<double, double>> parameters;  ///< per parameter: its certified enclosure
  Configuration configuration;                        ///< every body's pose, every point
  Residual_report residuals;                          ///< in the original system
  double max_residual = 0;                            ///< `residuals.max()` (absolute: lengths and squared lengths)
  /// the largest residual relative to the configuration's size (the diagonal of its bounding
  /// box): incidences and body fits divided by it, squared distances by its square; this is
  /// what `Scene_solve_parameters::residual_threshold` bounds (infinity: mirrored or unplaced)
  double max_relative_residual = 0;
  std::size_t found = 1;                              ///< chart combinations it was found in
  /// a double configuration: a body's placement in it is a double one (a point exactly on the
  /// plane of the three points it is placed from, decided exactly); the enclosure is certified,
  /// but the configuration is not a simple root: a perturbation of the distances splits it
  /// into two or none
  bool singular = false;
  std::string singular_reason;                        ///< where, when `singular`
  /// bits of the reduced system's coefficients in the solve that gave it: 53 for double
  /// intervals, the MPFR precision of a retry (see
  /// `Scene_solve_parameters::maximal_coefficient_precision`), 0 for exact rationals
  unsigned coefficient_precision = 53;
};

/// \ingroup PkgRigidIncidenceSolver
/// A region of one chart combination the solver could not decide.
struct Scene_unresolved
{
  Box_class kind = Box_class::UNKNOWN;                ///< `UNKNOWN` or `PENDING`
  std::string reason;                                 ///< why
  std::vector<int> charts;                            ///< chart combination
  std::vector<int> placements;                        ///< placement variant per body
  std::vector<std::pair<double, double>> box;         ///< per parameter
  std::size_t boxes = 1;                              ///< boxes merged into it
  Configuration at_centre;                            ///< the configuration at the box centre
};

/// \ingroup PkgRigidIncidenceSolver
/// The part of a `Scene_curve` traced in one chart combination.
struct Scene_curve_piece
{
  std::vector<int> charts;                          ///< chart combination
  std::vector<int> placements;                      ///< placement variant per body
  std::vector<std::vector<double>> parameters;      ///< the polyline in this chart's parameters
};

/// \ingroup PkgRigidIncidenceSolver
/// One branch of a curve of configurations: the motion of a scene with one degree of freedom.
struct Scene_curve
{
  /// the topology is certified: every piece certified by `trace_curves()` and joined to the
  /// next across a chart border where both end in the same configuration
  bool certified = true;
  bool closed = false;                              ///< a loop
  Curve_end ends[2] = {Curve_end::CLOSED, Curve_end::CLOSED};  ///< `BOUNDARY` does not occur (charts cover every rotation)
  std::vector<Configuration> configurations;        ///< the scene along the branch, in order
  std::vector<Scene_curve_piece> pieces;            ///< the chart pieces, in order
  double max_residual = 0;                          ///< largest residual in the original system along it
  bool on_inequality_boundary = false;              ///< an inequality clips it (to the tracer's minimal width)
  /// empty, or what limits the claim: e.g. the equation left out to trace a curve of a square
  /// system (checked to vanish at every point, not proved)
  std::string note;
};

/// \ingroup PkgRigidIncidenceSolver
/// A solution of one independent part of a scene's reduced system (see `Scene_part`).
struct Scene_part_solution
{
  bool certified = false;                             ///< the part's root is certified
  bool on_chart_border = false;                       ///< it lies on the border of its chart's box
  bool on_inequality_boundary = false;                ///< some inequality may be 0 there
  /// per chart group of the reduced system (tree edge), its chart: those of the part's own
  /// edges (the other entries are 0 and do not matter)
  std::vector<int> charts;
  std::vector<std::pair<double, double>> parameters;  ///< per variable of the part: its enclosure
  std::size_t found = 1;                              ///< chart assignments it was found in
};

/// \ingroup PkgRigidIncidenceSolver
/// An independent part of a scene's reduced system in one combination of placements: a set of
/// tree edges no equation links to the others (`independent_parts()`). The scene's
/// configurations with these placements are the product of its parts' solutions: one solution
/// per part, their parameters side by side (`Scene_solve_parameters::factor_parts`).
struct Scene_part
{
  std::vector<int> placements;                  ///< the placement combination it belongs to
  std::vector<std::string> variables;           ///< its variables (names of the reduced system's)
  std::vector<std::size_t> variable_indices;    ///< their indices in the reduced system
  /// the bodies its tree edges place, each relative to its parent in the incidence tree
  std::vector<std::string> bodies;
  /// its distinct solutions, each verified in the original system with one solution of every
  /// other part (a constraint involves one part's edges only: the residuals of the product's
  /// configurations are those of their parts)
  std::vector<Scene_part_solution> solutions;
  std::size_t unresolved = 0;  ///< regions it left undecided (in `Scene_solve_result::unresolved`)
};

/// \ingroup PkgRigidIncidenceSolver
/// Statistics of `solve_scene()`.
struct Scene_solve_statistics
{
  /// threads the solve ran on (`Subdivision_solver_parameters::threads`; 1 without oneTBB);
  /// the seconds below are summed over them
  unsigned threads = 1;
  std::size_t chart_combinations = 0;      ///< systems solved (chart combinations x placements)
  std::size_t excluded_at_once = 0;        ///< of those, excluded on their first box
  double excluded_at_once_seconds = 0;     ///< solver time spent on those
  std::size_t boxes = 0;                   ///< boxes visited, all systems
  std::size_t krawczyk_tests = 0;          ///< all systems
  std::size_t roots = 0;                   ///< roots before merging
  std::size_t duplicates = 0;              ///< roots merged into a configuration found before
  std::size_t spurious = 0;                ///< roots rejected: a body would have to be mirrored
  /// combinations of placements not solved: two bodies put two shared points at distances
  /// that certainly differ (their enclosures are disjoint), so no configuration has them
  std::size_t placements_excluded = 0;
  /// the widest coefficient enclosure of the reduced systems solved, relative to the largest
  /// coefficient of its equation (0: exact coefficients)
  double coefficient_width = 0;
  /// systems solved along their solution plan (more than one block;
  /// `Scene_solve_parameters::solve_with_plan`)
  std::size_t planned_systems = 0;
  /// the block solves those took (a block once per combination of the roots before it, and
  /// per chart of its own hinges)
  std::size_t block_solves = 0;
  /// block solves reused, not run again: a block no earlier value enters (an independent part
  /// of the reduced system) is solved once per chart of its own edges
  /// (`Plan_result::block_solves_reused`)
  std::size_t block_solves_reused = 0;
  /// chart combinations never built: solved along the plan over the charts
  /// (`solve_with_plan_over_charts()`), a block before their last had no root in its charts
  std::size_t excluded_by_plan = 0;
  /// chart combinations never built: propagating the equations along the tree of hinges
  /// excluded every box of theirs (`Scene_solve_parameters::chart_propagation`)
  std::size_t excluded_by_propagation = 0;
  /// the scene was solved along its tree by a sweep (`Scene_solve_parameters::sweep`), not per
  /// chart combination; `boxes` and `krawczyk_tests` are then the sweep's
  bool swept = false;
  /// per hinge, the fraction of its circle arc consistency kept before the sweep or the chart
  /// propagation (`Scene_solve_parameters::consistency_cells`; `Tree_solve_result::
  /// consistent_fraction`); empty when neither ran it
  std::vector<double> consistent_fraction;
  double consistency_seconds = 0;          ///< its time (in `solve_seconds` too)
  std::size_t curve_boxes = 0;             ///< boxes visited by the curve tracer, all systems
  double reduce_seconds = 0;               ///< building the reduced systems
  double solve_seconds = 0;                ///< the subdivision solver
  double verify_seconds = 0;               ///< back-substitution and residuals
};

/// \ingroup PkgRigidIncidenceSolver
/// How the placements of one body known by distances were enumerated (see `enumerate_placements()`).
struct Scene_placement_report
{
  std::string body;             ///< the body of the standard collection
  std::size_t placements = 0;   ///< placements found (all of them when `complete`)
  bool complete = true;         ///< false: stopped at `Scene_solve_parameters::maximal_placements`
  unsigned precision = 53;      ///< bits of the interval arithmetic that enclosed them (53: double)
  double relative_width = 0;    ///< widest coordinate enclosure, relative to the body's size (or to the coordinate, where larger)
  std::string singular;         ///< nonempty: every placement is a double one, and where
  std::string inconsistent;     ///< nonempty: no real placement (decided exactly), and why
  /// nonempty: a choice left undecided at the final precision (see
  /// `Placement_enumeration::undecided`); the result is then not complete
  std::string undecided;  /// the choices intervals left open were made in exact arithmetic (see
  /// `Placement_enumeration::decided_exactly`)
  bool decided_exactly = false;
};

/// \ingroup PkgRigidIncidenceSolver
/// What `solve_scene()` found.
struct Scene_solve_result
{
  std::vector<Scene_configuration> configurations; ///< in a stable order (by point coordinates)
  std::vector<Scene_unresolved> unresolved;        ///< unknown and pending regions
  /// the curves of configurations of a scene with one degree of freedom (or of a scene the dof
  /// count calls finite that flexes: then `diagnosis` says "positive_dimensional")
  std::vector<Scene_curve> curves;
  /// empty, or what was found: "positive_dimensional: ...", "under_constrained: ...",
  /// "over_constrained: ..."
  std::string diagnosis;
  bool fast = false;                               ///< solved in the fast, non-certified mode
  std::vector<std::string> variables;              ///< the reduced system's parameters
  std::size_t equations = 0;                       ///< the reduced system's equations
  Scene_solve_statistics statistics;              ///< counters and times per stage
  /// per body known by distances: its placements, the precision that enclosed them
  std::vector<Scene_placement_report> placements;
  /// every limit that cut the search short, and what it left out (then the result is not complete)
  std::vector<std::string> limits;
  /// the number of configurations found, exact: `configurations.size()` unless the list was
  /// cut (`listing`); the product of the parts' solutions where the answer is factored
  CGAL::Gmpz configuration_count = 0;
  /// the independent parts of a factored answer, per combination of placements (empty: the
  /// answer is not factored); see `Scene_solve_parameters::factor_parts`
  std::vector<Scene_part> parts;
  /// empty when `configurations` lists every configuration found; else why the list stops
  /// (`Scene_solve_parameters::maximal_listed_configurations`, or the time limit reached while
  /// a factored answer was expanded). The count and the completeness do not depend on it.
  std::string listing;
  /// nonempty: the scene has no real configuration, decided exactly, and why (the result is
  /// complete with no configuration)
  std::string no_configuration;
  /// the scene was solved scaled by 2^-`scale_exponent` (exactly), at unit size, when its size
  /// is beyond 2^+-20 (see `solve_scene()`); configurations, residuals and unresolved
  /// regions' centres are given back at the scene's own scale, parameters and curves'
  /// `max_residual` stay those of the scaled scene
  long scale_exponent = 0;
  /// bits of the reduced system's coefficients in this answer: 0 for exact rationals
  /// (`NT = CGAL::Gmpq`), 53 for double intervals, the MPFR precision for `CGAL::Gmpfi`
  unsigned coefficient_precision = 53;
  /// the answers at lower coefficient precisions that this one replaced (see
  /// `Scene_solve_parameters::maximal_coefficient_precision`), each as "53 bits: why it was
  /// not enough (coefficients W wide, T s)"
  std::vector<std::string> precision_history;
  /// configurations counted but not listed (see `listing`) that are not certified
  std::size_t unlisted_not_certified = 0;
  /// every configuration certified (listed or not: the parts' solutions too), nothing
  /// unresolved and no limit reached
  bool complete() const
  {
    if (fast || !unresolved.empty() || !diagnosis.empty() || !limits.empty() || unlisted_not_certified > 0) return false;
    for (const auto& c : configurations) if (!c.certified) return false;
    for (const auto& c : curves) if (!c.certified) return false;
    for (const auto& q : parts)
      for (const auto& x : q.solutions) if (!x.certified) return false;
    return true;
  }
};

namespace internal {

inline Scene_placement_report placement_report(const std::string& body, const Placement_enumeration<CGAL::Interval_nt<false>>& e)
{
  Scene_placement_report r;
  r.body = body;
  r.placements = e.placements.size();
  r.complete = e.complete;
  r.precision = e.precision;
  r.relative_width = e.relative_width;
  r.singular = e.singular;
  r.inconsistent = e.inconsistent;
  r.undecided = e.undecided;
  r.decided_exactly = e.decided_exactly;
  return r;
}

// The placements of every covering body known only by distances, and of every body outside
// the covering set whose equations depend on its placement (holds_pair_through_placement());
// counts: 1 for the others. Reports and singular reasons for the covering bodies only (the
// others are reported with the bodies outside the covering set).
template <class Traits>
std::vector<int> placement_counts(const Rigid_body_collection<Traits>& c, const Incidence_tree& tree, std::size_t maximal = default_maximal_placements,
                                  std::vector<Scene_placement_report>* reports = nullptr, std::vector<std::string>* singular = nullptr)
{
  std::vector<int> n(c.number_of_bodies(), 1);
  if (singular) singular->assign(c.number_of_bodies(), std::string());
  for (std::size_t b : tree.covering_set) {
    if (c.body(b).all_coordinates()) continue;
    auto e = cached_placements<CGAL::Interval_nt<false>>(c, b, maximal);
    n[b] = (std::max)(1, int(e->placements.size()));
    if (singular) (*singular)[b] = e->singular;
    if (reports) reports->push_back(placement_report(c.body(b).name, *e));
  }
  for (std::size_t b : tree.non_covering)
    if (holds_pair_through_placement(c, tree, b))
      n[b] = (std::max)(1, int(cached_placements<CGAL::Interval_nt<false>>(c, b, maximal)->placements.size()));
  return n;
}

// Whether body b, outside the covering set, has placements the solve enumerates per root (each
// a configuration of its own): one of its points is on no covering body (else the system's
// equations fix it whatever its placement), and its equations do not depend on its placement
// (holds_pair_through_placement(): then it is enumerated with the covering bodies).
template <class Traits>
bool own_points_outside(const Rigid_body_collection<Traits>& c, const Incidence_tree& tree, std::size_t b)
{
  if (c.body(b).all_coordinates() || holds_pair_through_placement(c, tree, b)) return false;
  std::vector<bool> covered(c.number_of_points(), false);
  for (std::size_t k : tree.covering_set) for (std::size_t q : c.body(k).points) covered[q] = true;
  return std::any_of(c.body(b).points.begin(), c.body(b).points.end(), [&](std::size_t q) { return !covered[q]; });
}

// Whether solve_scene() solves a tree of hinges by one sweep (Scene_solve_parameters::sweep),
// said the same way to scene_solve_work(): its Tree_system is square with a sweep order that
// has a driver, it has at least `sweep_from` chart combinations (2 per hinge, so 2^n: no
// product that saturates), a single combination of placements, and no body outside the
// covering set whose placements are enumerated per root (`per_root`).
template <class Traits>
bool sweeps(const Tree_system<Traits>& ts, const Sweep_order& o, std::size_t placement_combinations, bool per_root, std::size_t sweep_from)
{
  const std::size_t n = ts.number_of_variables();
  const std::size_t from = (std::max<std::size_t>)(sweep_from, 2);
  const bool enough = n >= std::size_t(std::numeric_limits<std::size_t>::digits) - 1 || (std::size_t(1) << n) >= from;
  return ts.is_square() && o.exists(n) && o.driver != Sweep_order::none && enough && placement_combinations == 1 && !per_root;
}

} // namespace internal

/*!
\ingroup PkgRigidIncidenceSolver
\brief The size of a scene's solve, known before it runs (what `rigid_incidence reduce` and
`analyze` report): the combinations of charts and placements for which `solve_scene()` builds
and solves one reduced system each, and the structure of that system.
*/
struct Scene_solve_work
{
  std::size_t chart_combinations = 1;      ///< the product of the charts of every tree edge
  /// the product of the placements of the bodies enumerated with the charts (the covering
  /// bodies known by distances, and those outside whose equations depend on their placement)
  std::size_t placement_combinations = 1;
  /// those bodies with more than one placement, and how many each has
  std::vector<std::pair<std::string, std::size_t>> placements;
  std::size_t variables = 0;  ///< of the reduced system
  std::size_t equations = 0;  ///< of the reduced system
  /// the variables of each block of the reduced system's solution plan (`Solution_plan`), in
  /// the order they would be solved; one block: the system is solved whole
  std::vector<std::size_t> block_sizes;
  /// the parts of the reduced system no equation (in chart 0) or tree edge links
  /// (`independent_parts()`): the scene's configurations are the product of theirs, and
  /// `solve_scene()` answers factored where the equations of every chart and the orientation
  /// inequalities keep them apart too (`Scene_solve_parameters::factor_parts`)
  std::size_t independent_parts = 0;
  /// the variable of the hinge a sweep along the tree would drive (`Scene_solve_parameters::
  /// sweep`: a tree of hinges whose system has a sweep order with a driver, at least `sweep_from`
  /// chart combinations, every body in the covering set, one placement combination); empty: not
  /// solved so. No reduced system is then built, here nor by the solve.
  std::string sweep_driver;
  std::size_t sweep_steps = 0;   ///< the hinges the sweep finds from its equations in turn
  std::size_t sweep_checks = 0;  ///< the equations left to check (a chain's closing distance)
  /// chart_combinations x placement_combinations (saturating at SIZE_MAX): the most reduced
  /// systems a full solve builds and subdivides (fewer when two bodies' placements put a shared
  /// pair of points at certainly different distances: `Scene_solve_statistics::placements_excluded`)
  std::size_t systems() const
  {
    if (placement_combinations != 0 && chart_combinations > (std::numeric_limits<std::size_t>::max)() / placement_combinations)
      return (std::numeric_limits<std::size_t>::max)();
    return chart_combinations * placement_combinations;
  }
};

namespace internal {

// per variable of a reduced system, the tree edge whose chart chooses it (its rotation or
// translation parameters; none: -1): the groups independent_parts() keeps together
template <class Parametrization>
std::vector<std::size_t> chart_groups(const Parametrization& p, std::size_t variables)
{
  std::vector<std::size_t> group(variables, std::size_t(-1));
  const auto& edges = p.edges();
  for (std::size_t k = 0; k < edges.size(); ++k) {
    for (std::size_t v : edges[k].rotation) if (v < variables) group[v] = k;
    for (std::size_t v : edges[k].translation) if (v < variables) group[v] = k;
  }
  return group;
}

} // namespace internal

/*!
\ingroup PkgRigidIncidenceSolver
\brief The size of the solve of the standard collection `c` on `tree` and `selection` (the
arguments of `solve_scene()`), before it runs: it enumerates the placements of the bodies known
by distances (cached for the solve) and builds the reduced system of the first combination, or,
for a tree of hinges, its `Tree_system` (the same equations, never expanded: a chain of 16
hinged tetrahedra's closing distance would have 3^15 terms). `sweep_from`: as
`Scene_solve_parameters::sweep_from`.
*/
template <class Traits>
Scene_solve_work scene_solve_work(const Rigid_body_collection<Traits>& c, const Incidence_tree& tree,
                                  const Well_formed_selection& selection, std::size_t maximal_placements = default_maximal_placements,
                                  std::size_t sweep_from = Scene_solve_parameters().sweep_from)
{
  Scene_solve_work w;
  auto times = [](std::size_t a, std::size_t b) {
    return b != 0 && a > (std::numeric_limits<std::size_t>::max)() / b ? (std::numeric_limits<std::size_t>::max)() : a * b;
  };
  const std::vector<int> n = internal::placement_counts(c, tree, maximal_placements);
  for (std::size_t b = 0; b < n.size(); ++b)
    if (n[b] > 1) {
      w.placements.emplace_back(c.body(b).name, std::size_t(n[b]));
      w.placement_combinations = times(w.placement_combinations, std::size_t(n[b]));
    }
  internal::Rounding_guard<CGAL::Interval_nt<false>> guard;
  std::vector<std::vector<std::size_t>> support;
  std::vector<std::size_t> group;
  // a tree of hinges: its Tree_system (the same equations as the reduced system, in the same
  // order, one variable per hinge, two charts each), never expanded
  std::optional<Tree_system<Traits>> ts;
  if (Tree_system<Traits>::unsupported(c, tree).empty()) {
    try { ts.emplace(c, tree, selection); } catch (const Input_error&) {}  // (then expanded, as any scene)
  }
  if (ts) {
    w.variables = ts->number_of_variables();
    w.equations = ts->number_of_equations();
    for (std::size_t k = 0; k < w.variables; ++k) w.chart_combinations = times(w.chart_combinations, 2);
    for (const auto& e : ts->equations()) support.push_back(e.variables);
    for (std::size_t k = 0; k < w.variables; ++k) group.push_back(k);
    const Sweep_order o = ts->is_square() ? sweep_order(*ts) : Sweep_order();
    bool per_root = false;
    for (std::size_t b : tree.non_covering)
      per_root = per_root || (internal::own_points_outside(c, tree, b) &&
                              internal::cached_placements<CGAL::Interval_nt<false>>(c, b, maximal_placements)->placements.size() > 1);
    if (internal::sweeps(*ts, o, w.placement_combinations, per_root, sweep_from)) {
      w.sweep_driver = ts->parametrization(0).variable_names()[o.driver];
      w.sweep_steps = o.steps.size();
      w.sweep_checks = o.checks.size();
    }
  } else {
    const Reduced_system<Traits, CGAL::Interval_nt<false>> r(c, tree, selection);
    for (const auto& e : r.parametrization().edges()) w.chart_combinations = times(w.chart_combinations, std::size_t(e.number_of_charts));
    w.variables = r.number_of_variables();
    w.equations = r.number_of_equations();
    for (const auto& e : r.equations()) support.push_back(e.variables);
    group = internal::chart_groups(r.parametrization(), w.variables);
  }
  const Solution_plan plan(w.variables, support);
  for (const auto& b : plan.blocks()) w.block_sizes.push_back(b.variables.size());
  w.independent_parts = independent_parts(w.variables, support, {}, group).size();
  return w;
}

namespace internal {

// "8 chart combinations x 4 placement combinations (body 'I2': 2, 'I3': 2) = at most 32
// reduced systems; 3 equations in 3 variables: 1 block of 3, 1 independent part"
inline std::string describe_work(const Scene_solve_work& w)
{
  std::ostringstream o;
  o << w.chart_combinations << " chart combination" << (w.chart_combinations == 1 ? "" : "s") << " x " << w.placement_combinations
    << " placement combination" << (w.placement_combinations == 1 ? "" : "s");
  if (!w.placements.empty()) {
    o << " (";
    for (std::size_t k = 0; k < w.placements.size(); ++k)
      o << (k ? ", " : "") << "body '" << w.placements[k].first << "': " << w.placements[k].second;
    o << ")";
  }
  o << " = " << (w.systems() == (std::numeric_limits<std::size_t>::max)() ? std::string("over 1.8e19") : std::to_string(w.systems()))
    << " reduced system" << (w.systems() == 1 ? "" : "s") << " at most; " << w.equations << " equation" << (w.equations == 1 ? "" : "s")
    << " in " << w.variables << " variable" << (w.variables == 1 ? "" : "s") << ": ";
  std::size_t largest = 0;
  for (std::size_t b : w.block_sizes) largest = (std::max)(largest, b);
  o << w.block_sizes.size() << " block" << (w.block_sizes.size() == 1 ? "" : "s") << " (largest: " << largest << " variable"
    << (largest == 1 ? "" : "s") << "), " << w.independent_parts << " independent part" << (w.independent_parts == 1 ? "" : "s");
  if (!w.sweep_driver.empty())
    o << "; solved along the tree by one sweep driven by " << w.sweep_driver << " (" << w.sweep_steps << " hinge" << (w.sweep_steps == 1 ? "" : "s")
      << " found in turn, " << w.sweep_checks << " equation" << (w.sweep_checks == 1 ? "" : "s") << " checked), no reduced system built";
  return o.str();
}

// The widest coefficient enclosure of a system, relative to the largest coefficient of its
// equation (0 for exact coefficients).
template <class NT>
double coefficient_width(const Polynomial_system<NT>& s)
{
  double w = 0;
  for (const auto& f : s.equations) {
    double big = 0, wide = 0;
    for (const auto& t : f.terms()) {
      const std::pair<double, double> i = CGAL::to_interval(t.second);
      big = (std::max)(big, (std::max)(std::abs(i.first), std::abs(i.second)));
      wide = (std::max)(wide, i.second - i.first);
    }
    if (big > 0) w = (std::max)(w, wide / big);
  }
  return w;
}

// Seconds as a person reads them: 2 significant digits below 10 s, whole seconds above.
inline std::string seconds_text(double x)
{
  std::ostringstream os;
  if (x < 10) os << std::setprecision(2) << x;
  else os << std::fixed << std::setprecision(0) << x;
  return os.str();
}

inline std::string short_number(double x)
{
  std::ostringstream os;
  os.precision(2);
  os << x;
  return os.str();
}

// Advances a mixed-radix counter; false when it wraps around.
inline bool next_combination(std::vector<int>& v, const std::vector<int>& radix)
{
  for (std::size_t i = 0; i < v.size(); ++i) {
    if (++v[i] < radix[i]) return true;
    v[i] = 0;
  }
  return false;
}

inline double configuration_distance(const Configuration& a, const Configuration& b)
{
  double d = 0;
  for (std::size_t i = 0; i < a.points.size() && i < b.points.size(); ++i) {
    if (a.placed[i] != b.placed[i]) return std::numeric_limits<double>::infinity();
    if (!a.placed[i]) continue;
    for (int k = 0; k < 3; ++k) d = (std::max)(d, std::abs(a.points[i][k] - b.points[i][k]));
  }
  return d;
}

inline double configuration_size(const Configuration& a)
{
  double lo[3] = {0, 0, 0}, hi[3] = {0, 0, 0};
  bool first = true;
  for (std::size_t i = 0; i < a.points.size(); ++i) {
    if (!a.placed[i]) continue;
    for (int k = 0; k < 3; ++k) {
      if (first || a.points[i][k] < lo[k]) lo[k] = a.points[i][k];
      if (first || a.points[i][k] > hi[k]) hi[k] = a.points[i][k];
    }
    first = false;
  }
  // the diagonal of the bounding box, without overflow (a point at 1e308 has a size)
  double big = 0;
  for (int k = 0; k < 3; ++k) big = (std::max)(big, hi[k] - lo[k]);
  if (!(big > 0)) return 1.0;
  if (!std::isfinite(big)) return std::numeric_limits<double>::max();
  double s = 0;
  for (int k = 0; k < 3; ++k) s += ((hi[k] - lo[k]) / big) * ((hi[k] - lo[k]) / big);
  return big * std::sqrt(s);
}

// A configuration satisfies the original system: incidences and body fits (lengths) within
// `threshold` times the scene's size, distances (squared lengths) within `threshold` times its
// square, nothing mirrored or unplaced.
inline bool verified(const Residual_report& r, double threshold, double size)
{
  if (!r.complete || r.mirrored) return false;
  return r.max_incidence <= threshold * size && r.max_distance <= threshold * size * size;
}

// A root of a system blind to handedness that is a mirror image, not a configuration: some
// body fits only mirrored, and with those bodies mirrored every residual is within the
// threshold (so the points are an exact mirrored solution, not points that fit no body: those
// are not verified, and are said so, never dropped).
inline bool mirror_image(const Residual_report& r, double threshold, double size)
{
  return r.complete && r.mirrored && r.max_incidence_mirrored <= threshold * size && r.max_distance_mirrored <= threshold * size * size;
}

// The largest residual relative to `size` (see Scene_configuration::max_relative_residual).
inline double relative_residual(const Residual_report& r, double size)
{
  if (!r.complete || r.mirrored) return std::numeric_limits<double>::infinity();
  return (std::max)(r.max_incidence / size, r.max_distance / size / size);
}

// About log2 |x| for x != 0 through a double (the overload for Gmpq, exact at any size, is in
// Polynomial_system.h).
template <class FT>
long binary_exponent(const FT& x)
{
  const double d = CGAL::to_double(x);
  if (!std::isfinite(d)) return 1100;
  if (d == 0) return -1100;
  int e = 0;
  std::frexp(d, &e);
  return e;
}

// The size of a collection as a power of two: the largest exponent of the coordinates of the
// points that enter the reduced system (points of two or more bodies, ends of distances) and
// of the distances (half the exponent of the squared ones). A point of one body alone does
// not count: a frame point at 1e308 does not make a unit-size hinge tiny.
template <class Traits>
long size_exponent(const Rigid_body_collection<Traits>& c)
{
  typedef typename Rigid_body_collection<Traits>::Body Body;
  std::vector<int> uses(c.number_of_points(), 0);
  for (const auto& b : c.bodies()) for (std::size_t q : b.points) ++uses[q];
  for (const auto& d : c.distances()) { uses[d.a] += 2; uses[d.b] += 2; }
  long hi = 0;
  bool any = false;
  auto see = [&](const typename Traits::FT& v, long div) {
    if (v == 0) return;
    const long e = binary_exponent(v) / div;
    hi = any ? (std::max)(hi, e) : e;
    any = true;
  };
  std::function<void(const Body&)> body = [&](const Body& b) {
    for (std::size_t i = 0; i < b.points.size(); ++i)
      if (b.has_coordinates[i] && b.points[i] < uses.size() && uses[b.points[i]] >= 2) {
        see(Traits::x(b.coordinates[i]), 1);
        see(Traits::y(b.coordinates[i]), 1);
        see(Traits::z(b.coordinates[i]), 1);
      }
    for (const auto& d : b.squared_distances) see(d.squared, 2);
    for (const auto& part : b.parts) body(part);
  };
  for (const auto& b : c.bodies()) body(b);
  for (const auto& d : c.distances()) see(d.squared, 2);
  return hi;
}

// The collection with every length multiplied by 2^e, exactly (coordinates, distances, parts).
template <class Traits>
Rigid_body_collection<Traits> scaled_collection(Rigid_body_collection<Traits> c, long e)
{
  typedef typename Traits::FT FT;
  typedef typename Rigid_body_collection<Traits>::Body Body;
  FT f(1);
  for (long left = e; left != 0;) {  // factors of at most 2^900: exact in a double
    const long s = (std::max)(-900L, (std::min)(900L, left));
    f = f * FT(std::ldexp(1.0, int(s)));
    left -= s;
  }
  const FT f2 = f * f;
  std::function<void(Body&)> scale = [&](Body& b) {
    for (auto& p : b.coordinates) p = Traits::point(Traits::x(p) * f, Traits::y(p) * f, Traits::z(p) * f);
    for (auto& d : b.squared_distances) d.squared = d.squared * f2;
    for (auto& part : b.parts) scale(part);
  };
  for (auto& b : c.mutable_bodies()) scale(b);
  for (auto& d : c.mutable_distances()) d.squared = d.squared * f2;
  return c;
}

// The result of the scene scaled by 2^-k at the scene's own scale (k adds to scale_exponent).
inline void scale_result(Scene_solve_result& r, long k)
{
  for (auto& x : r.configurations) {
    scale_configuration(x.configuration, k);
    scale_residuals(x.residuals, k);
    x.max_residual = x.residuals.max();
  }
  for (auto& u : r.unresolved) scale_configuration(u.at_centre, k);
  for (auto& c : r.curves)
    for (auto& f : c.configurations) scale_configuration(f, k);
  r.scale_exponent += k;
}

// The equation to leave out of a square system whose solution set is a curve: at the centre
// of a rank-deficient unresolved region, the largest entry of the Jacobian's left null vector
// (the equation the others make dependent there); -1 if there is no such region.
template <class NT, class IT>
long dependent_equation(const Polynomial_system<NT>& sys, const Solver_result<IT>& res)
{
  const std::size_t n = sys.number_of_variables(), m = sys.number_of_equations();
  for (const auto& u : res.unresolved) {
    if (!u.rank_deficient) continue;
    std::vector<double> x;
    for (const auto& e : u.box) x.push_back(0.5 * CGAL::to_interval(e).first + 0.5 * CGAL::to_interval(e).second);
    Eigen::MatrixXd J(m, n);
    for (std::size_t k = 0; k < m; ++k)
      for (std::size_t v = 0; v < n; ++v) J(k, v) = sys.equations[k].derivative(v).template evaluate<double>(x);
    Eigen::JacobiSVD<Eigen::MatrixXd> svd(J, Eigen::ComputeFullU);
    Eigen::VectorXd w = svd.matrixU().col(m - 1);
    long best = 0;
    for (std::size_t k = 1; k < m; ++k)
      if (std::abs(w(long(k))) > std::abs(w(best))) best = long(k);
    return best;
  }
  return -1;
}

// f vanishes at every point, up to 1e-8 relative to the size of its terms there; or f's
// coefficients are intervals that all contain 0 (f may be identically zero: its enclosure
// cannot tell, and a branch kept for it is not certified anyway)
template <class NT>
bool vanishes_along(const Sparse_polynomial<NT>& f, const std::vector<std::vector<double>>& points)
{
  if constexpr (!std::is_same<NT, CGAL::Gmpq>::value) {
    bool all_zero = true;
    for (const auto& t : f.terms()) {
      const auto iv = CGAL::to_interval(t.second);
      all_zero = all_zero && iv.first <= 0 && iv.second >= 0;
    }
    if (all_zero) return true;
  }
  for (const auto& x : points) {
    double value = 0, size = 0;
    for (const auto& t : f.terms()) {
      double m = CGAL::to_double(t.second);
      for (std::size_t v = 0; v < x.size(); ++v)
        for (unsigned e = 0; e < t.first[v]; ++e) m *= x[v];
      value += m;
      size += std::abs(m);
    }
    if (std::abs(value) > 1e-8 * (size + 1e-300)) return false;
  }
  return true;
}

// A branch traced in one chart combination, as configurations.
struct Scene_piece
{
  Scene_curve_piece piece;
  std::vector<Configuration> configurations;
  Curve_end ends[2];
  // an end on the border of a range that is not a chart's (a family's free distance): not
  // joined to another piece, and kept as `BOUNDARY`
  bool range_end[2] = {false, false};
  bool certified = true, closed = false, on_inequality_boundary = false;
  double max_residual = 0;
  std::string note;
};

// The configurations along a traced polyline (each point's first coordinates are the reduced
// system's parameters; a family appends one more), each checked in the original system: a
// failed check makes the piece not certified. False if a body must be mirrored somewhere
// (then the piece is not a branch of the scene).
template <class Traits, class NT>
bool add_configurations(Scene_piece& q, const std::vector<std::vector<double>>& points, const Reduced_system<Traits, NT>& r,
                        const Rigid_body_collection<Traits>& original, double threshold, const std::vector<int>& variants = {},
                        bool* failed_check = nullptr)
{
  bool spurious = false;
  const std::size_t n = r.number_of_variables();
  for (const auto& p : points) {
    q.configurations.push_back(configuration(r, std::vector<double>(p.begin(), p.begin() + long(n)), variants));
    Residual_report rep = residuals(original, q.configurations.back());
    const double size = configuration_size(q.configurations.back());
    if (!verified(rep, threshold, size)) {
      if (mirror_image(rep, threshold, size)) spurious = true;
      else q.certified = false;
      if (failed_check) *failed_check = true;
    }
    q.max_residual = (std::max)(q.max_residual, rep.max());
  }
  return !spurious;
}

// Joins the pieces of all chart combinations into branches: a piece ending on its chart's
// border continues in the piece of another chart that ends in the same configuration (within
// `tolerance` times the scene's size).
inline std::vector<Scene_curve> join_pieces(std::vector<Scene_piece>& pieces, double tolerance)
{
  const std::size_t N = pieces.size();
  // partner[2 p + side] = 2 q + side' of the joined end, or -1
  std::vector<long> partner(2 * N, -1);
  auto end_conf = [&](std::size_t e) -> const Configuration& {
    const auto& c = pieces[e / 2].configurations;
    return e % 2 ? c.back() : c.front();
  };
  for (std::size_t e = 0; e < 2 * N; ++e) {
    if (pieces[e / 2].closed || pieces[e / 2].ends[e % 2] != Curve_end::BOUNDARY || pieces[e / 2].range_end[e % 2] || partner[e] >= 0) continue;
    const double size = configuration_size(end_conf(e));
    double best = tolerance * size;
    long at = -1;
    for (std::size_t f = 0; f < 2 * N; ++f) {
      if (f == e || pieces[f / 2].closed || pieces[f / 2].ends[f % 2] != Curve_end::BOUNDARY || pieces[f / 2].range_end[f % 2] ||
          partner[f] >= 0)
        continue;
      if (pieces[f / 2].piece.charts == pieces[e / 2].piece.charts && pieces[f / 2].piece.placements == pieces[e / 2].piece.placements) continue;
      const double d = configuration_distance(end_conf(e), end_conf(f));
      if (d <= best) { best = d; at = long(f); }
    }
    if (at >= 0) { partner[e] = at; partner[std::size_t(at)] = long(e); }
  }
  std::vector<Scene_curve> out;
  std::vector<char> used(N, 0);
  auto chain = [&](std::size_t start_piece, int start_side) {
    Scene_curve c;
    std::size_t p = start_piece;
    int side = start_side;  // the end we enter the piece by
    c.ends[0] = pieces[p].ends[side];
    const bool start_in_range = !pieces[p].range_end[side];
    while (true) {
      used[p] = 1;
      Scene_piece& q = pieces[p];
      Scene_curve_piece piece = q.piece;
      std::vector<Configuration> confs = q.configurations;
      if (side == 1) {
        std::reverse(piece.parameters.begin(), piece.parameters.end());
        std::reverse(confs.begin(), confs.end());
      }
      c.configurations.insert(c.configurations.end(), confs.begin(), confs.end());
      c.pieces.push_back(std::move(piece));
      c.certified = c.certified && q.certified;
      c.on_inequality_boundary = c.on_inequality_boundary || q.on_inequality_boundary;
      c.max_residual = (std::max)(c.max_residual, q.max_residual);
      if (!q.note.empty() && c.note.find(q.note) == std::string::npos) c.note += (c.note.empty() ? "" : "; ") + q.note;
      const std::size_t leave = 2 * p + (1 - side);
      const long next = partner[leave];
      if (next < 0) {
        c.ends[1] = q.ends[1 - side];
        // an end on a chart border without a partner in another chart: not accounted for
        if (c.ends[1] == Curve_end::BOUNDARY && !q.range_end[1 - side]) { c.ends[1] = Curve_end::UNRESOLVED; c.certified = false; }
        break;
      }
      if (used[std::size_t(next) / 2]) {
        c.closed = std::size_t(next) / 2 == start_piece;
        if (!c.closed) c.certified = false;
        c.ends[0] = c.ends[1] = Curve_end::CLOSED;
        break;
      }
      p = std::size_t(next) / 2;
      side = int(std::size_t(next) % 2);
    }
    if (c.ends[0] == Curve_end::BOUNDARY && start_in_range) { c.ends[0] = Curve_end::UNRESOLVED; c.certified = false; }
    out.push_back(std::move(c));
  };
  for (std::size_t p = 0; p < N; ++p)
    if (!used[p] && pieces[p].closed) {
      used[p] = 1;
      Scene_curve c;
      c.closed = true;
      c.configurations = pieces[p].configurations;
      c.pieces.push_back(pieces[p].piece);
      c.certified = pieces[p].certified;
      c.on_inequality_boundary = pieces[p].on_inequality_boundary;
      c.max_residual = pieces[p].max_residual;
      c.note = pieces[p].note;
      out.push_back(std::move(c));
    }
  // chains from a true end first, then the loops made of several pieces
  for (std::size_t e = 0; e < 2 * N; ++e)
    if (!used[e / 2] && partner[e] < 0) chain(e / 2, int(e % 2));
  for (std::size_t p = 0; p < N; ++p)
    if (!used[p]) chain(p, 0);
  return out;
}

} // namespace internal

namespace internal {

// A combination of placements (per body) and charts (per tree edge): one reduced system.
typedef std::pair<std::vector<int>, std::vector<int>> Scene_combination;

// A pass that solves again only some combinations, at a higher precision, and keeps an
// earlier pass's answer for the others.
struct Scene_retry
{
  const Scene_solve_result* earlier = nullptr;
  std::set<Scene_combination> only;
};

// the stable order of configurations: by the coordinates of the points, in label order
inline bool configuration_order(const Scene_configuration& a, const Scene_configuration& b)
{
  const auto& p = a.configuration.points;
  const auto& q = b.configuration.points;
  for (std::size_t i = 0; i < p.size() && i < q.size(); ++i)
    for (int k = 0; k < 3; ++k) {
      double x = std::round(p[i][k] * 1e6), y = std::round(q[i][k] * 1e6);
      if (x != y) return x < y;
    }
  return false;
}

// solve_scene() at the scene's own scale. With `retry`, only its combinations are solved; the
// earlier pass's configurations and regions of the others are kept. `uncertain`, if given,
// receives the combinations whose solve left a root not certified or a region unknown (what a
// retry at a higher precision solves again).
template <class IT, class NT, class Traits>
Scene_solve_result solve_scene_unscaled(const Rigid_body_collection<Traits>& original, const Rigid_body_collection<Traits>& c,
                               const Incidence_tree& tree, const Well_formed_selection& selection,
                               const Scene_solve_parameters& parameters, double seconds_before = 0,
                               const Scene_retry* retry = nullptr, std::set<Scene_combination>* uncertain = nullptr)
{
  typedef std::chrono::steady_clock Clock;
  auto since = [](Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); };
  const Clock::time_point started = Clock::now();
  // why the solve must stop now (null: it need not): parameters.maximal_seconds is what is
  // left of the whole solve's limit when this pass began
  auto stop_reason = [&]() -> const char* {
    if (parameters.interrupt && parameters.interrupt->load(std::memory_order_relaxed)) return "interrupted";
    if (parameters.maximal_seconds > 0 && since(started) >= parameters.maximal_seconds) return "time limit";
    return nullptr;
  };
  Scene_solve_result out;
  out.fast = parameters.solver.fast;
  Scene_solve_statistics& st = out.statistics;
  out.coefficient_precision = std::is_same<NT, CGAL::Gmpq>::value ? 0 : 53;
#ifdef CGAL_USE_MPFI
  if constexpr (std::is_same<NT, CGAL::Gmpfi>::value) out.coefficient_precision = unsigned(CGAL::Gmpfi::get_default_precision());
#endif

  auto t0 = Clock::now();
  std::vector<std::string> singular_body;
  std::vector<int> radix_p = internal::placement_counts(c, tree, parameters.maximal_placements, &out.placements, &singular_body);
  // per body known by distances: its placements, whose own double points (in a rigid part, or
  // a height found exactly 0 by the exact pass) make the configurations that use them singular
  std::vector<std::shared_ptr<const Placement_enumeration<CGAL::Interval_nt<false>>>> enumerations(c.number_of_bodies());
  for (std::size_t b = 0; b < c.number_of_bodies(); ++b)
    if (!c.body(b).all_coordinates())
      enumerations[b] = internal::cached_placements<CGAL::Interval_nt<false>>(c, b, parameters.maximal_placements);
  // The reduced system's coefficients come from the enumeration at its own precision (NT),
  // the counts and configurations from the one above: where a decision depends on the
  // precision they could differ in length or order. Placement i must be the same in both:
  // else its combinations are solved no further than both lists go, and the answer says so.
  if constexpr (!std::is_same<NT, CGAL::Interval_nt<false>>::value && !std::is_same<NT, CGAL::Gmpq>::value)
    for (std::size_t b = 0; b < c.number_of_bodies(); ++b) {
      if (!enumerations[b]) continue;
      const auto own = internal::cached_placements<NT>(c, b, parameters.maximal_placements);
      const auto& d = enumerations[b]->placements;
      const auto& g = own->placements;
      std::string why;
      if (g.size() != d.size())
        why = std::to_string(g.size()) + " placement(s) at " + std::to_string(own->precision) + " bits, " + std::to_string(d.size()) +
              " in the enumeration the counts use";
      for (std::size_t i = 0; why.empty() && i < g.size(); ++i)
        for (std::size_t k = 0; why.empty() && k < g[i].coordinates.size() && k < d[i].coordinates.size(); ++k)
          for (std::size_t x = 0; x < 3; ++x) {
            const auto gi = CGAL::to_interval(g[i].coordinates[k][x]);
            if (gi.second < d[i].coordinates[k][x].inf() || d[i].coordinates[k][x].sup() < gi.first) {
              why = "placement " + std::to_string(i + 1) + " puts point '" + c.label(c.body(b).points[k]) + "' elsewhere at " +
                    std::to_string(own->precision) + " bits";
              break;
            }
          }
      if (why.empty()) continue;
      out.limits.push_back("placements of body '" + c.body(b).name + "' differ between precisions (" + why +
                           "): the configurations of the placements past the shorter list, or of mismatched ones, may be missing");
      if (b < radix_p.size() && radix_p[b] > int(g.size())) radix_p[b] = (std::max)(1, int(g.size()));
    }
  for (const auto& r : out.placements) {
    if (!r.complete)
      out.limits.push_back("body '" + r.body + "' has more than " + std::to_string(r.placements) +
                           " placements (maximal_placements): only the first " + std::to_string(r.placements) + " were solved");
    if (!r.inconsistent.empty() && out.no_configuration.empty()) out.no_configuration = r.inconsistent;
    if (!r.undecided.empty()) out.limits.push_back("placements of body '" + r.body + "' not decided: " + r.undecided);
  }
  // a covering body all of whose placements were left undecided: nothing to solve, and the
  // result is incomplete (its limit says why), not "no configuration"
  for (const auto& r : out.placements)
    if (r.placements == 0 && !r.undecided.empty() && r.inconsistent.empty()) return out;
  // bodies outside the covering set known by distances with more than one placement: the
  // reduced system fixes their covered points (by exact distances), and each placement that
  // fits them is a configuration of its own (its other points differ), not placement 0 alone
  std::vector<std::size_t> nc_bodies;
  std::vector<int> nc_radix;
  std::size_t nc_product = 1;
  for (std::size_t b : tree.non_covering) {
    if (c.body(b).all_coordinates()) continue;
    auto e = internal::cached_placements<CGAL::Interval_nt<false>>(c, b, parameters.maximal_placements);
    if (!e->complete)
      out.limits.push_back("body '" + c.body(b).name + "' (outside the covering set) has more than " + std::to_string(e->placements.size()) +
                           " placements (maximal_placements): only the first " + std::to_string(e->placements.size()) + " were tried");
    if (!e->singular.empty()) singular_body[b] = e->singular;
    // (a body whose equations depend on its placement is enumerated with the covering bodies)
    // (a body whose points the covering set all places is fixed by the system's equations: its
    // placements only differ in points of its own)
    if (e->placements.size() > 1 && internal::own_points_outside(c, tree, b)) {
      nc_bodies.push_back(b);
      nc_radix.push_back(int(e->placements.size()));
      nc_product = nc_product > parameters.maximal_placements ? nc_product : nc_product * e->placements.size();
    }
    out.placements.push_back(internal::placement_report(c.body(b).name, *e));
    if (!e->inconsistent.empty() && out.no_configuration.empty()) out.no_configuration = e->inconsistent;
    if (!e->undecided.empty()) out.limits.push_back("placements of body '" + c.body(b).name + "' not decided: " + e->undecided);
  }
  if (!out.no_configuration.empty()) return out;
  if (nc_product > parameters.maximal_placements)
    out.limits.push_back("the bodies outside the covering set have more than " + std::to_string(parameters.maximal_placements) +
                         " combinations of placements (maximal_placements): only the first ones were tried for each root");
  // the combinations of their placements, in order, up to the limit
  auto next_nc = [&](std::vector<int>& v, std::size_t& tried) {
    return ++tried < parameters.maximal_placements && internal::next_combination(v, nc_radix);
  };
  // How a body's double placements reach a configuration: through the placement the
  // configuration uses, where the body's placements are enumerated (radix_p, nc_bodies);
  // else (its points all fixed by the system) through any of them, so on every configuration
  // when every placement is double, and never otherwise. Said once per body (singular_body).
  std::vector<const Body_enclosure<CGAL::Interval_nt<false>>*> always_double(c.number_of_bodies(), nullptr);
  std::vector<bool> chosen_double(c.number_of_bodies(), false);
  for (std::size_t b = 0; b < enumerations.size(); ++b) {
    if (!enumerations[b] || !singular_body[b].empty()) continue;
    const auto& list = enumerations[b]->placements;
    const bool enumerated = (b < radix_p.size() && radix_p[b] > 1) || std::find(nc_bodies.begin(), nc_bodies.end(), b) != nc_bodies.end() ||
                            list.size() == 1;
    if (enumerated) chosen_double[b] = std::any_of(list.begin(), list.end(), [](const auto& e) { return e.singular; });
    else if (!list.empty() && std::all_of(list.begin(), list.end(), [](const auto& e) { return e.singular; })) always_double[b] = &list[0];
  }
  std::vector<int> placements(c.number_of_bodies(), 0);
  // A scene the sweep may solve (Scene_solve_parameters::sweep, below): its Tree_system, built
  // first, says what the reduced system would (variables, equations, charts) without
  // expanding it (a chain of 14 hinges: 1.6 million terms, 56 s)
  std::optional<Tree_system<Traits>> sweep_system;
  if (parameters.sweep && !retry && Tree_system<Traits>::unsupported(c, tree).empty()) {
    try { sweep_system.emplace(c, tree, selection); } catch (const Input_error&) {}  // (then as any scene)
    if (sweep_system) {
      const Sweep_order o = sweep_system->is_square() ? sweep_order(*sweep_system) : Sweep_order();
      if (!o.exists(sweep_system->number_of_variables()) || o.driver == Sweep_order::none) sweep_system.reset();
    }
  }
  std::optional<Reduced_system<Traits, NT>> first;
  if (!sweep_system) first.emplace(c, tree, selection);
  st.reduce_seconds += since(t0);
  std::vector<int> radix_c;
  if (first) {
    out.variables = first->parametrization().variable_names();
    out.equations = first->number_of_equations();
    for (const auto& e : first->parametrization().edges()) radix_c.push_back(e.number_of_charts);
  } else {
    out.variables = sweep_system->parametrization(0).variable_names();
    out.equations = sweep_system->number_of_equations();
    for (const auto& e : sweep_system->parametrization(0).edges()) radix_c.push_back(e.number_of_charts);
  }
  // one equation fewer than parameters and no loose body: the configurations form curves
  const bool one_dof = first && !first->is_square() && first->number_of_equations() + 1 == first->number_of_variables() &&
                       first->loose_bodies().empty() && !parameters.solver.fast;
  if (first && !first->is_square() && !one_dof) {
    const std::string d = first->diagnostic();
    out.diagnosis = (first->number_of_equations() < first->number_of_variables() || !first->loose_bodies().empty()
                         ? "under_constrained: "
                         : "over_constrained: ") + d;
    return out;
  }
  std::vector<std::array<std::size_t, 4>> orientation;
  for (std::size_t q = 0; q < parameters.inequalities.size(); ++q) {
    std::array<std::size_t, 4> pts;
    for (std::size_t k = 0; k < 4; ++k) {
      pts[k] = c.point_index(original.resolve_alias(parameters.inequalities[q].points[k]));  // (a coincidence: its point)
      if (pts[k] == Rigid_body_collection<Traits>::npos)
        throw Input_error("inequality " + std::to_string(q) + ": no point '" + parameters.inequalities[q].points[k] + "' in the scene");
    }
    orientation.push_back(pts);
  }

  // Pairs of covering bodies with several placements that share two or more points: a
  // combination of placements that puts two shared points at certainly different distances
  // has no configuration (a body placed through another body's placement, e.g. an implied
  // triangle whose side runs through a merged body, fits only that placement).
  struct Shared_pair { std::size_t i, j; std::vector<std::vector<bool>> fits; };
  std::vector<Shared_pair> shared_pairs;
  {
    const auto& cover = tree.covering_set;
    for (std::size_t x = 0; x < cover.size(); ++x)
      for (std::size_t y = x + 1; y < cover.size(); ++y) {
        const std::size_t i = cover[x], j = cover[y];
        if (radix_p[i] < 2 && radix_p[j] < 2) continue;
        if (c.body(i).all_coordinates() && c.body(j).all_coordinates()) continue;
        std::vector<std::size_t> common = c.common_points(i, j);
        if (common.size() < 2) continue;
        auto enc = [&](std::size_t b) {
          std::vector<Body_enclosure<CGAL::Interval_nt<false>>> v;
          if (c.body(b).all_coordinates()) v.push_back(enclose_coordinates<CGAL::Interval_nt<false>>(c, b, 0));
          else v = internal::cached_placements<CGAL::Interval_nt<false>>(c, b, parameters.maximal_placements)->placements;
          return v;
        };
        const auto ei = enc(i), ej = enc(j);
        if (ei.empty() || ej.empty()) continue;
        Shared_pair sp{i, j, std::vector<std::vector<bool>>(ei.size(), std::vector<bool>(ej.size(), true))};
        bool any = false;
        typename CGAL::Interval_nt<false>::Protector protect;
        for (std::size_t vi = 0; vi < ei.size(); ++vi)
          for (std::size_t vj = 0; vj < ej.size(); ++vj)
            for (std::size_t u = 0; u < common.size() && sp.fits[vi][vj]; ++u)
              for (std::size_t w = u + 1; w < common.size() && sp.fits[vi][vj]; ++w) {
                auto sq = [&](const Body_enclosure<CGAL::Interval_nt<false>>& e, std::size_t b) {
                  const auto& a = e.coordinates[c.body(b).local(common[u])];
                  const auto& d = e.coordinates[c.body(b).local(common[w])];
                  return internal::dot(internal::sub(a, d), internal::sub(a, d));
                };
                CGAL::Interval_nt<false> a = sq(ei[vi], i), b = sq(ej[vj], j);
                if (!Traits::has_exact_ft) {  // rounded input: a mismatch within 1e-9 of the length is no mismatch
                  const double e = 1e-9 * (std::max)(std::abs(a.sup()), std::abs(b.sup()));
                  a += CGAL::Interval_nt<false>(-e, e);
                }
                if (!internal::overlap(a, b)) { sp.fits[vi][vj] = false; any = true; }
              }
        if (any) shared_pairs.push_back(std::move(sp));
      }
  }
  auto placements_fit = [&](const std::vector<int>& v) {
    for (const auto& sp : shared_pairs)
      if (std::size_t(v[sp.i]) < sp.fits.size() && std::size_t(v[sp.j]) < sp.fits[0].size() && !sp.fits[std::size_t(v[sp.i])][std::size_t(v[sp.j])])
        return false;
    return true;
  };

  struct Candidate { Scene_configuration s; double size; };
  std::vector<Candidate> found;
  // `found` by the x coordinate of the first placed point (two configurations within d of each
  // other, placing the same points, have it within d), and the largest size among them: the
  // duplicates of a configuration are looked for in a window of that coordinate, not among all
  // (a linear scan made the 40,500 configurations of five stacked platforms take 370 s)
  std::multimap<double, std::size_t> found_by_x;
  std::vector<std::size_t> found_not_by_x;  // (no finite coordinate: a candidate for every one)
  double found_largest = 0;
  auto first_x = [](const Configuration& x) {
    for (std::size_t i = 0; i < x.points.size(); ++i)
      if (x.placed[i]) return x.points[i][0];
    return 0.0;
  };
  auto remember_found = [&](std::size_t i) {
    const double x = first_x(found[i].s.configuration);
    if (std::isfinite(x)) found_by_x.emplace(x, i);
    else found_not_by_x.push_back(i);
    if (std::isfinite(found[i].size)) found_largest = (std::max)(found_largest, found[i].size);
    else found_largest = std::numeric_limits<double>::infinity();
  };
  auto forget_found = [&](std::size_t i) {
    const double x = first_x(found[i].s.configuration);
    if (!std::isfinite(x)) return;  // (stays a candidate for every one: harmless)
    for (auto r = found_by_x.equal_range(x); r.first != r.second; ++r.first)
      if (r.first->second == i) { found_by_x.erase(r.first); return; }
  };
  std::vector<internal::Scene_piece> pieces;
  std::string positive;
  // the combinations, counted for the progress and for a solve stopped early
  std::size_t per_placement = 1, total = 1;
  for (int x : radix_c) per_placement = per_placement > (std::size_t(1) << 62) / std::size_t(x) ? 0 : per_placement * std::size_t(x);
  total = per_placement;
  for (int x : radix_p) total = total == 0 || total > (std::size_t(1) << 62) / std::size_t(x) ? 0 : total * std::size_t(x);
  // a retry: the earlier answer of the combinations it does not solve again (theirs had every
  // root certified and no unknown region; a configuration's combination is its placements
  // with those of the bodies outside the covering set, enumerated per root, at 0)
  auto combination_of = [&](const std::vector<int>& pl, const std::vector<int>& ch) {
    std::vector<int> p = pl;
    for (std::size_t b : nc_bodies) if (b < p.size()) p[b] = 0;
    return Scene_combination(p, ch);
  };
  if (retry) {
    total = retry->only.size();
    if (retry->earlier) {
      for (const auto& x : retry->earlier->configurations)
        if (!retry->only.count(combination_of(x.placements, x.charts)))
        {
          found.push_back({x, internal::configuration_size(x.configuration)});
          remember_found(found.size() - 1);
        }
      for (const auto& u : retry->earlier->unresolved)
        if (!retry->only.count(Scene_combination(u.placements, u.charts))) out.unresolved.push_back(u);
      const double width = st.coefficient_width;
      const auto& e = retry->earlier->statistics;
      st.chart_combinations += e.chart_combinations;
      st.boxes += e.boxes;
      st.krawczyk_tests += e.krawczyk_tests;
      st.roots += e.roots;
      st.duplicates += e.duplicates;
      st.spurious += e.spurious;
      st.solve_seconds += e.solve_seconds;
      st.reduce_seconds += e.reduce_seconds;
      st.verify_seconds += e.verify_seconds;
      st.coefficient_width = width;  // (of the systems solved again)
    }
  }
  const unsigned threads = internal::worker_threads(parameters.solver.threads);
  st.threads = threads;
  std::size_t done = 0;
  bool plan_cut = false;  // a plan over the charts stopped inside (its combinations not counted done)
  const char* stopped = nullptr;
  auto report = [&]() {
    if (!parameters.progress) return;
    Scene_solve_progress g;
    g.combinations_done = done;
    g.combinations_total = total;
    g.boxes = st.boxes + st.curve_boxes;
    g.configurations = found.size();
    g.coefficient_precision = out.coefficient_precision;
    g.seconds = seconds_before + since(started);
    parameters.progress(g);
  };
  std::mutex width_mutex;
  // a reduced system with the orientation inequalities
  auto system_of = [&](const Reduced_system<Traits, NT>& r) {
    Polynomial_system<NT> sys = r.system();
    for (std::size_t q = 0; q < orientation.size(); ++q) {
      auto g = r.orientation_numerator(orientation[q]);
      sys.inequalities.push_back(parameters.inequalities[q].negative ? NT(-1) * g : g);
      sys.inequality_labels.push_back("orientation " + parameters.inequalities[q].points[0] + " " + parameters.inequalities[q].points[1] +
                                      " " + parameters.inequalities[q].points[2] + " " + parameters.inequalities[q].points[3]);
    }
    if constexpr (!std::is_same<NT, CGAL::Gmpq>::value) {
      const double w = internal::coefficient_width(sys);
      std::lock_guard<std::mutex> lock(width_mutex);  // (built on several threads)
      st.coefficient_width = (std::max)(st.coefficient_width, w);
    }
    return sys;
  };
  // what the solve, or the tracer, of one chart combination found: configurations, curves,
  // regions
  // a verified configuration into `found`: one root seen from two charts is kept once; never
  // two roots of one system, nor two placements of a body (distinct shapes, however close: a
  // near-degenerate body's mirror pair); but two regions of one system around one possible
  // multiple root (a cluster the solver left in two pieces) are one configuration, still not
  // certified
  auto add_found = [&](Scene_configuration& s) {
    const double size = internal::configuration_size(s.configuration);
    // the candidates, in the order they were found (the first that matches takes it)
    const double x = first_x(s.configuration), reach = parameters.merge_tolerance * (std::max)(size, found_largest);
    std::vector<std::size_t> near;
    if (std::isfinite(x) && std::isfinite(reach)) {
      for (auto it = found_by_x.lower_bound(x - reach); it != found_by_x.end() && it->first <= x + reach; ++it) near.push_back(it->second);
      near.insert(near.end(), found_not_by_x.begin(), found_not_by_x.end());
      std::sort(near.begin(), near.end());
    } else {
      for (std::size_t i = 0; i < found.size(); ++i) near.push_back(i);
    }
    for (std::size_t i : near) {
      auto& f = found[i];
      if (f.s.placements != s.placements) continue;
      if (f.s.charts == s.charts && (f.s.certified || s.certified)) continue;
      if (internal::configuration_distance(f.s.configuration, s.configuration) <= parameters.merge_tolerance * (std::max)(size, f.size)) {
        ++f.s.found;
        ++st.duplicates;
        if (!f.s.certified && s.certified) {
          forget_found(i);
          std::size_t k = f.s.found;
          f.s = s;
          f.s.found = k;
          remember_found(i);
        }
        return;
      }
    }
    found.push_back({s, size});
    remember_found(found.size() - 1);
  };
  // A root's configuration (the root's values `x` in the parametrization `p` of its charts,
  // with `v.placements`) into `v`, with its singular marks and its residuals in the original
  // system; its size returned. `multiple`: the centre of a possible multiple root.
  auto finish_configuration = [&](Scene_configuration& v, const Incidence_tree_parametrization<Traits, NT>& p, const std::vector<double>& x,
                                  bool multiple) {
    for (std::size_t b = 0; b < singular_body.size(); ++b)
      if (!singular_body[b].empty()) {
        v.singular = true;
        v.singular_reason = joined_reasons(v.singular_reason, singular_body[b]);
      }
    for (std::size_t b = 0; b < enumerations.size(); ++b) {
      const Body_enclosure<CGAL::Interval_nt<false>>* e = always_double[b];
      if (chosen_double[b] && b < v.placements.size() && std::size_t(v.placements[b]) < enumerations[b]->placements.size())
        e = &enumerations[b]->placements[std::size_t(v.placements[b])];
      if (e && e->singular) {
        v.singular = true;
        v.singular_reason = joined_reasons(v.singular_reason, e->singular_reason);
      }
    }
    v.configuration = configuration(c, tree, p, x, v.placements);
    // a point standardize() put on a body's line where two distances' spheres touch: a
    // double point of those two equations, which the scene's other equations may still
    // hold (then, as below, the root is simple)
    for (const std::string& why : c.singular_notes()) {
      v.singular = true;
      v.singular_reason = joined_reasons(v.singular_reason, why);
    }
    // a height exactly 0 in a placement is a double point of the body's own distances;
    // further equations of the scene (a distance or a body it leaves to the reduced
    // system) may still hold the point: then the Jacobian has full rank and the root is simple
    if (v.singular && !multiple && jacobian_conditioning(original, v.configuration) > 1e-7) {
      v.singular = false;
      v.singular_reason.clear();
    }
    v.residuals = residuals(original, v.configuration);
    v.max_residual = v.residuals.max();
    const double vsize = internal::configuration_size(v.configuration);
    v.max_relative_residual = internal::relative_residual(v.residuals, vsize);
    return vsize;
  };
  auto process = [&](const std::vector<int>& charts, const Reduced_system<Traits, NT>& r, const Polynomial_system<NT>& sys,
                     Solver_result<IT>& res) {
    if (positive.empty() && !res.diagnosis.empty()) {
      // say how far precision is ruled out as the cause: the widest coefficient enclosure
      // of the system, relative to its equation's largest coefficient (0: exact)
      positive = res.diagnosis + "; the reduced system's coefficients are " +
                 (std::is_same<NT, CGAL::Gmpq>::value
                      ? std::string("exact")
                      : "enclosed to a relative width of " + internal::short_number(internal::coefficient_width(sys)));
      std::string bits;
      for (const auto& pr : out.placements) bits += (bits.empty() ? " (placements: " : ", ") + std::to_string(pr.precision) + " bits for '" + pr.body + "'";
      if (!bits.empty()) positive += bits + ")";
    }
    auto unresolved = [&](Box_class kind, const std::string& reason, const std::vector<std::pair<double, double>>& box, std::size_t boxes,
                          const Configuration& at) {
      Scene_unresolved x;
      x.kind = kind;
      x.reason = reason;
      x.charts = charts;
      x.placements = placements;
      x.box = box;
      x.boxes = boxes;
      x.at_centre = at;
      return x;
    };
    // the solver's or the tracer's regions, with the configuration at each centre
    auto add_regions = [&](const std::vector<Solver_unresolved<IT>>& regions) {
      for (const auto& u : regions) {
          std::vector<std::pair<double, double>> box;
          std::vector<double> centre;
          for (const auto& e : u.box) {
            box.push_back(CGAL::to_interval(e));
            centre.push_back(0.5 * box.back().first + 0.5 * box.back().second);
          }
          out.unresolved.push_back(unresolved(u.kind, u.reason, box, u.boxes, configuration(r, centre)));
      }
    };
    // the curves of this chart combination: the whole system when it has one equation fewer
    // than parameters; else, when the solver found a curve of solutions (rank n - 1 along a
    // chain of boxes), the system without the equation the Jacobian's left null vector
    // weighs most, keeping the branches on which that equation vanishes
    long left_out = -1;
    if (!one_dof && res.diagnosis.rfind("positive_dimensional", 0) == 0)
      left_out = internal::dependent_equation(sys, res);
    if (one_dof || left_out >= 0) {
      Polynomial_system<NT> tsys = sys;
      if (left_out >= 0) {
        tsys.equations.erase(tsys.equations.begin() + left_out);
        if (std::size_t(left_out) < tsys.labels.size()) tsys.labels.erase(tsys.labels.begin() + left_out);
      }
      Curve_tracer_parameters cp;
      cp.precision = parameters.solver.precision;
      cp.maximal_boxes = parameters.solver.maximal_boxes;
      auto t4 = Clock::now();
      Curve_result<IT> cr;
      bool zero_equation = false;
      for (const auto& e : tsys.equations) zero_equation = zero_equation || e.is_zero();
      if (tsys.number_of_variables() == 1 && tsys.number_of_equations() == 0 && tsys.inequalities.empty()) {
        // one parameter and nothing left to hold (the scene turns freely about a hinge): every
        // value is a configuration, the chart's whole range one branch (its ends on the
        // chart's border, joined to the next chart's)
        Solution_curve<IT> whole;
        const int samples = 64;
        for (int k = 0; k <= samples; ++k)
          whole.points.push_back({tsys.box[0].first + (tsys.box[0].second - tsys.box[0].first) * k / samples});
        whole.ends[0] = whole.ends[1] = Curve_end::BOUNDARY;
        cr.curves.push_back(whole);
      } else if (tsys.number_of_variables() < 2 || tsys.number_of_equations() + 1 != tsys.number_of_variables() || zero_equation) {
        // not a curve the tracer takes: the diagnosis stands, the regions stay unresolved
        if (positive.empty()) positive = "positive_dimensional: the reduced system's solutions are not isolated";
        positive += "; its curve was not traced (" + std::to_string(tsys.number_of_equations()) + " equation(s) in " +
                    std::to_string(tsys.number_of_variables()) + " variable(s) after leaving one out)";
      } else {
        cr = trace_curves<IT>(tsys, cp);
      }
      st.solve_seconds += since(t4);
      st.curve_boxes += cr.statistics.boxes;
      add_regions(cr.unresolved);
      for (const auto& c : cr.curves) {
        internal::Scene_piece q;
        q.piece.charts = charts;
        q.piece.placements = placements;
        q.piece.parameters = c.points;
        q.ends[0] = c.ends[0];
        q.ends[1] = c.ends[1];
        q.closed = c.closed;
        q.certified = c.certified;
        q.on_inequality_boundary = c.on_inequality_boundary;
        if (left_out >= 0) {
          if (!internal::vanishes_along(sys.equations[std::size_t(left_out)], c.points)) continue;  // not a branch of the scene
          q.certified = false;
          q.note = "traced without equation " + std::to_string(left_out + 1) + " (" +
                   (std::size_t(left_out) < sys.labels.size() ? sys.labels[std::size_t(left_out)] : std::string()) +
                   "), which vanishes at every point of the branch (or whose coefficients' enclosures all contain 0):"
                   " checked numerically, not proved";
        }
        // one piece per combination of placements of the bodies outside the covering set that
        // holds along it; if none does, the first one, not certified (as without them)
        std::vector<int> nc(nc_bodies.size(), 0);
        std::size_t tried = 0;
        std::vector<internal::Scene_piece> fitting, failing;
        bool any_spurious = false;
        do {
          internal::Scene_piece qv = q;
          std::vector<int> variants = placements;
          for (std::size_t k = 0; k < nc_bodies.size(); ++k) variants[nc_bodies[k]] = nc[k];
          qv.piece.placements = variants;
          bool failed = false;
          if (!internal::add_configurations(qv, c.points, r, original, parameters.residual_threshold, variants, &failed)) {
            any_spurious = true;
            continue;
          }
          (failed ? failing : fitting).push_back(std::move(qv));
        } while (next_nc(nc, tried));
        if (fitting.empty() && failing.empty() && any_spurious) ++st.spurious;
        if (!fitting.empty()) for (auto& x : fitting) pieces.push_back(std::move(x));
        else if (!failing.empty()) pieces.push_back(std::move(failing.front()));
      }
    }
    // A cluster the solver stopped as a possible multiple root: a root that is not simple
    // is not stable under perturbation, so no interval test proves it exists. Its centre
    // is tried as a configuration like a root: if it satisfies the original system it is
    // returned not certified and marked singular (the answer is then not complete); else
    // the region stays unresolved. Not along a curve of solutions (a positive-dimensional
    // diagnosis), whose regions are points of the curve, not roots.
    std::vector<Solver_unresolved<IT>> regions_left;
    std::vector<std::optional<Solver_unresolved<IT>>> from_region(res.roots.size());
    for (const auto& u : res.unresolved) {
      if (!res.diagnosis.empty() || u.kind != Box_class::UNKNOWN || u.reason.rfind("possible multiple root", 0) != 0) {
        regions_left.push_back(u);
        continue;
      }
      Solver_root<IT> root;
      root.certified = false;
      root.enclosure = u.box;
      for (const auto& e : u.box) {
        const auto iv = CGAL::to_interval(e);
        root.approximation.push_back(0.5 * iv.first + 0.5 * iv.second);
      }
      res.roots.push_back(root);
      from_region.push_back(u);
    }
    for (std::size_t ri = 0; ri < res.roots.size(); ++ri) {
      const Solver_root<IT>& root = res.roots[ri];
      ++st.roots;
      Scene_configuration s;
      s.certified = root.certified;
      s.coefficient_precision = out.coefficient_precision;
      if (from_region[ri]) {
        s.singular = true;
        s.singular_reason = "a possible multiple root of the reduced system (" + from_region[ri]->reason + ", " +
                            std::to_string(from_region[ri]->boxes) + " box(es)): its centre satisfies the original system, but"
                            " a root that is not simple cannot be certified by intervals, nor told from two close roots";
      }
      s.on_chart_border = root.on_boundary;
      s.on_inequality_boundary = root.on_inequality_boundary;
      s.charts = charts;
      s.placements = placements;
      s.variables = sys.variable_names;
      for (const auto& e : root.enclosure) s.parameters.push_back(CGAL::to_interval(e));
      // one configuration per placement of the bodies outside the covering set that fits
      std::vector<Scene_configuration> variants_found;
      Scene_configuration first_failed;
      std::vector<int> nc(nc_bodies.size(), 0);
      std::size_t tried = 0;
      do {
        Scene_configuration v = s;
        for (std::size_t k = 0; k < nc_bodies.size(); ++k) v.placements[nc_bodies[k]] = nc[k];
        const double vsize = finish_configuration(v, r.parametrization(), root.approximation, bool(from_region[ri]));
        // a multiple root's centre must satisfy the system far more closely than a root's
        // double approximation (the cluster is narrow at the solver's precision)
        if (internal::verified(v.residuals, from_region[ri] ? (std::min)(parameters.residual_threshold, 1e-10) : parameters.residual_threshold, vsize)) {
          // two placements that put every point at the same place are one configuration
          bool same = false;
          for (const auto& w : variants_found)
            same = same || internal::configuration_distance(w.configuration, v.configuration) <= parameters.merge_tolerance * vsize;
          if (!same) variants_found.push_back(std::move(v));
        } else if (first_failed.configuration.points.empty()) {
          first_failed = std::move(v);
        }
      } while (next_nc(nc, tried));
      if (variants_found.empty()) {
        if (from_region[ri]) { regions_left.push_back(*from_region[ri]); continue; }  // not a configuration: stays unresolved
        s = first_failed;
        // a mirror image of the scene (some body reflected), not a configuration
        if (internal::mirror_image(s.residuals, parameters.residual_threshold, internal::configuration_size(s.configuration))) { ++st.spurious; continue; }
        // not verified for another reason: say so rather than drop it
        out.unresolved.push_back(unresolved(Box_class::UNKNOWN, "root of the reduced system not verified in the original system (residual " +
                                                std::to_string(s.max_residual) + ")", s.parameters, 1, s.configuration));
        continue;
      }
      for (Scene_configuration& v : variants_found) add_found(v);
    }
    add_regions(regions_left);
  };
  // what one combination's build and solve give (touched by its own thread only)
  struct Combination_work
  {
    std::vector<int> charts, placements;
    bool excluded = false;  // a placement combination placements_fit() excludes: nothing to do
    std::optional<Reduced_system<Traits, NT>> r;
    Polynomial_system<NT> sys;
    Solver_result<IT> res;
    double reduce_seconds = 0, solve_seconds = 0;
    bool planned = false;
    std::size_t block_solves = 0, block_solves_reused = 0, plan_boxes = 0, plan_krawczyk_tests = 0;
  };
  // one combination's solve, its system built (w.r, w.sys, w.reduce_seconds): on any thread
  auto solve_combination = [&](Combination_work& w) {
    const Polynomial_system<NT>& sys = w.sys;
    Solver_result<IT>& res = w.res;
    auto t2 = Clock::now();
    if (one_dof) {
      // traced below
    } else if (sys.number_of_variables() == 0) {
      // one body, or bodies fixed by the placements alone: the configuration is the
      // placement itself (each placement variant is one)
      Solver_root<IT> root;
      root.certified = true;
      res.roots.push_back(root);
    } else {
      // what is left of the whole solve's time, and its interrupt, bound this solve too
      Subdivision_solver_parameters sp = parameters.solver;
      if (!sp.interrupt) sp.interrupt = parameters.interrupt;
      if (parameters.maximal_seconds > 0) {
        const double left = (std::max)(parameters.maximal_seconds - since(started), 1e-3);
        sp.maximal_seconds = sp.maximal_seconds > 0 ? (std::min)(sp.maximal_seconds, left) : left;
      }
      bool planned = false;
      if (parameters.solve_with_plan && sys.number_of_equations() == sys.number_of_variables()) {
        const Solution_plan plan(sys);
        if (plan.blocks().size() > 1 && plan.over_determined_equations().empty() && plan.under_determined_variables().empty() &&
            plan.unattached_inequalities().empty()) {
          try {
            const Plan_result<IT> pr = solve_with_plan<IT>(sys, plan, sp);
            if (pr.diagnosis.empty()) {
              res = internal::solver_result_of_plan(pr, plan.blocks().size());
              planned = true;
              w.planned = true;
              w.block_solves = pr.block_solves;
              w.block_solves_reused = pr.block_solves_reused;
            } else {
              // the whole system's solve diagnoses, and traces, what a block could not
              w.plan_boxes = pr.boxes;
              w.plan_krawczyk_tests = pr.krawczyk_tests;
            }
          } catch (const Input_error&) {
            // (an equation vanishes once earlier roots are substituted: solved whole)
          }
        }
      }
      if (!planned) res = Subdivision_solver<IT>(sp).solve(sys);
    }
    w.solve_seconds = since(t2);
  };
  // what one combination found, taken in the order of the combinations (one at a time)
  auto take_combination = [&](Combination_work& w) {
    // (process() reads it; in the placement loop below, every combination has the loop's own,
    // read meanwhile by the stages that build and solve: not written then)
    if (placements != w.placements) placements = w.placements;
    const Solver_result<IT>& res = w.res;
    const double ts = w.solve_seconds;
    st.reduce_seconds += w.reduce_seconds;
    st.solve_seconds += ts;
    if (w.planned) {
      ++st.planned_systems;
      st.block_solves += w.block_solves;
      st.block_solves_reused += w.block_solves_reused;
    }
    st.boxes += w.plan_boxes;
    st.krawczyk_tests += w.plan_krawczyk_tests;
    ++st.chart_combinations;
    st.boxes += res.statistics.boxes;
    st.krawczyk_tests += res.statistics.krawczyk_tests;
    if (res.statistics.boxes == 1 && res.roots.empty() && res.unresolved.empty()) {
      ++st.excluded_at_once;
      st.excluded_at_once_seconds += ts;
    }
    auto t3 = Clock::now();
    process(w.charts, *w.r, w.sys, w.res);
    st.verify_seconds += since(t3);
    ++done;
    report();
  };
  // The charts the hinges can take together, chosen along the tree (chart_propagation): the
  // combinations it excludes are never built. Computed once (one placement combination: the
  // covering bodies all have coordinates); a propagation the budget or a stop cuts short
  // excludes nothing.
  // A chain of hinges braced by near distances (a sweep order with a driver): solved along the
  // tree by one sweep, never expanded, instead of chart combination by chart combination
  bool swept = false;
  std::size_t placement_combinations = 1;
  for (int x : radix_p) placement_combinations = x > 1 ? 2 : placement_combinations;  // (1, or more than 1)
  if (sweep_system && !one_dof &&
      internal::sweeps(*sweep_system, sweep_order(*sweep_system), placement_combinations, !nc_bodies.empty(), parameters.sweep_from) &&
      placements_fit(placements)) {
    auto t1 = Clock::now();
    const Tree_system<Traits>* ts = &*sweep_system;
    {
      swept = true;
      st.swept = true;
      out.coefficient_precision = 53;  // (every configuration from the tree's maps in double intervals)
      Tree_solver_parameters tp;
      tp.interrupt = parameters.interrupt;
      tp.threads = threads;  // (its slices in parallel; the same answer with any number)
      tp.consistency_cells = parameters.consistency_cells;
      if (parameters.maximal_seconds > 0) tp.maximal_seconds = (std::max)(1e-3, parameters.maximal_seconds - since(started));
      const std::size_t boxes_before = st.boxes;
      tp.progress = [&](std::size_t boxes, std::size_t) { st.boxes = boxes_before + boxes; report(); };
      const Tree_solve_result tr = solve_tree_system(*ts, tp);
      st.boxes = boxes_before;
      st.solve_seconds += since(t1);
      st.boxes += tr.statistics.boxes;
      st.krawczyk_tests += tr.statistics.krawczyk_tests;
      st.consistent_fraction = tr.consistent_fraction;
      st.consistency_seconds += tr.consistency_seconds;
      auto t3 = Clock::now();
      typedef Incidence_tree_parametrization<Traits, CGAL::Interval_nt<false>> Tree_parametrization;
      for (const Tree_root& root : tr.roots) {
        ++st.roots;
        const Tree_parametrization p(c, tree, root.charts);
        Scene_configuration x;
        x.certified = root.certified;
        x.coefficient_precision = 53;  // (the tree's maps in double intervals)
        x.charts = root.charts;
        x.placements = placements;
        x.variables = ts->variable_names(root.charts);
        for (const auto& e : root.enclosure) {
          x.parameters.push_back({e.inf(), e.sup()});
          x.on_chart_border = x.on_chart_border || e.inf() <= -1 || e.sup() >= 1;
        }
        x.configuration = configuration(c, tree, p, root.approximation, placements);
        x.residuals = residuals(original, x.configuration);
        x.max_residual = x.residuals.max();
        const double size = internal::configuration_size(x.configuration);
        x.max_relative_residual = internal::relative_residual(x.residuals, size);
        if (internal::verified(x.residuals, parameters.residual_threshold, size)) {
          add_found(x);
        } else if (internal::mirror_image(x.residuals, parameters.residual_threshold, size)) {
          ++st.spurious;
        } else {
          Scene_unresolved u;
          u.reason = "root of the tree's system not verified in the original system (residual " + std::to_string(x.max_residual) + ")";
          u.charts = x.charts;
          u.placements = placements;
          u.box = x.parameters;
          u.at_centre = x.configuration;
          out.unresolved.push_back(std::move(u));
        }
      }
      for (const Tree_region& r : tr.unresolved) {
        Scene_unresolved u;
        u.kind = r.kind;
        u.reason = r.reason + " (solved along the tree: chart -1 is a hinge whose chart was not chosen yet, its whole circle)";
        u.charts = r.charts;
        u.placements = placements;
        u.box = r.box;
        u.boxes = r.boxes;
        if (std::find(r.charts.begin(), r.charts.end(), Tree_system<Traits>::WHOLE) == r.charts.end()) {
          std::vector<double> centre;
          for (const auto& b : r.box) centre.push_back(0.5 * b.first + 0.5 * b.second);
          u.at_centre = configuration(c, tree, Tree_parametrization(c, tree, r.charts), centre, placements);
        }
        out.unresolved.push_back(std::move(u));
      }
      st.verify_seconds += since(t3);
      if (!tr.stopped.empty()) {
        std::ostringstream why;
        why << (tr.stopped == "interrupted" ? std::string("interrupted")
                : tr.stopped == "time limit" ? "time limit of " + seconds_text(seconds_before + parameters.maximal_seconds) + " s reached"
                                             : tr.stopped + " (" + std::to_string(tp.maximal_boxes) + " boxes)")
            << " after " << seconds_text(seconds_before + since(started)) << " s, solving along the tree: " << tr.statistics.boxes
            << " boxes, the configurations certified so far are listed, the rest of the hinges' circles is pending";
        out.limits.push_back(why.str());
      }
      done = total;
      report();
    }
  }
  // The factored answer of the placement combination `placements` (see its call in the loop
  // below): `parts` of the system s0 of chart 0, `eqv` and `inv` the union of the supports
  // over the charts, `group` the chart group (tree edge) of each variable, `build` the
  // reduced system of a full chart assignment. False, with nothing recorded in the answer
  // (the work it did counted in the statistics: boxes, seconds), where it does not apply: the
  // plan over every chart then solves the combination.
  CGAL::Gmpz not_listed = 0;     // configurations a factored answer counted and did not list
  std::string listing_stop;      // why a factored answer's expansion stopped (empty: it did not)
  std::size_t product_unverified = 0;  // listed products a residual refused (see below)
  auto solve_factored = [&](const std::vector<Independent_part>& parts, const std::vector<std::vector<std::size_t>>& eqv,
                            const std::vector<std::vector<std::size_t>>& inv, const std::vector<std::size_t>& group,
                            const auto& build, const Polynomial_system<NT>& s0) -> bool {
    typedef Incidence_tree_parametrization<Traits, NT> Parametrization;
    const std::size_t n = s0.number_of_variables(), npos = std::size_t(-1);
    const double threshold = parameters.residual_threshold;
    // each part along its own plan, over its own edges' charts (the others at chart 0: its
    // equations do not see them)
    struct Part_run
    {
      const Independent_part* part;
      std::vector<std::size_t> local_group;
      std::vector<int> radix;
      Plan_charts_result<IT> result;
    };
    std::vector<Part_run> runs;
    auto t2 = Clock::now();
    for (const auto& part : parts) {
      Part_run pr;
      pr.part = &part;
      auto local = [&](const std::vector<std::size_t>& v) {
        std::vector<std::size_t> w;
        for (std::size_t j : v) w.push_back(std::size_t(std::lower_bound(part.variables.begin(), part.variables.end(), j) - part.variables.begin()));
        return w;
      };
      std::vector<std::vector<std::size_t>> pe, pi;
      for (std::size_t i : part.equations) pe.push_back(local(eqv[i]));
      for (std::size_t q : part.inequalities) pi.push_back(local(inv[q]));
      const Solution_plan pp(part.variables.size(), pe, pi);
      if (pp.structure() != Solution_plan::WELL_CONSTRAINED || !pp.unattached_inequalities().empty() || pp.blocks().empty()) return false;
      for (std::size_t j : part.variables)
        pr.local_group.push_back(group[j] == npos ? npos
                                                  : std::size_t(std::lower_bound(part.groups.begin(), part.groups.end(), group[j]) - part.groups.begin()));
      for (std::size_t g : part.groups) pr.radix.push_back(radix_c[g]);
      const std::function<Polynomial_system<NT>(const std::vector<int>&)> make = [&](const std::vector<int>& ch) {
        std::vector<int> full(radix_c.size(), 0);
        for (std::size_t k = 0; k < ch.size(); ++k) full[part.groups[k]] = ch[k];
        return part_system(system_of(build(full)), part);
      };
      Subdivision_solver_parameters sp = parameters.solver;
      if (!sp.interrupt) sp.interrupt = parameters.interrupt;
      if (parameters.maximal_seconds > 0) {
        const double left = (std::max)(parameters.maximal_seconds - since(started), 1e-3);
        sp.maximal_seconds = sp.maximal_seconds > 0 ? (std::min)(sp.maximal_seconds, left) : left;
      }
      try {
        pr.result = solve_with_plan_over_charts<IT, NT>(pp, pr.local_group, pr.radix, make, sp);
      } catch (const Input_error&) {
        st.solve_seconds += since(t2);
        return false;
      }
      st.boxes += pr.result.totals.boxes;
      st.krawczyk_tests += pr.result.totals.krawczyk_tests;
      bool apart = pr.result.totals.diagnosis.empty();
      // (an early region stands for every chart of the later blocks; a possible multiple root
      // is tried as a configuration by process(): both left to the plan over every chart)
      for (const auto& f : pr.result.found)
        for (const auto& u : f.result.unresolved)
          apart = apart && !(u.kind == Box_class::UNKNOWN &&
                             (u.block + 1 < pp.blocks().size() || u.reason.rfind("possible multiple root", 0) == 0));
      if (!apart) {
        st.solve_seconds += since(t2);
        return false;
      }
      runs.push_back(std::move(pr));
    }
    st.solve_seconds += since(t2);
    auto t3 = Clock::now();
    std::map<std::vector<int>, std::unique_ptr<Parametrization>> made;
    auto parametrization = [&](const std::vector<int>& ch) -> const Parametrization& {
      auto it = made.find(ch);
      if (it != made.end()) return *it->second;
      if (made.size() >= 4096) made.clear();  // (a reference is used before the next call)
      auto& e = made[ch];
      e.reset(new Parametrization(c, tree, ch, Rotation_form::QUATERNION_CHARTS, placements));
      return *e;
    };
    // each part's roots, its full chart assignment with the others at 0, and its regions
    struct Part_root
    {
      std::vector<int> charts;
      std::vector<std::pair<double, double>> parameters;
      std::vector<double> approximation;
      bool certified, on_boundary, on_inequality_boundary;
    };
    std::vector<std::vector<Part_root>> roots(runs.size());
    std::vector<Scene_unresolved> regions;
    std::vector<std::size_t> regions_of(runs.size(), 0);
    std::vector<char> cut_in(runs.size(), 0);  // a part's solve cut by the time limit or the interrupt
    bool cut = false;  // (set from the regions recorded)
    double assignments = 1;  // full chart assignments with something found
    for (std::size_t k = 0; k < runs.size(); ++k) {
      const Independent_part& part = *runs[k].part;
      assignments *= double(runs[k].result.found.size());
      for (const auto& f : runs[k].result.found) {
        std::vector<int> ch(radix_c.size(), 0);
        for (std::size_t g = 0; g < f.charts.size(); ++g) ch[part.groups[g]] = f.charts[g];
        for (const auto& r : f.result.roots) {
          Part_root x{ch, {}, r.approximation, r.certified, r.on_boundary, r.on_inequality_boundary};
          for (const IT& e : r.enclosure) x.parameters.push_back(CGAL::to_interval(e));
          roots[k].push_back(std::move(x));
        }
        for (const auto& u : f.result.unresolved) {
          Scene_unresolved x;
          x.kind = u.kind;
          x.reason = "independent part " + std::to_string(k + 1) + " of " + std::to_string(runs.size()) + ": " + u.reason;
          x.charts = ch;
          x.placements = placements;
          x.box = s0.box;
          std::vector<double> centre(n);
          for (std::size_t l = 0; l < part.variables.size(); ++l) x.box[part.variables[l]] = CGAL::to_interval(u.box[l]);
          for (std::size_t j = 0; j < n; ++j) centre[j] = 0.5 * x.box[j].first + 0.5 * x.box[j].second;
          x.at_centre = configuration(c, tree, parametrization(ch), centre, placements);
          regions.push_back(std::move(x));
          ++regions_of[k];
          if (u.kind == Box_class::PENDING &&
              (u.reason.find("interrupted") != std::string::npos || u.reason.find("time budget") != std::string::npos))
            cut_in[k] = 1;
        }
      }
    }
    auto account = [&]() {
      st.chart_combinations += per_placement;
      st.planned_systems += per_placement;
      for (const auto& r : runs) {
        st.block_solves += r.result.totals.block_solves;
        st.block_solves_reused += r.result.totals.block_solves_reused;
      }
      st.excluded_by_plan += std::size_t((std::max)(0.0, double(per_placement) - assignments));
      if (cut) plan_cut = true;
      else done += per_placement;
      st.verify_seconds += since(t3);
    };
    // a part without roots nor regions: no configuration with these placements, whatever the
    // others left (their regions stand for nothing); a part without roots but with regions:
    // every part's regions stay (nothing to list)
    for (std::size_t k = 0; k < runs.size(); ++k)
      if (roots[k].empty() && regions_of[k] == 0) {
        account();
        return true;
      }
    for (std::size_t k = 0; k < runs.size(); ++k) cut = cut || cut_in[k];
    for (std::size_t k = 0; k < runs.size(); ++k)
      if (roots[k].empty()) {
        for (auto& x : regions) out.unresolved.push_back(std::move(x));
        account();
        return true;
      }
    // A constraint of the scene involves one part's edges only, so the residuals of a product
    // of the parts' roots are those of its factors: each part's roots are verified with one
    // root of every other part, the references, chosen to verify (the first root of a part
    // may be a mirror image).
    // the configuration of root pick(q) of each part q into v (charts, parameters, poses,
    // residuals); its size returned
    auto assemble = [&](const auto& pick, Scene_configuration& v) {
      std::vector<int> ch(radix_c.size(), 0);
      std::vector<double> x(n, 0);
      v.parameters.assign(n, std::make_pair(0.0, 0.0));
      for (std::size_t q = 0; q < runs.size(); ++q) {
        const Part_root& a = roots[q][pick(q)];
        for (std::size_t g : runs[q].part->groups) ch[g] = a.charts[g];
        for (std::size_t l = 0; l < a.approximation.size(); ++l) {
          x[runs[q].part->variables[l]] = a.approximation[l];
          v.parameters[runs[q].part->variables[l]] = a.parameters[l];
        }
      }
      v.placements = placements;
      v.charts = ch;
      v.variables = s0.variable_names;
      return finish_configuration(v, parametrization(ch), x, false);
    };
    std::vector<std::size_t> ref(runs.size(), 0);
    auto evaluate = [&](std::size_t k, std::size_t i, Scene_configuration& v) {
      return assemble([&](std::size_t q) { return q == k ? i : ref[q]; }, v);
    };
    auto failures = [&](const Scene_configuration& v, double size) {
      std::size_t m = 0;
      for (const auto& e : v.residuals.entries)
        if (e.kind == Residual::MIRRORED || e.kind == Residual::UNPLACED || !(e.value <= threshold * (e.kind == Residual::DISTANCE ? size * size : size))) ++m;
      return m;
    };
    {
      Scene_configuration v;
      double size = evaluate(0, 0, v);
      if (!internal::verified(v.residuals, threshold, size)) {
        for (std::size_t k = 0; k < runs.size(); ++k) {
          std::size_t best = ref[k], fewest = std::size_t(-1);
          for (std::size_t i = 0; i < roots[k].size() && fewest > 0; ++i) {
            Scene_configuration w;
            const double sw = evaluate(k, i, w);
            const std::size_t m = failures(w, sw);
            if (m < fewest) { fewest = m; best = i; }
          }
          ref[k] = best;
        }
        Scene_configuration w;
        size = evaluate(0, ref[0], w);
        if (!internal::verified(w.residuals, threshold, size)) {  // some part has no verified root
          st.verify_seconds += since(t3);
          return false;
        }
      }
    }
    // each part's verified roots, one seen from two charts kept once (as add_found() does)
    std::vector<Scene_part> factors(runs.size());
    std::vector<std::vector<std::size_t>> kept(runs.size());  // root indices
    for (std::size_t k = 0; k < runs.size(); ++k) {
      std::vector<Scene_configuration> seen;
      std::vector<double> sizes;
      for (std::size_t i = 0; i < roots[k].size(); ++i) {
        ++st.roots;
        Scene_configuration v;
        v.certified = roots[k][i].certified;
        const double size = evaluate(k, i, v);
        if (!internal::verified(v.residuals, threshold, size)) {
          if (internal::mirror_image(v.residuals, threshold, size)) { ++st.spurious; continue; }
          Scene_unresolved x;
          x.kind = Box_class::UNKNOWN;
          x.reason = "independent part " + std::to_string(k + 1) + " of " + std::to_string(runs.size()) +
                     ": root of the reduced system not verified in the original system (residual " + std::to_string(v.max_residual) + ")";
          x.charts = v.charts;
          x.placements = placements;
          x.box = v.parameters;
          x.at_centre = v.configuration;
          regions.push_back(std::move(x));
          ++regions_of[k];
          continue;
        }
        bool merged = false;
        for (std::size_t a = 0; a < seen.size() && !merged; ++a) {
          const Part_root& o = roots[k][kept[k][a]];
          if (o.charts == roots[k][i].charts && (o.certified || roots[k][i].certified)) continue;
          if (internal::configuration_distance(seen[a].configuration, v.configuration) > parameters.merge_tolerance * (std::max)(size, sizes[a])) continue;
          merged = true;
          ++st.duplicates;
          const std::size_t times = factors[k].solutions[a].found + 1;
          if (!o.certified && roots[k][i].certified) {
            kept[k][a] = i;
            seen[a] = v;
            sizes[a] = size;
          }
          factors[k].solutions[a].found = times;
        }
        if (merged) continue;
        kept[k].push_back(i);
        seen.push_back(v);
        sizes.push_back(size);
        factors[k].solutions.emplace_back();
      }
      const Independent_part& part = *runs[k].part;
      Scene_part& f = factors[k];
      f.placements = placements;
      f.variable_indices = part.variables;
      for (std::size_t j : part.variables) f.variables.push_back(s0.variable_names[j]);
      for (std::size_t g : part.groups) f.bodies.push_back(c.body(tree.edges[g].child).name);
      for (std::size_t a = 0; a < kept[k].size(); ++a) {
        const Part_root& r = roots[k][kept[k][a]];
        Scene_part_solution& x = f.solutions[a];
        x.certified = r.certified;
        x.on_chart_border = r.on_boundary;
        x.on_inequality_boundary = r.on_inequality_boundary;
        x.charts = r.charts;
        x.parameters = r.parameters;
      }
      f.unresolved = regions_of[k];
    }
    for (auto& x : regions) out.unresolved.push_back(std::move(x));
    CGAL::Gmpz count = 1;
    for (const auto& f : factors) count *= CGAL::Gmpz(long(f.solutions.size()));
    // the product, listed in the order of its digits (the last part's the fastest) up to
    // maximal_listed_configurations and while time is left
    std::size_t listed = 0;
    std::vector<std::size_t> d(runs.size(), 0);
    bool more = count > 0;
    while (more && listing_stop.empty()) {
      if (parameters.maximal_listed_configurations > 0 && found.size() >= parameters.maximal_listed_configurations) {
        listing_stop = "maximal_listed_configurations (" + std::to_string(parameters.maximal_listed_configurations) + ") reached";
        break;
      }
      if (listed % 64 == 0)
        if (const char* why = stop_reason()) {
          listing_stop = std::string(std::string(why) == "interrupted" ? "interrupted" : "the time limit reached") +
                         " while the product of the independent parts was listed";
          break;
        }
      Scene_configuration s;
      s.certified = true;
      s.found = 1;
      for (std::size_t q = 0; q < runs.size(); ++q) {
        const Scene_part_solution& a = factors[q].solutions[d[q]];
        s.certified = s.certified && a.certified;
        s.on_chart_border = s.on_chart_border || a.on_chart_border;
        s.on_inequality_boundary = s.on_inequality_boundary || a.on_inequality_boundary;
        s.found *= a.found;
      }
      s.coefficient_precision = out.coefficient_precision;
      const double size = assemble([&](std::size_t q) { return kept[q][d[q]]; }, s);
      ++listed;
      if (internal::verified(s.residuals, threshold, size)) found.push_back({std::move(s), size});
      else ++product_unverified;
      // the next digits
      std::size_t q = runs.size();
      for (;;) {
        if (q == 0) { more = false; break; }
        --q;
        if (++d[q] < factors[q].solutions.size()) break;
        d[q] = 0;
      }
    }
    not_listed += count - CGAL::Gmpz(long(listed));
    for (auto& f : factors) out.parts.push_back(std::move(f));
    account();
    return true;
  };
  report();  // (0 combinations done: on a large scene the first visible step)
  std::optional<std::set<std::vector<int>>> propagated;
  if (!swept && !retry && !one_dof && parameters.chart_propagation && per_placement > 1 && total == per_placement &&
      Tree_system<Traits>::unsupported(c, tree).empty()) {
    auto t1 = Clock::now();
    std::optional<Tree_system<Traits>> ts;
    try { ts.emplace(c, tree, selection); } catch (const Input_error&) {}  // (an optimization only: every combination then)
    if (ts && ts->is_square()) {
      Tree_solver_parameters tp;
      tp.charts_only = true;
      tp.maximal_boxes = 16 * per_placement;
      tp.consistency_cells = parameters.consistency_cells;
      tp.interrupt = parameters.interrupt;
      if (parameters.maximal_seconds > 0) tp.maximal_seconds = (std::max)(1e-3, parameters.maximal_seconds - since(started));
      Tree_solve_result tr = solve_tree_system(*ts, tp);
      st.consistent_fraction = tr.consistent_fraction;
      st.consistency_seconds += tr.consistency_seconds;
      if (tr.stopped.empty()) propagated = std::move(tr.chart_combinations);
    }
    st.solve_seconds += since(t1);
  }
  // One chart combination per placement combination (no tree edge with charts: a merged
  // rigid part's placements, a tree or strip of bodies known by distances): the placement
  // combinations themselves are built and solved in parallel, and taken in their order.
  if (swept) {
    // (solved above)
  } else if (per_placement == 1) {
    std::vector<int> next_placements = placements;
    bool more_placements = true;
    auto next = [&](Combination_work& w) {
      while (more_placements) {
        std::vector<int> pl = next_placements;
        more_placements = internal::next_combination(next_placements, radix_p);
        if (!placements_fit(pl)) {
          if (retry) continue;
          w.placements = std::move(pl);
          w.excluded = true;
          return true;
        }
        std::vector<int> ch(radix_c.size(), 0);
        if (retry && !retry->only.count(Scene_combination(pl, ch))) continue;
        if ((stopped = stop_reason())) return more_placements = false;
        w.placements = std::move(pl);
        w.charts = std::move(ch);
        return true;
      }
      return false;
    };
    internal::ordered_pipeline<Combination_work>(threads, 4 * std::size_t(threads), next, [&](Combination_work& w) {
        if (w.excluded) return;
        auto t1 = Clock::now();
        // as below: chart 0's system, and the system by a change of chart from it where it allows
        std::optional<Reduced_system<Traits, NT>> zero;
        if (parameters.change_charts) {
          zero.emplace(c, tree, selection, std::vector<int>(radix_c.size(), 0), Rotation_form::QUATERNION_CHARTS, w.placements);
          if (!zero->changes_charts()) {
            w.r.emplace(std::move(*zero));  // (the system a direct build gives: the same constructor)
            zero.reset();
          }
        }
        if (!w.r)
          w.r.emplace(zero ? Reduced_system<Traits, NT>(*zero, w.charts)
                           : Reduced_system<Traits, NT>(c, tree, selection, w.charts, Rotation_form::QUATERNION_CHARTS, w.placements));
        w.sys = system_of(*w.r);
        w.reduce_seconds = since(t1);
        solve_combination(w);
      }, [&](Combination_work& w) {
        if (w.excluded) {
          ++st.placements_excluded;
          done += per_placement;
          return;
        }
        take_combination(w);
      });
  } else
  do {
    if (!placements_fit(placements)) {
      if (!retry) { ++st.placements_excluded; done += per_placement; }
      continue;
    }
    // the system of chart 0 of this placement combination, which the others are made from
    std::optional<Reduced_system<Traits, NT>> base;
    bool base_tried = !parameters.change_charts;
    // Along the solution plan over the charts (solve_with_plan_over_charts()): each block
    // chooses the charts of its own tree edges (hinges and free rotations), so a block is not
    // solved again for each chart of the edges after it, and the chart combinations under a
    // block without roots are never built. For square systems of more than one block, in a
    // first pass (not a retry at a higher precision, which solves chosen combinations only).
    if (!retry && !one_dof && parameters.solve_with_plan && parameters.plan_over_charts && per_placement > 1) {
      if ((stopped = stop_reason())) break;
      auto t1 = Clock::now();
      std::optional<Reduced_system<Traits, NT>> zero;
      zero.emplace(c, tree, selection, std::vector<int>(radix_c.size(), 0), Rotation_form::QUATERNION_CHARTS, placements);
      // the others by a change of chart of this one where it allows (hinges), else built
      const bool changes = parameters.change_charts && zero->changes_charts();
      st.reduce_seconds += since(t1);
      // (one block in chart 0 is one block over the charts: the union can only merge blocks;
      // told from the equations' supports, before any system is copied)
      auto blocks_in_chart_0 = [&]() {
        std::vector<std::vector<std::size_t>> v;
        for (const auto& e : zero->equations()) v.push_back(e.variables);
        return Solution_plan(zero->number_of_variables(), v).blocks().size();
      };
      if (zero->number_of_variables() > 0 && zero->number_of_equations() == zero->number_of_variables() && blocks_in_chart_0() > 1) {
        auto t2 = Clock::now();
        auto build = [&](const std::vector<int>& ch) {
          return changes ? Reduced_system<Traits, NT>(*zero, ch)
                         : Reduced_system<Traits, NT>(c, tree, selection, ch, Rotation_form::QUATERNION_CHARTS, placements);
        };
        // the variables an equation involves in any chart: the union over the systems with
        // every edge at chart j (a chart moves the exponents of its edge's variables only;
        // the plan's solve checks each system it builds against it)
        const Polynomial_system<NT> s0 = system_of(*zero);
        {
          std::vector<std::vector<std::size_t>> eqv(s0.equations.size()), inv(s0.inequalities.size());
          auto unite = [](std::vector<std::vector<std::size_t>>& u, const std::vector<Sparse_polynomial<NT>>& a) {
            for (std::size_t i = 0; i < a.size() && i < u.size(); ++i) {
              std::vector<std::size_t> x = a[i].variables(), y;
              std::set_union(x.begin(), x.end(), u[i].begin(), u[i].end(), std::back_inserter(y));
              u[i].swap(y);
            }
          };
          unite(eqv, s0.equations);
          unite(inv, s0.inequalities);
          const int most = radix_c.empty() ? 1 : *std::max_element(radix_c.begin(), radix_c.end());
          for (int j = 1; j < most; ++j) {
            std::vector<int> ch(radix_c.size());
            for (std::size_t k = 0; k < ch.size(); ++k) ch[k] = (std::min)(j, radix_c[k] - 1);
            const Polynomial_system<NT> sj = system_of(build(ch));
            unite(eqv, sj.equations);
            unite(inv, sj.inequalities);
          }
          const Solution_plan plan(s0.number_of_variables(), eqv, inv);
          if (plan.blocks().size() > 1 && plan.structure() == Solution_plan::WELL_CONSTRAINED && plan.unattached_inequalities().empty()) {
            const std::vector<std::size_t> group = internal::chart_groups(zero->parametrization(), s0.number_of_variables());
            // Independent parts (no equation, inequality or tree edge joins them: one per
            // plate of stacked platforms): each solved over its own edges' charts, the answer
            // their product, counted exactly and listed up to maximal_listed_configurations
            // (issue 28, item 1). A part left with a diagnosis, an early region or a possible
            // multiple root, or whose solutions no verified solution of the others completes,
            // falls back to the plan over every chart below, with the time then left.
            if (parameters.factor_parts && nc_bodies.empty()) {
              const std::vector<Independent_part> parts = independent_parts(s0.number_of_variables(), eqv, inv, group);
              if (parts.size() > 1) {
                if (solve_factored(parts, eqv, inv, group, build, s0)) {
                  report();
                  continue;
                }
                if ((stopped = stop_reason())) break;
                t2 = Clock::now();  // (the attempt counted its own seconds)
              }
            }
            Subdivision_solver_parameters sp = parameters.solver;
            if (!sp.interrupt) sp.interrupt = parameters.interrupt;
            if (parameters.maximal_seconds > 0) {
              const double left = (std::max)(parameters.maximal_seconds - since(started), 1e-3);
              sp.maximal_seconds = sp.maximal_seconds > 0 ? (std::min)(sp.maximal_seconds, left) : left;
            }
            const std::function<Polynomial_system<NT>(const std::vector<int>&)> make = [&](const std::vector<int>& ch) {
              return system_of(build(ch));
            };
            std::optional<Plan_charts_result<IT>> pc;
            try {
              pc = solve_with_plan_over_charts<IT, NT>(plan, group, radix_c, make, sp);
            } catch (const Input_error&) {
              // an equation vanishes once earlier roots are substituted, or a chart changed an
              // earlier block's equations: each combination alone
            }
            st.solve_seconds += since(t2);
            if (pc) {
              st.boxes += pc->totals.boxes;
              st.krawczyk_tests += pc->totals.krawczyk_tests;
            }
            // a region a block before the last left undecided stands for every chart of the
            // edges after it, but a retry at a higher precision solves the combinations named
            // by its regions only: then each combination alone, with regions of its own
            bool early_region = false;
            if (pc)
              for (const auto& f : pc->found)
                for (const auto& u : f.result.unresolved)
                  early_region = early_region || (u.kind == Box_class::UNKNOWN && u.block + 1 < plan.blocks().size());
            if (pc && pc->totals.diagnosis.empty() && !early_region) {
              st.chart_combinations += per_placement;
              st.planned_systems += per_placement;
              st.block_solves += pc->totals.block_solves;
              st.block_solves_reused += pc->totals.block_solves_reused;
              st.excluded_by_plan += per_placement - pc->found.size();
              auto t3 = Clock::now();
              for (auto& f : pc->found) {
                const Reduced_system<Traits, NT> r = build(f.charts);
                const Polynomial_system<NT> sys = system_of(r);
                Solver_result<IT> res = internal::solver_result_of_plan(f.result, plan.blocks().size());
                process(f.charts, r, sys, res);
              }
              st.verify_seconds += since(t3);
              // stopped inside (the time limit, the interrupt): what it certified is kept, its
              // rest is pending, and none of its combinations counts as solved
              bool cut = false;
              for (const auto& f : pc->found)
                for (const auto& u : f.result.unresolved)
                  cut = cut || (u.kind == Box_class::PENDING &&
                                (u.reason.find("interrupted") != std::string::npos || u.reason.find("time budget") != std::string::npos));
              if (cut) plan_cut = true;
              else done += per_placement;
              report();
              continue;
            }
            // a block not zero-dimensional, or an early region: each combination alone, whole
            // where the plan diagnoses (the whole solve diagnoses, and traces, what a block could not)
          }
        }
      }
      // each combination alone from here: chart 0's system is the base of the others
      base_tried = true;
      if (changes) base.emplace(std::move(*zero));
      report();  // (chart 0's system built: on a large scene the first visible step)
    }
    // Each chart combination alone, built and solved in parallel (parameters.solver.threads,
    // up to four combinations per thread under way), what each found processed here, one at a
    // time, in the order of the combinations (internal::ordered_pipeline()): the answer does not
    // depend on the threads. The stop is checked before each combination starts.
    std::vector<int> next_charts(radix_c.size(), 0);
    bool more_charts = true;
    auto next = [&](Combination_work& w) {
      while (more_charts) {
        std::vector<int> ch = next_charts;
        more_charts = internal::next_combination(next_charts, radix_c);
        if (retry && !retry->only.count(Scene_combination(placements, ch))) continue;
        if (propagated && !propagated->count(ch)) { ++st.excluded_by_propagation; ++done; continue; }
        if ((stopped = stop_reason())) return more_charts = false;
        if (!base_tried) {
          auto t1 = Clock::now();
          base_tried = true;
          base.emplace(c, tree, selection, std::vector<int>(radix_c.size(), 0), Rotation_form::QUATERNION_CHARTS, placements);
          if (!base->changes_charts()) base.reset();
          st.reduce_seconds += since(t1);
        }
        w.charts = std::move(ch);
        w.placements = placements;
        return true;
      }
      return false;
    };
    internal::ordered_pipeline<Combination_work>(threads, 4 * std::size_t(threads), next, [&](Combination_work& w) {
        const std::vector<int>& charts = w.charts;
        auto t1 = Clock::now();
        w.r.emplace(base ? Reduced_system<Traits, NT>(*base, charts)
                         : Reduced_system<Traits, NT>(c, tree, selection, charts, Rotation_form::QUATERNION_CHARTS, w.placements));
        w.sys = system_of(*w.r);
        w.reduce_seconds = since(t1);
        solve_combination(w);
      }, take_combination);
  } while (!stopped && internal::next_combination(placements, radix_p));
  // a stop the solver met inside the last combination (its rest left pending for it) is a
  // stop of the whole solve too
  if (!stopped && !swept)
    if (const char* why = stop_reason())
      for (const auto& u : out.unresolved)
        if (u.kind == Box_class::PENDING && (u.reason.find("interrupted") != std::string::npos || u.reason.find("time budget") != std::string::npos)) {
          stopped = why;
          break;
        }
  if (stopped) {
    std::ostringstream why;
    why << (std::string(stopped) == "interrupted" ? std::string("interrupted")
                                                  : "time limit of " + seconds_text(seconds_before + parameters.maximal_seconds) + " s reached")
        << " after " << seconds_text(seconds_before + since(started)) << " s: " << done << " of ";
    if (total) why << total; else why << "more than 2^62";
    why << " combinations of charts and placements solved (a solve it cut short left its rest pending), the others not solved";
    if (plan_cut)
      why << "; a solve along the plan over the charts of a placement combination was cut short: the configurations it"
             " certified are listed, the blocks it did not reach are pending";
    out.limits.push_back(why.str());
  }
  if (!positive.empty()) out.diagnosis = positive;
  // the first found, up to maximal_listed_configurations; the count exact
  out.configuration_count = not_listed + CGAL::Gmpz(long(found.size()));
  if (parameters.maximal_listed_configurations > 0 && found.size() > parameters.maximal_listed_configurations) {
    // (those not certified among the dropped ones keep the answer incomplete, and a retry at
    // more bits solves their combinations again)
    for (std::size_t i = parameters.maximal_listed_configurations; i < found.size(); ++i)
      if (!found[i].s.certified) {
        ++out.unlisted_not_certified;
        if (uncertain) uncertain->insert(combination_of(found[i].s.placements, found[i].s.charts));
      }
    found.resize(parameters.maximal_listed_configurations);
    if (listing_stop.empty())
      listing_stop = "maximal_listed_configurations (" + std::to_string(parameters.maximal_listed_configurations) + ") reached";
  }
  if (!listing_stop.empty()) {
    std::ostringstream o;
    o << found.size() << " of " << out.configuration_count << " configurations listed: " << listing_stop;
    out.listing = o.str();
  }
  if (product_unverified > 0)
    out.limits.push_back(std::to_string(product_unverified) + " configuration(s) of the product of the independent parts failed the"
                         " residual test in the original system that their parts passed (not listed, not counted): a constraint"
                         " across two parts the reduced system does not show");
  for (auto& f : found) out.configurations.push_back(std::move(f.s));
  out.curves = internal::join_pieces(pieces, 1e-7);
  // a stable order: by the first configuration's points
  std::sort(out.curves.begin(), out.curves.end(), [](const Scene_curve& a, const Scene_curve& b) {
    return a.configurations.front().points < b.configurations.front().points;
  });
  std::sort(out.configurations.begin(), out.configurations.end(), configuration_order);
  if (uncertain) {
    for (const auto& u : out.unresolved)
      if (u.kind == Box_class::UNKNOWN) uncertain->insert(Scene_combination(u.placements, u.charts));
    for (const auto& x : out.configurations)
      if (!x.certified) uncertain->insert(combination_of(x.placements, x.charts));
  }
  return out;
}

// An answer that is not complete for a reason wide coefficients can cause: a positive-
// dimensional diagnosis, an unknown region, a configuration or curve not certified, with
// coefficients that are not exact. Budgets (pending regions) and limits are not such reasons.
inline bool precision_may_help(const Scene_solve_result& r)
{
  if (r.complete() || r.fast || !r.no_configuration.empty() || !r.limits.empty()) return false;
  if (r.statistics.coefficient_width == 0) return false;
  if (r.diagnosis.rfind("positive_dimensional", 0) == 0) return true;
  if (!r.diagnosis.empty()) return false;  // under- or over-constrained: the structure
  for (const auto& u : r.unresolved) if (u.kind == Box_class::UNKNOWN) return true;
  for (const auto& x : r.configurations) if (!x.certified) return true;
  for (const auto& c : r.curves) if (!c.certified) return true;
  if (r.unlisted_not_certified > 0) return true;
  for (const auto& q : r.parts)
    for (const auto& x : q.solutions) if (!x.certified) return true;
  return false;
}

// What an answer lacked, for Scene_solve_result::precision_history.
inline std::string precision_note(const Scene_solve_result& r, double seconds)
{
  std::size_t unknown = 0, uncertified = 0;
  for (const auto& u : r.unresolved) if (u.kind == Box_class::UNKNOWN) ++unknown;
  for (const auto& x : r.configurations) if (!x.certified) ++uncertified;
  std::string s = std::to_string(r.coefficient_precision) + " bits: " + std::to_string(r.configurations.size()) + " configuration(s)";
  if (uncertified) s += ", " + std::to_string(uncertified) + " not certified";
  if (unknown) s += ", " + std::to_string(unknown) + " unknown region(s)";
  if (r.diagnosis.rfind("positive_dimensional", 0) == 0) s += ", positive-dimensional";
  std::ostringstream o;
  o.precision(2);
  o << " (coefficients " << r.statistics.coefficient_width << " wide, " << seconds << " s)";
  return s + o.str();
}

// solve_scene_unscaled(), then again with more bits while precision may be the cause: only
// the combinations of charts and placements whose solve left something uncertain, when the
// answer is a list of configurations (a curve, or a positive-dimensional diagnosis, is
// solved again whole: its pieces are joined across combinations).
template <class IT, class NT, class Traits>
Scene_solve_result solve_scene_with_precision(const Rigid_body_collection<Traits>& original, const Rigid_body_collection<Traits>& c,
                                              const Incidence_tree& tree, const Well_formed_selection& selection,
                                              const Scene_solve_parameters& parameters)
{
  auto t0 = std::chrono::steady_clock::now();
  const auto begun = t0;
  std::set<Scene_combination> uncertain;
  Scene_solve_result r = solve_scene_unscaled<IT, NT>(original, c, tree, selection, parameters, 0, nullptr, &uncertain);
  if constexpr (std::is_same<NT, CGAL::Gmpq>::value) {
    return r;  // exact coefficients (the solver raises its own precision)
  } else {
    if (!precision_may_help(r)) return r;
#ifdef CGAL_USE_MPFI
    while (precision_may_help(r)) {
      const unsigned bits = r.coefficient_precision < 128 ? 128 : 2 * r.coefficient_precision;
      if (bits > parameters.maximal_coefficient_precision) break;
      const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - begun).count();
      // the whole solve's time limit and interrupt bound the retries too: one not begun, or
      // cut short, leaves the answer before it (not complete), and says so
      const bool interrupted = parameters.interrupt && parameters.interrupt->load(std::memory_order_relaxed);
      if (interrupted || (parameters.maximal_seconds > 0 && elapsed >= parameters.maximal_seconds)) {
        r.limits.push_back(std::string(interrupted ? "interrupted" : "time limit of " + seconds_text(parameters.maximal_seconds) + " s reached") +
                           " before the retry with coefficients at " + std::to_string(bits) + " bits");
        break;
      }
      // only the uncertain combinations, unless curves are joined across them
      // (and a factored or cut answer: solved again whole, its parts factored again)
      const bool whole = !r.curves.empty() || !r.diagnosis.empty() || uncertain.empty() || !r.parts.empty() || !r.listing.empty();
      Scene_retry retry;
      retry.earlier = &r;
      retry.only = uncertain;
      std::vector<std::string> history = r.precision_history;
      history.push_back(precision_note(r, seconds) +
                        (whole ? std::string() : "; " + std::to_string(uncertain.size()) + " combination(s) of charts and placements"
                                                     " left something uncertain and were solved again at " + std::to_string(bits) +
                                                     " bits, the others kept"));
      t0 = std::chrono::steady_clock::now();
      Scene_solve_parameters p = parameters;
      p.solver.precision = bits;
      if (parameters.maximal_seconds > 0) p.maximal_seconds = parameters.maximal_seconds - elapsed;
      Solver_precision_guard<CGAL::Gmpfi> guard(bits);
      std::set<Scene_combination> still;
      Scene_solve_result again =
          solve_scene_unscaled<CGAL::Gmpfi, CGAL::Gmpfi>(original, c, tree, selection, p, elapsed, whole ? nullptr : &retry, &still);
      const bool cut = std::any_of(again.limits.begin(), again.limits.end(), [](const std::string& l) {
        return l.rfind("interrupted", 0) == 0 || l.rfind("time limit of", 0) == 0;
      });
      if (cut) {
        r.limits.push_back("the retry with coefficients at " + std::to_string(bits) + " bits was cut short (" + again.limits.back() +
                           "); this is the answer at " + std::to_string(r.coefficient_precision) + " bits");
        break;
      }
      r = std::move(again);
      r.precision_history = std::move(history);
      uncertain = std::move(still);
    }
    if (!r.precision_history.empty() && r.diagnosis.rfind("positive_dimensional", 0) == 0)
      r.diagnosis += "; the same with coefficients at " + std::to_string(r.coefficient_precision) +
                     " bits (precision ruled out as the cause up to there)";
#else
    r.precision_history.push_back("this build has no MPFI: the coefficients were not raised above " +
                                  std::to_string(r.coefficient_precision) + " bits");
#endif
    return r;
  }
}

} // namespace internal

/*!
\ingroup PkgRigidIncidenceSolver
\brief Every real configuration of a scene: the reduced system solved in every chart
combination by `Subdivision_solver<IT>`, each root turned into a configuration, verified in
the original system, and roots found in two charts merged.

When the coefficients are enclosed in intervals (`NT` is not `CGAL::Gmpq`) and the answer is
not complete for a reason their width can cause (a positive-dimensional diagnosis, an unknown
region, a configuration not certified), the scene is solved again with `CGAL::Gmpfi`
coefficients at 128, then 256 bits (`Scene_solve_parameters::maximal_coefficient_precision`);
the answer is the last one, `Scene_solve_result::coefficient_precision` says at which
precision, `precision_history` what the lower ones gave, and a positive-dimensional diagnosis
that persists says up to which precision precision was ruled out.

A region the solver stops as a "possible multiple root" whose centre satisfies the original
system is returned as a configuration that is not certified and is marked `singular` (a root
that is not simple cannot be certified by intervals); the answer is then not complete.

A scene whose size (see below) is beyond 2^+-20 is solved scaled by a power of two, exactly,
at unit size (the reduced system's coefficients grow as the sixth power of the size and
would leave the range of doubles at 1e55), and its configurations are given back at its own
scale (`Scene_solve_result::scale_exponent`). The size counts the coordinates of the points
that enter the reduced system (points of two or more bodies, ends of distances) and the
distances, not the points of one body alone.

\tparam IT the solver's interval type (`CGAL::Interval_nt<false>` or `CGAL::Gmpfi`)
\tparam NT the coefficient type of the reduced system: `CGAL::Gmpq` when every covering body
has coordinates (then a root the double precision cannot certify is retried with more bits),
else `CGAL::Interval_nt<false>` or `CGAL::Gmpfi`
\param original the collection as the scene file gives it (for the residuals)
\param c its standard collection (`standardize()`)
\param tree the incidence tree of `c` (`optimal_incidence_tree()`)
\param selection the well-formed incidences for `tree` (`select_well_formed_incidences()`)
\param parameters the solver's parameters and the tolerances of merging and verification
*/
template <class IT, class NT, class Traits>
Scene_solve_result solve_scene(const Rigid_body_collection<Traits>& original, const Rigid_body_collection<Traits>& c,
                               const Incidence_tree& tree, const Well_formed_selection& selection,
                               const Scene_solve_parameters& parameters = Scene_solve_parameters())
{
  // the interrupt and the time limit also cut the wait for the exact decisions of a body
  // (run in a child process, see enumerate_placements())
  internal::Wait_stop_scope stop(parameters.interrupt, parameters.maximal_seconds);
  // (refused before any work, not when a sweep or the chart propagation first needs it)
  internal::check_consistency_cells(parameters.consistency_cells, "solve_scene");
  const long k = internal::size_exponent(c);
  if (k >= -20 && k <= 20) return internal::solve_scene_with_precision<IT, NT>(original, c, tree, selection, parameters);
  Scene_solve_result r = internal::solve_scene_with_precision<IT, NT>(internal::scaled_collection(original, -k),
                                                                      internal::scaled_collection(c, -k), tree, selection, parameters);
  internal::scale_result(r, k);
  return r;
}

} // namespace Rigid_incidence
} // namespace CGAL

#endif
