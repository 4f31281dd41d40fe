// Copyright (c) 2026 Rigid_incidence contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// What the subdivision solver returns: every box it leaves, in exactly one class (certified,
// unknown, pending), as IBEX reports them, and its parameters and statistics.

#ifndef CGAL_RIGID_INCIDENCE_SOLVER_RESULT_H
#define CGAL_RIGID_INCIDENCE_SOLVER_RESULT_H

#include <atomic>
#include <cstddef>
#include <algorithm>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Rigid_incidence {

/// \ingroup PkgRigidIncidenceSolver
/// How the solver chooses the variable to split a box in.
enum class Split_strategy {
  LARGEST_WIDTH, ///< the variable whose interval is widest relative to the initial box (default)
  ROUND_ROBIN,   ///< the variables in turn, whatever their widths
  SMEAR          ///< the variable j with the largest max_i |df_i/dx_j| / max_k |df_i/dx_k| * width_j / initial width_j at the box centre (after IBEX's smear)
};

/*!
\ingroup PkgRigidIncidenceSolver
\brief Parameters of `Subdivision_solver`.

Widths are absolute, in the units of each variable.
*/
struct Subdivision_solver_parameters
{
  /// A certified root is tightened by interval Newton until its enclosure is at most this wide
  /// in every variable (or until the precision cannot tighten it more).
  double tolerance = 1e-12;
  /// A box at most this wide in every variable that is neither excluded nor certified is not
  /// split further: it becomes an `UNKNOWN` box. 0: the default, 1e-9 times the widest
  /// variable of the initial box in double precision, and 2^(-(p - 53) / 2) times that with
  /// `CGAL::Gmpfi` at p > 53 bits (finer with the precision, so that close roots the
  /// arithmetic can separate are not kept in one box).
  double minimal_width = 0;
  /// A box at most this wide in every variable on which the Jacobian may be singular (the
  /// Krawczyk operator does not contract) becomes an `UNKNOWN` box with reason "possible
  /// multiple root" without further splitting (a multiple root, or a point of a solution
  /// curve). 0: the default, 1e-6 times the widest variable of the initial box; negative:
  /// split such boxes down to `minimal_width` too. The retry at a higher precision splits down
  /// to the minimal width, so two simple roots closer than this are still separated there;
  /// where there is no higher precision to try (interval coefficients, `maximal_precision`
  /// 0), a small cluster of such boxes is solved again at the working precision down to the
  /// minimal width.
  double singular_width = 0;
  /// Bits of the MPFR mantissa when the interval type is `CGAL::Gmpfi` (ignored for
  /// `CGAL::Interval_nt`).
  unsigned precision = 53;
  /// With exact coefficients (`CGAL::Gmpq` or `double`) and MPFI available: a small cluster of
  /// unknown boxes (a root the working precision could not certify, e.g. two roots 1e-8
  /// apart in double) is solved again with `CGAL::Gmpfi` at twice the working precision (at
  /// least 106 bits), as long as that is at most this many bits (0: never).
  unsigned maximal_precision = 212;
  /// At most this many boxes are visited; what is left is `PENDING`.
  std::size_t maximal_boxes = 200000;
  /// The solver keeps every equation and inequality as a dense tensor-product array over the
  /// variables it involves (prod (degree + 1) coefficients), with its first derivatives (one
  /// array per variable, k of them) and second derivatives (k^2): about (1 + k + k^2) times the
  /// array. A system that needs more than this many coefficients in all is refused with an
  /// `Input_error` that names its largest equation, before anything is allocated (an equation
  /// in 20 variables of degree 2 would need 3^20 = 3.5e9 coefficients for its array alone).
  /// The default, 2^25, is about 0.8 GB with `CGAL::Interval_nt<false>`.
  double maximal_coefficients = 33554432;
  /// Wall-clock budget in seconds (0: none); what is left when it runs out is `PENDING`.
  double maximal_seconds = 0;
  /// A flag another thread or a signal handler may set (null: none): the solve stops at the
  /// next box once it reads true, and what is left is `PENDING` ("interrupted").
  const std::atomic<bool>* interrupt = nullptr;
  /// Threads for the independent pieces of a solve (oneTBB): the branches of a solution plan
  /// (each root of a block, each chart of a block's own hinges) in `solve_with_plan()` and
  /// `solve_with_plan_over_charts()`, the chart and placement combinations of `solve_scene()`.
  /// 1: the calling thread only; 0: every core of the machine (never more than oneTBB's default
  /// concurrency, the cores it may use). The answer is the same, in the
  /// same order, with any number (what each piece finds is merged in the order of a sequential
  /// run); only a time limit or an interrupt can stop different pieces. Without oneTBB
  /// (`CGAL_LINKED_WITH_TBB` not defined, as CGAL's `CGAL::TBB_support` target defines it)
  /// every solve runs on the calling thread. One subdivision (one box tree) is sequential.
  unsigned threads = 1;
  /// Fast, non-certified mode: plain double subdivision, Newton polish, no existence proof.
  /// Roots come back with `certified == false`.
  bool fast = false;
  /// Preconditioning by the inverse Jacobian at the box centre before domain reduction.
  bool preconditioning = true;
  /// Domain reduction by projected-polyhedron clipping (else plain bisection).
  bool domain_reduction = true;
  /// Domain reduction is repeated while it leaves at most this fraction of every variable's
  /// width; a weaker reduction is followed by a split.
  double reduction_ratio = 0.7;
  /// How to choose the variable to split.
  Split_strategy split = Split_strategy::LARGEST_WIDTH;
  /// Near an ill-conditioned point (the Jacobian's singular values at the box centre more
  /// than 100 times apart, once the box is at most 1/16 of the search box wide), solve the box
  /// once in sheared coordinates, one of whose axes follows the Jacobian's near-null direction
  /// (see the user manual); the box falls back to ordinary subdivision when that solve leaves
  /// anything unresolved, and the solver stops trying after 8 such solves once half of them
  /// fell back. Needs the preconditioning; not used with inequalities, in the fast mode (where
  /// a root of the sheared solve cannot be accepted without its proof: 24 of the Stewart-Gough
  /// platform's 162 sheared solves fell back there, and the fast solve took longer), or when a
  /// coefficient is wider than 1e-9 of its equation's largest (a block of a plan whose inputs
  /// are boxes: the tube is then as wide as the coefficients make it; on Jansen's linkage the
  /// sheared solves of its block solves took a fifth of the time for nothing).
  bool oriented_boxes = true;
  /// Stop once the unknown boxes show a curve of solutions (a chain of at least this many
  /// touching rank-deficient boxes spanning 100 singular widths): the rest is `PENDING` with
  /// reason "stopped: positive-dimensional solution set", and the result's diagnosis says
  /// so. Subdividing along a curve would otherwise spend the whole box budget at the
  /// singular width. 0: never stop.
  std::size_t positive_dimensional_evidence = 256;
};

