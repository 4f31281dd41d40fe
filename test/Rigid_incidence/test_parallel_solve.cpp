// Copyright (c) 2026 Rigid_incidence contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The parallel solve (Subdivision_solver_parameters::threads, oneTBB; issue 28, item 4): "the
// same answer in the same order with any number of threads". The oracle is the sequential
// solve of the same scene: with 2 and 3 threads, solve_scene() must give the same
// configurations in the same order (parameter enclosures bound for bound, charts, placements,
// certified and singular flags, every point's coordinates), the same unresolved regions, curves,
// diagnosis, limits, and the same statistics but the seconds; and `threads` must say how many
// ran. The scenes reach each parallel path:
// - each chart combination alone (tetra, pent, quad with placements, a chain of 6 tetrahedra,
//   a ring of 7, the Stewart-Gough platform's free rotation, the one-dof quad with curves);
// - the plan over the charts, whose branches (a block's charts and roots) are forked
//   (data/plan_three_blocks.json, two pairs of hinges, a tree of 7 bodies);
// - placements built on worker threads (a molecular ring of 10 atoms, a strip of 8 triangles);
// - the precision retry at more bits (CGAL::Gmpfi coefficients, whose default precision is per
//   thread): tetra_i_tangent.
// Without oneTBB the threads are 1 and the test says so (it still compares the runs).
// Usage: test_parallel_solve [scene.json ...] (default: the list above)

#include <CGAL/Gmpq.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Rigid_incidence.h>
#include <CGAL/Rigid_incidence/IO/read_scene.h>

#include <algorithm>
#include <fstream>
#include <regex>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include "test_check.h"
#include "solve_scene_instances.h"

namespace RI = CGAL::Rigid_incidence;
typedef RI::Rigid_incidence_traits<CGAL::Simple_cartesian<CGAL::Gmpq>> Traits;

static RI::Scene_solve_result solve(const std::string& file, unsigned threads)
{
  std::ifstream in(file);
  const RI::Scene scene = RI::read_scene(in, file);
  RI::Rigid_body_collection<Traits> input = RI::make_collection<Traits>(scene);
  RI::Rigid_body_collection<Traits> c = RI::standardize(input);
  RI::Incidence_tree t = RI::optimal_incidence_tree(c);
  RI::Well_formed_selection wf = RI::select_well_formed_incidences(c, t);
  RI::Scene_solve_parameters p;
  p.solver.threads = threads;
  for (const auto& q : scene.inequalities) {
    RI::Orientation_inequality g;
    for (std::size_t k = 0; k < 4; ++k) g.points[k] = q.points[k];
    g.negative = q.negative;
    p.inequalities.push_back(g);
  }
  if (RI::exact_coefficients(c, t)) return RI::solve_scene<CGAL::Interval_nt<false>, CGAL::Gmpq>(input, c, t, wf, p);
  return RI::solve_scene<CGAL::Interval_nt<false>, CGAL::Interval_nt<false>>(input, c, t, wf, p);
}

// everything but the seconds, as text: two results are the same if their texts are
static std::string text(const RI::Scene_solve_result& r)
{
  std::ostringstream o;
  o.precision(17);
  auto configuration = [&](const RI::Configuration& x) {
    for (const auto& p : x.points) o << " (" << p[0] << " " << p[1] << " " << p[2] << ")";
  };
  auto ints = [&](const std::vector<int>& v) { for (int x : v) o << " " << x; };
  o << "complete " << r.complete() << " diagnosis " << r.diagnosis << " no_configuration " << r.no_configuration << "\n";
  for (const auto& l : r.limits) o << "limit " << l << "\n";
  for (const auto& x : r.configurations) {
    o << "configuration certified " << x.certified << " singular " << x.singular << " " << x.singular_reason << " border "
      << x.on_chart_border << " found " << x.found << " charts";
    ints(x.charts);
    o << " placements";
    ints(x.placements);
    o << " parameters";
    for (const auto& e : x.parameters) o << " [" << e.first << ", " << e.second << "]";
    o << " residual " << x.max_residual << " points";
    configuration(x.configuration);
    o << "\n";
  }
  for (const auto& u : r.unresolved) {
    o << "unresolved " << int(u.kind) << " " << u.reason << " boxes " << u.boxes << " charts";
    ints(u.charts);
    o << " placements";
    ints(u.placements);
    for (const auto& e : u.box) o << " [" << e.first << ", " << e.second << "]";
    o << "\n";
  }
  for (const auto& c : r.curves) {
    o << "curve certified " << c.certified << " closed " << c.closed << " frames " << c.configurations.size();
    for (const auto& x : c.configurations) configuration(x);
    o << "\n";
  }
  const auto& st = r.statistics;
  o << "statistics " << st.chart_combinations << " " << st.excluded_at_once << " " << st.boxes << " " << st.krawczyk_tests << " "
    << st.roots << " " << st.duplicates << " " << st.spurious << " " << st.curve_boxes << " " << st.placements_excluded << " "
    << st.planned_systems << " " << st.block_solves << " " << st.excluded_by_plan << " " << st.coefficient_width << "\n";
  // (each pass says its seconds: left out)
  for (const auto& h : r.precision_history) o << "pass " << std::regex_replace(h, std::regex(", [0-9.e+-]+ s\\)"), ")") << "\n";
  return o.str();
}

int main(int argc, char** argv)
{
  std::vector<std::string> files;
  for (int i = 1; i < argc; ++i) files.push_back(argv[i]);
  if (files.empty()) {
    const std::string d = RIGID_INCIDENCE_DATA_DIR, t = RIGID_INCIDENCE_TEST_DATA_DIR;
    for (const char* f : {"tetra", "pent", "quad", "stewart_gough40", "quad_one_dof", "tetra_i_tangent"}) files.push_back(d + "/" + f + ".json");
    for (const char* f : {"plan_three_blocks", "two_pairs_of_hinges", "chain6", "ring7", "tree7", "molecule10", "strip8"})
      files.push_back(t + "/" + f + ".json");
  }
  std::cout << "test_parallel_solve: oneTBB " << (RI::internal::parallel_available() ? "on" : "off (every run sequential)") << ", "
            << RI::internal::worker_threads(0) << " cores\n";
  for (const std::string& f : files) {
    const RI::Scene_solve_result one = solve(f, 1);
    const std::string expected = text(one);
    CHECK(one.statistics.threads == 1, f << ": one thread asked, " << one.statistics.threads << " said");
    for (unsigned n : {2u, 3u}) {
      const RI::Scene_solve_result many = solve(f, n);
      const std::string got = text(many);
      CHECK(many.statistics.threads == (std::min)(n, RI::internal::worker_threads(0)),
            f << ": " << n << " threads asked, " << many.statistics.threads << " said");
      if (got != expected) {
        // the first line that differs
        std::istringstream a(expected), b(got);
        std::string la, lb;
        while (std::getline(a, la) && std::getline(b, lb) && la == lb) {}
        CHECK(false, f << " with " << n << " threads: not what one thread gives; one thread:\n  " << la << "\n" << n << " threads:\n  " << lb);
      } else {
        CHECK(true, "");
      }
    }
    std::cout << f << ": " << one.configurations.size() << " configurations, " << one.curves.size() << " curves, "
              << one.statistics.chart_combinations << " systems, " << one.statistics.block_solves << " block solves"
              << (one.complete() ? ", complete" : ", not complete") << "; the same with 2 and 3 threads\n";
  }
  std::cout << checks << " checks, " << failures << " failures\n";
  return failures == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
