// Copyright (c) 2026 The Rigid_incidence authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The Krawczyk operator of a square polynomial system, evaluated term by term on its sparse
// polynomials: no dense Bernstein arrays, so it runs on systems of any size (the whole system
// of a solution plan, whose arrays the subdivision solver refuses: two stacked platforms,
// 12 variables).

#ifndef CGAL_RIGID_INCIDENCE_INTERNAL_SPARSE_KRAWCZYK_H
#define CGAL_RIGID_INCIDENCE_INTERNAL_SPARSE_KRAWCZYK_H

#include <CGAL/Rigid_incidence/Input_error.h>
#include <CGAL/Rigid_incidence/Polynomial_system.h>
#include <CGAL/Rigid_incidence/internal/interval_ops.h>

#include <Eigen/Dense>

#include <string>
#include <vector>

namespace CGAL {
namespace Rigid_incidence {
namespace internal {

// What sparse_krawczyk_tighten() did.
struct Sparse_krawczyk_outcome
{
  bool proved = false;   // a step had K(X) in the interior of X: exactly one root there
  bool empty = false;    // X and K(X) were disjoint: X holds no root (X is left as it was)
  int iterations = 0;    // steps that narrowed X
  double width = 0;      // the widest variable of X at the end
};

// The system f (square: as many equations as variables), its coefficients and the partial
// derivatives' coefficients enclosed in IT once (exact derivatives of exact coefficients).
template <class IT>
struct Sparse_krawczyk_system
{
  std::vector<Sparse_polynomial<IT>> f;
  std::vector<std::vector<Sparse_polynomial<IT>>> df;  // df[i][j] = d f_i / d x_j

  template <class NT>
  explicit Sparse_krawczyk_system(const std::vector<Sparse_polynomial<NT>>& g)
  {
    typedef Interval_ops<IT> O;
    const std::size_t n = g.size();
    auto enclose = [&](const Sparse_polynomial<NT>& p) {
      Sparse_polynomial<IT> r(n);
      for (const auto& t : p.terms()) r.add_term(t.first, O::from(t.second));
      return r;
    };
    for (std::size_t i = 0; i < n; ++i) {
      if (g[i].number_of_variables() != n)
        throw Input_error("sparse Krawczyk test: equation " + std::to_string(i) + " has " + std::to_string(g[i].number_of_variables()) +
                          " variables in a system of " + std::to_string(n) + " equations (not square)");
      f.push_back(enclose(g[i]));
      df.emplace_back();
      for (std::size_t j = 0; j < n; ++j) df.back().push_back(enclose(g[i].derivative(j)));
    }
  }
};

// X narrowed to X ∩ K(X), repeatedly, with
//   K(X) = m - Y f(m) + (I - Y J(X)) (X - m),
// m a point of X, J(X) the interval Jacobian over X (term by term), Y the inverse of J(m) in
// double. Every root of f in X lies in K(X), so X keeps every root it held; K(X) in the
// interior of X proves that X holds exactly one (Krawczyk). It stops once X is at most
// `tolerance` wide in every variable, stops narrowing (the precision of IT, or the width of
// the coefficients, is reached), or after `maximal_iterations`. The caller sets IT's rounding
// mode or precision (Solver_precision_guard).
template <class IT>
Sparse_krawczyk_outcome sparse_krawczyk_tighten(const Sparse_krawczyk_system<IT>& s, std::vector<IT>& X, double tolerance,
                                                int maximal_iterations = 64)
{
  typedef Interval_ops<IT> O;
  typedef typename O::Bound Bound;
  const std::size_t n = s.f.size();
  if (X.size() != n)
    throw Input_error("sparse Krawczyk test: a box of " + std::to_string(X.size()) + " variables for " + std::to_string(n) + " equations");
  auto width = [&](const std::vector<IT>& B) {
    double w = 0;  // (in IT: bounds beyond double's resolution near a large coordinate)
    for (const IT& x : B) w = (std::max)(w, O::upper_double(O::point(O::upper(x)) - O::point(O::lower(x))));
    return w;
  };
  Sparse_krawczyk_outcome out;
  out.width = width(X);
  for (int it = 0; it < maximal_iterations && out.width > tolerance; ++it) {
    std::vector<IT> m(n);
    for (std::size_t j = 0; j < n; ++j) {
      // a bound of the midpoint's enclosure: a point of X in any precision
      Bound c = O::lower(O::half_sum(O::point(O::lower(X[j])), O::point(O::upper(X[j]))));
      if (c < O::lower(X[j])) c = O::lower(X[j]);
      m[j] = O::point(c);
    }
    Eigen::MatrixXd A(n, n);
    std::vector<std::vector<IT>> J(n, std::vector<IT>(n));
    std::vector<IT> fm(n);
    for (std::size_t i = 0; i < n; ++i) {
      fm[i] = s.f[i].evaluate(m);
      for (std::size_t j = 0; j < n; ++j) {
        J[i][j] = s.df[i][j].evaluate(X);
        const IT a = s.df[i][j].evaluate(m);
        A(long(i), long(j)) = 0.5 * O::lower_double(a) + 0.5 * O::upper_double(a);
      }
    }
    if (!A.allFinite()) break;
    Eigen::FullPivLU<Eigen::MatrixXd> lu(A);
    if (!lu.isInvertible()) break;
    const Eigen::MatrixXd Yd = lu.inverse();
    if (!Yd.allFinite()) break;
    std::vector<IT> K(n);
    bool inside = true;
    for (std::size_t a = 0; a < n; ++a) {
      IT k = m[a];
      for (std::size_t i = 0; i < n; ++i) {
        if (Yd(long(a), long(i)) == 0) continue;
        k = k - O::point(O::bound_from_double(Yd(long(a), long(i)))) * fm[i];
      }
      for (std::size_t j = 0; j < n; ++j) {
        IT c(a == j ? 1 : 0);
        for (std::size_t i = 0; i < n; ++i) {
          if (Yd(long(a), long(i)) == 0) continue;
          c = c - O::point(O::bound_from_double(Yd(long(a), long(i)))) * J[i][j];
        }
        k = k + c * (X[j] - m[j]);
      }
      K[a] = k;
      if (!(O::lower(X[a]) < O::lower(k) && O::upper(k) < O::upper(X[a]))) inside = false;
    }
    std::vector<IT> Z(n);
    for (std::size_t j = 0; j < n; ++j) {
      const Bound lo = O::lower(X[j]) < O::lower(K[j]) ? O::lower(K[j]) : O::lower(X[j]);
      const Bound hi = O::upper(K[j]) < O::upper(X[j]) ? O::upper(K[j]) : O::upper(X[j]);
      if (hi < lo) {
        out.empty = true;
        return out;
      }
      Z[j] = O::make(lo, hi);
    }
    out.proved = out.proved || inside;
    // (X ∩ K(X) holds X's roots whether it narrowed or not)
    X = Z;
    const double w = width(Z);
    if (!(w < out.width)) break;
    out.width = w;
    ++out.iterations;
  }
  return out;
}

} // namespace internal
} // namespace Rigid_incidence
} // namespace CGAL

#endif
