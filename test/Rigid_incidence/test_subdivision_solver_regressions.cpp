// Copyright (c) 2026 Rigid_incidence contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Regressions of the subdivision solver, each once a failure of the stress tests:
//  - two roots 1.4e-8 apart (Mignotte x^6 - 2 (100 x - 1)^2) with Interval_nt coefficients:
//    no higher precision to retry at, so the cluster must be solved again at the working
//    precision below the singular width (both certified, exact sign changes at the ends);
//  - two roots 1.4e-14 apart (x^12 - 2 (100 x - 1)^2) with the Gmpfi solver at 200 bits: the
//    default minimal width must follow the precision (both certified);
//  - a planted system in 3 variables whose 9 roots are all ill-conditioned (cond ~ 1e2 .. 1e3),
//    without domain reduction: the Krawczyk exclusion must end the boxes along the roots'
//    near-null directions (complete, 9 roots, the same as with domain reduction, few boxes);
//  - an equation in many variables (its dense array too large to allocate): refused with an
//    Input_error naming it, at the exact limit counted by hand (maximal_coefficients);
//  - a planted system in 11 variables (too many for the dense preconditioned arrays) on a small
//    box around its root, and on one beside it: the Krawczyk test must be tried at once, not
//    after halving every variable 4 times (the curve tracer's face systems around a fold of
//    Jansen's linkage took thousands of boxes each);
//  - a planted root whose Jacobian is nearly singular along an oblique direction (a thin tube
//    of near-solutions through it, the case the oriented boxes are for), with oriented boxes
//    and without, in double and Gmpfi: one certified root at the planted point either way, and
//    a sheared solve tried, and at eps = 1e-5 not every one falling back (at eps = 1e-8 it
//    falls back to plain subdivision: the fallback must not lose the root either); and with
//    maximal_coefficients just above what the system needs, the larger sheared system must
//    fall back, not throw out of solve() (found by a review).
//  - random system #2488 of seed 99 (4 variables, two cubics): tightening must fall back on the
//    Bernstein arrays' Jacobian where the evaluations' one does not contract (every planted root
//    in exactly one certified enclosure at most 1e-11 wide; it stayed 0.08 wide).
//  - random system #5539 of seed 99: a simple root with a condition number of 1e9 leaves a
//    compact cluster of 2171 boxes in double, which must be retried at 106 bits (certified).
//  - degree elevation above degree 50, where C(n, k) is no longer exact in doubles: the
//    Bernstein coefficients of t and t^2 elevated to degree 60..64 must enclose their exact
//    values k/D and k(k-1)/(D(D-1)) (Gmpq); the weights were rounded, not enclosed.

#include "test_check.h"

#include <CGAL/Gmpq.h>
#include <CGAL/Interval_nt.h>
#include <CGAL/Rigid_incidence/IO/read_polynomial_system.h>
#include <CGAL/Rigid_incidence/Subdivision_solver.h>
#include <CGAL/Rigid_incidence/Curve_tracer.h>
#ifdef CGAL_USE_MPFI
#include <CGAL/Gmpfi.h>
#endif

#include <iostream>
#include <sstream>
#include <string>
#include <vector>

namespace RI = CGAL::Rigid_incidence;
typedef CGAL::Gmpq Q;
typedef CGAL::Interval_nt<false> I;

// x^d - 2 (a x - 1)^2, coefficients from degree 0 up
static std::vector<Q> mignotte(int d, long a)
{
  std::vector<Q> p(d + 1, Q(0));
  p[d] = 1;
  p[2] -= 2 * a * a;
  p[1] += 4 * a;
  p[0] -= 2;
  return p;
}

static Q value(const std::vector<Q>& p, const Q& x)
{
  Q v = 0;
  for (std::size_t k = p.size(); k-- > 0;) v = v * x + p[k];
  return v;
}

template <class NT> static RI::Polynomial_system<NT> univariate(const std::vector<Q>& p, double lo, double hi)
{
  RI::Polynomial_system<NT> s;
  s.variable_names = {"x"};
  s.box = {{lo, hi}};
  RI::Sparse_polynomial<NT> f(1);
  for (std::size_t k = 0; k < p.size(); ++k)
    if (p[k] != 0) {
      if constexpr (std::is_same<NT, Q>::value) f.add_term({unsigned(k)}, p[k]);
      else f.add_term({unsigned(k)}, NT(CGAL::to_interval(p[k])));
    }
  s.equations = {f};
  return s;
}

