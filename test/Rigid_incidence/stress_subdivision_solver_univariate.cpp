// Copyright (c) 2026 Rigid_incidence contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The subdivision solver on univariate polynomials against CGAL's Algebraic_kernel_d_1 over
// Gmpz (Descartes isolation, exact): Solve_1 gives every real root with its multiplicity, and
// Compare_1 compares an algebraic real with the rational bounds of an enclosure exactly.
// Polynomials: random integer and rational coefficients (degree 1 .. 12), products of random
// rational linear factors and quadratics, Wilkinson-like products (integer roots, roots 1e-3
// apart), Mignotte polynomials x^d - 2 (a x - 1)^2 (two roots very close to 1/a), squared
// factors. Checks, for every result:
//  - each simple real root in the closed box is in exactly one certified enclosure;
//  - each multiple root in the box is in no certified enclosure and in an UNKNOWN box whose
//    reason says "multiple";
//  - each certified enclosure contains exactly one real root (none spurious), of multiplicity 1,
//    lies in the box unless flagged on_boundary, is at most the tolerance wide (or at the
//    precision limit), and the enclosures are disjoint;
//  - complete() exactly when no multiple root is in the box (for the well-separated cases).

#include "test_check.h"

#include <CGAL/Algebraic_kernel_d_1.h>
#include <CGAL/Gmpq.h>
#include <CGAL/Gmpz.h>
#include <CGAL/Interval_nt.h>
#include <CGAL/Rigid_incidence/Subdivision_solver.h>
#ifdef CGAL_USE_MPFI
#include <CGAL/Gmpfi.h>
#endif

#include <chrono>
#include <cmath>
#include <cstdint>
#include <iostream>
#include <random>
#include <sstream>
#include <string>
#include <vector>

namespace RI = CGAL::Rigid_incidence;
typedef CGAL::Gmpq Q;
typedef CGAL::Gmpz Z;
typedef CGAL::Algebraic_kernel_d_1<Z> AK;
typedef AK::Polynomial_1 Poly_z;
typedef AK::Algebraic_real_1 Alg;
typedef AK::Bound Bound;
typedef CGAL::Interval_nt<false> I;

static const std::uint64_t seed = 7391026;
static AK ak;

struct Rng
{
  std::mt19937_64 g;
  explicit Rng(std::uint64_t s) : g(s) {}
  long uniform(long lo, long hi) { return std::uniform_int_distribution<long>(lo, hi)(g); }
  Q rational(long num, long den) { return Q(uniform(-num, num), uniform(1, den)); }
};

// a univariate test case: the rational polynomial given to the solver (coefficients from
// degree 0 up) and the box
struct Case
{
  std::string name;
  std::vector<Q> coefficients;
  double lo, hi;
  bool expect_complete_if_squarefree = true; // false: a hard case (roots closer than double precision resolves)
};

static std::string poly_string(const std::vector<Q>& c)
{
  std::ostringstream os;
  bool first = true;
  for (std::size_t k = c.size(); k-- > 0;) {
    if (c[k] == 0) continue;
    os << (first ? "" : " + ") << "(" << c[k] << ")";
    if (k) os << "*x^" << k;
    first = false;
  }
  return first ? "0" : os.str();
}

// the integer polynomial with the same roots: times the product of the denominators
static Poly_z integer_polynomial(const std::vector<Q>& c)
{
  Z d = 1;
  for (const Q& q : c) d *= q.denominator();
  std::vector<Z> z;
  for (const Q& q : c) {
    Q s = q * Q(d);
    CHECK(s.denominator() == 1, "setup: denominators");
    z.push_back(s.numerator());
  }
  return Poly_z(z.begin(), z.end());
}

static std::vector<Q> multiply(const std::vector<Q>& a, const std::vector<Q>& b)
{
  std::vector<Q> r(a.size() + b.size() - 1, Q(0));
  for (std::size_t i = 0; i < a.size(); ++i)
    for (std::size_t j = 0; j < b.size(); ++j) r[i + j] += a[i] * b[j];
  return r;
}

static RI::Polynomial_system<Q> make_system(const Case& c)
{
  RI::Polynomial_system<Q> s;
  s.variable_names = {"x"};
  s.box = {{c.lo, c.hi}};
  RI::Sparse_polynomial<Q> p(1);
  for (std::size_t k = 0; k < c.coefficients.size(); ++k) p.add_term({unsigned(k)}, c.coefficients[k]);
  s.equations = {p};
  s.labels = {c.name};
  return s;
}

