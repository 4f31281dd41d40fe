// Copyright (c) 2026 Rigid_incidence contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Tree_system (the reduced system of a hinged scene evaluated along its incidence tree, never
// expanded) and solve_tree_system() (branch and prune with charts chosen lazily). Oracles:
// - the expanded reduced system (Reduced_system with exact coefficients) in the same chart
//   combination: at random points, the tree's value times the hinges' denominators
//   prod D_e^(rotation_degree / 2) is the expanded numerator;
// - the enclosures themselves at random points of random boxes: the first-order (affine)
//   enclosure contains every value, the gradient enclosure every gradient, and the gradient at
//   a point agrees with central differences of the values;
// - solve_scene() on the expanded systems: the same configurations (compared by every pairwise
//   distance of the points, which no choice of frame changes), on chains of 4, 5 and 6
//   hinged tetrahedra (6, 2 and 2 configurations) and on the ring of 7;
// - solve_scene() with and without the chart propagation (Scene_solve_parameters::
//   chart_propagation): the same configurations, point for point, and the combinations it
//   excludes never built (two pairs of hinged bodies, each combination alone: 7 of 16; chains
//   of 4 and 6: 2 of 8 and 26 of 32, with arc consistency first);
// - the sweep (a chain's driver hinge bisected, the others found in turn) against the same
//   expanded answer, in solve_tree_system() and in solve_scene() (point for point), and the
//   sweep cut by a time limit (not complete, saying why); sweep orders of hand-made supports;
// - arc consistency (Tree_solver_parameters::consistency_cells) against none: the same roots,
//   each in the cells kept; its clip by hand at cell borders; a bad cell count
//   refused; the chain of 7 (64 combinations: swept by default) point for point against the
//   expanded systems, the planted configuration among its configurations;
// - a box budget: the rest pending, the result not complete;
// - a scene outside its reach (tetra: bodies known by distances in the covering set): refused,
//   saying why.
// Usage: test_tree_system

#include <CGAL/Gmpq.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Rigid_incidence.h>
#include <CGAL/Rigid_incidence/IO/read_scene.h>
#include <CGAL/Rigid_incidence/solve_tree_system.h>

#include <nlohmann/json.hpp>

#include <cmath>
#include <fstream>
#include <iostream>
#include <random>
#include <string>
#include <vector>

#include "test_check.h"

namespace RI = CGAL::Rigid_incidence;
typedef RI::Rigid_incidence_traits<CGAL::Simple_cartesian<CGAL::Gmpq>> Traits;
typedef CGAL::Interval_nt<false> IT;

struct Loaded
{
  RI::Rigid_body_collection<Traits> input, c;
  RI::Incidence_tree t;
  RI::Well_formed_selection wf;
};

static Loaded load(const std::string& file)
{
  std::ifstream in(file);
  const RI::Scene scene = RI::read_scene(in, file);
  Loaded l{RI::make_collection<Traits>(scene), {}, {}, {}};
  l.c = RI::standardize(l.input);
  l.t = RI::optimal_incidence_tree(l.c);
  l.wf = RI::select_well_formed_incidences(l.c, l.t);
  return l;
}

static bool overlap(const IT& a, const IT& b, double slack)
{
  return a.inf() - slack <= b.sup() && b.inf() - slack <= a.sup();
}

