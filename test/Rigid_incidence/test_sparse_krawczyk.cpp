// Copyright (c) 2026 Rigid_incidence contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The Krawczyk test on sparse polynomials (internal/sparse_krawczyk.h), which tightens the
// roots a solution plan assembles from its blocks when the whole system is beyond the dense
// arrays. Oracle: exact planted roots. Random sparse systems of 2 to 14 variables, degree up
// to 3, each f_i = g_i - g_i(r) with r a rational point (so r is an exact root, simple for a
// generic g), from a box of 1e-4 around r (r off centre):
//  - in double intervals: proved, r inside (compared exactly, in rationals), at most 1e-10 wide;
//  - in CGAL::Gmpfi at 128 bits: the same, at most 1e-25 wide;
// a linear system from a box that misses its one root: empty; x^2 = 0 (a double root): never
// proved, 0 kept; a root near 10^6 and a Jacobian of condition 10^8 (exact coefficients):
// double precision stops above the tolerance 1e-12, 128 bits reach it; a system that is not
// square, or a box of the wrong size: Input_error.

#include "test_check.h"

#include <CGAL/Gmpq.h>
#include <CGAL/Interval_nt.h>
#include <CGAL/Rigid_incidence/Input_error.h>
#include <CGAL/Rigid_incidence/Polynomial_system.h>
#include <CGAL/Rigid_incidence/internal/sparse_krawczyk.h>
#ifdef CGAL_USE_MPFI
#include <CGAL/Gmpfi.h>
#endif

#include <iostream>
#include <random>
#include <string>
#include <vector>

namespace RI = CGAL::Rigid_incidence;
typedef CGAL::Gmpq Q;
typedef CGAL::Interval_nt<false> I;
typedef RI::Sparse_polynomial<Q> Poly;

// r inside every interval of X, exactly
template <class IT>
static bool holds(const std::vector<IT>& X, const std::vector<Q>& r)
{
  typedef RI::internal::Interval_ops<IT> O;
  for (std::size_t j = 0; j < r.size(); ++j)
    if (!(Q(O::lower(X[j])) <= r[j] && r[j] <= Q(O::upper(X[j])))) return false;  // (a double or a Gmpfr bound: exact)
  return true;
}

template <class IT>
static std::vector<IT> box_around(const std::vector<Q>& r, const std::vector<double>& below, const std::vector<double>& above)
{
  typedef RI::internal::Interval_ops<IT> O;
  std::vector<IT> X;
  for (std::size_t j = 0; j < r.size(); ++j) {
    const std::pair<double, double> e = CGAL::to_interval(r[j]);
    X.push_back(O::make(O::bound_from_double(e.first - below[j]), O::bound_from_double(e.second + above[j])));
  }
  return X;
}

// monomial of exponent e, evaluated exactly at r
static Q monomial(const std::vector<unsigned>& e, const std::vector<Q>& r)
{
  Q m(1);
  for (std::size_t j = 0; j < e.size(); ++j)
    for (unsigned k = 0; k < e[j]; ++k) m *= r[j];
  return m;
}

