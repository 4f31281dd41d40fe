// Copyright (c) 2026 Rigid_incidence contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Test helpers of the subdivision-solver tests: polynomial systems with planted roots that
// an oracle independent of the solver knows exactly, and an exact checker of a solver result.
//
// A planted system is f = A g: each g_j is a product of rational affine forms and A is an
// invertible rational matrix (the identity: uncoupled). Its real roots are those of g: a
// point where every g_j vanishes, i.e. where one factor of each g_j vanishes. The oracle
// enumerates every choice of one factor per equation and solves the n x n linear system of
// the chosen forms exactly (Gmpq Gaussian elimination); a singular but consistent choice is
// a positive-dimensional component (the system is rejected), a point reached by two choices
// is a singular root (multiplicity > 1). Every root is checked exactly: f(root) == 0 and the
// sign of det J_f(root). A linear change of coordinates x = M y + t of a product system
// keeps the factors affine, so coupled systems are planted the same way.
//
// The checker compares a Solver_result with the planted roots with rationals only: interval
// bounds are converted to Gmpq exactly (double and MPFR bounds are dyadic rationals).

#ifndef RIGID_INCIDENCE_TEST_PLANTED_SYSTEMS_H
#define RIGID_INCIDENCE_TEST_PLANTED_SYSTEMS_H

#include "test_check.h"

#include <CGAL/Gmpq.h>
#include <CGAL/Interval_nt.h>
#include <CGAL/Rigid_incidence/Polynomial_system.h>
#include <CGAL/Rigid_incidence/Solver_result.h>
#ifdef CGAL_USE_MPFI
#include <CGAL/Gmpfi.h>
#include <CGAL/Gmpfr.h>
#endif

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>
#include <random>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace planted_systems {

namespace RI = CGAL::Rigid_incidence;
typedef CGAL::Gmpq Q;
typedef std::vector<Q> Point;
typedef RI::Sparse_polynomial<Q> Poly;
typedef RI::Polynomial_system<Q> System;

// ------------------------------------------------------------------ random numbers
struct Rng
{
  std::mt19937_64 g;
  explicit Rng(std::uint64_t seed) : g(seed) {}
  long uniform(long lo, long hi) { return std::uniform_int_distribution<long>(lo, hi)(g); } // inclusive
  bool coin(double p = 0.5) { return std::uniform_real_distribution<double>(0, 1)(g) < p; }
  // num / den, num in [-num_max, num_max], den in [1, den_max]
  Q rational(long num_max, long den_max) { return Q(uniform(-num_max, num_max), uniform(1, den_max)); }
  // a rational in [lo, hi] with denominator at most den
  Q rational_in(const Q& lo, const Q& hi, long den)
  {
    Q u(uniform(0, den), den);
    return lo + u * (hi - lo);
  }
};

// ------------------------------------------------------------------ affine forms
// c . x + c0
struct Affine
{
  std::vector<Q> c;
  Q c0;
  Q operator()(const Point& x) const
  {
    Q s = c0;
    for (std::size_t i = 0; i < c.size(); ++i) s += c[i] * x[i];
    return s;
  }
};

// x_i - r in n variables
inline Affine coordinate_form(std::size_t n, std::size_t i, const Q& r)
{
  Affine a;
  a.c.assign(n, Q(0));
  a.c[i] = 1;
  a.c0 = -r;
  return a;
}

// c . (x - p): an affine form vanishing at p
inline Affine form_through(const std::vector<Q>& c, const Point& p)
{
  Affine a;
  a.c = c;
  a.c0 = 0;
  for (std::size_t i = 0; i < c.size(); ++i) a.c0 -= c[i] * p[i];
  return a;
}

// L(M y + t) as a form in y
inline Affine substitute(const Affine& a, const std::vector<std::vector<Q>>& M, const Point& t)
{
  std::size_t n = a.c.size();
  Affine b;
  b.c.assign(n, Q(0));
  b.c0 = a(t);
  for (std::size_t k = 0; k < n; ++k)
    for (std::size_t i = 0; i < n; ++i) b.c[k] += a.c[i] * M[i][k];
  return b;
}

inline Poly affine_poly(const Affine& a)
{
  std::size_t n = a.c.size();
  Poly p(n);
  p.add_term(Poly::Exponent(n, 0), a.c0);
  for (std::size_t i = 0; i < n; ++i) {
    Poly::Exponent e(n, 0);
    e[i] = 1;
    p.add_term(e, a.c[i]);
  }
  return p;
}

