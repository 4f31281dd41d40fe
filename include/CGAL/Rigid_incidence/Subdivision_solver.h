// Copyright (c) 2026 Rigid_incidence contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The certified interval Bernstein subdivision solver (elimination_generically_rigid_3d.txt
// Section 4; decomposition_subdivision_solver.txt Section 3.1): every real root of n
// polynomial equations in n variables in a box, each certified by a Krawczyk test or left in
// an unresolved box with its reason.
//
// Per box: (1) exclusion: some equation's Bernstein coefficients share a strict sign;
// (2) domain reduction: projected-polyhedron clipping of the equations preconditioned by the
// inverse Jacobian at the box centre (so near a simple root each preconditioned equation is
// nearly x_j - x_j*, and the clip converges quadratically), and where that Jacobian is nearly
// singular also by a regularized inverse; (3) certification: the Krawczyk
// operator on a slightly inflated box (so a root on a face is certified in one box) proves
// existence and uniqueness, and interval Newton (Krawczyk contraction) then tightens the
// enclosure to the tolerance; a Krawczyk operator that misses its box excludes it; (4) otherwise split at the midpoint of the widest variable
// (relative to the initial box) by de Casteljau, or stop at the minimal width (unknown).

#ifndef CGAL_RIGID_INCIDENCE_SUBDIVISION_SOLVER_H
#define CGAL_RIGID_INCIDENCE_SUBDIVISION_SOLVER_H

#include <CGAL/Rigid_incidence/Input_error.h>
#include <CGAL/Rigid_incidence/Polynomial_system.h>
#include <CGAL/Rigid_incidence/Solver_result.h>
#include <CGAL/Rigid_incidence/internal/Bernstein_tensor.h>
#include <CGAL/Rigid_incidence/internal/interval_ops.h>

#include <Eigen/Dense>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <functional>
#include <limits>
#include <numeric>
#include <optional>
#include <string>
#include <type_traits>
#include <vector>

namespace CGAL {
namespace Rigid_incidence {

/*!
\ingroup PkgRigidIncidenceSolver
\brief Certified interval Bernstein subdivision solver for square polynomial systems over a box.

\tparam IT the interval type of the arithmetic: `CGAL::Interval_nt<false>` (double, fast) or
`CGAL::Gmpfi` (MPFI: correctly rounded intervals at `parameters().precision` bits).

Each equation is kept as a tensor-product Bernstein array over the variables it involves
only. Every box the solver leaves is in exactly one class of `Box_class`; a root is never
dropped: it is certified, or inside an unknown or pending box.
*/
template <class IT = CGAL::Interval_nt<false>>
class Subdivision_solver
{
  typedef internal::Interval_ops<IT> O;
  typedef typename O::Bound Bound;
  typedef internal::Tensor_shape Shape;
  typedef Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic> Matrix;
  typedef Eigen::Matrix<double, Eigen::Dynamic, 1> Vector;

public:
  typedef IT Interval;  ///< the interval type

  /// A solver with the given parameters.
  explicit Subdivision_solver(const Subdivision_solver_parameters& p = Subdivision_solver_parameters()) : p_(p) {}
  /// The parameters.
  const Subdivision_solver_parameters& parameters() const { return p_; }

  /*!
  Every real root of `system` (n equations in n variables) in `system.box`.
  \tparam NT the coefficient type: `CGAL::Gmpq` (exact), `CGAL::Interval_nt<false>`,
  `CGAL::Gmpfi` or `double` (taken as exact).
  \throws Input_error if the system is not square, has no variable, has an identically zero
  equation, or the box is not a nonempty finite box with one interval per variable.
  */
  template <class NT>
  Solver_result<IT> solve(const Polynomial_system<NT>& system_in) const
  {
    check(system_in);
    Polynomial_system<NT> scaled;
    const Polynomial_system<NT>& system = internal::scaled_to_unit(system_in, scaled);
    internal::Solver_precision_guard<IT> guard(p_.precision);
    Run run(*this, system);
    run.go();
    return run.result;
  }

  /*!
  Proves that `system` has exactly one root near `box` (in `box` widened by 10% of its width
  and a few units in the last place, around a Newton estimate) and tightens its enclosure to
  `parameters().tolerance`, like a root the solver finds; empty if the Krawczyk test fails there
  or the root lies outside `system.box` (the inequalities are not looked at). For a root known approximately, or known in a wide
  enclosure (a root assembled from the blocks of a `Solution_plan`).
  \throws Input_error as `solve()`, or if `box` does not have one interval per variable.
  */
  template <class NT>
  std::optional<Solver_root<IT>> refine(const Polynomial_system<NT>& system_in, const std::vector<IT>& box) const
  {
    check(system_in);
    Polynomial_system<NT> scaled;
    const Polynomial_system<NT>& system = internal::scaled_to_unit(system_in, scaled);
    if (box.size() != system.number_of_variables())
      throw Input_error("Subdivision_solver::refine: the box has " + std::to_string(box.size()) + " intervals for " +
                        std::to_string(system.number_of_variables()) + " variables");
    internal::Solver_precision_guard<IT> guard(p_.precision);
    Run run(*this, system);
    std::vector<Bound> lo, hi;
    for (const IT& b : box) { lo.push_back(O::lower(b)); hi.push_back(O::upper(b)); }
    typename Run::Node_type x = run.make_node(lo, hi, 0);
    if (!run.certify(x) || run.found.empty()) return std::nullopt;
    return run.found.back().root;
  }

private:
  struct Equation
  {
    Shape shape;
    std::vector<IT> power;               // power-basis coefficients, dense over `shape`
    std::vector<double> power_d;         // rounded to double (estimates, fast mode)
    std::vector<Shape> dshape;           // per local variable: shape of the derivative
    std::vector<std::vector<IT>> dpower;  // per local variable: the derivative's power coefficients
    std::vector<std::vector<double>> dpower_d;
    // per pair of local variables (k, l): the second derivative's shape and power coefficients
    // (empty: identically zero), for the mean-value form of the Jacobian
    std::vector<std::vector<Shape>> ddshape;
    std::vector<std::vector<std::vector<IT>>> ddpower;
  };

  struct Node
  {
    std::vector<Bound> lo, hi;
    std::vector<std::vector<IT>> b;      // per equation, Bernstein array on [lo, hi]
    std::size_t depth = 0;
    bool no_shear = false;               // a solve in sheared coordinates failed on it or an ancestor
    bool stale = false;                  // b not made by the split: converted afresh when processed
  };

  struct Found
  {
    Solver_root<IT> root;
    std::vector<Bound> klo, khi;         // the box in which the root is proved unique
  };

  template <class NT>
  void check(const Polynomial_system<NT>& s) const
  {
    const std::size_t n = s.number_of_variables();
    if (n == 0) throw Input_error("Subdivision_solver: the system has no variable");
    if (s.number_of_equations() != n)
      throw Input_error("Subdivision_solver: " + std::to_string(s.number_of_equations()) + " equations in " + std::to_string(n) +
                        " variables; the solver takes square systems (see Solution_plan for others)");
    if (s.box.size() != n)
      throw Input_error("Subdivision_solver: the box has " + std::to_string(s.box.size()) + " intervals for " + std::to_string(n) + " variables");
    for (std::size_t j = 0; j < n; ++j) {
      const auto& b = s.box[j];
      if (!std::isfinite(b.first) || !std::isfinite(b.second) || !(b.first < b.second))
        throw Input_error("Subdivision_solver: the interval of variable " + name(s, j) + " is not a nonempty finite interval [" +
                          std::to_string(b.first) + ", " + std::to_string(b.second) + "]");
    }
    for (std::size_t i = 0; i < s.inequalities.size(); ++i)
      if (s.inequalities[i].number_of_variables() != n)
        throw Input_error("Subdivision_solver: inequality " + std::to_string(i) + " is in " +
                          std::to_string(s.inequalities[i].number_of_variables()) + " variables, the system in " + std::to_string(n));
    // the equations' dense arrays, their k first and k^2 second derivatives
    internal::check_dense_storage(s, p_.maximal_coefficients, 1, 1, "Subdivision_solver");
    for (std::size_t i = 0; i < n; ++i) {
      if (s.equations[i].number_of_variables() != n)
        throw Input_error("Subdivision_solver: equation " + std::to_string(i) + " is in " +
                          std::to_string(s.equations[i].number_of_variables()) + " variables, the system in " + std::to_string(n));
      if (s.equations[i].is_zero())
        throw Input_error("Subdivision_solver: equation " + std::to_string(i) +
                          (i < s.labels.size() && !s.labels[i].empty() ? " (" + s.labels[i] + ")" : std::string()) +
                          " is identically zero: the solution set is not finite");
    }
  }
  template <class NT> static std::string name(const Polynomial_system<NT>& s, std::size_t j)
  {
    return j < s.variable_names.size() && !s.variable_names[j].empty() ? s.variable_names[j] : "x" + std::to_string(j);
  }

