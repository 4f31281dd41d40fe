// Copyright (c) 2026 Rigid_incidence contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The real solution curves of n - 1 polynomial equations in n variables in a box (a
// mechanism, a scene with one degree of freedom: decomposition_subdivision_solver.txt
// Section 3.4), as polylines whose topology is certified.
//
// Which method, and why: an interval-certified subdivision tracer rather than Barton, Elber
// and Hanniel's no-loop and single-component tests. Those tests certify a box by bounding
// the normal cones of the equations' gradients, which needs the equations' gradients
// separated by a cone test that fails wherever two gradients are close to parallel, and it
// follows the curve by marching. The tracer here needs only what the solver already proves:
// (1) a box is *regular* for a variable x_j if the Jacobian of the equations with respect to
// the other n - 1 variables is nonsingular for every point of the box (preconditioned
// interval test ||I - Y J(B)|| < 1). By the mean-value theorem the curve then meets every
// slice x_j = c of the box at most once: inside the box it is a union of x_j-monotone arcs
// with disjoint x_j-ranges, without loops and without endpoints.
// (2) Where the arcs end, the curve crosses the box's faces: the crossings are the roots of
// the n - 1 equations with one variable fixed, found and certified by Subdivision_solver
// (a tangency to a face is a double root there: not certified, so the box is split).
// (3) Whether a crossing is an entry or an exit (in increasing x_j) follows from the sign of
// dx_i/dx_j = -(J_{not j}^{-1} J_j)_i at the crossing, enclosed by a preconditioned interval
// linear solve; sorted by x_j, entries and exits must alternate, and consecutive pairs are
// the arcs. (4) A crossing seen from two neighbouring boxes is one point when one's
// enclosure lies in the other's Krawczyk uniqueness box (both are roots of the same system on
// the same hyperplane). Every node of the resulting graph must have one arc on each side of
// its face; a curve with a node that fails this check is returned with `certified == false`.
//
// Boxes that never become regular down to the minimal width (singular points of the curve:
// crossings of branches, cusps, isolated points) are returned as unresolved regions; the
// branches that end there say so. Splits are placed slightly off the middle so that a curve
// through a symmetric point does not hit a box edge (a crossing on an edge is not certified).

#ifndef CGAL_RIGID_INCIDENCE_CURVE_TRACER_H
#define CGAL_RIGID_INCIDENCE_CURVE_TRACER_H

#include <CGAL/Rigid_incidence/Input_error.h>
#include <CGAL/Rigid_incidence/Polynomial_system.h>
#include <CGAL/Rigid_incidence/Solver_result.h>
#include <CGAL/Rigid_incidence/Subdivision_solver.h>
#include <CGAL/Rigid_incidence/internal/Bernstein_tensor.h>
#include <CGAL/Rigid_incidence/internal/interval_ops.h>

#include <Eigen/Dense>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <functional>
#include <numeric>
#include <string>
#include <type_traits>
#include <vector>