// the tree's equations against the expanded ones, and the enclosures against point values
static void check_evaluator(const std::string& name, const Loaded& l, std::mt19937_64& rng)
{
  RI::Tree_system<Traits> S(l.c, l.t, l.wf);
  const std::size_t n = S.number_of_variables();
  std::uniform_real_distribution<double> u(-1, 1);
  std::uniform_int_distribution<int> coin(0, 1);
  for (int round = 0; round < 6; ++round) {
    std::vector<int> charts(n);
    for (int& ch : charts) ch = coin(rng);
    RI::Reduced_system<Traits, CGAL::Gmpq> r(l.c, l.t, l.wf, charts);
    CHECK(r.number_of_equations() == S.number_of_equations(), name << ": " << r.number_of_equations() << " expanded equations, "
                                                                     << S.number_of_equations() << " along the tree");
    if (r.number_of_equations() != S.number_of_equations()) return;
    CGAL::Protect_FPU_rounding<true> guard;
    for (int k = 0; k < 5; ++k) {
      std::vector<double> x(n);
      for (double& v : x) v = u(rng);
      std::vector<IT> xi(x.begin(), x.end());
      for (std::size_t e = 0; e < S.number_of_equations(); ++e) {
        IT tree = S.value(e, charts, x);
        IT scale(1);
        for (std::size_t k2 = 0; k2 < n; ++k2)
          for (unsigned p = 0; p < r.equations()[e].rotation_degree[k2] / 2; ++p)
            scale *= r.parametrization().denominator(k2).template evaluate<IT>(xi);
        const IT expanded = r.equations()[e].polynomial.template evaluate<IT>(xi);
        const double mag = (std::max)(1.0, CGAL::abs(expanded).sup());
        CHECK(overlap(tree * scale, expanded, 1e-9 * mag), name << " charts round " << round << " equation " << e << " ("
                                                               << S.equations()[e].label << "): tree " << tree * scale
                                                               << ", expanded " << expanded);
      }
      // a random box around x: its enclosures contain the values and gradients at its points
      std::vector<IT> box(n);
      for (std::size_t i = 0; i < n; ++i) {
        const double w = std::pow(10.0, -1 - 4 * (u(rng) + 1) / 2);
        box[i] = IT(x[i] - w, x[i] + w * (1 + u(rng)) / 2 + 1e-300);
      }
      for (std::size_t e = 0; e < S.number_of_equations(); ++e) {
        std::vector<IT> A, G, g;
        const IT C = S.evaluate(e, charts, box, A);
        const IT range = RI::Tree_system<Traits>::range(C, A);
        S.gradient(e, charts, box, G);
        const auto& vars = S.equations()[e].variables;
        for (int p = 0; p < 8; ++p) {
          std::vector<double> y = x;
          for (std::size_t i = 0; i < n; ++i) y[i] = box[i].inf() + (box[i].sup() - box[i].inf()) * (u(rng) + 1) / 2;
          const IT v = S.value(e, charts, y);
          CHECK(overlap(range, v, 0), name << " equation " << e << ": the affine enclosure " << range << " misses the value " << v);
          std::vector<IT> yi(y.begin(), y.end());
          S.gradient(e, charts, yi, g);
          for (std::size_t j = 0; j < vars.size(); ++j) {
            CHECK(overlap(G[j], g[j], 0), name << " equation " << e << " variable " << vars[j] << ": the gradient enclosure " << G[j]
                                               << " misses " << g[j]);
            // central differences
            const double h = 1e-6;
            std::vector<double> yp = y, ym = y;
            yp[vars[j]] += h;
            ym[vars[j]] -= h;
            const double fd = (CGAL::to_double(S.value(e, charts, yp)) - CGAL::to_double(S.value(e, charts, ym))) / (2 * h);
            const double gd = CGAL::to_double(g[j]);
            CHECK(std::abs(fd - gd) <= 1e-4 * (1 + std::abs(gd)), name << " equation " << e << " variable " << vars[j] << ": derivative "
                                                                    << gd << ", central difference " << fd);
          }
        }
      }
    }
  }
}

// every pairwise distance of the placed points, in order
static std::vector<double> shape(const std::vector<std::array<double, 3>>& p)
{
  std::vector<double> d;
  for (std::size_t i = 0; i < p.size(); ++i)
    for (std::size_t j = i + 1; j < p.size(); ++j)
      d.push_back(std::sqrt((p[i][0] - p[j][0]) * (p[i][0] - p[j][0]) + (p[i][1] - p[j][1]) * (p[i][1] - p[j][1]) +
                            (p[i][2] - p[j][2]) * (p[i][2] - p[j][2])));
  return d;
}
static double shape_distance(const std::vector<double>& a, const std::vector<double>& b)
{
  double m = 0;
  for (std::size_t i = 0; i < a.size() && i < b.size(); ++i) m = (std::max)(m, std::abs(a[i] - b[i]));
  return a.size() == b.size() ? m : 1e300;
}