int main()
{
  std::mt19937_64 rng(20261128);
  auto uniform = [&](long lo, long hi) { return std::uniform_int_distribution<long>(lo, hi)(rng); };
  std::size_t proved_double = 0, proved_mp = 0, systems = 0;
  double widest_double = 0, widest_mp = 0;
  for (int s = 0; s < 60; ++s) {
    const std::size_t n = std::size_t(2 + s % 13);
    std::vector<Q> r(n);
    for (auto& x : r) x = Q(uniform(-300, 300), uniform(1, 97));
    std::vector<Poly> f;
    for (std::size_t i = 0; i < n; ++i) {
      Poly g(n);
      // a term in x_i (the Jacobian's diagonal: generic, invertible) and 2 to 5 random terms of
      // degree at most 3 in at most 3 variables
      std::vector<unsigned> e(n, 0);
      e[i] = 1;
      g.add_term(e, Q(uniform(5, 20), uniform(1, 5)));
      const long terms = uniform(2, 5);
      for (long t = 0; t < terms; ++t) {
        std::vector<unsigned> d(n, 0);
        const long vars = uniform(1, 3);
        unsigned deg = 0;
        for (long v = 0; v < vars && deg < 3; ++v) {
          const std::size_t j = std::size_t(uniform(0, long(n) - 1));
          ++d[j];
          ++deg;
        }
        g.add_term(d, Q(uniform(-9, 9), uniform(1, 7)));
      }
      Q at(0);
      for (const auto& t : g.terms()) at += t.second * monomial(t.first, r);
      g.add_term(std::vector<unsigned>(n, 0), -at);
      f.push_back(g);
    }
    ++systems;
    std::vector<double> below(n), above(n);
    for (std::size_t j = 0; j < n; ++j) {
      below[j] = 1e-4 * double(uniform(1, 99)) / 100;
      above[j] = 1e-4 - below[j];
    }
    {
      typename CGAL::Interval_nt<false>::Protector protect;
      const RI::internal::Sparse_krawczyk_system<I> k(f);
      std::vector<I> X = box_around<I>(r, below, above);
      const auto o = RI::internal::sparse_krawczyk_tighten(k, X, 1e-13);
      CHECK(!o.empty && holds(X, r), "system " << s << " (" << n << " variables): the root left the box in double");
      CHECK(o.width <= 1e-10, "system " << s << " (" << n << " variables): " << o.width << " wide in double");
      proved_double += o.proved;
      widest_double = (std::max)(widest_double, o.width);
    }
#ifdef CGAL_USE_MPFI
    {
      RI::internal::Solver_precision_guard<CGAL::Gmpfi> guard(128);
      const RI::internal::Sparse_krawczyk_system<CGAL::Gmpfi> k(f);
      std::vector<CGAL::Gmpfi> X = box_around<CGAL::Gmpfi>(r, below, above);
      const auto o = RI::internal::sparse_krawczyk_tighten(k, X, 1e-30);
      CHECK(!o.empty && holds(X, r), "system " << s << " (" << n << " variables): the root left the box at 128 bits");
      CHECK(o.width <= 1e-25, "system " << s << " (" << n << " variables): " << o.width << " wide at 128 bits");
      proved_mp += o.proved;
      widest_mp = (std::max)(widest_mp, o.width);
    }
#endif
  }
  // (a generic system, a box 1e-4 wide: K(X) inside it at the first step, every time)
  CHECK(proved_double == systems, proved_double << " of " << systems << " proved in double");
#ifdef CGAL_USE_MPFI
  CHECK(proved_mp == systems, proved_mp << " of " << systems << " proved at 128 bits");
#endif
  std::cout << systems << " random systems: " << proved_double << " proved in double (widest " << widest_double << "), " << proved_mp
            << " at 128 bits (widest " << widest_mp << ")\n";

  typename CGAL::Interval_nt<false>::Protector protect;
  // a linear system, a box beside its one root: disjoint
  {
    Poly a(2), b(2);
    a.add_term({1, 0}, Q(2));
    a.add_term({0, 1}, Q(1));
    a.add_term({0, 0}, Q(-3));  // 2x + y = 3
    b.add_term({1, 0}, Q(1));
    b.add_term({0, 1}, Q(-1));  // x - y = 0: (1, 1)
    const RI::internal::Sparse_krawczyk_system<I> k(std::vector<Poly>{a, b});
    std::vector<I> X = {I(1.01, 1.02), I(0.99, 1.0)};
    const auto o = RI::internal::sparse_krawczyk_tighten(k, X, 1e-12);
    CHECK(o.empty && !o.proved, "linear system, a box beside its root: not found empty");
    std::vector<I> Y = {I(0.9, 1.2), I(0.95, 1.1)};
    const auto p = RI::internal::sparse_krawczyk_tighten(k, Y, 1e-12);
    CHECK(p.proved && p.width <= 1e-12 && Y[0].inf() <= 1 && 1 <= Y[0].sup() && Y[1].inf() <= 1 && 1 <= Y[1].sup(),
          "linear system, a box around its root: not tightened to (1, 1)");
  }
  // a double root: never proved, still inside
  {
    Poly a(1);
    a.add_term({2}, Q(1));
    const RI::internal::Sparse_krawczyk_system<I> k(std::vector<Poly>{a});
    std::vector<I> X = {I(-1e-3, 2e-3)};
    const auto o = RI::internal::sparse_krawczyk_tighten(k, X, 1e-12);
    CHECK(!o.proved && !o.empty && X[0].inf() <= 0 && 0 <= X[0].sup(), "x^2 = 0: proved, or 0 lost");
  }
  // a root near 10^6 and a Jacobian of condition 1e8: x + y = s, x + (1 + 10^-8) y = t
  {
    const Q x0 = Q(1000000) + Q(1, 3), y0 = Q(-7, 11), c = Q(1) + Q(1, 100000000);
    Poly a(2), b(2);
    a.add_term({1, 0}, Q(1));
    a.add_term({0, 1}, Q(1));
    a.add_term({0, 0}, -(x0 + y0));
    b.add_term({1, 0}, Q(1));
    b.add_term({0, 1}, c);
    b.add_term({0, 0}, -(x0 + c * y0));
    const std::vector<Poly> f = {a, b};
    const std::vector<Q> r = {x0, y0};
    const std::vector<double> off = {1e-7, 1e-7};
    const RI::internal::Sparse_krawczyk_system<I> k(f);
    std::vector<I> X = box_around<I>(r, off, off);
    const auto o = RI::internal::sparse_krawczyk_tighten(k, X, 1e-12);
    CHECK(!o.empty && holds(X, r), "ill-conditioned: the root left the box in double");
    // (10^6 alone is an ulp of 1.2e-10; the conditioning multiplies the rounding errors)
    CHECK(o.width > 1e-12, "ill-conditioned: double reached " << o.width << ", the test below proves nothing");
    std::cout << "ill-conditioned, root near 1e6: " << o.width << " wide in double";
#ifdef CGAL_USE_MPFI
    RI::internal::Solver_precision_guard<CGAL::Gmpfi> guard(128);
    const RI::internal::Sparse_krawczyk_system<CGAL::Gmpfi> km(f);
    std::vector<CGAL::Gmpfi> Y;
    for (const I& v : X) Y.push_back(RI::internal::Interval_ops<CGAL::Gmpfi>::from(v));
    const auto p = RI::internal::sparse_krawczyk_tighten(km, Y, 1e-12);
    CHECK(!p.empty && holds(Y, r) && p.width <= 1e-12, "ill-conditioned: " << p.width << " wide at 128 bits");
    std::cout << ", " << p.width << " at 128 bits";
#endif
    std::cout << "\n";
  }
  // malformed input
  {
    bool thrown = false;
    try {
      Poly a(3);
      a.add_term({1, 0, 0}, Q(1));
      const RI::internal::Sparse_krawczyk_system<I> k(std::vector<Poly>{a, a});
    } catch (const RI::Input_error& e) {
      thrown = std::string(e.what()).find("not square") != std::string::npos;
    }
    CHECK(thrown, "2 equations in 3 variables: no Input_error naming it");
    thrown = false;
    try {
      Poly a(1);
      a.add_term({1}, Q(1));
      const RI::internal::Sparse_krawczyk_system<I> k(std::vector<Poly>{a});
      std::vector<I> X = {I(0, 1), I(0, 1)};
      RI::internal::sparse_krawczyk_tighten(k, X, 1e-12);
    } catch (const RI::Input_error&) {
      thrown = true;
    }
    CHECK(thrown, "a box of 2 variables for 1 equation: no Input_error");
  }
  std::cout << checks << " checks, " << failures << " failures\n";
  return failures == 0 ? 0 : 1;
}