namespace CGAL {
namespace Rigid_incidence {

/*!
\ingroup PkgRigidIncidenceSolver
\brief Parameters of `trace_curves()`. Widths are absolute, in the units of each variable.
*/
struct Curve_tracer_parameters
{
  /// Crossing points of the curve with box faces are certified and tightened to this width.
  double tolerance = 1e-10;
  /// A box at most this wide in every variable that is not regular (a possible singular
  /// point of the curve) is not split further: it becomes an unresolved region. 0: the
  /// default, 1e-6 times the widest variable of the box.
  double minimal_width = 0;
  /// Polyline points are sampled inside each arc at most this far apart in the arc's
  /// monotone variable. 0: the default, the widest variable of the box over 64.
  double sample_step = 0;
  /// Bits of the MPFR mantissa when the interval type is `CGAL::Gmpfi`.
  unsigned precision = 53;
  /// At most this many boxes are visited; what is left is `PENDING`.
  std::size_t maximal_boxes = 200000;
  /// Box budget of each zero-dimensional face system (the crossings of the curve with a box
  /// face, in n-1 variables); a face not settled within it makes the box be split. 0: the
  /// default, 4000. `trace_curves_with_plan()` raises it to 4000*(n-3) for its traces around
  /// folds in n > 4 variables (on Jansen's linkage, 12 variables, the faces of a small box
  /// around a fold need 10000 to 20000 boxes before the box is proved regular).
  std::size_t face_boxes = 0;
  /// As `Subdivision_solver_parameters::maximal_coefficients` (each equation and inequality
  /// with its first and second derivatives, as the solver of the box faces stores them): a
  /// larger system is refused with an `Input_error` naming its largest equation.
  double maximal_coefficients = 33554432;
};

/// \ingroup PkgRigidIncidenceSolver
/// How a solution curve ends.
enum class Curve_end {
  CLOSED,      ///< no end: a closed loop
  BOUNDARY,    ///< it leaves the search box
  UNRESOLVED,  ///< it runs into an unresolved region (a singular point, or a box left pending)
  INEQUALITY   ///< it reaches the boundary of an inequality g >= 0 (to the minimal width)
};

/// \ingroup PkgRigidIncidenceSolver
/// One branch of a solution curve: a polyline from one end to the other.
template <class IT>
struct Solution_curve
{
  /// The polyline: every point lies on the curve up to `max_residual`; the crossings of box
  /// faces among them are certified points of the curve.
  std::vector<std::vector<double>> points;
  /// the topology is certified: every arc lies in a regular box and every crossing was matched
  /// to exactly one arc on each side of its face
  bool certified = true;
  bool closed = false;                 ///< a loop (then `ends` are both `CLOSED`)
  Curve_end ends[2] = {Curve_end::CLOSED, Curve_end::CLOSED};  ///< how the polyline starts and ends
  /// for an `UNRESOLVED` end, the index of the region in `Curve_result::unresolved`, else -1
  long end_region[2] = {-1, -1};
  /// the regular boxes the branch runs through: the branch lies in their union
  std::vector<std::vector<IT>> boxes;
  /// some of the branch lies in a box at the minimal width where an inequality may be 0
  bool on_inequality_boundary = false;
  double max_residual = 0;             ///< largest |f_i| at the polyline's points
};

/// \ingroup PkgRigidIncidenceSolver
/// Counters of one trace.
struct Curve_statistics
{
  std::size_t boxes = 0;              ///< boxes visited
  std::size_t excluded = 0;           ///< boxes without a curve point (a strict sign)
  std::size_t excluded_by_inequality = 0; ///< boxes where some inequality is < 0
  std::size_t regular = 0;            ///< leaf boxes proved regular, with their arcs
  std::size_t splits = 0;             ///< boxes split in two
  std::size_t reductions = 0;         ///< slabs without curve points cut off a box (domain reduction)
  std::size_t face_solves = 0;        ///< zero-dimensional face systems solved
  std::size_t arcs = 0;               ///< arcs between crossings
  std::size_t crossings = 0;          ///< crossing points certified (counted per box)
  std::size_t unmatched = 0;          ///< crossings that could not be matched across a face
  std::size_t block_solves = 0;       ///< `trace_curves_with_plan()`: square blocks solved over pieces of the curve block
  std::size_t pieces = 0;             ///< `trace_curves_with_plan()`: pieces of the curve block lifted (halvings included)
  std::size_t kept_solves = 0;        ///< `trace_curves_with_plan()`: block solves over a halved piece that settled a group of lifts over one of its halves, instead of a solve
  std::size_t fold_traces = 0;        ///< `trace_curves_with_plan()`: whole-system traces around pieces that could not be lifted
  std::size_t coarse_solves = 0;      ///< `trace_curves_with_plan()`: block solves around folds repeated with a coarser minimal width (`Plan_trace_parameters::block_boxes`)
  std::size_t lifted_arcs = 0;        ///< `trace_curves_with_plan()`: arcs over runs of failed pieces proved by their certified enclosures, not traced
  double seconds = 0;                 ///< wall-clock time
};

/*!
\ingroup PkgRigidIncidenceSolver
\brief What `trace_curves()` found: branches of the real solution curve and the regions it
could not resolve.
*/
template <class IT>
struct Curve_result
{
  std::vector<Solution_curve<IT>> curves;        ///< the branches
  /// regions not resolved: singular points of the curve (reason "singular: no regular
  /// parametrization at the minimal width"), crossings that could not be certified at the
  /// minimal width, or boxes left when the budget ran out (`PENDING`)
  std::vector<Solver_unresolved<IT>> unresolved;
  Curve_statistics statistics;  ///< counters of the trace
  /// no unresolved region is left and every branch is certified
  bool complete() const
  {
    if (!unresolved.empty()) return false;
    for (const auto& c : curves) if (!c.certified) return false;
    return true;
  }
};

namespace internal {

// A polynomial as a dense power-basis tensor over the variables it involves: ranges over a
// box come from its Bernstein coefficients there.
template <class IT> struct Dense_polynomial
{
  typedef Interval_ops<IT> O;
  Tensor_shape shape;
  std::vector<IT> power;

  template <class NT> explicit Dense_polynomial(const Sparse_polynomial<NT>& f)
  {
    std::vector<std::size_t> vars = f.variables();
    std::vector<unsigned> degs;
    for (std::size_t v : vars) degs.push_back(f.degree(v));
    shape.set(vars, degs);
    power.assign(shape.size, IT(0));
    for (const auto& t : f.terms()) {
      std::size_t at = 0;
      for (std::size_t k = 0; k < vars.size(); ++k) at += t.first[vars[k]] * shape.strides[k];
      power[at] = O::from(t.second);
    }
  }
  // the Bernstein coefficients on the box [lo, hi] (per global variable)
  std::vector<IT> bernstein(const std::vector<typename O::Bound>& lo, const std::vector<typename O::Bound>& hi) const
  {
    std::vector<IT> l, w;
    for (std::size_t v : shape.variables) {
      l.push_back(O::point(lo[v]));
      w.push_back(O::point(hi[v]) - O::point(lo[v]));
    }
    return to_bernstein(shape, power, l, w);
  }
  // the hull of the Bernstein coefficients on the box [lo, hi] (per global variable)
  IT range(const std::vector<typename O::Bound>& lo, const std::vector<typename O::Bound>& hi) const
  {
    if (shape.variables.empty()) return power[0];
    std::vector<IT> b = bernstein(lo, hi);
    typename O::Bound mn = O::lower(b[0]), mx = O::upper(b[0]);
    for (const IT& x : b) {
      if (O::lower(x) < mn) mn = O::lower(x);
      if (O::upper(x) > mx) mx = O::upper(x);
    }
    return O::make(mn, mx);
  }
};

template <class IT> bool certainly_positive(const IT& x) { return Interval_ops<IT>::lower(x) > 0; }
template <class IT> bool certainly_negative(const IT& x) { return Interval_ops<IT>::upper(x) < 0; }

// f with x_i fixed to the double c, in the other variables: exact if NT is Gmpq, else in IT.
template <class FT, class NT>
Sparse_polynomial<FT> fix_variable(const Sparse_polynomial<NT>& f, std::size_t i, double c)
{
  typedef Interval_ops<typename std::conditional<std::is_same<FT, NT>::value, CGAL::Interval_nt<false>, FT>::type> O;
  const std::size_t n = f.number_of_variables();
  Sparse_polynomial<FT> r(n - 1);
  for (const auto& t : f.terms()) {
    FT k;
    if constexpr (std::is_same<FT, NT>::value) k = t.second;
    else k = O::from(t.second);
    const FT cc = [&]() {
      if constexpr (std::is_same<FT, NT>::value) return FT(c);
      else return O::point(O::bound_from_double(c));
    }();
    for (unsigned p = 0; p < t.first[i]; ++p) k = k * cc;
    typename Sparse_polynomial<FT>::Exponent e;
    for (std::size_t v = 0; v < n; ++v)
      if (v != i) e.push_back(t.first[v]);
    r.add_term(e, k);
  }
  return r;
}

template <class IT, class NT> class Curve_tracer_run
{
  typedef Interval_ops<IT> O;
  typedef typename O::Bound Bound;
  typedef Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic> Matrix;
  typedef Eigen::Matrix<double, Eigen::Dynamic, 1> Vector;
  // face systems: exact coefficients stay exact (the solver may then raise the precision)
  typedef typename std::conditional<std::is_same<NT, CGAL::Gmpq>::value, CGAL::Gmpq, IT>::type Face_NT;

public:
  enum State { OPEN, SPLIT, EXCLUDED, EXCLUDED_BY_INEQUALITY, REGULAR, UNRESOLVED, PENDING };

  struct Crossing
  {
    std::size_t face_variable;  // the fixed variable
    bool upper;                 // on the upper face of that variable
    std::vector<IT> enclosure;  // n intervals (the fixed one a point)
    std::vector<IT> uniqueness; // n intervals: the only root of the face system in it
    std::vector<double> point;  // approximation
    bool entry = false;         // entry in increasing x_j
    bool sign_known = false;    // `entry` is proved (else it follows from the order)
    bool dropped = false;       // its arc is left out: an inequality is < 0 along it
    bool at_edge = false;       // at an edge or corner of the search box (found on each face there)
    std::size_t node = 0;       // index in the leaf's crossing list -> global id
  };
  struct Arc
  {
    std::size_t from, to;                 // global crossing ids
    std::vector<std::vector<double>> samples;  // interior points, from -> to
  };
  struct Box
  {
    std::vector<Bound> lo, hi;
    State state = OPEN;
    std::size_t depth = 0;
    std::size_t split_variable = 0;
    Bound split_value;
    std::size_t child[2] = {0, 0};
    std::size_t parameter = 0;                // j of a regular box
    bool inequality_boundary = false;
    std::vector<std::size_t> crossings;       // global crossing ids
    std::string reason;
  };

  const Polynomial_system<NT>& sys;
  const Curve_tracer_parameters& P;
  std::size_t n;
  std::vector<Dense_polynomial<IT>> eq, ineq;
  std::vector<std::vector<Sparse_polynomial<NT>>> derivative;        // [k][v]
  std::vector<std::vector<Dense_polynomial<IT>>> dense_derivative;   // [k][v]
  double min_width, step, widest;
  std::vector<Box> boxes;
  std::vector<Crossing> crossings;
  std::vector<Arc> arcs;
  std::vector<std::size_t> crossing_box;  // global crossing id -> box
  Curve_result<IT> result;
  Clip_workspace clip_work;

  Curve_tracer_run(const Polynomial_system<NT>& s, const Curve_tracer_parameters& p) : sys(s), P(p), n(s.number_of_variables())
  {
    for (const auto& f : sys.equations) eq.emplace_back(f);
    for (const auto& g : sys.inequalities) ineq.emplace_back(g);
    derivative.resize(sys.number_of_equations());
    dense_derivative.resize(sys.number_of_equations());
    for (std::size_t k = 0; k < sys.number_of_equations(); ++k)
      for (std::size_t v = 0; v < n; ++v) {
        derivative[k].push_back(sys.equations[k].derivative(v));
        dense_derivative[k].emplace_back(derivative[k].back());
      }
    widest = 0;
    for (const auto& b : sys.box) widest = (std::max)(widest, b.second - b.first);
    min_width = P.minimal_width > 0 ? P.minimal_width : 1e-6 * widest;
    step = P.sample_step > 0 ? P.sample_step : widest / 64;
  }

  void go()
  {
    const auto start = std::chrono::steady_clock::now();
    Box root;
    for (const auto& b : sys.box) {
      root.lo.push_back(O::bound_from_double(b.first));
      root.hi.push_back(O::bound_from_double(b.second));
    }
    boxes.push_back(root);
    std::vector<std::size_t> todo{0};
    while (!todo.empty()) {
      const std::size_t b = todo.back();
      todo.pop_back();
      if (result.statistics.boxes >= P.maximal_boxes) {
        boxes[b].state = PENDING;
        boxes[b].reason = "box budget exhausted";
        continue;
      }
      ++result.statistics.boxes;
      process(b);
      // the open leaves below b, the first child's first (a reduction cuts several slabs at
      // once: a chain of splits)
      std::vector<std::size_t> below{b}, open;
      while (!below.empty()) {
        const std::size_t x = below.back();
        below.pop_back();
        if (boxes[x].state == SPLIT) {
          below.push_back(boxes[x].child[0]);
          below.push_back(boxes[x].child[1]);
        } else if (boxes[x].state == OPEN && x != b) {
          open.push_back(x);
        }
      }
      todo.insert(todo.end(), open.begin(), open.end());
    }
    assemble();
    result.statistics.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  }

private:
  double width(const Box& b) const
  {
    double w = 0;
    for (std::size_t v = 0; v < n; ++v) w = (std::max)(w, O::to_double(b.hi[v]) - O::to_double(b.lo[v]));
    return w;
  }
  std::vector<IT> box_intervals(const Box& b) const
  {
    std::vector<IT> r;
    for (std::size_t v = 0; v < n; ++v) r.push_back(O::make(b.lo[v], b.hi[v]));
    return r;
  }

  void split(std::size_t b)
  {
    // the widest variable relative to the search box; the cut slightly off the middle
    std::size_t s = 0;
    double best = -1;
    for (std::size_t v = 0; v < n; ++v) {
      const double full = sys.box[v].second - sys.box[v].first;
      const double rel = (O::to_double(boxes[b].hi[v]) - O::to_double(boxes[b].lo[v])) / full;
      if (rel > best) { best = rel; s = v; }
    }
    static const double offsets[] = {0.0123, -0.0217, 0.0311, -0.0089, 0.0167, -0.0271, 0.0053, -0.0149};
    const double lo = O::to_double(boxes[b].lo[s]), hi = O::to_double(boxes[b].hi[s]);
    double c = lo + (hi - lo) * (0.5 + offsets[(boxes[b].depth + 3 * s) % 8]);
    if (!(c > lo && c < hi)) c = 0.5 * lo + 0.5 * hi;
    if (!(c > lo && c < hi)) {  // cannot be split in double
      boxes[b].state = UNRESOLVED;
      boxes[b].reason = "precision exhausted";
      return;
    }
    Box l = boxes[b], r = boxes[b];
    l.state = r.state = OPEN;
    l.depth = r.depth = boxes[b].depth + 1;
    l.hi[s] = r.lo[s] = O::bound_from_double(c);
    l.crossings.clear();
    r.crossings.clear();
    boxes[b].state = SPLIT;
    boxes[b].split_variable = s;
    boxes[b].split_value = O::bound_from_double(c);
    boxes[b].child[0] = boxes.size();
    boxes[b].child[1] = boxes.size() + 1;
    boxes.push_back(l);
    boxes.push_back(r);
    ++result.statistics.splits;
  }

  // -1: no curve point in the box; 1: empty slabs were cut off (a chain of splits, each part
  // without curve points excluded, the open box last); 0: no cut worth it (every empty slab
  // less than a fifth of its side)
  int reduce(std::size_t b)
  {
    const Box& B = boxes[b];
    std::vector<double> lo(n), hi(n);
    for (std::size_t v = 0; v < n; ++v) { lo[v] = O::to_double(B.lo[v]); hi[v] = O::to_double(B.hi[v]); }
    std::vector<double> keep_lo = lo, keep_hi = hi, tu, tv;
    for (const auto& f : eq) {
      if (f.shape.variables.empty()) continue;
      if (!clip_axes(f.shape, f.bernstein(B.lo, B.hi), tu, tv, clip_work)) return -1;
      for (std::size_t k = 0; k < f.shape.variables.size(); ++k) {
        const std::size_t v = f.shape.variables[k];
        const double w = hi[v] - lo[v];
        // 1e-12 of the side covers the rounding of lo + t w in any rounding mode
        keep_lo[v] = (std::max)(keep_lo[v], lo[v] + (std::max)(0.0, tu[k] - 1e-12) * w);
        keep_hi[v] = (std::min)(keep_hi[v], lo[v] + (std::min)(1.0, tv[k] + 1e-12) * w);
      }
    }
    // the cut goes through the middle of the empty slab, not along the hull: a face on the
    // hull could touch the curve (a tangency, which no face solve certifies), a face inside
    // the slab meets no curve point at all
    // a variable already ten times thinner than the widest (relative to the search box) is
    // not cut further: a curve in a hyperplane x_v = c would otherwise be approached forever
    double widest_relative = 0;
    for (std::size_t v = 0; v < n; ++v)
      widest_relative = (std::max)(widest_relative, (hi[v] - lo[v]) / (sys.box[v].second - sys.box[v].first));
    struct Cut
    {
      double gain, at;
      std::size_t v;
      bool upper;
    };
    std::vector<Cut> cuts;
    for (std::size_t v = 0; v < n; ++v) {
      if (keep_lo[v] > keep_hi[v]) return -1;
      const double w = hi[v] - lo[v];
      if (w / (sys.box[v].second - sys.box[v].first) < 0.1 * widest_relative) continue;
      // where in the slab: a fraction that differs between variables and depths, so that two
      // variables equal along the curve (a symmetric mechanism) are not cut at the same value,
      // which would put a crossing on a box edge
      const double f = 0.35 + 0.3 * std::abs(std::fmod(std::sin(12.9898 * double(v + 1) + 78.233 * double(B.depth)) * 43758.5453, 1.0));
      if ((keep_lo[v] - lo[v]) / w > 0.2) cuts.push_back({(keep_lo[v] - lo[v]) / w, lo[v] + f * (keep_lo[v] - lo[v]), v, false});
      if ((hi[v] - keep_hi[v]) / w > 0.2) cuts.push_back({(hi[v] - keep_hi[v]) / w, hi[v] - f * (hi[v] - keep_hi[v]), v, true});
    }
    // every slab worth it at once, the largest first: the bounds hold in every part of the
    // box, so the parts need no new clipping (was one slab per visit: in 12 variables most
    // of a trace's boxes went to reductions)
    std::sort(cuts.begin(), cuts.end(), [](const Cut& x, const Cut& y) { return x.gain > y.gain; });
    const std::size_t depth = B.depth;
    std::size_t at_box = b;
    int cut = 0;
    for (const Cut& c : cuts) {
      const double l0 = O::to_double(boxes[at_box].lo[c.v]), h0 = O::to_double(boxes[at_box].hi[c.v]);
      if (!(c.at > l0 && c.at < h0)) continue;
      Box l = boxes[at_box], r = boxes[at_box];
      l.state = r.state = OPEN;
      l.depth = r.depth = depth + 1;
      l.hi[c.v] = r.lo[c.v] = O::bound_from_double(c.at);
      (c.upper ? r : l).state = EXCLUDED;
      ++result.statistics.excluded;
      Box& S = boxes[at_box];
      S.state = SPLIT;
      S.split_variable = c.v;
      S.split_value = O::bound_from_double(c.at);
      S.child[0] = boxes.size();
      S.child[1] = boxes.size() + 1;
      at_box = c.upper ? boxes.size() : boxes.size() + 1;
      boxes.push_back(l);  // S is not used after this
      boxes.push_back(r);
      ++result.statistics.reductions;
      ++cut;
    }
    return cut > 0 ? 1 : 0;
  }

  // split, or leave the box unresolved with `why` at the minimal width
  void split_or_give_up(std::size_t b, const std::string& why)
  {
    boxes[b].crossings.clear();
    if (width(boxes[b]) <= min_width) {
      boxes[b].state = UNRESOLVED;
      boxes[b].reason = why;
      return;
    }
    split(b);
  }

  Matrix jacobian_at(const std::vector<double>& x) const
  {
    Matrix J(sys.number_of_equations(), n);
    for (std::size_t k = 0; k < sys.number_of_equations(); ++k)
      for (std::size_t v = 0; v < n; ++v) J(k, v) = derivative[k][v].template evaluate<double>(x);
    return J;
  }
  Vector values_at(const std::vector<double>& x) const
  {
    Vector f(sys.number_of_equations());
    for (std::size_t k = 0; k < sys.number_of_equations(); ++k) f(k) = sys.equations[k].template evaluate<double>(x);
    return f;
  }

  // the variable the curve is most steeply parametrized by at x: the largest component of
  // the Jacobian's null vector
  std::vector<std::size_t> parameter_order(const std::vector<double>& x) const
  {
    Matrix J = jacobian_at(x);
    Eigen::JacobiSVD<Matrix> svd(J, Eigen::ComputeFullV);
    Vector t = svd.matrixV().col(n - 1);
    std::vector<std::size_t> order(n);
    std::iota(order.begin(), order.end(), std::size_t(0));
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return std::abs(t(a)) > std::abs(t(b)); });
    return order;
  }

