// Copyright (c) 2026 Rigid_incidence contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Curves along a solution plan (decomposition_subdivision_solver.txt, Section 3.4 and
// Algorithm 6 for m = k - 1): the plan's curve block, merged with the square blocks it depends
// on (block 0), is traced by trace_curves(), and the other blocks, all square, are lifted over
// short certified pieces of block 0's branches.
//
// A piece runs between two certified points of block 0's curve (nodes: Krawczyk boxes of the
// curve with one variable t fixed). A parametric Krawczyk test on block 0 with t over the piece's
// interval proves that for every t there is exactly one point of the curve in a narrow box X0
// that holds both nodes, so the piece is the curve between them. Over X0, a parametric Krawczyk
// test on all later blocks together (block by block the inputs' boxes would be independent
// intervals whose widths grow with every block) proves, for each root found at X0's centre, one
// root in a box X for every input in X0: a lift, single-valued and continuous over the piece.
// Each later block is then solved again over the lifts' boxes with interval coefficients, to
// prove that these are all its roots there (so the roots at the centre may be continued by
// Newton from the lifts of the piece before instead of solved; where that misses one, they are
// solved). Lifts of consecutive pieces are joined where their
// boxes meet (a bijection is required: both sets hold every root above the shared node, each
// one unique in its box). A piece that fails is halved, down to `maximal_halvings` levels. A
// run of pieces that still fail (two roots of a later block meet there: a fold, where the whole
// curve turns back over block 0, or a singular point of the whole curve) is traced whole:
// enclose() boxes every solution above the run (the later blocks solved over it, branching over
// roots and unresolved boxes), trace_curves() traces the whole system in those boxes, and its
// arcs must end at the run's two nodes (or at true ends of the curve), where they are joined
// to the lifts by the roots above the node. Where that fails the run becomes an unresolved
// region where the chains of lifts through it end.

#ifndef CGAL_RIGID_INCIDENCE_TRACE_CURVES_WITH_PLAN_H
#define CGAL_RIGID_INCIDENCE_TRACE_CURVES_WITH_PLAN_H

#include <CGAL/Rigid_incidence/Curve_tracer.h>
#include <CGAL/Rigid_incidence/Input_error.h>
#include <CGAL/Rigid_incidence/Polynomial_system.h>
#include <CGAL/Rigid_incidence/Solution_plan.h>
#include <CGAL/Rigid_incidence/Subdivision_solver.h>
#include <CGAL/Rigid_incidence/solve_with_plan.h>

#include <CGAL/Interval_nt.h>

#include <Eigen/Dense>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <optional>
#include <string>
#include <vector>