// the certified roots of p: disjoint, each with an exact sign change of p at its ends
template <class IT> static void check_cluster(const std::vector<Q>& p, const RI::Solver_result<IT>& r, std::size_t expected, const std::string& name)
{
  CHECK(r.roots.size() == expected, name << ": " << r.roots.size() << " roots, expected " << expected);
  CHECK(r.complete(), name << ": not complete (" << r.unresolved.size() << " unresolved"
                           << (r.unresolved.empty() ? std::string() : ", " + r.unresolved[0].reason) << ")");
  std::vector<std::pair<Q, Q>> e;
  for (const auto& root : r.roots) {
    CHECK(root.certified, name << ": a root is not certified");
    Q lo(CGAL::to_interval(root.enclosure[0]).first), hi(CGAL::to_interval(root.enclosure[0]).second);
    if constexpr (!std::is_same<IT, I>::value) { lo = Q(root.enclosure[0].inf()); hi = Q(root.enclosure[0].sup()); }
    CHECK(CGAL::sign(value(p, lo)) * CGAL::sign(value(p, hi)) < 0, name << ": no sign change over an enclosure");
    for (const auto& f : e) CHECK(hi < f.first || f.second < lo, name << ": enclosures overlap");
    e.push_back({lo, hi});
  }
}

static const char* planted = R"(3
(11237/2304)*x0^3 + (-3539/1536)*x0^2*x1 + (-4847/3072)*x0^2*x2 + (1358845489/203695360)*x0^2 + (-15223/3072)*x0*x1^2 + (1925/3072)*x0*x1*x2 + (-94197387/203695360)*x0*x1 + (2081/12288)*x0*x2^2 + (-118853763/81478144)*x0*x2 + (-158289503/122217216)*x0 + (15153/2048)*x1^3 + (1119/4096)*x1^2*x2 + (-2157573283/814781440)*x1^2 + (-309/8192)*x1*x2^2 + (93978689/814781440)*x1*x2 + (-8166855293/2036953600)*x1 + (-99/16384)*x2^3 + (258606341/3259125760)*x2^2 + (-1820541107/370355200)*x2 + (-2805740837/664224000);
(-2657/2304)*x0^3 + (4693/4608)*x0^2*x1 + (3385/9216)*x0^2*x2 + (-1214793271/611086080)*x0^2 + (-18751/9216)*x0*x1^2 + (-1603/9216)*x0*x1*x2 + (336263551/203695360)*x0*x1 + (-1447/36864)*x0*x2^2 + (33914615/81478144)*x0*x2 + (-259520297/122217216)*x0 + (5107/2048)*x1^3 + (541/4096)*x1^2*x2 + (-2630282443/2444344320)*x1^2 + (65/8192)*x1*x2^2 + (-22278263/143784960)*x1*x2 + (-1275328231/2036953600)*x1 + (23/16384)*x2^3 + (-214102819/9777377280)*x2^2 + (-383681169/370355200)*x2 + (-895709279/664224000);
(-90157/41472)*x0^3 + (9049/9216)*x0^2*x1 + (12973/18432)*x0^2*x2 + (-10758958681/3666516480)*x0^2 + (5149/2048)*x0*x1^2 + (-567/2048)*x0*x1*x2 + (72499201/1222172160)*x0*x1 + (-619/8192)*x0*x2^2 + (314542697/488868864)*x0*x2 + (-1532569891/733303296)*x0 + (-45491/12288)*x1^3 + (-1151/8192)*x1^2*x2 + (2187586563/1629562880)*x1^2 + (277/16384)*x1*x2^2 + (-63965409/1629562880)*x1*x2 + (1061123479/12221721600)*x1 + (265/98304)*x2^3 + (-228593061/6518251520)*x2^2 + (-627406279/2222131200)*x2 + (-1003330363/1328448000);

box * -2 2
)";