  // ||I - Y A||_inf as an upper bound, Y = inverse of the midpoint of A (m x m intervals)
  // (+infinity if the midpoint is singular); M receives I - Y A
  double contraction(const std::vector<std::vector<IT>>& A, Matrix& Y, std::vector<std::vector<IT>>& M) const
  {
    const std::size_t m = A.size();
    Matrix mid(m, m);
    for (std::size_t r = 0; r < m; ++r)
      for (std::size_t c = 0; c < m; ++c) mid(r, c) = 0.5 * O::lower_double(A[r][c]) + 0.5 * O::upper_double(A[r][c]);
    Eigen::FullPivLU<Matrix> lu(mid);
    if (!lu.isInvertible()) return std::numeric_limits<double>::infinity();
    Y = lu.inverse();
    if (!Y.allFinite()) return std::numeric_limits<double>::infinity();
    M.assign(m, std::vector<IT>(m, IT(0)));
    double norm = 0;
    for (std::size_t r = 0; r < m; ++r) {
      IT row_sum(0);
      for (std::size_t c = 0; c < m; ++c) {
        IT s(r == c ? 1 : 0);
        for (std::size_t q = 0; q < m; ++q) s = s - O::point(O::bound_from_double(Y(r, q))) * A[q][c];
        M[r][c] = s;
        const double a = (std::max)(std::abs(O::lower_double(s)), std::abs(O::upper_double(s)));
        row_sum = row_sum + IT(a);
      }
      norm = (std::max)(norm, O::upper_double(row_sum));
    }
    return norm;
  }