inline Poly product_poly(const std::vector<Affine>& f, std::size_t n)
{
  Poly p = Poly::constant(n, Q(1));
  for (const Affine& a : f) p = p * affine_poly(a);
  return p;
}

// ------------------------------------------------------------------ exact linear algebra
// Solves A x = b exactly. 0: unique solution in x; 1: inconsistent; 2: infinitely many.
inline int solve_linear(std::vector<std::vector<Q>> A, std::vector<Q> b, Point& x)
{
  std::size_t n = A.size();
  std::size_t m = n ? A[0].size() : 0;
  std::size_t row = 0;
  std::vector<std::size_t> pivot_col;
  for (std::size_t col = 0; col < m && row < n; ++col) {
    std::size_t p = row;
    while (p < n && A[p][col] == 0) ++p;
    if (p == n) continue;
    std::swap(A[p], A[row]);
    std::swap(b[p], b[row]);
    for (std::size_t r = 0; r < n; ++r) {
      if (r == row || A[r][col] == 0) continue;
      Q f = A[r][col] / A[row][col];
      for (std::size_t k = col; k < m; ++k) A[r][k] -= f * A[row][k];
      b[r] -= f * b[row];
    }
    pivot_col.push_back(col);
    ++row;
  }
  for (std::size_t r = row; r < n; ++r)
    if (b[r] != 0) return 1;
  if (row < m) return 2;
  x.assign(m, Q(0));
  for (std::size_t r = 0; r < row; ++r) x[pivot_col[r]] = b[r] / A[r][pivot_col[r]];
  return 0;
}

inline Q determinant(std::vector<std::vector<Q>> A)
{
  std::size_t n = A.size();
  Q det = 1;
  for (std::size_t col = 0; col < n; ++col) {
    std::size_t p = col;
    while (p < n && A[p][col] == 0) ++p;
    if (p == n) return Q(0);
    if (p != col) { std::swap(A[p], A[col]); det = -det; }
    det *= A[col][col];
    for (std::size_t r = col + 1; r < n; ++r) {
      if (A[r][col] == 0) continue;
      Q f = A[r][col] / A[col][col];
      for (std::size_t k = col; k < n; ++k) A[r][k] -= f * A[col][k];
    }
  }
  return det;
}

inline std::vector<std::vector<Q>> identity(std::size_t n)
{
  std::vector<std::vector<Q>> I(n, std::vector<Q>(n, Q(0)));
  for (std::size_t i = 0; i < n; ++i) I[i][i] = 1;
  return I;
}

// a random invertible rational matrix, entries num/den with |num| <= num_max, den <= den_max
inline std::vector<std::vector<Q>> random_invertible(Rng& rng, std::size_t n, long num_max = 5, long den_max = 4)
{
  for (;;) {
    std::vector<std::vector<Q>> A(n, std::vector<Q>(n));
    for (auto& row : A)
      for (auto& a : row) a = rng.rational(num_max, den_max);
    if (determinant(A) != 0) return A;
  }
}

// ------------------------------------------------------------------ factor generators
// distinct rationals in [lo, hi] with denominators at most den
inline std::vector<Q> distinct_rationals(Rng& rng, std::size_t m, const Q& lo, const Q& hi, long den)
{
  std::vector<Q> v;
  while (v.size() < m) {
    Q r = rng.rational_in(lo, hi, rng.uniform(1, den));
    if (std::find(v.begin(), v.end(), r) == v.end()) v.push_back(r);
  }
  return v;
}

// grid: g_j = prod_m (x_j - r_{j,m}); its roots are the grid of the r's
inline std::vector<std::vector<Affine>> grid_factors(Rng& rng, const std::vector<unsigned>& degrees, const Q& lo, const Q& hi, long den)
{
  std::size_t n = degrees.size();
  std::vector<std::vector<Affine>> f(n);
  for (std::size_t j = 0; j < n; ++j)
    for (const Q& r : distinct_rationals(rng, degrees[j], lo, hi, den)) f[j].push_back(coordinate_form(n, j, r));
  return f;
}

