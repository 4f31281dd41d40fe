// Copyright (c) 2026 Rigid_incidence contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// trace_curves_with_plan(): curves traced along a solution plan (the curve block, then the
// square blocks lifted over it), checked against closed forms.
//  - Jansen's linkage with the five orientation inequalities (data/systems/jansen_ineq.txt,
//    the paper's Fig. 6): one certified closed branch, the physical leg; for the crank at 36
//    angles, the assemblies computed by intersecting circles (32 sign choices) that satisfy the
//    inequalities must each lie on the branch, and the branch must cross each angle exactly as
//    often as there are such assemblies (once).
//  - A circle with z^2 = x y + 2 above it: two certified closed lifts; with z^2 = x y the lifts
//    meet on the axes (the whole curve turns back over the circle there) and, traced whole
//    around those folds, form two certified closed loops, checked against a dense sampling of
//    the closed form; z^2 = x - 1/2: one loop. With the folds not traced (fold_boxes = 0), each
//    run of failed pieces is one region and every chain stopping there names it.
//  - A curve block after square blocks (a = +-sqrt(2), the circle of radius |a|, z = x y; and
//    b = +-sqrt(3) besides, merged with the curve block or lifted after it, with an inequality
//    that needs b): one certified loop per root kept, against the closed form.
//  - An inequality of the curve block: a circle over the line z = x cut by z >= 1/2 (one
//    certified branch ending at the inequality on both sides, flagged; also in the cube, whose
//    corners the line goes through) and clear of z >= -1.01 (one closed loop, not flagged
//    although block 0's line meets the inequality's zero).
//  - Plans of the wrong form are refused.

#include <CGAL/Interval_nt.h>
#include <CGAL/Rigid_incidence.h>
#include <CGAL/Rigid_incidence/trace_curves_with_plan.h>

#include "test_check.h"

#include <array>
#include <cmath>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

namespace RI = CGAL::Rigid_incidence;
typedef CGAL::Interval_nt<false> IT;

// ------------------------------------------------------------------ Jansen's linkage, closed form

typedef std::array<double, 2> P2;

// the intersections of the circles (c1, r1) and (c2, r2); false if they do not meet
static bool circles(const P2& c1, double r1, const P2& c2, double r2, P2& p, P2& q)
{
  const double dx = c2[0] - c1[0], dy = c2[1] - c1[1], d2 = dx * dx + dy * dy, d = std::sqrt(d2);
  const double a = (r1 * r1 - r2 * r2 + d2) / (2 * d), h2 = r1 * r1 - a * a;
  if (h2 < 0) return false;
  const double h = std::sqrt(h2), mx = c1[0] + a * dx / d, my = c1[1] + a * dy / d;
  p = {mx - h * dy / d, my + h * dx / d};
  q = {mx + h * dy / d, my - h * dx / d};
  return true;
}

// every assembly for the crank angle th: the 12 coordinates in the file's variable order
// (Mx My Ax Ay Cx Cy Bx By Dx Dy Fx Fy as they first appear)
static std::vector<std::vector<double>> jansen_assemblies(double th)
{
  const P2 Z{-38, -7.8}, M{15 * std::cos(th), 15 * std::sin(th)};
  std::vector<std::vector<double>> out;
  P2 A[2], C[2], B[2], Dp[2], F[2];
  if (!circles(M, 50, Z, 41.5, A[0], A[1]) || !circles(M, std::sqrt(3831.61), Z, std::sqrt(1544.49), C[0], C[1])) return out;
  for (int a = 0; a < 2; ++a)
    for (int c = 0; c < 2; ++c) {
      if (!circles(A[a], std::sqrt(3113.64), Z, std::sqrt(1608.01), B[0], B[1])) continue;
      for (int b = 0; b < 2; ++b) {
        if (!circles(B[b], std::sqrt(1552.36), C[c], std::sqrt(1346.89), Dp[0], Dp[1])) continue;
        for (int d = 0; d < 2; ++d) {
          if (!circles(Dp[d], std::sqrt(4316.49), C[c], 49, F[0], F[1])) continue;
          for (int f = 0; f < 2; ++f)
            out.push_back({M[0], M[1], A[a][0], A[a][1], C[c][0], C[c][1], B[b][0], B[b][1], Dp[d][0], Dp[d][1], F[f][0], F[f][1]});
        }
      }
    }
  return out;
}