  // the Jacobian with respect to every variable but j, over the box given by intervals X
  // (Bernstein ranges if `bernstein`, else plain evaluation at X)
  std::vector<std::vector<IT>> reduced_jacobian(const Box* b, const std::vector<IT>& X, std::size_t j) const
  {
    const std::size_t m = sys.number_of_equations();
    std::vector<std::vector<IT>> A(m);
    for (std::size_t k = 0; k < m; ++k)
      for (std::size_t v = 0; v < n; ++v) {
        if (v == j) continue;
        A[k].push_back(b ? dense_derivative[k][v].range(b->lo, b->hi) : derivative[k][v].template evaluate<IT>(X));
      }
    return A;
  }

  // an enclosure of dx/dx_j (the other variables, in order) at the point box X, or empty
  std::vector<IT> tangent(const std::vector<IT>& X, std::size_t j) const
  {
    const std::size_t m = sys.number_of_equations();
    std::vector<std::vector<IT>> A = reduced_jacobian(nullptr, X, j), M;
    Matrix Y;
    const double r = contraction(A, Y, M);
    if (!(r < 1)) return {};
    std::vector<IT> z(m, IT(0));
    double zn = 0;
    for (std::size_t a = 0; a < m; ++a) {
      for (std::size_t q = 0; q < m; ++q) z[a] = z[a] - O::point(O::bound_from_double(Y(a, q))) * derivative[q][j].template evaluate<IT>(X);
      zn = (std::max)(zn, (std::max)(std::abs(O::lower_double(z[a])), std::abs(O::upper_double(z[a]))));
    }
    // u = z + M u, so |u| <= |z| / (1 - r) and u in z + M [-R, R]
    const IT R = IT(zn) / (IT(1) - IT(r));
    const IT ball = O::make(O::bound_from_double(-O::upper_double(R)), O::bound_from_double(O::upper_double(R)));
    std::vector<IT> u(m);
    for (std::size_t a = 0; a < m; ++a) {
      IT s = z[a];
      for (std::size_t c = 0; c < m; ++c) s = s + M[a][c] * ball;
      u[a] = s;
    }
    return u;
  }

