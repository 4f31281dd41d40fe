// Copyright (c) 2026 Rigid_incidence contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Benchmark of solving along a solution plan (decomposition_subdivision_solver.txt, Algorithm
// 6: solve_with_plan) against solving the whole system at once (Subdivision_solver), with and
// without inequality constraints, side by side in one run:
//   1. the paper's parallelogram with a diagonal (Section 4, Fig. 4; 4 variables), without and
//      with its two inequalities (examples/Rigid_incidence/data/systems/);
//   2. random sparse block-triangular systems with planted roots (the generator of
//      test_solve_with_plan: blocks of 1 to 3 variables, each equation a product of affine forms
//      in its own block and at most three variables of the blocks before it, mixed within its
//      block; at most 6 equations of degree 2, the others of degree 1, so at most 64 roots) of
//      4 to 30 variables, and the same with one inequality x_0 >= c on the first block (c
//      splits its planted values in two), which the plan tests in the first block.
// The whole-system solve gets a time budget (CAP_SECONDS); what it leaves is pending, and the
// table says "> CAP". Every solve's roots are checked against the planted ones (count in the
// box). Written as PREFIX.md (Markdown, with the paper's Table 1 ratios beside ours), PREFIX.csv
// and PREFIX.svg (time against the number of variables, log scale).
//
// Usage: benchmark_plan [RESULTS_PREFIX (plan)] [SEEDS (2)] [CAP_SECONDS (10)] [MAX_VARIABLES (30)]

#include "benchmark_common.h"
#include "../../test/Rigid_incidence/planted_systems.h"

#include <CGAL/Rigid_incidence/IO/read_polynomial_system.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <string>
#include <vector>

using namespace planted_systems;
using benchmark_common::fixed;
using benchmark_common::fmt;
using benchmark_common::ratio_text;

struct Cell
{
  double seconds = 0;
  std::size_t boxes = 0, roots = 0;
  bool complete = false;
};

template <class F> static Cell timed(F f, int repeats)
{
  // the median of the repeats (a cell over 1 s is not repeated)
  std::vector<Cell> runs;
  for (int r = 0; r < repeats; ++r) {
    CGAL::Real_timer t;
    t.start();
    Cell c = f();
    c.seconds = t.time();
    runs.push_back(c);
    if (c.seconds > 1) break;
  }
  std::sort(runs.begin(), runs.end(), [](const Cell& a, const Cell& b) { return a.seconds < b.seconds; });
  return runs[runs.size() / 2];
}

static Cell plan_cell(const System& s, double cap, int repeats)
{
  RI::Solution_plan plan(s);
  RI::Subdivision_solver_parameters p;
  p.maximal_seconds = cap;
  return timed([&] {
    auto r = RI::solve_with_plan(s, plan, p);
    Cell c;
    c.boxes = r.boxes;
    c.roots = r.roots.size();
    c.complete = r.complete();
    return c;
  }, repeats);
}

static Cell whole_cell(const System& s, double cap, int repeats)
{
  RI::Subdivision_solver_parameters p;
  p.maximal_seconds = cap;
  p.maximal_boxes = std::size_t(-1);
  return timed([&] {
    auto r = RI::Subdivision_solver<>(p).solve(s);
    Cell c;
    c.boxes = r.statistics.boxes;
    c.roots = r.roots.size();
    c.complete = r.complete();
    return c;
  }, repeats);
}

struct Row
{
  std::string name;
  std::size_t n = 0, blocks = 0, largest = 0, expected = 0, expected_ineq = 0;
  Cell plan, whole, plan_ineq, whole_ineq;
};

// A random block-triangular planted system of n variables (see the header); false if the
// planted system is degenerate.
static bool random_system(Rng& rng, std::size_t n, Planted& p, Affine& g)
{
  std::vector<unsigned> degree(n, 1);
  for (int k = 0; k < 6 && k < int(n); ++k) degree[std::size_t(rng.uniform(0, long(n) - 1))] = 2;
  std::vector<std::vector<std::size_t>> members;
  std::vector<std::vector<Q>> A;
  const auto factors = block_triangular_factors(rng, degree, 3, members, A);
  if (!make_planted(factors, A, cube(n, -2, 2), p)) return false;
  // x_0 >= c, c between the planted values of x_0 in the box
  std::vector<Q> v;
  for (const auto& x : p.roots) if (in_box(x.x, p.system.box)) v.push_back(x.x[0]);
  if (v.size() < 2) return false;
  std::sort(v.begin(), v.end());
  const Q c = (v[v.size() / 2 - 1] + v[v.size() / 2]) / 2;
  if (c == v[v.size() / 2]) return false;  // equal values: no split
  g.c.assign(n, Q(0));
  g.c[0] = 1;
  g.c0 = -c;
  for (const auto& x : p.roots) if (g(x.x) == 0) return false;
  return true;
}

