// Copyright (c) 2026 Rigid_incidence contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Reduced_system(base, charts): the systems of the other chart combinations made from the one
// of chart 0 by a change of chart (a hinge's t -> 1/s, a free rotation's q0 = 1 -> qj = 1, by
// homogenizing each equation with its rotation_degree), not by a new reduction (issue 28,
// item 2). Oracles:
// - the direct build of every chart combination: the same polynomial, term for term (exact
//   coefficients) or with overlapping interval coefficients, wherever the direct build wrote
//   the equation through the same carriers (a different choice between equivalent forms is
//   counted, and must stay rare);
// - the solve: solve_scene with and without the change of chart gives the same
//   configurations, point for point, on the paper's scenes and on scenes of 2 and 4 hinges
//   (a ball joint held by three distances, which the standardization makes two hinges; two
//   pairs of hinged bodies, exact coefficients);
// - the refusals: a system of another chart, or with a translation, does not change charts.

#include <CGAL/Gmpq.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Rigid_incidence.h>
#include <CGAL/Rigid_incidence/IO/read_scene.h>

#include <cmath>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>

#include "test_check.h"
#include "solve_scene_instances.h"

namespace RI = CGAL::Rigid_incidence;
typedef RI::Rigid_incidence_traits<CGAL::Simple_cartesian<CGAL::Gmpq>> Traits;

static bool same(const CGAL::Gmpq& a, const CGAL::Gmpq& b) { return a == b; }
static bool same(const CGAL::Interval_nt<false>& a, const CGAL::Interval_nt<false>& b)
{
  return a.inf() <= b.sup() && b.inf() <= a.sup();
}

template <class NT>
static void against_direct_builds(const std::string& name, const RI::Rigid_body_collection<Traits>& c, const RI::Incidence_tree& t,
                                  const RI::Well_formed_selection& wf)
{
  const RI::Reduced_system<Traits, NT> base(c, t, wf);
  CHECK(base.changes_charts(), name << ": the system of chart 0 changes charts");
  if (!base.changes_charts()) return;
  std::vector<int> radix;
  for (const auto& e : base.parametrization().edges()) radix.push_back(e.number_of_charts);
  std::vector<int> charts(radix.size(), 0);
  std::size_t combinations = 0, equations = 0, other_forms = 0;
  do {
    ++combinations;
    const RI::Reduced_system<Traits, NT> direct(c, t, wf, charts);
    const RI::Reduced_system<Traits, NT> changed(base, charts);
    CHECK(changed.parametrization().variable_names() == direct.parametrization().variable_names(), name << ": the variables of the chart");
    CHECK(changed.number_of_equations() == direct.number_of_equations(), name << ": as many equations");
    for (std::size_t i = 0; i < changed.number_of_equations() && i < direct.number_of_equations(); ++i) {
      ++equations;
      const auto& a = changed.equations()[i].polynomial.terms();
      const auto& b = direct.equations()[i].polynomial.terms();
      bool equal = a.size() == b.size();
      for (auto x = a.begin(), y = b.begin(); equal && x != a.end(); ++x, ++y) equal = x->first == y->first && same(x->second, y->second);
      if (!equal) {
        ++other_forms;
        // another form: at least the same variables and the same rotation degrees
        CHECK(changed.equations()[i].variables == direct.equations()[i].variables,
              name << ": equation " << i << " of charts " << charts.size() << ": other variables than the direct build's");
      }
      CHECK(changed.equations()[i].rotation_degree == direct.equations()[i].rotation_degree, name << ": the rotation degrees");
    }
  } while (RI::internal::next_combination(charts, radix));
  std::cout << name << ": " << combinations << " chart combinations, " << equations << " equations, " << other_forms
            << " written in another form by the direct build\n";
  CHECK(other_forms * 10 <= equations, name << ": most equations are the direct build's own (" << other_forms << " of " << equations << ")");
}

template <class IT, class NT>
static RI::Scene_solve_result solve(const RI::Scene& scene, const RI::Rigid_body_collection<Traits>& input,
                                    const RI::Rigid_body_collection<Traits>& c, const RI::Incidence_tree& t,
                                    const RI::Well_formed_selection& wf, bool change)
{
  (void)scene;
  RI::Scene_solve_parameters p;
  p.change_charts = change;
  return RI::solve_scene<IT, NT>(input, c, t, wf, p);
}