static void check_solve(const std::string& name, const Loaded& l, std::size_t expected, bool sweep)
{
  RI::Tree_system<Traits> S(l.c, l.t, l.wf);
  RI::Tree_solver_parameters P;
  P.split_width = 0.0625;
  P.sweep = sweep;
  CHECK(RI::sweep_order(S).exists(S.number_of_variables()) && RI::sweep_order(S).driver != RI::Sweep_order::none &&
            RI::sweep_order(S).checks.size() == 1,
        name << ": a chain without a sweep order (a driver, the closing distance the one check)");
  const RI::Tree_solve_result r = RI::solve_tree_system(S, P);
  CHECK(r.complete() && r.stopped.empty(), name << ": the tree solve is not complete (" << r.unresolved.size() << " regions; " << r.stopped << ")");
  // the roots as shapes, one configuration per root (a root on a chart border is found in both charts)
  std::vector<std::vector<double>> tree_shapes;
  for (const auto& x : r.roots) {
    CHECK(x.certified, name << ": a root not certified");
    for (std::size_t i = 0; i < x.enclosure.size(); ++i)
      CHECK(x.enclosure[i].sup() - x.enclosure[i].inf() <= 1e-9, name << ": a root enclosure " << x.enclosure[i] << " is wide");
    RI::Incidence_tree_parametrization<Traits, IT> p(l.c, l.t, x.charts);
    CGAL::Protect_FPU_rounding<true> guard;
    auto poses = p.template poses<double>(x.approximation);
    std::vector<std::array<double, 3>> pts(l.c.number_of_points(), {0, 0, 0});
    for (std::size_t b : l.t.covering_set)
      for (std::size_t i = 0; i < l.c.body(b).points.size(); ++i) {
        const auto y = p.coordinates(b)[i];
        std::array<double, 3> z;
        for (int k = 0; k < 3; ++k) {
          z[std::size_t(k)] = poses[b].t[std::size_t(k)];
          for (int m = 0; m < 3; ++m) z[std::size_t(k)] += poses[b].R[std::size_t(3 * k + m)] * CGAL::to_double(y[std::size_t(m)]);
        }
        pts[l.c.body(b).points[i]] = z;
      }
    const auto sh = shape(pts);
    bool seen = false;
    for (const auto& o : tree_shapes) seen = seen || shape_distance(o, sh) < 1e-7;
    if (!seen) tree_shapes.push_back(sh);
  }
  // the expanded systems' answer
  RI::Scene_solve_parameters sp;
  sp.sweep = false;
  const RI::Scene_solve_result e = RI::solve_scene<IT, CGAL::Gmpq>(l.input, l.c, l.t, l.wf, sp);
  CHECK(e.complete(), name << ": the expanded solve is not complete");
  CHECK(tree_shapes.size() == e.configurations.size() && e.configurations.size() == expected,
        name << ": " << tree_shapes.size() << " configurations along the tree, " << e.configurations.size() << " expanded, " << expected
             << " expected");
  for (const auto& conf : e.configurations) {
    std::vector<std::array<double, 3>> pts(l.c.number_of_points());
    for (std::size_t q = 0; q < l.c.number_of_points(); ++q) pts[q] = conf.configuration.points[l.input.point_index(l.c.label(q))];
    const auto sh = shape(pts);
    bool found = false;
    for (const auto& o : tree_shapes) found = found || shape_distance(o, sh) < 1e-7;
    CHECK(found, name << ": an expanded configuration has no root along the tree");
  }
  std::cout << name << (sweep ? " (sweep)" : " (branch and prune)") << ": " << tree_shapes.size() << " configurations (" << r.roots.size() << " roots), " << r.statistics.boxes << " boxes, "
            << r.statistics.krawczyk_tests << " Krawczyk tests, " << r.statistics.seconds << " s\n";
}

// solve_scene() with the chart propagation against without it
static void check_propagation(const std::string& name, const Loaded& l, std::size_t excluded)
{
  RI::Scene_solve_parameters on, off;
  off.chart_propagation = false;
  on.plan_over_charts = off.plan_over_charts = false;  // (each combination alone: the path the propagation filters)
  const RI::Scene_solve_result a = RI::solve_scene<IT, CGAL::Gmpq>(l.input, l.c, l.t, l.wf, on);
  const RI::Scene_solve_result b = RI::solve_scene<IT, CGAL::Gmpq>(l.input, l.c, l.t, l.wf, off);
  CHECK(a.complete() && b.complete(), name << ": not complete with or without the propagation");
  CHECK(a.statistics.excluded_by_propagation == excluded && b.statistics.excluded_by_propagation == 0,
        name << ": " << a.statistics.excluded_by_propagation << " combinations excluded by propagation, " << excluded << " expected");
  CHECK(a.statistics.chart_combinations + a.statistics.excluded_by_propagation == b.statistics.chart_combinations,
        name << ": " << a.statistics.chart_combinations << " systems built and " << a.statistics.excluded_by_propagation << " excluded, "
             << b.statistics.chart_combinations << " without the propagation");
  CHECK(a.configurations.size() == b.configurations.size(), name << ": " << a.configurations.size() << " configurations with the propagation, "
                                                                  << b.configurations.size() << " without");
  for (std::size_t i = 0; i < a.configurations.size() && i < b.configurations.size(); ++i) {
    double d = 0;
    const auto &p = a.configurations[i].configuration.points, &q = b.configurations[i].configuration.points;
    for (std::size_t k = 0; k < p.size() && k < q.size(); ++k)
      for (int x = 0; x < 3; ++x) d = (std::max)(d, std::abs(p[k][std::size_t(x)] - q[k][std::size_t(x)]));
    CHECK(d < 1e-9 && a.configurations[i].certified == b.configurations[i].certified && a.configurations[i].charts == b.configurations[i].charts,
          name << ": configuration " << i << " differs with the propagation (" << d << ")");
  }
  std::cout << name << ": " << a.configurations.size() << " configurations; " << a.statistics.excluded_by_propagation << " of "
            << b.statistics.chart_combinations << " chart combinations excluded by propagation\n";
}

