// Copyright (c) 2026 Rigid_incidence contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Branch and prune over a Tree_system: charts chosen lazily, each equation contracting the
// variables it involves, Krawczyk certification.

#ifndef CGAL_RIGID_INCIDENCE_SOLVE_TREE_SYSTEM_H
#define CGAL_RIGID_INCIDENCE_SOLVE_TREE_SYSTEM_H

#include <CGAL/Rigid_incidence/Solver_result.h>
#include <CGAL/Rigid_incidence/Tree_system.h>
#include <CGAL/Rigid_incidence/internal/parallel.h>
#include <Eigen/Dense>
#include <algorithm>
#include <array>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <functional>
#include <mutex>
#include <set>
#include <string>
#include <vector>

namespace CGAL {
namespace Rigid_incidence {

/// \ingroup PkgRigidIncidenceSolver
/// Parameters of `solve_tree_system()`. Widths are in the hinges' chart parameters ([-1, 1]).
struct Tree_solver_parameters
{
  /// a certified root is tightened until its enclosure is at most this wide (or stops shrinking)
  double tolerance = 1e-12;
  /// a box at most this wide in every variable, neither excluded nor certified, is `UNKNOWN`
  double minimal_width = 1e-9;
  /// hinges whose chart is chosen are bisected down to this width before the chart of another
  /// hinge is chosen, and the Krawczyk test is tried on boxes at most this wide
  double split_width = 0.125;
  /// rounds of contraction per box (each equation on its variables, then all at once), at most
  int contraction_rounds = 6;
  /// of which the first ones also slice the variables of short equations
  int slicing_rounds = 1;
  /// stop at boxes whose charts are all chosen, and list their chart combinations
  bool charts_only = false;
  /// at most this many boxes; what is left is `PENDING` ("box budget exhausted")
  std::size_t maximal_boxes = 5000000;
  /// wall-clock budget in seconds (0: none); what is left is `PENDING` ("time limit")
  double maximal_seconds = 0;
  /// set by another thread or a signal handler: the solve stops, the rest `PENDING` ("interrupted")
  const std::atomic<bool>* interrupt = nullptr;
  /// called every 4096 boxes with the boxes visited and the roots found so far (empty: never)
  std::function<void(std::size_t, std::size_t)> progress;
  /// when the system has a sweep order (`sweep_order()`): branch on its driver only and find
  /// the other variables in order, each from its equation (not with `charts_only`)
  bool sweep = true;
  /// the sweep cuts its driver's interval into this many slices per chart (a power of 2, 1 for
  /// no cut; anything else is refused with an `Input_error`), solved one by one or in parallel
  /// and merged in their order, so that the answer does not depend on `threads`
  std::size_t sweep_slices = 16;
  /// threads for the sweep's slices (0: every core; oneTBB, 1 without it): the same answer with
  /// any number, unless a budget, the time limit or an interrupt cuts the solve short (`progress`
  /// is then called from any of them, one call at a time)
  unsigned threads = 1;
  /// the sweep's slices are solved as tasks of at most this many boxes each (the boxes a task
  /// leaves: tasks of the next round), so that uneven work spreads over the threads; the answer
  /// (roots, their order, boxes) does not depend on it
  std::size_t task_boxes = 4096;
  /// arc consistency before the search (see `solve_tree_system()`): the cells of the grid per
  /// chart of a hinge, a power of 2 from 2 to 65536 (anything else is refused with an
  /// `Input_error`), or 0 for none
  std::size_t consistency_cells = 512;
};

/// \ingroup PkgRigidIncidenceSolver
/// An order in which the equations of a `Tree_system` find its variables one at a time: with
/// the driver's value known, `steps[i].first` (an equation) involves no variable but the driver
/// and those of the steps before it, and `steps[i].second`; the equations `checks` are left
/// over. A chain of hinged bodies braced by distances between near neighbours has one: the
/// first hinge drives, each brace finds the next hinge, the closing distance is the check.
struct Sweep_order
{
  static constexpr std::size_t none = std::size_t(-1);       ///< no variable (no driver)
  std::size_t driver = none;                                  ///< the variable branched on (`none`: no driver)
  std::vector<std::pair<std::size_t, std::size_t>> steps;     ///< (equation, the variable it finds)
  std::vector<std::size_t> checks;                            ///< the other equations
  /// every variable is the driver or found by a step
  bool exists(std::size_t variables) const { return steps.size() + (driver == none ? 0 : 1) == variables && variables > 0; }
};

/// \ingroup PkgRigidIncidenceSolver
/// A sweep order of the system of equations whose variables are `vars` (one sorted list per
/// equation) over `n` variables: no driver if one exists without, else the driver whose steps
/// use the shortest equations (the sum of their sizes; ties: the lowest driver). Greedy: at each
/// step the first equation with exactly one variable not yet found. Empty (`exists()` false)
/// when there is none with at most one driver.
inline Sweep_order sweep_order(std::size_t n, const std::vector<std::vector<std::size_t>>& vars)
{
  Sweep_order best;
  std::size_t best_cost = std::size_t(-1);
  for (std::size_t d = Sweep_order::none;; ++d) {  // none, then 0 .. n-1
    if (d != Sweep_order::none && d >= n) break;
    Sweep_order o;
    o.driver = d;
    std::vector<char> found(n, 0), used(vars.size(), 0);
    if (d != Sweep_order::none) found[d] = 1;
    std::size_t cost = 0;
    for (bool grew = true; grew;) {
      grew = false;
      for (std::size_t e = 0; e < vars.size(); ++e) {
        if (used[e]) continue;
        std::size_t open = 0, which = 0;
        for (std::size_t v : vars[e]) if (!found[v]) { ++open; which = v; }
        if (open != 1) continue;
        used[e] = 1;
        found[which] = 1;
        o.steps.push_back({e, which});
        cost += vars[e].size();
        grew = true;
        break;
      }
    }
    for (std::size_t e = 0; e < vars.size(); ++e) if (!used[e]) o.checks.push_back(e);
    if (o.exists(n) && cost < best_cost) { best = o; best_cost = cost; }
    if (d == Sweep_order::none && best.exists(n)) break;
  }
  if (!best.exists(n)) return Sweep_order();
  return best;
}

/// \ingroup PkgRigidIncidenceSolver
/// The sweep order of a `Tree_system` (see `sweep_order(std::size_t, ...)`).
template <class Traits>
Sweep_order sweep_order(const Tree_system<Traits>& S)
{
  std::vector<std::vector<std::size_t>> vars;
  for (const auto& e : S.equations()) vars.push_back(e.variables);
  return sweep_order(S.number_of_variables(), vars);
}

/// \ingroup PkgRigidIncidenceSolver
/// A root of a `Tree_system`: per variable its chart and an enclosure in that chart.
struct Tree_root
{
  std::vector<int> charts;                                ///< per hinge, 0 or 1
  std::vector<CGAL::Interval_nt<false>> enclosure;        ///< contains the root
  std::vector<CGAL::Interval_nt<false>> uniqueness_box;   ///< the box in which the root is proved the only one
  std::vector<double> approximation;                      ///< the enclosure's midpoint
  bool certified = true;                                  ///< Krawczyk: always, for a root
};

/// \ingroup PkgRigidIncidenceSolver
/// A region `solve_tree_system()` could not decide (one box, or a hull of touching boxes).
struct Tree_region
{
  Box_class kind = Box_class::UNKNOWN;                    ///< `UNKNOWN` or `PENDING`
  std::string reason;                                     ///< why
  std::vector<int> charts;                                ///< per hinge, 0, 1 or -1 (the whole circle: no chart chosen yet)
  std::vector<std::pair<double, double>> box;             ///< per hinge, in its chart (ignored for -1)
  std::size_t boxes = 1;                                  ///< how many boxes it merges
};

/// \ingroup PkgRigidIncidenceSolver
/// The result of `solve_tree_system()`.
struct Tree_solve_result
{
  std::vector<Tree_root> roots;         ///< certified roots, one per root (in the order found)
  std::vector<Tree_region> unresolved;  ///< unknown and pending regions
  Solver_statistics statistics;         ///< counters
  std::string stopped;                  ///< empty, or why the search stopped early
  std::set<std::vector<int>> chart_combinations; ///< with `charts_only`: the combinations not excluded
  /// per variable, the fraction of its circle (both charts) that arc consistency kept
  /// (`Tree_solver_parameters::consistency_cells`); empty when it did not run or a stop cut it short
  std::vector<double> consistent_fraction;
  double consistency_seconds = 0;       ///< the time arc consistency took (in `statistics.seconds` too)
  /// no region left
  bool complete() const { return unresolved.empty(); }
};

namespace internal {

class Tree_branch_and_prune_base
{
public:
  typedef CGAL::Interval_nt<false> IT;
  static double width(const IT& x) { return x.sup() - x.inf(); }
  static double mid(const IT& x) { return 0.5 * x.inf() + 0.5 * x.sup(); }
  static bool contains_zero(const IT& x) { return x.inf() <= 0 && 0 <= x.sup(); }
  static bool empty_meet(const IT& a, const IT& b) { return a.sup() < b.inf() || b.sup() < a.inf(); }
  static IT meet(const IT& a, const IT& b) { return IT((std::max)(a.inf(), b.inf()), (std::min)(a.sup(), b.sup())); }
};

// The cells of each hinge's charts that arc consistency kept (tree_domains()): a grid of
// `cells` closed cells per chart, cell i = [lower(i), lower(i + 1)]; no cell of the grid
// outside them holds a solution of the equations it was built from.
struct Tree_domains
{
  typedef CGAL::Interval_nt<false> IT;
  std::size_t cells = 0;                                   // 0: none (every value kept)
  std::vector<std::array<std::vector<char>, 2>> kept;     // per variable and chart, per cell
  // exact: -1 + 2 i / cells with cells a power of 2 (at most 2^16)
  double lower(std::size_t i) const { return -1 + 2 * double(i) / double(cells); }
  // X (in chart ch of variable v) cut to the hull of the kept cells it meets; false: it meets
  // none. A `WHOLE` variable (ch not 0 or 1) is left as it is.
  bool clip(std::size_t v, int ch, IT& X) const
  {
    if (cells == 0 || ch < 0 || ch > 1) return true;
    const std::vector<char>& k = kept[v][std::size_t(ch)];
    const std::size_t G = cells;
    auto guess = [&](double t) {  // (a first guess; the loops below settle it exactly)
      const double g = std::floor((t + 1) * 0.5 * double(G));
      return g <= 0 ? std::size_t(0) : g >= double(G - 1) ? G - 1 : std::size_t(g);
    };
    // the lowest cell holding X.inf(), the highest holding X.sup() (a bound on a cell border
    // is in both cells)
    std::size_t i0 = guess(X.inf()), i1 = guess(X.sup());
    while (i0 > 0 && lower(i0) >= X.inf()) --i0;
    while (i0 + 1 < G && lower(i0 + 1) < X.inf()) ++i0;
    while (i1 + 1 < G && lower(i1 + 1) <= X.sup()) ++i1;
    while (i1 > 0 && lower(i1) > X.sup()) --i1;
    while (i0 <= i1 && !k[i0]) ++i0;
    while (i1 >= i0 && i1 < G && !k[i1]) { if (i1 == 0) return false; --i1; }
    if (i0 > i1) return false;
    const IT hull(lower(i0), lower(i1 + 1));
    if (Tree_branch_and_prune_base::empty_meet(X, hull)) return false;
    X = Tree_branch_and_prune_base::meet(X, hull);
    return true;
  }
  // the fraction of variable v's cells kept, over both charts
  double fraction(std::size_t v) const
  {
    std::size_t k = 0;
    for (int ch = 0; ch < 2; ++ch) for (char c : kept[v][std::size_t(ch)]) k += c ? 1 : 0;
    return cells ? double(k) / double(2 * cells) : 1.0;
  }
};

} // namespace internal

/*!
\ingroup PkgRigidIncidenceSolver
\brief Every real root of a square `Tree_system`, by branch and prune over the hinges' circles.

The search starts from one box: every hinge `WHOLE` (both charts). Then, box by box (depth
first, so the answer does not depend on anything but the system):
1. <b>Chart choice.</b> An equation with one hinge left whose chart is not chosen is evaluated
   with that hinge in each chart: a chart where it cannot vanish is dropped (both: the box is
   excluded).
2. <b>Contraction</b> (each equation on the variables it involves, as IBEX's contractors do
   for sparse systems, to a fixed point): with the enclosure J of its gradient over the box
   and its value at the centre m, every point of the box where the equation vanishes has
   \f$x_j \in m_j - (f(m) + \sum_{i \ne j} J_i (x_i - m_i)) / J_j\f$ (mean value theorem), which
   cuts variable j where \f$0 \notin J_j\f$; a box where the natural or the mean-value enclosure
   of an equation excludes 0 is excluded.
3. <b>Certification</b> on a box with every chart chosen and at most `split_width` wide: the
   Krawczyk operator \f$K = m - Y f(m) + (I - Y J(X'))(X' - m)\f$ on the box inflated by 5 %
   (Y the inverse of the Jacobian at m) proves a unique root in X' when \f$K \subset X'\f$ (the
   root is then tightened by iterating it); \f$K \cap X = \emptyset\f$ excludes the box; else the
   box is cut to \f$K \cap X\f$.
4. <b>Split.</b> While a hinge whose chart is chosen is wider than `split_width`, the widest
   is bisected; else, while a hinge has no chart, the one in the equation with the fewest
   unchosen hinges is split into its two charts; else the variable of largest relative smear
   (\f$\sum_e |J_{ej}| w_j / \sum_i |J_{ei}| w_i\f$) is bisected.
A chart is thus chosen only where a box must be split on that hinge, and the combinations of
charts the equations exclude on a coarse box are never enumerated. `solve_scene()` uses it with
`Tree_solver_parameters::charts_only` to leave out the chart combinations it excludes before
they are built (`Scene_solve_parameters::chart_propagation`).

<b>The sweep</b> (`Tree_solver_parameters::sweep`, when `sweep_order()` finds an order; not with
`charts_only`): the driver is the only variable bisected (both charts as two boxes); in each
box every step's variable is projected from its equation over the variables before it (its
first-order contraction, then slices of its interval, or of both charts' circles while its
chart is open, where the equation can vanish), separate pieces becoming separate boxes (the
real branches of the steps' curve over the driver); then steps 2 and 3 above on the whole box,
and the driver is bisected, or, at a fold where a found variable stays a million times wider
than the driver, that variable. `solve_scene()` solves a chain of hinges braced by near
distances this way (`Scene_solve_parameters::sweep`): the chain of 12 tetrahedra in 5,358 boxes
(3.6 s), where the branch and prune above needs about 4 times more boxes per body (see the user
manual, \ref RI_tree_propagation).
The sweep cuts the driver's interval into `Tree_solver_parameters::sweep_slices` slices per
chart and solves them as tasks of at most `Tree_solver_parameters::task_boxes` boxes each, in rounds on
`Tree_solver_parameters::threads` threads: the boxes a task leaves become the next round's
tasks, and the answers are merged in depth-first order, so the answer (roots, their order,
boxes) is the same with any number of threads (unless a budget, the time limit or an interrupt
cuts it).

<b>Arc consistency</b> (`Tree_solver_parameters::consistency_cells`, 512) runs first, once: each
equation in one or two hinges (a chain's braces) is enclosed over a grid of that many closed
cells per chart of each of its hinges (a quadtree: its first-order enclosure over a square that
cannot vanish drops the square), and a cell of a hinge is dropped when no cell of an equation's
other hinge that is still kept meets it in a square left, to a fixed point (AC-3 over the grid,
as constraint programming does for binary constraints). No solution of those equations lies
outside the cells kept, so every box of the search is cut to them (the driver, each step's
pieces, each round of contraction): on a chain of tetrahedra, 2 to 30 % of each hinge's circle
is kept, and the branches of the steps' curve that die further along the chain are cut where
they start, not found box by box. An equation whose squares left exceed 64 cells per cell of a
side (a curve crosses a few) is left out (it would prune little); a stop (time limit, interrupt)
during it keeps every cell. `Tree_solve_result::consistent_fraction` gives the fraction kept per
hinge.

Roots are certified (the Krawczyk test is a proof in outward-rounded double intervals); a root
found from two neighbouring boxes is kept once (its enclosure lies in the other's uniqueness
box). A root on the border between two charts (a hinge at t = +-1, s = +-1) is found in both:
the caller merges them (`solve_scene()` compares the configurations). Boxes at the minimal width
are `UNKNOWN`; a budget or an interrupt leaves the rest `PENDING`; touching boxes of one chart
combination are merged into one region, their hull.
*/
template <class Traits>
Tree_solve_result solve_tree_system(const Tree_system<Traits>& S, const Tree_solver_parameters& P = Tree_solver_parameters());

namespace internal {

// a box of solve_tree_system(); `groups`: where slicing left a variable in separate pieces (or
// in both charts), the pieces, which the split takes as the children; `level`: the sweep's
// steps before it are done
struct Tree_piece { int ch; CGAL::Interval_nt<false> x; };
struct Tree_box
{
  std::vector<int> ch;
  std::vector<CGAL::Interval_nt<false>> x;
  std::size_t group_variable = std::size_t(-1);
  std::vector<Tree_piece> groups;
  std::size_t level = 0;
};

// the boxes as regions appended to `out`: touching boxes of one chart combination merged into
// their hull, each region where its first box was
inline void add_tree_regions(std::size_t n, const std::vector<const Tree_box*>& boxes, Box_class kind,
                             const std::function<std::string(std::size_t)>& reason, std::vector<Tree_region>& out)
{
  typedef CGAL::Interval_nt<false> IT;
  typedef Tree_branch_and_prune_base B;
  // each box into the first region of its charts whose hull it touches, then regions whose
  // hulls touch merged, until none do (linear in the boxes for a few regions)
  struct Region { std::size_t first; std::size_t count; std::vector<IT> hull; bool alive; };
  std::vector<Region> regions;
  auto touch = [&](const std::vector<IT>& p, const std::vector<IT>& q) {
    for (std::size_t k = 0; k < n; ++k) if (B::empty_meet(p[k], q[k])) return false;
    return true;
  };
  auto join = [&](std::vector<IT>& h, const std::vector<IT>& x) {
    for (std::size_t k = 0; k < n; ++k) h[k] = IT((std::min)(h[k].inf(), x[k].inf()), (std::max)(h[k].sup(), x[k].sup()));
  };
  for (std::size_t i = 0; i < boxes.size(); ++i) {
    bool placed = false;
    for (Region& r : regions)
      if (boxes[r.first]->ch == boxes[i]->ch && touch(r.hull, boxes[i]->x)) { join(r.hull, boxes[i]->x); ++r.count; placed = true; break; }
    if (!placed) regions.push_back({i, 1, boxes[i]->x, true});
  }
  for (bool merged = true; merged;) {
    merged = false;
    for (std::size_t i = 0; i < regions.size(); ++i)
      for (std::size_t j = i + 1; regions[i].alive && j < regions.size(); ++j)
        if (regions[j].alive && boxes[regions[i].first]->ch == boxes[regions[j].first]->ch && touch(regions[i].hull, regions[j].hull)) {
          join(regions[i].hull, regions[j].hull);
          regions[i].count += regions[j].count;
          regions[j].alive = false;
          merged = true;
        }
  }
  for (const Region& g : regions) {
    if (!g.alive) continue;
    Tree_region r;
    r.kind = kind;
    r.reason = reason(g.first);
    r.charts = boxes[g.first]->ch;
    r.boxes = g.count;
    for (const IT& h : g.hull) r.box.push_back({h.inf(), h.sup()});
    out.push_back(std::move(r));
  }
}

// Arc consistency (AC-3) of the equations of S in one or two variables on a grid of `cells`
// cells per chart of each hinge (see solve_tree_system()). The caller keeps a
// CGAL::Protect_FPU_rounding<true> alive. `stop` (checked every 1024 evaluations and before
// each equation's pass of the fixed point) cuts it short: the result is then none (cells 0: every value kept), an optimization lost, nothing else.
template <class Traits>
Tree_domains tree_domains(const Tree_system<Traits>& S, std::size_t cells, const std::function<bool()>& stop, std::size_t leaf_factor = 64)
{
  typedef CGAL::Interval_nt<false> IT;
  typedef Tree_branch_and_prune_base B;
  typedef Tree_system<Traits> TS;
  const std::size_t n = S.number_of_variables(), ne = S.number_of_equations();
  Tree_domains d;
  if (cells == 0 || n == 0) return d;
  d.cells = cells;
  d.kept.assign(n, {std::vector<char>(cells, 1), std::vector<char>(cells, 1)});
  // per equation, the cells (one per variable: chart, index) of the grid where its first-order
  // enclosure contains 0: a quadtree over each combination of its variables' charts
  struct Leaf { std::uint32_t i[2]; std::uint8_t c[2]; };  // (12 bytes: up to 64 cells a side each)
  std::vector<std::vector<Leaf>> leaves(ne);
  std::vector<char> used(ne, 0);
  std::vector<int> ch(n, 0);
  std::vector<IT> x(n, IT(-1, 1));
  std::vector<IT> A;
  typename TS::Workspace ws;
  std::size_t evaluations = 0;
  // (a curve crosses a few cells per cell of a side; an equation that keeps far more than that
  // over its grid, `leaf_factor` per cell of a side, prunes little and costs much: left out)
  const std::size_t leaf_cap = leaf_factor * cells;
  struct Cell { std::size_t lo[2], hi[2]; };
  for (std::size_t e = 0; e < ne; ++e) {
    const std::vector<std::size_t>& vars = S.equations()[e].variables;
    const std::size_t m = vars.size();
    if (m == 0 || m > 2) continue;
    bool over = false;
    for (int combo = 0; combo < (m == 2 ? 4 : 2) && !over; ++combo) {
      const int c0 = combo & 1, c1 = (combo >> 1) & 1;
      ch[vars[0]] = c0;
      if (m == 2) ch[vars[1]] = c1;
      std::vector<Cell> todo{{{0, 0}, {cells, m == 2 ? cells : 1}}};
      while (!todo.empty() && !over) {
        const Cell q = todo.back();
        todo.pop_back();
        if (++evaluations % 1024 == 0 && stop && stop()) return Tree_domains();
        for (std::size_t k = 0; k < m; ++k) x[vars[k]] = IT(d.lower(q.lo[k]), d.lower(q.hi[k]));
        if (!B::contains_zero(TS::range(S.evaluate(e, ch, x, A, &ws), A))) continue;
        const bool leaf = q.hi[0] - q.lo[0] == 1 && (m == 1 || q.hi[1] - q.lo[1] == 1);
        if (leaf) {
          leaves[e].push_back({{std::uint32_t(q.lo[0]), std::uint32_t(m == 2 ? q.lo[1] : 0)}, {std::uint8_t(c0), std::uint8_t(c1)}});
          over = leaves[e].size() > leaf_cap;
          continue;
        }
        // the halves of each side longer than one cell (the upper ones first on the stack)
        const std::size_t h0 = q.hi[0] - q.lo[0] > 1 ? 2 : 1, h1 = m == 2 && q.hi[1] - q.lo[1] > 1 ? 2 : 1;
        for (std::size_t a = h0; a-- > 0;)
          for (std::size_t b = h1; b-- > 0;) {
            Cell r = q;
            if (h0 == 2) { const std::size_t mid = (q.lo[0] + q.hi[0]) / 2; (a ? r.lo[0] : r.hi[0]) = mid; }
            if (h1 == 2) { const std::size_t mid = (q.lo[1] + q.hi[1]) / 2; (b ? r.lo[1] : r.hi[1]) = mid; }
            todo.push_back(r);
          }
      }
    }
    if (over) leaves[e].clear();
    else used[e] = 1;
  }
  // to a fixed point: a cell of a variable is kept while some leaf of each of its equations
  // holds it with the other variable's cell kept
  for (bool changed = true; changed;) {
    changed = false;
    for (std::size_t e = 0; e < ne; ++e) {
      if (!used[e]) continue;
      if (stop && stop()) return Tree_domains();
      const std::vector<std::size_t>& vars = S.equations()[e].variables;
      const std::size_t m = vars.size();
      std::vector<std::array<std::vector<char>, 2>> seen(m, {std::vector<char>(cells, 0), std::vector<char>(cells, 0)});
      std::vector<Leaf> keep;
      for (const Leaf& l : leaves[e]) {
        bool alive = true;
        for (std::size_t k = 0; k < m; ++k) alive = alive && d.kept[vars[k]][std::size_t(l.c[k])][l.i[k]];
        if (!alive) continue;
        for (std::size_t k = 0; k < m; ++k) seen[k][std::size_t(l.c[k])][l.i[k]] = 1;
        keep.push_back(l);
      }
      leaves[e].swap(keep);
      for (std::size_t k = 0; k < m; ++k)
        for (std::size_t c = 0; c < 2; ++c)
          for (std::size_t i = 0; i < cells; ++i)
            if (d.kept[vars[k]][c][i] && !seen[k][c][i]) { d.kept[vars[k]][c][i] = 0; changed = true; }
    }
  }
  return d;
}

// what a task of the sweep leaves to the caller: its unknown boxes (and why), its pending
// boxes (a stop), and the boxes it would have visited next (its share of boxes done)
struct Tree_task_boxes
{
  std::vector<Tree_box> unknown;
  std::vector<std::string> reasons;
  std::vector<Tree_box> pending;
  std::vector<Tree_box> left_over;
};

// solve_tree_system(); `sweep`, if given, is the system's sweep order (not computed again);
// `shared`
// counts the boxes of every slice against the budget (and calls `progress`); `since` (with a
// time limit) is when the time limit started for every slice; `domains`, the cells arc
// consistency kept (every box cut to them). With `start` (a sweep), from
// these boxes (the first visited first). With `task`, a task of the sweep: it stops after
// `task_boxes` boxes and leaves the boxes it would have visited next in `task->left_over`, in
// that order; its unknown and pending boxes go to `task` as boxes, and its roots are all kept
// (the caller merges regions and duplicates over every task, in depth-first order)
template <class Traits>
Tree_solve_result solve_tree_system_from(const Tree_system<Traits>& S, const Tree_solver_parameters& P,
                                         const Sweep_order* sweep,
                                         std::atomic<std::size_t>* shared,
                                         const std::chrono::steady_clock::time_point* since = nullptr,
                                         const std::vector<Tree_box>* start = nullptr, std::size_t task_boxes = 0,
                                         Tree_task_boxes* task = nullptr, const Tree_domains* domains = nullptr)
{
  typedef CGAL::Interval_nt<false> IT;
  typedef internal::Tree_branch_and_prune_base B;
  typedef std::chrono::steady_clock Clock;
  const Clock::time_point started = Clock::now();
  CGAL::Protect_FPU_rounding<true> guard;
  const std::size_t n = S.number_of_variables(), ne = S.number_of_equations();
  const int WHOLE = Tree_system<Traits>::WHOLE;
  if (!S.is_square()) throw Input_error("solve_tree_system: the system is not square");
  Tree_solve_result out;
  Solver_statistics& st = out.statistics;
  const Tree_domains none;
  const Tree_domains& D = domains ? *domains : none;
  // a box; `groups`: where slicing left a variable in separate pieces (or in both charts), the
  // pieces, which the split takes as the children
  typedef Tree_piece Piece;
  typedef Tree_box Box;
  std::vector<Box> stack;
  stack.push_back({std::vector<int>(n, WHOLE), std::vector<IT>(n, IT(-1, 1))});
  std::vector<Box> unknown;
  std::vector<std::string> unknown_reason;

  auto whole_count = [&](std::size_t e, const Box& b, std::size_t* which) {
    std::size_t k = 0;
    for (std::size_t v : S.equations()[e].variables)
      if (b.ch[v] == WHOLE) { ++k; if (which) *which = v; }
    return k;
  };
  typedef Tree_system<Traits> TS;
  typename TS::Workspace ws;
  std::vector<IT> A;
  std::vector<std::vector<IT>> rows(ne);
  std::vector<IT> C(ne);
  // x_j from eps_j in [-1, 1]: t0 + r eps
  auto from_eps = [&](const IT& x, const IT& eps) {
    double t0, r;
    TS::centre_radius(x, t0, r);
    return IT(t0) + IT(r) * eps;
  };
  // variable v of box b in 8 slices (16 over both charts when `whole`): the runs of slices on
  // which equation e can vanish (its first-order enclosure contains 0), merged, in `kept`
  auto slice = [&](Box& b, std::size_t e, std::size_t v, bool whole, std::vector<Piece>& kept) {
    const int K = 8;
    const int saved_ch = b.ch[v];
    const IT saved = b.x[v];
    kept.clear();
    for (int ch = 0; ch < 2; ++ch) {
      if (!whole && ch != saved_ch) continue;
      const IT range = whole ? IT(-1, 1) : saved;
      const double lo = range.inf(), hi = range.sup();
      b.ch[v] = whole ? ch : saved_ch;
      bool open = false;
      for (int k = 0; k < K; ++k) {
        const double a = k == 0 ? lo : lo + (hi - lo) * k / K, z = k == K - 1 ? hi : lo + (hi - lo) * (k + 1) / K;
        b.x[v] = IT(a, z);
        const IT c = S.evaluate(e, b.ch, b.x, A, &ws);
        if (B::contains_zero(TS::range(c, A))) {
          if (open) kept.back().x = IT(kept.back().x.inf(), z);
          else kept.push_back({b.ch[v], IT(a, z)});
          open = true;
        } else {
          open = false;
        }
      }
    }
    b.ch[v] = saved_ch;
    b.x[v] = saved;
    return true;
  };
  // steps 1 and 2; false: excluded
  auto contract = [&](Box& b, int slicing_rounds) {
    b.groups.clear();
    b.group_variable = std::size_t(-1);
    for (int round = 0; round < P.contraction_rounds; ++round) {
      bool changed = false;
      bool all_chosen = true;
      // (each hinge cut to the cells arc consistency kept: no solution lies outside them)
      for (std::size_t i = 0; i < n; ++i) {
        const IT before = b.x[i];
        if (!D.clip(i, b.ch[i], b.x[i])) return false;
        if (round > 0 && B::width(b.x[i]) < 0.9 * B::width(before)) changed = true;
      }
      for (std::size_t e = 0; e < ne; ++e) {
        std::size_t j = 0;
        const std::size_t w = whole_count(e, b, &j);
        if (w == 1) {
          // the hinge's circle in slices, both charts: the ones where the equation can vanish
          std::vector<Piece> kept;
          if (!slice(b, e, j, true, kept)) return false;
          b.ch[j] = WHOLE;
          b.x[j] = IT(-1, 1);
          if (kept.empty()) return false;
          if (kept.front().ch == kept.back().ch) {
            b.ch[j] = kept.front().ch;
            b.x[j] = IT(kept.front().x.inf(), kept.back().x.sup());
            changed = true;
            if (kept.size() > 1) { b.group_variable = j; b.groups = kept; }
          } else {
            b.group_variable = j;
            b.groups = kept;
          }
          all_chosen = false;
          continue;
        }
        const IT c = S.evaluate(e, b.ch, b.x, A, &ws);
        if (!B::contains_zero(TS::range(c, A))) return false;
        if (w > 1) { all_chosen = false; continue; }
        const auto& vars = S.equations()[e].variables;
        // each variable from the others: 0 in c + sum_i A_i eps_i
        for (std::size_t i = 0; i < vars.size(); ++i) {
          if (B::contains_zero(A[i])) continue;
          IT rest = c;
          for (std::size_t l = 0; l < vars.size(); ++l)
            if (l != i) rest += CGAL::abs(A[l]).sup() * IT(-1, 1);
          const IT eps = B::meet(IT(-1, 1), (-rest) / A[i]);
          if (B::empty_meet(IT(-1, 1), (-rest) / A[i])) return false;
          IT& xi = b.x[vars[i]];
          const IT cand = from_eps(xi, eps);
          if (B::empty_meet(xi, cand)) return false;
          const IT nx = B::meet(xi, cand);
          if (B::width(nx) < 0.9 * B::width(xi)) changed = true;
          xi = nx;
        }
        // short equations: each variable's slices (what projecting a Bernstein form gives)
        if (vars.size() <= 3 && round < slicing_rounds)
          for (std::size_t v2 : vars) {
            if (B::width(b.x[v2]) <= P.split_width / 8) continue;
            std::vector<Piece> kept;
            const IT before = b.x[v2];
            if (!slice(b, e, v2, false, kept) || kept.empty()) return false;
            b.x[v2] = IT(kept.front().x.inf(), kept.back().x.sup());
            if (B::width(b.x[v2]) < 0.9 * B::width(before)) changed = true;
            if (kept.size() > 1) { b.group_variable = v2; b.groups = kept; }
            else if (b.group_variable == v2) b.groups.clear();
          }
      }
      // every chart chosen: the preconditioned linear step on all the equations at once,
      // eps in -Y C + (I - Y A) [-1, 1]^n with Y the inverse of mid(A)
      if (all_chosen) {
        Eigen::MatrixXd M(ne, n);
        M.setZero();
        for (std::size_t e = 0; e < ne; ++e) {
          C[e] = S.evaluate(e, b.ch, b.x, A, &ws);
          rows[e].assign(n, IT(0));
          const auto& vars = S.equations()[e].variables;
          for (std::size_t i = 0; i < vars.size(); ++i) {
            rows[e][vars[i]] = A[i];
            M(Eigen::Index(e), Eigen::Index(vars[i])) = B::mid(A[i]);
          }
        }
        Eigen::FullPivLU<Eigen::MatrixXd> lu(M);
        if (lu.isInvertible()) {
          const Eigen::MatrixXd Y = lu.inverse();
          if (Y.allFinite()) {
            std::vector<IT> nx(n);
            for (std::size_t i = 0; i < n; ++i) {
              IT v(0);
              for (std::size_t e = 0; e < ne; ++e) v -= IT(Y(Eigen::Index(i), Eigen::Index(e))) * C[e];
              for (std::size_t j2 = 0; j2 < n; ++j2) {
                IT cij = IT(i == j2 ? 1.0 : 0.0);
                for (std::size_t e = 0; e < ne; ++e) cij -= IT(Y(Eigen::Index(i), Eigen::Index(e))) * rows[e][j2];
                v += CGAL::abs(cij).sup() * IT(-1, 1);
              }
              if (B::empty_meet(v, IT(-1, 1))) return false;
              nx[i] = from_eps(b.x[i], B::meet(v, IT(-1, 1)));
              if (B::empty_meet(nx[i], b.x[i])) return false;
            }
            for (std::size_t i = 0; i < n; ++i) {
              const IT m2 = B::meet(nx[i], b.x[i]);
              if (B::width(m2) < 0.9 * B::width(b.x[i])) changed = true;
              b.x[i] = m2;
            }
          }
        }
      }
      if (!changed) return true;
    }
    return true;
  };
  std::vector<IT> grad;
  // the Jacobian over a box (rows over all variables)
  auto jacobian = [&](const std::vector<int>& ch, const std::vector<IT>& x, std::vector<std::vector<IT>>& J) {
    J.assign(ne, std::vector<IT>(n, IT(0)));
    for (std::size_t e = 0; e < ne; ++e) {
      S.gradient(e, ch, x, grad);
      const auto& vars = S.equations()[e].variables;
      for (std::size_t i = 0; i < vars.size(); ++i) J[e][vars[i]] = grad[i];
    }
  };
  auto values = [&](const std::vector<int>& ch, const std::vector<double>& m) {
    std::vector<IT> f(ne);
    for (std::size_t e = 0; e < ne; ++e) f[e] = S.value(e, ch, m);
    return f;
  };
  enum Outcome { ROOT, EXCLUDED, UNDECIDED, SINGULAR };
  // Krawczyk on x (inflated by `inflate`); on ROOT, `k` is the operator's box and `xx` the box
  // it was proved on
  std::vector<std::vector<IT>> J;
  auto krawczyk = [&](const std::vector<int>& ch, const std::vector<IT>& x, double inflate, std::vector<IT>& k, std::vector<IT>& xx) {
    ++st.krawczyk_tests;
    xx = x;
    std::vector<double> m(n);
    for (std::size_t i = 0; i < n; ++i) {
      m[i] = B::mid(x[i]);
      const double r = inflate * B::width(x[i]) + 1e-300;
      xx[i] = IT(x[i].inf() - r, x[i].sup() + r);
    }
    std::vector<IT> f = values(ch, m);
    // Y: the inverse of the Jacobian's midpoint at m
    std::vector<IT> xm2(n);
    for (std::size_t i = 0; i < n; ++i) xm2[i] = IT(m[i]);
    jacobian(ch, xm2, J);
    Eigen::MatrixXd Am(ne, n);
    for (std::size_t e = 0; e < ne; ++e)
      for (std::size_t i = 0; i < n; ++i) Am(Eigen::Index(e), Eigen::Index(i)) = B::mid(J[e][i]);
    Eigen::FullPivLU<Eigen::MatrixXd> lu(Am);
    if (!lu.isInvertible()) return SINGULAR;
    Eigen::MatrixXd Y = lu.inverse();
    if (!Y.allFinite()) return SINGULAR;
    jacobian(ch, xx, J);
    k.assign(n, IT(0));
    bool inside = true;
    for (std::size_t i = 0; i < n; ++i) {
      IT v = IT(m[i]);
      for (std::size_t e = 0; e < ne; ++e) v -= IT(Y(Eigen::Index(i), Eigen::Index(e))) * f[e];
      for (std::size_t j = 0; j < n; ++j) {
        IT c = IT(i == j ? 1.0 : 0.0);
        for (std::size_t e = 0; e < ne; ++e) c -= IT(Y(Eigen::Index(i), Eigen::Index(e))) * J[e][j];
        v += c * (xx[j] - m[j]);
      }
      k[i] = v;
      if (B::empty_meet(v, xx[i])) return EXCLUDED;
      inside = inside && xx[i].inf() < v.inf() && v.sup() < xx[i].sup();
    }
    return inside ? ROOT : UNDECIDED;
  };
  auto stop_reason = [&]() -> std::string {
    if (P.interrupt && P.interrupt->load(std::memory_order_relaxed)) return "interrupted";
    if (P.maximal_seconds > 0 && std::chrono::duration<double>(Clock::now() - (since ? *since : started)).count() >= P.maximal_seconds)
      return "time limit";
    if (st.boxes >= P.maximal_boxes) return "box budget exhausted";
    return std::string();
  };
  auto record_root = [&](const std::vector<int>& ch, std::vector<IT> enc, const std::vector<IT>& uniq) {
    // tighten: Krawczyk on the enclosure until it is narrow or stops shrinking
    for (int it = 0; it < 40; ++it) {
      double w = 0;
      for (const IT& v : enc) w = (std::max)(w, B::width(v));
      if (w <= P.tolerance) break;
      std::vector<IT> k, xx;
      if (krawczyk(ch, enc, 0.0, k, xx) == SINGULAR) break;
      std::vector<IT> next(n);
      bool ok = true;
      double nw = 0;
      for (std::size_t i = 0; i < n; ++i) {
        if (B::empty_meet(enc[i], k[i])) { ok = false; break; }
        next[i] = B::meet(enc[i], k[i]);
        nw = (std::max)(nw, B::width(next[i]));
      }
      if (!ok) break;  // (cannot happen: the root is in both)
      const bool progress = nw < 0.75 * w;
      enc = next;
      if (!progress) break;
    }
    auto inside = [&](const std::vector<IT>& a, const std::vector<IT>& b) {
      for (std::size_t i = 0; i < n; ++i) if (a[i].inf() < b[i].inf() || b[i].sup() < a[i].sup()) return false;
      return true;
    };
    for (const Tree_root& r : out.roots)
      if (!task && r.charts == ch && (inside(enc, r.uniqueness_box) || inside(r.enclosure, uniq))) { ++st.duplicates; return; }
    Tree_root r;
    r.charts = ch;
    r.enclosure = enc;
    r.uniqueness_box = uniq;
    for (const IT& v : enc) r.approximation.push_back(B::mid(v));
    out.roots.push_back(std::move(r));
  };

  // the Krawczyk test on box b (every chart chosen): true when nothing is left of b (a root
  // recorded, or b excluded); else b is cut to its meet with the operator and `widest` is its
  // widest variable
  auto certify = [&](Box& b, Outcome& o, double& widest) {
    std::vector<IT> k, xx;
    o = krawczyk(b.ch, b.x, 0.05, k, xx);
    if (o == ROOT) { ++st.certified_boxes; record_root(b.ch, k, xx); return true; }
    if (o == EXCLUDED) { ++st.excluded; return true; }
    if (o == UNDECIDED) {
      double nw = 0;
      for (std::size_t i = 0; i < n; ++i) {
        if (B::empty_meet(b.x[i], k[i])) { ++st.excluded; return true; }
        b.x[i] = B::meet(b.x[i], k[i]);
        nw = (std::max)(nw, B::width(b.x[i]));
      }
      widest = nw;
    }
    return false;
  };
  // box b halved on variable v, the lower half visited first
  auto bisect = [&](const Box& b, std::size_t v) {
    ++st.splits;
    const double c = B::mid(b.x[v]);
    Box lo = b, hi = b;
    lo.x[v] = IT(b.x[v].inf(), c);
    hi.x[v] = IT(c, b.x[v].sup());
    stack.push_back(std::move(hi));
    stack.push_back(std::move(lo));
  };
  const Sweep_order order = sweep ? *sweep : P.sweep && !P.charts_only ? sweep_order(S) : Sweep_order();
  if (order.exists(n)) {
    stack.clear();
    if (start) {
      for (auto it = start->rbegin(); it != start->rend(); ++it) stack.push_back(*it);
    } else if (order.driver != Sweep_order::none) {
      Box b1{std::vector<int>(n, WHOLE), std::vector<IT>(n, IT(-1, 1))};
      b1.ch[order.driver] = 1;
      stack.push_back(b1);
      b1.ch[order.driver] = 0;
      stack.push_back(b1);
    } else {
      stack.push_back({std::vector<int>(n, WHOLE), std::vector<IT>(n, IT(-1, 1))});
    }
  }
  // the solutions in variable v (chart ch, interval X) of equation e over the rest of box b:
  // first-order contraction of v, then, where the equation is not monotone in v, slices of
  // X in which it can vanish, each refined the same way `depth` more times; touching pieces
  // merged (appended to `out`)
  std::function<void(Box&, std::size_t, std::size_t, int, IT, int, std::vector<Piece>&)> refine =
      [&](Box& b, std::size_t e, std::size_t v, int ch, IT X, int depth, std::vector<Piece>& out_pieces) {
    const auto& vars = S.equations()[e].variables;
    const std::size_t iv = std::size_t(std::find(vars.begin(), vars.end(), v) - vars.begin());
    b.ch[v] = ch;
    // tight: the equation is monotone in v over X, with a slope known to 20 % (its first-order
    // form then finds v as narrow as the other variables allow). Looser, the pieces are wider
    // and the boxes more: at a factor 3 the chain of 30 took 4.86 million boxes and 872 s on
    // one thread, at 1.2 3.40 million and 611 s (chain of 20: 104,598 boxes, 10.5 s; 77,660,
    // 8.3 s); at 1 (slicing every interval) the slices cost more than they save (29 s).
    bool tight = false;
    for (int it = 0; it < 8; ++it) {
      b.x[v] = X;
      const IT c = S.evaluate(e, b.ch, b.x, A, &ws);
      if (!B::contains_zero(TS::range(c, A))) return;
      if (B::contains_zero(A[iv])) { tight = false; break; }
      tight = CGAL::abs(A[iv]).sup() <= 1.2 * CGAL::abs(A[iv]).inf();
      IT rest = c;
      for (std::size_t l = 0; l < vars.size(); ++l)
        if (l != iv) rest += CGAL::abs(A[l]).sup() * IT(-1, 1);
      const IT q = (-rest) / A[iv];
      if (B::empty_meet(IT(-1, 1), q)) return;
      const IT cand = from_eps(X, B::meet(IT(-1, 1), q));
      if (B::empty_meet(X, cand)) return;
      const IT nx = B::meet(X, cand);
      const bool shrunk = B::width(nx) < 0.9 * B::width(X);
      X = nx;
      if (!shrunk) break;
    }
    b.x[v] = X;
    // (a first-order form over a wide interval prunes little even where the equation is
    // monotone: wide pieces are sliced again)
    if (depth == 0 || tight || B::width(X) <= P.minimal_width) {
      if (!out_pieces.empty() && out_pieces.back().ch == ch && out_pieces.back().x.sup() >= X.inf())
        out_pieces.back().x = IT(out_pieces.back().x.inf(), (std::max)(out_pieces.back().x.sup(), X.sup()));
      else
        out_pieces.push_back({ch, X});
      return;
    }
    const int K = 8;
    const double lo = X.inf(), hi = X.sup();
    for (int k = 0; k < K; ++k) {
      const double a = k == 0 ? lo : lo + (hi - lo) * k / K, z = k == K - 1 ? hi : lo + (hi - lo) * (k + 1) / K;
      refine(b, e, v, ch, IT(a, z), depth - 1, out_pieces);
    }
  };
  std::vector<Piece> pieces;
  while (order.exists(n) && !stack.empty()) {
    out.stopped = stop_reason();
    if (out.stopped.empty() && task && st.boxes >= task_boxes) {
      // the task's share done: the caller solves the rest
      for (auto it = stack.rbegin(); it != stack.rend(); ++it) task->left_over.push_back(std::move(*it));
      stack.clear();
      break;
    }
    if (out.stopped.empty() && shared) {
      const std::size_t k = shared->fetch_add(1);
      if (k >= P.maximal_boxes) out.stopped = "box budget exhausted";
      else if (P.progress && (k + 1) % 4096 == 0) P.progress(k + 1, out.roots.size());
    }
    if (!out.stopped.empty()) break;
    Box b = std::move(stack.back());
    stack.pop_back();
    ++st.boxes;
    if (P.progress && !shared && st.boxes % 4096 == 0) P.progress(st.boxes, out.roots.size());
    // each step's variable from its equation, in order; separate pieces are separate boxes
    // (every variable within the cells arc consistency kept)
    bool excluded = order.driver != Sweep_order::none && !D.clip(order.driver, b.ch[order.driver], b.x[order.driver]);
    for (std::size_t i = b.level; i < order.steps.size() && !excluded; ++i) {
      const std::size_t e = order.steps[i].first, v = order.steps[i].second;
      pieces.clear();
      const IT X0 = b.x[v];
      const int ch0 = b.ch[v];
      for (int ch = 0; ch < 2; ++ch) {
        if (ch0 != WHOLE && ch != ch0) continue;
        IT X = ch0 == WHOLE ? IT(-1, 1) : X0;
        if (!D.clip(v, ch, X)) continue;
        refine(b, e, v, ch, X, ch0 == WHOLE ? 3 : 2, pieces);
      }
      std::size_t kept = 0;
      for (Piece& pc : pieces)
        if (D.clip(v, pc.ch, pc.x)) pieces[kept++] = pc;
      pieces.resize(kept);
      if (pieces.empty()) { excluded = true; break; }
      // pieces that cover most of their hull are slices of one wide set (the driver still
      // wide), not separate branches: one box for their hull (else the boxes multiply with the
      // steps)
      bool one_chart = true;
      double covered = 0;
      for (const Piece& pc : pieces) { one_chart = one_chart && pc.ch == pieces[0].ch; covered += B::width(pc.x); }
      const double hull_width = one_chart ? pieces.back().x.sup() - pieces.front().x.inf() : 4;
      if (pieces.size() > 1 && order.driver != Sweep_order::none && covered > 0.25 * hull_width) {
        pieces[0] = one_chart ? Piece{pieces[0].ch, IT(pieces[0].x.inf(), pieces.back().x.sup())} : Piece{WHOLE, IT(-1, 1)};
        pieces.resize(1);
      }
      for (std::size_t k = pieces.size(); k-- > 1;) {
        Box child = b;
        child.ch[v] = pieces[k].ch;
        child.x[v] = pieces[k].x;
        child.level = i + 1;
        stack.push_back(std::move(child));
      }
      if (pieces.size() > 1) ++st.splits;
      b.ch[v] = pieces[0].ch;
      b.x[v] = pieces[0].x;
    }
    if (excluded || !contract(b, 0)) { ++st.excluded; continue; }
    b.level = 0;
    double widest = 0;
    for (std::size_t i = 0; i < n; ++i) widest = (std::max)(widest, B::width(b.x[i]));
    Outcome o = UNDECIDED;
    if (widest <= P.split_width && certify(b, o, widest)) continue;
    // the driver; but at a fold of a found variable over the driver (where halving the driver
    // hardly narrows it), once the driver is a million times narrower, that variable, as a
    // curve tracer changes its parameter at a turning point
    std::size_t v = n, widest_other = n;
    double others = 0;
    for (std::size_t i = 0; i < n; ++i)
      if (i != order.driver && B::width(b.x[i]) > others) { others = B::width(b.x[i]); widest_other = i; }
    if (order.driver != Sweep_order::none && B::width(b.x[order.driver]) > P.minimal_width &&
        !(others > 1e6 * B::width(b.x[order.driver]))) {
      v = order.driver;
    } else if (others > P.minimal_width) {
      v = widest_other;
    }
    if (v == n) {
      unknown.push_back(b);
      unknown_reason.push_back(o == SINGULAR ? "possible multiple root (singular Jacobian)" : "not certified at minimal width");
      continue;
    }
    bisect(b, v);
  }
  while (!order.exists(n) && !stack.empty()) {
    out.stopped = stop_reason();
    if (!out.stopped.empty()) break;
    Box b = std::move(stack.back());
    stack.pop_back();
    ++st.boxes;
    if (P.progress && st.boxes % 4096 == 0) P.progress(st.boxes, out.roots.size());
    if (!contract(b, P.slicing_rounds)) { ++st.excluded; continue; }
    bool any_whole = false;
    double widest = 0;
    for (std::size_t i = 0; i < n; ++i) {
      if (b.ch[i] == WHOLE) any_whole = true;
      else widest = (std::max)(widest, B::width(b.x[i]));
    }
    if (P.charts_only && !any_whole) { out.chart_combinations.insert(b.ch); continue; }
    if (!any_whole && widest <= P.split_width) {
      Outcome o = UNDECIDED;
      if (certify(b, o, widest)) continue;
      if (widest <= P.minimal_width) {
        unknown.push_back(b);
        unknown_reason.push_back(o == SINGULAR ? "possible multiple root (singular Jacobian)" : "not certified at minimal width");
        continue;
      }
    }
    // split: into the pieces slicing left apart, if any
    if (!b.groups.empty() && b.group_variable < n) {
      const std::size_t gv = b.group_variable;
      bool valid = true;
      for (const Piece& g : b.groups) valid = valid && (b.ch[gv] == WHOLE || (g.ch == b.ch[gv] && !B::empty_meet(g.x, b.x[gv])));
      if (valid) {
        ++st.splits;
        for (auto it = b.groups.rbegin(); it != b.groups.rend(); ++it) {
          Box child = b;
          child.groups.clear();
          child.group_variable = std::size_t(-1);
          child.ch[gv] = it->ch;
          child.x[gv] = b.ch[gv] == WHOLE ? it->x : B::meet(it->x, b.x[gv]);
          stack.push_back(std::move(child));
        }
        continue;
      }
    }
    std::size_t v = n;
    if (widest > P.split_width) {
      double w = 0;
      for (std::size_t i = 0; i < n; ++i)
        if (b.ch[i] != WHOLE && B::width(b.x[i]) > w) { w = B::width(b.x[i]); v = i; }
    } else if (any_whole) {
      std::size_t best = std::size_t(-1), best_size = std::size_t(-1);
      for (std::size_t e = 0; e < ne; ++e) {
        std::size_t j = 0;
        const std::size_t w = whole_count(e, b, &j);
        if (w == 0) continue;
        const std::size_t size = S.equations()[e].variables.size();
        if (w < best || (w == best && size < best_size)) {
          best = w;
          best_size = size;
          // the first unchosen hinge of the equation
          for (std::size_t u : S.equations()[e].variables) if (b.ch[u] == WHOLE) { v = u; break; }
        }
      }
      if (v == n) for (std::size_t i = 0; i < n; ++i) if (b.ch[i] == WHOLE) { v = i; break; }
      ++st.splits;
      Box c0 = b, c1 = b;
      c0.ch[v] = 0;
      c1.ch[v] = 1;
      c0.x[v] = c1.x[v] = IT(-1, 1);
      stack.push_back(std::move(c1));
      stack.push_back(std::move(c0));
      continue;
    } else {
      std::vector<double> smear(n, 0.0);
      J.assign(ne, std::vector<IT>(n, IT(0)));
      for (std::size_t e = 0; e < ne; ++e) {
        S.evaluate(e, b.ch, b.x, A, &ws);
        const auto& vars = S.equations()[e].variables;
        for (std::size_t i = 0; i < vars.size(); ++i) J[e][vars[i]] = A[i];
      }
      for (std::size_t e = 0; e < ne; ++e) {
        double total = 0;
        for (std::size_t i = 0; i < n; ++i) total += CGAL::abs(J[e][i]).sup();
        if (!(total > 0)) continue;
        for (std::size_t i = 0; i < n; ++i) smear[i] += CGAL::abs(J[e][i]).sup() / total;
      }
      double best = -1;
      for (std::size_t i = 0; i < n; ++i) {
        if (B::width(b.x[i]) <= P.minimal_width) continue;
        const double s = std::isfinite(smear[i]) ? smear[i] : 1e300;
        if (s > best) { best = s; v = i; }
      }
      if (v == n) {
        unknown.push_back(b);
        unknown_reason.push_back("not certified at minimal width");
        continue;
      }
    }
    bisect(b, v);
  }
  // unknown boxes, then pending ones (in the order they would have been visited): touching
  // boxes of one chart combination merged into their hull (a cut sweep leaves thousands of
  // neighbouring boxes), each region where its first box was
  if (task) {
    task->unknown = std::move(unknown);
    task->reasons = std::move(unknown_reason);
    for (auto it = stack.rbegin(); it != stack.rend(); ++it) task->pending.push_back(std::move(*it));
  } else {
    std::vector<const Box*> u, pending;
    for (const Box& b : unknown) u.push_back(&b);
    for (auto it = stack.rbegin(); it != stack.rend(); ++it) pending.push_back(&*it);
    add_tree_regions(n, u, Box_class::UNKNOWN, [&](std::size_t i) { return unknown_reason[i]; }, out.unresolved);
    add_tree_regions(n, pending, Box_class::PENDING, [&](std::size_t) { return out.stopped; }, out.unresolved);
  }
  st.seconds = std::chrono::duration<double>(Clock::now() - started).count();
  return out;
}

} // namespace internal

namespace internal {
// consistency_cells: 0 or a power of 2 from 2 to 65536 (`who` names the function refusing it)
inline void check_consistency_cells(std::size_t G, const std::string& who)
{
  if (G != 0 && (G < 2 || (G & (G - 1)) != 0 || G > (std::size_t(1) << 16)))
    throw Input_error(who + ": consistency_cells must be 0 or a power of 2 (2 to 65536), not " + std::to_string(G));
}
} // namespace internal

template <class Traits>
Tree_solve_result solve_tree_system(const Tree_system<Traits>& S, const Tree_solver_parameters& P)
{
  const std::size_t n = S.number_of_variables();
  const std::size_t K = P.sweep_slices;
  if (K == 0 || (K & (K - 1)) != 0 || K > (std::size_t(1) << 20))
    throw Input_error("solve_tree_system: sweep_slices must be a power of 2 (1 to 2^20), not " + std::to_string(K));
  const std::size_t G = P.consistency_cells;
  internal::check_consistency_cells(G, "solve_tree_system");
  typedef CGAL::Interval_nt<false> IT;
  const auto started = std::chrono::steady_clock::now();  // (one time limit for every task)
  // arc consistency first: the cells of each hinge's circle no solution of the short equations
  // leaves out (an optimization: a stop cuts it short and it keeps every cell)
  internal::Tree_domains domains;
  double consistency_seconds = 0;
  if (G != 0 && S.is_square()) {
    CGAL::Protect_FPU_rounding<true> guard;
    domains = internal::tree_domains(S, G, [&]() {
      return (P.interrupt && P.interrupt->load(std::memory_order_relaxed)) ||
             (P.maximal_seconds > 0 && std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count() >= P.maximal_seconds);
    });
    consistency_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  }
  auto finish = [&](Tree_solve_result& r) {
    r.consistency_seconds = consistency_seconds;
    if (domains.cells) for (std::size_t v = 0; v < n; ++v) r.consistent_fraction.push_back(domains.fraction(v));
    r.statistics.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    return r;
  };
  const Sweep_order order = P.sweep && !P.charts_only && S.is_square() ? sweep_order(S) : Sweep_order();
  if (!order.exists(n) || order.driver == Sweep_order::none) {
    Tree_solver_parameters Q = P;  // (the time limit counts the consistency's time)
    if (P.maximal_seconds > 0) Q.maximal_seconds = (std::max)(1e-9, P.maximal_seconds - consistency_seconds);
    Tree_solve_result r = internal::solve_tree_system_from(S, Q, nullptr, nullptr, nullptr, nullptr, 0, nullptr, &domains);
    return finish(r);
  }
  // the slices, in the order the sweep visits them (chart 0 first, each from -1 up); their
  // bounds are exact (K a power of 2)
  std::vector<internal::Tree_box> slices;
  for (int ch = 0; ch < 2; ++ch)
    for (std::size_t k = 0; k < K; ++k) {
      internal::Tree_box b{std::vector<int>(n, Tree_system<Traits>::WHOLE), std::vector<IT>(n, IT(-1, 1))};
      b.ch[order.driver] = ch;
      b.x[order.driver] = IT(-1 + 2 * double(k) / double(K), -1 + 2 * double(k + 1) / double(K));
      slices.push_back(std::move(b));
    }
  // Rounds of tasks, each at most `task_boxes` boxes of the depth-first search from its boxes;
  // what a task leaves becomes tasks of the next round, one per box. A task's answer is its
  // own, then its leftover boxes' in the order they would have been visited: the order of one
  // depth-first search whatever the threads (the work is uneven: on the chain of 16, one
  // slice of 32 holds 60 % of it, in a fold of a few hinges over a narrow driver interval).
  const std::size_t task_boxes = (std::max<std::size_t>)(P.task_boxes, 1);
  struct Task
  {
    std::vector<internal::Tree_box> start;
    Tree_solve_result result;
    internal::Tree_task_boxes boxes;
    std::vector<std::size_t> children;
  };
  std::vector<Task> tasks(slices.size());
  for (std::size_t i = 0; i < slices.size(); ++i) tasks[i].start.push_back(std::move(slices[i]));
  std::atomic<std::size_t> boxes(0);
  std::mutex progress_mutex;
  Tree_solver_parameters Q = P;
  if (P.progress)  // (from any thread, one call at a time; roots: before duplicates are merged)
    Q.progress = [&](std::size_t b, std::size_t) {
      std::lock_guard<std::mutex> lock(progress_mutex);
      std::size_t r = 0;
      for (const Task& t : tasks) r += t.result.roots.size();
      P.progress(b, r);
    };
  for (std::size_t begin = 0; begin < tasks.size();) {
    const std::size_t end = tasks.size();
    internal::parallel_for_each_index(end - begin, P.threads, [&](std::size_t i) {
      Task& t = tasks[begin + i];
      Tree_solve_result r = internal::solve_tree_system_from(S, Q, &order, &boxes, &started, &t.start, task_boxes, &t.boxes, &domains);
      std::lock_guard<std::mutex> lock(progress_mutex);  // (the progress reads the results)
      t.result = std::move(r);
    });
    for (std::size_t i = begin; i < end; ++i) {
      std::vector<internal::Tree_box> left = std::move(tasks[i].boxes.left_over);
      for (internal::Tree_box& b : left) {
        tasks[i].children.push_back(tasks.size());
        Task c;
        c.start.push_back(std::move(b));
        tasks.push_back(std::move(c));
      }
    }
    begin = end;
  }
  // the tasks in depth-first order: roots (a root found from two neighbouring boxes kept once:
  // its enclosure lies in the other's uniqueness box), then the unknown and pending boxes
  // merged into regions, as one search would have
  Tree_solve_result out;
  auto inside = [&](const std::vector<IT>& a, const std::vector<IT>& b) {
    for (std::size_t i = 0; i < n; ++i) if (a[i].inf() < b[i].inf() || b[i].sup() < a[i].sup()) return false;
    return true;
  };
  std::vector<const internal::Tree_box*> unknown, pending;
  std::vector<const std::string*> unknown_reason, pending_reason;
  std::vector<std::size_t> todo;
  for (std::size_t i = slices.size(); i-- > 0;) todo.push_back(i);
  while (!todo.empty()) {
    Task& t = tasks[todo.back()];
    todo.pop_back();
    for (auto it = t.children.rbegin(); it != t.children.rend(); ++it) todo.push_back(*it);
    Tree_solve_result& r = t.result;
    for (Tree_root& root : r.roots) {
      bool duplicate = false;
      for (const Tree_root& q : out.roots)
        duplicate = duplicate || (q.charts == root.charts && (inside(root.enclosure, q.uniqueness_box) || inside(q.enclosure, root.uniqueness_box)));
      if (duplicate) { ++out.statistics.duplicates; continue; }
      out.roots.push_back(std::move(root));
    }
    for (std::size_t i = 0; i < t.boxes.unknown.size(); ++i) {
      unknown.push_back(&t.boxes.unknown[i]);
      unknown_reason.push_back(&t.boxes.reasons[i]);
    }
    for (const internal::Tree_box& b : t.boxes.pending) {
      pending.push_back(&b);
      pending_reason.push_back(&r.stopped);
    }
    if (out.stopped.empty()) out.stopped = r.stopped;
    const double seconds = out.statistics.seconds;
    out.statistics += r.statistics;
    out.statistics.seconds = seconds;
  }
  internal::add_tree_regions(n, unknown, Box_class::UNKNOWN, [&](std::size_t i) { return *unknown_reason[i]; }, out.unresolved);
  internal::add_tree_regions(n, pending, Box_class::PENDING, [&](std::size_t i) { return *pending_reason[i]; }, out.unresolved);
  return finish(out);
}

} // namespace Rigid_incidence
} // namespace CGAL

#endif