static std::size_t count_in_box(const Planted& p, const Affine* g)
{
  std::size_t k = 0;
  for (const auto& x : p.roots) if (in_box(x.x, p.system.box) && (!g || (*g)(x.x) > 0)) ++k;
  return k;
}

static std::string cell_time(const Cell& c, double cap)
{
  return c.complete ? fmt(c.seconds * 1e3, 3) : "> " + fixed(cap * 1e3, 0) + " (pending)";
}

int main(int argc, char** argv)
{
  const std::string prefix = argc > 1 ? argv[1] : "plan";
  const int seeds = argc > 2 ? std::atoi(argv[2]) : 2;
  const double cap = argc > 3 ? std::atof(argv[3]) : 10;
  const std::size_t max_n = argc > 4 ? std::size_t(std::atoi(argv[4])) : 30;
  const int repeats = 5;
  std::vector<Row> rows;

  // 1. the paper's parallelogram
  {
    const std::string dir = std::string(RIGID_INCIDENCE_DATA_DIR) + "/systems/";
    RI::Polynomial_system_file a = RI::read_polynomial_system(dir + "parallelogram.txt");
    RI::Polynomial_system_file b = RI::read_polynomial_system(dir + "parallelogram_ineq.txt");
    Row r;
    r.name = "parallelogram (paper Fig. 4)";
    r.n = a.system.number_of_variables();
    RI::Solution_plan plan(a.system);
    r.blocks = plan.blocks().size();
    r.largest = plan.largest_block();
    r.expected = 4;
    r.expected_ineq = 1;
    r.plan = plan_cell(a.system, cap, 50);
    r.whole = whole_cell(a.system, cap, 50);
    r.plan_ineq = plan_cell(b.system, cap, 50);
    r.whole_ineq = whole_cell(b.system, cap, 50);
    rows.push_back(r);
    std::cout << r.name << ": done\n";
  }

  // 2. random block-triangular systems
  const std::vector<std::size_t> sizes = {4, 6, 8, 10, 12, 16, 20, 24, 30};
  for (std::size_t n : sizes) {
    if (n > max_n) break;
    Rng rng(1000 + n);
    for (int s = 0; s < seeds; ++s) {
      Planted p;
      Affine g;
      int tries = 0;
      while (!random_system(rng, n, p, g) && ++tries < 50) {}
      if (tries >= 50) continue;
      Row r;
      r.name = "random n=" + std::to_string(n) + " #" + std::to_string(s);
      r.n = n;
      RI::Solution_plan plan(p.system);
      r.blocks = plan.blocks().size();
      r.largest = plan.largest_block();
      r.expected = count_in_box(p, nullptr);
      r.expected_ineq = count_in_box(p, &g);
      System q = p.system;
      q.inequalities.push_back(affine_poly(g));
      r.plan = plan_cell(p.system, cap, repeats);
      r.whole = whole_cell(p.system, cap, repeats);
      r.plan_ineq = plan_cell(q, cap, repeats);
      r.whole_ineq = whole_cell(q, cap, repeats);
      rows.push_back(r);
      std::cout << r.name << ": plan " << fmt(r.plan.seconds * 1e3) << " ms, whole " << (r.whole.complete ? "" : "> ")
                << fmt(r.whole.seconds * 1e3) << " ms\n";
    }
  }

  // the tables
  std::ofstream md(prefix + ".md"), csv(prefix + ".csv");
  md << "# Solving along a solution plan against solving the whole system\n\n"
     << "`" << benchmark_common::command_line(argc, argv) << "`, " << benchmark_common::utc_date() << ", "
     << benchmark_common::cpu_model() << ", " << benchmark_common::os_release() << ". Times in milliseconds (wall clock, median of up to "
     << repeats << " repeats; 50 for the parallelogram); the whole-system solve stops at " << cap << " s (then pending). "
     << "\"roots\" is found/expected (planted roots in the box [-2, 2]^n; with the inequality, those with x_0 > c). "
     << "Ratios: whole / plan.\n\n"
     << "| system | n | blocks | largest | roots | plan ms | whole ms | time ratio | box ratio | roots (ineq.) | plan ms (ineq.) | whole ms (ineq.) | time ratio (ineq.) | box ratio (ineq.) |\n"
     << "| :-- | --: | --: | --: | --: | --: | --: | --: | --: | --: | --: | --: | --: | --: |\n";
  csv << "system,n,blocks,largest,expected,plan_roots,plan_complete,plan_s,plan_boxes,whole_roots,whole_complete,whole_s,whole_boxes,"
         "expected_ineq,plan_ineq_roots,plan_ineq_s,plan_ineq_boxes,whole_ineq_roots,whole_ineq_complete,whole_ineq_s,whole_ineq_boxes\n";
  bool all_right = true;
  for (const auto& r : rows) {
    auto ratio = [](const Cell& w, const Cell& p, bool boxes) {
      double x = boxes ? double(w.boxes) / double((std::max)(p.boxes, std::size_t(1))) : w.seconds / (std::max)(p.seconds, 1e-9);
      return (w.complete ? "" : ">= ") + ratio_text(x);
    };
    auto roots = [](const Cell& c, std::size_t e) { return std::to_string(c.roots) + "/" + std::to_string(e); };
    if (r.plan.roots != r.expected || r.plan_ineq.roots != r.expected_ineq || !r.plan.complete || !r.plan_ineq.complete) all_right = false;
    if (r.whole.complete && r.whole.roots != r.expected) all_right = false;
    md << "| " << r.name << " | " << r.n << " | " << r.blocks << " | " << r.largest << " | " << roots(r.plan, r.expected) << " | "
       << fmt(r.plan.seconds * 1e3) << " | " << cell_time(r.whole, cap) << " | " << ratio(r.whole, r.plan, false) << " | "
       << ratio(r.whole, r.plan, true) << " | " << roots(r.plan_ineq, r.expected_ineq) << " | " << fmt(r.plan_ineq.seconds * 1e3) << " | "
       << cell_time(r.whole_ineq, cap) << " | " << ratio(r.whole_ineq, r.plan_ineq, false) << " | " << ratio(r.whole_ineq, r.plan_ineq, true)
       << " |\n";
    csv << r.name << "," << r.n << "," << r.blocks << "," << r.largest << "," << r.expected << "," << r.plan.roots << "," << r.plan.complete
        << "," << r.plan.seconds << "," << r.plan.boxes << "," << r.whole.roots << "," << r.whole.complete << "," << r.whole.seconds << ","
        << r.whole.boxes << "," << r.expected_ineq << "," << r.plan_ineq.roots << "," << r.plan_ineq.seconds << "," << r.plan_ineq.boxes << ","
        << r.whole_ineq.roots << "," << r.whole_ineq.complete << "," << r.whole_ineq.seconds << "," << r.whole_ineq.boxes << "\n";
  }
  std::ostringstream curves_md;
  // 3. curves: one-degree-of-freedom systems traced whole by trace_curves() and along their plan
  // by trace_curves_with_plan(), with and without the paper's inequalities; scenes that move and
  // a family
  {
    typedef RI::Rigid_incidence_traits<CGAL::Simple_cartesian<CGAL::Gmpq>> Traits;
    typedef CGAL::Interval_nt<false> IT;
    struct Curve_row { std::string name; Cell cell; std::size_t branches = 0; std::string note; };
    std::vector<Curve_row> curve_rows;
    const std::string dir = std::string(RIGID_INCIDENCE_DATA_DIR) + "/";
    auto trace = [&](const std::string& name, const std::string& file, std::size_t budget, bool along_plan) {
      RI::Polynomial_system_file f = RI::read_polynomial_system(dir + "systems/" + file);
      const RI::Solution_plan plan(f.system);
      Curve_row r;
      r.name = name + (along_plan ? ", along the plan" : ", whole system");
      std::size_t unresolved = 0, certified = 0;
      r.cell = timed([&] {
        RI::Curve_tracer_parameters p;
        p.maximal_boxes = budget;
        RI::Curve_result<IT> res = along_plan ? RI::trace_curves_with_plan<IT>(f.system, plan, p) : RI::trace_curves<IT>(f.system, p);
        Cell c;
        c.boxes = res.statistics.boxes;
        c.roots = res.curves.size();
        c.complete = res.complete();
        unresolved = res.unresolved.size();
        certified = 0;
        for (const auto& b : res.curves) certified += b.certified;
        return c;
      }, repeats);
      r.branches = r.cell.roots;
      r.note = std::to_string(certified) + " certified branch(es), " + std::to_string(unresolved) + " unresolved region(s)";
      if (!along_plan && r.cell.boxes >= budget) r.note += ": the " + std::to_string(budget) + " box budget ran out";
      curve_rows.push_back(r);
    };
    trace("4-bar linkage (paper Fig. 5)", "four_bar_linkage.txt", 200000, false);
    trace("4-bar linkage, with inequalities", "four_bar_linkage_ineq.txt", 200000, false);
    trace("Jansen's linkage (paper Fig. 6), 12 variables", "jansen.txt", 20000, false);
    trace("Jansen's linkage (paper Fig. 6), 12 variables", "jansen.txt", 200000, true);
    trace("Jansen's linkage, with inequalities", "jansen_ineq.txt", 20000, false);
    trace("Jansen's linkage, with inequalities", "jansen_ineq.txt", 200000, true);
    {
      RI::Scene scene = RI::read_scene(dir + "quad_one_dof.json");
      RI::Rigid_body_collection<Traits> input = RI::make_collection<Traits>(scene);
      Curve_row r;
      r.name = "scene quad_one_dof (solve_scene)";
      r.cell = timed([&] {
        RI::Rigid_body_collection<Traits> c = RI::standardize(input);
        RI::Incidence_tree t = RI::optimal_incidence_tree(c);
        RI::Well_formed_selection wf = RI::select_well_formed_incidences(c, t);
        RI::Scene_solve_result res = RI::solve_scene<IT, CGAL::Gmpq>(input, c, t, wf);
        Cell x;
        x.boxes = res.statistics.curve_boxes;
        x.roots = res.curves.size();
        x.complete = res.complete();
        return x;
      }, repeats);
      r.branches = r.cell.roots;
      curve_rows.push_back(r);
    }
    {
      RI::Scene scene = RI::read_scene(dir + "quad_family.json");
      RI::Rigid_body_collection<Traits> input = RI::make_collection<Traits>(scene);
      Curve_row r;
      r.name = "family quad_family (solve_family)";
      std::size_t folds = 0;
      r.cell = timed([&] {
        RI::Family_result res = RI::solve_family<IT>(input, scene.free_distance.a, scene.free_distance.b, scene.free_distance.lo, scene.free_distance.hi);
        Cell x;
        x.boxes = res.statistics.curve_boxes + res.statistics.fold_boxes;
        x.roots = res.branches.size();
        x.complete = res.complete();
        folds = res.folds.size();
        return x;
      }, repeats);
      r.branches = r.cell.roots;
      r.note = std::to_string(folds) + " certified folds (tracer and fold solver boxes together)";
      curve_rows.push_back(r);
    }
    curves_md << "\n## Curves\n\nOne degree of freedom: the whole system traced by `trace_curves()`, or along its plan by "
              << "`trace_curves_with_plan()` (the crank traced, the later blocks lifted over certified pieces of it; the four-bar is "
              << "traced whole: along its plan, the crank then the coupler point, the coupler folds at its collinear positions), scenes that move (`solve_scene()`) and a family (`solve_family()`). *boxes*: "
              << "tracer boxes, plus the block solver's boxes along a plan. Wall-clock ms, median of up to " << repeats
              << " repeats (a cell over 1 s runs once).\n\n| system | ms | boxes | branches | complete | note |\n| :-- | --: | --: | --: | :-- | :-- |\n";
    for (const auto& r : curve_rows) {
      curves_md << "| " << r.name << " | " << fmt(r.cell.seconds * 1e3) << " | " << r.cell.boxes << " | " << r.branches << " | "
                << (r.cell.complete ? "yes" : "no") << " | " << r.note << " |\n";
      std::cout << r.name << ": " << fmt(r.cell.seconds * 1e3) << " ms, " << r.cell.boxes << " boxes, " << r.branches << " branches\n";
    }
    if (curve_rows.size() >= 6 && curve_rows[1].cell.seconds > 0 && curve_rows[5].cell.seconds > 0)
      curves_md << "\nThe 4-bar linkage's inequalities speed its trace up " << fmt(curve_rows[0].cell.seconds / curve_rows[1].cell.seconds)
                << " times (boxes: " << fmt(double(curve_rows[0].cell.boxes) / double(std::max<std::size_t>(1, curve_rows[1].cell.boxes)))
                << " times fewer); the paper's Table 1 has 1.32 (decomposition) and 1.21 (decomposition with inequalities) for it. "
                << "Jansen's linkage: the whole-system tracer does not finish in " << curve_rows[2].cell.boxes << " boxes ("
                << fmt(curve_rows[2].cell.seconds * 1e3) << " ms) with or without the inequalities; along the plan the whole motion takes "
                << fmt(curve_rows[3].cell.seconds * 1e3) << " ms (" << (curve_rows[3].cell.complete ? "complete" : "not complete: its folds, where two "
                "assemblies meet and the motion turns back over the crank, are left as unresolved regions") << ") and the physical leg (with the "
                << "inequalities) " << fmt(curve_rows[5].cell.seconds * 1e3) << " ms, " << fmt(curve_rows[3].cell.seconds / curve_rows[5].cell.seconds)
                << " times faster; the paper's Table 1: 19,730 s without decomposition, 61.2 s with it, 2.7 s with the inequalities as well.\n";
  }
  md << "\nEvery plan solve found exactly the planted roots and was complete: " << (all_right ? "yes" : "**NO**") << ".\n\n"
     << "The paper's Table 1 (its own solver, with / without decomposition, speed-up): parallelogram (Fig. 4) 1.05, with "
     << "inequalities 1.13; 4-bar linkage (Fig. 5, a curve) 1.32, with inequalities 1.21; Jansen's linkage (Fig. 6) 322, with "
     << "inequalities 3530; Fig. 7 599; Fig. 8 24.5; Fig. 9 1.96. The curves (Fig. 5, 6) are in the Curves section below.\n\n"
     << "Plot: [" << prefix.substr(prefix.find_last_of('/') + 1) << ".svg](" << prefix.substr(prefix.find_last_of('/') + 1) << ".svg)\n";
  md << curves_md.str();

  // the plot: time (log) against n, four series
  {
    const int width = 760, height = 440, left = 70, top = 40, pw = 520, ph = 340;
    std::ofstream svg(prefix + ".svg");
    benchmark_common::svg_open(svg, width, height);
    svg << "<text x=\"" << left << "\" y=\"22\" font-size=\"14\" font-weight=\"bold\">Random block-triangular systems: solve time against variables</text>\n";
    const double lo = -1, hi = std::log10(cap * 1e3) + 0.3;  // log10 of ms
    auto X = [&](double n) { return left + pw * (n - 4) / (double(sizes.back()) - 4); };
    auto Y = [&](double ms) { double l = std::log10((std::max)(ms, 0.1)); return top + ph * (1 - (l - lo) / (hi - lo)); };
    svg << "<rect x=\"" << left << "\" y=\"" << top << "\" width=\"" << pw << "\" height=\"" << ph << "\" fill=\"none\" stroke=\"black\"/>\n";
    for (int e = int(std::ceil(lo)); e <= int(hi); ++e) {
      double y = Y(std::pow(10.0, e));
      svg << "<line x1=\"" << left << "\" y1=\"" << y << "\" x2=\"" << left + pw << "\" y2=\"" << y << "\" stroke=\"#eee\"/>"
          << "<text x=\"" << left - 6 << "\" y=\"" << y + 4 << "\" text-anchor=\"end\">" << fmt(std::pow(10.0, e)) << " ms</text>\n";
    }
    for (std::size_t n : sizes)
      svg << "<text x=\"" << X(double(n)) << "\" y=\"" << top + ph + 16 << "\" text-anchor=\"middle\">" << n << "</text>\n";
    svg << "<text x=\"" << left + pw / 2 << "\" y=\"" << top + ph + 34 << "\" text-anchor=\"middle\">variables</text>\n";
    struct Series { const char* label; const char* colour; Cell Row::*cell; };
    const Series series[] = {{"plan", "#1f77b4", &Row::plan}, {"whole system", "#d62728", &Row::whole},
                             {"plan, with inequality", "#2ca02c", &Row::plan_ineq}, {"whole, with inequality", "#ff7f0e", &Row::whole_ineq}};
    int legend = top + 10;
    for (const auto& se : series) {
      for (const auto& r : rows) {
        if (r.name.rfind("random", 0) != 0) continue;
        const Cell& c = r.*(se.cell);
        const double ms = c.complete ? c.seconds * 1e3 : cap * 1e3;
        svg << "<circle cx=\"" << X(double(r.n)) << "\" cy=\"" << Y(ms) << "\" r=\"3.5\" fill=\"" << (c.complete ? se.colour : "white")
            << "\" stroke=\"" << se.colour << "\"><title>" << r.name << ": " << se.label << " " << cell_time(c, cap) << " ms</title></circle>\n";
      }
      svg << "<circle cx=\"" << left + pw + 20 << "\" cy=\"" << legend << "\" r=\"4\" fill=\"" << se.colour << "\"/><text x=\"" << left + pw + 30
          << "\" y=\"" << legend + 4 << "\">" << se.label << "</text>\n";
      legend += 18;
    }
    svg << "<text x=\"" << left + pw + 14 << "\" y=\"" << legend + 8 << "\">open: stopped at the cap</text>\n</svg>\n";
  }
  std::cout << "wrote " << prefix << ".md, " << prefix << ".csv and " << prefix << ".svg\n";
  return all_right ? 0 : 1;
}
