// Copyright (c) 2026 Rigid_incidence contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Curves along a solution plan (decomposition_subdivision_solver.txt, Section 3.4 and
// Algorithm 6 for m = k - 1): the plan's curve block (block 0) is traced by trace_curves(),
// and the square blocks after it are lifted over short certified pieces of block 0's branches.
//
// A piece runs between two certified points of block 0's curve (nodes: Krawczyk boxes of the
// curve with one variable t fixed). A parametric Krawczyk test on block 0 with t over the piece's
// interval proves that for every t there is exactly one point of the curve in a narrow box X0
// that holds both nodes, so the piece is the curve between them. Over X0, a parametric Krawczyk
// test on all later blocks together (block by block the inputs' boxes would be independent
// intervals whose widths grow with every block) proves, for each root found at X0's centre, one
// root in a box X for every input in X0: a lift, single-valued and continuous over the piece.
// Each later block is then solved again over the lifts' boxes with interval coefficients, to
// prove that these are all its roots there. Lifts of consecutive pieces are joined where their
// boxes meet (a bijection is required: both sets hold every root above the shared node, each
// one unique in its box). A piece that fails is halved, down to `maximal_halvings` levels; one
// that still fails (two roots of a later block meet there: a singular point of the whole
// curve, or a turning point over block 0) becomes an unresolved region where the chains of
// lifts through it end.

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
#include <chrono>
#include <cmath>
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
  unsigned maximal_halvings = 12;
  /// Each later block's solve over a piece visits at most this many boxes (a block whose roots
  /// meet over the piece would otherwise spend the whole budget).
  std::size_t block_boxes = 2000;
};