/// \ingroup PkgRigidIncidenceSolver
/// The class of a box the solver leaves.
enum class Box_class {
  CERTIFIED, ///< exactly one root in the box, proved (Krawczyk)
  UNKNOWN,   ///< minimal width reached without a proof; `reason` says why
  PENDING    ///< the box or time budget ran out before the box was decided
};

/// \ingroup PkgRigidIncidenceSolver
/// A root the solver found.
template <class IT>
struct Solver_root
{
  std::vector<IT> enclosure;       ///< per variable, an interval containing the root
  std::vector<double> approximation; ///< per variable, the double nearest a point of the enclosure
  /// proved: the (interval-inflated) Krawczyk box holds exactly one root, and the root is in
  /// `enclosure`; false only in fast mode
  bool certified = false;
  /// the enclosure meets the boundary of the search box (the root may lie just outside it)
  bool on_boundary = false;
  /// some inequality g_j >= 0 of the system may be 0 on the enclosure (the root is kept: it
  /// satisfies the inequalities or lies on their boundary); roots where some g_j < 0 certainly
  /// are not returned
  bool on_inequality_boundary = false;
  /// an upper bound of max_i |f_i| over `enclosure`
  double residual = 0;
  /// the box in which the root is proved to be the only one (the Krawczyk box; contains
  /// `enclosure`)
  std::vector<IT> uniqueness_box;
};