// triangular: g_j = prod_m (x_j - sum_{k<j} c_{jkm} x_k - r_{jm})
inline std::vector<std::vector<Affine>> triangular_factors(Rng& rng, const std::vector<unsigned>& degrees, const Q& lo, const Q& hi, long den)
{
  std::size_t n = degrees.size();
  std::vector<std::vector<Affine>> f(n);
  for (std::size_t j = 0; j < n; ++j)
    for (const Q& r : distinct_rationals(rng, degrees[j], lo, hi, den)) {
      Affine a = coordinate_form(n, j, r);
      for (std::size_t k = 0; k < j; ++k) a.c[k] = rng.rational(3, 4) / Q(2);
      f[j].push_back(a);
    }
  return f;
}

// general: each factor c . (x - q) with c random and q random in [lo, hi]^n
inline std::vector<std::vector<Affine>> general_factors(Rng& rng, const std::vector<unsigned>& degrees, const Q& lo, const Q& hi, long den)
{
  std::size_t n = degrees.size();
  std::vector<std::vector<Affine>> f(n);
  for (std::size_t j = 0; j < n; ++j)
    for (unsigned m = 0; m < degrees[j]; ++m) {
      std::vector<Q> c(n);
      for (auto& x : c) x = rng.rational(4, 3);
      c[j] = rng.uniform(1, 4); // keeps every factor nonconstant
      Point q(n);
      for (auto& x : q) x = rng.rational_in(lo, hi, rng.uniform(1, den));
      f[j].push_back(form_through(c, q));
    }
  return f;
}

// shared points: factor m of every equation passes through the point P_m (random in
// [lo, hi]^n), so P_0 .. P_{min degree - 1} are roots; the other choices meet anywhere
inline std::vector<std::vector<Affine>> shared_point_factors(Rng& rng, const std::vector<unsigned>& degrees, const Q& lo, const Q& hi, long den)
{
  std::size_t n = degrees.size();
  unsigned dmax = *std::max_element(degrees.begin(), degrees.end());
  std::vector<Point> P(dmax, Point(n));
  for (auto& q : P)
    for (auto& x : q) x = rng.rational_in(lo, hi, rng.uniform(1, den));
  std::vector<std::vector<Affine>> f(n);
  for (std::size_t j = 0; j < n; ++j)
    for (unsigned m = 0; m < degrees[j]; ++m) {
      std::vector<Q> c(n);
      for (auto& x : c) x = rng.rational(4, 3);
      c[j] = rng.uniform(1, 4);
      f[j].push_back(form_through(c, P[m]));
    }
  return f;
}

// block triangular: the variables fall in consecutive blocks of 1 to 3; factor m of equation j
// is x_j - r_jm plus random multiples of the other variables of its block (each with
// probability 1/2) and of variables of the blocks before it: each with probability 1/2 when
// `earlier` < 0, else `earlier` random ones (smaller multiples: the roots stay in a box of
// moderate size as n grows). A (returned) mixes the equations within each block only, so
// f = A g is block triangular. `members` gets the blocks.
inline std::vector<std::vector<Affine>> block_triangular_factors(Rng& rng, const std::vector<unsigned>& degrees, int earlier,
                                                                 std::vector<std::vector<std::size_t>>& members, std::vector<std::vector<Q>>& A)
{
  const std::size_t n = degrees.size();
  std::vector<std::size_t> block_of(n);
  members.clear();
  for (std::size_t j = 0; j < n;) {
    std::size_t size = (std::min)(n - j, std::size_t(rng.uniform(1, 3)));
    members.emplace_back();
    for (std::size_t k = 0; k < size; ++k, ++j) { block_of[j] = members.size() - 1; members.back().push_back(j); }
  }
  std::vector<std::vector<Affine>> f(n);
  for (std::size_t j = 0; j < n; ++j)
    for (const Q& r : distinct_rationals(rng, degrees[j], Q(-3, 2), Q(3, 2), 8)) {
      Affine a = coordinate_form(n, j, r);
      for (std::size_t k = 0; k < n; ++k) {
        const bool before = block_of[k] < block_of[j];
        if (k != j && (block_of[k] == block_of[j] || (before && earlier < 0)) && rng.coin()) a.c[k] = rng.rational(3, 4) / Q(2);
      }
      for (int t = 0; t < earlier && block_of[j] > 0; ++t)
        a.c[std::size_t(rng.uniform(0, long(members[block_of[j] - 1].back())))] = rng.rational(3, 4) / Q(4);
      f[j].push_back(a);
    }
  A.assign(n, std::vector<Q>(n, Q(0)));
  for (const auto& m : members) {
    auto B = random_invertible(rng, m.size());
    for (std::size_t a = 0; a < m.size(); ++a)
      for (std::size_t b = 0; b < m.size(); ++b) A[m[a]][m[b]] = B[a][b];
  }
  return f;
}