template <class IT> static bool exact_bounds(const IT& x, Q& lo, Q& hi);
template <> bool exact_bounds(const I& x, Q& lo, Q& hi)
{
  if (!std::isfinite(x.inf()) || !std::isfinite(x.sup()) || x.inf() > x.sup()) return false;
  lo = Q(x.inf());
  hi = Q(x.sup());
  return true;
}
#ifdef CGAL_USE_MPFI
template <> bool exact_bounds(const CGAL::Gmpfi& x, Q& lo, Q& hi)
{
  if (!x.inf().is_number() || !x.sup().is_number()) return false;
  lo = Q(x.inf());
  hi = Q(x.sup());
  return lo <= hi;
}
#endif

static bool alg_in(const Alg& a, const Q& lo, const Q& hi)
{
  AK::Compare_1 compare = ak.compare_1_object();
  return compare(a, Bound(lo)) != CGAL::SMALLER && compare(a, Bound(hi)) != CGAL::LARGER;
}

static double alg_double(const Alg& a)
{
  std::pair<Bound, Bound> b = ak.approximate_absolute_1_object()(a, 80);
  return CGAL::to_double((b.first + b.second) / 2);
}

// narrowest enclosure interval Newton can reach with unit roundoff u around the simple root x
static double attainable_width(const std::vector<Q>& c, double x, double u)
{
  double sum = 0, d = 0, terms = 0;
  for (std::size_t k = 0; k < c.size(); ++k) {
    double ck = CGAL::to_double(c[k]);
    if (ck == 0) continue;
    ++terms;
    sum += std::abs(ck) * std::pow(std::abs(x) + u, double(k));
    if (k) d += double(k) * ck * std::pow(x, double(k - 1));
  }
  if (d == 0) return HUGE_VAL;
  return 2 * (terms + double(c.size()) + 1) * u * sum / std::abs(d);
}

struct Tally
{
  std::size_t cases = 0, roots_in_box = 0, multiple_in_box = 0, certified = 0, complete = 0, beyond_precision = 0;
};
static Tally tally;

static RI::Polynomial_system<I> to_interval_system(const RI::Polynomial_system<Q>& s)
{
  RI::Polynomial_system<I> si;
  si.variable_names = s.variable_names;
  si.box = s.box;
  si.labels = s.labels;
  RI::Sparse_polynomial<I> p(1);
  for (const auto& t : s.equations[0].terms()) p.add_term(t.first, I(CGAL::to_interval(t.second)));
  si.equations = {p};
  return si;
}

