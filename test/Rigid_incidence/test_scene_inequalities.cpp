// Copyright (c) 2026 Rigid_incidence contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Orientation inequalities of scenes ("inequalities": [{"orientation": [A, B, C, D], "sign"}]:
// det(B - A, C - A, D - A) >= 0, or <= 0). Oracle: the scene solved without the inequality,
// each configuration's determinant computed from its world coordinates (independent of the
// orientation polynomial of the reduced system). For the paper scenes tetra, pent and
// quad_distinct and every choice of four points whose determinant is clearly nonzero in every
// configuration and changes sign between them (up to 6 choices per scene), the solve with the
// inequality returns exactly the configurations of the right sign, certified and complete,
// for both signs; with double (Interval_nt) and exact (Gmpq) coefficients as the scene allows.
// The first inequality of each scene is solved again naming its last point by an alias (a label
// made one with it by a distance of 0): the same configurations.
// Then the reader: malformed inequalities are refused with the field named.

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
#include <sstream>
#include <string>
#include <vector>

namespace RI = CGAL::Rigid_incidence;
typedef RI::Rigid_incidence_traits<CGAL::Simple_cartesian<CGAL::Gmpq>> Traits;
typedef std::array<double, 3> P3;

static RI::Scene_solve_result solve(const RI::Scene& scene, const std::vector<RI::Orientation_inequality>& ineq)
{
  RI::Rigid_body_collection<Traits> input = RI::make_collection<Traits>(scene);
  RI::Rigid_body_collection<Traits> c = RI::standardize(input);
  RI::Incidence_tree t = RI::optimal_incidence_tree(c);
  RI::Well_formed_selection wf = RI::select_well_formed_incidences(c, t);
  const bool exact = RI::exact_coefficients(c, t);
  RI::Scene_solve_parameters p;
  p.inequalities = ineq;
  if (exact) return RI::solve_scene<CGAL::Interval_nt<false>, CGAL::Gmpq>(input, c, t, wf, p);
  return RI::solve_scene<CGAL::Interval_nt<false>, CGAL::Interval_nt<false>>(input, c, t, wf, p);
}

static double det(const RI::Configuration& k, const std::array<std::string, 4>& l)
{
  const P3 &a = k.point(l[0]), &b = k.point(l[1]), &c = k.point(l[2]), &d = k.point(l[3]);
  P3 u, v, w;
  for (int i = 0; i < 3; ++i) { u[i] = b[i] - a[i]; v[i] = c[i] - a[i]; w[i] = d[i] - a[i]; }
  return u[0] * (v[1] * w[2] - v[2] * w[1]) - u[1] * (v[0] * w[2] - v[2] * w[0]) + u[2] * (v[0] * w[1] - v[1] * w[0]);
}

static double distance(const RI::Configuration& a, const RI::Configuration& b)
{
  double d = 0;
  for (std::size_t i = 0; i < a.labels.size(); ++i)
    for (int k = 0; k < 3; ++k) d = (std::max)(d, std::abs(a.point(a.labels[i])[k] - b.point(a.labels[i])[k]));
  return d;
}