// maximal_coefficients: the dense arrays the solver (and the tracer) would allocate, counted by
// hand, against the limit: refused above it with an Input_error naming the largest equation,
// solved at it; an equation in 20 variables of degree 2 (3^20 coefficients) is refused at once
// under the default.
static void storage_limit()
{
  typedef RI::Sparse_polynomial<Q> P;
  RI::Polynomial_system<Q> s;
  s.variable_names = {"x", "y", "z"};
  s.box = {{-1, 1}, {-1, 1}, {-1, 1}};
  P x = P::variable(3, 0), y = P::variable(3, 1), z = P::variable(3, 2);
  s.equations = {x * x + y * y + z * z - P::constant(3, Q(1)), x - y, y - z};
  // x^2 + y^2 + z^2 - 1: 27 coefficients, 3 variables: 27 (1 + 3 + 9) = 351; x - y, y - z: 4 (1 + 2 + 4) = 28 each
  const double need = 351 + 28 + 28;
  auto message = [&](double limit) -> std::string {
    RI::Subdivision_solver_parameters p;
    p.maximal_coefficients = limit;
    try {
      RI::Solver_result<I> r = RI::Subdivision_solver<I>(p).solve(s);
      return r.complete() && r.roots.size() == 2 ? "solved" : "wrong result";
    } catch (const RI::Input_error& e) {
      return e.what();
    }
  };
  CHECK(message(need) == "solved", "a system that needs exactly maximal_coefficients is solved (x = y = z = +-1/sqrt 3)");
  const std::string m = message(need - 1);
  CHECK(m.find("407 coefficients") != std::string::npos && m.find("equation 0 in x^2, y^2, z^2") != std::string::npos &&
            m.find("27 coefficients by itself") != std::string::npos,
        "one coefficient over the limit: refused, naming equation 0: " + m);

  const std::size_t n = 20;
  RI::Polynomial_system<Q> big;
  P sum = P::constant(n, Q(-1));
  for (std::size_t j = 0; j < n; ++j) {
    big.variable_names.push_back("v" + std::to_string(j));
    big.box.push_back({-2, 2});
    sum = sum + P::variable(n, j) * P::variable(n, j);
  }
  big.equations.push_back(sum);
  for (std::size_t j = 1; j < n; ++j) big.equations.push_back(P::variable(n, j) - P::variable(n, j - 1));
  bool refused = false;
  try {
    RI::Subdivision_solver<I>().solve(big);
  } catch (const RI::Input_error& e) {
    refused = std::string(e.what()).find("3.49e+09 coefficients by itself") != std::string::npos;
  }
  CHECK(refused, "an equation in 20 variables of degree 2 is refused under the default limit");

  // the tracer counts as its face solves do: the unit circle in (x, y) is 9 (1 + 2 + 4) = 63
  RI::Polynomial_system<Q> c;
  c.variable_names = {"x", "y"};
  c.box = {{-2, 2}, {-2, 2}};
  P u = P::variable(2, 0), v = P::variable(2, 1);
  c.equations = {u * u + v * v - P::constant(2, Q(1))};
  auto traced = [&](double limit) {
    RI::Curve_tracer_parameters p;
    p.maximal_coefficients = limit;
    try {
      RI::Curve_result<I> r = RI::trace_curves(c, p);
      return r.complete() && r.curves.size() == 1;
    } catch (const RI::Input_error&) {
      return false;
    }
  };
  CHECK(traced(63), "the circle traced with maximal_coefficients = 63");
  CHECK(!traced(62), "the circle refused with maximal_coefficients = 62");
}

// x_i^2 + x_{i+1} + x_{i+2} = r_i^2 + r_{i+1} + r_{i+2} (indices mod 11), planted root
// r_i = (i + 20) / 40, on boxes 2e-3 wide: around the root (one root, certified), and shifted by
// 1e-2 (none). Each equation bounds a variable by the sum of two others' widths divided by
// 2 r_i <= 1.5, so the clipping of the equations themselves does not shrink the box.
// Degree elevation d -> D of the Bernstein arrays of t (d = 1: [0, 1]) and t^2 (d = 2:
// [0, 0, 1]) on [0, 1]; exactly, the coefficient k of t is k/D, of t^2 k(k-1)/(D(D-1)).
template <class IT> static void elevation_encloses(const char* name)
{
  typename RI::internal::Tensor_shape from1, from2, to;
  typename IT::Protector protect;
  for (unsigned D = 60; D <= 64; ++D) {
    from1.set({0}, {1});
    from2.set({0}, {2});
    to.set({0}, {D});
    const std::vector<IT> t = RI::internal::embed(from1, std::vector<IT>{IT(0), IT(1)}, to);
    const std::vector<IT> t2 = RI::internal::embed(from2, std::vector<IT>{IT(0), IT(0), IT(1)}, to);
    for (unsigned k = 0; k <= D; ++k) {
      const Q e1 = Q(int(k)) / Q(int(D)), e2 = Q(int(k * (k - 1))) / Q(int(D * (D - 1)));
      CHECK(Q(t[k].inf()) <= e1 && e1 <= Q(t[k].sup()), name << ": t elevated to degree " << D << ", coefficient " << k
                                                               << " [" << t[k].inf() << ", " << t[k].sup() << "] misses " << e1);
      CHECK(Q(t2[k].inf()) <= e2 && e2 <= Q(t2[k].sup()), name << ": t^2 elevated to degree " << D << ", coefficient " << k
                                                                 << " misses " << e2);
    }
  }
}