// the factors after the change of coordinates x = M y + t
inline std::vector<std::vector<Affine>> change_coordinates(const std::vector<std::vector<Affine>>& f,
                                                           const std::vector<std::vector<Q>>& M, const Point& t)
{
  std::vector<std::vector<Affine>> g = f;
  for (auto& fj : g)
    for (auto& a : fj) a = substitute(a, M, t);
  return g;
}

// a random change of coordinates M = I + E, |E_ik| <= 1/2, |det M| >= 1/4
inline std::vector<std::vector<Q>> random_coupling(Rng& rng, std::size_t n)
{
  for (;;) {
    std::vector<std::vector<Q>> M = identity(n);
    for (std::size_t i = 0; i < n; ++i)
      for (std::size_t k = 0; k < n; ++k) M[i][k] += rng.rational(1, 4) / Q(2);
    if (CGAL::abs(determinant(M)) >= Q(1, 4)) return M;
  }
}

// ------------------------------------------------------------------ planted systems
struct Planted_root
{
  Point x;
  int selections = 1;  // how many choices of one factor per equation reach it
  bool simple = true;  // det J_f(x) != 0, checked exactly
};

struct Planted
{
  System system;
  std::vector<Planted_root> roots; // every real root, inside and outside the box
  std::string name;
};

inline std::string point_string(const Point& p)
{
  std::ostringstream os;
  os << "(";
  for (std::size_t i = 0; i < p.size(); ++i) os << (i ? ", " : "") << p[i] << " ~ " << CGAL::to_double(p[i]);
  os << ")";
  return os.str();
}

inline std::string system_string(const System& s)
{
  std::ostringstream os;
  os << s.number_of_variables() << " variables, box";
  for (const auto& b : s.box) os << " [" << b.first << ", " << b.second << "]";
  os << "\n";
  for (std::size_t i = 0; i < s.equations.size(); ++i) {
    os << "  f" << i << " = ";
    s.equations[i].write(os, s.variable_names);
    os << "\n";
  }
  return os.str();
}

inline std::vector<std::string> default_names(std::size_t n)
{
  std::vector<std::string> v;
  for (std::size_t i = 0; i < n; ++i) v.push_back("x" + std::to_string(i));
  return v;
}

inline std::vector<std::pair<double, double>> cube(std::size_t n, double lo, double hi)
{
  return std::vector<std::pair<double, double>>(n, std::make_pair(lo, hi));
}

// Builds f = A g with g_j = prod factors[j] over `box`. Returns false if the variety is not
// zero-dimensional (a singular consistent choice of factors), or, unless allow_singular, if a
// root is singular.
inline bool make_planted(const std::vector<std::vector<Affine>>& factors, const std::vector<std::vector<Q>>& A,
                         const std::vector<std::pair<double, double>>& box, Planted& out, bool allow_singular = false)
{
  std::size_t n = factors.size();
  out.system = System();
  out.roots.clear();
  out.system.variable_names = default_names(n);
  out.system.box = box;
  std::vector<Poly> g;
  for (const auto& f : factors) g.push_back(product_poly(f, n));
  for (std::size_t i = 0; i < n; ++i) {
    Poly fi(n);
    for (std::size_t j = 0; j < n; ++j)
      if (A[i][j] != 0) fi = fi + A[i][j] * g[j];
    out.system.equations.push_back(fi);
    out.system.labels.push_back("planted f" + std::to_string(i));
  }
  // every choice of one factor per equation
  std::map<Point, int> found;
  std::vector<std::size_t> sel(n, 0);
  for (;;) {
    std::vector<std::vector<Q>> M(n);
    std::vector<Q> b(n);
    for (std::size_t j = 0; j < n; ++j) {
      M[j] = factors[j][sel[j]].c;
      b[j] = -factors[j][sel[j]].c0;
    }
    Point x;
    int r = solve_linear(M, b, x);
    if (r == 2) return false;
    if (r == 0) ++found[x];
    std::size_t j = 0;
    while (j < n && ++sel[j] == factors[j].size()) sel[j++] = 0;
    if (j == n) break;
  }
  // Jacobian
  std::vector<std::vector<Poly>> J(n);
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t k = 0; k < n; ++k) J[i].push_back(out.system.equations[i].derivative(k));
  for (const auto& f : found) {
    Planted_root pr;
    pr.x = f.first;
    pr.selections = f.second;
    std::vector<std::vector<Q>> Jx(n, std::vector<Q>(n));
    for (std::size_t i = 0; i < n; ++i)
      for (std::size_t k = 0; k < n; ++k) Jx[i][k] = J[i][k].evaluate(pr.x);
    pr.simple = determinant(Jx) != 0;
    if (!pr.simple && !allow_singular) return false;
    out.roots.push_back(pr);
  }
  // the oracle checks itself: every planted root is a root, exactly
  for (const auto& pr : out.roots)
    for (std::size_t i = 0; i < n; ++i)
      CHECK(out.system.equations[i].evaluate(pr.x) == 0, "oracle: f" << i << " does not vanish at planted root " << point_string(pr.x));
  return true;
}