namespace internal {

template <class IT, class NT> struct Plan_trace_run
{
  typedef Interval_ops<IT> O;
  typedef CGAL::Interval_nt<false> I;
  const Polynomial_system<NT>& sys;
  const Solution_plan& plan;
  const Subdivision_solver_parameters& SP;
  const Plan_trace_parameters& PP;
  const std::size_t n;
  std::vector<std::size_t> v0, e0, down, down_eq;  // block 0's variables and equations, the later ones
  std::vector<std::vector<Sparse_polynomial<NT>>> D;  // D[i][j]: d f_i / d x_j
  std::vector<std::vector<char>> uses;               // uses[i][j]: f_i involves x_j
  std::size_t block_solves = 0, block_boxes = 0, pieces = 0, halvings = 0;

  Plan_trace_run(const Polynomial_system<NT>& s, const Solution_plan& p, const Subdivision_solver_parameters& sp, const Plan_trace_parameters& pp)
      : sys(s), plan(p), SP(sp), PP(pp), n(s.number_of_variables())
  {
    v0 = plan.blocks()[0].variables;
    e0 = plan.blocks()[0].equations;
    for (std::size_t b = 1; b < plan.blocks().size(); ++b) {
      down.insert(down.end(), plan.blocks()[b].variables.begin(), plan.blocks()[b].variables.end());
      down_eq.insert(down_eq.end(), plan.blocks()[b].equations.begin(), plan.blocks()[b].equations.end());
    }
    D.resize(sys.equations.size());
    uses.resize(sys.equations.size());
    for (std::size_t i = 0; i < sys.equations.size(); ++i) {
      uses[i].assign(n, 0);
      for (std::size_t j : sys.equations[i].variables()) uses[i][j] = 1;
      for (std::size_t j = 0; j < n; ++j) D[i].push_back(sys.equations[i].derivative(j));
    }
  }

  IT search(std::size_t j) const { return O::make(O::bound_from_double(sys.box[j].first), O::bound_from_double(sys.box[j].second)); }
  static IT to_it(const I& x) { return O::make(O::bound_from_double(x.inf()), O::bound_from_double(x.sup())); }
  static double mid(const IT& x) { return 0.5 * O::lower_double(x) + 0.5 * O::upper_double(x); }

  // Newton on the equations E for the unknowns Y (the other variables of x fixed); false if
  // it does not converge.
  bool newton(const std::vector<std::size_t>& E, const std::vector<std::size_t>& Y, std::vector<double>& x) const
  {
    const std::size_t m = Y.size();
    for (int it = 0; it < 30; ++it) {
      Eigen::MatrixXd J(m, m);
      Eigen::VectorXd f(m);
      for (std::size_t i = 0; i < m; ++i) {
        f(long(i)) = sys.equations[E[i]].template evaluate<double>(x);
        for (std::size_t k = 0; k < m; ++k) J(long(i), long(k)) = uses[E[i]][Y[k]] ? D[E[i]][Y[k]].template evaluate<double>(x) : 0.0;
      }
      Eigen::VectorXd d = J.fullPivLu().solve(f);
      if (!d.allFinite()) return false;
      double big = 1;
      for (std::size_t k = 0; k < m; ++k) { x[Y[k]] -= d(long(k)); big = (std::max)(big, std::abs(x[Y[k]])); }
      if (d.lpNorm<Eigen::Infinity>() <= 1e-15 * big) return true;
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
      for (std::size_t k = 0; k < m; ++k) JY(long(i), long(k)) = uses[E[i]][Y[k]] ? D[E[i]][Y[k]].template evaluate<double>(x) : 0.0;
      for (std::size_t k = 0; k < P.size(); ++k) JP(long(i), long(k)) = uses[E[i]][P[k]] ? D[E[i]][P[k]].template evaluate<double>(x) : 0.0;
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
    for (std::size_t i = 0; i < m; ++i) g[i] = sys.equations[E[i]].template evaluate<I>(xc);
    X.assign(m, I(0));
    for (int attempt = 0; attempt < 8; ++attempt) {
      for (std::size_t k = 0; k < P.size(); ++k) xU[P[k]] = U[k];
      for (std::size_t j = 0; j < m; ++j) xU[Y[j]] = I(x[Y[j]] - r[j], x[Y[j]] + r[j]);
      bool inside = true;
      std::vector<I> K(m);
      for (std::size_t j = 0; j < m; ++j) {
        I k = I(x[Y[j]]);
        for (std::size_t i = 0; i < m; ++i) k -= I(Yi(long(j), long(i))) * g[i];
        for (std::size_t q = 0; q < P.size(); ++q) {
          I s(0);
          for (std::size_t i = 0; i < m; ++i)
            if (uses[E[i]][P[q]]) s += I(Yi(long(j), long(i))) * D[E[i]][P[q]].template evaluate<I>(xU);
          k -= s * (U[q] - I(x[P[q]]));
        }
        for (std::size_t l = 0; l < m; ++l) {
          I s(l == j ? 1 : 0);
          for (std::size_t i = 0; i < m; ++i)
            if (uses[E[i]][Y[l]]) s -= I(Yi(long(j), long(i))) * D[E[i]][Y[l]].template evaluate<I>(xU);
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

  // the variable of block 0 along which the curve runs fastest at p (the largest component of
  // the tangent, the null vector of block 0's Jacobian)
  std::size_t tangent_variable(const std::vector<double>& p) const
  {
    std::vector<double> x(n, 0.0);
    for (std::size_t k = 0; k < v0.size(); ++k) x[v0[k]] = p[k];
    Eigen::MatrixXd J(e0.size(), v0.size());
    for (std::size_t i = 0; i < e0.size(); ++i)
      for (std::size_t k = 0; k < v0.size(); ++k) J(long(i), long(k)) = uses[e0[i]][v0[k]] ? D[e0[i]][v0[k]].template evaluate<double>(x) : 0.0;
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
    std::size_t t = 0;
    for (std::size_t k = 1; k < v0.size(); ++k)
      if (std::abs(b.p[k] - a.p[k]) > std::abs(b.p[t] - a.p[t])) t = k;
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
    // k entries have the same values in blocks 1 .. k over the whole piece (each lift's
    // values in those blocks are the unique root of blocks 1 .. k in its box, the preconditioned
    // operator being block triangular like the plan, and they agree at the centre)
    std::vector<std::size_t> path;
  };

  // Block b solved with its inputs the boxes of L (those with `known` set).
  Solver_result<IT> solve_block(std::size_t b, const Lift& L, const std::vector<char>& known)
  {
    const Plan_block& blk = plan.blocks()[b];
    Polynomial_system<IT> s;
    for (std::size_t j : blk.variables) {
      s.variable_names.push_back(j < sys.variable_names.size() ? sys.variable_names[j] : "x" + std::to_string(j));
      s.box.push_back(sys.box[j]);
    }
    for (std::size_t i : blk.equations) s.equations.push_back(restrict_polynomial<IT>(sys.equations[i], blk.variables, L.value, known));
    for (std::size_t q : blk.inequalities) s.inequalities.push_back(restrict_polynomial<IT>(sys.inequalities[q], blk.variables, L.value, known));
    Subdivision_solver_parameters q = SP;
    q.maximal_precision = 0;  // interval coefficients: no higher precision to try
    q.maximal_boxes = (std::min)(q.maximal_boxes, PP.block_boxes);
    // the roots for all inputs in the box fill a region about as wide as the inputs: the
    // Krawczyk test must see a box that holds it, not pieces of it
    double input = 0;
    for (std::size_t j = 0; j < n; ++j)
      if (known[j]) input = (std::max)(input, O::upper_double(L.value[j]) - O::lower_double(L.value[j]));
    q.minimal_width = q.singular_width = (std::max)(q.minimal_width, 4 * input);
    Solver_result<IT> res = Subdivision_solver<IT>(q).solve(s);
    ++block_solves;
    block_boxes += res.statistics.boxes;
    return res;
  }

  // every lift over the point u of block 0 (inputs crisp), block by block
  bool lift_point(const std::vector<double>& u, std::vector<Lift>& out)
  {
    const auto& blocks = plan.blocks();
    Lift start;
    start.value.assign(n, IT(0));
    std::vector<char> known(n, 0);
    for (std::size_t k = 0; k < v0.size(); ++k) {
      start.value[v0[k]] = O::make(O::bound_from_double(u[k]), O::bound_from_double(u[k]));
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

  // Proves that no lift over the piece continues the partial lift P (blocks before b known):
  // block b and the ones after it, solved with interval coefficients over P's boxes, end
  // without a root in some block (no real root, or every root fails an inequality), with no
  // unresolved box on the way. This accounts for roots of a block that belong to no lift (a
  // circle intersection whose leg fails a later orientation inequality).
  bool dies(std::size_t b, const Lift& P, std::vector<char> known, int depth = 0)
  {
    const auto& blocks = plan.blocks();
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

  // The lifts over the box X0 of a piece of block 0's curve; false (with `why`) if they
  // cannot all be certified there.
  bool lift_piece(const std::vector<I>& X0, std::vector<Lift>& out, std::string& why)
  {
    const auto& blocks = plan.blocks();
    std::vector<double> uc(v0.size());
    for (std::size_t k = 0; k < v0.size(); ++k) uc[k] = 0.5 * X0[k].inf() + 0.5 * X0[k].sup();
    std::vector<Lift> centre;
    if (!lift_point(uc, centre)) { why = "a later block is not resolved above the piece's centre"; return false; }
    out.clear();
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
        if (all) { why = "two lifts' boxes overlap"; return false; }
      }
    // completeness: above each lift's boxes of the blocks before b, block b solved with those
    // boxes as its inputs has the roots the lifts agreeing with it before b give (root boxes
    // and lift boxes meet one to one: every root lies in some root box, each holds one root per
    // input), and roots or unresolved boxes whose partial lifts die (dies())
    if (out.empty()) {
      Lift S;
      S.value.assign(n, IT(0));
      std::vector<char> known(n, 0);
      for (std::size_t k = 0; k < v0.size(); ++k) { S.value[v0[k]] = to_it(X0[k]); known[v0[k]] = 1; }
      if (!dies(1, S, known)) { why = "no lift at the piece's centre, but the later blocks are not proved empty over the piece"; return false; }
    }
    for (const Lift& L : out) {
      std::vector<char> known(n, 0);
      for (std::size_t j : v0) known[j] = 1;
      for (std::size_t b = 1; b < blocks.size(); ++b) {
        const Plan_block& blk = blocks[b];
        // the lifts that agree with L on the blocks before b (the same roots there at the
        // centre), one per root of block b
        std::vector<const Lift*> same;
        for (const Lift& M : out) {
          if (!std::equal(M.path.begin(), M.path.begin() + (b - 1), L.path.begin())) continue;
          bool fresh = true;
          for (const Lift* S : same) fresh = fresh && S->path[b - 1] != M.path[b - 1];
          if (fresh) same.push_back(&M);
        }
        Solver_result<IT> res = solve_block(b, L, known);
        for (const auto& u : res.unresolved) {  // no lift's root: fine if nothing in it continues
          Lift M = L;
          for (std::size_t k = 0; k < blk.variables.size(); ++k) M.value[blk.variables[k]] = u.box[k];
          std::vector<char> after = known;
          for (std::size_t j : blk.variables) after[j] = 1;
          if (!dies(b + 1, M, after)) { why = "block " + std::to_string(b) + " over the piece: " + u.reason; return false; }
        }
        std::vector<char> hit(same.size(), 0);
        for (const auto& root : res.roots) {
          if (!root.certified) { why = "block " + std::to_string(b) + " over the piece: a root not certified"; return false; }
          // the lifts whose boxes meet the root's box
          std::size_t h = same.size(), meets = 0;
          for (std::size_t s = 0; s < same.size(); ++s) {
            bool all = true;
            for (std::size_t k = 0; k < blk.variables.size(); ++k) all = all && meet(root.enclosure[k], same[s]->value[blk.variables[k]]);
            if (all) { h = s; ++meets; }
          }
          if (meets > 1 || (meets == 1 && hit[h])) { why = "block " + std::to_string(b) + " over the piece: a root's box meets several lifts"; return false; }
          if (meets == 1) { hit[h] = 1; continue; }
          // a root of no lift: its partial lift must die in the blocks after b
          Lift M = L;
          for (std::size_t k = 0; k < blk.variables.size(); ++k) M.value[blk.variables[k]] = root.enclosure[k];
          std::vector<char> after = known;
          for (std::size_t j : blk.variables) after[j] = 1;
          if (!dies(b + 1, M, after)) {
            why = "block " + std::to_string(b) + " over the piece: a root the lifts do not account for";
            return false;
          }
        }
        if (std::find(hit.begin(), hit.end(), char(0)) != hit.end()) { why = "block " + std::to_string(b) + " over the piece: a lift's root not found"; return false; }
        // each lift's box meets exactly one root's box, which therefore holds the lift's root
        // (every root lies in some root's box); a root's box met by one lift holds only its root
        for (const Lift* S : same) {
          std::size_t meets = 0;
          for (const auto& root : res.roots) {
            bool all = true;
            for (std::size_t k = 0; k < blk.variables.size(); ++k) all = all && meet(root.enclosure[k], S->value[blk.variables[k]]);
            meets += all;
          }
          for (const auto& u : res.unresolved) {
            bool all = true;
            for (std::size_t k = 0; k < blk.variables.size(); ++k) all = all && meet(u.box[k], S->value[blk.variables[k]]);
            meets += all;
          }
          if (meets != 1) { why = "block " + std::to_string(b) + " over the piece: a lift's box meets several roots' boxes"; return false; }
        }
        for (std::size_t j : blk.variables) known[j] = 1;
      }
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
  std::vector<double> point(const std::vector<double>& p, const Lift& L, const std::vector<double>* guess = nullptr) const
  {
    std::vector<double> x(n, 0.0);
    for (std::size_t k = 0; k < v0.size(); ++k) x[v0[k]] = p[k];
    for (int start = guess ? 0 : 1; start < 2; ++start) {
      for (std::size_t j : down) x[j] = start == 0 ? (*guess)[j] : mid(L.value[j]);
      // block by block: each block's root for p is the one in the lift's box
      bool all = true;
      for (std::size_t b = 1; b < plan.blocks().size() && all; ++b) {
        const Plan_block& blk = plan.blocks()[b];
        std::vector<double> y = x;
        all = newton(blk.equations, blk.variables, y);
        for (std::size_t j : blk.variables) all = all && O::lower_double(L.value[j]) <= y[j] && y[j] <= O::upper_double(L.value[j]);
        if (all) x = y;
      }
      if (all) return x;
    }
    for (std::size_t j : down) x[j] = mid(L.value[j]);
    return x;
  }

  // ---------------------------------------------------------------- pieces

  struct Piece
  {
    Node a, b;
    bool ok = false;
    std::string why;
    std::vector<I> X0;
    std::vector<Lift> lifts;
  };

  // block 0's curve from node a to node b, halved where it cannot be lifted
  void pieces_between(const Node& a, const Node& b, unsigned depth, std::vector<Piece>& out)
  {
    Piece P;
    P.a = a;
    P.b = b;
    ++pieces;
    if (!piece_box(a, b, P.X0)) P.why = "block 0's curve not certified between two of its points";
    else P.ok = lift_piece(P.X0, P.lifts, P.why);
    if (P.ok || depth >= PP.maximal_halvings) { out.push_back(std::move(P)); return; }
    // halve: the node at the middle value of the piece's fastest variable
    std::size_t t = 0;
    for (std::size_t k = 1; k < v0.size(); ++k)
      if (std::abs(b.p[k] - a.p[k]) > std::abs(b.p[t] - a.p[t])) t = k;
    std::vector<double> m(v0.size());
    for (std::size_t k = 0; k < v0.size(); ++k) m[k] = 0.5 * (a.p[k] + b.p[k]);
    Node M;
    if (!(std::abs(b.p[t] - a.p[t]) > 0) || !make_node(m, t, M)) { out.push_back(std::move(P)); return; }
    ++halvings;
    pieces_between(a, M, depth + 1, out);
    pieces_between(M, b, depth + 1, out);
  }
};

} // namespace internal

/*!
\ingroup PkgRigidIncidenceSolver
\brief The real solution curves of a system with one degree of freedom, traced along its
solution plan: the plan's curve block by `trace_curves()`, the square blocks after it lifted
over short certified pieces of it.

The plan (`Solution_plan`, structure `ONE_DEGREE_OF_FREEDOM`) must have its curve block
first, without inputs, and only square blocks after it, as Jansen's linkage has (the crank,
then one point at a time). Block 0 is traced by `trace_curves()`; its polyline points become
certified nodes of its curve, and between consecutive nodes a parametric Krawczyk test proves
the piece of curve inside a narrow box X0. Over X0 each later block's roots at the centre are
continued by a parametric Krawczyk test on all later blocks together (one root in a box for
every input in X0: the lift is single-valued and continuous over the piece), and each later
block is solved again over the lifts' boxes with interval coefficients to prove they are all
its roots there (with its inequalities: the physical branch only). Lifts of consecutive pieces
are joined where their boxes meet (a bijection). A piece that fails is halved, at most
`plan_parameters.maximal_halvings` times; then it becomes an unresolved region (two roots of a
later block meet there: a singular point of the whole curve, or a turning point over block 0)
where the chains of lifts end, uncertified. A closed branch of block 0 closes its lifts after
one or more turns. Each polyline point is a node with the later blocks' values by Newton in
their boxes.

A branch is certified when block 0's branch is and every piece of it was lifted and joined,
so that the branch is the whole solution curve above block 0's branch, its points within
`max_residual` of the curve. Caveat: the chain of pieces follows block 0's polyline through
nodes certified next to its points; that the chain is the tracer's branch (and not a branch
within 1e-12 of it) rests on the tracer's polyline accuracy.

\throws Input_error if the plan is not of this form (use `trace_curves()` on the whole system).
*/
template <class IT = CGAL::Interval_nt<false>, class NT>
Curve_result<IT> trace_curves_with_plan(const Polynomial_system<NT>& system, const Solution_plan& plan,
                                        const Curve_tracer_parameters& tracer = Curve_tracer_parameters(),
                                        const Subdivision_solver_parameters& solver = Subdivision_solver_parameters(),
                                        const Plan_trace_parameters& plan_parameters = Plan_trace_parameters())
{
  const auto start = std::chrono::steady_clock::now();
  const auto& blocks = plan.blocks();
  if (plan.structure() != Solution_plan::ONE_DEGREE_OF_FREEDOM || blocks.empty() || blocks[0].dimension() != 1 || !blocks[0].inputs.empty())
    throw Input_error("trace_curves_with_plan: the plan's first block must be its curve block, without inputs");
  for (std::size_t b = 1; b < blocks.size(); ++b)
    if (blocks[b].dimension() != 0)
      throw Input_error("trace_curves_with_plan: block " + std::to_string(b) + " is not square");
  const std::size_t n = system.number_of_variables();
  typedef internal::Plan_trace_run<IT, NT> Run;
  typedef typename Run::Lift Lift;
  typedef typename Run::Piece Piece;
  typedef typename Run::Node Node;
  Run run(system, plan, solver, plan_parameters);
  const auto& v0 = run.v0;

  // block 0 on its own variables
  Polynomial_system<NT> s0;
  auto renumber = [&](const Sparse_polynomial<NT>& f) { return internal::Plan_run<IT, NT>::restrict_exact(f, v0); };
  for (std::size_t j : v0) {
    s0.variable_names.push_back(j < system.variable_names.size() ? system.variable_names[j] : "x" + std::to_string(j));
    s0.box.push_back(system.box[j]);
  }
  for (std::size_t i : blocks[0].equations) s0.equations.push_back(renumber(system.equations[i]));
  for (std::size_t q : blocks[0].inequalities) s0.inequalities.push_back(renumber(system.inequalities[q]));
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
    for (const Piece& p : pieces)
      if (!p.ok) {
        Solver_unresolved<IT> v;
        v.reason = "not lifted over a piece of block 0's curve: " + p.why;
        std::vector<IT> b0;
        for (std::size_t k = 0; k < v0.size(); ++k)
          b0.push_back(Run::to_it(typename Run::I((std::min)(p.a.box[k].inf(), p.b.box[k].inf()), (std::max)(p.a.box[k].sup(), p.b.box[k].sup()))));
        v.box = whole_box(b0);
        out.unresolved.push_back(v);
      }
    // the joins: piece s to piece s + 1 (and the last to the first on a closed branch)
    const std::size_t joins = c.closed ? P : (P ? P - 1 : 0);
    std::vector<std::vector<std::size_t>> to(joins);
    std::vector<char> joined(joins, 0);
    for (std::size_t s = 0; s < joins; ++s) joined[s] = pieces[s].ok && pieces[(s + 1) % P].ok && run.match(pieces[s].lifts, pieces[(s + 1) % P].lifts, to[s]);
    const bool all_joined = std::find(joined.begin(), joined.end(), char(0)) == joined.end();
    // follow every lift; on a closed branch a lift may come back to another lift of piece 0
    std::vector<std::vector<char>> used(P);
    for (std::size_t s = 0; s < P; ++s) used[s].assign(pieces[s].lifts.size(), 0);
    for (std::size_t s0 = 0; s0 < P; ++s0)
      for (std::size_t i0 = 0; i0 < pieces[s0].lifts.size(); ++i0) {
        if (used[s0][i0]) continue;
        // a chain starts where it cannot be entered (piece 0 of an open branch, or after a
        // failed join); on a closed branch whose joins all hold it starts at piece 0
        const bool entered = s0 > 0 ? bool(joined[s0 - 1]) : (c.closed && joins > 0 && joined[joins - 1]);
        if (entered && !(c.closed && all_joined && s0 == 0)) continue;
        Solution_curve<IT> whole;
        const bool from_start = s0 == 0 && (!c.closed || all_joined);
        whole.certified = c.certified && from_start;
        whole.ends[0] = from_start ? c.ends[0] : Curve_end::UNRESOLVED;
        whole.end_region[0] = from_start && !c.closed ? c.end_region[0] : -1;
        std::size_t s = s0, i = i0;
        while (true) {
          used[s][i] = 1;
          const Lift& L = pieces[s].lifts[i];
          whole.boxes.push_back(L.value);
          whole.on_inequality_boundary = whole.on_inequality_boundary || L.inequality_boundary || c.on_inequality_boundary;
          if (whole.points.empty()) whole.points.push_back(run.point(pieces[s].a.p, L));
          whole.points.push_back(run.point(pieces[s].b.p, L, &whole.points.back()));
          if (s + 1 == P && !c.closed) {
            whole.ends[1] = c.ends[1];
            whole.end_region[1] = c.end_region[1];
            break;
          }
          if (!joined[s]) {
            whole.ends[1] = Curve_end::UNRESOLVED;
            whole.certified = false;
            break;
          }
          const std::size_t t = (s + 1) % P, k = to[s][i];
          if (t == 0 && used[t][k]) {
            if (t == s0 && k == i0) {
              whole.closed = true;
              whole.ends[0] = whole.ends[1] = Curve_end::CLOSED;
            } else {  // back at piece 0 on a lift whose chain was already followed
              whole.certified = false;
              whole.ends[1] = Curve_end::UNRESOLVED;
            }
            break;
          }
          s = t;
          i = k;
        }
        for (const auto& p : whole.points)
          for (const auto& f : system.equations) whole.max_residual = (std::max)(whole.max_residual, std::abs(f.template evaluate<double>(p)));
        out.curves.push_back(std::move(whole));
      }
  }
  out.statistics.boxes += run.block_boxes;
  out.statistics.block_solves = run.block_solves;
  out.statistics.pieces = run.pieces;
  out.statistics.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return out;
}

} // namespace Rigid_incidence
} // namespace CGAL

#endif