static double cross(double ax, double ay, double bx, double by) { return ax * by - ay * bx; }

// the five orientation inequalities of jansen_ineq.txt
static bool physical(const std::vector<double>& x)
{
  const double Mx = x[0], My = x[1], Ax = x[2], Ay = x[3], Cx = x[4], Cy = x[5], Bx = x[6], By = x[7], Dx = x[8], Dy = x[9], Fx = x[10], Fy = x[11];
  return -cross(-38 - Mx, -7.8 - My, Ax - Mx, Ay - My) >= 0 && cross(-38 - Mx, -7.8 - My, Cx - Mx, Cy - My) >= 0 &&
         -cross(-38 - Ax, -7.8 - Ay, Bx - Ax, By - Ay) >= 0 && -cross(Cx - Bx, Cy - By, Dx - Bx, Dy - By) >= 0 &&
         -cross(Cx - Dx, Cy - Dy, Fx - Dx, Fy - Dy) >= 0;
}

static double dist_to_segment(const std::vector<double>& p, const std::vector<double>& a, const std::vector<double>& b)
{
  double ab = 0, ap = 0;
  for (std::size_t k = 0; k < p.size(); ++k) { ab += (b[k] - a[k]) * (b[k] - a[k]); ap += (p[k] - a[k]) * (b[k] - a[k]); }
  const double t = ab > 0 ? (std::max)(0.0, (std::min)(1.0, ap / ab)) : 0.0;
  double d = 0;
  for (std::size_t k = 0; k < p.size(); ++k) d = (std::max)(d, std::abs(a[k] + t * (b[k] - a[k]) - p[k]));
  return d;
}

static void check_jansen(const std::string& file, bool with_inequalities)
{
  auto f = RI::read_polynomial_system(std::string(RIGID_INCIDENCE_DATA_DIR) + "/systems/" + file);
  const auto& sys = f.system;
  const std::vector<std::string> order{"Mx", "My", "Ax", "Ay", "Cx", "Cy", "Bx", "By", "Dx", "Dy", "Fx", "Fy"};
  std::vector<std::size_t> where;
  for (const auto& v : order) {
    std::size_t k = std::find(sys.variable_names.begin(), sys.variable_names.end(), v) - sys.variable_names.begin();
    CHECK(k < sys.variable_names.size(), file << ": variable " << v);
    where.push_back(k);
  }
  if (failures) return;
  RI::Solution_plan plan(sys);
  CHECK(plan.blocks().size() == 6 && plan.blocks()[0].variables.size() == 2, file << ": the plan is the crank, then one point at a time");
  auto r = RI::trace_curves_with_plan<IT>(sys, plan);
  std::cout << file << ": " << r.curves.size() << " branch(es), " << r.unresolved.size() << " unresolved, " << r.statistics.boxes << " boxes, "
            << r.statistics.block_solves << " block solves (" << r.statistics.kept_solves << " more kept from halved pieces), " << r.statistics.pieces
            << " pieces, " << r.statistics.fold_traces << " fold traces, " << r.statistics.lifted_arcs << " arcs lifted, " << r.statistics.coarse_solves << " coarser block solves, " << r.statistics.seconds << " s\n";
  CHECK(r.complete(), file << ": complete");
  if (with_inequalities) CHECK(r.curves.size() == 1 && r.curves[0].closed && r.curves[0].certified, file << ": one certified closed branch");
  for (const auto& c : r.curves) CHECK(c.certified && c.closed, file << ": every branch certified and closed (the crank turns fully)");
  // every point on the system
  for (const auto& c : r.curves) CHECK(c.max_residual < 1e-8, file << ": residual " << c.max_residual);
  // the closed form at 36 crank angles (not multiples of the polyline's spacing)
  for (int k = 0; k < 36; ++k) {
    const double th = 2 * CGAL_PI * (k + 0.37) / 36;
    std::vector<std::vector<double>> asm_ = jansen_assemblies(th);
    std::size_t expected = 0;
    for (const auto& a : asm_) {
      if (with_inequalities && !physical(a)) continue;
      ++expected;
      // on some branch: near one of its segments (polyline spacing: a few units)
      double best = 1e300;
      for (const auto& c : r.curves)
        for (std::size_t i = 0; i + 1 < c.points.size(); ++i) {
          std::vector<double> p(12), q(12);
          for (std::size_t v = 0; v < 12; ++v) { p[v] = c.points[i][where[v]]; q[v] = c.points[i + 1][where[v]]; }
          best = (std::min)(best, dist_to_segment(a, p, q));
        }
      CHECK(best < 1.0, file << ": assembly at crank angle " << th << " is " << best << " away from the branches");
    }
    // crossings of the crank ray at th: the count of assemblies
    std::size_t crossings = 0;
    for (const auto& c : r.curves)
      for (std::size_t i = 0; i + 1 < c.points.size(); ++i) {
        const double a0 = std::atan2(c.points[i][where[1]], c.points[i][where[0]]), a1 = std::atan2(c.points[i + 1][where[1]], c.points[i + 1][where[0]]);
        double d0 = std::remainder(a0 - th, 2 * CGAL_PI), d1 = std::remainder(a1 - th, 2 * CGAL_PI);
        if (std::abs(d0 - d1) < 1 && ((d0 < 0) != (d1 < 0))) ++crossings;
      }
    CHECK(crossings == expected, file << ": at crank angle " << th << " the branches cross " << crossings << " times, " << expected << " assemblies");
  }
}