static void many_variables()
{
  typedef RI::Sparse_polynomial<Q> P;
  const std::size_t n = 11;
  std::vector<Q> r;
  for (std::size_t i = 0; i < n; ++i) r.push_back(Q(int(i) + 20) / Q(40));
  RI::Polynomial_system<Q> s;
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t k = (i + 1) % n, l = (i + 2) % n;
    s.variable_names.push_back("x" + std::to_string(i));
    s.equations.push_back(P::variable(n, i) * P::variable(n, i) + P::variable(n, k) + P::variable(n, l) - P::constant(n, r[i] * r[i] + r[k] + r[l]));
  }
  for (double shift : {0.0, 1e-2}) {
    s.box.clear();
    for (std::size_t i = 0; i < n; ++i) s.box.push_back({CGAL::to_double(r[i]) + shift - 1e-3, CGAL::to_double(r[i]) + shift + 1e-3});
    RI::Solver_result<I> res = RI::Subdivision_solver<I>().solve(s);
    const std::string what = shift == 0 ? "11 variables, around the root: " : "11 variables, beside the root: ";
    CHECK(res.complete() && res.roots.size() == (shift == 0 ? 1u : 0u), what << res.roots.size() << " roots, complete " << res.complete());
    if (shift == 0 && res.roots.size() == 1) {
      CHECK(res.roots[0].certified, what << "certified");
      for (std::size_t i = 0; i < n; ++i)
        CHECK(res.roots[0].enclosure[i].inf() <= CGAL::to_double(r[i]) + 1e-15 && res.roots[0].enclosure[i].sup() >= CGAL::to_double(r[i]) - 1e-15,
              what << "x" << i << " encloses " << CGAL::to_double(r[i]));
    }
    // (halving all 11 variables until each is 1/16 of the box: a box is 16^-11 of the volume)
    CHECK(res.statistics.boxes <= 8, what << res.statistics.boxes << " boxes (at most 8)");
  }
}