  // One solve: the state shared by the steps.
  struct Run
  {
    typedef Node Node_type;
    const Subdivision_solver_parameters& P;
    std::size_t n;
    std::vector<Equation> eq;
    std::vector<Equation> ineq;           // g_j >= 0
    std::vector<Bound> dlo, dhi;          // the search box
    std::vector<double> initial_width;    // per variable
    double min_width;
    double singular_width;
    double last_contraction = 0;          // ||I - Y J(X)|| of the last Krawczyk test
    bool certify_excluded = false;        // the last certify() proved its node root-free
    std::size_t wide_tries = 0, wide_hits = 0;  // Krawczyk tests on wide boxes, and those that settled the box
    bool ill_conditioned = false;         // the last reduce() met singular values more than 100 times apart
    bool wide_coefficients = false;       // some coefficient is wider than 1e-9 of its equation's largest
    Shape full;                           // all variables, the highest degree of each
    bool precondition;
    std::vector<internal::Embedding<IT>> embedding;  // per equation: its array over `full`
    // work buffers of reduce(), kept between boxes
    internal::Clip_workspace clip_work;
    std::vector<std::vector<IT>> F;
    std::vector<IT> g, embed_scratch;
    std::vector<std::vector<double>> F_nl, F_hi;
    std::vector<double> g_nl, g_hi;
    mutable std::vector<double> eval_x, eval_work;  // of evaluate_d()
    std::vector<Found> found;
    std::vector<Node> unknown_nodes;
    std::vector<std::string> unknown_reason;
    std::vector<char> unknown_rank_deficient;
    std::vector<Node> pending_nodes;
    std::string pending_reason;
    std::size_t next_curve_check = 16;  // unknown boxes before the next look for a curve
    Solver_result<IT> result;
    std::chrono::steady_clock::time_point start;
    std::function<void(const std::vector<Bound>&, const std::vector<Bound>&, Solver_result<IT>&)> retry;
    bool same_precision_retry = false;    // `retry` is at the working precision

    template <class NT>
    Run(const Subdivision_solver& s, const Polynomial_system<NT>& sys) : P(s.p_), n(sys.number_of_variables())
    {
      for (const auto& f : sys.equations) eq.push_back(make_equation(f));
      for (const auto& g : sys.inequalities) ineq.push_back(make_equation(g));
      for (const auto& e : eq) {
        double big = 0, wide = 0;
        for (const IT& c : e.power) {
          big = (std::max)(big, (std::max)(std::abs(O::lower_double(c)), std::abs(O::upper_double(c))));
          wide = (std::max)(wide, O::upper_double(c) - O::lower_double(c));
        }
        if (wide > 1e-9 * big) wide_coefficients = true;
      }
      std::vector<unsigned> dmax(n, 0);
      for (const auto& e : eq)
        for (std::size_t k = 0; k < e.shape.variables.size(); ++k) dmax[e.shape.variables[k]] = (std::max)(dmax[e.shape.variables[k]], e.shape.degrees[k]);
      std::vector<std::size_t> all(n);
      std::iota(all.begin(), all.end(), std::size_t(0));
      full.set(all, dmax);
      // the dense preconditioned arrays cost full.size per equation: only when small
      precondition = P.preconditioning && P.domain_reduction && full.size * n <= 40000;
      if (precondition)
        for (const auto& e : eq) embedding.emplace_back(e.shape, full);
      double widest = 0;
      for (std::size_t j = 0; j < n; ++j) {
        dlo.push_back(O::bound_from_double(sys.box[j].first));
        dhi.push_back(O::bound_from_double(sys.box[j].second));
        initial_width.push_back(sys.box[j].second - sys.box[j].first);
        widest = (std::max)(widest, initial_width.back());
      }
      // the default: 1e-9 in double, and finer with the precision (its square root, as the
      // resolvable separation of two close roots): 1e-9 of the box at 200 bits would keep two
      // roots 1e-14 apart in one box however fine the arithmetic
      min_width = P.minimal_width > 0 ? P.minimal_width : 1e-9 * widest * std::ldexp(1.0, -int((std::max)(O::bits(), 53u) - 53) / 2);
      singular_width = P.singular_width > 0 ? P.singular_width : P.singular_width < 0 ? 0 : 1e-6 * widest;
      singular_width = (std::max)(singular_width, min_width);
      if constexpr (std::is_same<NT, CGAL::Gmpq>::value || std::is_same<NT, double>::value) {
#ifdef CGAL_USE_MPFI
        const unsigned bits = (std::max)(2 * O::bits(), 106u);
        if (!P.fast && P.maximal_precision > 0 && (std::max)(P.maximal_precision, 2 * P.precision) >= bits) {
          // solve a region again with CGAL::Gmpfi at twice the precision
          retry = [&sys, this, bits](const std::vector<Bound>& lo, const std::vector<Bound>& hi, Solver_result<IT>& out) {
            const Polynomial_system<NT> sub = region_system(sys, lo, hi);
            Subdivision_solver_parameters q = P;
            q.precision = bits;
            if (P.maximal_precision < 2 * bits) q.maximal_precision = 0;  // one doubling only, unless asked for more
            q.minimal_width = min_width / 4;
            q.singular_width = -1;  // down to the minimal width: separate close roots
            q.maximal_boxes = P.maximal_boxes / 8 + 1;
            Solver_result<CGAL::Gmpfi> r = Subdivision_solver<CGAL::Gmpfi>(q).solve(sub);
            for (const auto& x : r.roots) {
              Solver_root<IT> y;
              for (const auto& e : x.enclosure) y.enclosure.push_back(O::from(e));
              y.approximation = x.approximation;
              y.certified = x.certified;
              y.on_boundary = x.on_boundary;
              y.residual = x.residual;
              for (const auto& e : x.uniqueness_box) y.uniqueness_box.push_back(O::from(e));
              out.roots.push_back(y);
            }
            for (const auto& x : r.unresolved) {
              Solver_unresolved<IT> y;
              y.kind = x.kind;
              y.reason = x.reason.find(" bits)") == std::string::npos ? x.reason + " (at " + std::to_string(bits) + " bits)" : x.reason;
              for (const auto& e : x.box) y.box.push_back(O::from(e));
              y.boxes = x.boxes;
              y.rank_deficient = x.rank_deficient;
              out.unresolved.push_back(y);
            }
            out.statistics.boxes += r.statistics.boxes;
            out.statistics.krawczyk_tests += r.statistics.krawczyk_tests;
          };
        }
#endif
      }
      if (!retry && !P.fast && singular_width > min_width) {
        // no higher precision to try (interval coefficients, or the retry itself): a small
        // cluster stopped as a possible multiple root may be simple roots closer than the
        // singular width, so solve it again at this precision down to the minimal width
        same_precision_retry = true;
        retry = [&sys, this](const std::vector<Bound>& lo, const std::vector<Bound>& hi, Solver_result<IT>& out) {
          const Polynomial_system<NT> sub = region_system(sys, lo, hi);
          Subdivision_solver_parameters q = P;
          q.maximal_precision = 0;
          q.minimal_width = min_width;
          q.singular_width = -1;
          q.maximal_boxes = P.maximal_boxes / 8 + 1;
          out = Subdivision_solver<IT>(q).solve(sub);
        };
      }
    }

    // The system on a region of the search box (for a retry): its double box contains the
    // region (rounded outward) and stays inside the search box.
    template <class NT>
    Polynomial_system<NT> region_system(const Polynomial_system<NT>& sys, const std::vector<Bound>& lo, const std::vector<Bound>& hi) const
    {
      Polynomial_system<NT> sub = sys;
      for (std::size_t j = 0; j < n; ++j) {
        sub.box[j] = {std::nextafter(O::to_double(lo[j]), -std::numeric_limits<double>::infinity()),
                      std::nextafter(O::to_double(hi[j]), std::numeric_limits<double>::infinity())};
        sub.box[j].first = (std::max)(sub.box[j].first, O::to_double(dlo[j]));
        sub.box[j].second = (std::min)(sub.box[j].second, O::to_double(dhi[j]));
      }
      return sub;
    }

    template <class NT> Equation make_equation(const Sparse_polynomial<NT>& f)
    {
      Equation e;
      const std::vector<unsigned> all = f.degrees();  // (one pass over the terms)
      std::vector<std::size_t> vars;
      std::vector<unsigned> degs;
      for (std::size_t v = 0; v < all.size(); ++v)
        if (all[v] > 0) { vars.push_back(v); degs.push_back(all[v]); }
      e.shape.set(vars, degs);
      e.power.assign(e.shape.size, IT(0));
      for (const auto& t : f.terms()) {
        std::size_t idx = 0;
        for (std::size_t k = 0; k < vars.size(); ++k) idx += t.first[vars[k]] * e.shape.strides[k];
        e.power[idx] = e.power[idx] + O::from(t.second);
      }
      for (const IT& c : e.power) e.power_d.push_back(CGAL::to_double(c));
      for (std::size_t k = 0; k < vars.size(); ++k) {
        Shape ds;
        std::vector<IT> dpi;
        std::vector<double> dp;
        differentiate(e.shape, e.power, k, ds, dpi);
        differentiate(e.shape, e.power_d, k, ds, dp);
        e.dshape.push_back(ds);
        e.dpower.push_back(dpi);
        e.dpower_d.push_back(dp);
      }
      e.ddshape.assign(vars.size(), std::vector<Shape>(vars.size()));
      e.ddpower.assign(vars.size(), std::vector<std::vector<IT>>(vars.size()));
      for (std::size_t k = 0; k < vars.size(); ++k)
        for (std::size_t l = 0; l < vars.size(); ++l) differentiate(e.dshape[k], e.dpower[k], l, e.ddshape[k][l], e.ddpower[k][l]);
      return e;
    }

    // The partial derivative along local axis k of a power-basis array of shape s (coefficients
    // of type T: intervals, or their double estimates): shape ds (one degree lower along k); an
    // axis of degree 0 gives the zero polynomial (empty da).
    template <class T>
    static void differentiate(const Shape& s, const std::vector<T>& a, std::size_t k, Shape& ds, std::vector<T>& da)
    {
      da.clear();
      if (s.degrees[k] == 0) return;
      std::vector<unsigned> dd = s.degrees;
      dd[k] -= 1;
      ds.set(s.variables, dd);
      da.resize(ds.size);
      // index = (outer * (d + 1) + i) * st + inner in s, (outer * d + i - 1) * st + inner in ds
      const std::size_t st = s.strides[k], d = s.degrees[k], outer = s.size / (st * (d + 1));
      for (std::size_t o = 0; o < outer; ++o)
        for (std::size_t i = 1; i <= d; ++i) {
          const T f = T(int(i));
          const T* from = a.data() + (o * (d + 1) + i) * st;
          T* to = da.data() + (o * d + i - 1) * st;
          for (std::size_t in = 0; in < st; ++in) to[in] = f * from[in];
        }
    }