  void process(std::size_t b)
  {
    Box& B = boxes[b];
    // (1) exclusion
    for (const auto& f : eq) {
      const IT r = f.range(B.lo, B.hi);
      if (certainly_positive(r) || certainly_negative(r)) { B.state = EXCLUDED; ++result.statistics.excluded; return; }
    }
    std::vector<std::size_t> straddling;
    for (std::size_t q = 0; q < ineq.size(); ++q) {
      const IT r = ineq[q].range(B.lo, B.hi);
      if (certainly_negative(r)) { B.state = EXCLUDED_BY_INEQUALITY; ++result.statistics.excluded_by_inequality; return; }
      if (!certainly_positive(r) && O::lower(r) < 0) straddling.push_back(q);
    }
    const bool small = width(B) <= min_width;
    // (2) domain reduction: the equations' projected control polygons (unpreconditioned)
    // bound where the curve can be in each variable; a large enough empty slab is cut off
    // as an excluded box (the tree of boxes keeps tiling the search box)
    if (!small) {
      const int cut = reduce(b);
      if (cut < 0) { boxes[b].state = EXCLUDED; ++result.statistics.excluded; return; }
      if (cut > 0) return;
    }
    // (3) regularity
    std::vector<double> centre(n);
    for (std::size_t v = 0; v < n; ++v) centre[v] = 0.5 * O::to_double(B.lo[v]) + 0.5 * O::to_double(B.hi[v]);
    std::vector<std::size_t> order = parameter_order(centre);
    bool regular = false;
    for (std::size_t c = 0; c < (std::min<std::size_t>)(2, n) && !regular; ++c) {
      std::vector<std::vector<IT>> A = reduced_jacobian(&B, {}, order[c]), M;
      Matrix Y;
      if (contraction(A, Y, M) < 1) { regular = true; B.parameter = order[c]; }
    }
    if (!regular) { split_or_give_up(b, "singular: no regular parametrization at the minimal width"); return; }
    // (4) crossings on the faces
    std::vector<Crossing> found;
    std::string why;
    if (!face_crossings(B, found, why)) { split_or_give_up(b, why); return; }
    // (5) entries and exits alternate in increasing x_j
    const std::size_t j = B.parameter;
    std::sort(found.begin(), found.end(), [&](const Crossing& x, const Crossing& y) {
      return O::lower_double(x.enclosure[j]) + O::upper_double(x.enclosure[j]) < O::lower_double(y.enclosure[j]) + O::upper_double(y.enclosure[j]);
    });
    for (std::size_t k = 0; k < found.size(); ++k) {
      if (found[k].sign_known && found[k].entry != (k % 2 == 0)) { split_or_give_up(b, "crossings not certified"); return; }
      if (k + 1 < found.size() && !(O::upper(found[k].enclosure[j]) < O::lower(found[k + 1].enclosure[j]))) {
        split_or_give_up(b, "crossings not certified");
        return;
      }
    }
    if (found.size() % 2) { split_or_give_up(b, "crossings not certified"); return; }
    // (6) an inequality whose range in the box contains 0: where the curve meets g = 0 (the
    // roots of the equations and g together) the box is split down to the minimal width;
    // where it does not, g keeps one sign along each arc, read at the arc's first crossing
    std::vector<char> keep(found.size() / 2, 1);
    if (!straddling.empty() && small) B.inequality_boundary = true;
    else
      for (std::size_t q : straddling) {
        const int meets = meets_inequality(B, q);
        if (meets != 0) {
          if (meets > 0) split(b);
          else split_or_give_up(b, "inequality not decided");
          return;
        }
        for (std::size_t k = 0; k + 1 < found.size(); k += 2) {
          const IT g = sys.inequalities[q].template evaluate<IT>(found[k].enclosure);
          if (certainly_negative(g)) keep[k / 2] = 0;
          else if (!certainly_positive(g)) { split_or_give_up(b, "inequality not decided"); return; }
        }
      }
    B.state = REGULAR;
    ++result.statistics.regular;
    for (std::size_t k = 0; k < found.size(); ++k) {
      found[k].dropped = !keep[k / 2];
      B.crossings.push_back(crossings.size());
      crossing_box.push_back(b);
      crossings.push_back(found[k]);
    }
    result.statistics.crossings += found.size();
    for (std::size_t k = 0; k + 1 < found.size(); k += 2) {
      if (!keep[k / 2]) continue;
      Arc a;
      a.from = B.crossings[k];
      a.to = B.crossings[k + 1];
      sample(B, a);
      arcs.push_back(a);
      ++result.statistics.arcs;
    }
  }

  // 0 if the curve certainly does not meet g_q = 0 in the box, 1 if it does, -1 if the
  // solver cannot tell
  int meets_inequality(const Box& B, std::size_t q)
  {
    Polynomial_system<NT> s;
    s.variable_names = sys.variable_names;
    for (std::size_t v = 0; v < n; ++v) s.box.emplace_back(O::to_double(B.lo[v]), O::to_double(B.hi[v]));
    s.equations = sys.equations;
    s.equations.push_back(sys.inequalities[q]);
    Subdivision_solver_parameters p = face_parameters();
    Solver_result<IT> r;
    try {
      r = Subdivision_solver<IT>(p).solve(s);
    } catch (const Input_error&) {
      return -1;
    }
    ++result.statistics.face_solves;
    if (!r.roots.empty()) return 1;
    return r.unresolved.empty() ? 0 : -1;
  }

  // the equations on the hyperplane x_i = c, in the other variables over the box's other
  // sides; 1 if some equation is then identically zero, -1 if some is a nonzero constant
  int slice_system(const Box& B, std::size_t i, double c, Polynomial_system<Face_NT>& f) const
  {
    for (std::size_t v = 0; v < n; ++v)
      if (v != i) {
        f.variable_names.push_back(v < sys.variable_names.size() ? sys.variable_names[v] : "x" + std::to_string(v));
        f.box.emplace_back(O::to_double(B.lo[v]), O::to_double(B.hi[v]));
      }
    int what = 0;
    for (const auto& e : sys.equations) {
      f.equations.push_back(fix_variable<Face_NT>(e, i, c));
      if (f.equations.back().is_zero()) return 1;
      if (f.equations.back().total_degree() == 0) {
        const IT v = Interval_ops<IT>::from(f.equations.back().terms().begin()->second);
        if (certainly_positive(v) || certainly_negative(v)) what = -1;
      }
    }
    return what;
  }
  Subdivision_solver_parameters face_parameters() const
  {
    Subdivision_solver_parameters q;
    q.tolerance = P.tolerance;
    q.precision = P.precision;
    // a face the solver cannot settle quickly (two crossings closer than double precision
    // separates) is settled by a smaller box, or left unresolved at the minimal width
    q.maximal_boxes = P.face_boxes > 0 ? P.face_boxes : 4000;
    q.minimal_width = q.singular_width = 1e-3 * min_width;
    q.positive_dimensional_evidence = 64;
    q.maximal_precision = 0;  // no multiprecision retry on every face near such a pair
    q.maximal_coefficients = P.maximal_coefficients;
    return q;
  }

