// Copyright (c) 2026 Rigid_incidence contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// trace_curves (Curve_tracer.h) against curves whose topology and points are known exactly:
//  - circles, arcs leaving the box, nested and nearly touching circles (no false join),
//    random sets of up to 5 disjoint circles (the number of loops), two circles crossing (singular
//    points reported as unresolved regions, four branches ending there), two circles on a
//    sphere, Viviani's curve (a loop through a singular point), a circle tangent to the box
//    (not certified there, never a wrong topology);
//  - the four-bar linkage in its three Grashof cases (two circuits, one circuit, the change
//    point where they touch), with a dense independent sampling of the true curve (crank
//    angle on a grid, the coupler point from the circle-circle intersection in closed form)
//    that must lie near the traced polylines, and every polyline point on the curve;
//  - the paper's four-bar (a parallelogram linkage) with and without its two inequalities;
//  - an inequality clipping a circle; CGAL::Gmpfi intervals; interval coefficients;
//  - curves leaving the box through its edges and corners (a line through the square's corners,
//    exactly and 1e-17 or 1e-13 beside; through two edges of the cube): one certified branch
//    each, the crossing counted once; a circle meeting the square in its corners only: unresolved;
//  - malformed input throws Input_error.

#include "test_check.h"

#include <CGAL/Gmpq.h>
#include <CGAL/Rigid_incidence/Curve_tracer.h>
#include <CGAL/Rigid_incidence/Input_error.h>
#include <CGAL/Random.h>

#include <cmath>
#include <iostream>
#include <string>
#include <vector>

namespace RI = CGAL::Rigid_incidence;
typedef CGAL::Gmpq Q;
typedef RI::Sparse_polynomial<Q> P;
typedef CGAL::Interval_nt<false> I;
typedef std::vector<double> Pt;

static double distance_to_segment(const Pt& p, const Pt& a, const Pt& b)
{
  double ab = 0, t = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    ab += (b[i] - a[i]) * (b[i] - a[i]);
    t += (p[i] - a[i]) * (b[i] - a[i]);
  }
  t = ab > 0 ? std::max(0.0, std::min(1.0, t / ab)) : 0;
  double d = 0;
  for (std::size_t i = 0; i < p.size(); ++i) d += std::pow(p[i] - a[i] - t * (b[i] - a[i]), 2);
  return std::sqrt(d);
}

template <class IT>
static double distance_to_curves(const Pt& p, const RI::Curve_result<IT>& r)
{
  double best = 1e300;
  for (const auto& c : r.curves) {
    for (std::size_t k = 0; k + 1 < c.points.size(); ++k) best = std::min(best, distance_to_segment(p, c.points[k], c.points[k + 1]));
    if (c.points.size() == 1) best = std::min(best, distance_to_segment(p, c.points[0], c.points[0]));
  }
  return best;
}

template <class IT>
static bool in_region(const Pt& p, const RI::Solver_unresolved<IT>& u, double slack = 0)
{
  typedef RI::internal::Interval_ops<IT> O;
  for (std::size_t i = 0; i < p.size(); ++i)
    if (p[i] < O::lower_double(u.box[i]) - slack || p[i] > O::upper_double(u.box[i]) + slack) return false;
  return true;
}

static RI::Polynomial_system<Q> plane(const std::vector<P>& eqs, double lo0, double hi0, double lo1, double hi1)
{
  RI::Polynomial_system<Q> s;
  s.variable_names = {"x", "y"};
  s.box = {{lo0, hi0}, {lo1, hi1}};
  s.equations = eqs;
  return s;
}

static P circle(const Q& cx, const Q& cy, const Q& r2)
{
  P x = P::variable(2, 0), y = P::variable(2, 1), one = P::constant(2, 1);
  return (x - cx * one) * (x - cx * one) + (y - cy * one) * (y - cy * one) - r2 * one;
}

static int count_closed(const RI::Curve_result<I>& r)
{
  int k = 0;
  for (const auto& c : r.curves) k += c.closed;
  return k;
}