    // ---- small helpers --------------------------------------------------------------
    static IT pt(const Bound& b) { return O::point(b); }
    static IT width_interval(const Bound& lo, const Bound& hi) { return pt(hi) - pt(lo); }
    static Bound midpoint(const Bound& lo, const Bound& hi)
    {
      Bound m = O::lower((pt(lo) + pt(hi)) / 2);
      if (!(m > lo) || !(m < hi)) m = O::upper((pt(lo) + pt(hi)) / 2);
      return m;
    }
    double width(const Node& x, std::size_t j) const { return O::upper_double(width_interval(x.lo[j], x.hi[j])); }
    std::vector<double> center_d(const std::vector<Bound>& lo, const std::vector<Bound>& hi) const
    {
      std::vector<double> c(n);
      for (std::size_t j = 0; j < n; ++j) c[j] = 0.5 * O::to_double(lo[j]) + 0.5 * O::to_double(hi[j]);
      return c;
    }
    double seconds() const { return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(); }

    std::vector<IT> bernstein(const Equation& e, const std::vector<Bound>& lo, const std::vector<Bound>& hi) const
    {
      std::vector<IT> l, w;
      for (std::size_t v : e.shape.variables) { l.push_back(pt(lo[v])); w.push_back(width_interval(lo[v], hi[v])); }
      return internal::to_bernstein(e.shape, e.power, l, w);
    }
    Node make_node(const std::vector<Bound>& lo, const std::vector<Bound>& hi, std::size_t depth) const
    {
      Node x;
      x.lo = lo;
      x.hi = hi;
      x.depth = depth;
      for (const auto& e : eq) x.b.push_back(bernstein(e, lo, hi));
      return x;
    }

    // f and the Jacobian at a point, in double.
    void evaluate_d(const std::vector<double>& x, Vector& f, Matrix& J) const
    {
      f.resize(n);
      J.setZero(n, n);
      std::vector<double>& xl = eval_x;
      for (std::size_t i = 0; i < n; ++i) {
        const Equation& e = eq[i];
        xl.clear();
        for (std::size_t v : e.shape.variables) xl.push_back(x[v]);
        f[i] = internal::horner(e.shape, e.power_d, xl, eval_work);
        for (std::size_t k = 0; k < e.shape.variables.size(); ++k)
          J(i, e.shape.variables[k]) = internal::horner(e.dshape[k], e.dpower_d[k], xl, eval_work);
      }
    }

    // ---- the main loop ---------------------------------------------------------------
    void go()
    {
      start = std::chrono::steady_clock::now();
      result.fast = P.fast;
      std::vector<Node> stack;
      stack.push_back(make_node(dlo, dhi, 0));
      while (!stack.empty()) {
        const bool interrupted = P.interrupt && P.interrupt->load(std::memory_order_relaxed);
        if (result.statistics.boxes >= P.maximal_boxes || (P.maximal_seconds > 0 && seconds() > P.maximal_seconds) || interrupted) {
          pending_reason = interrupted ? "interrupted"
                           : result.statistics.boxes >= P.maximal_boxes ? "box budget exhausted" : "time budget exhausted";
          for (auto& x : stack) pending_nodes.push_back(std::move(x));
          stack.clear();
          break;
        }
        Node x = std::move(stack.back());
        stack.pop_back();
        ++result.statistics.boxes;
        result.statistics.maximal_depth = (std::max)(result.statistics.maximal_depth, x.depth);
        process(x, stack);
        if (P.positive_dimensional_evidence > 0 && unknown_nodes.size() >= next_curve_check) {
          next_curve_check *= 2;
          if (!curve_evidence().empty()) {
            pending_reason = "stopped: positive-dimensional solution set";
            for (auto& y : stack) pending_nodes.push_back(std::move(y));
            stack.clear();
          }
        }
      }
      finish();
    }

    bool excluded(const Node& x) const
    {
      for (const auto& b : x.b) if (internal::strict_sign(b)) return true;
      return false;
    }

    // Some equation's coefficient enclosures are wide compared with the coefficients.
    bool blurred(const Node& x) const
    {
      for (const auto& b : x.b) {
        double big = 0, wide = 0;
        for (const IT& c : b) {
          double l = O::lower_double(c), h = O::upper_double(c);
          big = (std::max)(big, (std::max)(std::abs(l), std::abs(h)));
          wide = (std::max)(wide, h - l);
        }
        if (wide > 1e-6 * big) return true;
      }
      return false;
    }

    bool inside_found(const Node& x) const
    {
      for (const auto& f : found) {
        bool in = true;
        for (std::size_t j = 0; j < n && in; ++j) in = !(x.lo[j] < f.klo[j]) && !(f.khi[j] < x.hi[j]);
        if (in) return true;
      }
      return false;
    }

    // Some inequality g_j >= 0 fails on the whole box (its Bernstein coefficients are all < 0).
    bool violates_inequality(const std::vector<Bound>& lo, const std::vector<Bound>& hi) const
    {
      for (const auto& g : ineq) {
        std::vector<IT> b = bernstein(g, lo, hi);
        bool neg = true;
        for (const IT& c : b) if (!(O::upper(c) < 0)) { neg = false; break; }
        if (neg) return true;
      }
      return false;
    }

    void process(Node& x, std::vector<Node>& stack)
    {
      if (!ineq.empty() && violates_inequality(x.lo, x.hi)) { ++result.statistics.excluded_by_inequality; return; }
      const bool fresh = x.stale;
      if (x.stale) {
        x.b.resize(n);
        for (std::size_t i = 0; i < n; ++i) x.b[i] = bernstein(eq[i], x.lo, x.hi);
        x.stale = false;
      }
      bool converging = false;
      for (int round = 0; round < 32; ++round) {
        if (excluded(x)) { ++result.statistics.excluded; return; }
        if (round == 0 && x.depth > 0 && !fresh && blurred(x)) {
          // the subdivided arrays carry the rounding of every level above: convert the
          // equations afresh on this box, which is exact up to one rounding per operation
          // (with wide coefficients too, where it is not the rounding: Jansen's linkage took
          // 7.5 times as many boxes without it)
          for (std::size_t i = 0; i < n; ++i) x.b[i] = bernstein(eq[i], x.lo, x.hi);
          if (excluded(x)) { ++result.statistics.excluded; return; }
        }
        if (!P.domain_reduction) break;
        double ratio = 1;
        if (!reduce(x, ratio)) { ++result.statistics.excluded; return; }
        if (ratio < 0.5) converging = true;
        if (ratio > P.reduction_ratio) break;  // weak contraction: split instead
      }
      if (!found.empty() && inside_found(x)) return;  // its only possible root is known
      double rel = 0;
      bool small = true;
      for (std::size_t j = 0; j < n; ++j) {
        double w = width(x, j);
        rel = (std::max)(rel, w / initial_width[j]);
        if (w > min_width) small = false;
      }
      if (P.oriented_boxes && !P.fast && ill_conditioned && !x.no_shear && precondition && ineq.empty() && !wide_coefficients && !small && rel <= 1.0 / 16 &&
          (result.statistics.oriented_solves < 8 || 2 * result.statistics.oriented_fallbacks < result.statistics.oriented_solves)) {
        // (given up after 8 tries once half of them fail: along a curve of solutions, or at a
        // multiple root, every sheared solve leaves boxes unresolved)
        if (sheared_solve(x)) return;
        x.no_shear = true;  // and its children: subdivided as usual
      }
      // Without the preconditioned clipping (a system too large for its dense arrays) nothing
      // converges, and a box 1/16 as wide in each of n variables is 16^-n of the volume: so
      // the test is tried on wider boxes too (a face system of the curve tracer in 11
      // variables, on a small box where it is nearly linear, then takes a box or two instead
      // of thousands), as long as it certifies or excludes at least 1 box in 8 after 32 tries
      // (on most random systems in 10 to 30 variables over [-2, 2]^n it does not, and trying
      // it on every box made them slower: 1.4 times to finish in 10 variables, 2.6 to 26 times
      // fewer boxes in a 10 s budget in 12 to 30).
      const bool wide = !(converging || rel <= 1.0 / 16 || small);
      if (!wide || (!precondition && !P.fast && (wide_tries < 32 || 8 * wide_hits >= wide_tries))) {
        if (wide) ++wide_tries;
        last_contraction = 0;
        bool below = true;
        for (std::size_t j = 0; j < n && below; ++j) below = width(x, j) <= singular_width;
        if (P.fast ? polish(x) : certify(x, !small && !below)) { wide_hits += wide; return; }
        if (!P.fast && certify_excluded) { wide_hits += wide; ++result.statistics.excluded; return; }
        // a box this small on which the Jacobian may be singular (the Krawczyk operator does
        // not contract): a multiple root, or a point of a solution curve; deeper subdivision
        // would only multiply the boxes
        if (!P.fast && last_contraction >= 1 && below) { make_unknown(x, small, true); return; }
      }
      // the variable to split
      std::size_t best = n;
      double score = -1;
      Vector fc;
      Matrix Jc;
      if (P.split == Split_strategy::SMEAR) evaluate_d(center_d(x.lo, x.hi), fc, Jc);
      for (std::size_t k = 0; k < n; ++k) {
        std::size_t j = P.split == Split_strategy::ROUND_ROBIN ? (x.depth + k) % n : k;
        double w = width(x, j);
        if (w <= min_width || !O::splittable(x.lo[j], x.hi[j])) continue;
        double s = w / initial_width[j];
        if (P.split == Split_strategy::SMEAR) {
          double m = 0;  // relative to the equation's largest derivative: the equations' scales do not matter
          for (std::size_t i = 0; i < n; ++i) {
            double row = Jc.row(Eigen::Index(i)).cwiseAbs().maxCoeff();
            if (row > 0) m = (std::max)(m, std::abs(Jc(Eigen::Index(i), Eigen::Index(j))) / row);
          }
          // floored: a variable the centre's derivatives miss (a symmetric box, a product
          // of factors) is still split once it is 10 times wider than the others
          s = (std::max)(m, 0.1) * w / initial_width[j];
        }
        if (P.split == Split_strategy::ROUND_ROBIN) { best = j; break; }
        if (s > score) { score = s; best = j; }
      }
      if (best == n) { make_unknown(x, small); return; }
      Node l, r;
      split_node(x, best, l, r);
      ++result.statistics.splits;
      stack.push_back(std::move(r));
      stack.push_back(std::move(l));
    }

