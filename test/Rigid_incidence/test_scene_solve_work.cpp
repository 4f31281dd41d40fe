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
// And the solve along the solution plan (Scene_solve_parameters::solve_with_plan, issue 28,
// items 1 and 6), against the whole solve (the oracle) and planted configurations:
// - two pairs of hinges: the same configurations block after block as whole, every system
//   solved along its plan; tetra (one block): never;
// - three blocks of hinges (data/plan_three_blocks.json): the plan over the charts (each block
//   choosing its own hinges' charts), each chart combination along its plan alone, and whole:
//   the same configurations, fewer block solves over the charts;
// - two stacked Stewart-Gough platforms (data/platforms2.json, scripts/make_scene_family.py
//   platforms 2): 2 blocks of 6 variables where the whole system of 12 is beyond the dense
//   arrays (the whole solve refuses it): complete, every configuration certified and holding
//   in the scene, the planted one among them, its enclosures within the tolerance (the whole
//   system's sparse Krawczyk test);
// - the same with a time limit of 0.3 s or an interrupt already set: not complete, and what
//   it holds is among the full answer; the limit counts no combination solved (the plan over
//   the charts was cut inside).
// And the placements of a merged rigid part (a strip of 12 triangles): 2048, pairwise
// distinct by a brute-force scan.

#include <CGAL/Gmpq.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Rigid_incidence.h>
#include <CGAL/Rigid_incidence/IO/read_scene.h>

#include <nlohmann/json.hpp>

#include <atomic>
#include <cmath>
#include <fstream>
#include <functional>
#include <iostream>
#include <array>
#include <map>
#include <set>
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