// ------------------------------------------------------------------ small systems

static RI::Polynomial_system<CGAL::Gmpq> system_of(const std::string& text)
{
  std::istringstream in(text);
  return RI::read_polynomial_system(in).system;
}

int main(int argc, char** argv)
{
  // jansen.txt (without the inequalities: 32 assemblies over most of the crank circle, fewer
  // where circle intersections fold) takes about 40 s in Release, minutes under the sanitizers
  // (its runs of folds are traced whole in 12 variables): the ctest test_trace_curves_with_plan_jansen (label 'heavy', option
  // RIGID_INCIDENCE_HEAVY_TESTS) runs it, against the closed form at 36 crank angles
  if (argc > 1 && std::string(argv[1]) == "--jansen-without-inequalities") {
    check_jansen("jansen.txt", false);
    std::cout << (failures ? "FAILED" : "passed") << " (" << failures << " failures)\n";
    return failures ? 1 : 0;
  }
  check_jansen("jansen_ineq.txt", true);

  {  // two lifts that never meet: z = +- sqrt(x y + 2) over the unit circle (z involves x and y,
     // so the plan is the circle, then z)
    auto s = system_of("2 3\nx^2 + y^2 - 1;\nz^2 - x*y - 2;\nbox * -3 3\n");
    RI::Solution_plan plan(s);
    CHECK(plan.blocks().size() == 2 && plan.blocks()[0].variables.size() == 2, "two lifts: the plan is the circle, then z");
    auto r = RI::trace_curves_with_plan<IT>(s, plan);
    CHECK(r.complete() && r.curves.size() == 2, "two lifts: " << r.curves.size() << " branches, complete " << r.complete());
    for (const auto& c : r.curves) {
      CHECK(c.closed && c.certified && c.max_residual < 1e-12, "two lifts: closed certified branch");
      double zmin = 1e9, zmax = -1e9;
      for (const auto& p : c.points) { zmin = (std::min)(zmin, p[2]); zmax = (std::max)(zmax, p[2]); }
      CHECK(zmin * zmax > 0 && std::abs(zmax) <= std::sqrt(2.5) + 1e-9 && std::abs(zmin) >= std::sqrt(1.5) - 1e-9, "two lifts: one sign of z each");
    }
  }
  {  // z = +- sqrt(x y): real where x y >= 0; the two lifts meet on the axes, where the whole
     // curve turns back over the circle (a fold of the plan): traced whole there, it is two
     // certified closed loops, one over each quadrant where x y >= 0, each through both signs of z
    auto s = system_of("2 3\nx^2 + y^2 - 1;\nz^2 - x*y;\nbox * -3 3\n");
    auto r = RI::trace_curves_with_plan<IT>(s, RI::Solution_plan(s));
    std::cout << "z^2 = x y: " << r.curves.size() << " curves, " << r.unresolved.size() << " unresolved, " << r.statistics.fold_traces << " fold traces\n";
    CHECK(r.complete() && r.curves.size() == 2, "meeting lifts: complete, " << r.curves.size() << " curves");
    CHECK(r.statistics.fold_traces > 0, "meeting lifts: the folds were traced whole");
    int quadrants = 0;
    for (const auto& c : r.curves) {
      CHECK(c.closed && c.certified && c.max_residual < 1e-9, "meeting lifts: closed certified loop, residual " << c.max_residual);
      double zmin = 1e9, zmax = -1e9, sx = 0;
      for (const auto& p : c.points) {
        CHECK(p[0] * p[1] > -1e-9, "meeting lifts: only x y >= 0 has real lifts");
        zmin = (std::min)(zmin, p[2]);
        zmax = (std::max)(zmax, p[2]);
        sx += p[0];
      }
      CHECK(zmin < -0.7 && zmax > 0.7, "meeting lifts: a loop passes through both signs of z (max |z| = sqrt(1/2))");
      quadrants |= sx > 0 ? 1 : 2;
    }
    CHECK(quadrants == 3, "meeting lifts: one loop over each of the quadrants x, y >= 0 and x, y <= 0");
    // the closed form, sampled densely: every point lies near a loop
    for (int k = 0; k <= 200; ++k)
      for (int sign = -1; sign <= 1; sign += 2) {
        const double th = (k % 2 ? CGAL_PI : 0) + 0.5 * CGAL_PI * (k / 2) / 100.0;
        const std::vector<double> p{std::cos(th), std::sin(th), sign * std::sqrt((std::max)(0.0, std::cos(th) * std::sin(th)))};
        double best = 1e300;
        for (const auto& c : r.curves)
          for (std::size_t i = 0; i + 1 < c.points.size(); ++i) best = (std::min)(best, dist_to_segment(p, c.points[i], c.points[i + 1]));
        CHECK(best < 0.05, "meeting lifts: (" << p[0] << ", " << p[1] << ", " << p[2] << ") is " << best << " away from the loops");
      }
  }
  {  // the same folds with fold_stretch = 1: the result must not change (its runs have at most
     // 2 pieces, so they are not cut; Jansen's linkage, run by benchmark_plan, is where runs of
     // 160 pieces are cut into stretches and joined through the lifts between them)
    auto s = system_of("2 3\nx^2 + y^2 - 1;\nz^2 - x*y;\nbox * -3 3\n");
    RI::Plan_trace_parameters pp;
    pp.fold_stretch = 1;
    auto r = RI::trace_curves_with_plan<IT>(s, RI::Solution_plan(s), RI::Curve_tracer_parameters(), RI::Subdivision_solver_parameters(), pp);
    std::cout << "z^2 = x y in stretches: " << r.curves.size() << " curves, " << r.unresolved.size() << " unresolved, " << r.statistics.fold_traces << " fold traces\n";
    CHECK(r.complete() && r.curves.size() == 2, "in stretches: complete, " << r.curves.size() << " curves");
    for (const auto& c : r.curves) CHECK(c.closed && c.certified && c.max_residual < 1e-9, "in stretches: closed certified loop");
  }
  {  // the same folds with a small box budget for each block solve: near a fold the z block's
     // roots sweep a thin region that boxes of the minimal width cannot cover within it, and the
     // boxes left pending are large; the enclosures around the folds are then solved again with
     // boxes left unknown at 16, 256, ... times the minimal width (Jansen's linkage: without
     // this, a pending box 400 wide made one fold's traced box 400 wide, and it ran out of boxes)
    auto s = system_of("2 3\nx^2 + y^2 - 1;\nz^2 - x*y;\nbox * -3 3\n");
    RI::Plan_trace_parameters pp;
    pp.block_boxes = 40;
    auto r = RI::trace_curves_with_plan<IT>(s, RI::Solution_plan(s), RI::Curve_tracer_parameters(), RI::Subdivision_solver_parameters(), pp);
    std::cout << "z^2 = x y, 40 boxes per block solve: " << r.curves.size() << " curves, " << r.unresolved.size() << " unresolved, "
              << r.statistics.fold_traces << " fold traces, " << r.statistics.coarse_solves << " coarser block solves, " << r.statistics.boxes << " boxes\n";
    CHECK(r.statistics.coarse_solves > 0, "small block budget: the enclosures around the folds were solved again coarser");
    CHECK(r.complete() && r.curves.size() == 2, "small block budget: complete, " << r.curves.size() << " curves");
    for (const auto& c : r.curves) {
      CHECK(c.closed && c.certified && c.max_residual < 1e-9, "small block budget: closed certified loop");
      double zmin = 1e9, zmax = -1e9;
      for (const auto& p : c.points) { zmin = (std::min)(zmin, p[2]); zmax = (std::max)(zmax, p[2]); }
      CHECK(zmin < -0.7 && zmax > 0.7, "small block budget: a loop passes through both signs of z");
    }
  }
  {  // a fold of one branch next to a branch that does not fold there: u = +-sqrt(4 + x + y),
     // then z = +-sqrt((u - 1.9) y) (the plan: the circle, u, z). Branch u > 0 folds where y = 0
     // and where u = 1.9 (x + y = -0.39); at the one with y < 0 (angle about -61 degrees) branch
     // u < 0 has its two z apart, so over that run its clusters are lifted from their certified
     // enclosures (lifted_arcs), not traced
    auto s = system_of("3 4\nx^2 + y^2 - 1;\nu^2 - x - y - 4;\nz^2 - (u - 1.9)*y;\nbox * -3 3\n");
    CHECK(RI::Solution_plan(s).blocks().size() == 3 && RI::Solution_plan(s).blocks()[0].variables == std::vector<std::size_t>({0, 1}),
          "fold next to a regular branch: the plan is the circle, then u, then z");
    auto r = RI::trace_curves_with_plan<IT>(s, RI::Solution_plan(s));
    std::cout << "a fold next to a branch without one: " << r.curves.size() << " curves, " << r.unresolved.size() << " unresolved, "
              << r.statistics.fold_traces << " fold traces, " << r.statistics.lifted_arcs << " arcs lifted\n";
    CHECK(r.complete() && !r.curves.empty(), "fold next to a regular branch: complete, " << r.curves.size() << " curves");
    CHECK(r.statistics.lifted_arcs > 0, "fold next to a regular branch: some arcs lifted, not traced");
    for (const auto& c : r.curves) CHECK(c.closed && c.certified && c.max_residual < 1e-9, "fold next to a regular branch: closed certified loop");
    for (int k = 0; k < 720; ++k) {
      const double th = 2 * CGAL_PI * (k + 0.29) / 720, x = std::cos(th), y = std::sin(th);
      std::size_t expected = 0;
      for (int su = -1; su <= 1; su += 2) {
        const double u = su * std::sqrt(4 + x + y), w = (u - 1.9) * y;
        if (w < 0) continue;
        for (int sz = -1; sz <= 1; sz += 2) {
          ++expected;
          const std::vector<double> p{x, y, u, sz * std::sqrt(w)};
          double best = 1e300;
          for (const auto& c : r.curves)
            for (std::size_t i = 0; i + 1 < c.points.size(); ++i) best = (std::min)(best, dist_to_segment(p, c.points[i], c.points[i + 1]));
          CHECK(best < 0.05, "fold next to a regular branch: the closed form at angle " << th << " is " << best << " away");
        }
      }
      std::size_t crossings = 0;
      for (const auto& c : r.curves)
        for (std::size_t i = 0; i < c.points.size(); ++i) {
          const auto& p = c.points[i];
          const auto& q = c.points[(i + 1) % c.points.size()];
          const double d0 = std::remainder(std::atan2(p[1], p[0]) - th, 2 * CGAL_PI), d1 = std::remainder(std::atan2(q[1], q[0]) - th, 2 * CGAL_PI);
          if (std::abs(d0 - d1) < 1 && ((d0 < 0) != (d1 < 0))) ++crossings;
        }
      CHECK(crossings == expected, "fold next to a regular branch: at angle " << th << " " << crossings << " crossings, " << expected << " points");
    }
  }
  {  // the same folds, not traced whole (fold_boxes = 0): each run of failed pieces is one
     // region, and every chain that stops at one names it (end_region) with its end inside
    auto s = system_of("2 3\nx^2 + y^2 - 1;\nz^2 - x*y;\nbox * -3 3\n");
    RI::Plan_trace_parameters pp;
    pp.fold_boxes = 0;
    auto r = RI::trace_curves_with_plan<IT>(s, RI::Solution_plan(s), RI::Curve_tracer_parameters(), RI::Subdivision_solver_parameters(), pp);
    CHECK(!r.complete() && r.statistics.fold_traces == 0, "folds not traced: not complete");
    CHECK(r.unresolved.size() >= 4 && r.unresolved.size() <= 8, "folds not traced: " << r.unresolved.size() << " regions (4 folds)");
    std::vector<int> used(r.unresolved.size(), 0);
    for (const auto& c : r.curves) {
      CHECK(!c.certified && !c.closed, "folds not traced: the chains stop at the folds, uncertified");
      for (int e = 0; e < 2; ++e) {
        if (c.ends[e] != RI::Curve_end::UNRESOLVED) continue;
        const long g = c.end_region[e];
        CHECK(g >= 0 && std::size_t(g) < r.unresolved.size(), "folds not traced: an unresolved end names its region (" << g << ")");
        if (g < 0 || std::size_t(g) >= r.unresolved.size()) continue;
        ++used[std::size_t(g)];
        const std::vector<double>& p = e == 0 ? c.points.front() : c.points.back();
        bool inside = true;
        for (std::size_t k = 0; k < 2; ++k)  // the curve block's variables x, y
          inside = inside && CGAL::to_double(r.unresolved[std::size_t(g)].box[k].inf()) - 1e-9 <= p[k] &&
                   p[k] <= CGAL::to_double(r.unresolved[std::size_t(g)].box[k].sup()) + 1e-9;
        CHECK(inside, "folds not traced: a chain's end (" << p[0] << ", " << p[1] << ") lies in its region");
        CHECK(std::abs(p[0] * p[1]) < 0.05, "folds not traced: a chain ends near an axis, where the lifts meet");
      }
    }
    for (std::size_t g = 0; g < used.size(); ++g) CHECK(used[g] >= 2, "folds not traced: region " << g << " is where " << used[g] << " chain ends stop (both lifts, at least)");
  }
  {  // z = +- sqrt(x - 1/2): real on the arc x >= 1/2 of the circle, the lifts meet at its two
     // ends (x = 1/2): one certified closed loop
    auto s = system_of("2 3\nx^2 + y^2 - 1;\nz^2 - x + 1/2;\nbox * -3 3\n");
    auto r = RI::trace_curves_with_plan<IT>(s, RI::Solution_plan(s));
    CHECK(r.complete() && r.curves.size() == 1, "one fold pair: complete, " << r.curves.size() << " curves");
    for (const auto& c : r.curves) {
      CHECK(c.closed && c.certified && c.max_residual < 1e-9, "one fold pair: closed certified loop");
      double xmin = 1e9, ymin = 1e9, ymax = -1e9;
      for (const auto& p : c.points) { xmin = (std::min)(xmin, p[0]); ymin = (std::min)(ymin, p[1]); ymax = (std::max)(ymax, p[1]); }
      CHECK(xmin > 0.5 - 1e-9 && xmin < 0.5 + 1e-3 && ymax > 0.86 && ymin < -0.86, "one fold pair: the loop spans the arc x >= 1/2 up to its ends (y = +-sqrt(3)/2)");
    }
  }
  {  // an inequality of the curve block (z = x, then y from the circle): z >= 1/2 cuts the
     // lifted circle at x = 1/2, so one certified branch with both ends at the inequality,
     // flagged; z >= -1.01 never meets it (block 0's line does, at x = -1.01, beyond the
     // circle): one closed certified loop, not flagged (it was, from block 0's flag, before
     // the flag was restricted to the pieces where the inequality may vanish). With z in
     // [-3, 3], and in the cube [-2, 2]^3, where block 0's line leaves the box through its
     // corners (it was left unresolved there, "crossing at a box edge").
    for (int variant = 0; variant < 3; ++variant) {
      const bool cut = variant > 0;
      auto s = system_of(std::string("2 3\nx^2 + y^2 - 1;\nz - x;\nbox * -2 2\n") + (variant < 2 ? "box z -3 3\n" : "") + "inequality z " +
                         (cut ? "- 1/2" : "+ 101/100") + " >= 0;\n");
      const std::string name = std::string(cut ? "circle cut by z >= 1/2" : "circle clear of z >= -1.01") + (variant == 2 ? " in the cube" : "");
      RI::Solution_plan plan(s);
      CHECK(plan.blocks().size() == 2 && plan.blocks()[0].inequalities.size() == 1, name << ": the inequality belongs to the curve block");
      auto r = RI::trace_curves_with_plan<IT>(s, plan);
      CHECK(r.complete() && r.curves.size() == 1, name << ": complete, " << r.curves.size() << " branches, " << r.unresolved.size() << " regions");
      for (const auto& c : r.curves) {
        CHECK(c.certified && c.max_residual < 1e-9, name << ": a certified branch, residual " << c.max_residual);
        double xmin = 1e9, worst = 0;
        for (const auto& p : c.points) {
          xmin = (std::min)(xmin, p[0]);
          worst = (std::max)(worst, (std::max)(std::abs(p[0] * p[0] + p[1] * p[1] - 1), std::abs(p[2] - p[0])));
        }
        CHECK(worst < 1e-9, name << ": a point " << worst << " off the closed form");
        if (cut) {
          CHECK(!c.closed && c.ends[0] == RI::Curve_end::INEQUALITY && c.ends[1] == RI::Curve_end::INEQUALITY, name << ": both ends at the inequality");
          CHECK(c.on_inequality_boundary, name << ": flagged on the inequality's boundary");
          CHECK(xmin > 0.5 - 1e-5, name << ": the branch stays where z >= 1/2 (x min " << xmin << ")");
          for (int e = 0; e < 2; ++e) {
            const auto& p = e ? c.points.back() : c.points.front();
            CHECK(std::abs(p[0] - 0.5) < 1e-5 && std::abs(std::abs(p[1]) - std::sqrt(0.75)) < 1e-5, name << ": an end at (" << p[0] << ", " << p[1] << ")");
          }
        } else {
          CHECK(c.closed && !c.on_inequality_boundary, name << ": a closed loop, not flagged (" << c.on_inequality_boundary << ")");
          CHECK(xmin < -1 + 1e-3, name << ": the loop goes round to x = -1 (x min " << xmin << ")");
        }
      }
    }
  }
  {  // plans of the wrong form
    auto square = system_of("2 2\nx^2 + y^2 - 1;\nx - y;\n");
    bool thrown = false;
    try { RI::trace_curves_with_plan<IT>(square, RI::Solution_plan(square)); } catch (const RI::Input_error&) { thrown = true; }
    CHECK(thrown, "a square system is refused");
    auto two = system_of("4 5\nx^2 + y^2 - 1;\nz^2 + w^2 - 1;\nu - 1;\nu - 2;\n");  // two curves, one conflict
    CHECK(RI::Solution_plan(two).structure() == RI::Solution_plan::MIXED, "two curves and a conflict: a mixed plan");
    thrown = false;
    try { RI::trace_curves_with_plan<IT>(two, RI::Solution_plan(two)); } catch (const RI::Input_error&) { thrown = true; }
    CHECK(thrown, "a mixed system (two curves, one conflict) is refused");
    // a plan made without the system's inequality (it would let the branch with x < 0 through)
    auto halves = system_of("2 3\nx^2 + y^2 - 1;\nz - x*y;\nbox * -3 3\ninequality x >= 0;\n");
    std::string what;
    try { RI::trace_curves_with_plan<IT>(halves, RI::Solution_plan(halves, {})); } catch (const RI::Input_error& e) { what = e.what(); }
    CHECK(what.find("0 inequalities, the system has 1") != std::string::npos, "a plan without the system's inequality is refused: " << what);
  }
  {  // the curve block after square blocks: a = +-sqrt(2) first, then the circle of radius |a|,
     // then z = x y. Variant 1: b = +-sqrt(3) too, with the circle of radius sqrt(a^2 + b), so
     // that b's block is merged into block 0 as well. Variant 2: b = +-sqrt(3) only in
     // z = x y + b, so that b's block is not an ancestor of the curve block: it comes before it
     // in the plan but is lifted after it. Variant 3: as 2 with the inequality x - b >= 0, which
     // the plan attaches to the curve block (its last variable) but which needs b: moved to b's
     // block, it keeps b = -sqrt(3) only (x - sqrt(3) < 0 on the circle of radius sqrt(2)).
     // Each loop is checked against the closed form, sampled densely.
    const char* systems[4] = {"3 4\na^2 - 2;\nx^2 + y^2 - a^2;\nz - x*y;\nbox * -3 3\n",
                              "4 5\na^2 - 2;\nb^2 - 3;\nx^2 + y^2 - a^2 - b;\nz - x*y;\nbox * -3 3\n",
                              "4 5\na^2 - 2;\nb^2 - 3;\nx^2 + y^2 - a^2;\nz - x*y - b;\nbox * -3 3\n",
                              "4 5\na^2 - 2;\nb^2 - 3;\nx^2 + y^2 - a^2;\nz - x*y - b;\nbox * -3 3\ninequality x - b >= 0;\n"};
    for (int variant = 0; variant < 4; ++variant) {
      auto s = system_of(systems[variant]);
      const bool has_b = variant > 0, b_in_circle = variant == 1;
      const std::string what = "curve block after square blocks (variant " + std::to_string(variant) + ")";
      auto plan = RI::Solution_plan(s);
      CHECK(plan.blocks().size() == std::size_t(has_b ? 4 : 3) && plan.blocks()[0].dimension() == 0, what << ": the plan starts with a square block");
      if (variant == 3) {
        bool on_curve_block = false;
        for (const auto& B : plan.blocks()) if (B.dimension() == 1 && B.inequalities.size() == 1) on_curve_block = true;
        CHECK(on_curve_block, what << ": the plan attaches x - b >= 0 to the curve block");
      }
      auto r = RI::trace_curves_with_plan<IT>(s, plan);
      const std::size_t expected = variant == 0 || variant == 3 ? 2 : 4;
      CHECK(r.complete() && r.curves.size() == expected, what << ": complete " << r.complete() << ", " << r.curves.size() << " curves");
      const std::size_t x = has_b ? 2 : 1, y = x + 1, z = y + 1;
      std::vector<int> seen(4, 0);
      for (const auto& c : r.curves) {
        CHECK(c.closed && c.certified && c.max_residual < 1e-9, what << ": closed certified loop");
        const double a = c.points.front()[0], b = has_b ? c.points.front()[1] : 0;
        CHECK(std::abs(std::abs(a) - std::sqrt(2.0)) < 1e-9 && (!has_b || std::abs(std::abs(b) - std::sqrt(3.0)) < 1e-9), what << ": a = " << a << ", b = " << b);
        ++seen[(a > 0 ? 1 : 0) + (b > 0 ? 2 : 0)];
        const double radius = std::sqrt(2 + (b_in_circle ? b : 0)), shift = b_in_circle ? 0 : b;
        for (const auto& p : c.points)
          CHECK(std::abs(p[0] - a) < 1e-12 && (!has_b || std::abs(p[1] - b) < 1e-12) && std::abs(std::hypot(p[x], p[y]) - radius) < 1e-9 &&
                std::abs(p[z] - p[x] * p[y] - shift) < 1e-9, what << ": a point off the closed form");
        for (int k = 0; k < 400; ++k) {
          const double th = 2 * CGAL_PI * k / 400;
          std::vector<double> q = c.points.front();
          q[x] = radius * std::cos(th);
          q[y] = radius * std::sin(th);
          q[z] = q[x] * q[y] + shift;
          double best = 1e300;
          for (std::size_t i = 0; i + 1 < c.points.size(); ++i) best = (std::min)(best, dist_to_segment(q, c.points[i], c.points[i + 1]));
          CHECK(best < 0.05, what << ": the closed form at angle " << th << " is " << best << " away from the loop");
        }
      }
      for (int k = 0; k < 4; ++k) {
        const bool want = k < 2 || (has_b && variant != 3);
        CHECK(seen[k] == (want ? 1 : 0), what << ": " << seen[k] << " loop(s) with a " << (k % 2 ? "> 0" : "< 0") << ", b " << (k / 2 ? "> 0" : "<= 0"));
      }
    }
  }

  std::cout << checks << " checks, " << failures << " failures\n";
  return failures == 0 ? 0 : 1;
}