  // the crossings of the curve with the box's faces, each certified; false (with why) if a
  // face system is not solved completely or a crossing touches an edge of the box
  bool face_crossings(const Box& B, std::vector<Crossing>& found, std::string& why)
  {
    const std::size_t j = B.parameter;
    const Subdivision_solver_parameters q = face_parameters();
    for (std::size_t i = 0; i < n; ++i)
      for (int side = 0; side < 2; ++side) {
        const Bound& cb = side ? B.hi[i] : B.lo[i];
        const double c = O::to_double(cb);
        Polynomial_system<Face_NT> f;
        const int kind = slice_system(B, i, c, f);
        if (kind == 1) { why = "the curve lies in a box face"; return false; }
        if (kind == -1) continue;
        ++result.statistics.face_solves;
        Solver_result<IT> r;
        try {
          r = Subdivision_solver<IT>(q).solve(f);
        } catch (const Input_error&) {
          why = "face system not solvable";
          return false;
        }
        if (!r.complete()) { why = "crossings not certified"; return false; }
        for (const auto& root : r.roots) {
          // A crossing at an edge of the box: inside the search box, an edge a split moves (or
          // leaves unresolved at the minimal width). An edge of the search box itself stays, and
          // a curve may leave through it (z = x leaves the cube [-2, 2]^3 through its edges
          // x = z = +-2): such a crossing is an end of the curve, found on each of the faces
          // that meet there, and counted once. It is one only if the curve enters the box
          // there: its tangent points strictly inwards through every one of those faces (a
          // curve that touches the box at a corner only, x^2 + z^2 = 8 at the corners of
          // [-2, 2]^2, does not; taken as two crossings it made an arc between two corners)
          std::vector<std::pair<std::size_t, int>> faces;  // (variable, side) the crossing lies on
          if (root.on_boundary) {
            bool outer = search_face(B, i, side);
            faces.emplace_back(i, side);
            for (std::size_t v = 0, w = 0; v < n && outer; ++v) {
              if (v == i) continue;
              const IT& e = root.enclosure[w];
              if (!(f.box[w].first < O::lower_double(e))) { outer = outer && search_face(B, v, 0); faces.emplace_back(v, 0); }
              if (!(O::upper_double(e) < f.box[w].second)) { outer = outer && search_face(B, v, 1); faces.emplace_back(v, 1); }
              ++w;
            }
            if (!outer) { why = "crossing at a box edge"; return false; }
          }
          Crossing x;
          x.at_edge = !faces.empty();
          x.face_variable = i;
          x.upper = side == 1;
          for (std::size_t v = 0, w = 0; v < n; ++v) {
            if (v == i) {
              x.enclosure.push_back(O::point(cb));
              x.uniqueness.push_back(O::point(cb));
              x.point.push_back(c);
            } else {
              x.enclosure.push_back(root.enclosure[w]);
              x.uniqueness.push_back(root.uniqueness_box[w]);
              x.point.push_back(root.approximation[w]);
              ++w;
            }
          }
          // entry or exit in increasing x_j: a j-face says it; on another face the sign of
          // dx_i/dx_j does, where its enclosure decides it (a check only: every crossing is
          // transversal, so sorted by x_j they alternate anyway)
          x.sign_known = true;
          if (i == j) x.entry = !x.upper;
          else {
            std::vector<IT> u = tangent(x.enclosure, j);
            const IT ui = u.empty() ? IT(0) : u[i < j ? i : i - 1];
            x.sign_known = certainly_positive(ui) || certainly_negative(ui);
            // moving in +x_j, x_i grows if ui > 0: into the box through its lower face
            x.entry = certainly_positive(ui) != x.upper;
          }
          if (x.at_edge) {
            // moving along s * (dx/dx_j) (s = +-1) the curve enters through every face it lies on
            const std::vector<IT> u = tangent(x.enclosure, j);  // (B.parameter: j < n)
            int s = 0;
            bool enters = !u.empty();
            for (const auto& fv : faces) {
              if (!enters) break;
              const IT t = fv.first == j ? IT(1) : u[fv.first < j ? fv.first : fv.first - 1];
              if (!certainly_positive(t) && !certainly_negative(t)) { enters = false; break; }
              const int in = (certainly_positive(t) ? 1 : -1) * (fv.second ? -1 : 1);  // the s that goes in here
              if (s != 0 && in != s) enters = false;
              s = in;
            }
            if (!enters) { why = "crossing at a box edge"; return false; }
            x.sign_known = true;
            x.entry = s > 0;
            bool seen = false;  // on another face of the edge already: the same point, the same way in
            for (const Crossing& y : found) {
              if (!y.at_edge || !meet(y.enclosure, x.enclosure)) continue;
              if (y.face_variable == x.face_variable || y.entry != x.entry) { why = "crossing at a box edge"; return false; }
              seen = true;
            }
            if (seen) continue;
          }
          found.push_back(x);
        }
      }
    return true;
  }

  // B's lower (side 0) or upper (side 1) face in x_v lies on the search box's
  bool search_face(const Box& B, std::size_t v, int side) const
  {
    return side ? !(O::to_double(B.hi[v]) < sys.box[v].second) : !(sys.box[v].first < O::to_double(B.lo[v]));
  }

  // the point of the curve on the slice x_j = x[j] in the box, by Newton from x
  bool on_slice(const Box& B, std::size_t j, std::vector<double>& y) const
  {
    bool ok = false;
    for (int it = 0; it < 30 && !ok; ++it) {
      Vector f = values_at(y);
      Matrix J = jacobian_at(y);
      Matrix A(n - 1, n - 1);
      for (std::size_t r = 0; r + 1 < n; ++r)
        for (std::size_t v = 0, c = 0; v < n; ++v)
          if (v != j) A(r, c++) = J(r, v);
      Vector d = A.fullPivLu().solve(f);
      if (!d.allFinite()) return false;
      for (std::size_t v = 0, c = 0; v < n; ++v)
        if (v != j) y[v] -= d(c++);
      ok = d.template lpNorm<Eigen::Infinity>() <= 1e-12 * (1 + widest);
    }
    for (std::size_t v = 0; v < n; ++v)
      if (!(y[v] >= O::to_double(B.lo[v]) && y[v] <= O::to_double(B.hi[v]))) return false;
    return ok;
  }

  // interior points of the arc: slices halved until consecutive points are at most `step`
  // apart in every variable
  void sample(const Box& B, Arc& a) const
  {
    const std::size_t j = B.parameter;
    std::function<void(const std::vector<double>&, const std::vector<double>&, int)> between =
        [&](const std::vector<double>& p, const std::vector<double>& q, int depth) {
          double gap = 0;
          for (std::size_t v = 0; v < n; ++v) gap = (std::max)(gap, std::abs(q[v] - p[v]));
          if (gap <= step || depth > 20) return;
          // Newton from the chord's midpoint, else from either end moved onto the slice
          std::vector<double> m(n);
          bool found = false;
          for (int start = 0; start < 3 && !found; ++start) {
            for (std::size_t v = 0; v < n; ++v) m[v] = start == 0 ? 0.5 * (p[v] + q[v]) : start == 1 ? p[v] : q[v];
            m[j] = 0.5 * (p[j] + q[j]);
            found = on_slice(B, j, m);
          }
          if (!found) {
            // the slice solved: in a regular box it holds exactly one point of the arc
            Polynomial_system<Face_NT> f;
            if (slice_system(B, j, m[j], f) != 0) return;
            Solver_result<IT> r;
            try {
              r = Subdivision_solver<IT>(face_parameters()).solve(f);
            } catch (const Input_error&) {
              return;
            }
            if (r.roots.size() != 1 || !r.unresolved.empty()) return;
            for (std::size_t v = 0, w = 0; v < n; ++v)
              if (v != j) m[v] = r.roots[0].approximation[w++];
          }
          between(p, m, depth + 1);
          a.samples.push_back(m);
          between(m, q, depth + 1);
        };
    between(crossings[a.from].point, crossings[a.to].point, 0);
  }