// solve_scene() solving along the tree by a sweep (Scene_solve_parameters::sweep, from 2
// combinations on) against the expanded systems, combination by combination: the same
// configurations, point for point; and the sweep cut by a time limit says so
static void check_sweep_scene(const std::string& name, const Loaded& l)
{
  RI::Scene_solve_parameters on, off;
  on.sweep_from = 2;
  off.sweep = false;
  const RI::Scene_solve_result a = RI::solve_scene<IT, CGAL::Gmpq>(l.input, l.c, l.t, l.wf, on);
  const RI::Scene_solve_result b = RI::solve_scene<IT, CGAL::Gmpq>(l.input, l.c, l.t, l.wf, off);
  CHECK(a.statistics.swept && !b.statistics.swept, name << ": swept " << a.statistics.swept << " / " << b.statistics.swept);
  CHECK(a.complete() && b.complete(), name << ": not complete with or without the sweep");
  CHECK(a.configurations.size() == b.configurations.size(), name << ": " << a.configurations.size() << " configurations by the sweep, "
                                                                  << b.configurations.size() << " expanded");
  for (const auto& x : a.configurations) {
    CHECK(x.certified && x.max_relative_residual < 1e-12, name << ": a swept configuration not certified or with residual " << x.max_relative_residual);
    double best = 1e300;
    for (const auto& y : b.configurations) {
      double d = 0;
      const auto &p = x.configuration.points, &q = y.configuration.points;
      for (std::size_t k = 0; k < p.size() && k < q.size(); ++k)
        for (int c = 0; c < 3; ++c) d = (std::max)(d, std::abs(p[k][std::size_t(c)] - q[k][std::size_t(c)]));
      best = (std::min)(best, d);
    }
    CHECK(best < 1e-9, name << ": a swept configuration is " << best << " from every expanded one");
  }
  // a time limit too short for the sweep: the answer says so and is not complete
  RI::Scene_solve_parameters cut = on;
  cut.maximal_seconds = 1e-6;
  const RI::Scene_solve_result z = RI::solve_scene<IT, CGAL::Gmpq>(l.input, l.c, l.t, l.wf, cut);
  CHECK(!z.complete() && !z.limits.empty() && z.limits.front().find("solving along the tree") != std::string::npos,
        name << ": the sweep cut by a time limit: " << (z.limits.empty() ? std::string("no limit reported") : z.limits.front()));
  std::cout << name << ": " << a.configurations.size() << " configurations by the sweep (" << a.statistics.boxes << " boxes), as expanded\n";
}