    // ---- oriented boxes -----------------------------------------------------------------
    // Near an ill-conditioned root, or a near miss (a point where every equation nearly
    // vanishes and the Jacobian is nearly singular), the points where all the equations are
    // small form a thin tube along the Jacobian's near-null direction v. An axis-aligned box
    // around a piece of that tube is wide in every variable v moves, and the combination of
    // the equations that the smallest singular value governs varies over the whole box by its
    // curvature times the squared width: the box is excluded only once it is about
    // sigma_min / curvature wide, so plain subdivision walks the tube in thousands of tiny
    // boxes (1200 to 1800 around each of the Stewart-Gough platform's ill-conditioned roots).
    // In the sheared coordinates
    //   x_j = c_j + s_j y_j + g_j y_p (j != p),   x_p = c_p + s_p y_p,
    // with p the variable v moves most and g_j = s_j v_j / v_p, the tube follows the y_p axis:
    // the clipping shrinks the other y_j to a thin slab around it, over which that combination
    // varies little, and long pieces of the tube go at once. The equations are composed with
    // the map (each y_j keeps x_j's degree, y_p gets the total degree), the parallelepiped of
    // y that covers the box is solved by a solver of its own (without oriented boxes, at most
    // 256 boxes: the Stewart-Gough platform's 162 sheared solves take 1 to 111), and its roots
    // that meet the box are certified again in x. Returns false, having recorded at most some
    // of the box's roots, when the sheared solve leaves anything unresolved (a root so
    // ill-conditioned that the sheared system's rounded coefficients blur it) or a root
    // cannot be certified in x: the box is then subdivided as usual.
    bool sheared_solve(const Node& x)
    {
      std::vector<double> c = center_d(x.lo, x.hi), s(n), g(n, 0.0);
      for (std::size_t j = 0; j < n; ++j) {
        s[j] = width(x, j);
        if (!(s[j] > 0) || !std::isfinite(s[j])) return false;
      }
      // the Jacobian scaled by the widths, over the variables in which the box is not already
      // thin (a thin variable's column is small, which is not a tube through the box)
      const double widest = *std::max_element(s.begin(), s.end());
      std::vector<std::size_t> wide;
      for (std::size_t j = 0; j < n; ++j) if (s[j] >= 1e-3 * widest) wide.push_back(j);
      if (wide.size() < 2) return false;
      Vector f;
      Matrix J;
      evaluate_d(c, f, J);
      Matrix Jw(Eigen::Index(n), Eigen::Index(wide.size()));
      for (std::size_t k = 0; k < wide.size(); ++k) Jw.col(Eigen::Index(k)) = J.col(Eigen::Index(wide[k])) * s[wide[k]];
      if (!Jw.allFinite()) return false;
      Eigen::JacobiSVD<Matrix> svd(Jw, Eigen::ComputeFullV);
      const Vector& sv = svd.singularValues();
      const Eigen::Index m = Eigen::Index(wide.size());
      if (!(sv[m - 1] < 0.01 * sv[0])) return false;
      std::vector<double> v(n, 0.0);
      for (std::size_t k = 0; k < wide.size(); ++k) v[wide[k]] = svd.matrixV()(Eigen::Index(k), m - 1);
      std::size_t p = 0;
      for (std::size_t j = 1; j < n; ++j) if (std::abs(v[j]) > std::abs(v[p])) p = j;
      for (std::size_t j = 0; j < n; ++j) if (j != p) g[j] = s[j] * v[j] / v[p];
      // the doubles c, s, g define the map exactly; the y-box covers the node (interval
      // arithmetic, rounded outward)
      std::vector<IT> X(n), Y(n);
      for (std::size_t j = 0; j < n; ++j) X[j] = O::make(x.lo[j], x.hi[j]);
      Y[p] = (X[p] - IT(c[p])) / IT(s[p]);
      for (std::size_t j = 0; j < n; ++j) if (j != p) Y[j] = (X[j] - IT(c[j]) - IT(g[j]) * Y[p]) / IT(s[j]);
      Polynomial_system<IT> sys;
      for (std::size_t j = 0; j < n; ++j) {
        sys.variable_names.push_back("y" + std::to_string(j));
        sys.box.push_back({O::lower_double(Y[j]), O::upper_double(Y[j])});
      }
      for (const Equation& e : eq) {
        std::optional<Sparse_polynomial<IT>> h = sheared(e, c, s, g, p);
        if (!h) return false;
        sys.equations.push_back(std::move(*h));
      }
      Subdivision_solver_parameters q = P;
      q.oriented_boxes = false;
      q.maximal_boxes = (std::min)(std::size_t(256), P.maximal_boxes - (std::min)(P.maximal_boxes, result.statistics.boxes));
      if (q.maximal_boxes == 0) return false;
      if (P.maximal_seconds > 0) {
        q.maximal_seconds = P.maximal_seconds - seconds();
        if (!(q.maximal_seconds > 0)) return false;
      }
      ++result.statistics.oriented_solves;
      Solver_result<IT> r;
      try {
        r = Subdivision_solver<IT>(q).solve(sys);
      } catch (const Input_error&) {
        // the sheared arrays are larger than the node's (y_p of the total degree in every
        // equation): beyond maximal_coefficients, subdivide as usual
        ++result.statistics.oriented_fallbacks;
        return false;
      }
      Solver_statistics& st = result.statistics;
      st.boxes += r.statistics.boxes;
      st.krawczyk_tests += r.statistics.krawczyk_tests;
      st.excluded += r.statistics.excluded;
      st.splits += r.statistics.splits;
      st.reductions += r.statistics.reductions;
      st.certified_boxes += r.statistics.certified_boxes;
      st.maximal_depth = (std::max)(st.maximal_depth, x.depth + r.statistics.maximal_depth);
      if (!r.unresolved.empty()) { ++result.statistics.oriented_fallbacks; return false; }
      for (const auto& root : r.roots) {
        std::vector<IT> Z(n);
        const IT& yp = root.enclosure[p];
        bool meets = true;
        for (std::size_t j = 0; j < n && meets; ++j) {
          Z[j] = j == p ? IT(c[p]) + IT(s[p]) * yp : IT(c[j]) + IT(s[j]) * root.enclosure[j] + IT(g[j]) * yp;
          meets = !(O::upper(Z[j]) < x.lo[j]) && !(x.hi[j] < O::lower(Z[j]));
        }
        if (!meets) continue;  // a root of the parallelepiped outside the node: another node's
        Node z = make_node(lower_of(Z), upper_of(Z), x.depth);
        if (!certify(z)) { ++result.statistics.oriented_fallbacks; return false; }
      }
      return true;
    }

    // The equation composed with the shear of sheared_solve(): each term's factors
    // (c_j + s_j y_j + g_j y_p)^a = sum a! / (a0! a1! a2!) c_j^a0 (s_j y_j)^a1 (g_j y_p)^a2
    // multiplied out in interval arithmetic. Empty above total degree 30, where a multinomial
    // coefficient as a double may no longer be exact.
    std::optional<Sparse_polynomial<IT>> sheared(const Equation& e, const std::vector<double>& c, const std::vector<double>& s,
                                                 const std::vector<double>& g, std::size_t p) const
    {
      const Shape& sh = e.shape;
      const std::size_t m = sh.variables.size();
      unsigned total = 0, top = 0;
      std::vector<unsigned> idx(m);
      for (std::size_t a = 0; a < sh.size; ++a) {
        if (internal::certainly_zero(e.power[a])) continue;
        unsigned t = 0;
        for (std::size_t k = 0; k < m; ++k) t += unsigned((a / sh.strides[k]) % (sh.degrees[k] + 1));
        total = (std::max)(total, t);
      }
      if (total > 30) return std::nullopt;
      for (unsigned d : sh.degrees) top = (std::max)(top, d);
      // the target: x's variables and y_p; y_p of the total degree
      std::vector<std::size_t> tv = sh.variables;
      if (sh.local(p) == std::size_t(-1)) tv.insert(std::lower_bound(tv.begin(), tv.end(), p), p);
      std::vector<unsigned> td;
      for (std::size_t v : tv) td.push_back(v == p ? total : sh.degrees[sh.local(v)]);
      Shape ts;
      ts.set(tv, td);
      const std::size_t tp = ts.local(p);
      std::vector<IT> G(ts.size, IT(0));
      // powers of c_j, s_j, g_j
      std::vector<std::vector<IT>> cp(m), sp(m), gp(m);
      for (std::size_t k = 0; k < m; ++k) {
        const std::size_t j = sh.variables[k];
        cp[k].push_back(IT(1)); sp[k].push_back(IT(1)); gp[k].push_back(IT(1));
        for (unsigned d = 1; d <= top; ++d) {
          cp[k].push_back(cp[k].back() * IT(c[j]));
          sp[k].push_back(sp[k].back() * IT(s[j]));
          gp[k].push_back(gp[k].back() * IT(g[j]));
        }
      }
      std::vector<std::size_t> tk(m);
      for (std::size_t k = 0; k < m; ++k) tk[k] = ts.local(sh.variables[k]);
      std::function<void(std::size_t, const IT&, std::size_t, unsigned)> expand = [&](std::size_t k, const IT& coef, std::size_t at,
                                                                                      unsigned pdeg) {
        if (k == m) { G[at + pdeg * ts.strides[tp]] = G[at + pdeg * ts.strides[tp]] + coef; return; }
        const unsigned a = idx[k];
        if (sh.variables[k] == p) {
          for (unsigned a2 = 0; a2 <= a; ++a2)
            expand(k + 1, coef * internal::binomial_enclosure<IT>(a, a2) * cp[k][a - a2] * sp[k][a2], at, pdeg + a2);
          return;
        }
        for (unsigned a1 = 0; a1 <= a; ++a1)
          for (unsigned a2 = 0; a1 + a2 <= a; ++a2) {
            if (a2 > 0 && g[sh.variables[k]] == 0) break;
            expand(k + 1, coef * internal::binomial_enclosure<IT>(a, a1) * internal::binomial_enclosure<IT>(a - a1, a2) * cp[k][a - a1 - a2] * sp[k][a1] * gp[k][a2],
                   at + a1 * ts.strides[tk[k]], pdeg + a2);
          }
      };
      for (std::size_t a = 0; a < sh.size; ++a) {
        if (internal::certainly_zero(e.power[a])) continue;
        for (std::size_t k = 0; k < m; ++k) idx[k] = unsigned((a / sh.strides[k]) % (sh.degrees[k] + 1));
        expand(0, e.power[a], 0, 0);
      }
      Sparse_polynomial<IT> out(n);
      std::vector<unsigned> ex(n, 0);
      for (std::size_t a = 0; a < ts.size; ++a) {
        for (std::size_t k = 0; k < tv.size(); ++k) ex[tv[k]] = unsigned((a / ts.strides[k]) % (ts.degrees[k] + 1));
        out.add_term(ex, G[a]);
      }
      return out;
    }