static void check_scene(const std::string& name, const RI::Scene& scene)
{
  RI::Rigid_body_collection<Traits> input = RI::make_collection<Traits>(scene);
  RI::Rigid_body_collection<Traits> c = RI::standardize(input);
  RI::Incidence_tree t = RI::optimal_incidence_tree(c);
  RI::Well_formed_selection wf = RI::select_well_formed_incidences(c, t);
  const bool exact = RI::exact_coefficients(c, t);
  if (exact) against_direct_builds<CGAL::Gmpq>(name + " (exact)", c, t, wf);
  against_direct_builds<CGAL::Interval_nt<false>>(name + " (intervals)", c, t, wf);
  RI::Scene_solve_result a, b;
  if (exact) {
    a = solve<CGAL::Interval_nt<false>, CGAL::Gmpq>(scene, input, c, t, wf, true);
    b = solve<CGAL::Interval_nt<false>, CGAL::Gmpq>(scene, input, c, t, wf, false);
  } else {
    a = solve<CGAL::Interval_nt<false>, CGAL::Interval_nt<false>>(scene, input, c, t, wf, true);
    b = solve<CGAL::Interval_nt<false>, CGAL::Interval_nt<false>>(scene, input, c, t, wf, false);
  }
  std::cout << name << ": " << a.configurations.size() << " configurations (" << (a.complete() ? "complete" : "not complete")
            << "), reduce " << a.statistics.reduce_seconds << " s with the change of chart, " << b.statistics.reduce_seconds
            << " s without\n";
  CHECK(a.complete() == b.complete() && a.configurations.size() == b.configurations.size(),
        name << ": " << a.configurations.size() << " configurations with the change of chart, " << b.configurations.size() << " without");
  for (std::size_t k = 0; k < a.configurations.size() && k < b.configurations.size(); ++k) {
    const auto& x = a.configurations[k].configuration;
    const auto& y = b.configurations[k].configuration;
    double far = 0;
    for (std::size_t p = 0; p < x.points.size() && p < y.points.size(); ++p)
      for (std::size_t i = 0; i < 3; ++i) far = (std::max)(far, std::abs(x.points[p][i] - y.points[p][i]));
    CHECK(x.points.size() == y.points.size() && far < 1e-8, name << ": configuration " << k << " differs by " << far);
    CHECK(a.configurations[k].certified == b.configurations[k].certified, name << ": configuration " << k << " certified in one only");
  }
}

int main()
{
  const std::string d = RIGID_INCIDENCE_DATA_DIR;
  for (const char* f : {"tetra", "tetra_i", "tetra_ii", "quad", "quad_distinct", "pent", "flat_hinges", "hinge_three_point_axis"}) {
    std::ifstream in(d + "/" + f + ".json");
    check_scene(f, RI::read_scene(in, f));
  }
  // a ball joint held by three distances (the standardization makes it two hinges of implied
  // triangles)
  const std::string ball = R"({"format": "rigid-incidence-scene/1", "bodies": [
    {"name": "F", "points": {"A": [0, 0, 0], "K1": [5, 1, 0], "K2": [0, 5, 2], "K3": [1, -1, 6]}},
    {"name": "B", "points": {"A": [0, 0, 0], "P": [2, 1, 0], "Q": [0, 2, 1], "R": [1, 0, 2]}}],
    "distances": [{"between": ["P", "K1"], "squared": "9"}, {"between": ["Q", "K2"], "squared": "10"},
                  {"between": ["R", "K3"], "squared": "17"}], "frame": "F"})";
  {
    std::istringstream in(ball);
    check_scene("ball joint", RI::read_scene(in, "ball joint"));
  }
  // four hinges in two pairs, each pair held together by two distances: exact coefficients
  {
    std::ifstream in(std::string(RIGID_INCIDENCE_TEST_DATA_DIR) + "/two_pairs_of_hinges.json");
    check_scene("two pairs of hinges", RI::read_scene(in, "two_pairs_of_hinges.json"));
  }
  // refusals: a system of chart 1, and a free body (a translation)
  {
    std::ifstream in(d + "/tetra.json");
    const RI::Scene s = RI::read_scene(in, "tetra");
    RI::Rigid_body_collection<Traits> c = RI::standardize(RI::make_collection<Traits>(s));
    RI::Incidence_tree t = RI::optimal_incidence_tree(c);
    RI::Well_formed_selection wf = RI::select_well_formed_incidences(c, t);
    const RI::Reduced_system<Traits, CGAL::Interval_nt<false>> other(c, t, wf, {1, 0, 0});
    CHECK(!other.changes_charts(), "a system of chart 1 does not change charts");
    bool refused = false;
    try {
      RI::Reduced_system<Traits, CGAL::Interval_nt<false>> r(other, {0, 0, 0});
    } catch (const RI::Input_error&) { refused = true; }
    CHECK(refused, "a change of chart from chart 1 is refused");
  }
  {
    std::ifstream in(d + "/stewart_gough40.json");
    const RI::Scene s = RI::read_scene(in, "stewart_gough40");
    RI::Rigid_body_collection<Traits> c = RI::standardize(RI::make_collection<Traits>(s));
    RI::Incidence_tree t = RI::optimal_incidence_tree(c);
    RI::Well_formed_selection wf = RI::select_well_formed_incidences(c, t);
    const RI::Reduced_system<Traits, CGAL::Interval_nt<false>> r(c, t, wf);
    CHECK(!r.changes_charts(), "a free body (translation) does not change charts");
  }
  std::cout << (failures ? "FAILED" : "OK") << ": " << checks << " checks, " << failures << " failures\n";
  return failures ? 1 : 0;
}