// every point of the curves lies on the system, every point of `truth` near a polyline
template <class IT>
static void check_points(const RI::Curve_result<IT>& r, const std::vector<Pt>& truth, double near, const std::string& what,
                         double residual = 1e-9)
{
  for (const auto& c : r.curves) CHECK(c.max_residual < residual, what << ": polyline residual " << c.max_residual);
  double worst = 0;
  for (const Pt& p : truth) worst = std::max(worst, distance_to_curves(p, r));
  CHECK(worst <= near, what << ": a point of the true curve is " << worst << " from the polylines");
}

static void circles()
{
  {
    auto r = RI::trace_curves(plane({circle(0, 0, 1)}, -2, 2, -2, 2));
    CHECK(r.complete() && r.curves.size() == 1 && r.curves[0].closed, "circle: one certified loop");
    std::vector<Pt> truth;
    for (int k = 0; k < 720; ++k) truth.push_back({std::cos(k * M_PI / 360), std::sin(k * M_PI / 360)});
    check_points(r, truth, 0.01, "circle");
  }
  {
    // leaves the box through x = 0 at (0, -1) and (0, 1)
    auto r = RI::trace_curves(plane({circle(0, 0, 1)}, 0, 2, -2, 2));
    CHECK(r.complete() && r.curves.size() == 1 && !r.curves[0].closed, "half circle: one open branch");
    if (r.curves.size() == 1) {
      const auto& c = r.curves[0];
      CHECK(c.ends[0] == RI::Curve_end::BOUNDARY && c.ends[1] == RI::Curve_end::BOUNDARY, "half circle: ends on the box boundary");
      CHECK(std::abs(c.points.front()[0]) < 1e-9 && std::abs(std::abs(c.points.front()[1]) - 1) < 1e-9 &&
                std::abs(c.points.back()[0]) < 1e-9 && std::abs(std::abs(c.points.back()[1]) - 1) < 1e-9 &&
                c.points.front()[1] * c.points.back()[1] < 0,
            "half circle: ends at (0, -1) and (0, 1)");
    }
  }
  {
    // nested circles: two loops, never joined
    auto r = RI::trace_curves(plane({circle(0, 0, 1) * circle(0, 0, Q(81, 100))}, -2, 2, -2, 2));
    CHECK(r.complete() && count_closed(r) == 2 && r.curves.size() == 2, "nested circles: two loops (" << r.curves.size() << ")");
  }
  for (double gap : {1e-3, 1e-4}) {
    // two circles of radius 1/2 a gap apart: two loops where the tracer resolves the gap
    const Q c = Q(1) + Q(gap);
    auto r = RI::trace_curves(plane({circle(0, 0, Q(1, 4)) * circle(c, 0, Q(1, 4))}, -1, 2, -1, 1));
    CHECK(r.complete() && count_closed(r) == 2 && r.curves.size() == 2, "circles " << gap << " apart: two loops (" << r.curves.size() << ")");
  }
  {
    // 1e-9 apart, below the minimal width: never one certified loop for the two
    const Q c = Q(1) + Q(1, 1000000000);
    auto r = RI::trace_curves(plane({circle(0, 0, Q(1, 4)) * circle(c, 0, Q(1, 4))}, -1, 2, -1, 1));
    bool wrong = false;
    for (const auto& k : r.curves)
      if (k.certified && k.closed) {
        double lo = 1e9, hi = -1e9;
        for (const auto& p : k.points) { lo = std::min(lo, p[0]); hi = std::max(hi, p[0]); }
        if (hi - lo > 1.5) wrong = true;  // a loop spanning both circles
      }
    CHECK(!wrong, "circles 1e-9 apart: no certified loop joins them");
    CHECK(r.complete() ? count_closed(r) == 2 : !r.unresolved.empty(), "circles 1e-9 apart: two loops or an unresolved region");
  }
  // random disjoint circles: one loop each
  CGAL::Random rnd(7);
  for (int t = 0; t < 20; ++t) {
    P f = P::constant(2, 1);
    int k = 0;
    std::vector<std::pair<Pt, double>> truth;
    for (int gx = 0; gx < 3; ++gx)
      for (int gy = 0; gy < 3; ++gy) {
        if (rnd.get_int(0, 2) == 0 || k == 5) continue;  // at most 5 circles: degree 10
        const Q cx = Q(gx) + Q(rnd.get_int(3, 7), 10), cy = Q(gy) + Q(rnd.get_int(3, 7), 10), r = Q(rnd.get_int(5, 25), 100);
        f = f * circle(cx, cy, r * r);
        truth.push_back({{CGAL::to_double(cx), CGAL::to_double(cy)}, CGAL::to_double(r)});
        ++k;
      }
    if (k == 0) continue;
    auto r = RI::trace_curves(plane({f}, 0, 3, 0, 3));
    CHECK(r.complete() && count_closed(r) == k && int(r.curves.size()) == k,
          "random circles " << t << ": " << r.curves.size() << " loops for " << k << (r.complete() ? "" : " (not complete)"));
    std::vector<Pt> pts;
    for (const auto& c : truth)
      for (int a = 0; a < 90; ++a) pts.push_back({c.first[0] + c.second * std::cos(a * M_PI / 45), c.first[1] + c.second * std::sin(a * M_PI / 45)});
    // the product of up to 9 circles has large coefficients: residual relative to them
    check_points(r, pts, 0.01, "random circles " + std::to_string(t), 1e-6);
    for (const auto& c : r.curves)
      for (const auto& p : c.points) {
        double off = 1e9;
        for (const auto& k : truth) off = std::min(off, std::abs(std::hypot(p[0] - k.first[0], p[1] - k.first[1]) - k.second));
        CHECK(off < 1e-7, "random circles " << t << ": a polyline point " << off << " off the circles");
      }
  }
}

