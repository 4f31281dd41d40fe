// Copyright (c) 2026 Rigid_incidence contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// scene_solve_work(): the size of a solve, known before it runs (issue 28, item 5: "analyze and
// reduce state the structure and an estimate of the work"). Oracles:
// - the solve itself: the reduced systems solve_scene() builds and solves, plus the
//   combinations of placements it excludes at once, are the estimate, on the paper's scenes
//   and on scenes with several placements per body;
// - the scene's construction: two pairs of hinged bodies, each pair held together by two
//   distances, are 2 blocks of 2 variables and 2 independent parts, and their configurations
//   are the product of those of each pair solved alone; bar_end is a block of 3 and one of 1;
// - the charts counted by hand: 2 per hinge, 4 per free rotation.

#include <CGAL/Gmpq.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Rigid_incidence.h>
#include <CGAL/Rigid_incidence/IO/read_scene.h>

#include <fstream>
#include <iostream>
#include <sstream>
#include <string>

#include "test_check.h"
#include "solve_scene_instances.h"

namespace RI = CGAL::Rigid_incidence;
typedef RI::Rigid_incidence_traits<CGAL::Simple_cartesian<CGAL::Gmpq>> Traits;

struct Outcome
{
  RI::Scene_solve_work work;
  RI::Scene_solve_result result;
};

static Outcome solve(const RI::Scene& scene)
{
  Outcome o;
  RI::Rigid_body_collection<Traits> input = RI::make_collection<Traits>(scene);
  RI::Rigid_body_collection<Traits> c = RI::standardize(input);
  RI::Incidence_tree t = RI::optimal_incidence_tree(c);
  RI::Well_formed_selection wf = RI::select_well_formed_incidences(c, t);
  o.work = RI::scene_solve_work(c, t, wf);
  RI::Scene_solve_parameters p;
  p.maximal_coefficient_precision = 53;  // (one pass: a retry would solve some systems twice)
  if (RI::exact_coefficients(c, t)) o.result = RI::solve_scene<CGAL::Interval_nt<false>, CGAL::Gmpq>(input, c, t, wf, p);
  else o.result = RI::solve_scene<CGAL::Interval_nt<false>, CGAL::Interval_nt<false>>(input, c, t, wf, p);
  return o;
}

static RI::Scene read(const std::string& file)
{
  std::ifstream in(file);
  return RI::read_scene(in, file);
}

// the estimate against what the solve did
static void against_the_solve(const std::string& name, const Outcome& o)
{
  const auto& st = o.result.statistics;
  std::cout << name << ": " << RI::internal::describe_work(o.work) << "; the solve: " << st.chart_combinations << " systems, "
            << st.placements_excluded << " excluded at once, " << o.result.configurations.size() << " configurations\n";
  CHECK(o.result.precision_history.empty(), name << ": solved in one pass");
  CHECK(st.chart_combinations + st.placements_excluded == o.work.systems(),
        name << ": the solve built " << st.chart_combinations << " systems and excluded " << st.placements_excluded
             << ", the estimate says " << o.work.systems());
  CHECK(o.work.variables == o.result.variables.size() && o.work.equations == o.result.equations,
        name << ": the reduced system's size");
  std::size_t in_blocks = 0;
  for (std::size_t b : o.work.block_sizes) in_blocks += b;
  CHECK(in_blocks == o.work.variables, name << ": the blocks hold every variable once");
  CHECK((o.work.variables == 0 ? o.work.independent_parts == 0 : o.work.independent_parts >= 1) &&
            o.work.independent_parts <= o.work.block_sizes.size(),
        name << ": an independent part is one block or more");
}

int main()
{
  const std::string d = RIGID_INCIDENCE_DATA_DIR;
  // the paper's scenes: 3 hinges (2 charts each), one block of 3 (their equations couple all)
  for (const char* f : {"tetra", "tetra_i", "quad", "quad_distinct", "pent", "flat_hinges"}) {
    const Outcome o = solve(read(d + "/" + f + ".json"));
    against_the_solve(f, o);
    if (std::string(f) == "tetra") {
      CHECK(o.work.chart_combinations == 8 && o.work.placement_combinations == 1 && o.work.systems() == 8,
            "tetra: 2 charts for each of its 3 hinges, one placement each");
      CHECK(o.work.block_sizes == std::vector<std::size_t>{3} && o.work.independent_parts == 1, "tetra: one block of 3");
    }
  }
  // a body with several placements: the quad of Section 6 has implied bodies with 2 placements
  {
    const Outcome o = solve(read(d + "/quad.json"));
    std::size_t product = 1;
    for (const auto& p : o.work.placements) {
      CHECK(p.second > 1, "quad: a listed body has more than one placement");
      product *= p.second;
    }
    CHECK(product == o.work.placement_combinations, "quad: the placement combinations are the product of the bodies' placements");
  }
  // two parts no equation links, each a pair of hinged bodies held to each other by two
  // distances (between moving points: the standardization finds no implied body): 2 blocks of
  // 2 variables, 2 parts, and the whole scene's configurations are the product of the parts'
  {
    const RI::Scene scene = read(std::string(RIGID_INCIDENCE_TEST_DATA_DIR) + "/two_pairs_of_hinges.json");
    const Outcome o = solve(scene);
    against_the_solve("two parts", o);
    CHECK(o.work.block_sizes == (std::vector<std::size_t>{2, 2}) && o.work.independent_parts == 2,
          "two parts: 2 blocks of 2 variables, 2 independent parts");
    CHECK(o.work.chart_combinations == 16, "two parts: 2 charts for each of 4 hinges");
    // each part alone (the frame body and its two hinged bodies, their two distances)
    std::size_t product = 1;
    for (int part = 0; part < 2; ++part) {
      RI::Scene p = scene;
      p.bodies = {scene.bodies[0], scene.bodies[std::size_t(1 + 2 * part)], scene.bodies[std::size_t(2 + 2 * part)]};
      p.distances = {scene.distances[std::size_t(2 * part)], scene.distances[std::size_t(2 * part + 1)]};
      const Outcome q = solve(p);
      CHECK(q.result.complete() && q.work.independent_parts == 1, "part " << part << ": complete, one part");
      product *= q.result.configurations.size();
    }
    CHECK(o.result.complete() && o.result.configurations.size() == product && product > 1,
          "two parts: " << o.result.configurations.size() << " configurations, the product of the parts' is " << product);
  }
  // blocks solved in order: bar_end (2 equations in 4 variables) is a block of 3 and one of 1
  {
    const RI::Scene scene = read(d + "/bar_end.json");
    RI::Rigid_body_collection<Traits> c = RI::standardize(RI::make_collection<Traits>(scene));
    RI::Incidence_tree t = RI::optimal_incidence_tree(c);
    RI::Well_formed_selection wf = RI::select_well_formed_incidences(c, t);
    const RI::Scene_solve_work w = RI::scene_solve_work(c, t, wf);
    CHECK(w.variables == 4 && w.equations == 2 && w.block_sizes == (std::vector<std::size_t>{3, 1}) && w.independent_parts == 1,
          "bar_end: " << RI::internal::describe_work(w));
  }
  if (failures) { std::cerr << failures << " failure(s)\n"; return 1; }
  std::cout << "all scene_solve_work checks passed\n";
  return 0;
}