// arc consistency against none: the same roots (root for root), every root inside the cells
// kept (the boxes printed)
static void check_consistency(const std::string& name, const Loaded& l, bool sweep)
{
  RI::Tree_system<Traits> S(l.c, l.t, l.wf);
  RI::Tree_solver_parameters on, off;
  on.sweep = off.sweep = sweep;
  off.consistency_cells = 0;
  const RI::Tree_solve_result a = RI::solve_tree_system(S, on), b = RI::solve_tree_system(S, off);
  const std::size_t n = S.number_of_variables();
  CHECK(a.complete() && b.complete(), name << ": not complete with or without arc consistency");
  CHECK(b.consistent_fraction.empty() && a.consistent_fraction.size() == n, name << ": " << a.consistent_fraction.size() << " fractions kept for "
                                                                                    << n << " hinges");
  double least = 1;
  for (double f : a.consistent_fraction) {
    CHECK(f > 0 && f <= 1, name << ": a fraction kept of " << f);
    least = (std::min)(least, f);
  }
  CHECK(least < 1, name << ": arc consistency kept every cell of every hinge");
  CHECK(a.roots.size() == b.roots.size(), name << ": " << a.roots.size() << " roots with arc consistency, " << b.roots.size() << " without");
  for (const auto& x : b.roots) {
    std::size_t seen = 0;
    for (const auto& y : a.roots) seen += x.charts == y.charts && shape_distance(x.approximation, y.approximation) < 1e-9;
    CHECK(seen == 1, name << ": a root without arc consistency found " << seen << " times with it");
  }
  // (fewer boxes is usual, not a property: the chain of 7 at 16 cells takes 791 against 771)
  // the cells kept hold every root (the domains computed again, as the solve does)
  CGAL::Protect_FPU_rounding<true> guard;
  const RI::internal::Tree_domains d = RI::internal::tree_domains(S, on.consistency_cells, {});
  for (const auto& x : b.roots)
    for (std::size_t v = 0; v < n; ++v) {
      IT e = x.enclosure[v];
      CHECK(d.clip(v, x.charts[v], e) && e.inf() == x.enclosure[v].inf() && e.sup() == x.enclosure[v].sup(),
            name << ": hinge " << v << " of a root, " << x.enclosure[v] << " in chart " << x.charts[v] << ", outside the cells kept");
    }
  std::cout << name << (sweep ? " (sweep)" : " (branch and prune)") << ": arc consistency keeps " << 100 * least
            << " % of a hinge's circle at least; " << a.statistics.boxes << " boxes against " << b.statistics.boxes << " (" << a.consistency_seconds
            << " s of it)\n";
}

// Tree_domains::clip by hand: cell borders belong to both cells
static void check_clip()
{
  RI::internal::Tree_domains d;
  d.cells = 8;  // cell i = [-1 + i/4, -1 + (i+1)/4]
  d.kept.assign(1, {std::vector<char>{0, 1, 1, 0, 0, 1, 0, 0}, std::vector<char>(8, 0)});
  struct Case { double lo, hi; bool kept; double klo, khi; };
  const Case cases[] = {
      {-1, 1, true, -0.75, 0.5},          // the hull of cells 1 to 5
      {-0.5, -0.25, true, -0.5, -0.25},   // cell 2 exactly
      {-0.25, 0.2, true, -0.25, -0.25},   // cells 3 and 4 dropped; -0.25 is also cell 2's
      {-0.25, 0.25, true, -0.25, 0.25},   // and 0.25 cell 5's
      {-0.2, 0.2, false, 0, 0},           // cells 3 and 4 only
      {0.25, 0.3, true, 0.25, 0.3},       // 0.25: cell 4's and cell 5's (kept)
      {0.5, 1, true, 0.5, 0.5},           // 0.5: cell 5's upper border
      {0.51, 1, false, 0, 0},             // cells 6 and 7
      {-1, -0.8, false, 0, 0},            // cell 0
      {-1, -0.75, true, -0.75, -0.75},    // -0.75: cell 1's lower border
  };
  for (const Case& c : cases) {
    IT x(c.lo, c.hi);
    const bool k = d.clip(0, 0, x);
    CHECK(k == c.kept && (!k || (x.inf() == c.klo && x.sup() == c.khi)),
          "clip of [" << c.lo << ", " << c.hi << "]: " << (k ? "kept " : "dropped ") << x << ", expected " << (c.kept ? "kept" : "dropped"));
  }
  IT x(-1, 1);
  CHECK(!d.clip(0, 1, x), "clip in chart 1 (no cell kept): kept");
  x = IT(-1, 1);
  CHECK(d.clip(0, -1, x) && x.inf() == -1 && x.sup() == 1, "clip of an open chart: changed");
  RI::internal::Tree_domains none;
  x = IT(-0.2, 0.2);
  CHECK(none.clip(0, 0, x) && x.inf() == -0.2 && x.sup() == 0.2, "clip without domains: changed");
}