static void singular()
{
  {
    // two unit circles crossing at (1/2, +-sqrt(3)/2): two singular points, four branches
    auto r = RI::trace_curves(plane({circle(0, 0, 1) * circle(1, 0, 1)}, -2, 3, -2, 2));
    CHECK(!r.complete() && r.unresolved.size() == 2, "crossing circles: two unresolved regions (" << r.unresolved.size() << ")");
    for (const auto& u : r.unresolved)
      CHECK(in_region<I>({0.5, std::sqrt(3.0) / 2}, u) || in_region<I>({0.5, -std::sqrt(3.0) / 2}, u),
            "crossing circles: the region holds a crossing point");
    CHECK(r.curves.size() == 4, "crossing circles: four branches (" << r.curves.size() << ")");
    for (const auto& c : r.curves)
      CHECK(c.certified && c.ends[0] == RI::Curve_end::UNRESOLVED && c.ends[1] == RI::Curve_end::UNRESOLVED && c.end_region[0] != c.end_region[1],
            "crossing circles: each branch runs from one singular point to the other");
    std::vector<Pt> truth;
    for (int k = 0; k < 360; ++k) {
      truth.push_back({std::cos(k * M_PI / 180), std::sin(k * M_PI / 180)});
      truth.push_back({1 + std::cos(k * M_PI / 180), std::sin(k * M_PI / 180)});
    }
    check_points(r, truth, 0.01, "crossing circles");
  }
  {
    // a circle tangent to the box at (+-1, 0): not certified there; never a wrong topology
    auto r = RI::trace_curves(plane({circle(0, 0, 1)}, -1, 1, -2, 2));
    CHECK(!r.complete(), "tangent circle: not complete");
    for (const auto& u : r.unresolved)
      CHECK(in_region<I>({1, 0}, u, 1e-9) || in_region<I>({-1, 0}, u, 1e-9), "tangent circle: the region holds a tangency point");
    for (const auto& c : r.curves) CHECK(!c.closed || !c.certified, "tangent circle: no certified loop through the box face");
  }
  P X = P::variable(3, 0), Y = P::variable(3, 1), Z = P::variable(3, 2), O = P::constant(3, 1);
  RI::Polynomial_system<Q> s;
  s.variable_names = {"x", "y", "z"};
  s.box = {{-3, 3}, {-3, 3}, {-3, 3}};
  {
    // a sphere and two planes: two circles
    s.equations = {X * X + Y * Y + Z * Z - Q(4) * O, (Z - Q(1, 2) * O) * (Z + Q(1, 2) * O)};
    auto r = RI::trace_curves(s);
    CHECK(r.complete() && r.curves.size() == 2 && count_closed(r) == 2, "sphere and two planes: two loops");
    std::vector<Pt> truth;
    const double rho = std::sqrt(4 - 0.25);
    for (int k = 0; k < 360; ++k)
      for (double z : {-0.5, 0.5}) truth.push_back({rho * std::cos(k * M_PI / 180), rho * std::sin(k * M_PI / 180), z});
    check_points(r, truth, 0.02, "sphere and two planes");
  }
  {
    // Viviani's curve: sphere of radius 2 and cylinder through its centre; a figure eight
    // with its double point at (2, 0, 0)
    s.equations = {X * X + Y * Y + Z * Z - Q(4) * O, (X - O) * (X - O) + Y * Y - O};
    auto r = RI::trace_curves(s);
    CHECK(r.unresolved.size() == 1 && in_region<I>({2, 0, 0}, r.unresolved[0], 1e-9), "Viviani: one region, at (2, 0, 0)");
    CHECK(r.curves.size() == 2, "Viviani: two branches (" << r.curves.size() << ")");
    for (const auto& c : r.curves)
      CHECK(c.certified && c.ends[0] == RI::Curve_end::UNRESOLVED && c.ends[1] == RI::Curve_end::UNRESOLVED, "Viviani: loops through the double point");
    std::vector<Pt> truth;
    for (int k = 0; k < 720; ++k) {
      const double t = k * M_PI / 360;  // (1 + cos t, sin t, 2 sin(t/2))
      truth.push_back({1 + std::cos(t), std::sin(t), 2 * std::sin(t / 2)});
      truth.push_back({1 + std::cos(t), std::sin(t), -2 * std::sin(t / 2)});
    }
    check_points(r, truth, 0.03, "Viviani");
  }
}