  // the leaf containing the crossing's point just across face (i, upper), or -1 if the
  // crossing's enclosure straddles a split plane on the way down (a box edge)
  long locate_across(const Crossing& c) const
  {
    std::size_t b = 0;
    const std::size_t i = c.face_variable;
    if (c.upper ? c.point[i] >= sys.box[i].second : c.point[i] <= sys.box[i].first) return -2;  // the search box's boundary
    while (boxes[b].state == SPLIT) {
      const std::size_t s = boxes[b].split_variable;
      const Bound& at = boxes[b].split_value;
      bool right;
      if (s == i && O::lower(c.enclosure[i]) == at) right = c.upper;  // across the face
      else if (O::upper(c.enclosure[s]) < at) right = false;
      else if (O::lower(c.enclosure[s]) > at) right = true;
      else return -1;
      b = boxes[b].child[right ? 1 : 0];
    }
    return long(b);
  }

  static bool inside(const std::vector<IT>& a, const std::vector<IT>& b)
  {
    for (std::size_t v = 0; v < a.size(); ++v)
      if (O::lower(a[v]) < O::lower(b[v]) || O::upper(a[v]) > O::upper(b[v])) return false;
    return true;
  }
  static bool meet(const std::vector<IT>& a, const std::vector<IT>& b)
  {
    for (std::size_t v = 0; v < a.size(); ++v)
      if (O::upper(a[v]) < O::lower(b[v]) || O::upper(b[v]) < O::lower(a[v])) return false;
    return true;
  }

  // union-find
  std::vector<std::size_t> parent;
  std::size_t find(std::size_t x)
  {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  }
  void unite(std::size_t a, std::size_t b) { parent[find(a)] = find(b); }

  void assemble()
  {
    // unresolved regions: touching unresolved or pending leaves of one kind
    std::vector<std::size_t> bad;
    for (std::size_t b = 0; b < boxes.size(); ++b)
      if (boxes[b].state == UNRESOLVED || boxes[b].state == PENDING || boxes[b].state == OPEN) bad.push_back(b);
    parent.resize(bad.size());
    std::iota(parent.begin(), parent.end(), std::size_t(0));
    for (std::size_t a = 0; a < bad.size(); ++a)
      for (std::size_t c = a + 1; c < bad.size(); ++c)
        if ((boxes[bad[a]].state == UNRESOLVED) == (boxes[bad[c]].state == UNRESOLVED) &&
            meet(box_intervals(boxes[bad[a]]), box_intervals(boxes[bad[c]])))
          unite(a, c);
    std::vector<long> region_of_box(boxes.size(), -1), region_of_root(bad.size(), -1);
    for (std::size_t a = 0; a < bad.size(); ++a) {
      const std::size_t r = find(a);
      if (region_of_root[r] < 0) {
        region_of_root[r] = long(result.unresolved.size());
        Solver_unresolved<IT> u;
        u.kind = boxes[bad[a]].state == UNRESOLVED ? Box_class::UNKNOWN : Box_class::PENDING;
        u.reason = boxes[bad[a]].reason.empty() ? "box budget exhausted" : boxes[bad[a]].reason;
        u.box = box_intervals(boxes[bad[a]]);
        u.boxes = 0;
        u.rank_deficient = u.reason.compare(0, 8, "singular") == 0;
        result.unresolved.push_back(u);
      }
      Solver_unresolved<IT>& u = result.unresolved[std::size_t(region_of_root[r])];
      if (u.boxes > 0)
        for (std::size_t v = 0; v < n; ++v)
          u.box[v] = O::make((std::min)(O::lower(u.box[v]), boxes[bad[a]].lo[v]), (std::max)(O::upper(u.box[v]), boxes[bad[a]].hi[v]));
      ++u.boxes;
      region_of_box[bad[a]] = region_of_root[r];
    }

    // crossings: merged with their partner across the face; ends of branches otherwise
    const std::size_t N = crossings.size();
    parent.assign(N, 0);
    std::iota(parent.begin(), parent.end(), std::size_t(0));
    std::vector<long> end_region(N, -1);
    std::vector<Curve_end> end_kind(N, Curve_end::CLOSED);
    std::vector<char> suspect(N, 0);
    for (std::size_t x = 0; x < N; ++x) {
      const Crossing& c = crossings[x];
      if (c.dropped) continue;
      const long across = locate_across(c);
      if (across == -2) { end_kind[x] = Curve_end::BOUNDARY; continue; }
      if (across < 0) { suspect[x] = 1; ++result.statistics.unmatched; continue; }
      const Box& o = boxes[std::size_t(across)];
      if (o.state == REGULAR) {
        long partner = -1;
        for (std::size_t y : o.crossings) {
          const Crossing& d = crossings[y];
          if (d.face_variable != c.face_variable || d.upper == c.upper) continue;
          if (inside(c.enclosure, d.uniqueness) || inside(d.enclosure, c.uniqueness)) { partner = long(y); break; }
        }
        if (partner < 0) { suspect[x] = 1; ++result.statistics.unmatched; }
        else if (crossings[std::size_t(partner)].dropped) end_kind[x] = Curve_end::INEQUALITY;  // g changes sign on it
        else unite(x, std::size_t(partner));
      } else if (region_of_box[std::size_t(across)] >= 0) {
        end_kind[x] = Curve_end::UNRESOLVED;
        end_region[x] = region_of_box[std::size_t(across)];
      } else if (o.state == EXCLUDED_BY_INEQUALITY) {
        end_kind[x] = Curve_end::INEQUALITY;
      } else {
        suspect[x] = 1;  // a curve point in a box shown empty: numerically inconsistent
        ++result.statistics.unmatched;
      }
    }
    // the graph: nodes are classes of crossings, edges the arcs
    std::vector<std::vector<std::size_t>> incident(N);
    for (std::size_t a = 0; a < arcs.size(); ++a) {
      incident[find(arcs[a].from)].push_back(a);
      incident[find(arcs[a].to)].push_back(a);
    }
    std::vector<char> node_suspect(N, 0), node_is_end(N, 0);
    std::vector<Curve_end> node_end(N, Curve_end::CLOSED);
    std::vector<long> node_region(N, -1);
    for (std::size_t x = 0; x < N; ++x) {
      const std::size_t r = find(x);
      if (suspect[x]) node_suspect[r] = 1;
      if (end_kind[x] != Curve_end::CLOSED) { node_is_end[r] = 1; node_end[r] = end_kind[x]; node_region[r] = end_region[x]; }
    }
    for (std::size_t r = 0; r < N; ++r) {
      if (find(r) != r) continue;
      const std::size_t expected = node_is_end[r] ? 1 : 2;
      if (incident[r].size() != expected && !node_suspect[r]) node_suspect[r] = 1;
      if (node_suspect[r] && incident[r].size() < 2) node_is_end[r] = 1;
    }
    // walk the branches: from every end first, then the loops
    std::vector<char> used(arcs.size(), 0);
    auto walk = [&](std::size_t start_node, std::size_t first_arc) {
      Solution_curve<IT> curve;
      std::size_t node = start_node, a = first_arc;
      curve.ends[0] = node_is_end[node] ? (node_suspect[node] && node_end[node] == Curve_end::CLOSED ? Curve_end::UNRESOLVED : node_end[node]) : Curve_end::CLOSED;
      curve.end_region[0] = node_region[node];
      if (node_suspect[node]) curve.certified = false;
      while (true) {
        used[a] = 1;
        const Arc& arc = arcs[a];
        const bool forward = find(arc.from) == node;
        const Crossing& s = crossings[forward ? arc.from : arc.to];
        if (curve.points.empty()) curve.points.push_back(s.point);
        if (forward) curve.points.insert(curve.points.end(), arc.samples.begin(), arc.samples.end());
        else curve.points.insert(curve.points.end(), arc.samples.rbegin(), arc.samples.rend());
        const std::size_t other = find(forward ? arc.to : arc.from);
        curve.points.push_back(crossings[forward ? arc.to : arc.from].point);
        const Box& B = boxes[crossing_box[arc.from]];
        curve.boxes.push_back(box_intervals(B));
        if (B.inequality_boundary) curve.on_inequality_boundary = true;
        node = other;
        if (node_suspect[node]) curve.certified = false;
        if (node_is_end[node]) {
          curve.ends[1] = node_suspect[node] && node_end[node] == Curve_end::CLOSED ? Curve_end::UNRESOLVED : node_end[node];
          curve.end_region[1] = node_region[node];
          break;
        }
        std::size_t next = arcs.size();
        for (std::size_t b : incident[node])
          if (!used[b]) { next = b; break; }
        if (next == arcs.size()) {  // back at the start: a loop
          curve.closed = node == start_node;
          if (!curve.closed) curve.certified = false;
          break;
        }
        a = next;
      }
      for (const auto& p : curve.points) curve.max_residual = (std::max)(curve.max_residual, values_at(p).template lpNorm<Eigen::Infinity>());
      result.curves.push_back(std::move(curve));
    };
    for (std::size_t r = 0; r < N; ++r)
      if (find(r) == r && node_is_end[r])
        for (std::size_t a : incident[r])
          if (!used[a]) walk(r, a);
    for (std::size_t a = 0; a < arcs.size(); ++a)
      if (!used[a]) walk(find(arcs[a].from), a);
    // an open piece that never gets farther from an unresolved region than the region's own
    // width (it leaves the region to come back, or is clipped by an inequality next to it) is
    // part of that region: the region grows to hold its boxes
    std::vector<Solution_curve<IT>> kept;
    for (auto& c : result.curves) {
      long region = c.ends[0] == Curve_end::UNRESOLVED ? c.end_region[0] : c.ends[1] == Curve_end::UNRESOLVED ? c.end_region[1] : -1;
      if (region < 0 && !c.closed)  // both ends elsewhere: the nearest region to its first point
        for (std::size_t k = 0; k < result.unresolved.size() && region < 0; ++k) {
          bool near = true;
          for (std::size_t v = 0; v < n; ++v) {
            const double lo = O::lower_double(result.unresolved[k].box[v]), hi = O::upper_double(result.unresolved[k].box[v]);
            if (c.points.front()[v] < lo - (hi - lo) || c.points.front()[v] > hi + (hi - lo)) near = false;
          }
          if (near) region = long(k);
        }
      bool fold = !c.closed && region >= 0 && (c.ends[0] != Curve_end::UNRESOLVED || c.end_region[0] == region) &&
                  (c.ends[1] != Curve_end::UNRESOLVED || c.end_region[1] == region);
      if (fold) {
        Solver_unresolved<IT>& u = result.unresolved[std::size_t(region)];
        for (const auto& p : c.points)
          for (std::size_t v = 0; v < n; ++v) {
            const double lo = O::lower_double(u.box[v]), hi = O::upper_double(u.box[v]), w = hi - lo;
            if (p[v] < lo - w || p[v] > hi + w) fold = false;
          }
        if (fold)
          for (const auto& bx : c.boxes)
            for (std::size_t v = 0; v < n; ++v)
              u.box[v] = O::make((std::min)(O::lower(u.box[v]), O::lower(bx[v])), (std::max)(O::upper(u.box[v]), O::upper(bx[v])));
      }
      if (!fold) kept.push_back(std::move(c));
    }
    result.curves.swap(kept);
    // a stable order: by the first point
    std::sort(result.curves.begin(), result.curves.end(), [](const Solution_curve<IT>& x, const Solution_curve<IT>& y) {
      return x.points.front() < y.points.front();
    });
  }
};

} // namespace internal