static Outcome solve(const RI::Scene& scene, bool plan = true, double seconds = 0, const std::atomic<bool>* interrupt = nullptr,
                     bool over_charts = true, bool propagation = true,
                     const std::function<void(RI::Scene_solve_parameters&)>& adjust = nullptr)
{
  Outcome o;
  RI::Rigid_body_collection<Traits> input = RI::make_collection<Traits>(scene);
  RI::Rigid_body_collection<Traits> c = RI::standardize(input);
  RI::Incidence_tree t = RI::optimal_incidence_tree(c);
  RI::Well_formed_selection wf = RI::select_well_formed_incidences(c, t);
  o.work = RI::scene_solve_work(c, t, wf);
  RI::Scene_solve_parameters p;
  p.maximal_coefficient_precision = 53;  // (one pass: a retry would solve some systems twice)
  p.solve_with_plan = plan;
  p.plan_over_charts = over_charts;
  p.chart_propagation = propagation;
  p.maximal_seconds = seconds;
  p.interrupt = interrupt;
  if (adjust) adjust(p);
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
  CHECK(st.chart_combinations + st.placements_excluded + st.excluded_by_propagation == o.work.systems(),
        name << ": the solve built " << st.chart_combinations << " systems and excluded " << st.placements_excluded << " + "
             << st.excluded_by_propagation
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

// the largest coordinate difference between two configurations' points
static double distance(const RI::Configuration& a, const RI::Configuration& b, const std::vector<std::string>& labels)
{
  double d = 0;
  for (const auto& l : labels)
    for (std::size_t k = 0; k < 3; ++k) d = (std::max)(d, std::abs(a.point(l)[k] - b.point(l)[k]));
  return d;
}

// the planted points a scene generator wrote ({"points": {label: [x, y, z]}})
static std::map<std::string, std::array<double, 3>> read_planted(const std::string& file)
{
  std::map<std::string, std::array<double, 3>> planted;
  std::ifstream in(file);
  const nlohmann::json j = nlohmann::json::parse(in);
  for (const auto& e : j.at("points").items()) planted[e.key()] = {e.value()[0].get<double>(), e.value()[1].get<double>(), e.value()[2].get<double>()};
  return planted;
}

static std::vector<std::string> point_labels(const RI::Scene& s)
{
  std::set<std::string> l;
  for (const auto& b : s.bodies)
    for (const auto& p : b.points) l.insert(p.label);
  return std::vector<std::string>(l.begin(), l.end());
}

// is each configuration of `part` one of `full`'s?
static bool among(const RI::Scene_solve_result& part, const RI::Scene_solve_result& full, const std::vector<std::string>& labels)
{
  for (const auto& x : part.configurations) {
    bool found = false;
    for (const auto& y : full.configurations) found = found || distance(x.configuration, y.configuration, labels) < 1e-7;
    if (!found) return false;
  }
  return true;
}

static void along_the_plan()
{
  const std::string td = RIGID_INCIDENCE_TEST_DATA_DIR;
  {
    const RI::Scene scene = read(td + "/two_pairs_of_hinges.json");
    const Outcome planned = solve(scene), whole = solve(scene, false);
    const auto labels = point_labels(scene);
    std::cout << "two parts along the plan: " << planned.result.configurations.size() << " configurations, "
              << planned.result.statistics.planned_systems << " of " << planned.result.statistics.chart_combinations << " systems planned, "
              << planned.result.statistics.block_solves << " block solves; whole: " << whole.result.configurations.size() << "\n";
    CHECK(planned.result.complete() && whole.result.complete(), "two parts: complete both ways");
    CHECK(planned.result.statistics.planned_systems == planned.result.statistics.chart_combinations &&
              planned.result.statistics.planned_systems > 0 && whole.result.statistics.planned_systems == 0,
          "two parts: every system solved along its plan (2 blocks), none with solve_with_plan = false");
    CHECK(planned.result.configurations.size() == whole.result.configurations.size() && among(planned.result, whole.result, labels) &&
              among(whole.result, planned.result, labels),
          "two parts: the same configurations along the plan as whole");
  }
  {
    // three blocks of hinges (scene 23 of test_random_planted_scenes, seed 20261127, which the
    // plan once solved to 0 configurations): over the charts, each combination alone along
    // its plan, and whole, the same configurations
    const RI::Scene scene = read(td + "/plan_three_blocks.json");
    const Outcome charted = solve(scene), alone = solve(scene, true, 0, nullptr, false, false), whole = solve(scene, false);
    const auto labels = point_labels(scene);
    const auto& a = charted.result.statistics;
    const auto& b = alone.result.statistics;
    std::cout << "three blocks: over the charts " << charted.result.configurations.size() << " configurations, " << a.block_solves
              << " block solves, " << a.excluded_by_plan << " of " << a.chart_combinations << " combinations excluded by a block; each alone "
              << alone.result.configurations.size() << ", " << b.block_solves << " block solves; whole " << whole.result.configurations.size()
              << "\n";
    CHECK(charted.result.complete() && alone.result.complete() && whole.result.complete(), "three blocks: complete three ways");
    CHECK(!whole.result.configurations.empty(), "three blocks: configurations");
    CHECK(charted.result.configurations.size() == whole.result.configurations.size() && among(charted.result, whole.result, labels) &&
              among(whole.result, charted.result, labels),
          "three blocks: the same configurations over the charts as whole");
    CHECK(alone.result.configurations.size() == whole.result.configurations.size() && among(alone.result, whole.result, labels),
          "three blocks: the same configurations along each combination's plan as whole");
    CHECK(a.block_solves < b.block_solves && a.excluded_by_plan > 0 && a.chart_combinations == b.chart_combinations &&
              a.planned_systems == a.chart_combinations,
          "three blocks: over the charts, fewer block solves (" << a.block_solves << " against " << b.block_solves
                                                                 << ") and combinations excluded by a block");
  }
  {
    const Outcome o = solve(read(std::string(RIGID_INCIDENCE_DATA_DIR) + "/tetra.json"));
    CHECK(o.result.statistics.planned_systems == 0 && o.result.complete() && o.result.configurations.size() == 4,
          "tetra: one block, solved whole");
  }
  const RI::Scene platforms = read(td + "/platforms2.json");
  const auto labels = point_labels(platforms);
  const auto planted = read_planted(td + "/platforms2_planted.json");
  const Outcome full = solve(platforms);
  {
    const auto& r = full.result;
    bool planted_found = false, certified = true, holds = true;
    double widest = 0;  // the parameters' enclosures
    for (const auto& x : r.configurations) {
      double d = 0;
      for (const auto& p : planted)
        for (std::size_t k = 0; k < 3; ++k) d = (std::max)(d, std::abs(x.configuration.point(p.first)[k] - p.second[k]));
      planted_found = planted_found || d < 1e-6;
      certified = certified && x.certified;
      holds = holds && x.max_relative_residual < 1e-9;
      for (const auto& e : x.parameters) widest = (std::max)(widest, e.second - e.first);
    }
    std::cout << "two stacked platforms: " << RI::internal::describe_work(full.work) << "; " << r.configurations.size()
              << " configurations, " << (r.complete() ? "complete" : "NOT complete") << ", " << r.statistics.planned_systems << " of "
              << r.statistics.chart_combinations << " systems planned, " << r.statistics.block_solves << " block solves, "
              << r.statistics.boxes << " boxes\n";
    for (const auto& l : r.limits) std::cout << "  limit: " << l << "\n";
    CHECK(full.work.block_sizes == (std::vector<std::size_t>{6, 6}), "two platforms: 2 blocks of 6 variables");
    CHECK(r.complete() && certified && holds && planted_found,
          "two platforms: complete (" << r.complete() << "), every configuration certified (" << certified << ") and holding ("
                                      << holds << "), the planted one among them (" << planted_found << ")");
    CHECK(r.statistics.planned_systems == r.statistics.chart_combinations, "two platforms: every system solved along its plan");
    // the whole system's dense Krawczyk test cannot run (its arrays): the roots are tightened
    // by the sparse one, in double and then in MPFR, down to the solver's tolerance (the chain
    // of blocks alone left them 2e-9 wide)
    const double tolerance = RI::Scene_solve_parameters().solver.tolerance;
    std::cout << "  widest parameter enclosure " << widest << " (tolerance " << tolerance << ")\n";
#ifdef CGAL_USE_MPFI
    CHECK(widest <= tolerance, "two platforms: parameter enclosures " << widest << " wide, above the tolerance " << tolerance);
#else
    CHECK(widest < 1e-7, "two platforms: parameter enclosures " << widest << " wide");
#endif
  }
  {
    // the optimal tree is the path of plates (the second criterion, distance paths): each
    // plate's legs involve its own 6 variables, two independent parts, each solved once per
    // chart of its own rotation (4 + 4 block solves, the second part's roots reused on every
    // branch of the first's)
    CHECK(full.work.independent_parts == 2, "two platforms: " << full.work.independent_parts << " independent parts, expected 2");
    CHECK(full.result.statistics.block_solves == 8 && full.result.parts.size() == 2,
          "two platforms: " << full.result.statistics.block_solves << " block solves, " << full.result.parts.size()
                            << " parts; expected 8 and 2 (a factored answer)");
    // the factored answer against the plan over every chart assignment listed (the oracle:
    // each full assignment's roots, merged across charts): the same configurations, the
    // count the product of the parts' counts, each part's bodies one plate
    const Outcome listed = solve(platforms, true, 0, nullptr, true, true, [](RI::Scene_solve_parameters& p) { p.factor_parts = false; });
    const auto& f = full.result;
    CGAL::Gmpz product = 1;
    for (const auto& q : f.parts) product *= CGAL::Gmpz(long(q.solutions.size()));
    std::cout << "two platforms factored: " << f.parts[0].solutions.size() << " x " << f.parts[1].solutions.size() << " = " << f.configuration_count
              << "; listed from every chart assignment: " << listed.result.configurations.size() << " (" << listed.result.statistics.block_solves
              << " block solves, " << listed.result.statistics.block_solves_reused << " reused)\n";
    CHECK(listed.result.parts.empty() && listed.result.complete() && listed.result.statistics.block_solves_reused > 0,
          "two platforms, not factored: no parts, complete, the second plate's solves reused");
    CHECK(f.configuration_count == product && f.configuration_count == CGAL::Gmpz(long(f.configurations.size())) &&
              f.configurations.size() == listed.result.configurations.size() && among(f, listed.result, labels) &&
              among(listed.result, f, labels) && f.listing.empty(),
          "two platforms: the factored answer (" << f.configuration_count << ", " << f.configurations.size()
                                                 << " listed) is the listed one (" << listed.result.configurations.size() << ")");
    CHECK(f.parts[0].bodies.size() == 1 && f.parts[1].bodies.size() == 1 && f.parts[0].bodies != f.parts[1].bodies &&
              f.parts[0].variables.size() == 6 && f.parts[1].variables.size() == 6,
          "two platforms: each part one plate's edge, 6 variables");
    // the list cut at 5: the count exact, the answer still complete, the listing says so
    const Outcome five = solve(platforms, true, 0, nullptr, true, true, [](RI::Scene_solve_parameters& p) { p.maximal_listed_configurations = 5; });
    std::cout << "  at most 5 listed: " << five.result.listing << "\n";
    CHECK(five.result.configurations.size() == 5 && five.result.configuration_count == f.configuration_count && five.result.complete() &&
              !five.result.listing.empty() && among(five.result, f, labels),
          "two platforms, 5 listed: " << five.result.configurations.size() << " listed of " << five.result.configuration_count);
    // a part solution that is not certified, listed in no product, or a dropped configuration
    // that is not certified: the answer is not complete
    {
      RI::Scene_solve_result x = five.result;
      CHECK(x.complete(), "two platforms, 5 listed: complete");
      x.parts.back().solutions.back().certified = false;
      CHECK(!x.complete(), "a part solution not certified, in no listed product: complete() says not complete");
      RI::Scene_solve_result y = five.result;
      y.unlisted_not_certified = 1;
      CHECK(!y.complete(), "a configuration not listed and not certified: complete() says not complete");
    }
    // the same cut where the answer is not factored: the first five found, the count exact
    const Outcome five_listed = solve(platforms, true, 0, nullptr, true, true, [](RI::Scene_solve_parameters& p) {
      p.maximal_listed_configurations = 5;
      p.factor_parts = false;
    });
    CHECK(five_listed.result.configurations.size() == 5 && five_listed.result.configuration_count == f.configuration_count &&
              five_listed.result.complete() && !five_listed.result.listing.empty(),
          "two platforms, not factored, 5 listed: " << five_listed.result.configurations.size() << " of " << five_listed.result.configuration_count);
    // the paper's criterion alone (depth sum) takes the star on plate 0, where the legs between
    // plates 1 and 2 are equations in both plates' variables: one part, and the whole system of
    // 12 variables is refused for its dense arrays (what the plan avoids)
    RI::Rigid_body_collection<Traits> c = RI::standardize(RI::make_collection<Traits>(platforms));
    const RI::Incidence_tree star = RI::make_incidence_tree(c, 0, {{0, 1}, {0, 2}});
    const RI::Well_formed_selection wf = RI::select_well_formed_incidences(c, star);
    CHECK(RI::scene_solve_work(c, star, wf).independent_parts == 1, "two platforms, star: one part");
    bool refused = false;
    RI::Scene_solve_parameters p;
    p.solve_with_plan = false;
    try {
      RI::solve_scene<CGAL::Interval_nt<false>, CGAL::Gmpq>(RI::make_collection<Traits>(platforms), c, star, wf, p);
    } catch (const std::exception& e) {
      refused = std::string(e.what()).find("dense") != std::string::npos;
    }
    CHECK(refused, "two platforms, star tree, whole: refused for its dense arrays (what the plan avoids)");
  }
  {
    const Outcome cut = solve(platforms, true, 0.3);
    std::cout << "two platforms in 0.3 s: " << cut.result.configurations.size() << " configurations, "
              << (cut.result.complete() ? "complete" : "not complete") << "\n";
    CHECK(!cut.result.complete() && !cut.result.limits.empty() && among(cut.result, full.result, labels),
          "two platforms in 0.3 s: not complete, says why, holds only configurations of the full answer");
    // the plan over the charts (all 16 combinations in one) cut inside: none counted solved
    // (it once said "16 of 16 combinations solved" with its blocks pending)
    bool counted = false;
    for (const auto& l : cut.result.limits) {
      std::cout << "  limit: " << l << "\n";
      counted = counted || (l.find("0 of 16 combinations") != std::string::npos && l.find("over the charts") != std::string::npos);
    }
    CHECK(counted, "two platforms in 0.3 s: the limit says 0 of 16 combinations solved, the plan over the charts cut short");
    std::atomic<bool> stop{true};
    const Outcome stopped = solve(platforms, true, 0, &stop);
    CHECK(!stopped.result.complete() && among(stopped.result, full.result, labels), "two platforms interrupted: not complete");
  }
}

// The placements of a merged rigid part (a braced strip of 12 triangles, data/strip12.json,
// 2^11 placements by construction) are found once each: the kept placements of a
// superposition are looked up by a necessary condition (Placement_index), not scanned, and
// a brute-force scan of every pair here finds none alike (some coordinate's enclosures
// disjoint) and the count the strip has.
static void merged_part_placements()
{
  typedef CGAL::Interval_nt<false> I;
  const RI::Scene s = read(std::string(RIGID_INCIDENCE_TEST_DATA_DIR) + "/strip12.json");
  const RI::Rigid_body_collection<Traits> c = RI::standardize(RI::make_collection<Traits>(s));
  RI::Placement_enumeration<I> best;
  std::string name;
  for (std::size_t b = 0; b < c.number_of_bodies(); ++b) {
    if (c.body(b).all_coordinates()) continue;
    RI::Placement_enumeration<I> e = RI::enumerate_placements<I>(c, b);
    if (e.placements.size() > best.placements.size()) {
      best = std::move(e);
      name = c.body(b).name;
    }
  }
  std::size_t alike = 0;
  for (std::size_t i = 0; i < best.placements.size(); ++i)
    for (std::size_t j = i + 1; j < best.placements.size(); ++j) {
      const auto& x = best.placements[i].coordinates;
      const auto& y = best.placements[j].coordinates;
      bool differ = false;
      for (std::size_t k = 0; k < x.size() && !differ; ++k)
        for (std::size_t d = 0; d < 3 && !differ; ++d) differ = x[k][d].sup() < y[k][d].inf() || y[k][d].sup() < x[k][d].inf();
      alike += !differ;
    }
  std::cout << "strip of 12: the merged part has " << best.placements.size() << " placements (" << alike << " pairs alike)\n";
  CHECK(best.complete && best.undecided.empty() && best.placements.size() == 2048 && alike == 0,
        "strip of 12: body '" << name.substr(0, 40) << "...' has " << best.placements.size() << " placements (2048 expected), "
                              << alike << " pairs alike, complete " << best.complete);
}

// Three stacked platforms of another seed (scripts/make_scene_family.py platforms 3 --seed 2,
// 8 x 2 x 8 assembly modes): the factored answer against the plan over every chart assignment
// listed, the planted configuration among both, the count the parts' product.
static void factored_three_platforms()
{
  const std::string td = RIGID_INCIDENCE_TEST_DATA_DIR;
  const RI::Scene scene = read(td + "/platforms3_seed2.json");
  const auto labels = point_labels(scene);
  const auto planted = read_planted(td + "/platforms3_seed2_planted.json");
  auto has_planted = [&](const RI::Scene_solve_result& r) {
    for (const auto& x : r.configurations) {
      double d = 0;
      for (const auto& p : planted)
        for (std::size_t k = 0; k < 3; ++k) d = (std::max)(d, std::abs(x.configuration.point(p.first)[k] - p.second[k]));
      if (d < 1e-6) return true;
    }
    return false;
  };
  const Outcome f = solve(scene);
  const Outcome l = solve(scene, true, 0, nullptr, true, true, [](RI::Scene_solve_parameters& p) { p.factor_parts = false; });
  CGAL::Gmpz product = 1;
  std::string counts;
  for (const auto& q : f.result.parts) {
    product *= CGAL::Gmpz(long(q.solutions.size()));
    counts += (counts.empty() ? "" : " x ") + std::to_string(q.solutions.size());
  }
  std::cout << "three platforms (seed 2): factored " << counts << " = " << f.result.configuration_count << " in "
            << f.result.statistics.block_solves << " block solves; listed from every chart assignment: "
            << l.result.configurations.size() << " in " << l.result.statistics.block_solves << " block solves\n";
  CHECK(f.result.parts.size() == 3 && f.result.complete() && l.result.complete() && l.result.parts.empty(),
        "three platforms: 3 parts, complete both ways");
  CHECK(f.result.configuration_count == product && f.result.configurations.size() == l.result.configurations.size() &&
            CGAL::Gmpz(long(l.result.configurations.size())) == l.result.configuration_count && among(f.result, l.result, labels) &&
            among(l.result, f.result, labels),
        "three platforms: the factored answer (" << f.result.configuration_count << ") is the listed one (" << l.result.configurations.size() << ")");
  CHECK(has_planted(f.result) && has_planted(l.result), "three platforms: the planted configuration among both answers");
  for (const auto& x : f.result.configurations)
    CHECK(x.certified && x.max_relative_residual < 1e-9, "three platforms: a factored configuration not certified or not holding");
}

int main()
{
  merged_part_placements();
  along_the_plan();
  factored_three_platforms();
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
  // a tree of hinges: its work read off its Tree_system, never expanded, against the expanded
  // reduced system's (variables, equations, charts, blocks, parts); the sweep said where the
  // solve would take it (64 chart combinations or more: the chain of 7, not the chain of 5)
  for (const char* name : {"chain5.json", "chain7.json", "ring7.json", "two_pairs_of_hinges.json"}) {
    const RI::Scene scene = read(std::string(RIGID_INCIDENCE_TEST_DATA_DIR) + "/" + name);
    RI::Rigid_body_collection<Traits> c = RI::standardize(RI::make_collection<Traits>(scene));
    RI::Incidence_tree t = RI::optimal_incidence_tree(c);
    RI::Well_formed_selection wf = RI::select_well_formed_incidences(c, t);
    CHECK(RI::Tree_system<Traits>::unsupported(c, t).empty(), name << ": not a tree of hinges");
    const RI::Scene_solve_work w = RI::scene_solve_work(c, t, wf);
    CGAL::Protect_FPU_rounding<true> guard;
    const RI::Reduced_system<Traits, CGAL::Interval_nt<false>> r(c, t, wf);
    std::size_t charts = 1;
    for (const auto& e : r.parametrization().edges()) charts *= std::size_t(e.number_of_charts);
    std::vector<std::vector<std::size_t>> support;
    for (const auto& e : r.equations()) support.push_back(e.variables);
    std::vector<std::size_t> blocks;
    for (const auto& b : RI::Solution_plan(r.number_of_variables(), support).blocks()) blocks.push_back(b.variables.size());
    const std::size_t parts =
        RI::independent_parts(r.number_of_variables(), support, {}, RI::internal::chart_groups(r.parametrization(), r.number_of_variables()))
            .size();
    CHECK(w.variables == r.number_of_variables() && w.equations == r.number_of_equations() && w.chart_combinations == charts &&
              w.block_sizes == blocks && w.independent_parts == parts,
          name << ": " << RI::internal::describe_work(w) << "; expanded: " << r.number_of_variables() << " variables, " << r.number_of_equations()
               << " equations, " << charts << " chart combinations");
    const bool swept = std::string(name) == "chain7.json";
    CHECK(swept == !w.sweep_driver.empty() && (!swept || (w.sweep_steps == 5 && w.sweep_checks == 1)) &&
              (RI::internal::describe_work(w).find("one sweep") != std::string::npos) == swept,
          name << ": " << RI::internal::describe_work(w));
    // the solve sweeps exactly where the estimate says it will (one predicate decides both)
    const Outcome o = solve(scene, true, 60);
    CHECK(o.result.statistics.swept == swept && o.result.complete(),
          name << ": the solve " << (o.result.statistics.swept ? "swept" : "did not sweep") << ", the estimate says it "
               << (swept ? "will" : "will not"));
    std::cout << name << ": " << RI::internal::describe_work(w) << "\n";
  }
  if (failures) { std::cerr << failures << " failure(s)\n"; return 1; }
  std::cout << "all scene_solve_work checks passed\n";
  return 0;
}