// u = (x - r1) + (y - r2), w = (x - r1) - (y - r2), Z = z - r3:
//   w - u^2 = 0,  eps u + w - u^2 + u^3 = 0,  Z - u^2 + w = 0.
// The first two give u (eps + u^2) = 0: u = 0 is the only real root (u = +-i sqrt(eps) are
// complex, which leaves |f| < eps^1.5 along the parabola w = u^2 for |u| < sqrt(eps)), so the
// one real root is r, and the Jacobian there has singular values about eps / 2 apart from 1
// along the oblique direction x = y.
template <class IT> static void ill_conditioned_tube(const std::string& type)
{
  {
    // u = X + Y, w = X - 2 Y: the input needs fewer than 300 coefficients, the sheared system more
    typedef RI::Sparse_polynomial<Q> P;
    const std::size_t n = 3;
    const Q r[3] = {Q(1, 7), Q(-2, 9), Q(3, 11)};
    const P X = P::variable(n, 0) - P::constant(n, r[0]), Y = P::variable(n, 1) - P::constant(n, r[1]),
            Z = P::variable(n, 2) - P::constant(n, r[2]);
    const P u = X + Y, w = X - P::constant(n, Q(2)) * Y;
    RI::Polynomial_system<Q> s;
    s.variable_names = {"x", "y", "z"};
    s.equations = {w - u * u, P::constant(n, Q(1, 100000)) * u + w - u * u + u * u * u, Z - Y * Y};
    s.box = {{-1, 1}, {-1, 1}, {-1, 1}};
    RI::Subdivision_solver_parameters prm;
    prm.maximal_coefficients = 300;
    const std::string what = "tube, maximal_coefficients 300, " + type + ": ";
    try {
      RI::Solver_result<IT> res = RI::Subdivision_solver<IT>(prm).solve(s);
      CHECK(res.complete() && res.roots.size() == 1 && res.roots[0].certified, what << res.roots.size() << " roots, complete " << res.complete());
      CHECK(res.statistics.oriented_solves >= 1 && res.statistics.oriented_fallbacks >= 1,
            what << res.statistics.oriented_solves << " sheared solves, " << res.statistics.oriented_fallbacks << " fallbacks (expected the sheared system refused)");
    } catch (const std::exception& e) {
      CHECK(false, what << "exception: " << e.what());
    }
  }
  typedef RI::Sparse_polynomial<Q> P;
  const std::size_t n = 3;
  const Q r[3] = {Q(1, 7), Q(-2, 9), Q(3, 11)};
  const P X = P::variable(n, 0) - P::constant(n, r[0]), Y = P::variable(n, 1) - P::constant(n, r[1]),
          Z = P::variable(n, 2) - P::constant(n, r[2]);
  const P u = X + Y, w = X - Y;
  for (int e : {5, 8}) {
    Q eps(1);
    for (int k = 0; k < e; ++k) eps = eps / Q(10);
    RI::Polynomial_system<Q> s;
    s.variable_names = {"x", "y", "z"};
    s.equations = {w - u * u, P::constant(n, eps) * u + w - u * u + u * u * u, Z - u * u + w};
    s.box = {{-1, 1}, {-1, 1}, {-1, 1}};
    for (bool oriented : {true, false}) {
      RI::Subdivision_solver_parameters prm;
      prm.oriented_boxes = oriented;
      RI::Solver_result<IT> res = RI::Subdivision_solver<IT>(prm).solve(s);
      const std::string what = "tube, eps = 1e-" + std::to_string(e) + ", " + type + (oriented ? ", oriented boxes: " : ", axis-aligned boxes: ");
      CHECK(res.complete() && res.roots.size() == 1, what << res.roots.size() << " roots, complete " << res.complete());
      if (res.roots.size() == 1) {
        CHECK(res.roots[0].certified, what << "certified");
        for (std::size_t j = 0; j < n; ++j) {
          const std::pair<double, double> b = CGAL::to_interval(res.roots[0].enclosure[j]), q = CGAL::to_interval(r[j]);
          CHECK(b.first <= q.second && q.first <= b.second, what << "variable " << j << " [" << b.first << ", " << b.second << "] encloses " << q.first);
        }
      }
      if (oriented) {
        CHECK(res.statistics.oriented_solves >= 1, what << "no sheared solve tried");
        // at 1e-5 the sheared solve settles its box (a broken composition or y-box would fall back)
        if (e == 5)
          CHECK(res.statistics.oriented_fallbacks < res.statistics.oriented_solves,
                what << res.statistics.oriented_fallbacks << " of " << res.statistics.oriented_solves << " sheared solves fell back");
      } else {
        CHECK(res.statistics.oriented_solves == 0, what << res.statistics.oriented_solves << " sheared solves with oriented_boxes false");
      }
    }
  }
}