int main()
{
  std::size_t choices = 0, selected = 0, alias_cases = 0;
  for (const char* name : {"tetra", "pent", "quad_distinct"}) {
    RI::Scene scene = RI::read_scene(std::string(RIGID_INCIDENCE_DATA_DIR) + "/" + name + ".json");
    RI::Scene_solve_result all = solve(scene, {});
    CHECK(all.complete() && !all.configurations.empty(), name << ": the scene without inequality is not solved completely");
    // the labels of the scene, in a fixed order
    std::vector<std::string> labels;
    for (const auto& b : scene.bodies)
      for (const auto& p : b.points)
        if (std::find(labels.begin(), labels.end(), p.label) == labels.end()) labels.push_back(p.label);
    std::size_t tried = 0;
    for (std::size_t a = 0; a < labels.size() && tried < 6; ++a)
      for (std::size_t b = a + 1; b < labels.size() && tried < 6; ++b)
        for (std::size_t c = b + 1; c < labels.size() && tried < 6; ++c)
          for (std::size_t d = c + 1; d < labels.size() && tried < 6; ++d) {
            std::array<std::string, 4> l = {labels[a], labels[b], labels[c], labels[d]};
            // the scene's size: the largest coordinate
            double size = 0, least = 1e300;
            std::size_t pos = 0;
            for (const auto& k : all.configurations) {
              for (const auto& p : k.configuration.points) for (double x : p) size = (std::max)(size, std::abs(x));
              const double v = det(k.configuration, l);
              least = (std::min)(least, std::abs(v));
              pos += v > 0;
            }
            // clearly nonzero everywhere, and splitting the configurations
            if (least < 1e-6 * size * size * size || pos == 0 || pos == all.configurations.size()) continue;
            ++tried;
            ++choices;
            for (bool negative : {false, true}) {
              RI::Orientation_inequality g;
              g.points = l;
              g.negative = negative;
              RI::Scene_solve_result r = solve(scene, {g});
              const std::string what = std::string(name) + " with det(" + l[1] + "-" + l[0] + ", " + l[2] + "-" + l[0] + ", " + l[3] + "-" +
                                       l[0] + ") " + (negative ? "<= 0" : ">= 0");
              const std::size_t want = negative ? all.configurations.size() - pos : pos;
              CHECK(r.complete(), what << ": not complete");
              CHECK(r.configurations.size() == want, what << ": " << r.configurations.size() << " configurations, expected " << want);
              selected += r.configurations.size();
              for (const auto& k : r.configurations) {
                const double v = det(k.configuration, l);
                CHECK(negative ? v < 0 : v > 0, what << ": a configuration has determinant " << v);
                CHECK(k.certified && !k.on_inequality_boundary, what << ": a configuration is not certified or on the boundary");
                std::size_t same = 0;
                for (const auto& m : all.configurations) same += distance(m.configuration, k.configuration) < 1e-7 * (1 + size);
                CHECK(same == 1, what << ": a configuration matches " << same << " of the unconstrained solve");
              }
              // the same inequality naming D by an alias (D renamed D' in the last body that holds
              // it, joined to D by a distance of 0): a coincidence, the same configurations
              std::size_t holders = 0;
              for (const auto& b : scene.bodies)
                for (const auto& x : b.points) holders += x.label == l[3];
              if (tried == 1 && holders >= 2) {
                ++alias_cases;
                RI::Scene sa = scene;
                for (auto b = sa.bodies.rbegin(); b != sa.bodies.rend(); ++b) {
                  auto q = std::find_if(b->points.begin(), b->points.end(), [&](const RI::Scene::Point& x) { return x.label == l[3]; });
                  if (q == b->points.end()) continue;
                  q->label = l[3] + "'";
                  break;
                }
                RI::Scene::Distance zero;
                zero.a = l[3];
                zero.b = l[3] + "'";
                zero.squared = 0;
                sa.distances.push_back(zero);
                RI::Orientation_inequality ga = g;
                ga.points[3] = l[3] + "'";
                RI::Scene_solve_result ra = solve(sa, {ga});
                CHECK(ra.complete() && ra.configurations.size() == want,
                      what << ", D named by an alias: " << ra.configurations.size() << " configurations, expected " << want);
                for (const auto& k : ra.configurations) CHECK(negative ? det(k.configuration, l) < 0 : det(k.configuration, l) > 0, what << ", alias: a configuration on the wrong side");
              }
            }
          }
    CHECK(tried > 0, name << ": no four points split the configurations");
  }
  CHECK(alias_cases > 0, "no inequality was tried with an alias");

  // the reader
  const std::string head = R"({"format": "rigid-incidence-scene/1", "bodies": [{"name": "c1", "points": {"A": [0,0,0], "B": [1,0,0], "C": [0,1,0]}},
    {"name": "c2", "points": {"A": [0,0,0], "B": [1,0,0], "D": [0,0,1]}}], )";
  struct Bad { const char* inequalities; const char* needle; };
  const Bad bad[] = {{R"("inequalities": {})", "inequalities"},
                     {R"("inequalities": [{"orientation": ["A", "B", "C"]}])", "expected 4 point labels"},
                     {R"("inequalities": [{"orientation": ["A", "B", "C", "E"]}])", "point 'E' is in no body"},
                     {R"("inequalities": [{"orientation": ["A", "B", "C", "A"]}])", "point 'A' appears twice"},
                     {R"("inequalities": [{"orientation": ["A", "B", "C", "D"], "sign": "up"}])", "expected \"positive\" or \"negative\""},
                     {R"("inequalities": [{"orientation": ["A", "B", "C", "D"], "weight": 1}])", "unknown field \"weight\""},
                     {R"("inequalities": [{"sign": "negative"}])", "missing field \"orientation\""},
                     {R"("inequalities": [{"orientation": ["A", "B", 3, "D"]}])", "inequalities[0].orientation[2]"}};
  for (const auto& x : bad) {
    std::istringstream in(head + x.inequalities + "}");
    std::string what;
    try { RI::read_scene(in, "bad.json"); } catch (const RI::Input_error& e) { what = e.what(); }
    CHECK(what.find(x.needle) != std::string::npos && what.find("bad.json") != std::string::npos,
          "inequalities " << x.inequalities << ": message '" << what << "' should name " << x.needle);
  }
  {
    std::istringstream in(head + R"("inequalities": [{"orientation": ["A", "B", "C", "D"], "sign": "negative"}, {"orientation": ["D", "C", "B", "A"]}]})");
    RI::Scene s = RI::read_scene(in, "good.json");
    CHECK(s.inequalities.size() == 2 && s.inequalities[0].negative && !s.inequalities[1].negative && s.inequalities[1].points[0] == "D",
          "a valid inequalities field is read as written");
  }
  std::cout << choices << " choices of four points, " << selected << " configurations selected; " << checks << " checks, " << failures
            << " failures\n";
  return failures == 0 ? 0 : 1;
}