    void split_node(const Node& x, std::size_t j, Node& l, Node& r) const
    {
      Bound m = midpoint(x.lo[j], x.hi[j]);
      IT t = (pt(m) - pt(x.lo[j])) / width_interval(x.lo[j], x.hi[j]);
      l.lo = x.lo; l.hi = x.hi; l.hi[j] = m;
      r.lo = x.lo; r.hi = x.hi; r.lo[j] = m;
      l.depth = r.depth = x.depth + 1;
      l.no_shear = r.no_shear = x.no_shear;
      if (wide_coefficients) {
        // the halves' arrays would be blurred by the coefficients' widths (see process()):
        // converted afresh there, not subdivided here
        l.stale = r.stale = true;
        return;
      }
      l.b.resize(n);
      r.b.resize(n);
      for (std::size_t i = 0; i < n; ++i) {
        std::size_t k = eq[i].shape.local(j);
        if (k == std::size_t(-1)) { l.b[i] = x.b[i]; r.b[i] = x.b[i]; continue; }
        internal::split(eq[i].shape, x.b[i], k, t, l.b[i], r.b[i]);
      }
    }

    // The clip of the k-th preconditioned equation sum_i M(k, i) F_i (F: the arrays over
    // `full`). With double intervals the sum runs on the bounds directly, the FPU rounding
    // upward (set for the whole solve by Solver_precision_guard): for a weight m >= 0 the upper bound gathers m * hi and
    // the negated lower bound m * (-lo), for m < 0 the other way round; every sum then rounds
    // up, so the result encloses the exact combination (and the loops vectorize).
    bool preconditioned_clip(const Matrix& M, std::size_t k, std::vector<double>& cu, std::vector<double>& cv)
    {
      if constexpr (std::is_same<IT, CGAL::Interval_nt<false>>::value) {  // the rounding is upward throughout
        if (F_nl.size() != n) { F_nl.assign(n, std::vector<double>(full.size)); F_hi.assign(n, std::vector<double>(full.size)); }
        if (k == 0)
          for (std::size_t i = 0; i < n; ++i)
            for (std::size_t a = 0; a < full.size; ++a) { F_nl[i][a] = -F[i][a].inf(); F_hi[i][a] = F[i][a].sup(); }
        g_nl.assign(full.size, 0.0);
        g_hi.assign(full.size, 0.0);
        double* gl = g_nl.data();
        double* gh = g_hi.data();
        for (std::size_t i = 0; i < n; ++i) {
          const double m = M(Eigen::Index(k), Eigen::Index(i));
          if (m == 0) continue;
          const double am = std::abs(m);
          const double* up = m > 0 ? F_hi[i].data() : F_nl[i].data();
          const double* dn = m > 0 ? F_nl[i].data() : F_hi[i].data();
          for (std::size_t a = 0; a < full.size; ++a) { gh[a] += am * up[a]; gl[a] += am * dn[a]; }
        }
        for (std::size_t a = 0; a < full.size; ++a) gl[a] = -gl[a];
        return internal::clip_bounds(full, gl, gh, cu, cv, clip_work);
      } else {
        g.assign(full.size, IT(0));
        for (std::size_t i = 0; i < n; ++i) {
          if (M(Eigen::Index(k), Eigen::Index(i)) == 0) continue;
          IT m(M(Eigen::Index(k), Eigen::Index(i)));
          for (std::size_t a = 0; a < full.size; ++a) g[a] = g[a] + m * F[i][a];
        }
        return internal::clip_axes(full, g, cu, cv, clip_work);
      }
    }

    // Projected-polyhedron clipping (preconditioned when affordable). Returns false if the
    // box holds no root; `ratio` is the largest remaining fraction of a variable's width.
    bool reduce(Node& x, double& ratio)
    {
      ill_conditioned = false;
      std::vector<double> tu(n, 0.0), tv(n, 1.0), cu, cv;
      {
        // the equations themselves (the projected-polyhedron method) first: cheap (each over
        // its own variables), and on large boxes often sharper than the preconditioned ones,
        // whose linearization is poor there; a box they exclude costs no preconditioning
        for (std::size_t i = 0; i < n; ++i) {
          const Shape& s = eq[i].shape;
          if (!internal::clip_axes(s, x.b[i], cu, cv, clip_work)) return false;
          for (std::size_t k = 0; k < s.variables.size(); ++k) {
            std::size_t j = s.variables[k];
            tu[j] = (std::max)(tu[j], cu[k]);
            tv[j] = (std::min)(tv[j], cv[k]);
          }
        }
      }
      if (precondition) {
        Vector f;
        Matrix J;
        evaluate_d(center_d(x.lo, x.hi), f, J);
        for (std::size_t j = 0; j < n; ++j) J.col(j) *= width(x, j);
        Eigen::FullPivLU<Matrix> lu(J);
        Matrix M;
        // the reciprocal condition number in the 1-norm, from the inverse that is needed anyway
        // (Eigen's estimate of it cost as much as the inverse: 5% of Jansen's linkage)
        double rcond = 0;
        if (lu.isInvertible() && (M = lu.inverse()).allFinite()) {
          const double nj = J.cwiseAbs().colwise().sum().maxCoeff(), nm = M.cwiseAbs().colwise().sum().maxCoeff();
          if (nj > 0 && nm > 0 && std::isfinite(nj * nm)) rcond = 1 / (nj * nm);
        }
        if (rcond > 1e-12) {
          F.resize(n);
          for (std::size_t i = 0; i < n; ++i) embedding[i].apply(x.b[i], F[i], embed_scratch);
          for (std::size_t k = 0; k < n; ++k) {
            if (!preconditioned_clip(M, k, cu, cv)) return false;
            for (std::size_t j = 0; j < n; ++j) {
              tu[j] = (std::max)(tu[j], cu[j]);
              tv[j] = (std::min)(tv[j], cv[j]);
            }
          }
          if (rcond < 0.01) {
            // J nearly singular (near an ill-conditioned root): every row of its inverse is
            // dominated by the near-null direction (weight 1 / sigma_min), so the rows are all
            // nearly one equation and clip little; the inverse with the singular values
            // floored at a tenth of the largest keeps the other directions apart (5 times
            // fewer boxes on the Stewart-Gough scene; a gate at 0.1 saves a few more boxes
            // there but costs more than it saves on the pentagon scene)
            Eigen::JacobiSVD<Matrix> svd(J, Eigen::ComputeFullU | Eigen::ComputeFullV);
            const Vector& sv = svd.singularValues();
            if (sv[Eigen::Index(n) - 1] < 0.01 * sv[0]) {
              ill_conditioned = true;
              Vector inv(n);
              for (std::size_t k = 0; k < n; ++k) inv[Eigen::Index(k)] = 1 / (std::max)(sv[Eigen::Index(k)], 0.1 * sv[0]);
              Matrix R = svd.matrixV() * inv.asDiagonal() * svd.matrixU().transpose();
              if (R.allFinite())
                for (std::size_t k = 0; k < n; ++k) {
                  if (!preconditioned_clip(R, k, cu, cv)) return false;
                  for (std::size_t j = 0; j < n; ++j) {
                    tu[j] = (std::max)(tu[j], cu[j]);
                    tv[j] = (std::min)(tv[j], cv[j]);
                  }
                }
            }
          }
        }
      }
      ratio = 0;
      for (std::size_t j = 0; j < n; ++j) {
        if (tu[j] > tv[j]) return false;
        ratio = (std::max)(ratio, tv[j] - tu[j]);
      }
      bool changed = false;
      for (std::size_t j = 0; j < n; ++j) {
        if (tv[j] - tu[j] > 0.9) continue;  // not worth the restriction
        IT w = width_interval(x.lo[j], x.hi[j]);
        Bound nlo = x.lo[j], nhi = x.hi[j];
        if (tu[j] > 0) { Bound c = O::lower(pt(x.lo[j]) + w * IT(tu[j])); if (c > nlo) nlo = c; }
        if (tv[j] < 1) { Bound c = O::upper(pt(x.lo[j]) + w * IT(tv[j])); if (c < nhi) nhi = c; }
        if (!(nlo < nhi)) continue;  // below the resolution of the bounds: leave it
        if (nlo == x.lo[j] && nhi == x.hi[j]) continue;
        IT pu = (pt(nlo) - pt(x.lo[j])) / w, pv = (pt(nhi) - pt(x.lo[j])) / w;
        for (std::size_t i = 0; i < n; ++i) {
          std::size_t k = eq[i].shape.local(j);
          if (k == std::size_t(-1)) continue;
          x.b[i] = internal::restrict_axis(eq[i].shape, x.b[i], k, pu, pv, nlo == x.lo[j], nhi == x.hi[j]);
        }
        x.lo[j] = nlo;
        x.hi[j] = nhi;
        changed = true;
      }
      if (changed) ++result.statistics.reductions;
      else ratio = 1;
      return true;
    }