inline bool in_box(const Point& x, const std::vector<std::pair<double, double>>& box)
{
  for (std::size_t i = 0; i < x.size(); ++i)
    if (x[i] < Q(box[i].first) || x[i] > Q(box[i].second)) return false;
  return true;
}

// distance (max norm, exact) from x to the box; 0 inside
inline Q distance_to_box(const Point& x, const std::vector<std::pair<double, double>>& box)
{
  Q d = 0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    if (x[i] < Q(box[i].first)) d = (std::max)(d, Q(box[i].first) - x[i]);
    if (x[i] > Q(box[i].second)) d = (std::max)(d, x[i] - Q(box[i].second));
  }
  return d;
}

// ------------------------------------------------------------------ coefficient conversions
// The same system with every coefficient converted by `convert`.
template <class T, class F>
RI::Polynomial_system<T> convert_system(const System& s, F convert)
{
  RI::Polynomial_system<T> r;
  r.variable_names = s.variable_names;
  r.box = s.box;
  r.labels = s.labels;
  for (const auto& f : s.equations) {
    RI::Sparse_polynomial<T> p(s.number_of_variables());
    for (const auto& t : f.terms()) p.add_term(t.first, convert(t.second));
    r.equations.push_back(p);
  }
  return r;
}

inline RI::Polynomial_system<CGAL::Interval_nt<false>> to_interval_system(const System& s)
{
  return convert_system<CGAL::Interval_nt<false>>(s, [](const Q& c) { return CGAL::Interval_nt<false>(CGAL::to_interval(c)); });
}

// exact only if every coefficient is a double (the caller makes sure)
inline RI::Polynomial_system<double> to_double_system(const System& s)
{
  return convert_system<double>(s, [](const Q& c) {
    double d = CGAL::to_double(c);
    CHECK(Q(d) == c, "test setup: coefficient " << c << " is not a double");
    return d;
  });
}

#ifdef CGAL_USE_MPFI
inline RI::Polynomial_system<CGAL::Gmpfi> to_gmpfi_system(const System& s, CGAL::Gmpfi::Precision_type prec)
{
  return convert_system<CGAL::Gmpfi>(s, [prec](const Q& c) { return CGAL::Gmpfi(c, prec); });
}
#endif

// ------------------------------------------------------------------ exact interval bounds
// [lo, hi] of an interval as rationals; false if a bound is not a finite number
inline bool exact_bounds(const CGAL::Interval_nt<false>& x, Q& lo, Q& hi)
{
  if (!std::isfinite(x.inf()) || !std::isfinite(x.sup())) return false;
  lo = Q(x.inf());
  hi = Q(x.sup());
  return true;
}
#ifdef CGAL_USE_MPFI
inline bool exact_bounds(const CGAL::Gmpfi& x, Q& lo, Q& hi)
{
  CGAL::Gmpfr a = x.inf(), b = x.sup();
  if (!a.is_number() || !b.is_number()) return false;
  lo = Q(a);
  hi = Q(b);
  return true;
}
#endif

typedef std::vector<std::pair<Q, Q>> Q_box;