// The four-bar linkage: A = (0, 0) and D = (d, 0) fixed; B = (x1, y1) with |AB| = a, C = (x2,
// y2) with |BC| = b and |DC| = c. Three equations in four variables.
static void four_bar(int a, int b, int c, int d, int circuits, bool change_point)
{
  const std::size_t n = 4;
  P x1 = P::variable(n, 0), y1 = P::variable(n, 1), x2 = P::variable(n, 2), y2 = P::variable(n, 3), one = P::constant(n, 1);
  RI::Polynomial_system<Q> s;
  s.variable_names = {"x1", "y1", "x2", "y2"};
  const double R = a + b + d + 1;
  s.box.assign(4, {-R, R});
  s.equations = {x1 * x1 + y1 * y1 - Q(a * a) * one, (x2 - x1) * (x2 - x1) + (y2 - y1) * (y2 - y1) - Q(b * b) * one,
                 (x2 - Q(d) * one) * (x2 - Q(d) * one) + y2 * y2 - Q(c * c) * one};
  auto r = RI::trace_curves(s);
  const std::string what = "four-bar " + std::to_string(a) + " " + std::to_string(b) + " " + std::to_string(c) + " " + std::to_string(d);
  if (!change_point) {
    CHECK(r.complete() && count_closed(r) == circuits && int(r.curves.size()) == circuits,
          what << ": " << circuits << " circuit(s), found " << r.curves.size() << (r.complete() ? "" : " (not complete)"));
  } else {
    // at the change point the circuits touch where all four bars are collinear
    CHECK(!r.unresolved.empty(), what << ": the collinear configurations are singular");
    for (const auto& u : r.unresolved) CHECK(u.rank_deficient, what << ": singular region");
  }
  // the true curve: B at crank angle t, C = the intersections of the circles (B, b), (D, c)
  std::vector<Pt> truth;
  for (int k = 0; k < 2000; ++k) {
    const double t = 2 * M_PI * k / 2000, bx = a * std::cos(t), by = a * std::sin(t);
    const double ex = d - bx, ey = -by, e = std::hypot(ex, ey);
    const double along = (b * b - c * c + e * e) / (2 * e), h2 = double(b) * b - along * along;
    if (h2 < 0) continue;
    const double h = std::sqrt(h2);
    for (int sgn : {-1, 1})
      truth.push_back({bx, by, bx + along * ex / e - sgn * h * ey / e, by + along * ey / e + sgn * h * ex / e});
  }
  CHECK(truth.size() > 100, what << ": the oracle sampled the curve");
  check_points(r, truth, change_point ? 0.1 : 0.05, what);
}