    // The Krawczyk operator on the box [lo, hi] with its Bernstein arrays b. Returns false
    // if it could not be formed (singular midpoint Jacobian). `inside`: K lies in the
    // interior of the box (one root, unique); `empty`: K misses the box (no root).
    bool krawczyk(const std::vector<Bound>& lo, const std::vector<Bound>& hi, const std::vector<std::vector<IT>>& b,
                  std::vector<IT>& K, bool& inside, bool& empty)
    {
      // interval Jacobian: the Bernstein differences (tight on large boxes) intersected with
      // the derivatives evaluated in interval arithmetic (no division by a tiny width); without
      // arrays (b empty: tighten() first) the evaluations alone
      const bool arrays = !b.empty();
      std::vector<std::vector<IT>> J(n, std::vector<IT>(n, IT(0)));
      Matrix Jm = Matrix::Zero(n, n);
      std::vector<IT> w(n), X(n);
      for (std::size_t j = 0; j < n; ++j) { w[j] = width_interval(lo[j], hi[j]); X[j] = O::make(lo[j], hi[j]); }
      std::vector<Bound> m(n);
      std::vector<IT> mi(n);
      for (std::size_t j = 0; j < n; ++j) { m[j] = midpoint(lo[j], hi[j]); mi[j] = pt(m[j]); }
      for (std::size_t i = 0; i < n; ++i) {
        const Shape& s = eq[i].shape;
        for (std::size_t k = 0; k < s.variables.size(); ++k) {
          std::size_t j = s.variables[k];
          const unsigned d = s.degrees[k];
          const std::size_t st = s.strides[k];
          if (d == 0) continue;
          bool first = true;
          Bound mn = Bound(), mx = Bound();
          if (arrays)
            s.for_each_fiber(k, [&](std::size_t base) {
              for (unsigned a = 0; a < d; ++a) {
                IT diff = (b[i][base + (a + 1) * st] - b[i][base + a * st]) * IT(int(d));
                if (first) { mn = O::lower(diff); mx = O::upper(diff); first = false; }
                else { if (O::lower(diff) < mn) mn = O::lower(diff); if (mx < O::upper(diff)) mx = O::upper(diff); }
              }
            });
          std::vector<IT> xl;
          for (std::size_t v : s.variables) xl.push_back(X[v]);
          IT h = internal::horner(eq[i].dshape[k], eq[i].dpower[k], xl);
          if (!(O::lower(w[j]) > 0)) { J[i][j] = h; }  // a point in x_j: the evaluation alone
          else {
            if (first) J[i][j] = h;
            else {
              IT bb = O::make(mn, mx) / w[j];
              Bound l = O::lower(h) < O::lower(bb) ? O::lower(bb) : O::lower(h);
              Bound u = O::upper(bb) < O::upper(h) ? O::upper(bb) : O::upper(h);
              J[i][j] = u < l ? bb : O::make(l, u);
            }
            // and with the mean-value form J_ij(m) + sum_l d2f_i/dx_j dx_l (X) (X_l - m_l): tight
            // where the plain interval evaluation loses everything to cancellation (a
            // Wilkinson-like polynomial: near x = 9 its derivative's Horner enclosure on a box
            // 1e-7 wide spans [-6.7e5, 1.9e5] around -2.4e5)
            std::vector<IT> ml;
            for (std::size_t v : s.variables) ml.push_back(mi[v]);
            IT t = internal::horner(eq[i].dshape[k], eq[i].dpower[k], ml);
            for (std::size_t q = 0; q < s.variables.size(); ++q) {
              if (eq[i].ddpower[k][q].empty()) continue;
              const std::size_t v = s.variables[q];
              t = t + internal::horner(eq[i].ddshape[k][q], eq[i].ddpower[k][q], xl) * (X[v] - mi[v]);
            }
            Bound l2 = O::lower(J[i][j]) < O::lower(t) ? O::lower(t) : O::lower(J[i][j]);
            Bound u2 = O::upper(t) < O::upper(J[i][j]) ? O::upper(t) : O::upper(J[i][j]);
            if (!(u2 < l2)) J[i][j] = O::make(l2, u2);
          }
          Jm(i, j) = 0.5 * O::lower_double(J[i][j]) + 0.5 * O::upper_double(J[i][j]);
        }
      }
      last_contraction = std::numeric_limits<double>::infinity();
      Eigen::FullPivLU<Matrix> lu(Jm);
      if (!lu.isInvertible()) return false;
      Matrix Y = lu.inverse();
      if (!Y.allFinite()) return false;
      ++result.statistics.krawczyk_tests;
      std::vector<IT> fm(n);
      for (std::size_t i = 0; i < n; ++i) {
        std::vector<IT> xl;
        for (std::size_t v : eq[i].shape.variables) xl.push_back(mi[v]);
        fm[i] = internal::horner(eq[i].shape, eq[i].power, xl);
      }
      std::vector<IT> dx(n);
      for (std::size_t j = 0; j < n; ++j) dx[j] = O::make(lo[j], hi[j]) - mi[j];
      K.assign(n, IT(0));
      inside = true;
      empty = false;
      last_contraction = 0;
      for (std::size_t r = 0; r < n; ++r) {
        IT k = mi[r];
        for (std::size_t i = 0; i < n; ++i) if (Y(r, i) != 0) k = k - IT(Y(r, i)) * fm[i];
        double row = 0;
        for (std::size_t c = 0; c < n; ++c) {
          IT a = IT(r == c ? 1 : 0);
          for (std::size_t i = 0; i < n; ++i) if (Y(r, i) != 0) a = a - IT(Y(r, i)) * J[i][c];
          k = k + a * dx[c];
          row += (std::max)(std::abs(O::lower_double(a)), std::abs(O::upper_double(a)));
        }
        last_contraction = (std::max)(last_contraction, row);
        K[r] = k;
        if (!(O::lower(k) > lo[r]) || !(O::upper(k) < hi[r])) inside = false;
        if (O::upper(k) < lo[r] || hi[r] < O::lower(k)) empty = true;
      }
      return true;
    }

    // Tries to prove one root near the box (in the box inflated by 10% each side); on
    // success records it (tightened, merged with a duplicate) and returns true: the box then
    // holds no other root.
    // With `newton_gate`, gives up before the (costly) Krawczyk test when quasi-Newton from
    // the centre leaves the node: the test would fail (K holds the Newton step), and the
    // halves get their own chance; on the 6-variable Stewart-Gough system this halves the time.
    bool certify(Node& x, bool newton_gate = false)
    {
      // The Krawczyk box: centred at a Newton estimate of the root (so that a root near a
      // face of the node, or on it, sits near the centre), covering the node with a margin of
      // 10%, and at least a few thousand units in the last place (a box the clipping shrank
      // to a point on a face must still hold its root in its interior).
      const double eps = std::ldexp(1.0, 16 - int(O::bits()));
      std::vector<Bound> c(n), lo(n), hi(n);
      std::vector<IT> margin(n);
      // (and at least 1e-12 of the widest relative width: a box the clipping made thin in
      // one variable must not be thinner than what the double-precision preconditioner Y
      // leaks into it from the others)
      double widest = 0;
      for (std::size_t j = 0; j < n; ++j) widest = (std::max)(widest, width(x, j) / initial_width[j]);
      for (std::size_t j = 0; j < n; ++j) {
        double floor = eps * ((std::max)(std::abs(O::to_double(x.lo[j])), std::abs(O::to_double(x.hi[j]))) + initial_width[j]);
        floor = (std::max)(floor, 1e-12 * widest * initial_width[j]);
        margin[j] = width_interval(x.lo[j], x.hi[j]) * IT(0.1) + IT(floor);
        c[j] = midpoint_or_point(x.lo[j], x.hi[j]);
      }
      certify_excluded = false;
      if (!newton_point(x.lo, x.hi, margin, c) && newton_gate) {
        // no certification here; without the preconditioned clipping (which excludes such
        // boxes itself), the Krawczyk operator of the node may miss the node (K(X) holds every
        // root in X): near an ill-conditioned root the boxes along its near-null direction
        // keep their sign changes for many levels, and this ends them
        std::vector<IT> K;
        bool inside, empty;
        if (!precondition && krawczyk(x.lo, x.hi, x.b, K, inside, empty) && empty) certify_excluded = true;
        return false;
      }
      for (std::size_t j = 0; j < n; ++j) {
        IT a = pt(c[j]) - pt(x.lo[j]), b = pt(x.hi[j]) - pt(c[j]);
        IT r = (O::upper(a) < O::upper(b) ? b : a) * IT(1.1) + margin[j];
        Bound rr = O::upper(r);
        lo[j] = O::lower(pt(c[j]) - pt(rr));
        hi[j] = O::upper(pt(c[j]) + pt(rr));
      }
      std::vector<std::vector<IT>> b;
      for (const auto& e : eq) b.push_back(bernstein(e, lo, hi));
      std::vector<IT> K;
      bool inside, empty;
      if (!krawczyk(lo, hi, b, K, inside, empty)) return false;
      if (empty) { certify_excluded = true; return false; }  // [lo, hi] contains the node
      for (int round = 0; round < 4 && !inside && last_contraction < 0.5; ++round) {
        // epsilon-inflation (Rump): the box was too thin for K to fit; again on the hull of
        // the box and K, widened, in the variables where K sticks out only: in a box the
        // clipping made long in some variables and thin in others, K of a thin variable gathers
        // the long ones' widths (through I - Y J), and widening those too would keep it out
        for (std::size_t j = 0; j < n; ++j) {
          if (lo[j] < O::lower(K[j]) && O::upper(K[j]) < hi[j]) continue;
          Bound l = O::lower(K[j]) < lo[j] ? O::lower(K[j]) : lo[j], h = hi[j] < O::upper(K[j]) ? O::upper(K[j]) : hi[j];
          IT w = width_interval(l, h) * IT(0.5);
          lo[j] = O::lower(pt(l) - w);
          hi[j] = O::upper(pt(h) + w);
        }
        for (std::size_t i = 0; i < n; ++i) b[i] = bernstein(eq[i], lo, hi);
        if (!krawczyk(lo, hi, b, K, inside, empty)) return false;
        if (empty) { certify_excluded = true; return false; }  // the inflation only grows the box
      }
      if (!inside) return false;
      ++result.statistics.certified_boxes;
      // tighten: Z <- K(Z) ∩ Z
      std::vector<Bound> zlo(n), zhi(n);
      for (std::size_t j = 0; j < n; ++j) {
        zlo[j] = O::lower(K[j]) > lo[j] ? O::lower(K[j]) : lo[j];
        zhi[j] = O::upper(K[j]) < hi[j] ? O::upper(K[j]) : hi[j];
      }
      tighten(zlo, zhi);
      record(zlo, zhi, lo, hi, true);
      return true;
    }