// Solves c with the solver IT (coefficients exact, or their Interval_nt enclosures) and checks
// the result against the algebraic kernel. A simple root must be certified if the case expects
// it and the root is resolvable at the working precision: 8 attainable_width < 1/4 of the
// distance to the nearest other real root.
template <class IT>
static void check_case(const Case& c, const RI::Subdivision_solver_parameters& prm, double width_required, double unit_roundoff,
                       const std::string& tag, bool interval_coefficients = false)
{
  std::string name = c.name + tag;
  RI::Solver_result<IT> r;
  try {
    if (interval_coefficients) r = RI::Subdivision_solver<IT>(prm).solve(to_interval_system(make_system(c)));
    else r = RI::Subdivision_solver<IT>(prm).solve(make_system(c));
  } catch (const std::exception& e) {
    CHECK(false, name << ": solve threw " << e.what() << "\n  p = " << poly_string(c.coefficients));
    return;
  }
  if (r.statistics.seconds > 0.5)
    std::cout << "  slow: " << name << ": " << r.statistics.seconds << " s, " << r.statistics.boxes << " boxes\n";
  int before = failures;
  ++tally.cases;
  Poly_z pz = integer_polynomial(c.coefficients);
  std::vector<std::pair<Alg, int>> roots;
  ak.solve_1_object()(pz, std::back_inserter(roots));
  Q blo(c.lo), bhi(c.hi);
  // certified enclosures
  std::vector<std::pair<Q, Q>> enc(r.roots.size());
  std::vector<bool> valid(r.roots.size(), false);
  CHECK(!r.fast, name << ": fast");
  for (std::size_t k = 0; k < r.roots.size(); ++k) {
    const auto& root = r.roots[k];
    CHECK(root.certified, name << ": root " << k << " not certified");
    if (root.certified) ++tally.certified;
    bool ok = root.enclosure.size() == 1 && exact_bounds(root.enclosure[0], enc[k].first, enc[k].second);
    CHECK(ok, name << ": root " << k << " has a malformed enclosure");
    if (!ok) continue;
    valid[k] = true;
    std::vector<std::size_t> in;
    for (std::size_t j = 0; j < roots.size(); ++j)
      if (alg_in(roots[j].first, enc[k].first, enc[k].second)) in.push_back(j);
    CHECK(in.size() == 1, name << ": certified enclosure [" << CGAL::to_double(enc[k].first) << ", " << CGAL::to_double(enc[k].second)
          << "] contains " << in.size() << " real roots");
    if (in.size() != 1) continue;
    const Alg& a = roots[in[0]].first;
    CHECK(roots[in[0]].second == 1, name << ": root ~" << alg_double(a) << " of multiplicity " << roots[in[0]].second << " certified");
    bool enclosure_in_box = enc[k].first >= blo && enc[k].second <= bhi;
    CHECK(root.on_boundary || enclosure_in_box, name << ": enclosure leaves the box, on_boundary false");
    if (!alg_in(a, blo, bhi)) CHECK(root.on_boundary, name << ": root ~" << alg_double(a) << " outside the box certified without on_boundary");
    if (width_required > 0 && !root.on_boundary && roots[in[0]].second == 1) {
      double limit = 8 * attainable_width(c.coefficients, alg_double(a), unit_roundoff);
      if (!std::isfinite(limit)) limit = 0;
      CHECK(enc[k].second - enc[k].first <= Q((std::max)(width_required, limit)),
            name << ": enclosure of ~" << alg_double(a) << " is " << CGAL::to_double(enc[k].second - enc[k].first) << " wide, required "
                 << width_required << ", precision limit ~" << limit / 8);
    }
    if (root.approximation.size() == 1 && std::isfinite(root.approximation[0])) {
      double x = root.approximation[0];
      CHECK(Q(std::nextafter(x, -HUGE_VAL)) <= enc[k].second && enc[k].first <= Q(std::nextafter(x, HUGE_VAL)),
            name << ": approximation " << x << " outside its enclosure");
    } else {
      CHECK(false, name << ": approximation missing or not finite");
    }
  }
  for (std::size_t a = 0; a < r.roots.size(); ++a)
    for (std::size_t b = a + 1; b < r.roots.size(); ++b)
      if (valid[a] && valid[b])
        CHECK(enc[a].second < enc[b].first || enc[b].second < enc[a].first, name << ": certified enclosures overlap");
  // unresolved boxes
  std::vector<std::pair<Q, Q>> ub(r.unresolved.size());
  std::vector<bool> uvalid(r.unresolved.size(), false);
  for (std::size_t k = 0; k < r.unresolved.size(); ++k) {
    const auto& u = r.unresolved[k];
    CHECK(u.kind != RI::Box_class::CERTIFIED && !u.reason.empty(), name << ": unresolved box " << k << " of class CERTIFIED or without reason");
    uvalid[k] = u.box.size() == 1 && exact_bounds(u.box[0], ub[k].first, ub[k].second);
    CHECK(uvalid[k], name << ": unresolved box " << k << " malformed");
  }
  // every real root in the box
  bool multiple_in_box = false, hard = false;
  for (const auto& ar : roots) {
    std::size_t in_certified = 0, in_multiple = 0, in_unresolved = 0;
    for (std::size_t k = 0; k < r.roots.size(); ++k)
      if (valid[k] && alg_in(ar.first, enc[k].first, enc[k].second)) ++in_certified;
    for (std::size_t k = 0; k < r.unresolved.size(); ++k)
      if (uvalid[k] && alg_in(ar.first, ub[k].first, ub[k].second)) {
        ++in_unresolved;
        if (r.unresolved[k].kind == RI::Box_class::UNKNOWN && r.unresolved[k].reason.find("multiple") != std::string::npos) ++in_multiple;
      }
    CHECK(in_certified <= 1, name << ": root ~" << alg_double(ar.first) << " in " << in_certified << " certified enclosures");
    if (!alg_in(ar.first, blo, bhi)) continue;
    ++tally.roots_in_box;
    if (ar.second == 1) {
      CHECK(in_certified + in_unresolved >= 1, name << ": simple root ~" << alg_double(ar.first) << " missed");
      double x = alg_double(ar.first), separation = HUGE_VAL;
      for (const auto& other : roots)
        if (&other != &ar) separation = (std::min)(separation, std::abs(alg_double(other.first) - x));
      bool resolvable = 8 * attainable_width(c.coefficients, x, unit_roundoff) < separation / 4;
      if (!resolvable) {
        ++tally.beyond_precision;
        hard = true;
      }
      if (c.expect_complete_if_squarefree && resolvable)
        CHECK(in_certified == 1, name << ": simple root ~" << alg_double(ar.first) << " not certified"
              << (in_unresolved ? " (in an unresolved box)" : ""));
    } else {
      multiple_in_box = true;
      ++tally.multiple_in_box;
      CHECK(in_certified == 0 && in_multiple >= 1, name << ": root ~" << alg_double(ar.first) << " of multiplicity " << ar.second << ": "
            << in_certified << " certified enclosures, " << in_multiple << " UNKNOWN boxes with \"multiple\" (" << in_unresolved
            << " unresolved boxes)");
    }
  }
  if (!multiple_in_box && !hard && c.expect_complete_if_squarefree)
    CHECK(r.complete(), name << ": not complete (" << r.unresolved.size() << " unresolved"
          << (r.unresolved.empty() ? std::string() : ", first: " + r.unresolved[0].reason) << ")");
  if (multiple_in_box) CHECK(!r.complete(), name << ": complete with a multiple root");
  if (r.complete()) ++tally.complete;
  if (failures > before && failures <= max_messages)
    std::cerr << "  p = " << poly_string(c.coefficients) << " on [" << c.lo << ", " << c.hi << "], " << roots.size() << " real roots\n";
}