// The paper's four-bar linkage (van Sosin and Elber, Section 4, Fig. 5): P0 = (-1, 0), P1 =
// (1, 0), |A P0| = 0.9, |A B| = 2, |B P1| = 0.9: a parallelogram linkage, whose two circuits
// cross at the collinear configurations A = (-1.9, 0) and A = (-0.1, 0). With the paper's
// inequalities Ay >= 0 and (B - P1) x (A - P1) >= 0: the parallelogram motion with A above the
// axis, one branch between the two singular points.
static void paper_four_bar(bool with_inequalities)
{
  const std::size_t n = 4;
  P ax = P::variable(n, 0), ay = P::variable(n, 1), bx = P::variable(n, 2), by = P::variable(n, 3), one = P::constant(n, 1);
  RI::Polynomial_system<Q> s;
  s.variable_names = {"Ax", "Ay", "Bx", "By"};
  s.box.assign(4, {-3, 3});
  s.equations = {(ax + one) * (ax + one) + ay * ay - Q(81, 100) * one, (ax - bx) * (ax - bx) + (ay - by) * (ay - by) - Q(4) * one,
                 (bx - one) * (bx - one) + by * by - Q(81, 100) * one};
  auto g1 = [](const Pt& p) { return p[1]; };
  auto g2 = [](const Pt& p) { return (p[2] - 1) * p[1] - p[3] * (p[0] - 1); };
  if (with_inequalities) s.inequalities = {ay, (bx - one) * ay - by * (ax - one)};
  auto r = RI::trace_curves(s);
  const std::string what = with_inequalities ? "paper four-bar with inequalities" : "paper four-bar";
  CHECK(r.unresolved.size() == 2, what << ": two singular regions (" << r.unresolved.size() << ")");
  for (const auto& u : r.unresolved)
    CHECK(in_region<I>({-1.9, 0, 0.1, 0}, u) || in_region<I>({-0.1, 0, 1.9, 0}, u), what << ": a region holds a collinear configuration");
  CHECK(r.curves.size() == (with_inequalities ? 1u : 4u), what << ": " << r.curves.size() << " branches");
  for (const auto& c : r.curves) {
    CHECK(c.certified && c.ends[0] == RI::Curve_end::UNRESOLVED && c.ends[1] == RI::Curve_end::UNRESOLVED && c.end_region[0] != c.end_region[1],
          what << ": a branch from one collinear configuration to the other");
    if (with_inequalities)
      for (const auto& p : c.points) CHECK(g1(p) > -1e-5 && g2(p) > -1e-5, what << ": a polyline point violates an inequality");
  }
  // the true curve: A at angle t around P0, B = the intersections of the circles (A, 2), (P1, 0.9)
  std::vector<Pt> truth;
  for (int k = 0; k < 2000; ++k) {
    const double t = 2 * M_PI * k / 2000, x = -1 + 0.9 * std::cos(t), y = 0.9 * std::sin(t);
    const double ex = 1 - x, ey = -y, e = std::hypot(ex, ey);
    const double along = (4 - 0.81 + e * e) / (2 * e), h2 = 4 - along * along;
    if (h2 < 0) continue;
    for (int sgn : {-1, 1}) {
      const Pt p{x, y, x + along * ex / e - sgn * std::sqrt(h2) * ey / e, y + along * ey / e + sgn * std::sqrt(h2) * ex / e};
      if (!with_inequalities || (g1(p) > 1e-3 && g2(p) > 1e-3)) truth.push_back(p);
    }
  }
  CHECK(truth.size() > 100, what << ": the oracle sampled the curve");
  check_points(r, truth, 0.05, what);
}