    // A few quasi-Newton steps x <- x - Y f(x) in the working precision (Y: the inverse
    // Jacobian at the start, in double); x is left unchanged if they leave the node widened
    // by `margin` (and false is returned).
    bool newton_point(const std::vector<Bound>& nlo, const std::vector<Bound>& nhi, const std::vector<IT>& margin, std::vector<Bound>& x)
    {
      std::vector<double> xd(n);
      for (std::size_t j = 0; j < n; ++j) xd[j] = O::to_double(x[j]);
      Vector f;
      Matrix J;
      evaluate_d(xd, f, J);
      Eigen::FullPivLU<Matrix> lu(J);
      if (!lu.isInvertible()) return true;
      Matrix Y = lu.inverse();
      if (!Y.allFinite()) return true;
      std::vector<Bound> y = x;
      std::vector<IT> yi(n), fy(n);
      for (int it = 0; it < 6; ++it) {
        for (std::size_t j = 0; j < n; ++j) yi[j] = pt(y[j]);
        for (std::size_t i = 0; i < n; ++i) {
          std::vector<IT> xl;
          for (std::size_t v : eq[i].shape.variables) xl.push_back(yi[v]);
          fy[i] = internal::horner(eq[i].shape, eq[i].power, xl);
        }
        for (std::size_t j = 0; j < n; ++j) {
          IT step(0);
          for (std::size_t i = 0; i < n; ++i) if (Y(j, i) != 0) step = step + IT(Y(j, i)) * fy[i];
          IT z = yi[j] - step;
          y[j] = midpoint_or_point(O::lower(z), O::upper(z));
          if (O::lower(pt(y[j]) + margin[j]) < nlo[j] || nhi[j] < O::upper(pt(y[j]) - margin[j])) return false;
        }
      }
      x = y;
      return true;
    }

    double max_width(const std::vector<Bound>& lo, const std::vector<Bound>& hi) const
    {
      double w = 0;
      for (std::size_t j = 0; j < n; ++j) w = (std::max)(w, O::upper_double(width_interval(lo[j], hi[j])));
      return w;
    }

    void tighten(std::vector<Bound>& zlo, std::vector<Bound>& zhi)
    {
      double w = max_width(zlo, zhi);
      // the Jacobian from the derivatives' evaluations first (no arrays to convert); where that
      // does not contract (a Krawczyk box still wide), from the Bernstein arrays as well
      bool arrays = false;
      double step = 0;  // the last iteration's shrinking
      for (int it = 0; it < 64 && w > P.tolerance; ++it) {
        std::vector<std::vector<IT>> b;
        if (arrays)
          for (const auto& e : eq) b.push_back(bernstein(e, zlo, zhi));
        std::vector<IT> K;
        bool inside, empty;
        if (!krawczyk(zlo, zhi, b, K, inside, empty) || empty) {
          if (!arrays) { arrays = true; continue; }
          break;
        }
        for (std::size_t j = 0; j < n; ++j) {
          if (zlo[j] < O::lower(K[j])) zlo[j] = O::lower(K[j]);
          if (O::upper(K[j]) < zhi[j]) zhi[j] = O::upper(K[j]);
        }
        double nw = max_width(zlo, zhi);
        if (!(nw < w)) {  // no progress: the precision is exhausted, or the Jacobian is too loose
          if (!arrays) { arrays = true; continue; }
          break;
        }
        // With interval coefficients (a block's inputs are boxes) the enclosures tend to a box
        // as wide as the coefficients make it, at a linear rate: the shrinking steps form a
        // geometric series, and once the rest of it is below a tenth of the width the rest is
        // not worth the iterations (on Jansen's linkage 10 per root on average, many up to 64)
        const double d = w - nw;
        if (wide_coefficients && step > 0 && d < step) {
          const double rho = d / step;
          if (d * rho / (1 - rho) < 0.1 * nw) break;
        }
        step = d;
        w = nw;
      }
    }

    void record(const std::vector<Bound>& zlo, const std::vector<Bound>& zhi, const std::vector<Bound>& klo,
                const std::vector<Bound>& khi, bool certified)
    {
      // a root outside the search box is not ours
      bool boundary = false;
      for (std::size_t j = 0; j < n; ++j) {
        if (zhi[j] < dlo[j] || dhi[j] < zlo[j]) return;
        if (zlo[j] < dlo[j] || dhi[j] < zhi[j] || zlo[j] == dlo[j] || zhi[j] == dhi[j]) boundary = true;
      }
      for (auto& f : found) {
        bool overlap = true, z_in_f = true, f_in_k = true;
        for (std::size_t j = 0; j < n; ++j) {
          const auto& e = f.root.enclosure[j];
          if (zhi[j] < O::lower(e) || O::upper(e) < zlo[j]) overlap = false;
          if (zlo[j] < f.klo[j] || f.khi[j] < zhi[j]) z_in_f = false;
          if (O::lower(e) < klo[j] || khi[j] < O::upper(e)) f_in_k = false;
        }
        if (!certified) {
          // fast mode: the same root if the approximations are close
          double d = 0;
          for (std::size_t j = 0; j < n; ++j)
            d = (std::max)(d, std::abs(O::to_double(zlo[j]) - f.root.approximation[j]) / initial_width[j]);
          if (d < 1e-7) { ++result.statistics.duplicates; return; }
          continue;
        }
        if (overlap && (z_in_f || f_in_k)) {
          ++result.statistics.duplicates;
          // keep the tighter enclosure
          if (max_width(zlo, zhi) < max_width(lower_of(f.root.enclosure), upper_of(f.root.enclosure))) {
            for (std::size_t j = 0; j < n; ++j) f.root.enclosure[j] = O::make(zlo[j], zhi[j]);
          }
          return;
        }
      }
      Found f;
      f.klo = klo;
      f.khi = khi;
      f.root.certified = certified;
      f.root.on_boundary = boundary;
      for (std::size_t j = 0; j < n; ++j) {
        f.root.uniqueness_box.push_back(O::make(klo[j], khi[j]));
        f.root.enclosure.push_back(O::make(zlo[j], zhi[j]));
        f.root.approximation.push_back(O::to_double(midpoint_or_point(zlo[j], zhi[j])));
      }
      double res = 0;
      for (const auto& e : eq) {
        std::vector<IT> xl;
        for (std::size_t v : e.shape.variables) xl.push_back(f.root.enclosure[v]);
        IT v = internal::horner(e.shape, e.power, xl);
        res = (std::max)(res, (std::max)(std::abs(O::lower_double(v)), std::abs(O::upper_double(v))));
      }
      f.root.residual = res;
      found.push_back(std::move(f));
    }
    static std::vector<Bound> lower_of(const std::vector<IT>& v) { std::vector<Bound> r; for (const auto& x : v) r.push_back(O::lower(x)); return r; }
    static std::vector<Bound> upper_of(const std::vector<IT>& v) { std::vector<Bound> r; for (const auto& x : v) r.push_back(O::upper(x)); return r; }
    static Bound midpoint_or_point(const Bound& lo, const Bound& hi) { return lo < hi ? midpoint(lo, hi) : lo; }