/// \ingroup PkgRigidIncidenceSolver
/// A region the solver could not decide: one box, or a cluster of touching boxes.
template <class IT>
struct Solver_unresolved
{
  Box_class kind = Box_class::UNKNOWN; ///< `UNKNOWN` or `PENDING`
  /// why: "possible multiple root", "precision exhausted", "not certified at minimal width",
  /// "box budget exhausted", "time budget exhausted", "stopped: positive-dimensional solution set"
  std::string reason;
  std::vector<IT> box;             ///< per variable, the hull of the cluster's boxes
  std::size_t boxes = 1;           ///< how many boxes the cluster merges
  /// the Jacobian at the cluster's centre is numerically rank-deficient
  bool rank_deficient = false;
};

/// \ingroup PkgRigidIncidenceSolver
/// Counters of one solve.
struct Solver_statistics
{
  std::size_t boxes = 0;            ///< boxes visited
  std::size_t excluded = 0;         ///< boxes excluded by a strict sign of some equation
  std::size_t excluded_by_inequality = 0; ///< boxes excluded because some inequality is < 0 on them
  std::size_t rejected_roots = 0;   ///< certified roots left out because some inequality is < 0 there
  std::size_t splits = 0;           ///< boxes split in two
  std::size_t reductions = 0;       ///< domain reductions that shrank a box
  std::size_t krawczyk_tests = 0;   ///< existence / uniqueness tests
  std::size_t certified_boxes = 0;  ///< boxes certified (before duplicates were merged)
  std::size_t duplicates = 0;       ///< certified roots merged into one found before
  std::size_t precision_retries = 0;///< clusters of unknown boxes solved again (at a higher precision, or at the working precision down to the minimal width)
  std::size_t maximal_depth = 0;    ///< deepest subdivision level
  std::size_t oriented_solves = 0;  ///< boxes solved in sheared coordinates (`Subdivision_solver_parameters::oriented_boxes`; their boxes are counted in `boxes`)
  std::size_t oriented_fallbacks = 0; ///< of those, the ones that left something unresolved, exceeded `maximal_coefficients` or had a root not certified again in the original variables, and were subdivided as usual
  double seconds = 0;               ///< wall-clock time of the solve
  /// the counters of another solve added (seconds too; `maximal_depth`: the deeper)
  Solver_statistics& operator+=(const Solver_statistics& o)
  {
    boxes += o.boxes;
    excluded += o.excluded;
    excluded_by_inequality += o.excluded_by_inequality;
    rejected_roots += o.rejected_roots;
    splits += o.splits;
    reductions += o.reductions;
    krawczyk_tests += o.krawczyk_tests;
    certified_boxes += o.certified_boxes;
    duplicates += o.duplicates;
    precision_retries += o.precision_retries;
    maximal_depth = (std::max)(maximal_depth, o.maximal_depth);
    oriented_solves += o.oriented_solves;
    oriented_fallbacks += o.oriented_fallbacks;
    seconds += o.seconds;
    return *this;
  }
};

/*!
\ingroup PkgRigidIncidenceSolver
\brief The result of `Subdivision_solver::solve()`: every box the solver left, each in exactly
one class.
*/
template <class IT>
struct Solver_result
{
  std::vector<Solver_root<IT>> roots;            ///< certified (or, in fast mode, approximate) roots
  std::vector<Solver_unresolved<IT>> unresolved; ///< unknown and pending regions
  /// empty, or what the unresolved boxes suggest, e.g. "positive_dimensional: Jacobian
  /// rank-deficient along a chain of 812 boxes"
  std::string diagnosis;
  Solver_statistics statistics;                  ///< counters of the solve
  bool fast = false;                             ///< solved in the fast, non-certified mode
  /// no unknown or pending box is left and every root is certified
  bool complete() const
  {
    if (!unresolved.empty() || fast) return false;
    for (const auto& r : roots) if (!r.certified) return false;
    return true;
  }
};

} // namespace Rigid_incidence
} // namespace CGAL

#endif