// Random system #2488 of `test_subdivision_solver_random 6000 99` (planted_systems.h: 4
// variables, two linear and two cubic equations, new coordinates) and its 6 planted roots in the
// box. Tightening a certified root by the Krawczyk operator with the Jacobian from the
// derivatives' evaluations alone stopped there with an enclosure 0.08 wide: the Bernstein
// arrays' Jacobian must be used where that one does not contract (found by a review).
static const char* random_2488 = R"(4
(7/8)*x0 + (-2/1)*x1 + (-3/4)*x2 + (-2/1)*x3 + (371/264);
(1155/1024)*x0^3 + (51607/6912)*x0^2*x1 + (-163/384)*x0^2*x2 + (-275311/27648)*x0^2*x3 + (198330535/11031552)*x0^2 + (2219/144)*x0*x1^2 + (-3025/1728)*x0*x1*x2 + (-34435/864)*x0*x1*x3 + (1300703689/18960480)*x0*x1 + (-43/192)*x0*x2^2 + (-4031/6912)*x0*x2*x3 + (373939001/151683840)*x0*x2 + (124277/6912)*x0*x3^2 + (-3954459767/75841920)*x0*x3 + (100418063513/3185360640)*x0 + (10/1)*x1^3 + (-79/36)*x1^2*x2 + (-362/9)*x1^2*x3 + (5325233/79002)*x1^2 + (-17/27)*x1*x2^2 + (-91/54)*x1*x2*x3 + (26419711/4740120)*x1*x2 + (7601/216)*x1*x3^2 + (-6319573/62370)*x1*x3 + (6339950681/99542520)*x1 + (1/12)*x2^3 + (439/216)*x2^2*x3 + (-2583299/592515)*x2^2 + (19973/1728)*x2*x3^2 + (-485421967/9480240)*x2*x3 + (44344738451/796340160)*x2 + (1885/216)*x3^3 + (-534212587/6320160)*x3^2 + (3763478681/16590420)*x3 + (-219346114717/1194510240);
(5/24)*x0 + (-3/2)*x1 + (7/12)*x2 + (17/12)*x3 + (-1277/1170);
(9/256)*x0^3 + (15/64)*x0^2*x1 + (15/256)*x0^2*x2 + (3/64)*x0^2*x3 + (8193/21760)*x0^2 + (1/4)*x0*x1^2 + (5/16)*x0*x1*x2 + (19/16)*x0*x1*x3 + (3841/4760)*x0*x1 + (15/64)*x0*x2*x3 + (-125/22848)*x0*x2 + (-3/2)*x0*x3^2 + (483673/114240)*x0*x3 + (-102041/68544)*x0 + (2/1)*x1^2*x3 + (-34/21)*x1^2 + (5/2)*x1*x2*x3 + (-85/42)*x1*x2 + (-11/2)*x1*x3^2 + (82291/3570)*x1*x3 + (-11066/735)*x1 + (-15/8)*x2*x3^2 + (230/51)*x2*x3 + (-8545/3528)*x2 + (3/1)*x3^3 + (-276593/14280)*x3^2 + (413677/12495)*x3 + (-5815727/370440);

box x0 -6.5 2.5
box x1 -2 1.125
box x2 -4.875 -1
box x3 -0.25 3.25
)";
static const std::vector<std::vector<std::string>> random_2488_roots = {
  {"-9970729/1696695", "-268748059/156095940", "-8845147/7804797", "3620489/13007995"},
  {"-7664408/2375373", "-235938613/237537300", "-294093991/118768650", "960324/791791"},
  {"-55229848/28843815", "-9958453/16482180", "-89184541/57687630", "30253486/28843815"},
  {"-1134091/2747030", "-31522033/153833680", "-3370031/1098812", "33317873/17750040"},
  {"201195622/96711615", "8670169373/17794937160", "-17569636199/4448734290", "2108371457/808860780"},
  {"187501616866/86041100145", "87154752283/172082200290", "-40242327319/9056957910", "161516521129/57360733430"}};