template <class IT>
bool exact_box(const std::vector<IT>& v, Q_box& b)
{
  b.resize(v.size());
  for (std::size_t i = 0; i < v.size(); ++i)
    if (!exact_bounds(v[i], b[i].first, b[i].second) || b[i].first > b[i].second) return false;
  return true;
}

inline bool contains(const Q_box& b, const Point& x)
{
  if (b.size() != x.size()) return false;
  for (std::size_t i = 0; i < x.size(); ++i)
    if (x[i] < b[i].first || x[i] > b[i].second) return false;
  return true;
}

inline bool disjoint(const Q_box& a, const Q_box& b)
{
  for (std::size_t i = 0; i < a.size(); ++i)
    if (a[i].second < b[i].first || b[i].second < a[i].first) return true;
  return false;
}

inline Q max_width(const Q_box& b)
{
  Q w = 0;
  for (const auto& x : b) w = (std::max)(w, x.second - x.first);
  return w;
}

inline std::string box_string(const Q_box& b)
{
  std::ostringstream os;
  os.precision(17);
  for (const auto& x : b) os << "[" << CGAL::to_double(x.first) << ", " << CGAL::to_double(x.second) << "]";
  return os.str();
}

// ------------------------------------------------------------------ attainable width
// An estimate, independent of the solver, of the narrowest enclosure of the simple root x that
// interval Newton / Krawczyk can reach with unit roundoff u: 2 |J(x)^-1| E, E_i a bound of
// the rounding error of evaluating f_i at x (coefficient conversion, products, sums), in the
// max norm over the variables. 0 for a singular root (not used there).
inline double attainable_width(const System& s, const Point& x, double u)
{
  std::size_t n = s.number_of_variables();
  std::vector<std::vector<Q>> J(n, std::vector<Q>(n));
  std::vector<double> E(n, 0.0);
  for (std::size_t i = 0; i < n; ++i) {
    const Poly& f = s.equations[i];
    for (std::size_t k = 0; k < n; ++k) J[i][k] = f.derivative(k).evaluate(x);
    double sum = 0;
    for (const auto& t : f.terms()) {
      double m = std::abs(CGAL::to_double(t.second));
      for (std::size_t k = 0; k < n; ++k)
        for (unsigned e = 0; e < t.first[k]; ++e) m *= std::abs(CGAL::to_double(x[k])) + u;
      sum += m;
    }
    E[i] = double(f.terms().size() + f.total_degree() + 2) * u * sum;
  }
  double w = 0;
  for (std::size_t k = 0; k < n; ++k) {
    // row k of J^-1: solve J^T z = e_k
    std::vector<std::vector<Q>> JT(n, std::vector<Q>(n));
    for (std::size_t i = 0; i < n; ++i)
      for (std::size_t j = 0; j < n; ++j) JT[i][j] = J[j][i];
    std::vector<Q> ek(n, Q(0));
    ek[k] = 1;
    Point z;
    if (solve_linear(JT, ek, z) != 0) return 0;
    double r = 0;
    for (std::size_t i = 0; i < n; ++i) r += std::abs(CGAL::to_double(z[i])) * E[i];
    w = (std::max)(w, 2 * r);
  }
  return w;
}

// ------------------------------------------------------------------ the checker
struct Expectation
{
  double tolerance = 1e-12;     // certified non-boundary enclosures at most this wide (<= 0: not checked) ...
  double unit_roundoff = 0x1p-53; // ... or at most 8 attainable_width(unit_roundoff) wide (the precision limit)
  bool complete = true;         // complete(): nothing unresolved
  bool certify_simple = true;   // every resolvable simple root in the closed box is in a certified enclosure:
                                // resolvable at unit_roundoff, 8 attainable_width < 1/4 of the distance
                                // to the nearest other planted root
};

struct Tally
{
  std::size_t systems = 0, roots_in_box = 0, certified = 0, unresolved = 0, covered_by_unresolved = 0, complete = 0;
  std::size_t boundary_roots = 0, beyond_precision = 0;
  void add(const Tally& t)
  {
    systems += t.systems; roots_in_box += t.roots_in_box; certified += t.certified; unresolved += t.unresolved;
    covered_by_unresolved += t.covered_by_unresolved; complete += t.complete; boundary_roots += t.boundary_roots;
    beyond_precision += t.beyond_precision;
  }
};