// sweep orders of hand-made supports
static void check_sweep_orders()
{
  typedef std::vector<std::vector<std::size_t>> V;
  // a band (x0-x1, x1-x2, x2-x3) and one equation in all: x0 drives, the last is the check
  RI::Sweep_order o = RI::sweep_order(4, V{{0, 1}, {1, 2}, {2, 3}, {0, 1, 2, 3}});
  CHECK(o.exists(4) && o.driver == 0 && o.steps.size() == 3 && o.checks == std::vector<std::size_t>{3}, "band: no sweep order from x0");
  // triangular (x0 alone, then x0-x1): no driver
  o = RI::sweep_order(2, V{{0, 1}, {0}});
  CHECK(o.exists(2) && o.driver == RI::Sweep_order::none && o.steps.front().first == 1, "triangular: a driver where none is needed");
  // the band x0-x2-x1 listed out of order: from x0 (the lowest of equal cost), x2 then x1
  o = RI::sweep_order(3, V{{0, 1, 2}, {1, 2}, {0, 2}});
  CHECK(o.exists(3) && o.driver == 0 && o.steps.size() == 2 && o.steps[0].second == 2 && o.steps[1].second == 1,
        "band x0-x2-x1: driver " << o.driver);
  // two equations in the same three variables each, and a third: no order with one driver
  o = RI::sweep_order(3, V{{0, 1, 2}, {0, 1, 2}, {0, 1, 2}});
  CHECK(!o.exists(3), "three equations in three variables each: a sweep order");
}