static void check_default(const Case& c)
{
  check_case<I>(c, RI::Subdivision_solver_parameters(), 1e-12, 0x1p-53, "");
}

// a dyadic bound >= every |root|: 1 + max |a_k / a_d| (Cauchy), rounded up to a power of 2
static double cauchy_box(const std::vector<Q>& c)
{
  Q m = 0;
  for (std::size_t k = 0; k + 1 < c.size(); ++k) m = (std::max)(m, CGAL::abs(c[k] / c.back()));
  double b = 1;
  while (Q(b) < m + 1) b *= 2;
  return b;
}

// ------------------------------------------------------------------ cases
static std::vector<Q> linear(const Q& root) { return {-root, Q(1)}; }

static std::vector<Case> random_cases(Rng& rng, int count)
{
  std::vector<Case> v;
  for (int k = 0; k < count; ++k) {
    Case c;
    int d = int(rng.uniform(1, 12));
    bool rational = k % 2 == 1;
    c.coefficients.resize(d + 1);
    for (auto& a : c.coefficients) a = rational ? rng.rational(50, 30) : Q(rng.uniform(-100, 100));
    while (c.coefficients.back() == 0) c.coefficients.back() = rng.uniform(1, 9);
    double b = cauchy_box(c.coefficients);
    switch (k % 4) {
    case 0: c.lo = -b; c.hi = b; break;     // every real root
    case 1: c.lo = -1; c.hi = 1; break;
    case 2: c.lo = -0.75; c.hi = 2.5; break;
    default: c.lo = -b / 4; c.hi = 0.125; break;
    }
    c.name = std::string(rational ? "random rational" : "random integer") + " degree " + std::to_string(d) + " #" + std::to_string(k);
    v.push_back(c);
  }
  return v;
}

static std::vector<Case> product_cases(Rng& rng, int count)
{
  std::vector<Case> v;
  for (int k = 0; k < count; ++k) {
    Case c;
    std::vector<Q> p = {rng.rational(20, 9)};
    if (p[0] == 0) p[0] = 1;
    int d = int(rng.uniform(1, 8));
    std::vector<Q> used;
    for (int j = 0; j < d; ++j) {
      Q r = rng.rational(9, 10) / Q(5);
      if (std::find(used.begin(), used.end(), r) != used.end()) continue;
      used.push_back(r);
      p = multiply(p, linear(r));
    }
    if (k % 3 == 0) p = multiply(p, {Q(long(rng.uniform(1, 5)), 7L), Q(0), Q(1)});     // x^2 + a: no real root
    if (k % 3 == 1) p = multiply(p, {Q(-long(rng.uniform(1, 7)), 5L), Q(0), Q(1)});    // x^2 - a: irrational roots (or rational)
    c.coefficients = p;
    c.lo = -1.5;
    c.hi = 1.5;
    c.name = "product of linear factors #" + std::to_string(k);
    v.push_back(c);
  }
  return v;
}