// Random system #5539 of `test_subdivision_solver_random 6000 99` (4 variables, cubics through
// shared points) and its 4 planted roots in the box. The one at (592, -14.7, -354, -274) has a
// condition number of about 1e9: in double it leaves 2171 boxes of the singular width, 12 of
// them across, stopped as "possible multiple root"; too many for the retry at 106 bits, which
// took clusters of at most 256 boxes, and certifies it at once (a compact cluster is retried).
static const char* random_5539 = R"(4
(2/1)*x0^3 + (-18/1)*x0^2*x1 + (19/1)*x0^2*x2 + (50/3)*x0^2*x3 + (-114734/4095)*x0^2 + (12/1)*x0*x1^2 + (-37/1)*x0*x1*x2 + (-62/3)*x0*x1*x3 + (-13424/585)*x0*x1 + (24/1)*x0*x2^2 + (88/3)*x0*x2*x3 + (10844/1365)*x0*x2 + (16/3)*x0*x3^2 + (183739/4095)*x0*x3 + (-9318821/81900)*x0 + (32/1)*x1^3 + (-56/1)*x1^2*x2 + (-112/3)*x1^2*x3 + (140692/1365)*x1^2 + (24/1)*x1*x2^2 + (88/3)*x1*x2*x3 + (-190721/1365)*x1*x2 + (16/3)*x1*x3^2 + (-286276/4095)*x1*x3 + (681479/13650)*x1 + (54/1)*x2^2 + (152/3)*x2*x3 + (-209047/2730)*x2 + (38/3)*x3^2 + (20153/585)*x3 + (-1650333/18200);
(-5/1)*x0^3 + (45/1)*x0^2*x1 + (-95/2)*x0^2*x2 + (-125/3)*x0^2*x3 + (50821/728)*x0^2 + (-30/1)*x0*x1^2 + (185/2)*x0*x1*x2 + (155/3)*x0*x1*x3 + (19151/312)*x0*x1 + (-60/1)*x0*x2^2 + (-220/3)*x0*x2*x3 + (-44923/2184)*x0*x2 + (-40/3)*x0*x3^2 + (-724127/6552)*x0*x3 + (7323527/26208)*x0 + (-80/1)*x1^3 + (140/1)*x1^2*x2 + (280/3)*x1^2*x3 + (-74987/273)*x1^2 + (-60/1)*x1*x2^2 + (-220/3)*x1*x2*x3 + (386083/1092)*x1*x2 + (-40/3)*x1*x3^2 + (530783/3276)*x1*x3 + (-148703/1260)*x1 + (-489/4)*x2^2 + (-431/3)*x2*x3 + (1107423/7280)*x2 + (-329/12)*x3^2 + (-294601/5040)*x3 + (39016673/163800);
(3/4)*x0^3 + (-27/4)*x0^2*x1 + (57/8)*x0^2*x2 + (25/4)*x0^2*x3 + (-39913/3640)*x0^2 + (9/2)*x0*x1^2 + (-111/8)*x0*x1*x2 + (-31/4)*x0*x1*x3 + (-423/520)*x0*x1 + (9/1)*x0*x2^2 + (11/1)*x0*x2*x3 + (5839/3640)*x0*x2 + (2/1)*x0*x3^2 + (109387/5460)*x0*x3 + (-318008/6825)*x0 + (12/1)*x1^3 + (-21/1)*x1^2*x2 + (-14/1)*x1^2*x3 + (5143/910)*x1^2 + (9/1)*x1*x2^2 + (11/1)*x1*x2*x3 + (-160691/3640)*x1*x2 + (2/1)*x1*x3^2 + (-278273/5460)*x1*x3 + (2244421/54600)*x1 + (45/1)*x2^2 + (-14/1)*x2*x3 + (-16903/182)*x2 + (13/1)*x3^2 + (344087/5460)*x3 + (-4379/1365);
(-5/1)*x0^3 + (45/1)*x0^2*x1 + (-95/2)*x0^2*x2 + (-125/3)*x0^2*x3 + (19183/273)*x0^2 + (-30/1)*x0*x1^2 + (185/2)*x0*x1*x2 + (155/3)*x0*x1*x3 + (2090/39)*x0*x1 + (-60/1)*x0*x2^2 + (-220/3)*x0*x2*x3 + (-5240/273)*x0*x2 + (-40/3)*x0*x3^2 + (-186287/1638)*x0*x3 + (9338989/32760)*x0 + (-80/1)*x1^3 + (140/1)*x1^2*x2 + (280/3)*x1^2*x3 + (-65978/273)*x1^2 + (-60/1)*x1*x2^2 + (-220/3)*x1*x2*x3 + (188537/546)*x1*x2 + (-40/3)*x1*x3^2 + (152966/819)*x1*x3 + (-1121633/8190)*x1 + (-147/1)*x2^2 + (-332/3)*x2*x3 + (172141/780)*x2 + (-107/3)*x3^2 + (-1813939/16380)*x3 + (17288183/81900);

box x0 -3.5 592.375
box x1 -15 1.625
box x2 -354.75 1
box x3 -274.75 2.625
)";
static const std::vector<std::vector<std::string>> random_5539_roots = {
  {"-158191/51142", "55907/51142", "241907/383565", "232027/102284"},
  {"-2783/2743", "-2703/2743", "34721/41145", "34319/32916"},
  {"-5/13", "-1/1", "7/15", "3/4"},
  {"700195/1183", "-69607/4732", "-6284594/17745", "-46367/169"}};

