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
//   (data/plan_three_blocks.json, two pairs of hinges);
// - the placement combinations of a merged rigid part in parallel, one chart combination each
//   (a tree of 7 bodies: 32 placements, a strip of 8 triangles: 128), and placements built on
//   worker threads (a molecular ring of 10 atoms);
// - the precision retry at more bits (CGAL::Gmpfi coefficients, whose default precision is per
//   thread): tetra_i_tangent.
// And the loops of internal/parallel.h themselves: every piece, on whatever thread, sees the
// caller's rounding mode and Gmpfi default precision (nested loops too); the pipeline takes
// its pieces in order; an exception comes back as the smallest index's.
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
#include <thread>
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

// The loops of internal/parallel.h carry the caller's context to every piece, whatever thread
// runs it: the rounding mode (upward here, under a Protector) and CGAL::Gmpfi's default
// precision (200 bits here; thread_local in CGAL 5.5, a worker starts at 53); the pipeline
// takes the pieces in their order, one at a time; a nested loop runs too. Checked on the
// pieces another thread ran (counted: with 2 cores and oneTBB some must be).
static void loops_carry_the_context()
{
  typename CGAL::Interval_nt<false>::Protector protect;
  const CGAL::FPU_CW_t cw = CGAL::FPU_get_cw();
#ifdef CGAL_USE_MPFI
  const auto old = CGAL::Gmpfi::set_default_precision(200);
  auto precision_ok = [] { return CGAL::Gmpfi::get_default_precision() == 200; };
#else
  auto precision_ok = [] { return true; };
#endif
  const std::thread::id caller = std::this_thread::get_id();
  const std::size_t n = 64;
  std::vector<char> ok(n, 0), elsewhere(n, 0);
  auto busy = [] {  // (long enough for the other thread to take pieces)
    volatile double x = 0;
    for (int k = 0; k < 200000; ++k) x = x + 1e-9 * k;
  };
  RI::internal::parallel_for_each_index(n, 2, [&](std::size_t i) {
    busy();
    ok[i] = CGAL::FPU_get_cw() == cw && precision_ok();
    elsewhere[i] = std::this_thread::get_id() != caller;
    // a nested loop: its pieces see the context too
    std::vector<char> inner(4, 0);
    RI::internal::parallel_for_each_index(4, 2, [&](std::size_t j) { inner[j] = CGAL::FPU_get_cw() == cw && precision_ok(); });
    for (char c : inner) ok[i] = ok[i] && c;
  });
  std::size_t moved = 0;
  for (std::size_t i = 0; i < n; ++i) {
    CHECK(ok[i], "parallel_for_each_index: piece " << i << " ran without the caller's rounding mode or Gmpfi precision");
    moved += elsewhere[i];
  }
  std::vector<std::size_t> taken;
  std::size_t next = 0, moved_pipeline = 0;
  bool stages_ok = true;
  struct Piece { std::size_t i = 0; bool ok = false, elsewhere = false; };
  RI::internal::ordered_pipeline<Piece>(2, 8,
      [&](Piece& p) {
        stages_ok = stages_ok && CGAL::FPU_get_cw() == cw && precision_ok();
        if (next == n) return false;
        p.i = next++;
        return true;
      },
      [&](Piece& p) {
        busy();
        p.ok = CGAL::FPU_get_cw() == cw && precision_ok();
        p.elsewhere = std::this_thread::get_id() != caller;
      },
      [&](Piece& p) {
        stages_ok = stages_ok && CGAL::FPU_get_cw() == cw && precision_ok() && p.ok;
        moved_pipeline += p.elsewhere;
        taken.push_back(p.i);
      });
  CHECK(stages_ok, "ordered_pipeline: a stage ran without the caller's rounding mode or Gmpfi precision");
  bool in_order = taken.size() == n;
  for (std::size_t i = 0; in_order && i < n; ++i) in_order = taken[i] == i;
  CHECK(in_order, "ordered_pipeline: the pieces were not taken in their order");
  // an exception of a piece: the one of the smallest index
  std::string what;
  try {
    RI::internal::parallel_for_each_index(16, 2, [&](std::size_t i) {
      busy();
      if (i == 5 || i == 11) throw RI::Input_error("piece " + std::to_string(i));
    });
  } catch (const RI::Input_error& e) {
    what = e.what();
  }
  CHECK(what == "piece 5", "parallel_for_each_index: rethrew '" << what << "', not piece 5's");
  CHECK(CGAL::FPU_get_cw() == cw && precision_ok(), "the caller's own context changed by the loops");
#ifdef CGAL_USE_MPFI
  CGAL::Gmpfi::set_default_precision(old);
#endif
  std::cout << "loops: " << moved << " of " << n << " pieces and " << moved_pipeline << " of " << n
            << " pipeline pieces ran on another thread (each checked for the caller's context)\n";
  if (RI::internal::worker_threads(2) > 1) CHECK(moved + moved_pipeline > 0, "no piece ran on another thread: the context checks checked nothing");
}

int main(int argc, char** argv)
{
  loops_carry_the_context();
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