// Checks a certified (not fast) result against every planted root:
//  - each certified enclosure is a valid box, contains exactly one planted root, is inside the
//    closed search box unless flagged on_boundary, is at most `tolerance` wide unless on the
//    boundary, holds its approximation, and its residual bounds |f_i(approximation)|;
//  - certified enclosures are pairwise disjoint;
//  - each planted root in the closed box is in exactly one certified enclosure or in an
//    unresolved box (never in two certified enclosures);
//  - unresolved boxes are well-formed; complete() when expected.
template <class IT>
Tally check_result(const RI::Solver_result<IT>& r, const Planted& p, const Expectation& e, const std::string& name)
{
  Tally t;
  t.systems = 1;
  const System& s = p.system;
  std::size_t n = s.number_of_variables();
  std::vector<Q_box> enc(r.roots.size());
  std::vector<bool> valid(r.roots.size(), false);
  CHECK(!r.fast, name << ": result says fast mode");
  for (std::size_t k = 0; k < r.roots.size(); ++k) {
    const auto& root = r.roots[k];
    CHECK(root.certified, name << ": root " << k << " not certified");
    if (root.certified) ++t.certified;
    bool ok = root.enclosure.size() == n && exact_box(root.enclosure, enc[k]);
    CHECK(ok, name << ": root " << k << " enclosure is malformed (size " << root.enclosure.size() << ", NaN/inf or lo > hi)");
    if (!ok) continue;
    valid[k] = true;
    std::vector<std::size_t> inside;
    for (std::size_t j = 0; j < p.roots.size(); ++j)
      if (contains(enc[k], p.roots[j].x)) inside.push_back(j);
    CHECK(inside.size() == 1, name << ": certified enclosure " << box_string(enc[k]) << (root.on_boundary ? " (on boundary)" : "")
          << " contains " << inside.size() << " planted roots (expected exactly 1)"
          << (inside.empty() ? std::string(": spurious root") : " first " + point_string(p.roots[inside[0]].x)));
    bool enclosure_in_box = true;
    for (std::size_t i = 0; i < n; ++i)
      if (enc[k][i].first < Q(s.box[i].first) || enc[k][i].second > Q(s.box[i].second)) enclosure_in_box = false;
    CHECK(root.on_boundary || enclosure_in_box,
          name << ": enclosure " << box_string(enc[k]) << " leaves the search box but on_boundary is false");
    if (inside.size() == 1 && !in_box(p.roots[inside[0]].x, s.box))
      CHECK(root.on_boundary, name << ": enclosure " << box_string(enc[k]) << " holds only the outside root "
            << point_string(p.roots[inside[0]].x) << " and is not flagged on_boundary");
    if (e.tolerance > 0 && !root.on_boundary && inside.size() == 1) {
      double limit = p.roots[inside[0]].simple ? 8 * attainable_width(s, p.roots[inside[0]].x, e.unit_roundoff) : 0;
      if (!std::isfinite(limit)) limit = 0;
      CHECK(max_width(enc[k]) <= Q((std::max)(e.tolerance, limit)), name << ": enclosure " << box_string(enc[k]) << " is "
            << CGAL::to_double(max_width(enc[k])) << " wide, tolerance " << e.tolerance << ", precision limit ~" << limit / 8);
    }
    // approximation and residual
    CHECK(root.approximation.size() == n, name << ": root " << k << " approximation has " << root.approximation.size() << " values");
    if (root.approximation.size() == n) {
      bool finite = true;
      for (double a : root.approximation) finite = finite && std::isfinite(a);
      CHECK(finite, name << ": root " << k << " approximation not finite");
      if (finite) {
        Point a(n);
        for (std::size_t i = 0; i < n; ++i) a[i] = Q(root.approximation[i]);
        // a double of the enclosure, or (enclosure narrower than a double) next to it
        bool near = true;
        for (std::size_t i = 0; i < n; ++i) {
          double ai = root.approximation[i];
          near = near && Q(std::nextafter(ai, -HUGE_VAL)) <= enc[k][i].second && enc[k][i].first <= Q(std::nextafter(ai, HUGE_VAL));
        }
        CHECK(near, name << ": approximation " << point_string(a) << " outside its enclosure " << box_string(enc[k]));
        if (contains(enc[k], a) && !std::isinf(root.residual)) {
          bool res_ok = !std::isnan(root.residual);
          Q worst = 0;
          for (const auto& f : s.equations) worst = (std::max)(worst, CGAL::abs(f.evaluate(a)));
          if (res_ok) res_ok = Q(root.residual) >= worst;
          CHECK(res_ok, name << ": residual " << root.residual << " below |f(approximation)| = " << CGAL::to_double(worst));
        }
      }
    }
  }
  for (std::size_t a = 0; a < r.roots.size(); ++a)
    for (std::size_t b = a + 1; b < r.roots.size(); ++b)
      if (valid[a] && valid[b])
        CHECK(disjoint(enc[a], enc[b]), name << ": certified enclosures " << box_string(enc[a]) << " and " << box_string(enc[b]) << " overlap");
  // unresolved boxes
  std::vector<Q_box> ub(r.unresolved.size());
  std::vector<bool> uvalid(r.unresolved.size(), false);
  t.unresolved = r.unresolved.size();
  for (std::size_t k = 0; k < r.unresolved.size(); ++k) {
    const auto& u = r.unresolved[k];
    CHECK(u.kind == RI::Box_class::UNKNOWN || u.kind == RI::Box_class::PENDING, name << ": unresolved box " << k << " of class CERTIFIED");
    CHECK(!u.reason.empty(), name << ": unresolved box " << k << " without a reason");
    CHECK(u.boxes >= 1, name << ": unresolved cluster " << k << " merges " << u.boxes << " boxes");
    bool ok = u.box.size() == n && exact_box(u.box, ub[k]);
    CHECK(ok, name << ": unresolved box " << k << " malformed");
    uvalid[k] = ok;
  }
  // every planted root in the box is found
  for (const auto& pr : p.roots) {
    std::size_t in_certified = 0, in_unresolved = 0;
    for (std::size_t k = 0; k < r.roots.size(); ++k)
      if (valid[k] && contains(enc[k], pr.x)) ++in_certified;
    for (std::size_t k = 0; k < r.unresolved.size(); ++k)
      if (uvalid[k] && contains(ub[k], pr.x)) ++in_unresolved;
    CHECK(in_certified <= 1, name << ": planted root " << point_string(pr.x) << " in " << in_certified << " certified enclosures (duplicates)");
    if (!in_box(pr.x, s.box)) continue;
    ++t.roots_in_box;
    bool boundary = false;
    for (std::size_t i = 0; i < n; ++i)
      if (pr.x[i] == Q(s.box[i].first) || pr.x[i] == Q(s.box[i].second)) boundary = true;
    if (boundary) ++t.boundary_roots;
    if (in_certified == 0 && in_unresolved > 0) ++t.covered_by_unresolved;
    CHECK(in_certified + in_unresolved > 0, name << ": planted root " << point_string(pr.x) << (pr.simple ? " (simple)" : " (singular)")
          << (boundary ? " on the box boundary" : "") << " missed: in no certified enclosure and no unresolved box");
    bool resolvable = true;
    if (pr.simple) {
      Q separation = -1;
      for (const auto& other : p.roots) {
        if (&other == &pr) continue;
        Q d = 0;
        for (std::size_t i = 0; i < n; ++i) d = (std::max)(d, CGAL::abs(other.x[i] - pr.x[i]));
        if (separation < 0 || d < separation) separation = d;
      }
      double att = attainable_width(s, pr.x, e.unit_roundoff);
      if (separation >= 0 && !(8 * att < CGAL::to_double(separation) / 4)) {
        resolvable = false;
        ++t.beyond_precision;
      }
    }
    if (e.certify_simple && pr.simple && resolvable)
      CHECK(in_certified == 1, name << ": simple planted root " << point_string(pr.x) << (boundary ? " on the box boundary" : "")
            << " not certified");
  }
  if (e.complete && t.beyond_precision == 0)
    CHECK(r.complete(), name << ": not complete (" << r.unresolved.size() << " unresolved"
          << (r.unresolved.empty() ? std::string() : ", first: " + r.unresolved[0].reason + " " +
              (uvalid[0] ? box_string(ub[0]) : std::string("?"))) << ")");
  if (r.complete()) ++t.complete;
  CHECK(r.complete() == (r.unresolved.empty()), name << ": complete() disagrees with the unresolved list");
  return t;
}

} // namespace planted_systems

#endif
