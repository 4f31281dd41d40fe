// Copyright (c) 2026 Rigid_incidence contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Scenes whose configurations form curves (solve_scene with trace_curves):
//  - quad_one_dof (quad without its fourth apex distance E4-E1: one degree of freedom): the
//    curves must be certified and complete, every frame a configuration of the scene (residual
//    in the original system), and, as the independent oracle, the scene solved with the fourth
//    distance fixed to d for 20 values of d (well-constrained, isolated configurations): every
//    such configuration lies near a traced branch, and their number equals the number of times
//    the branches cross |E4 - E1| = d (counted from the frames);
//  - quad_symmetric (all four apex distances 5): the dof count says finite, the solver finds a
//    curve of solutions; solve must say so (diagnosis positive_dimensional, not complete) and
//    return the curves it traced without being told, every frame on all four distances.

#include <CGAL/Gmpq.h>
#include <CGAL/Interval_nt.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Rigid_incidence.h>

#include "test_check.h"
#include "solve_scene_instances.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <iostream>
#include <string>
#include <vector>

namespace RI = CGAL::Rigid_incidence;
typedef RI::Rigid_incidence_traits<CGAL::Simple_cartesian<CGAL::Gmpq>> Traits;
typedef std::array<double, 3> P3;

static RI::Scene_solve_result solve(const RI::Scene& scene)
{
  RI::Rigid_body_collection<Traits> input = RI::make_collection<Traits>(scene);
  RI::Rigid_body_collection<Traits> c = RI::standardize(input);
  RI::Incidence_tree t = RI::optimal_incidence_tree(c);
  RI::Well_formed_selection wf = RI::select_well_formed_incidences(c, t);
  return RI::solve_scene<CGAL::Interval_nt<false>, CGAL::Gmpq>(input, c, t, wf);
}

static double length(const RI::Configuration& k, const std::string& a, const std::string& b)
{
  const P3 &p = k.point(a), &q = k.point(b);
  return std::sqrt((p[0] - q[0]) * (p[0] - q[0]) + (p[1] - q[1]) * (p[1] - q[1]) + (p[2] - q[2]) * (p[2] - q[2]));
}

// distance from configuration x to the segment of configurations a, b (all points stacked)
static double to_segment(const RI::Configuration& x, const RI::Configuration& a, const RI::Configuration& b)
{
  double ab = 0, t = 0;
  for (const auto& l : x.labels)
    for (int i = 0; i < 3; ++i) {
      const double u = b.point(l)[i] - a.point(l)[i];
      ab += u * u;
      t += (x.point(l)[i] - a.point(l)[i]) * u;
    }
  t = ab > 0 ? std::max(0.0, std::min(1.0, t / ab)) : 0;
  double d = 0;
  for (const auto& l : x.labels)
    for (int i = 0; i < 3; ++i) d = std::max(d, std::abs(x.point(l)[i] - a.point(l)[i] - t * (b.point(l)[i] - a.point(l)[i])));
  return d;
}

static void quad_one_dof()
{
  RI::Scene scene = RI::read_scene(std::string(RIGID_INCIDENCE_DATA_DIR) + "/quad_one_dof.json");
  RI::Scene_solve_result r = solve(scene);
  CHECK(r.complete() && r.configurations.empty() && !r.curves.empty(), "quad_one_dof: complete curves (" << r.curves.size() << ")");
  for (const auto& c : r.curves) {
    CHECK(c.certified && c.closed, "quad_one_dof: a certified closed branch");
    for (const auto& f : c.configurations) {
      CHECK(std::abs(length(f, "E1", "E2") - 4) < 1e-9 && std::abs(length(f, "E2", "E3") - 3.5) < 1e-9 && std::abs(length(f, "E3", "E4") - 4.5) < 1e-9,
            "quad_one_dof: a frame off the distances");
    }
    CHECK(c.max_residual < 1e-9, "quad_one_dof: residual " << c.max_residual);
  }
  // the oracle: the scene with |E4 - E1| = d, solved as an isolated problem
  double lo = 1e300, hi = 0;
  for (const auto& c : r.curves)
    for (const auto& f : c.configurations) { lo = std::min(lo, length(f, "E4", "E1")); hi = std::max(hi, length(f, "E4", "E1")); }
  CHECK(hi > lo, "quad_one_dof: the free distance varies");
  int compared = 0;
  for (int k = 0; k < 20; ++k) {
    // 20 values across the range, rational with a small denominator (away from the folds)
    const CGAL::Gmpq d = CGAL::Gmpq(int(std::round((lo + (hi - lo) * (k + 0.5) / 20) * 64)), 64);
    const double dd = CGAL::to_double(d);
    RI::Scene fixed = scene;
    RI::Scene::Distance x;
    x.a = "E4";
    x.b = "E1";
    x.squared = d * d;
    x.given_as_length = true;
    x.length = d;
    fixed.distances.push_back(x);
    RI::Scene_solve_result s = solve(fixed);
    if (!s.complete()) continue;  // a sample too close to a fold: not a fair comparison
    ++compared;
    // crossings of |E4 - E1| = d along the branches
    std::size_t crossings = 0;
    for (const auto& c : r.curves) {
      const std::size_t m = c.configurations.size();
      for (std::size_t i = 0; i < (c.closed ? m : m - 1); ++i) {
        const double a = length(c.configurations[i], "E4", "E1") - dd, b = length(c.configurations[(i + 1) % m], "E4", "E1") - dd;
        if ((a < 0) != (b < 0)) ++crossings;
      }
    }
    CHECK(crossings == s.configurations.size(),
          "quad_one_dof at d = " << dd << ": " << s.configurations.size() << " configurations, the branches cross it " << crossings << " times");
    for (const auto& conf : s.configurations) {
      double best = 1e300;
      for (const auto& c : r.curves)
        for (std::size_t i = 0; i + 1 < c.configurations.size(); ++i)
          best = std::min(best, to_segment(conf.configuration, c.configurations[i], c.configurations[i + 1]));
      CHECK(best < 0.05, "quad_one_dof at d = " << dd << ": a configuration " << best << " from the branches");
    }
  }
  CHECK(compared >= 15, "quad_one_dof: only " << compared << " samples compared");
}

static void quad_symmetric()
{
  RI::Scene scene = RI::read_scene(std::string(RIGID_INCIDENCE_DATA_DIR) + "/quad_symmetric.json");
  RI::Scene_solve_result r = solve(scene);
  CHECK(!r.complete() && r.diagnosis.rfind("positive_dimensional", 0) == 0, "quad_symmetric: diagnosed positive-dimensional");
  CHECK(!r.curves.empty(), "quad_symmetric: curves traced without being told");
  std::size_t frames = 0;
  for (const auto& c : r.curves) {
    CHECK(!c.certified && !c.note.empty(), "quad_symmetric: a branch traced without one equation says so");
    for (const auto& f : c.configurations) {
      ++frames;
      CHECK(std::abs(length(f, "E1", "E2") - 5) < 1e-8 && std::abs(length(f, "E2", "E3") - 5) < 1e-8 && std::abs(length(f, "E3", "E4") - 5) < 1e-8 &&
                std::abs(length(f, "E4", "E1") - 5) < 1e-8,
            "quad_symmetric: a frame off the distances");
    }
  }
  CHECK(frames > 100, "quad_symmetric: " << frames << " frames");
}

int main()
{
  quad_one_dof();
  quad_symmetric();
  std::cout << checks << " checks, " << failures << " failures\n";
  return failures ? 1 : 0;
}