int main()
{
  check_sweep_orders();
  check_clip();
  std::mt19937_64 rng(20261128);
  const std::string dir = RIGID_INCIDENCE_TEST_DATA_DIR;
  for (const std::string f : {"chain4.json", "chain5.json", "chain6.json", "ring7.json"}) check_evaluator(f, load(dir + "/" + f), rng);
  for (bool sweep : {true, false}) {
    check_solve("chain4.json", load(dir + "/chain4.json"), 6, sweep);
    check_solve("chain5.json", load(dir + "/chain5.json"), 2, sweep);
    check_solve("chain6.json", load(dir + "/chain6.json"), 2, sweep);
  }
  check_sweep_scene("chain4.json", load(dir + "/chain4.json"));
  check_sweep_scene("chain6.json", load(dir + "/chain6.json"));
  for (bool sweep : {true, false}) {
    check_consistency("chain5.json", load(dir + "/chain5.json"), sweep);
    check_consistency("chain6.json", load(dir + "/chain6.json"), sweep);
  }
  // the chain of 7: 64 chart combinations, swept by default (Scene_solve_parameters::
  // sweep_from), with arc consistency; the same configurations expanded, the planted one among
  // them
  {
    const Loaded l = load(dir + "/chain7.json");
    check_sweep_scene("chain7.json", l);
    const RI::Scene_solve_result r = RI::solve_scene<IT, CGAL::Gmpq>(l.input, l.c, l.t, l.wf, RI::Scene_solve_parameters());
    std::ifstream in(dir + "/chain7_planted.json");
    const nlohmann::json planted = nlohmann::json::parse(in);
    bool found = false;
    for (const auto& x : r.configurations) {
      double d = 0;
      for (const auto& p : planted.at("points").items())
        for (std::size_t k = 0; k < 3; ++k) d = (std::max)(d, std::abs(x.configuration.point(p.key())[k] - p.value()[k].get<double>()));
      found = found || d < 1e-6;
    }
    CHECK(r.statistics.swept && r.complete() && r.configurations.size() == 2 && found,
          "chain7.json: swept " << r.statistics.swept << ", complete " << r.complete() << ", " << r.configurations.size()
                                << " configurations (2 expected), the planted one among them: " << found);
    // the statistics say what arc consistency kept (one fraction per hinge), and nothing without it
    RI::Scene_solve_parameters none;
    none.consistency_cells = 0;
    const RI::Scene_solve_result z = RI::solve_scene<IT, CGAL::Gmpq>(l.input, l.c, l.t, l.wf, none);
    CHECK(r.statistics.consistent_fraction.size() == r.variables.size() && r.statistics.consistency_seconds > 0 &&
              z.statistics.consistent_fraction.empty() && z.configurations.size() == 2,
          "chain7.json: " << r.statistics.consistent_fraction.size() << " fractions kept for " << r.variables.size() << " hinges, "
                          << z.statistics.consistent_fraction.size() << " without arc consistency (" << z.configurations.size() << " configurations)");
  }
  // a cell count that is not a power of 2: refused, by solve_tree_system() and by solve_scene()
  // before any work (the chain of 4 is never swept: its expanded systems would be solved)
  {
    Loaded l = load(dir + "/chain4.json");
    RI::Tree_system<Traits> S(l.c, l.t, l.wf);
    for (std::size_t cells : {std::size_t(1), std::size_t(3), std::size_t(1) << 17}) {
      RI::Tree_solver_parameters P;
      P.consistency_cells = cells;
      bool thrown = false;
      try { RI::solve_tree_system(S, P); } catch (const RI::Input_error& e) { thrown = std::string(e.what()).find("consistency_cells") != std::string::npos; }
      CHECK(thrown, "consistency_cells = " << cells << ": no Input_error");
      RI::Scene_solve_parameters Q;
      Q.consistency_cells = cells;
      thrown = false;
      try { RI::solve_scene<IT, CGAL::Gmpq>(l.input, l.c, l.t, l.wf, Q); } catch (const RI::Input_error& e) {
        thrown = std::string(e.what()).find("solve_scene: consistency_cells") != std::string::npos;
      }
      CHECK(thrown, "solve_scene, consistency_cells = " << cells << ": no Input_error");
    }
  }
  // the bounds of arc consistency: an equation over the leaf cap is left out (a cap of 0 leaves
  // every equation out, so every cell is kept), a stop keeps every cell, and a solve whose time
  // limit falls in it is incomplete and says so
  {
    Loaded l = load(dir + "/chain7.json");
    RI::Tree_system<Traits> S(l.c, l.t, l.wf);
    CGAL::Protect_FPU_rounding<true> guard;
    const RI::internal::Tree_domains capped = RI::internal::tree_domains(S, 64, {}, 0);
    const RI::internal::Tree_domains usual = RI::internal::tree_domains(S, 64, {});
    const RI::internal::Tree_domains stopped = RI::internal::tree_domains(S, 64, [] { return true; });
    double least_capped = 1, least_usual = 1;
    for (std::size_t v = 0; v < S.number_of_variables(); ++v) {
      least_capped = (std::min)(least_capped, capped.fraction(v));
      least_usual = (std::min)(least_usual, usual.fraction(v));
    }
    CHECK(capped.cells == 64 && least_capped == 1 && least_usual < 1 && stopped.cells == 0,
          "chain7.json: leaf cap 0 keeps " << least_capped << " of a circle at least (1 expected), the usual cap " << least_usual
                                           << ", a stop gives " << stopped.cells << " cells (0: none)");
    RI::Scene_solve_parameters Q;
    Q.consistency_cells = 65536;
    Q.maximal_seconds = 1e-3;
    const RI::Scene_solve_result r = RI::solve_scene<IT, CGAL::Gmpq>(l.input, l.c, l.t, l.wf, Q);
    bool said = false;
    for (const auto& m : r.limits) said = said || m.find("time limit") != std::string::npos;
    CHECK(!r.complete() && said && r.statistics.consistent_fraction.empty(),
          "chain7.json, a time limit of 1 ms with 65536 cells: complete " << r.complete() << ", limit said " << said << ", "
                                                                          << r.statistics.consistent_fraction.size() << " fractions kept");
  }
  check_propagation("two_pairs_of_hinges.json", load(dir + "/two_pairs_of_hinges.json"), 7);
  check_propagation("chain4.json", load(dir + "/chain4.json"), 2);
  check_propagation("chain6.json", load(dir + "/chain6.json"), 26);
  // a box budget: the rest pending
  {
    Loaded l = load(dir + "/chain6.json");
    RI::Tree_system<Traits> S(l.c, l.t, l.wf);
    RI::Tree_solver_parameters P;
    P.maximal_boxes = 50;
    const RI::Tree_solve_result r = RI::solve_tree_system(S, P);
    CHECK(!r.complete() && r.stopped == "box budget exhausted" && r.statistics.boxes == 50, "a budget of 50 boxes: stopped '" << r.stopped << "' after "
                                                                                              << r.statistics.boxes);
    bool pending = !r.unresolved.empty();
    for (const auto& u : r.unresolved) pending = pending && u.kind == RI::Box_class::PENDING;
    CHECK(pending, "a budget of 50 boxes: the rest is not pending");
  }
  // the sweep's slices: the same answer with 1 and 2 threads (root for root, in order) and
  // the same roots as one uncut sweep; a cut sweep's pending boxes merged into regions
  {
    Loaded l = load(dir + "/chain6.json");
    RI::Tree_system<Traits> S(l.c, l.t, l.wf);
    RI::Tree_solver_parameters P1, P2, P0, P3, P4;
    P2.threads = 2;
    P0.sweep_slices = 1;
    P3.task_boxes = 7;  // many rounds of small tasks
    P4.task_boxes = 7;
    P4.threads = 2;
    const RI::Tree_solve_result r1 = RI::solve_tree_system(S, P1), r2 = RI::solve_tree_system(S, P2), r0 = RI::solve_tree_system(S, P0);
    const RI::Tree_solve_result r3 = RI::solve_tree_system(S, P3), r4 = RI::solve_tree_system(S, P4);
    CHECK(r1.complete() && r2.complete() && r0.complete() && r3.complete() && r4.complete(), "chain6 slices: not complete");
    for (const RI::Tree_solve_result* r : {&r2, &r3, &r4}) {
      bool same = r1.roots.size() == r->roots.size() && r1.statistics.boxes == r->statistics.boxes;
      for (std::size_t i = 0; same && i < r1.roots.size(); ++i)
        same = r1.roots[i].charts == r->roots[i].charts && r1.roots[i].approximation == r->roots[i].approximation;
      CHECK(same, "chain6 slices: 1 thread and " << (r == &r2 ? "2 threads" : r == &r3 ? "tasks of 7 boxes" : "tasks of 7 boxes on 2 threads")
                                                 << " differ (" << r1.roots.size() << " and " << r->roots.size() << " roots, " << r1.statistics.boxes
                                                 << " and " << r->statistics.boxes << " boxes)");
    }
    // a root on a slice border is kept once: each root of the uncut sweep once among the slices'
    CHECK(r0.roots.size() == r1.roots.size(), "chain6 slices: " << r1.roots.size() << " roots, uncut " << r0.roots.size());
    for (const auto& a : r0.roots) {
      std::size_t seen = 0;
      for (const auto& b : r1.roots) seen += a.charts == b.charts && shape_distance(a.approximation, b.approximation) < 1e-9;
      CHECK(seen == 1, "chain6 slices: a root of the uncut sweep found " << seen << " times");
    }
    // cut by a budget on 2 threads: exactly the budget, the rest pending in merged regions
    RI::Tree_solver_parameters Pc;
    Pc.maximal_boxes = 200;
    Pc.threads = 2;
    const RI::Tree_solve_result rc = RI::solve_tree_system(S, Pc);
    std::size_t in_regions = 0;
    for (const auto& u : rc.unresolved) in_regions += u.boxes;
    CHECK(!rc.complete() && rc.stopped == "box budget exhausted" && rc.statistics.boxes == 200,
          "chain6 cut at 200 boxes on 2 threads: stopped '" << rc.stopped << "' after " << rc.statistics.boxes);
    // (the halves of a split touch: a cut leaves fewer regions than pending boxes)
    CHECK(!rc.unresolved.empty() && rc.unresolved.size() < in_regions, "chain6 cut: " << rc.unresolved.size() << " regions of " << in_regions << " boxes");
    std::cout << "chain6 cut at 200 boxes: " << rc.roots.size() << " roots, " << rc.unresolved.size() << " regions of " << in_regions << " pending boxes\n";
    // (the regions cover the boxes: each root of the full solve is a root of the cut one or
    // lies in a region)
    for (const auto& a : r1.roots) {
      bool covered = false;
      for (const auto& b : rc.roots) covered = covered || (a.charts == b.charts && shape_distance(a.approximation, b.approximation) < 1e-9);
      for (const auto& u : rc.unresolved) {
        bool in = true;
        for (std::size_t i = 0; i < a.approximation.size() && in; ++i)
          in = (u.charts[i] == -1 || (u.charts[i] == a.charts[i] && u.box[i].first <= a.approximation[i] && a.approximation[i] <= u.box[i].second));
        covered = covered || in;
      }
      CHECK(covered, "chain6 cut: a root neither found nor in a pending region");
    }
    bool thrown = false;
    RI::Tree_solver_parameters Pb;
    Pb.sweep_slices = 3;
    try { RI::solve_tree_system(S, Pb); } catch (const RI::Input_error& e) { thrown = std::string(e.what()).find("power of 2") != std::string::npos; }
    CHECK(thrown, "sweep_slices = 3: no Input_error");
  }
  // not a tree of hinges: refused, the edge named
  {
    Loaded l = load(std::string(RIGID_INCIDENCE_DATA_DIR) + "/tetra.json");
    const std::string why = RI::Tree_system<Traits>::unsupported(l.c, l.t);
    CHECK(!why.empty(), "tetra.json: taken (implied bodies known by distances in its covering set)");
    bool thrown = false;
    try { RI::Tree_system<Traits> S(l.c, l.t, l.wf); } catch (const RI::Input_error& e) { thrown = std::string(e.what()).find(why) != std::string::npos; }
    CHECK(thrown, "tetra.json: no Input_error saying why (" << why << ")");
  }
  std::cout << checks << " checks, " << failures << " failures\n";
  return failures ? 1 : 0;
}