namespace CGAL {
namespace Rigid_incidence {

/// \ingroup PkgRigidIncidenceSolver
/// Parameters of `trace_curves_with_plan()` beyond those of the tracer and the solver.
struct Plan_trace_parameters
{
  /// A piece of block 0's curve over which the later blocks cannot be lifted is halved at most
  /// this many times before it becomes an unresolved region.
  unsigned maximal_halvings = 9;
  /// Each later block's solve over a piece visits at most this many boxes (a block whose roots
  /// meet over the piece would otherwise spend the whole budget). Where the solutions above a
  /// fold are enclosed, a solve that runs out of boxes is repeated with a coarser minimal width
  /// (16, 256, 4096, 65536 times), so that its large pending boxes do not enlarge the box traced
  /// around the fold.
  std::size_t block_boxes = 2000;
  /// A piece that still fails after the halvings (two roots of a later block meet over it: a
  /// turning point of the whole curve over block 0) is traced with `trace_curves()` on the whole
  /// system in small boxes around it, visiting at most this many boxes for each run of such
  /// pieces; 0: never (the piece stays an unresolved region).
  std::size_t fold_boxes = 2000;
  /// The boxes that hold every solution above such a run (the later blocks solved over it,
  /// branching over their roots and unresolved boxes) are at most this many, and so are the
  /// block solves that find them over each piece, or the run stays an unresolved region.
  std::size_t fold_leaves = 4096;
  /// A run of more than twice this many failed pieces is traced in stretches of about this
  /// many, cut at nodes above which every lift is certified (smaller boxes around each fold).
  std::size_t fold_stretch = 8;
};

namespace internal {

template <class IT, class NT> struct Plan_trace_run
{
  typedef Interval_ops<IT> O;
  typedef CGAL::Interval_nt<false> I;
  const Polynomial_system<NT>& sys;
  const std::vector<Plan_block> blocks;  // block 0 the curve block (merged with its ancestors), then square blocks
  const Subdivision_solver_parameters& SP;
  const Plan_trace_parameters& PP;
  const std::size_t n;
  std::vector<std::size_t> v0, e0, down, down_eq;  // block 0's variables and equations, the later ones
  // the equations, inequalities and derivatives with their coefficients converted once (an
  // exact coefficient costs a conversion through MPFR at every evaluation otherwise): in double
  // for Newton and the preconditioners, enclosed in I for the Krawczyk tests and in IT for
  // the block solves
  std::vector<Sparse_polynomial<double>> Fd;
  std::vector<std::vector<Sparse_polynomial<double>>> Dd;  // Dd[i][j]: d f_i / d x_j
  std::vector<Sparse_polynomial<I>> FI, GI;
  std::vector<std::vector<Sparse_polynomial<I>>> DI;
  std::vector<Sparse_polynomial<IT>> FIT, GIT;
  std::vector<std::vector<char>> uses;               // uses[i][j]: f_i involves x_j
  std::size_t block_solves = 0, block_boxes = 0, pieces = 0, halvings = 0;
  std::vector<std::size_t> plan_index;  // each block's index in the plan, for messages

  std::string block_name(std::size_t b) const { return "block " + std::to_string(b < plan_index.size() ? plan_index[b] : b) + " of the plan"; }

  Plan_trace_run(const Polynomial_system<NT>& s, const std::vector<Plan_block>& p, const Subdivision_solver_parameters& sp, const Plan_trace_parameters& pp)
      : sys(s), blocks(p), SP(sp), PP(pp), n(s.number_of_variables())
  {
    v0 = blocks[0].variables;
    e0 = blocks[0].equations;
    for (std::size_t b = 1; b < blocks.size(); ++b) {
      down.insert(down.end(), blocks[b].variables.begin(), blocks[b].variables.end());
      down_eq.insert(down_eq.end(), blocks[b].equations.begin(), blocks[b].equations.end());
    }
    uses.resize(sys.equations.size());
    CGAL::Protect_FPU_rounding<true> guard;  // derivatives of interval coefficients round outward
    for (std::size_t i = 0; i < sys.equations.size(); ++i) {
      uses[i].assign(n, 0);
      for (std::size_t j : sys.equations[i].variables()) uses[i][j] = 1;
      Fd.push_back(converted<double>(sys.equations[i]));
      FI.push_back(converted<I>(sys.equations[i]));
      FIT.push_back(converted<IT>(sys.equations[i]));
      Dd.emplace_back();
      DI.emplace_back();
      for (std::size_t j = 0; j < n; ++j) {
        const Sparse_polynomial<NT> d = sys.equations[i].derivative(j);  // d f_i / d x_j
        Dd.back().push_back(converted<double>(d));
        DI.back().push_back(converted<I>(d));
      }
    }
    for (const auto& g : sys.inequalities) {
      GI.push_back(converted<I>(g));
      GIT.push_back(converted<IT>(g));
    }
  }

  // Some inequality of block 0 may be 0 over a piece: its range over block 0's enclosure X0 of
  // the piece (over v0) contains 0. Block 0's curve says only that it meets such a zero
  // somewhere; a branch lifted over pieces away from there does not.
  bool block0_inequality_boundary(const std::vector<I>& X0) const
  {
    CGAL::Protect_FPU_rounding<true> guard;
    std::vector<I> x(n, I(0));
    for (std::size_t k = 0; k < v0.size() && k < X0.size(); ++k) x[v0[k]] = X0[k];
    for (std::size_t q : blocks[0].inequalities) {
      const I v = GI[q].evaluate(x);
      if (v.inf() <= 0 && v.sup() >= 0) return true;
    }
    return false;
  }

  // f with its coefficients in T: rounded to double, or enclosed in an interval
  template <class T> static Sparse_polynomial<T> converted(const Sparse_polynomial<NT>& f)
  {
    Sparse_polynomial<T> r(f.number_of_variables());
    for (const auto& t : f.terms()) {
      if constexpr (std::is_same<T, double>::value) r.add_term(t.first, CGAL::to_double(t.second));
      else r.add_term(t.first, Interval_ops<T>::from(t.second));
    }
    return r;
  }

  IT search(std::size_t j) const { return O::make(O::bound_from_double(sys.box[j].first), O::bound_from_double(sys.box[j].second)); }
  static IT to_it(const I& x) { return O::make(O::bound_from_double(x.inf()), O::bound_from_double(x.sup())); }
  static double mid(const IT& x) { return 0.5 * O::lower_double(x) + 0.5 * O::upper_double(x); }

  // Newton on the equations E for the unknowns Y (the other variables of x fixed); false if
  // it does not converge (to steps of at most `tolerance` times max(1, the largest unknown)).
  bool newton(const std::vector<std::size_t>& E, const std::vector<std::size_t>& Y, std::vector<double>& x, double tolerance = 1e-15) const
  {
    const std::size_t m = Y.size();
    for (int it = 0; it < 30; ++it) {
      Eigen::MatrixXd J(m, m);
      Eigen::VectorXd f(m);
      for (std::size_t i = 0; i < m; ++i) {
        f(long(i)) = Fd[E[i]].evaluate(x);
        for (std::size_t k = 0; k < m; ++k) J(long(i), long(k)) = uses[E[i]][Y[k]] ? Dd[E[i]][Y[k]].evaluate(x) : 0.0;
      }
      Eigen::VectorXd d = J.fullPivLu().solve(f);
      if (!d.allFinite()) return false;
      double big = 1;
      for (std::size_t k = 0; k < m; ++k) { x[Y[k]] -= d(long(k)); big = (std::max)(big, std::abs(x[Y[k]])); }
      if (d.lpNorm<Eigen::Infinity>() <= tolerance * big) return true;
    }
    return false;
  }

  // The parametric Krawczyk test: the equations E in the unknowns Y with the parameters P over
  // the box U (P[k] in U[k]), around the point x (x[P] in U, x[Y] a near root for x[P]).
  // True with X (per unknown) if K(U, X) lies inside X: then for every parameter value in U
  // there is exactly one root in X. Mean-value form:
  //   K = y - Y F(x) - Y F_P(U, X) (U - x_P) + (I - Y F_Y(U, X)) (X - y).
  bool krawczyk(const std::vector<std::size_t>& E, const std::vector<std::size_t>& Y, const std::vector<std::size_t>& P,
                const std::vector<I>& U, const std::vector<double>& x, std::vector<I>& X) const
  {
    const std::size_t m = Y.size();
    Eigen::MatrixXd JY(m, m), JP(m, P.size());
    for (std::size_t i = 0; i < m; ++i) {
      for (std::size_t k = 0; k < m; ++k) JY(long(i), long(k)) = uses[E[i]][Y[k]] ? Dd[E[i]][Y[k]].evaluate(x) : 0.0;
      for (std::size_t k = 0; k < P.size(); ++k) JP(long(i), long(k)) = uses[E[i]][P[k]] ? Dd[E[i]][P[k]].evaluate(x) : 0.0;
    }
    Eigen::FullPivLU<Eigen::MatrixXd> lu(JY);
    if (!lu.isInvertible()) return false;
    const Eigen::MatrixXd Yi = lu.inverse(), S = Yi * JP;
    if (!Yi.allFinite()) return false;
    // the first guess: the roots' spread for parameters in U (first order), doubled
    std::vector<double> r(m);
    for (std::size_t j = 0; j < m; ++j) {
      double s = 0;
      for (std::size_t k = 0; k < P.size(); ++k) s += std::abs(S(long(j), long(k))) * (std::max)(U[k].sup() - x[P[k]], x[P[k]] - U[k].inf());
      r[j] = 2 * s + 1e-12 * (1 + std::abs(x[Y[j]]));
    }
    CGAL::Protect_FPU_rounding<true> guard;
    std::vector<I> xc(n), xU(n), xX(n);
    for (std::size_t j = 0; j < n; ++j) xc[j] = xU[j] = xX[j] = I(x[j]);
    std::vector<I> g(m);
    for (std::size_t i = 0; i < m; ++i) g[i] = FI[E[i]].evaluate(xc);
    X.assign(m, I(0));
    for (int attempt = 0; attempt < 8; ++attempt) {
      for (std::size_t k = 0; k < P.size(); ++k) xU[P[k]] = U[k];
      for (std::size_t j = 0; j < m; ++j) xU[Y[j]] = I(x[Y[j]] - r[j], x[Y[j]] + r[j]);
      bool inside = true;
      std::vector<I> K(m);
      // the interval derivatives over (U, X), once for all rows
      std::vector<I> FY(m * m, I(0)), FP(m * P.size(), I(0));
      for (std::size_t i = 0; i < m; ++i) {
        for (std::size_t l = 0; l < m; ++l)
          if (uses[E[i]][Y[l]]) FY[i * m + l] = DI[E[i]][Y[l]].evaluate(xU);
        for (std::size_t q = 0; q < P.size(); ++q)
          if (uses[E[i]][P[q]]) FP[i * P.size() + q] = DI[E[i]][P[q]].evaluate(xU);
      }
      for (std::size_t j = 0; j < m; ++j) {
        I k = I(x[Y[j]]);
        for (std::size_t i = 0; i < m; ++i) k -= I(Yi(long(j), long(i))) * g[i];
        for (std::size_t q = 0; q < P.size(); ++q) {
          I s(0);
          for (std::size_t i = 0; i < m; ++i)
            if (uses[E[i]][P[q]]) s += I(Yi(long(j), long(i))) * FP[i * P.size() + q];
          k -= s * (U[q] - I(x[P[q]]));
        }
        for (std::size_t l = 0; l < m; ++l) {
          I s(l == j ? 1 : 0);
          for (std::size_t i = 0; i < m; ++i)
            if (uses[E[i]][Y[l]]) s -= I(Yi(long(j), long(i))) * FY[i * m + l];
          k += s * I(-r[l], r[l]);
        }
        K[j] = k;
        if (!(k.inf() > x[Y[j]] - r[j] && k.sup() < x[Y[j]] + r[j])) inside = false;
      }
      if (inside) { X = K; return true; }
      // epsilon-inflation of the variables that K did not bring inside (inflating the others
      // too would widen their contributions to the failing ones as fast as those grow)
      for (std::size_t j = 0; j < m; ++j) {
        const double k = (std::max)(std::abs(K[j].inf() - x[Y[j]]), std::abs(K[j].sup() - x[Y[j]]));
        if (!(k < r[j])) r[j] = 1.5 * k;
      }
    }
    return false;
  }

  // ---------------------------------------------------------------- block 0's curve

  struct Node
  {
    std::vector<double> p;  // over v0
    std::vector<I> box;     // over v0: the certified point (one coordinate crisp)
  };

  // N's box in the interval type (the input of lift_box())
  static std::vector<IT> node_box(const Node& N)
  {
    std::vector<IT> u;
    for (const auto& x : N.box) u.push_back(to_it(x));
    return u;
  }

  // the variable of block 0 along which the curve runs fastest at p (the largest component of
  // the tangent, the null vector of block 0's Jacobian)
  std::size_t tangent_variable(const std::vector<double>& p) const
  {
    std::vector<double> x(n, 0.0);
    for (std::size_t k = 0; k < v0.size(); ++k) x[v0[k]] = p[k];
    Eigen::MatrixXd J(e0.size(), v0.size());
    for (std::size_t i = 0; i < e0.size(); ++i)
      for (std::size_t k = 0; k < v0.size(); ++k) J(long(i), long(k)) = uses[e0[i]][v0[k]] ? Dd[e0[i]][v0[k]].evaluate(x) : 0.0;
    Eigen::JacobiSVD<Eigen::MatrixXd> svd(J, Eigen::ComputeFullV);
    const Eigen::VectorXd t = svd.matrixV().col(long(v0.size()) - 1);
    std::size_t best = 0;
    for (std::size_t k = 1; k < v0.size(); ++k) if (std::abs(t(long(k))) > std::abs(t(long(best)))) best = k;
    return best;
  }

  // a certified point of block 0's curve near p with coordinate t (local index) fixed at p[t]
  bool make_node(std::vector<double> p, std::size_t t, Node& out) const
  {
    std::vector<std::size_t> Y, P{v0[t]};
    for (std::size_t k = 0; k < v0.size(); ++k) if (k != t) Y.push_back(v0[k]);
    std::vector<double> x(n, 0.0);
    for (std::size_t k = 0; k < v0.size(); ++k) x[v0[k]] = p[k];
    if (!newton(e0, Y, x)) return false;
    std::vector<I> X;
    if (!krawczyk(e0, Y, P, {I(x[v0[t]])}, x, X)) return false;
    out.p.assign(v0.size(), 0.0);
    out.box.assign(v0.size(), I(0));
    for (std::size_t k = 0, y = 0; k < v0.size(); ++k) {
      out.p[k] = x[v0[k]];
      out.box[k] = k == t ? I(x[v0[k]]) : X[y++];
    }
    return true;
  }

  // The box X0 (over v0) that holds block 0's curve between the nodes a and b: false if it
  // cannot be proved that for each t between them there is exactly one curve point in X0.
  bool piece_box(const Node& a, const Node& b, std::vector<I>& X0) const
  {
    const std::size_t t = piece_variable(a, b);
    const I T(std::min(a.box[t].inf(), b.box[t].inf()), std::max(a.box[t].sup(), b.box[t].sup()));
    std::vector<std::size_t> Y, P{v0[t]};
    for (std::size_t k = 0; k < v0.size(); ++k) if (k != t) Y.push_back(v0[k]);
    std::vector<double> x(n, 0.0);
    for (std::size_t k = 0; k < v0.size(); ++k) x[v0[k]] = 0.5 * (a.p[k] + b.p[k]);
    x[v0[t]] = 0.5 * T.inf() + 0.5 * T.sup();
    if (!newton(e0, Y, x)) return false;
    std::vector<I> X;
    if (!krawczyk(e0, Y, P, {T}, x, X)) return false;
    X0.assign(v0.size(), I(0));
    for (std::size_t k = 0, y = 0; k < v0.size(); ++k) X0[k] = k == t ? T : X[y++];
    // both nodes in X0: the curve for their t is the point they hold
    for (std::size_t k = 0; k < v0.size(); ++k)
      if (!(X0[k].inf() <= a.box[k].inf() && a.box[k].sup() <= X0[k].sup() && X0[k].inf() <= b.box[k].inf() && b.box[k].sup() <= X0[k].sup())) return false;
    return true;
  }

  // ---------------------------------------------------------------- the later blocks

  struct Lift
  {
    std::vector<IT> value;  // every variable: X0 on block 0's, the later blocks' boxes
    bool inequality_boundary = false;
    // per later block, the index of its root at the piece's centre: lifts with the same first
    // k entries have the same values in blocks 1 .. k over the whole piece (they agree at the
    // centre, and the Jacobian is regular over the piece, as their Krawczyk tests prove; with
    // paths from Newton, where "the same" is numerical, the completeness test checks it: every
    // lift's box meets the one root box of its path)
    std::vector<std::size_t> path;
  };

  // Block b solved with its inputs the boxes of L (those with `known` set).
  // With `whole`, a chain of unknown boxes does not stop the solve (enclose(): every box counts).
  // (over the search box, or over the boxes of `within` in the block's variables)
  // `coarse` multiplies the minimal width below which a box is left unknown.
  Solver_result<IT> solve_block(std::size_t b, const Lift& L, const std::vector<char>& known, bool whole = false, const Lift* within = nullptr,
                                double coarse = 1)
  {
    const Plan_block& blk = blocks[b];
    Polynomial_system<IT> s;
    for (std::size_t j : blk.variables) {
      s.variable_names.push_back(j < sys.variable_names.size() ? sys.variable_names[j] : "x" + std::to_string(j));
      s.box.push_back(sys.box[j]);
      if (within)
        s.box.back() = {(std::max)(sys.box[j].first, O::lower_double(within->value[j])), (std::min)(sys.box[j].second, O::upper_double(within->value[j]))};
    }
    CGAL::Protect_FPU_rounding<true> guard;  // the products of double intervals round outward
    for (std::size_t i : blk.equations) s.equations.push_back(restrict_polynomial<IT>(FIT[i], blk.variables, L.value, known));
    for (std::size_t q : blk.inequalities) s.inequalities.push_back(restrict_polynomial<IT>(GIT[q], blk.variables, L.value, known));
    Subdivision_solver_parameters q = SP;
    q.maximal_precision = 0;  // interval coefficients: no higher precision to try
    q.maximal_boxes = (std::min)(q.maximal_boxes, PP.block_boxes);
    if (whole) q.positive_dimensional_evidence = 0;
    // the roots for all inputs in the box fill a region about as wide as the inputs: the
    // Krawczyk test must see a box that holds it, not pieces of it
    double input = 0;
    for (std::size_t j = 0; j < n; ++j)
      if (known[j]) input = (std::max)(input, O::upper_double(L.value[j]) - O::lower_double(L.value[j]));
    double width = (std::max)(q.minimal_width, 4 * input);
    if (width == 0 && coarse > 1)  // crisp inputs and the solver's own default: coarser than that
      for (const auto& b : s.box) width = (std::max)(width, 1e-9 * (b.second - b.first));
    q.minimal_width = q.singular_width = coarse * width;
    Solver_result<IT> res = Subdivision_solver<IT>(q).solve(s);
    ++block_solves;
    block_boxes += res.statistics.boxes;
    return res;
  }

  // every lift over the point u of block 0 (inputs crisp), block by block
  bool lift_point(const std::vector<double>& u, std::vector<Lift>& out)
  {
    std::vector<IT> box;
    for (double x : u) box.push_back(O::make(O::bound_from_double(x), O::bound_from_double(x)));
    return lift_box(box, out);
  }

  // every lift over block 0's points in the box u (over v0), block by block: each lift's boxes
  // hold one root for every input in u; false if some block is not resolved there
  bool lift_box(const std::vector<IT>& u, std::vector<Lift>& out)
  {
    Lift start;
    start.value.assign(n, IT(0));
    std::vector<char> known(n, 0);
    for (std::size_t k = 0; k < v0.size(); ++k) {
      start.value[v0[k]] = u[k];
      known[v0[k]] = 1;
    }
    std::vector<Lift> lifts{start};
    for (std::size_t b = 1; b < blocks.size(); ++b) {
      std::vector<Lift> next;
      for (const Lift& L : lifts) {
        Solver_result<IT> res = solve_block(b, L, known);
        if (!res.unresolved.empty()) return false;
        for (std::size_t q = 0; q < res.roots.size(); ++q) {
          const auto& r = res.roots[q];
          if (!r.certified) return false;
          Lift M = L;
          for (std::size_t k = 0; k < blocks[b].variables.size(); ++k) M.value[blocks[b].variables[k]] = r.enclosure[k];
          M.inequality_boundary = M.inequality_boundary || r.on_inequality_boundary;
          M.path.push_back(q);
          next.push_back(M);
        }
      }
      for (std::size_t j : blocks[b].variables) known[j] = 1;
      lifts.swap(next);
    }
    out.swap(lifts);
    return true;
  }

  static bool meet(const IT& a, const IT& b) { return !(O::upper(a) < O::lower(b)) && !(O::upper(b) < O::lower(a)); }
  static IT hull(const IT& a, const IT& b)
  {
    return O::make(O::lower(a) < O::lower(b) ? O::lower(a) : O::lower(b), O::upper(b) < O::upper(a) ? O::upper(a) : O::upper(b));
  }
  // does `box` (over the block's variables) meet the lift's boxes there?
  static bool meets_lift(const std::vector<IT>& box, const Lift& S, const Plan_block& blk)
  {
    for (std::size_t k = 0; k < blk.variables.size(); ++k)
      if (!meet(box[k], S.value[blk.variables[k]])) return false;
    return true;
  }

  // Proves that no lift over the piece continues the partial lift P (blocks before b known):
  // block b and the ones after it, solved with interval coefficients over P's boxes, end
  // without a root in some block (no real root, or every root fails an inequality), with no
  // unresolved box on the way. This accounts for roots of a block that belong to no lift (a
  // circle intersection whose leg fails a later orientation inequality).
  bool dies(std::size_t b, const Lift& P, std::vector<char> known, int depth = 0)
  {
    if (b >= blocks.size() || depth > 64) return false;
    Solver_result<IT> res = solve_block(b, P, known);
    for (std::size_t j : blocks[b].variables) known[j] = 1;
    // every root of block b lies in a root's box or in an unresolved box (where two roots may
    // meet: a fold of this partial lift): each of them must die further on
    for (const auto& r : res.roots) {
      Lift M = P;
      for (std::size_t k = 0; k < blocks[b].variables.size(); ++k) M.value[blocks[b].variables[k]] = r.enclosure[k];
      if (!dies(b + 1, M, known, depth + 1)) return false;
    }
    for (const auto& u : res.unresolved) {
      Lift M = P;
      for (std::size_t k = 0; k < blocks[b].variables.size(); ++k) M.value[blocks[b].variables[k]] = u.box[k];
      if (!dies(b + 1, M, known, depth + 1)) return false;
    }
    return true;
  }

  // The roots of the later blocks above block 0's point u, by Newton from the lifts `from` of
  // the piece before (their boxes' centres), in the order and with the paths lift_point()
  // gives (roots within 1e-9 given one path), those in the search box whose inequalities are
  // not certainly violated at the point (flagged where a sign there is uncertain); not proved
  // to be all of them, nor distinct (duplicates fail the completeness test).
  void centre_by_newton(const std::vector<double>& u, const std::vector<Lift>& from, std::vector<Lift>& out) const
  {
    out.clear();
    std::vector<std::vector<double>> xs;
    for (const Lift& h : from) {
      std::vector<double> x(n, 0.0);
      for (std::size_t k = 0; k < v0.size(); ++k) x[v0[k]] = u[k];
      for (std::size_t j : down) x[j] = mid(h.value[j]);
      if (!newton(down_eq, down, x, 1e-12)) continue;  // its root may have left (a fold): the completeness test tells
      bool keep = true;
      for (std::size_t j : down) keep = keep && x[j] >= sys.box[j].first && x[j] <= sys.box[j].second;
      if (keep) xs.push_back(x);
    }
    CGAL::Protect_FPU_rounding<true> guard;
    std::vector<Lift> lifts;
    for (const auto& x : xs) {
      Lift L;
      L.value.assign(n, IT(0));
      for (std::size_t j = 0; j < n; ++j) L.value[j] = to_it(I(x[j]));
      std::vector<I> xi(x.begin(), x.end());
      bool keep = true;
      for (std::size_t b = 1; b < blocks.size() && keep; ++b)
        for (std::size_t q : blocks[b].inequalities) {
          const I v = GI[q].evaluate(xi);
          if (v.sup() < 0) keep = false;
          else if (!(v.inf() >= 0)) L.inequality_boundary = true;
        }
      if (keep) lifts.push_back(L);
    }
    // the paths: per block, the index of its root among the distinct ones after the same
    // earlier roots, in the solver's order (by value)
    for (auto& L : lifts) L.path.assign(blocks.size() - 1, 0);
    auto same = [&](const Lift& a, const Lift& c, std::size_t b) {
      for (std::size_t j : blocks[b].variables) {
        const double x = mid(a.value[j]), y = mid(c.value[j]);
        if (std::abs(x - y) > 1e-9 * (1 + std::abs(x) + std::abs(y))) return false;
      }
      return true;
    };
    for (std::size_t b = 1; b < blocks.size(); ++b) {
      std::vector<char> done(lifts.size(), 0);
      for (std::size_t g = 0; g < lifts.size(); ++g) {
        if (done[g]) continue;
        std::vector<std::size_t> group;  // the lifts with g's earlier roots
        for (std::size_t m = g; m < lifts.size(); ++m)
          if (std::equal(lifts[m].path.begin(), lifts[m].path.begin() + (b - 1), lifts[g].path.begin())) { group.push_back(m); done[m] = 1; }
        std::vector<std::size_t> roots;  // one member per distinct root of block b
        for (std::size_t m : group) {
          bool fresh = true;
          for (std::size_t r : roots) fresh = fresh && !same(lifts[m], lifts[r], b);
          if (fresh) roots.push_back(m);
        }
        auto value = [&](std::size_t m) {
          std::vector<double> v;
          for (std::size_t j : blocks[b].variables) v.push_back(mid(lifts[m].value[j]));
          return v;
        };
        std::sort(roots.begin(), roots.end(), [&](std::size_t p, std::size_t q) { return value(p) < value(q); });
        for (std::size_t m : group)
          for (std::size_t r = 0; r < roots.size(); ++r)
            if (same(lifts[m], lifts[roots[r]], b)) { lifts[m].path[b - 1] = r; break; }
      }
    }
    std::stable_sort(lifts.begin(), lifts.end(), [](const Lift& a, const Lift& c) { return a.path < c.path; });
    out.swap(lifts);
  }

  // set by lift_piece() when it fails on the set of lifts itself (a root missed, found twice or
  // matched to several lifts): solving the roots at the centre may then succeed where
  // continuing them by Newton did not
  bool lifts_missed = false;
  bool fail_on_lifts(std::string& why, std::string text)
  {
    why = std::move(text);
    lifts_missed = true;
    return false;
  }

  // The lifts over the box X0 of a piece of block 0's curve; false (with `why`) if they
  // cannot all be certified there. With `hint` (the lifts of the piece before), the roots
  // above X0's centre are continued from those by Newton instead of solved (about half the
  // block solves of a piece): the completeness test below then proves that they are all.
  bool lift_piece(const std::vector<I>& X0, std::vector<Lift>& out, std::string& why, const std::vector<Lift>* hint = nullptr)
  {
    out.clear();
    lifts_missed = false;
    std::vector<double> uc(v0.size());
    for (std::size_t k = 0; k < v0.size(); ++k) uc[k] = 0.5 * X0[k].inf() + 0.5 * X0[k].sup();
    std::vector<Lift> centre;
    if (hint)
      centre_by_newton(uc, *hint, centre);
    else if (!lift_point(uc, centre)) { why = "a later block is not resolved above the piece's centre"; return false; }
    for (const Lift& c : centre) {
      std::vector<double> x(n, 0.0);
      for (std::size_t k = 0; k < v0.size(); ++k) x[v0[k]] = uc[k];
      for (std::size_t j : down) x[j] = mid(c.value[j]);
      std::vector<I> X;
      if (!krawczyk(down_eq, down, v0, X0, x, X)) {
        why = "a lift is not unique over the piece (two roots of a later block meet?)";
        return false;
      }
      Lift L = c;
      for (std::size_t k = 0; k < v0.size(); ++k) L.value[v0[k]] = to_it(X0[k]);
      for (std::size_t j = 0; j < down.size(); ++j) L.value[down[j]] = to_it(X[j]);
      out.push_back(L);
    }
    // the lifts' boxes must be disjoint (each holds its own root for every input)
    for (std::size_t p = 0; p < out.size(); ++p)
      for (std::size_t q = 0; q < p; ++q) {
        bool all = true;
        for (std::size_t j : down) all = all && meet(out[p].value[j], out[q].value[j]);
        if (all) return fail_on_lifts(why, "two lifts' boxes overlap");
      }
    // completeness: above each group of lifts agreeing before b (over the hull of their boxes
    // of the blocks before b), block b solved with those boxes as its inputs has the roots the
    // group's lifts give (root boxes and lift boxes meet one to one: every root lies in some
    // root box, each holds one root per input), and roots or unresolved boxes whose partial
    // lifts die (dies())
    if (out.empty()) {
      Lift S;
      S.value.assign(n, IT(0));
      std::vector<char> known(n, 0);
      for (std::size_t k = 0; k < v0.size(); ++k) { S.value[v0[k]] = to_it(X0[k]); known[v0[k]] = 1; }
      if (!dies(1, S, known)) return fail_on_lifts(why, "no lift at the piece's centre, but the later blocks are not proved empty over the piece");
    }
    // Block b is solved once for each group of lifts that agree on the blocks before it: their
    // values there are the same roots (see Lift::path), so the hull of their boxes is the input
    // for all of them (one solve per distinct partial lift: 31 instead of 160 per piece of
    // Jansen's linkage, whose 32 lifts run through 5 blocks)
    std::vector<char> known(n, 0);
    for (std::size_t j : v0) known[j] = 1;
    for (std::size_t b = 1; b < blocks.size(); ++b) {
      const Plan_block& blk = blocks[b];
      std::vector<char> grouped(out.size(), 0);
      for (std::size_t g = 0; g < out.size(); ++g) {
        if (grouped[g]) continue;
        // the group of out[g] (the lifts agreeing with it before b), with the hull of their
        // inputs, and one lift per root of block b among them
        Lift L = out[g];
        std::vector<const Lift*> same, members;
        for (std::size_t m = g; m < out.size(); ++m) {
          const Lift& M = out[m];
          if (!std::equal(M.path.begin(), M.path.begin() + (b - 1), L.path.begin())) continue;
          grouped[m] = 1;
          members.push_back(&M);
          for (std::size_t j = 0; j < n; ++j)
            if (known[j])
              L.value[j] = hull(L.value[j], M.value[j]);
          bool fresh = true;
          for (const Lift* S : same) fresh = fresh && S->path[b - 1] != M.path[b - 1];
          if (fresh) same.push_back(&M);
        }
        // A solve of block b over inputs that contain this group's (kept from a piece this one
        // halves) says where its roots lie for these inputs too: tried first, and solved afresh
        // if the lifts do not match it (its root boxes are wider)
        bool settled = false;
        std::vector<const Lift*> near_boundary;
        if (const Solver_result<IT>* kept = kept_solve(b, L, known, this->kept)) {
          const bool missed = lifts_missed;
          std::string w;
          settled = check_group(b, L, known, *kept, same, members, w, near_boundary, true);
          lifts_missed = missed;
          if (settled) ++kept_solves;
        }
        if (!settled) {
          near_boundary.clear();
          Solver_result<IT> res = solve_block(b, L, known);
          if (res.unresolved.empty() && std::all_of(res.roots.begin(), res.roots.end(), [](const Solver_root<IT>& r) { return r.certified; }) &&
              !kept_solve(b, L, known, recent, true))  // (not twice when the piece is lifted a second time)
            recent.push_back(Kept_solve{b, L, res});
          if (!check_group(b, L, known, res, same, members, why, near_boundary)) return false;
        }
        // a lift whose root may meet an inequality's zero over the piece is marked, as lift_box()
        // marks one at a point
        for (const Lift* S : near_boundary) out[std::size_t(S - out.data())].inequality_boundary = true;
      }
      for (std::size_t j : blk.variables) known[j] = 1;
    }
    return true;
  }

  // Solves of later blocks kept for the halves of the pieces being halved (each holds for all
  // inputs in its box: block b's roots for them lie one in each root box), and the solves of
  // the piece being lifted.
  struct Kept_solve
  {
    std::size_t b;
    Lift L;
    Solver_result<IT> res;
  };
  std::vector<Kept_solve> kept, recent;
  std::size_t kept_solves = 0;
  // the newest solve in `from` of block b over inputs that contain L's (over the known
  // variables), or with `equal`, over exactly L's inputs
  const Solver_result<IT>* kept_solve(std::size_t b, const Lift& L, const std::vector<char>& known, const std::vector<Kept_solve>& from,
                                      bool equal = false) const
  {
    for (auto it = from.rbegin(); it != from.rend(); ++it) {  // the newest first: the narrowest
      const Kept_solve& k = *it;
      if (k.b != b) continue;
      bool in = true;
      for (std::size_t j = 0; j < n && in; ++j) {
        if (!known[j]) continue;
        const auto l = O::lower(L.value[j]), u = O::upper(L.value[j]), kl = O::lower(k.L.value[j]), ku = O::upper(k.L.value[j]);
        in = equal ? l == kl && u == ku : !(l < kl) && !(ku < u);
      }
      if (in) return &k.res;
    }
    return nullptr;
  }

  // lift_piece(): block b solved (`res`) over the inputs L of the group `members` of lifts
  // (`same`: one per root of block b among them) accounts for their roots and no others
  // (`near_boundary` gets the members whose root box over the piece meets an inequality's zero)
  // (`deferred`: the partial lifts that must die after b, which are further block solves, are
  // checked after the matching, so that a kept solve the matching rejects does not cost them)
  bool check_group(std::size_t b, const Lift& L, const std::vector<char>& known, const Solver_result<IT>& res,
                   const std::vector<const Lift*>& same, const std::vector<const Lift*>& members, std::string& why,
                   std::vector<const Lift*>& near_boundary, bool deferred = false)
  {
    const Plan_block& blk = blocks[b];
    std::vector<char> after = known;
    for (std::size_t j : blk.variables) after[j] = 1;
    std::vector<Lift> orphans;  // with `deferred`: the unresolved boxes', then the roots of no lift's
    const std::size_t unresolved = deferred ? res.unresolved.size() : 0;
    for (const auto& u : res.unresolved) {  // no lift's root: fine if nothing in it continues
      Lift M = L;
      for (std::size_t k = 0; k < blk.variables.size(); ++k) M.value[blk.variables[k]] = u.box[k];
      if (deferred) orphans.push_back(std::move(M));
      else if (!dies(b + 1, M, after)) { why = block_name(b) + " over the piece: " + u.reason; return false; }
    }
    std::vector<char> hit(same.size(), 0);
    std::vector<std::size_t> root_of(same.size(), res.roots.size());  // the root each one holds
    for (const auto& root : res.roots) {
      if (!root.certified) { why = block_name(b) + " over the piece: a root not certified"; return false; }
      // the lifts whose boxes meet the root's box
      std::size_t h = same.size(), meets = 0;
      for (std::size_t s = 0; s < same.size(); ++s)
        if (meets_lift(root.enclosure, *same[s], blk)) { h = s; ++meets; }
      if (meets > 1 || (meets == 1 && hit[h])) return fail_on_lifts(why, block_name(b) + " over the piece: a root's box meets several lifts");
      if (meets == 1) { hit[h] = 1; root_of[h] = std::size_t(&root - res.roots.data()); continue; }
      // a root of no lift: its partial lift must die in the blocks after b
      Lift M = L;
      for (std::size_t k = 0; k < blk.variables.size(); ++k) M.value[blk.variables[k]] = root.enclosure[k];
      if (deferred) orphans.push_back(std::move(M));
      else if (!dies(b + 1, M, after)) return fail_on_lifts(why, block_name(b) + " over the piece: a root the lifts do not account for");
    }
    if (std::find(hit.begin(), hit.end(), char(0)) != hit.end()) return fail_on_lifts(why, block_name(b) + " over the piece: a lift's root not found");
    // each lift of the group (not only the one per root above) meets with its box exactly
    // one root's box, which therefore holds its root (every root lies in some root's box),
    // and it is the root of the lift with its path here: so the lifts that share a path
    // share the root, whatever found the paths (the solves at the centre, or Newton)
    for (const Lift* S : members) {
      std::size_t meets = 0, which = res.roots.size();
      for (std::size_t q = 0; q < res.roots.size(); ++q)
        if (meets_lift(res.roots[q].enclosure, *S, blk)) { ++meets; which = q; }
      for (const auto& u : res.unresolved) meets += meets_lift(u.box, *S, blk);
      if (meets != 1) return fail_on_lifts(why, block_name(b) + " over the piece: a lift's box meets several roots' boxes");
      std::size_t r = same.size();
      for (std::size_t t = 0; t < same.size(); ++t)
        if (same[t]->path[b - 1] == S->path[b - 1]) r = t;
      if (r == same.size() || root_of[r] != which) return fail_on_lifts(why, block_name(b) + " over the piece: lifts with one path meet several roots");
      if (res.roots[which].on_inequality_boundary) near_boundary.push_back(S);
    }
    for (std::size_t k = 0; k < orphans.size(); ++k) {
      if (dies(b + 1, orphans[k], after)) continue;
      if (k < unresolved) { why = block_name(b) + " over the piece: " + res.unresolved[k].reason; return false; }
      return fail_on_lifts(why, block_name(b) + " over the piece: a root the lifts do not account for");
    }
    return true;
  }

  // per lift of a, the one lift of b whose later boxes meet its own; false if not a bijection
  bool match(const std::vector<Lift>& a, const std::vector<Lift>& b, std::vector<std::size_t>& to) const
  {
    if (a.size() != b.size()) return false;
    to.assign(a.size(), b.size());
    std::vector<char> taken(b.size(), 0);
    for (std::size_t i = 0; i < a.size(); ++i) {
      for (std::size_t k = 0; k < b.size(); ++k) {
        bool all = true;
        for (std::size_t j : down) all = all && meet(a[i].value[j], b[k].value[j]);
        if (!all) continue;
        if (to[i] != b.size()) return false;  // ambiguous
        to[i] = k;
      }
      if (to[i] == b.size() || taken[to[i]]) return false;
      taken[to[i]] = 1;
    }
    return true;
  }

  // the point of the whole curve above block 0's point p on the lift L (Newton from the
  // centres of its boxes, which hold the root for p)
  // (first from `guess`, the previous point of the branch, when given: a short step)
  std::vector<double> point(const std::vector<double>& p, const Lift& L, const std::vector<double>* guess = nullptr)
  {
    std::vector<double> x(n, 0.0);
    for (std::size_t k = 0; k < v0.size(); ++k) x[v0[k]] = p[k];
    for (int start = guess ? 0 : 1; start < 2; ++start) {
      for (std::size_t j : down) x[j] = start == 0 ? (*guess)[j] : mid(L.value[j]);
      // block by block: each block's root for p is the one in the lift's box
      bool all = true;
      for (std::size_t b = 1; b < blocks.size() && all; ++b) {
        const Plan_block& blk = blocks[b];
        std::vector<double> y = x;
        all = newton(blk.equations, blk.variables, y);
        for (std::size_t j : blk.variables) all = all && O::lower_double(L.value[j]) <= y[j] && y[j] <= O::upper_double(L.value[j]);
        if (all) x = y;
      }
      if (all) return x;
    }
    // Newton left a box (two roots of a block close together, next to a fold): each block
    // solved at p inside the lift's boxes, where its root for p is the only one
    {
      Lift Q = L;
      std::vector<char> known(n, 0);
      for (std::size_t k = 0; k < v0.size(); ++k) {
        Q.value[v0[k]] = O::make(O::bound_from_double(p[k]), O::bound_from_double(p[k]));
        known[v0[k]] = 1;
      }
      bool all = true;
      for (std::size_t b = 1; b < blocks.size() && all; ++b) {
        Solver_result<IT> r;
        try {
          r = solve_block(b, Q, known, false, &L);
        } catch (const Input_error&) {
          all = false;
          break;
        }
        all = r.roots.size() == 1;
        for (std::size_t k = 0; k < blocks[b].variables.size() && all; ++k) {
          const std::size_t j = blocks[b].variables[k];
          x[j] = r.roots[0].approximation[k];
          Q.value[j] = O::make(O::bound_from_double(x[j]), O::bound_from_double(x[j]));
          known[j] = 1;
        }
      }
      if (all) return x;
    }
    for (std::size_t j : down) x[j] = mid(L.value[j]);  // max_residual tells
    return x;
  }

  // ---------------------------------------------------------------- folds

  std::size_t fold_traces = 0, fold_trace_boxes = 0, enclose_solves = 0, coarse_solves = 0, lifted_arcs = 0;
  std::vector<std::size_t> leaf_piece;  // per leaf of enclose(): the piece (index in X0s) it lies above
  std::vector<char> leaf_certified;     // per leaf: made of certified roots only, none merged
  std::size_t current_piece = 0;

  // Replaces boxes that meet (directly or through others) by their hulls, until no two meet:
  // passes of union-find over all pairs, since a hull may meet boxes its parts did not.
  static void merge_touching(std::vector<std::vector<IT>>& boxes)
  {
    for (std::size_t count = 0; count != boxes.size();) {
      count = boxes.size();
      std::vector<std::size_t> root(count);
      for (std::size_t p = 0; p < count; ++p) root[p] = p;
      auto find = [&](std::size_t p) { while (root[p] != p) p = root[p] = root[root[p]]; return p; };
      for (std::size_t p = 0; p < count; ++p)
        for (std::size_t q = p + 1; q < count; ++q) {
          bool all = true;
          for (std::size_t k = 0; k < boxes[p].size() && all; ++k) all = meet(boxes[p][k], boxes[q][k]);
          if (all) root[find(q)] = find(p);
        }
      std::vector<std::vector<IT>> hulls;
      std::vector<std::size_t> index(count, count);
      for (std::size_t p = 0; p < count; ++p) {
        const std::size_t r = find(p);
        if (index[r] == count) { index[r] = hulls.size(); hulls.push_back(boxes[p]); continue; }
        std::vector<IT>& h = hulls[index[r]];
        for (std::size_t k = 0; k < h.size(); ++k)
          h[k] = O::make(O::bound_from_double((std::min)(O::lower_double(h[k]), O::lower_double(boxes[p][k]))),
                         O::bound_from_double((std::max)(O::upper_double(h[k]), O::upper_double(boxes[p][k]))));
      }
      boxes.swap(hulls);
    }
  }

  // Boxes in all the variables that together hold every solution above the box of P's block-0
  // values: block b and the ones after it solved over the boxes of P, branching over each
  // root's box and each hull of touching unresolved boxes. False if there would be more than
  // `fold_leaves` leaves, or block solves since enclose_solves was last reset (branches that
  // die cost a solve each, too). Each leaf's piece (current_piece) and whether it is made of
  // certified roots only go to leaf_piece and leaf_certified.
  bool enclose(std::size_t b, const Lift& P, std::vector<char> known, std::vector<std::vector<IT>>& leaves, bool certified = true)
  {
    if (b >= blocks.size()) {
      leaves.push_back(P.value);
      leaf_piece.push_back(current_piece);
      leaf_certified.push_back(certified);
      return leaves.size() <= PP.fold_leaves;
    }
    if (++enclose_solves > PP.fold_leaves) return false;
    Solver_result<IT> res = solve_block(b, P, known, true);
    // where two roots of the block meet over P (a fold) they move fast, through a thin region
    // that boxes of the minimal width cover only beyond the block's box budget: the boxes left
    // pending are large (on Jansen's linkage the whole 400-wide box of a point, and the blocks
    // after it enclosed over that), so the block is solved again with boxes left unknown at 16,
    // 256, 4096 and 65536 times the minimal width, until none is left pending by the box budget:
    // fewer and larger boxes, still around the fold (each solve counts against fold_leaves; what
    // is still pending after the last is branched over like any unresolved box)
    auto out_of_boxes = [](const Solver_result<IT>& r) {
      for (const auto& u : r.unresolved)
        if (u.kind == Box_class::PENDING && u.reason.find("box budget") != std::string::npos) return true;
      return false;
    };
    for (double coarse = 16; out_of_boxes(res) && coarse <= 65536; coarse *= 16) {
      if (++enclose_solves > PP.fold_leaves) return false;
      ++coarse_solves;
      res = solve_block(b, P, known, true, nullptr, coarse);
    }
    for (std::size_t j : blocks[b].variables) known[j] = 1;
    // every root of the block lies in a root's box or an unresolved box, unknown or pending
    // (the solver drops none): touching boxes are branched over as one hull (they are where two
    // roots meet, the fold), so that a chain of unresolved boxes costs one branch, not one each
    std::vector<std::vector<IT>> parts;
    bool roots_only = res.unresolved.empty();
    for (const auto& r : res.roots) {
      parts.push_back(r.enclosure);
      roots_only = roots_only && r.certified;
    }
    for (const auto& u : res.unresolved) parts.push_back(u.box);
    const std::size_t unmerged = parts.size();
    merge_touching(parts);
    roots_only = roots_only && parts.size() == unmerged;  // no two roots' boxes became one
    for (const auto& part : parts) {
      Lift M = P;
      for (std::size_t k = 0; k < blocks[b].variables.size(); ++k) M.value[blocks[b].variables[k]] = part[k];
      if (!enclose(b + 1, M, known, leaves, certified && roots_only)) return false;
    }
    return true;
  }

  // An arc of the whole curve over a piece that failed: its ends are at node a (0) or b (1) of
  // the piece, or true ends of the curve (-1: the search box's boundary, an inequality's).
  struct Arc
  {
    Solution_curve<IT> curve;
    int node[2] = {-1, -1};
  };

  // the piece's variable t (the one piece_box() and the halving fix): the largest change
  // between the nodes
  std::size_t piece_variable(const Node& a, const Node& b) const
  {
    std::size_t t = 0;
    for (std::size_t k = 1; k < v0.size(); ++k)
      if (std::abs(b.p[k] - a.p[k]) > std::abs(b.p[t] - a.p[t])) t = k;
    return t;
  }

  // Is p (in all the variables) on block 0's side at node N: on the face x_t = N's t, with
  // block 0's values in N's box (both up to d relative)?
  bool at_node(const std::vector<double>& p, const Node& N, std::size_t t, double d) const
  {
    if (std::abs(p[v0[t]] - N.box[t].inf()) > d * (1 + std::abs(p[v0[t]]))) return false;
    for (std::size_t k = 0; k < v0.size(); ++k) {
      const double e = d * (1 + std::abs(p[v0[k]]));
      if (p[v0[k]] < N.box[k].inf() - e || p[v0[k]] > N.box[k].sup() + e) return false;
    }
    return true;
  }

  // The whole curve over a run of consecutive pieces (the boxes X0s, nodes a and b at its ends,
  // one variable t for all) whose lifts failed (two roots of a later block meet above it:
  // the whole curve turns back over block 0 there, or its branches cross), traced by
  // trace_curves() on the whole system in small boxes. Every solution above the run lies in
  // the leaves of enclose() over its X0s; the hulls of overlapping leaves, widened in the later
  // variables (so that no solution lies on those faces) and with the hull of the X0s in block
  // 0's (block 0's curve meets it at the faces x_t = t_a and t_b only at the two nodes: each X0
  // holds one curve point per t), are the boxes traced. So an arc ends at a node, at the search box's
  // boundary or at an inequality; an arc ending anywhere else, or any unresolved region (a
  // singular point of the whole curve, an arc not certified, a budget) leaves the piece
  // unresolved. At most PP.fold_boxes boxes for the whole run.
  // `nodes`: the run's nodes in order (a, the nodes between its pieces, b: one more than X0s).
  bool trace_fold(const std::vector<const Node*>& nodes, std::size_t t, const std::vector<std::vector<I>>& X0s,
                  const Curve_tracer_parameters& tracer, std::vector<Arc>& arcs, std::string& why)
  {
    leaf_piece.clear();
    leaf_certified.clear();
    arcs.clear();
    if (PP.fold_boxes == 0 || X0s.empty()) return false;
    const Node &a = *nodes.front(), &b = *nodes.back();
    std::vector<I> X0 = X0s.front();
    std::vector<std::vector<IT>> leaves;
    for (const auto& X : X0s) {
      current_piece = std::size_t(&X - X0s.data());
      enclose_solves = 0;  // at most fold_leaves block solves for each piece
      Lift S;
      S.value.assign(n, IT(0));
      std::vector<char> known(n, 0);
      for (std::size_t k = 0; k < v0.size(); ++k) {
        S.value[v0[k]] = to_it(X[k]);
        known[v0[k]] = 1;
        X0[k] = I((std::min)(X0[k].inf(), X[k].inf()), (std::max)(X0[k].sup(), X[k].sup()));
      }
      if (!enclose(1, S, known, leaves)) { why += "; the later blocks could not be enclosed over it"; return false; }
    }
    // clusters: the leaves (over the later variables) widened, hulls of those that meet
    const std::size_t m = down.size();
    std::vector<std::vector<IT>> clusters;
    for (const auto& L : leaves) {
      std::vector<IT> c(m);
      for (std::size_t j = 0; j < m; ++j) {
        const double x = O::lower_double(L[down[j]]), y = O::upper_double(L[down[j]]), w = 0.01 * (y - x);
        c[j] = O::make(O::bound_from_double(x - w - 1e-9 * (1 + std::abs(x))), O::bound_from_double(y + w + 1e-9 * (1 + std::abs(y))));
      }
      clusters.push_back(c);
    }
    merge_touching(clusters);
    Curve_tracer_parameters q = tracer;
    // the faces of a small box around a fold in many variables need more boxes than the
    // tracer's default before the box is proved regular (Jansen's linkage: 10000 to 20000)
    if (q.face_boxes == 0 && n > 4) q.face_boxes = 4000 * (n - 3);
    std::size_t budget = (std::min)(q.maximal_boxes, PP.fold_boxes);
    const double d = 4 * (std::max)(q.tolerance, 1e-14);
    for (const auto& cluster : clusters) {
      Arc lifted;
      if (lift_cluster(cluster, leaves, nodes, lifted)) {
        arcs.push_back(std::move(lifted));
        continue;
      }
      if (budget == 0) { why += "; traced around it: box budget exhausted"; return false; }
      q.maximal_boxes = budget;
      Polynomial_system<NT> h = sys;
      for (std::size_t k = 0; k < v0.size(); ++k) {
        double l = X0[k].inf(), u = X0[k].sup();
        if (k != t) {  // a margin around X0, which holds block 0's curve for t in T: none of it is on
                       // these faces (another branch within the margin ends an arc away from the
                       // nodes, and the run fails)
          const double w = 0.01 * (u - l) + 1e-12 * (1 + std::abs(l) + std::abs(u));
          l -= w;
          u += w;
        }
        h.box[v0[k]] = {(std::max)(l, sys.box[v0[k]].first), (std::min)(u, sys.box[v0[k]].second)};
      }
      for (std::size_t j = 0; j < m; ++j)
        h.box[down[j]] = {(std::max)(O::lower_double(cluster[j]), sys.box[down[j]].first), (std::min)(O::upper_double(cluster[j]), sys.box[down[j]].second)};
      Curve_result<IT> r = trace_curves<IT>(h, q);
      ++fold_traces;
      fold_trace_boxes += r.statistics.boxes;
      budget -= (std::min)(budget, r.statistics.boxes);
      if (!r.unresolved.empty()) { why += "; traced around it: " + r.unresolved.front().reason; return false; }
      for (const auto& curve : r.curves) {
        if (!curve.certified) { why += "; traced around it: an arc not certified"; return false; }
        Arc A;
        A.curve = curve;
        if (!curve.closed)
          for (int e = 0; e < 2; ++e) {
            const std::vector<double>& p = e == 0 ? curve.points.front() : curve.points.back();
            if (curve.ends[e] == Curve_end::INEQUALITY) continue;
            if (curve.ends[e] != Curve_end::BOUNDARY) { why += "; traced around it: an arc ends inside"; return false; }
            A.node[e] = at_node(p, a, t, d) ? 0 : at_node(p, b, t, d) ? 1 : -1;
            if (A.node[e] >= 0) continue;
            bool search_face = false;  // a true end of the curve: it leaves the search box
            for (std::size_t j = 0; j < n && !search_face; ++j) {
              const double e2 = d * (1 + std::abs(p[j]));
              search_face = (std::abs(p[j] - sys.box[j].first) <= e2 && h.box[j].first == sys.box[j].first) ||
                            (std::abs(p[j] - sys.box[j].second) <= e2 && h.box[j].second == sys.box[j].second);
            }
            if (!search_face) { why += "; traced around it: an arc leaves the box away from the nodes"; return false; }
          }
        arcs.push_back(std::move(A));
      }
    }
    return true;
  }

  // A cluster (over the later variables) that holds one leaf of enclose() above each of the
  // run's pieces (one fewer than its nodes), each of certified roots only, and no other leaf, holds exactly one
  // solution above every point of block 0's curve over the run (each leaf holds one per input,
  // enclose() holds them all, and the clusters are disjoint), continuous: one arc from the run's
  // first node to its last, without tracing (on Jansen's linkage most clusters of a run, the
  // branches that do not fold there). Its points: the nodes, the later variables by Newton inside
  // the leaves. False if the cluster is not of that kind, or Newton leaves a leaf.
  bool lift_cluster(const std::vector<IT>& cluster, const std::vector<std::vector<IT>>& leaves, const std::vector<const Node*>& nodes, Arc& A)
  {
    const std::size_t pieces = nodes.size() - 1;
    std::vector<std::size_t> mine(pieces, leaves.size());
    for (std::size_t l = 0; l < leaves.size(); ++l) {
      bool in = true;
      for (std::size_t j = 0; j < down.size() && in; ++j) in = meet(leaves[l][down[j]], cluster[j]);
      if (!in) continue;
      if (!leaf_certified[l] || mine[leaf_piece[l]] != leaves.size()) return false;
      mine[leaf_piece[l]] = l;
    }
    for (std::size_t k = 0; k < pieces; ++k)
      if (mine[k] == leaves.size()) return false;
    A = Arc();
    A.curve.ends[0] = A.curve.ends[1] = Curve_end::BOUNDARY;
    A.node[0] = 0;
    A.node[1] = 1;
    for (std::size_t k = 0; k <= pieces; ++k) {
      const std::vector<IT>& L = leaves[mine[(std::min)(k, pieces - 1)]];  // node k lies in piece k's X0 (the last: in the last piece's)
      std::vector<double> x(n, 0.0);
      for (std::size_t q = 0; q < v0.size(); ++q) x[v0[q]] = nodes[k]->p[q];
      for (std::size_t j : down) x[j] = mid(L[j]);
      if (!newton(down_eq, down, x)) return false;
      for (std::size_t j : down)
        if (x[j] < O::lower_double(L[j]) || x[j] > O::upper_double(L[j])) return false;
      A.curve.points.push_back(x);
    }
    for (std::size_t k = 0; k < pieces; ++k) A.curve.boxes.push_back(leaves[mine[k]]);  // the arc lies in their union
    ++lifted_arcs;
    return true;
  }

  // Of the lifts Q over a node, the one whose boxes (later variables) come within d of the arc
  // end p, if exactly one does (the arc's crossing of the node's face is certified within the
  // tracer's tolerance of p, and it is one of the roots Q hold); else Q.size().
  std::size_t point_of_end(const std::vector<Lift>& Q, const std::vector<double>& p, double d) const
  {
    std::size_t found = Q.size(), count = 0;
    for (std::size_t q = 0; q < Q.size(); ++q) {
      bool near = true;
      for (std::size_t j : down) {
        const double e = d * (1 + std::abs(p[j]));
        near = near && O::lower_double(Q[q].value[j]) - e <= p[j] && p[j] <= O::upper_double(Q[q].value[j]) + e;
      }
      if (near) { found = q; ++count; }
    }
    return count == 1 ? found : Q.size();
  }

  // Of the lifts Q over a node, the one whose boxes meet those of the lift L of a piece that
  // holds the node (L's boxes hold its root above every point of the piece), if exactly one.
  std::size_t point_of_lift(const std::vector<Lift>& Q, const Lift& L) const
  {
    std::size_t found = Q.size(), count = 0;
    for (std::size_t q = 0; q < Q.size(); ++q) {
      bool all = true;
      for (std::size_t j : down) all = all && meet(Q[q].value[j], L.value[j]);
      if (all) { found = q; ++count; }
    }
    return count == 1 ? found : Q.size();
  }

  // ---------------------------------------------------------------- pieces

  struct Piece
  {
    Node a, b;
    bool ok = false;
    std::string why;
    std::vector<I> X0;
    std::vector<Lift> lifts;
    bool resolved = false;  // failed, but traced whole around the fold (arcs)
    std::vector<Arc> arcs;
  };

  static bool same_node(const Node& x, const Node& y) { return x.p == y.p; }

  // block 0's curve from node a to node b, halved where it cannot be lifted
  void pieces_between(const Node& a, const Node& b, unsigned depth, std::vector<Piece>& out)
  {
    Piece P;
    P.a = a;
    P.b = b;
    ++pieces;
    recent.clear();
    if (!piece_box(a, b, P.X0)) { P.why = "block 0's curve not certified between two of its points"; P.X0.clear(); }
    else {
      // first from the lifts of the piece before (it ends where this one starts), then, if
      // that fails for a reason that the roots at the centre may change (a root missed or
      // found twice by Newton; not a lift that is not unique over the piece or a block not
      // resolved over it), from the roots solved at the centre
      const Piece* before = out.empty() ? nullptr : &out.back();
      if (before && before->ok && !before->lifts.empty() && same_node(before->b, a)) {
        P.ok = lift_piece(P.X0, P.lifts, P.why, &before->lifts);
        if (!P.ok && lifts_missed) {
          P.why.clear();
          P.ok = lift_piece(P.X0, P.lifts, P.why);
        }
      } else
        P.ok = lift_piece(P.X0, P.lifts, P.why);
    }
    if (P.ok || depth >= PP.maximal_halvings) { out.push_back(std::move(P)); return; }
    // halve: the node at the middle value of the piece's fastest variable
    const std::size_t t = piece_variable(a, b);
    std::vector<double> m(v0.size());
    for (std::size_t k = 0; k < v0.size(); ++k) m[k] = 0.5 * (a.p[k] + b.p[k]);
    Node M;
    if (!(std::abs(b.p[t] - a.p[t]) > 0) || !make_node(m, t, M)) { out.push_back(std::move(P)); return; }
    ++halvings;
    // the halves' block solves are tried first from this piece's (about a third fewer block
    // solves on Jansen's linkage)
    const std::size_t mark = kept.size();
    for (Kept_solve& k : recent) kept.push_back(std::move(k));
    pieces_between(a, M, depth + 1, out);
    pieces_between(M, b, depth + 1, out);
    kept.resize(mark);
  }
};

// The blocks of a plan with one degree of freedom as trace_curves_with_plan() lifts them: the
// curve block merged with the blocks it depends on (directly or not: square blocks whose
// finitely many roots it takes as inputs), so that block 0 is a curve without inputs (traced
// whole: one curve for each root of those blocks), then the other blocks in the plan's order.
// An inequality of a merged block that needs a variable of a block not merged (the plan puts
// it where its last variable is solved, which may be the curve block although a square block
// before it is not an input) moves to the first block after which all its variables are known.
// plan_index, if given,
// receives each block's index in the plan (block 0: the curve block's), for messages.
// Throws Input_error if the plan has no curve block or a block that is not square.
inline std::vector<Plan_block> curve_block_first(const Solution_plan& plan, std::vector<std::size_t>* plan_index = nullptr)
{
  const auto& blocks = plan.blocks();
  std::size_t c = blocks.size();
  for (std::size_t b = 0; b < blocks.size(); ++b) {
    if (blocks[b].dimension() == 1 && c == blocks.size()) { c = b; continue; }
    if (blocks[b].dimension() != 0)
      throw Input_error("trace_curves_with_plan: block " + std::to_string(b) + " has " + std::to_string(blocks[b].equations.size()) + " equation(s) in " +
                        std::to_string(blocks[b].variables.size()) + " variable(s): only one curve block and square blocks can be traced");
  }
  if (plan.structure() != Solution_plan::ONE_DEGREE_OF_FREEDOM || c == blocks.size())
    throw Input_error("trace_curves_with_plan: the plan has no curve block (one equation fewer than variables)");
  std::vector<char> merged(blocks.size(), 0);
  merged[c] = 1;
  for (std::size_t b = c + 1; b-- > 0;)  // depends_on points to earlier blocks only
    if (merged[b])
      for (std::size_t d : blocks[b].depends_on) merged[d] = 1;
  std::vector<Plan_block> out(1);
  std::vector<std::size_t> index(1, c);
  for (std::size_t b = 0; b < blocks.size(); ++b) {
    if (!merged[b]) { out.push_back(blocks[b]); index.push_back(b); continue; }
    Plan_block& f = out[0];
    f.equations.insert(f.equations.end(), blocks[b].equations.begin(), blocks[b].equations.end());
    f.variables.insert(f.variables.end(), blocks[b].variables.begin(), blocks[b].variables.end());
    f.inequalities.insert(f.inequalities.end(), blocks[b].inequalities.begin(), blocks[b].inequalities.end());
  }
  for (auto* v : {&out[0].equations, &out[0].variables, &out[0].inequalities}) std::sort(v->begin(), v->end());
  // the block of out that solves each variable
  std::vector<std::size_t> where(plan.number_of_variables(), Solution_plan::none);
  for (std::size_t b = 0; b < out.size(); ++b)
    for (std::size_t j : out[b].variables) where[j] = b;
  std::vector<std::size_t> keep;
  for (std::size_t q : out[0].inequalities) {
    std::size_t last = 0;
    for (std::size_t j : plan.inequality_variables(q))
      if (where[j] != Solution_plan::none) last = (std::max)(last, where[j]);
    if (last == 0) keep.push_back(q);
    else {
      auto& to = out[last].inequalities;
      to.insert(std::upper_bound(to.begin(), to.end(), q), q);
    }
  }
  out[0].inequalities = keep;
  // depends_on and inputs are not used by the lifts (each block is solved with every variable
  // solved before it known), nor kept consistent with the new order
  for (auto& b : out) {
    b.depends_on.clear();
    b.inputs.clear();
  }
  if (plan_index) *plan_index = index;
  return out;
}

} // namespace internal

/*!
\ingroup PkgRigidIncidenceSolver
\brief The real solution curves of a system with one degree of freedom, traced along its
solution plan: the plan's curve block by `trace_curves()`, the square blocks after it lifted
over short certified pieces of it.

The plan (`Solution_plan`, structure `ONE_DEGREE_OF_FREEDOM`) must have one curve block (one
equation fewer than variables) and square blocks otherwise, as Jansen's linkage has (the crank,
then one point at a time). Block 0 is the curve block merged with the square blocks it depends
on, directly or not (their finitely many roots are its inputs: merged, its curve is one curve for
each of their roots); the other blocks follow in the plan's order. Block 0 is traced by
`trace_curves()`; its polyline points become certified nodes of its curve, and between
consecutive nodes a parametric Krawczyk test proves the piece of curve inside a narrow box X0.
Over X0 each later block's roots at the centre are continued by a parametric Krawczyk test on
all later blocks together (one root in a box for every input in X0: the lift is single-valued
and continuous over the piece), and each later block is solved again over the lifts' boxes with
interval coefficients to prove they are all its roots there (with its inequalities: the
physical branch only). Lifts of consecutive pieces are joined where their boxes meet (a
bijection). A piece that fails is halved, at most `plan_parameters.maximal_halvings` times. A
run of pieces that still fail (two roots of a later block meet there: a fold, where the whole
curve turns back over block 0, or a singular point of the whole curve) is traced whole: every
solution above it is boxed by solving the later blocks over it (at most
`plan_parameters.fold_leaves` boxes), `trace_curves()` traces the whole system in those boxes
(at most `plan_parameters.fold_boxes` boxes) and its arcs are joined at the run's two nodes to
the lifts there, one to one. Where that fails the run becomes an unresolved region where the
chains of lifts end, uncertified. A closed branch of block 0 closes its lifts after one or more
turns. Each polyline point is a node with the later blocks' values by Newton in their boxes.

A branch is certified when block 0's branch is and every piece of it was lifted or traced whole
and joined, so that the branch is the whole solution curve above block 0's branch, its points
within `max_residual` of the curve. Caveat: the chain of pieces follows block 0's polyline
through nodes certified next to its points; that the chain is the tracer's branch (and not a
branch within 1e-12 of it) rests on the tracer's polyline accuracy.

\throws Input_error if `plan` was not made for `system` (different numbers of variables,
equations or inequalities), if the plan has no curve block or a block that is neither square nor the
curve block (use `trace_curves()` on the whole system).
*/
template <class IT = CGAL::Interval_nt<false>, class NT>
Curve_result<IT> trace_curves_with_plan(const Polynomial_system<NT>& system_in, const Solution_plan& plan,
                                        const Curve_tracer_parameters& tracer = Curve_tracer_parameters(),
                                        const Subdivision_solver_parameters& solver = Subdivision_solver_parameters(),
                                        const Plan_trace_parameters& plan_parameters = Plan_trace_parameters())
{
  const auto start = std::chrono::steady_clock::now();
  Polynomial_system<NT> scaled;  // exact powers of two against coefficients beyond doubles
  const Polynomial_system<NT>& system = internal::scaled_to_unit(system_in, scaled);
  internal::check_plan(system, plan, "trace_curves_with_plan");
  std::vector<std::size_t> plan_index;
  const std::vector<Plan_block> blocks = internal::curve_block_first(plan, &plan_index);
  const std::size_t n = system.number_of_variables();
  typedef internal::Plan_trace_run<IT, NT> Run;
  typedef typename Run::Lift Lift;
  typedef typename Run::Piece Piece;
  typedef typename Run::Node Node;
  Run run(system, blocks, solver, plan_parameters);
  run.plan_index = plan_index;
  const auto& v0 = run.v0;

  // block 0 on its own variables
  Polynomial_system<NT> s0;
  auto renumber = [&](const Sparse_polynomial<NT>& f) { return internal::renumbered(f, v0); };
  for (std::size_t j : v0) {
    s0.variable_names.push_back(j < system.variable_names.size() ? system.variable_names[j] : "x" + std::to_string(j));
    s0.box.push_back(system.box[j]);
  }
  auto in_block0 = [&](const Sparse_polynomial<NT>& f, const std::string& what) {
    for (std::size_t j : f.variables())
      if (!std::binary_search(v0.begin(), v0.end(), j))  // the plan does not match the system
        throw Input_error("trace_curves_with_plan: " + what + " of the curve block involves a variable it does not solve (" +
                          (j < system.variable_names.size() ? system.variable_names[j] : "x" + std::to_string(j)) + "): a plan of another system?");
    return renumber(f);
  };
  for (std::size_t i : blocks[0].equations) s0.equations.push_back(in_block0(system.equations[i], "equation " + std::to_string(i + 1)));
  for (std::size_t q : blocks[0].inequalities) s0.inequalities.push_back(in_block0(system.inequalities[q], "inequality " + std::to_string(q + 1)));
  Curve_result<IT> c0 = trace_curves<IT>(s0, tracer);

  Curve_result<IT> out;
  out.statistics = c0.statistics;
  auto whole_box = [&](const std::vector<IT>& b0) {
    std::vector<IT> b;
    for (std::size_t j = 0; j < n; ++j) b.push_back(run.search(j));
    for (std::size_t k = 0; k < v0.size(); ++k) b[v0[k]] = b0[k];
    return b;
  };
  // block 0's regions, in the whole system's variables (their indices stay the branches' end_region)
  for (const auto& u : c0.unresolved) {
    Solver_unresolved<IT> v = u;
    v.box = whole_box(u.box);
    out.unresolved.push_back(v);
  }
  for (const auto& c : c0.curves) {
    // nodes at block 0's polyline points (a closed polyline's last point is its first)
    std::vector<Node> nodes;
    bool nodes_ok = true;
    std::size_t count = c.points.size();
    if (c.closed && count > 1) {
      double d = 0;
      for (std::size_t k = 0; k < v0.size(); ++k) d = (std::max)(d, std::abs(c.points.front()[k] - c.points.back()[k]));
      if (d < 1e-9) --count;
    }
    for (std::size_t p = 0; p < count && nodes_ok; ++p) {
      Node N;
      nodes_ok = run.make_node(c.points[p], run.tangent_variable(c.points[p]), N);
      nodes.push_back(N);
    }
    if (!nodes_ok || nodes.size() < 2) {
      Solver_unresolved<IT> v;
      v.reason = "block 0's polyline point not certified as a point of its curve";
      std::vector<IT> b0;
      for (std::size_t k = 0; k < v0.size(); ++k) {
        double lo = c.points.front()[k], hi = lo;
        for (const auto& p : c.points) { lo = (std::min)(lo, p[k]); hi = (std::max)(hi, p[k]); }
        b0.push_back(Run::to_it(typename Run::I(lo, hi)));
      }
      v.box = whole_box(b0);
      out.unresolved.push_back(v);
      continue;
    }
    std::vector<Piece> pieces;
    const std::size_t spans = c.closed ? nodes.size() : nodes.size() - 1;
    for (std::size_t s = 0; s < spans; ++s) run.pieces_between(nodes[s], nodes[(s + 1) % nodes.size()], 0, pieces);
    const std::size_t P = pieces.size();
    if (c.closed) {  // start at a piece that was lifted: a run of failed pieces then never wraps around
      std::size_t r = 0;
      while (r < P && !pieces[r].ok) ++r;
      if (r < P) std::rotate(pieces.begin(), pieces.begin() + long(r), pieces.end());
    }
    // runs of consecutive failed pieces along one variable, traced whole around their folds
    // (a fold at a node between two pieces lies inside the run); the arcs go to the run's first
    // piece, first[s] is the run's first piece for every piece of it
    // the lifts above the node where piece q starts (null: some block not resolved there),
    // solved once: the stretch cuts and the joins below both ask
    std::vector<char> node_lifted(P, 0);
    std::vector<std::optional<std::vector<Lift>>> node_lifts(P);
    auto lifts_at_node = [&](std::size_t q) -> const std::vector<Lift>* {
      if (!node_lifted[q]) {
        node_lifted[q] = 1;
        std::vector<Lift> Q;
        if (run.lift_box(Run::node_box(pieces[q].a), Q)) node_lifts[q] = std::move(Q);
      }
      return node_lifts[q] ? &*node_lifts[q] : nullptr;
    };
    std::vector<std::size_t> first(P), last(P);
    for (std::size_t s = 0; s < P; ++s) first[s] = last[s] = s;
    for (std::size_t s = 0; s < P;) {
      if (pieces[s].ok || pieces[s].X0.empty()) { ++s; continue; }
      const std::size_t t = run.piece_variable(pieces[s].a, pieces[s].b);
      std::size_t e = s + 1;
      while (e < P && !pieces[e].ok && !pieces[e].X0.empty() && run.piece_variable(pieces[e].a, pieces[e].b) == t &&
             (pieces[e].b.p[t] - pieces[e].a.p[t]) * (pieces[s].b.p[t] - pieces[s].a.p[t]) > 0)
        ++e;
      // is every lift above the node where piece q starts certified (a place to cut the run)?
      auto liftable = [&](std::size_t q) { return lifts_at_node(q) != nullptr; };
      // pieces a .. z-1 traced whole (halving a stretch that fails, down to its failing part,
      // was measured on Jansen's linkage: 628 s instead of 396 s, for the same branches)
      auto stretch = [&](std::size_t a, std::size_t z) {
        std::vector<std::vector<typename Run::I>> X0s;
        for (std::size_t q = a; q < z; ++q) X0s.push_back(pieces[q].X0);
        std::string why;
        std::vector<const Node*> nodes{&pieces[a].a};
        for (std::size_t q = a; q < z; ++q) nodes.push_back(&pieces[q].b);
        if (run.trace_fold(nodes, t, X0s, tracer, pieces[a].arcs, why)) {
          for (std::size_t q = a; q < z; ++q) {
            pieces[q].resolved = true;
            first[q] = a;
            last[q] = z - 1;
          }
          return;
        }
        for (std::size_t q = a; q < z; ++q) pieces[q].why += why;
      };
      // a long run in stretches of about plan_parameters.fold_stretch pieces, cut at nodes
      // where the lifts are certified: smaller boxes around each fold
      const std::size_t length = (std::max<std::size_t>)(1, plan_parameters.fold_stretch);
      for (std::size_t a = s; a < e;) {
        std::size_t z = e;
        if (e - a > 2 * length)
          for (std::size_t q = a + length; q + length <= e; ++q)
            if (liftable(q)) { z = q; break; }
        stretch(a, z);
        a = z;
      }
      s = e;
    }
    // node s is piece s's end a; on a closed branch node P is node 0
    auto node_id = [&](std::size_t s, int side) { return long(c.closed ? (s + std::size_t(side)) % P : s + std::size_t(side)); };
    // the region where a chain that stops at a node ends: the failed piece next to it, or the
    // node itself if the lifts could not be joined there
    // (one region for each stretch of consecutive pieces that failed, with the first one's reason)
    std::vector<long> node_region(P + 1, -1);
    for (std::size_t s = 0; s < P;) {
      if (pieces[s].ok || pieces[s].resolved) { ++s; continue; }
      std::size_t e = s + 1;
      while (e < P && !pieces[e].ok && !pieces[e].resolved) ++e;
      Solver_unresolved<IT> v;
      v.reason = "not lifted over " + (e - s == 1 ? std::string("a piece") : std::to_string(e - s) + " consecutive pieces") +
                 " of block 0's curve: " + pieces[s].why;
      v.boxes = e - s;
      std::vector<IT> b0;
      for (std::size_t k = 0; k < v0.size(); ++k) {
        double lo = pieces[s].a.box[k].inf(), hi = pieces[s].a.box[k].sup();
        for (std::size_t q = s; q < e; ++q) {
          for (const Node* N : {&pieces[q].a, &pieces[q].b}) {
            lo = (std::min)(lo, N->box[k].inf());
            hi = (std::max)(hi, N->box[k].sup());
          }
          if (!pieces[q].X0.empty()) {  // the piece of block 0's curve lies in X0
            lo = (std::min)(lo, pieces[q].X0[k].inf());
            hi = (std::max)(hi, pieces[q].X0[k].sup());
          }
        }
        b0.push_back(Run::to_it(typename Run::I(lo, hi)));
      }
      v.box = whole_box(b0);
      out.unresolved.push_back(v);
      for (std::size_t q = s; q < e; ++q)
        for (int side = 0; side < 2; ++side)
          if (node_region[std::size_t(node_id(q, side))] < 0) node_region[std::size_t(node_id(q, side))] = long(out.unresolved.size() - 1);
      s = e;
    }
    // The pieces of the whole curve: the lifts over the pieces that were lifted, the arcs traced
    // around the ones that were not. Each has two ends at nodes of block 0's branch (node s and
    // s + 1 for piece s; on a closed branch node P is node 0), or, for an arc, a true end.
    struct Elem
    {
      std::size_t piece, index;
      bool arc;
      long node[2];
    };
    std::vector<Elem> elems;
    std::vector<std::vector<std::size_t>> lift_elem(P), arc_elem(P);
    for (std::size_t s = 0; s < P; ++s) {
      const Piece& p = pieces[s];
      if (p.ok)
        for (std::size_t i = 0; i < p.lifts.size(); ++i) {
          lift_elem[s].push_back(elems.size());
          elems.push_back({s, i, false, {node_id(s, 0), node_id(s, 1)}});
        }
      if (p.resolved)
        for (std::size_t i = 0; i < p.arcs.size(); ++i) {
          const auto& A = p.arcs[i];
          arc_elem[s].push_back(elems.size());
          if (A.curve.closed) { elems.push_back({s, i, true, {-1, -1}}); continue; }  // a loop inside the piece
          auto id = [&](int at) { return at < 0 ? -1L : at == 0 ? node_id(s, 0) : node_id(last[s], 1); };
          elems.push_back({s, i, true, {id(A.node[0]), id(A.node[1])}});
        }
    }
    // the joins at the nodes between pieces: by the lifts' boxes where both pieces were lifted,
    // else through the lifts over the node itself (one root per point above it: each must be
    // met by exactly one end on either side)
    const std::size_t none = std::size_t(-1);
    std::vector<std::array<std::pair<std::size_t, int>, 2>> link(elems.size(), {{{none, 0}, {none, 0}}});
    auto connect = [&](std::size_t e, int x, std::size_t f, int y) { link[e][x] = {f, y}; link[f][y] = {e, x}; };
    const std::size_t junctions = c.closed ? P : (P ? P - 1 : 0);
    const double d = 4 * (std::max)(tracer.tolerance, 1e-14);
    for (std::size_t k = 0; k < junctions; ++k) {
      const std::size_t L = k, R = (k + 1) % P;  // the node between piece L and piece R
      const Piece &pl = pieces[L], &pr = pieces[R];
      if (!(pl.ok || pl.resolved) || !(pr.ok || pr.resolved)) continue;
      if (pl.resolved && pr.resolved && first[L] == first[R]) continue;  // inside a run
      const std::vector<IT> u = Run::node_box(pr.a);
      auto not_joined = [&](const std::string& why) {
        Solver_unresolved<IT> v;
        v.reason = "lifts not joined at a node of block 0's curve: " + why;
        v.box = whole_box(u);
        out.unresolved.push_back(v);
        node_region[std::size_t(node_id(L, 1))] = long(out.unresolved.size() - 1);
      };
      if (pl.ok && pr.ok) {
        std::vector<std::size_t> to;
        if (run.match(pl.lifts, pr.lifts, to))
          for (std::size_t i = 0; i < to.size(); ++i) connect(lift_elem[L][i], 1, lift_elem[R][to[i]], 0);
        else
          not_joined("the lifts of the two pieces do not meet one to one");
        continue;
      }
      const std::vector<Lift>* lifted = lifts_at_node(R);
      if (!lifted) { not_joined("the later blocks not solved at the node"); continue; }
      const std::vector<Lift>& Q = *lifted;
      // the ends at this node on either side, with the root above the node each one holds
      std::vector<std::pair<std::size_t, int>> side_end[2];
      std::vector<std::size_t> side_point[2];
      bool fine = true;
      for (int side = 0; side < 2 && fine; ++side) {
        const std::size_t s = side == 0 ? (pieces[L].ok ? L : first[L]) : R;  // a run's arcs are at its first piece
        const int at = side == 0 ? 1 : 0;  // piece L meets the node with its end b, piece R with its end a
        const Piece& p = pieces[s];
        if (p.ok)
          for (std::size_t i = 0; i < p.lifts.size(); ++i) {
            side_end[side].push_back({lift_elem[s][i], at});
            side_point[side].push_back(run.point_of_lift(Q, p.lifts[i]));
          }
        else
          for (std::size_t i = 0; i < p.arcs.size(); ++i)
            for (int e = 0; e < 2; ++e)
              if (!p.arcs[i].curve.closed && p.arcs[i].node[e] == at) {
                side_end[side].push_back({arc_elem[s][i], e});
                const auto& curve = p.arcs[i].curve;
                side_point[side].push_back(run.point_of_end(Q, e == 0 ? curve.points.front() : curve.points.back(), d));
              }
        // a bijection with the roots above the node
        std::vector<char> hit(Q.size(), 0);
        fine = side_point[side].size() == Q.size();
        for (std::size_t q : side_point[side]) {
          if (q >= Q.size() || hit[q]) fine = false;
          else hit[q] = 1;
        }
      }
      if (!fine) { not_joined("the ends of the arcs traced around a fold do not meet the roots at the node one to one"); continue; }
      std::vector<std::size_t> right_of(Q.size());
      for (std::size_t i = 0; i < side_point[1].size(); ++i) right_of[side_point[1][i]] = i;
      for (std::size_t i = 0; i < side_point[0].size(); ++i) {
        const auto& l = side_end[0][i];
        const auto& r = side_end[1][right_of[side_point[0][i]]];
        connect(l.first, l.second, r.first, r.second);
      }
    }
    // how a chain ends at the end x of element e that links to nothing
    auto end_of = [&](const Elem& e, int x, Curve_end& kind, long& region) {
      region = -1;
      if (e.node[x] < 0) {  // an arc's true end
        kind = pieces[e.piece].arcs[e.index].curve.ends[x];
        return;
      }
      kind = Curve_end::UNRESOLVED;
      region = node_region[std::size_t(e.node[x])];
      if (!c.closed && e.node[x] == 0) { kind = c.ends[0]; region = c.end_region[0]; }
      if (!c.closed && e.node[x] == long(P)) { kind = c.ends[1]; region = c.end_region[1]; }
    };
    // the element's points from its end x to the other one
    auto append = [&](Solution_curve<IT>& whole, const Elem& e, int x) {
      std::vector<std::vector<double>> pts;
      const Piece& p = pieces[e.piece];
      if (e.arc) {
        const auto& A = p.arcs[e.index].curve;
        pts = A.points;
        if (x == 1) std::reverse(pts.begin(), pts.end());
        whole.boxes.insert(whole.boxes.end(), A.boxes.begin(), A.boxes.end());
        whole.on_inequality_boundary = whole.on_inequality_boundary || A.on_inequality_boundary;
        whole.certified = whole.certified && A.certified;
      } else {
        const Lift& L = p.lifts[e.index];
        const std::vector<double>& first = x == 0 ? p.a.p : p.b.p;
        const std::vector<double>& second = x == 0 ? p.b.p : p.a.p;
        if (whole.points.empty()) pts.push_back(run.point(first, L));
        else pts.push_back(whole.points.back());
        pts.push_back(run.point(second, L, &pts.back()));
        whole.boxes.push_back(L.value);
        // (block 0's flag only where this piece's own stretch of block 0 may meet the zero)
        whole.on_inequality_boundary = whole.on_inequality_boundary || L.inequality_boundary ||
                                       (c.on_inequality_boundary && (p.X0.empty() || run.block0_inequality_boundary(p.X0)));
      }
      // the first point is the junction with the element before
      whole.points.insert(whole.points.end(), pts.begin() + (whole.points.empty() ? 0 : 1), pts.end());
    };
    std::vector<char> used(elems.size(), 0);
    auto follow = [&](std::size_t e0, int x0) {
      Solution_curve<IT> whole;
      whole.certified = c.certified;
      const bool loop = link[e0][x0].first != none;  // entered where it links: a closed chain
      if (!loop) end_of(elems[e0], x0, whole.ends[0], whole.end_region[0]);
      std::size_t e = e0;
      int x = x0;
      while (true) {
        used[e] = 1;
        append(whole, elems[e], x);
        const int y = 1 - x;
        const auto next = link[e][y];
        if (next.first == none) {
          end_of(elems[e], y, whole.ends[1], whole.end_region[1]);
          break;
        }
        if (next.first == e0 && next.second == x0) {
          whole.closed = true;
          whole.ends[0] = whole.ends[1] = Curve_end::CLOSED;
          break;
        }
        if (used[next.first]) {  // cannot happen with one link per end; kept safe
          whole.ends[1] = Curve_end::UNRESOLVED;
          break;
        }
        e = next.first;
        x = next.second;
      }
      for (int k = 0; k < 2; ++k) whole.certified = whole.certified && whole.ends[k] != Curve_end::UNRESOLVED;
      for (const auto& p : whole.points)
        for (const auto& f : system.equations) whole.max_residual = (std::max)(whole.max_residual, std::abs(f.template evaluate<double>(p)));
      out.curves.push_back(std::move(whole));
    };
    for (std::size_t e = 0; e < elems.size(); ++e) {  // loops traced inside one piece
      if (!elems[e].arc || !pieces[elems[e].piece].arcs[elems[e].index].curve.closed) continue;
      used[e] = 1;
      Solution_curve<IT> whole = pieces[elems[e].piece].arcs[elems[e].index].curve;
      whole.certified = whole.certified && c.certified;
      out.curves.push_back(std::move(whole));
    }
    // chains first (from an end that links to nothing: the branch's start comes first), then loops
    for (std::size_t e = 0; e < elems.size(); ++e)
      for (int x = 0; x < 2; ++x)
        if (!used[e] && link[e][x].first == none) follow(e, x);
    for (std::size_t e = 0; e < elems.size(); ++e)
      if (!used[e]) follow(e, 0);
  }
  out.statistics.boxes += run.block_boxes;
  out.statistics.block_solves = run.block_solves;
  out.statistics.kept_solves = run.kept_solves;
  out.statistics.pieces = run.pieces;
  out.statistics.fold_traces = run.fold_traces;
  out.statistics.coarse_solves = run.coarse_solves;
  out.statistics.lifted_arcs = run.lifted_arcs;
  out.statistics.boxes += run.fold_trace_boxes;
  out.statistics.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return out;
}

} // namespace Rigid_incidence
} // namespace CGAL

#endif
