// Copyright (c) 2026 Rigid_incidence contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// A whole solve bounded and visible (Scene_solve_parameters::maximal_seconds, interrupt,
// progress), on data/tetrahedron_chain10.json (a chain of 10 tetrahedra hinged edge to edge,
// 512 chart combinations, made by scripts/make_tetrahedron_chain.py), whose solve runs for
// 150 s in Release on this 2-core machine:
//  - with maximal_seconds = 1 the solve stops (within a minute) and its answer is
//    incomplete, says "time limit" in its limits, and every
//    configuration it holds is verified in the original system (the oracle: residuals());
//  - an interrupt flag set from another thread after half a second stops it the same way
//    ("interrupted");
//  - the progress callback is called, with combinations counted up to their total and time
//    that does not go back;
//  - on tetra.json (complete in milliseconds) a generous limit changes nothing: the same
//    configurations as without it, complete, no limit named.

#include "test_check.h"
#include "solve_scene_instances.h"

#include <CGAL/Gmpq.h>
#include <CGAL/Interval_nt.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Rigid_incidence.h>

#include <atomic>
#include <chrono>
#include <iostream>
#include <string>
#include <thread>

namespace RI = CGAL::Rigid_incidence;
typedef RI::Rigid_incidence_traits<CGAL::Simple_cartesian<CGAL::Gmpq>> Traits;

static double seconds_since(std::chrono::steady_clock::time_point t)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}

static RI::Scene_solve_result solve(const std::string& file, const RI::Scene_solve_parameters& p)
{
  RI::Rigid_body_collection<Traits> input = RI::make_collection<Traits>(RI::read_scene(file));
  RI::Rigid_body_collection<Traits> c = RI::standardize(input);
  RI::Incidence_tree t = RI::optimal_incidence_tree(c);
  RI::Well_formed_selection wf = RI::select_well_formed_incidences(c, t);
  if (RI::exact_coefficients(c, t)) return RI::solve_scene<CGAL::Interval_nt<false>, CGAL::Gmpq>(input, c, t, wf, p);
  return RI::solve_scene<CGAL::Interval_nt<false>, CGAL::Interval_nt<false>>(input, c, t, wf, p);
}

static bool names(const RI::Scene_solve_result& r, const std::string& what)
{
  for (const auto& l : r.limits)
    if (l.find(what) != std::string::npos) return true;
  return false;
}

// every configuration of a partial answer is one of the scene (residuals in the original system)
static void check_configurations(const std::string& file, const RI::Scene_solve_result& r, const std::string& name)
{
  RI::Rigid_body_collection<Traits> input = RI::make_collection<Traits>(RI::read_scene(file));
  for (const auto& s : r.configurations) {
    const RI::Residual_report rep = RI::residuals(input, s.configuration);
    const double size = RI::internal::configuration_size(s.configuration);
    CHECK(RI::internal::verified(rep, 1e-6, size), name << ": a configuration of the partial answer has residual " << rep.max());
  }
}

int main()
{
  const std::string long_scene = std::string(RIGID_INCIDENCE_TEST_DATA_DIR) + "/tetrahedron_chain10.json";
  // (the chain combination by combination, without arc consistency: solved along its tree by
  // the sweep it takes about a second, and with arc consistency 2 of its 512 combinations are
  // left, 2 s; test_tree_system checks the sweep's own time limit)
  {  // the time limit
    RI::Scene_solve_parameters p;
    p.sweep = false;
    p.consistency_cells = 0;
    p.maximal_seconds = 1;
    std::size_t calls = 0, last_done = 0;
    double last_seconds = 0;
    bool ordered = true;
    p.progress = [&](const RI::Scene_solve_progress& g) {
      ++calls;
      ordered = ordered && g.combinations_done >= last_done && g.seconds >= last_seconds &&
                (g.combinations_total == 0 || g.combinations_done <= g.combinations_total);
      last_done = g.combinations_done;
      last_seconds = g.seconds;
    };
    const auto t0 = std::chrono::steady_clock::now();
    RI::Scene_solve_result r = solve(long_scene, p);
    const double s = seconds_since(t0);
    std::cout << "time limit 1 s: stopped after " << s << " s, " << r.configurations.size() << " configuration(s), "
              << r.statistics.chart_combinations << " combination(s), " << calls << " progress call(s); limits:";
    for (const auto& l : r.limits) std::cout << " [" << l << "]";
    std::cout << "\n";
    CHECK(s < 60, "maximal_seconds = 1: the solve ran " << s << " s");
    CHECK(!r.complete(), "maximal_seconds = 1: a complete answer");
    CHECK(names(r, "time limit"), "maximal_seconds = 1: no limit names the time limit");
    CHECK(calls > 0 && ordered, "progress: " << calls << " call(s), in order " << ordered);
    check_configurations(long_scene, r, "time limit");
  }
  {  // an interrupt from another thread
    RI::Scene_solve_parameters p;
    p.sweep = false;
    p.consistency_cells = 0;
    std::atomic<bool> stop(false);
    p.interrupt = &stop;
    std::thread t([&stop] {
      std::this_thread::sleep_for(std::chrono::milliseconds(500));
      stop = true;
    });
    const auto t0 = std::chrono::steady_clock::now();
    RI::Scene_solve_result r = solve(long_scene, p);
    const double s = seconds_since(t0);
    t.join();
    std::cout << "interrupt at 0.5 s: stopped after " << s << " s, " << r.configurations.size() << " configuration(s)\n";
    CHECK(s < 60, "interrupt: the solve ran " << s << " s");
    CHECK(!r.complete() && names(r, "interrupted"), "interrupt: complete " << r.complete() << ", no limit says 'interrupted'");
    check_configurations(long_scene, r, "interrupt");
  }
  {  // a limit the solve does not reach changes nothing
    const std::string tetra = std::string(RIGID_INCIDENCE_DATA_DIR) + "/tetra.json";
    RI::Scene_solve_parameters p;
    RI::Scene_solve_result a = solve(tetra, p);
    p.maximal_seconds = 600;
    RI::Scene_solve_result b = solve(tetra, p);
    CHECK(a.complete() && b.complete() && a.configurations.size() == b.configurations.size() && b.limits.empty(),
          "tetra with a limit of 600 s: " << b.configurations.size() << " configurations (" << a.configurations.size()
                                          << " without), complete " << b.complete());
  }
  std::cout << "test_solve_time_limit: " << checks << " checks, " << failures << " failures\n";
  return failures == 0 ? 0 : 1;
}