static void inequality_and_types()
{
  {
    // the upper half of the circle: y >= 0 clips it at (-1, 0) and (1, 0)
    auto s = plane({circle(0, 0, 1)}, -2, 2, -2, 2);
    s.inequalities = {P::variable(2, 1)};
    auto r = RI::trace_curves(s);
    CHECK(r.curves.size() == 1 && !r.curves[0].closed, "clipped circle: one branch");
    if (r.curves.size() == 1) {
      const auto& c = r.curves[0];
      CHECK(c.ends[0] == RI::Curve_end::INEQUALITY && c.ends[1] == RI::Curve_end::INEQUALITY && c.on_inequality_boundary,
            "clipped circle: both ends on y = 0");
      double lowest = 1;
      for (const auto& p : c.points) lowest = std::min(lowest, p[1]);
      CHECK(lowest > -1e-5 && std::abs(std::abs(c.points.front()[0]) - 1) < 1e-4 && std::abs(std::abs(c.points.back()[0]) - 1) < 1e-4,
            "clipped circle: stays in y >= 0 to the minimal width, from x = -1 to x = 1 (lowest " << lowest << ")");
    }
  }
#ifdef CGAL_USE_MPFI
  {
    auto r = RI::trace_curves<CGAL::Gmpfi>(plane({circle(0, 0, 1) * circle(0, 0, Q(1, 4))}, -2, 2, -2, 2));
    CHECK(r.complete() && r.curves.size() == 2, "Gmpfi: two loops");
    for (const auto& c : r.curves) CHECK(c.max_residual < 1e-9, "Gmpfi: residual");
  }
#endif
  {
    // interval coefficients: x^2 + y^2 - [1 - 1e-12, 1 + 1e-12]
    RI::Sparse_polynomial<I> x = RI::Sparse_polynomial<I>::variable(2, 0), y = RI::Sparse_polynomial<I>::variable(2, 1);
    RI::Polynomial_system<I> s;
    s.variable_names = {"x", "y"};
    s.box = {{-2, 2}, {-2, 2}};
    s.equations = {x * x + y * y - RI::Sparse_polynomial<I>::constant(2, I(1 - 1e-12, 1 + 1e-12))};
    auto r = RI::trace_curves(s);
    CHECK(r.complete() && r.curves.size() == 1 && r.curves[0].closed, "interval coefficients: one loop");
  }
  // malformed input
  auto throws = [](const RI::Polynomial_system<Q>& s) {
    try {
      RI::trace_curves(s);
    } catch (const RI::Input_error&) {
      return true;
    }
    return false;
  };
  P x = P::variable(2, 0), y = P::variable(2, 1);
  CHECK(throws(plane({x, y}, -1, 1, -1, 1)), "square system throws");
  CHECK(throws(plane({P(2)}, -1, 1, -1, 1)), "zero equation throws");
  CHECK(throws(plane({x}, 1, -1, -1, 1)), "empty box throws");
  CHECK(throws(plane({x}, -1, std::numeric_limits<double>::infinity(), -1, 1)), "infinite box throws");
}