/*!
\ingroup PkgRigidIncidenceSolver
\brief The real solution curves of `system` (n - 1 equations in n variables) in `system.box`,
each branch a polyline with certified topology.

What is guaranteed (see the manual): every point of the real solution set in the box lies in a
regular box, on exactly one arc there, or in one of `unresolved`; inside a regular box the
curve is a set of arcs monotone in one variable, joined to their neighbours at certified
crossing points of the box faces, so no component is missed and no two branches are joined
by mistake where `certified` holds. The polyline's crossing points are certified to
`parameters.tolerance`; its other points are Newton points on the curve (`max_residual`).
Inequalities g >= 0 of the system remove the boxes where some g < 0 certainly; a branch that
reaches g = 0 ends there, to `parameters.minimal_width`.

\tparam IT the interval type: `CGAL::Interval_nt<false>` or `CGAL::Gmpfi`
\tparam NT the coefficient type (`CGAL::Gmpq`, an interval type, or `double`)
\throws Input_error if the system does not have exactly one equation fewer than variables, at
least two variables, an identically zero equation, or a finite nonempty box
*/
template <class IT = CGAL::Interval_nt<false>, class NT>
Curve_result<IT> trace_curves(const Polynomial_system<NT>& system_in, const Curve_tracer_parameters& parameters = Curve_tracer_parameters())
{
  Polynomial_system<NT> scaled;  // exact powers of two against coefficients beyond doubles
  const Polynomial_system<NT>& system = internal::scaled_to_unit(system_in, scaled);
  const std::size_t n = system.number_of_variables();
  if (n < 2 || system.number_of_equations() + 1 != n)
    throw Input_error("trace_curves: " + std::to_string(system.number_of_equations()) + " equations in " + std::to_string(n) +
                      " variables; a curve needs one equation fewer than variables (and at least two variables)");
  if (system.box.size() != n) throw Input_error("trace_curves: the box has " + std::to_string(system.box.size()) + " intervals for " + std::to_string(n) + " variables");
  for (std::size_t v = 0; v < n; ++v)
    if (!(system.box[v].first < system.box[v].second) || !std::isfinite(system.box[v].first) || !std::isfinite(system.box[v].second))
      throw Input_error("trace_curves: the box of variable " + (v < system.variable_names.size() ? system.variable_names[v] : std::to_string(v)) +
                        " is not a finite nonempty interval");
  for (std::size_t k = 0; k < system.number_of_equations(); ++k)
    if (system.equations[k].is_zero()) throw Input_error("trace_curves: equation " + std::to_string(k + 1) + " is identically zero");
  // counted as the face solves count (they get the same limit, and a face system is no larger),
  // so that a system accepted here is never refused on a face
  internal::check_dense_storage(system, parameters.maximal_coefficients, 1, 1, "trace_curves");
  internal::Solver_precision_guard<IT> guard(parameters.precision);
  internal::Curve_tracer_run<IT, NT> run(system, parameters);
  run.go();
  return run.result;
}

} // namespace Rigid_incidence
} // namespace CGAL

#endif