static std::vector<Case> wilkinson_cases()
{
  std::vector<Case> v;
  for (int n : {5, 8, 10, 12}) {
    std::vector<Q> p = {Q(1)};
    for (int k = 1; k <= n; ++k) p = multiply(p, linear(Q(k)));
    v.push_back(Case{"Wilkinson " + std::to_string(n) + " on [0, n+1]", p, 0, double(n + 1)});
    v.push_back(Case{"Wilkinson " + std::to_string(n) + " on [1, n] (roots on the boundary)", p, 1, double(n)});
    v.push_back(Case{"Wilkinson " + std::to_string(n) + " on [1.5, n - 0.5]", p, 1.5, n - 0.5});
    std::vector<Q> s = {Q(1)};
    for (int k = 1; k <= n; ++k) s = multiply(s, linear(Q(k, n)));
    v.push_back(Case{"scaled Wilkinson " + std::to_string(n) + " (roots k/n) on [0, 1]", s, 0, 1});
  }
  // close roots: 1/2 + k/1000, and 1/3 + k 1e-6
  {
    std::vector<Q> p = {Q(1)};
    for (int k = 1; k <= 8; ++k) p = multiply(p, linear(Q(1, 2) + Q(k, 1000)));
    v.push_back(Case{"8 roots 1e-3 apart", p, -1, 1});
    std::vector<Q> q = {Q(1)};
    for (int k = 1; k <= 4; ++k) q = multiply(q, linear(Q(1, 3) + Q(k, 1000000)));
    v.push_back(Case{"4 roots 1e-6 apart", q, -1, 1});
    std::vector<Q> w = multiply(linear(Q(1, 3)), linear(Q(1, 3) + Q(1, 100000000)));
    v.push_back(Case{"2 roots 1e-8 apart", w, -1, 1});
  }
  return v;
}

// x^d - 2 (a x - 1)^2: two real roots about 2^(1/2) a^(-d/2 - 1) apart around 1/a
static Case mignotte(int d, long a, double lo, double hi, bool easy)
{
  std::vector<Q> p(d + 1, Q(0));
  p[d] = 1;
  p[2] -= 2 * a * a;
  p[1] += 4 * a;
  p[0] -= 2;
  Case c{"Mignotte d = " + std::to_string(d) + ", a = " + std::to_string(a), p, lo, hi, easy};
  return c;
}

static std::vector<Case> mignotte_cases()
{
  std::vector<Case> v;
  v.push_back(mignotte(5, 10, -2, 2, true));    // separation ~ 4e-4
  v.push_back(mignotte(8, 10, -2, 2, true));    // ~ 1.4e-5
  v.push_back(mignotte(10, 10, 0, 1, true));    // ~ 1.4e-6
  v.push_back(mignotte(12, 10, 0, 1, true));    // ~ 1.4e-7
  v.push_back(mignotte(7, 30, -1, 1, true));    // ~ 3e-7
  v.push_back(mignotte(6, 100, -1, 1, true));   // ~ 1.4e-8, at the limit of double precision
  v.push_back(mignotte(12, 100, 0, 0.5, true));  // ~ 1.4e-14, beyond double precision
  return v;
}

static std::vector<Case> multiple_cases(Rng& rng, int count)
{
  std::vector<Case> v;
  v.push_back(Case{"(x - 1/3)^2 (x + 1/2)", multiply(multiply(linear(Q(1, 3)), linear(Q(1, 3))), linear(Q(-1, 2))), -1, 1});
  v.push_back(Case{"(x^2 - 2)^2 (x - 1)", multiply(multiply({Q(-2), Q(0), Q(1)}, {Q(-2), Q(0), Q(1)}), linear(Q(1))), -2, 2});
  {
    std::vector<Q> p = multiply(multiply(linear(Q(1, 2)), linear(Q(1, 2))), linear(Q(1, 2)));
    p = multiply(p, multiply(linear(Q(-1)), linear(Q(-1))));
    p = multiply(p, linear(Q(0)));
    v.push_back(Case{"(x - 1/2)^3 (x + 1)^2 x", p, -1.5, 1.5});
  }
  v.push_back(Case{"x^2 (double root at 0, box [-1, 1])", {Q(0), Q(0), Q(1)}, -1, 1});
  for (int k = 0; k < count; ++k) {
    // q^2 r with q, r products of random rational linear factors
    std::vector<Q> q = {Q(1)}, r = {Q(long(rng.uniform(1, 5)), long(rng.uniform(1, 3)))};
    std::vector<Q> used;
    int dq = int(rng.uniform(1, 2)), dr = int(rng.uniform(0, 3));
    for (int j = 0; j < dq + dr; ++j) {
      Q x = rng.rational(15, 11) / Q(10);
      if (std::find(used.begin(), used.end(), x) != used.end()) { --j; continue; }
      used.push_back(x);
      if (j < dq) q = multiply(q, linear(x));
      else r = multiply(r, linear(x));
    }
    v.push_back(Case{"q^2 r random #" + std::to_string(k), multiply(multiply(q, q), r), -1.25, 1.25});
  }
  return v;
}