// Curves that leave the search box through its edges or corners: each crossing there is found
// on every face that meets at it, and must be counted once (it was left unresolved, "crossing
// at a box edge"). The line z = x through the square's corners, and its parallel 1e-17 and
// 1e-13 away (exact coefficients: through the corner in double precision, beside it in fact);
// the line z = x, y = 1/2 through two edges of the cube. Curves that touch the box at corners
// only (x^2 + z^2 = 8, (z - 4)^2 = x^2): isolated points, never a branch.
static void box_edges()
{
  P x = P::variable(2, 0), z = P::variable(2, 1), one = P::constant(2, 1);
  const std::vector<std::pair<Q, std::string>> offsets = {{Q(0), "z = x"}, {Q(1) / Q(std::string("100000000000000000")), "z = x + 1e-17"},
                                                          {Q(1) / Q(std::string("10000000000000")), "z = x + 1e-13"}};
  for (const auto& o : offsets)
    for (int sign = 1; sign >= -1; sign -= 2) {
      const std::string name = sign > 0 ? o.second : o.second + ", mirrored (z = -x ...)";
      auto r = RI::trace_curves(plane({z - Q(sign) * x - o.first * one}, -2, 2, -2, 2));
      CHECK(r.complete() && r.curves.size() == 1, name << ": complete, " << r.curves.size() << " branches, " << r.unresolved.size() << " regions");
      for (const auto& c : r.curves) {
        CHECK(c.certified && !c.closed && c.ends[0] == RI::Curve_end::BOUNDARY && c.ends[1] == RI::Curve_end::BOUNDARY, name << ": one certified branch between two corners");
        const Pt& a = c.points.front();
        const Pt& b = c.points.back();
        CHECK(std::abs(std::abs(a[0]) - 2) < 1e-9 && std::abs(std::abs(b[0]) - 2) < 1e-9 && a[0] * b[0] < 0 && std::abs(a[1] - sign * a[0]) < 1e-9 &&
                  std::abs(b[1] - sign * b[0]) < 1e-9,
              name << ": ends at (" << a[0] << ", " << a[1] << ") and (" << b[0] << ", " << b[1] << ")");
      }
      std::vector<Pt> truth;
      for (int k = 0; k <= 400; ++k) truth.push_back({-2 + k / 100.0, sign * (-2 + k / 100.0)});
      check_points(r, truth, 1e-6, name);
    }
  {  // through two edges of the cube [-2, 2]^3, at y = 1/2
    RI::Polynomial_system<Q> s;
    s.variable_names = {"x", "y", "z"};
    s.box = {{-2, 2}, {-2, 2}, {-2, 2}};
    P x3 = P::variable(3, 0), y3 = P::variable(3, 1), z3 = P::variable(3, 2), one3 = P::constant(3, 1);
    s.equations = {z3 - x3, y3 - Q(1, 2) * one3};
    auto r = RI::trace_curves(s);
    CHECK(r.complete() && r.curves.size() == 1, "z = x, y = 1/2 in the cube: complete, " << r.curves.size() << " branches");
    for (const auto& c : r.curves)
      CHECK(c.certified && c.ends[0] == RI::Curve_end::BOUNDARY && c.ends[1] == RI::Curve_end::BOUNDARY &&
                std::abs(std::abs(c.points.front()[0]) - 2) < 1e-9 && std::abs(std::abs(c.points.back()[0]) - 2) < 1e-9,
            "z = x, y = 1/2 in the cube: one certified branch between two edges");
  }
  // curves that touch the box at corners only (isolated points of the solution set in the
  // box): no branch, every such corner in an unresolved region. In the box [-2, 2] x [0.5, 2]
  // the circle's two corners (-2, 2) and (2, 2) fall in one regular box, where an entry at one
  // and an exit at the other made a certified arc between them (found by a review): the
  // tangent must point into the box through every face of the edge
  struct Touching { P f; double zlo; std::vector<Pt> corners; std::string name; };
  const std::vector<Touching> touching = {
      {circle(0, 0, 8), -2, {{-2, -2}, {-2, 2}, {2, -2}, {2, 2}}, "x^2 + z^2 = 8 in the square"},
      {circle(0, 0, 8), 0.5, {{-2, 2}, {2, 2}}, "x^2 + z^2 = 8 in [-2, 2] x [0.5, 2]"},
      {(z - 4 * one) * (z - 4 * one) - x * x, -2, {{-2, 2}, {2, 2}}, "(z - 4)^2 = x^2 in the square"}};
  for (const auto& t : touching) {
    auto r = RI::trace_curves(plane({t.f}, -2, 2, t.zlo, 2));
    CHECK(!r.complete() && r.unresolved.size() >= t.corners.size(), t.name << ": " << r.unresolved.size() << " regions, complete " << r.complete());
    CHECK(r.curves.empty(), t.name << ": " << r.curves.size() << " branches (the curve meets the box in isolated points)");
    for (const Pt& corner : t.corners) {
      bool found = false;
      for (const auto& u : r.unresolved) found = found || in_region(corner, u, 1e-9);
      CHECK(found, t.name << ": the corner (" << corner[0] << ", " << corner[1] << ") is in an unresolved region");
    }
  }
}

int main()
{
  circles();
  box_edges();
  singular();
  four_bar(1, 3, 3, 4, 2, false);  // Grashof crank-rocker: 1 + 4 < 3 + 3, two circuits
  four_bar(4, 6, 5, 8, 1, false);  // non-Grashof: 4 + 8 > 6 + 5, one circuit
  four_bar(1, 3, 2, 4, 0, true);   // change point: 1 + 4 = 3 + 2
  paper_four_bar(false);
  paper_four_bar(true);
  inequality_and_types();
  std::cout << checks << " checks, " << failures << " failures\n";
  return failures ? 1 : 0;
}