// every planted root in exactly one certified enclosure at most 1e-11 wide, and nothing else
static void check_planted_roots(const char* text, const std::vector<std::vector<std::string>>& roots, const std::string& name)
{
  std::istringstream in(text);
  RI::Polynomial_system_file f = RI::read_polynomial_system(in);
  RI::Solver_result<I> r = RI::Subdivision_solver<I>().solve(f.system);
  CHECK(r.complete() && r.roots.size() == roots.size(), name << ": " << r.roots.size() << " roots, complete " << r.complete());
  for (const auto& u : r.unresolved) CHECK(false, name << ": unresolved, " << u.reason);
  std::vector<int> hits(roots.size(), 0);
  for (const auto& x : r.roots) {
    int inside = 0;
    for (std::size_t k = 0; k < roots.size(); ++k) {
      bool in_box = true;
      for (std::size_t j = 0; j < roots[k].size(); ++j) {
        const Q v(roots[k][j]);
        in_box = in_box && Q(x.enclosure[j].inf()) <= v && v <= Q(x.enclosure[j].sup());
      }
      if (in_box) { ++inside; ++hits[k]; }
    }
    double w = 0;
    for (const auto& e : x.enclosure) w = (std::max)(w, e.sup() - e.inf());
    CHECK(x.certified && inside == 1, name << ": a certified enclosure holds " << inside << " planted roots");
    CHECK(w <= 1e-11, name << ": a certified enclosure " << w << " wide (tolerance 1e-12; 1e-11 allowed)");
  }
  for (std::size_t k = 0; k < roots.size(); ++k) CHECK(hits[k] == 1, name << ": planted root " << k << " in " << hits[k] << " enclosures");
}

int main()
{
  storage_limit();
  elevation_encloses<I>("Interval_nt");
  check_planted_roots(random_2488, random_2488_roots, "random #2488 of seed 99");
#ifdef CGAL_USE_MPFI
  check_planted_roots(random_5539, random_5539_roots, "random #5539 of seed 99");
#endif
  many_variables();
  ill_conditioned_tube<I>("Interval_nt");
#ifdef CGAL_USE_MPFI
  ill_conditioned_tube<CGAL::Gmpfi>("Gmpfi");
#endif
  {
    std::vector<Q> p = mignotte(6, 100);
    RI::Solver_result<I> r = RI::Subdivision_solver<I>().solve(univariate<I>(p, -1, 1));
    check_cluster(p, r, 2, "Mignotte d = 6, a = 100, Interval_nt coefficients");
    RI::Solver_result<I> s = RI::Subdivision_solver<I>().solve(univariate<Q>(p, -1, 1));
    check_cluster(p, s, 2, "Mignotte d = 6, a = 100, exact coefficients");
  }
#ifdef CGAL_USE_MPFI
  {
    std::vector<Q> p = mignotte(12, 100);
    RI::Subdivision_solver_parameters prm;
    prm.precision = 200;
    prm.tolerance = 1e-45;
    RI::Solver_result<CGAL::Gmpfi> r = RI::Subdivision_solver<CGAL::Gmpfi>(prm).solve(univariate<Q>(p, 0, 0.5));
    check_cluster(p, r, 2, "Mignotte d = 12, a = 100, Gmpfi at 200 bits");
  }
#endif
  {
    std::istringstream in(planted);
    RI::Polynomial_system_file f = RI::read_polynomial_system(in);
    RI::Solver_result<I> ref = RI::Subdivision_solver<I>().solve(f.system);
    CHECK(ref.complete() && ref.roots.size() == 9, "planted 3 variables: " << ref.roots.size() << " roots with domain reduction");
    for (int option = 0; option < 2; ++option) {
      RI::Subdivision_solver_parameters prm;
      prm.domain_reduction = false;
      if (option == 1) { prm.preconditioning = false; prm.split = RI::Split_strategy::ROUND_ROBIN; }
      std::string name = option ? "planted 3 variables, plain bisection" : "planted 3 variables, no domain reduction";
      RI::Solver_result<I> r = RI::Subdivision_solver<I>(prm).solve(f.system);
      CHECK(r.complete() && r.roots.size() == 9, name << ": " << r.roots.size() << " roots, " << r.unresolved.size() << " unresolved");
      // about 4000 boxes (200000, the budget, before the Krawczyk exclusion)
      CHECK(r.statistics.boxes < 20000, name << ": " << r.statistics.boxes << " boxes");
      for (const auto& x : r.roots) {
        std::size_t same = 0;
        for (const auto& y : ref.roots) {
          bool overlap = true;
          for (std::size_t j = 0; j < 3; ++j) overlap = overlap && !(x.enclosure[j].sup() < y.enclosure[j].inf() || y.enclosure[j].sup() < x.enclosure[j].inf());
          if (overlap) ++same;
        }
        CHECK(x.certified && same == 1, name << ": a root not certified, or not one of the 9");
      }
    }
  }
  std::cout << "test_subdivision_solver_regressions: " << checks << " checks, " << failures << " failures\n";
  return failures == 0 ? 0 : 1;
}