int main()
{
  std::cout << "test_subdivision_solver_univariate: seed " << seed << "\n";
  auto t0 = std::chrono::steady_clock::now();
  Rng rng(seed);
  std::vector<Case> all;
  for (const auto& c : random_cases(rng, 240)) all.push_back(c);
  for (const auto& c : product_cases(rng, 60)) all.push_back(c);
  for (const auto& c : wilkinson_cases()) all.push_back(c);
  for (const auto& c : mignotte_cases()) all.push_back(c);
  std::vector<Case> mult = multiple_cases(rng, 30);
  for (const auto& c : mult) all.push_back(c);
  for (const auto& c : all) check_default(c);
  std::cout << "Interval_nt solver: " << tally.cases << " polynomials, " << tally.roots_in_box << " real roots in the boxes ("
            << tally.multiple_in_box << " multiple), " << tally.certified << " certified, " << tally.complete << " complete, "
            << tally.beyond_precision << " simple roots beyond double precision (not required)\n";

  // degenerate equations: a nonzero constant (no root), the zero polynomial (Input_error)
  {
    Case c{"constant 3", {Q(3)}, -1, 1};
    check_default(c);
    bool thrown = false;
    try {
      RI::Subdivision_solver<I>().solve(make_system(Case{"zero", {Q(0)}, -1, 1}));
    } catch (const RI::Input_error&) {
      thrown = true;
    }
    CHECK(thrown, "zero polynomial: no Input_error");
  }

  // Interval_nt coefficients (enclosures of the rational ones) with the Interval_nt solver:
  // the roots of the exact polynomial are in the family, so the same checks hold
  std::size_t before = tally.certified;
  for (std::size_t k = 0; k < all.size(); k += 3) check_case<I>(all[k], RI::Subdivision_solver_parameters(), 1e-12, 0x1p-53, " [Interval_nt coefficients]", true);
  std::cout << "Interval_nt coefficients: " << tally.certified - before << " certified\n";

  // tolerances
  for (double tol : {1e-3, 1e-6, 1e-9}) {
    RI::Subdivision_solver_parameters prm;
    prm.tolerance = tol;
    for (std::size_t k = 0; k < 40; ++k) check_case<I>(all[k], prm, tol, 0x1p-53, " [tolerance " + std::to_string(tol) + "]");
  }

#ifdef CGAL_USE_MPFI
  // the Gmpfi solver at 200 bits: every case, the hard Mignotte ones complete too
  {
    auto t1 = std::chrono::steady_clock::now();
    RI::Subdivision_solver_parameters prm;
    prm.precision = 200;
    prm.tolerance = 1e-45;
    std::size_t cases = 0;
    for (std::size_t k = 0; k < all.size(); k += (k < 240 ? 4 : 1)) {
      Case c = all[k];
      c.expect_complete_if_squarefree = true;
      check_case<CGAL::Gmpfi>(c, prm, 1e-40, 0x1p-200, " [Gmpfi 200 bits]");
      ++cases;
    }
    std::cout << "Gmpfi solver at 200 bits: " << cases << " polynomials, "
              << std::chrono::duration<double>(std::chrono::steady_clock::now() - t1).count() << " s\n";
  }
#endif

  double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  std::cout << "test_subdivision_solver_univariate: " << tally.cases << " solves, " << tally.roots_in_box << " roots in boxes, "
            << tally.certified << " certified, " << checks << " checks, " << failures << " failures, " << seconds << " s\n";
  return failures == 0 ? 0 : 1;
}