    // Fast mode: Newton in double from the box centre; accepted (uncertified) if it
    // converges inside the inflated box.
    bool polish(const Node& x)
    {
      std::vector<double> c = center_d(x.lo, x.hi), lo(n), hi(n);
      const double eps = std::ldexp(1.0, 16 - int(O::bits()));
      for (std::size_t j = 0; j < n; ++j) {
        // at least a few thousand units in the last place, as in certify(): a box the clipping
        // shrank to about a point leaves Newton's rounding no room (and its root was lost)
        const double l = O::to_double(x.lo[j]), h = O::to_double(x.hi[j]);
        const double m = (std::max)(0.1 * width(x, j), eps * ((std::max)(std::abs(l), std::abs(h)) + initial_width[j]));
        lo[j] = l - m;
        hi[j] = h + m;
      }
      Vector f;
      Matrix J;
      bool converged = false;
      double last_step = std::numeric_limits<double>::infinity();
      for (int it = 0; it < 30; ++it) {
        evaluate_d(c, f, J);
        Eigen::FullPivLU<Matrix> lu(J);
        if (!lu.isInvertible()) return false;
        Vector d = lu.solve(f);
        double step = 0;
        for (std::size_t j = 0; j < n; ++j) {
          c[j] -= d[j];
          step = (std::max)(step, std::abs(d[j]) / initial_width[j]);
          if (!(c[j] >= lo[j] && c[j] <= hi[j])) return false;
        }
        if (step < 1e-15 || step < 1e-3 * P.tolerance) { converged = true; break; }
        // stalled at the rounding noise (an ill-conditioned root): as close as double gets
        if (step < 1e-10 && step >= 0.5 * last_step) { converged = true; break; }
        last_step = step;
      }
      if (!converged) return false;
      ++result.statistics.certified_boxes;
      std::vector<Bound> z(n);
      for (std::size_t j = 0; j < n; ++j) z[j] = O::bound_from_double(c[j]);
      // no uniqueness is proved: the "uniqueness box" is the point itself, so that no other
      // box is skipped as holding only this root (inside_found)
      record(z, z, z, z, false);
      // the box may hold other roots: it is done only if the Jacobian is regular on it (one
      // root at most) and Newton's root is that one (in the box, not only in the 10% margin:
      // else the box's own root would be lost)
      for (std::size_t j = 0; j < n; ++j)
        if (c[j] < O::to_double(x.lo[j]) || c[j] > O::to_double(x.hi[j])) return false;
      std::vector<IT> K;
      bool inside, empty;
      return krawczyk(x.lo, x.hi, x.b, K, inside, empty) && last_contraction < 1;
    }

    void make_unknown(Node& x, bool small, bool singular = false)
    {
      // before giving up, one more certification attempt on the box itself
      if (!singular && !P.fast) {
        if (certify(x)) return;
        if (certify_excluded) { ++result.statistics.excluded; return; }
      }
      std::vector<double> c = center_d(x.lo, x.hi);
      Vector f;
      Matrix J;
      evaluate_d(c, f, J);
      Eigen::JacobiSVD<Matrix> svd(J);
      const auto& s = svd.singularValues();
      bool deficient = singular || !(s.size() > 0 && s[0] > 0 && s[s.size() - 1] > 1e-7 * s[0]);
      std::string reason;
      if (deficient) reason = "possible multiple root";
      else if (!small) reason = "precision exhausted";
      else reason = "not certified at minimal width";
      unknown_nodes.push_back(std::move(x));
      unknown_reason.push_back(reason);
      unknown_rank_deficient.push_back(deficient);
    }

    // ---- the result ------------------------------------------------------------------
    void finish()
    {
      std::vector<Solver_unresolved<IT>> unknown = cluster(unknown_nodes, Box_class::UNKNOWN);
      for (auto& u : unknown) {
        // a small cluster may be a root the precision could not certify: solve it again. Small:
        // at most 256 boxes, or compact, at most 64 singular widths across in every variable
        // (a simple root with a condition number of 1e9, at coordinates near 500, leaves
        // thousands of boxes of the singular width in a blob 12 to 16 of them across, and is
        // certified at once at 106 bits; a curve of solutions leaves long clusters instead)
        // (and at most 4096 boxes: a tangency of small curvature radius can be compact too)
        bool compact = u.boxes <= 4096;
        for (std::size_t j = 0; j < n && compact; ++j) compact = O::upper_double(u.box[j]) - O::lower_double(u.box[j]) <= 64 * singular_width;
        if (retry && (u.boxes <= 256 || compact) && unknown.size() <= 16 && pending_nodes.empty() && (!same_precision_retry || u.rank_deficient)) {
          ++result.statistics.precision_retries;
          std::vector<Bound> lo = lower_of(u.box), hi = upper_of(u.box);
          for (std::size_t j = 0; j < n; ++j) {
            IT w = width_interval(lo[j], hi[j]) * IT(0.25) + IT(4 * min_width);
            lo[j] = O::lower(pt(lo[j]) - w);
            hi[j] = O::upper(pt(hi[j]) + w);
          }
          Solver_result<IT> sub;
          retry(lo, hi, sub);
          result.statistics.boxes += sub.statistics.boxes;
          result.statistics.krawczyk_tests += sub.statistics.krawczyk_tests;
          for (const auto& r : sub.roots) {
            std::vector<Bound> rl = lower_of(r.enclosure), rh = upper_of(r.enclosure);
            const auto& u = r.uniqueness_box.empty() ? r.enclosure : r.uniqueness_box;
            record(rl, rh, lower_of(u), upper_of(u), r.certified);
          }
          // a retry that ran out of boxes says less than the cluster it was given: that is kept
          const bool ran_out = std::any_of(sub.unresolved.begin(), sub.unresolved.end(),
                                           [](const Solver_unresolved<IT>& v) { return v.kind == Box_class::PENDING; });
          if (ran_out) {
            u.reason += " (solved again at a higher precision: box budget exhausted)";
            result.unresolved.push_back(u);
          } else
            for (auto& v : sub.unresolved) result.unresolved.push_back(v);
          continue;
        }
        result.unresolved.push_back(u);
      }
      for (auto& u : cluster(pending_nodes, Box_class::PENDING)) result.unresolved.push_back(u);
      result.roots.clear();
      for (auto& f : found) {
        // the inequalities on the root's enclosure: < 0 certainly: not a root we want
        bool reject = false, boundary = false;
        for (const auto& g : ineq) {
          std::vector<IT> xl;
          for (std::size_t v : g.shape.variables) xl.push_back(f.root.enclosure[v]);
          IT v = internal::horner(g.shape, g.power, xl);
          if (O::upper(v) < 0) reject = true;
          else if (!(O::lower(v) >= 0)) boundary = true;
        }
        if (reject) { ++result.statistics.rejected_roots; continue; }
        f.root.on_inequality_boundary = boundary;
        result.roots.push_back(f.root);
      }
      std::sort(result.roots.begin(), result.roots.end(), [](const Solver_root<IT>& a, const Solver_root<IT>& b) {
        return a.approximation < b.approximation;
      });
      // diagnosis: a long chain of rank-deficient unknown boxes is a curve of solutions
      for (const auto& u : result.unresolved) {
        std::string d = curve_diagnosis(u, 16);
        if (!d.empty()) { result.diagnosis = d; break; }
      }
      result.statistics.seconds = seconds();
    }

    // "positive_dimensional: ..." if `u` is a chain of at least `least` rank-deficient unknown
    // boxes spanning at least 100 singular widths, else empty.
    std::string curve_diagnosis(const Solver_unresolved<IT>& u, std::size_t least) const
    {
      if (u.kind != Box_class::UNKNOWN || !u.rank_deficient || u.boxes < least) return {};
      double span = 0;
      for (const auto& v : u.box) span = (std::max)(span, O::upper_double(v) - O::lower_double(v));
      if (span < 100 * singular_width) return {};
      return "positive_dimensional: solution set appears to be positive-dimensional: Jacobian rank-deficient along a chain of " +
             std::to_string(u.boxes) + " boxes spanning " + std::to_string(span);
    }
    // The diagnosis of the unknown boxes so far, with the evidence the parameters ask for.
    std::string curve_evidence()
    {
      for (const auto& u : cluster(unknown_nodes, Box_class::UNKNOWN)) {
        std::string d = curve_diagnosis(u, P.positive_dimensional_evidence);
        if (!d.empty()) return d;
      }
      return {};
    }

    // Touching boxes of one class become one unresolved region.
    std::vector<Solver_unresolved<IT>> cluster(std::vector<Node>& nodes, Box_class kind)
    {
      const std::size_t m = nodes.size();
      if (m == 0) return {};
      std::vector<std::size_t> parent(m), order(m);
      std::iota(parent.begin(), parent.end(), std::size_t(0));
      std::iota(order.begin(), order.end(), std::size_t(0));
      auto find = [&](std::size_t a) { while (parent[a] != a) a = parent[a] = parent[parent[a]]; return a; };
      std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return nodes[a].lo[0] < nodes[b].lo[0]; });
      for (std::size_t a = 0; a < m; ++a) {
        const Node& x = nodes[order[a]];
        for (std::size_t c = a + 1; c < m && !(x.hi[0] < nodes[order[c]].lo[0]); ++c) {
          const Node& y = nodes[order[c]];
          bool touch = true;
          for (std::size_t j = 0; j < n && touch; ++j) touch = !(x.hi[j] < y.lo[j]) && !(y.hi[j] < x.lo[j]);
          if (touch) parent[find(order[a])] = find(order[c]);
        }
      }
      std::vector<std::size_t> slot(m, std::size_t(-1));
      std::vector<Solver_unresolved<IT>> out;
      std::vector<std::vector<Bound>> hlo, hhi;
      for (std::size_t a = 0; a < m; ++a) {
        std::size_t r = find(a);
        if (slot[r] == std::size_t(-1)) {
          slot[r] = out.size();
          Solver_unresolved<IT> u;
          u.kind = kind;
          u.boxes = 0;
          u.reason = kind == Box_class::PENDING ? pending_reason : unknown_reason[a];
          out.push_back(u);
          hlo.push_back(nodes[a].lo);
          hhi.push_back(nodes[a].hi);
        }
        std::size_t s = slot[r];
        auto& u = out[s];
        ++u.boxes;
        if (kind == Box_class::UNKNOWN) {
          if (unknown_rank_deficient[a]) u.rank_deficient = true;
          // the most telling reason wins
          if (unknown_reason[a] == "possible multiple root") u.reason = unknown_reason[a];
        }
        for (std::size_t j = 0; j < n; ++j) {
          if (nodes[a].lo[j] < hlo[s][j]) hlo[s][j] = nodes[a].lo[j];
          if (hhi[s][j] < nodes[a].hi[j]) hhi[s][j] = nodes[a].hi[j];
        }
      }
      for (std::size_t s = 0; s < out.size(); ++s)
        for (std::size_t j = 0; j < n; ++j) out[s].box.push_back(O::make(hlo[s][j], hhi[s][j]));
      return out;
    }
  };

  Subdivision_solver_parameters p_;
};

} // namespace Rigid_incidence
} // namespace CGAL

#endif
