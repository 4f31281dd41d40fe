// Copyright (c) 2026 Rigid_incidence contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// solve_family(): a scene with a free distance, solved as curves over that distance (also
// with the distance named by an alias of one of its points: the same family).
//  - determinant() against Eigen's determinant of the evaluated matrix at random points;
//  - quad_family (quad with E1-E2 free over [1, 8], the other apex distances 3.5, 4.5, 5): the
//    family must be complete; the oracle is the scene solved on its own (solve_scene) with
//    E1-E2 fixed: at 20 sample lengths its number of configurations equals the family's
//    count there, and each of its configurations lies near a branch; at 4 (quad_distinct) the
//    count is 16; on both sides of every fold (length +- 1e-3) the solved counts differ by
//    the fold's change; the counts between folds are those of solve_scene at their middle;
//  - the same family with the Epick kernel: the same folds;
//  - a range without folds; the scene file forms; malformed input: errors naming the fault.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Gmpq.h>
#include <CGAL/Interval_nt.h>
#include <CGAL/Random.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Rigid_incidence.h>

#include <Eigen/Dense>

#include "test_check.h"
#include "solve_scene_instances.h"

#include <algorithm>
#include <cmath>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

namespace RI = CGAL::Rigid_incidence;
typedef RI::Rigid_incidence_traits<CGAL::Simple_cartesian<CGAL::Gmpq>> Traits;
typedef RI::Rigid_incidence_traits<CGAL::Exact_predicates_inexact_constructions_kernel> Epick_traits;
typedef CGAL::Interval_nt<false> IT;
typedef CGAL::Gmpq Q;

static const std::string data = RIGID_INCIDENCE_DATA_DIR;

// ---------------------------------------------------------------- determinant

static void test_determinant()
{
  typedef RI::Sparse_polynomial<Q> P;
  CGAL::Random rng(7);
  for (std::size_t n = 1; n <= 5; ++n)
    for (int trial = 0; trial < 6; ++trial) {
      const std::size_t vars = 3;
      std::vector<std::vector<P>> m(n, std::vector<P>(n, P(vars)));
      for (auto& row : m)
        for (auto& e : row) {
          if (rng.get_int(0, 4) == 0) continue;  // some zero entries
          for (int t = 0; t < 3; ++t) {
            P::Exponent x(vars, 0);
            for (auto& k : x) k = unsigned(rng.get_int(0, 3));
            e.add_term(x, Q(rng.get_int(-9, 10)));
          }
        }
      const P d = RI::determinant(m);
      for (int s = 0; s < 3; ++s) {
        std::vector<double> x{rng.get_double(-1, 1), rng.get_double(-1, 1), rng.get_double(-1, 1)};
        Eigen::MatrixXd M(n, n);
        double scale = 1;
        for (std::size_t i = 0; i < n; ++i) {
          double row = 0;
          for (std::size_t j = 0; j < n; ++j) {
            M(long(i), long(j)) = m[i][j].evaluate(x);
            row = std::max(row, std::abs(M(long(i), long(j))));
          }
          scale *= std::max(row, 1.0);
        }
        const double expected = M.determinant(), got = d.evaluate(x);
        CHECK(std::abs(expected - got) <= 1e-9 * scale, "determinant " << n << "x" << n << ": " << got << " vs Eigen " << expected);
      }
    }
  bool threw = false;
  try {
    RI::determinant(std::vector<std::vector<P>>{{P(1), P(1)}});
  } catch (const RI::Input_error&) {
    threw = true;
  }
  CHECK(threw, "determinant of a 1x2 matrix must throw");
}

// ---------------------------------------------------------------- the oracle: solve_scene

// The scene with the free distance fixed to `length` (exact), solved on its own.
static RI::Scene_solve_result solve_at(RI::Scene scene, const Q& length)
{
  RI::Scene::Distance d;
  d.a = scene.free_distance.a;
  d.b = scene.free_distance.b;
  d.length = length;
  d.given_as_length = true;
  d.squared = length * length;
  scene.distances.push_back(d);
  scene.free_distance = RI::Scene::Free_distance();
  RI::Rigid_body_collection<Traits> input = RI::make_collection<Traits>(scene);
  RI::Rigid_body_collection<Traits> c;
  try {
    c = RI::standardize(input);
  } catch (const RI::Input_error& e) {
    // E1-E2 above 2 sqrt(10): the triangle B, E1, E2 cannot close, no configuration
    if (std::string(e.what()).find("triangle inequality") == std::string::npos) throw;
    return RI::Scene_solve_result();
  }
  RI::Incidence_tree t = RI::optimal_incidence_tree(c);
  RI::Well_formed_selection wf = RI::select_well_formed_incidences(c, t);
  // as the solve command: exact coefficients when every covering body has coordinates
  bool exact = true;
  for (std::size_t b : t.covering_set) exact = exact && c.body(b).all_coordinates();
  return exact ? RI::solve_scene<IT, Q>(input, c, t, wf) : RI::solve_scene<IT, IT>(input, c, t, wf);
}

static Q rational(double x) { return Q(std::round(x * 1e6)) / Q(1000000); }

static double configuration_gap(const RI::Configuration& x, const RI::Configuration& y)
{
  double d = 0;
  for (std::size_t i = 0; i < x.points.size(); ++i)
    for (int k = 0; k < 3; ++k) d = std::max(d, std::abs(x.points[i][k] - y.points[i][k]));
  return d;
}

// distance from x to the nearest segment of the branch polylines (points stacked)
static double to_branches(const RI::Configuration& x, const RI::Family_result& r)
{
  double best = 1e300;
  for (const auto& br : r.branches) {
    const auto& cs = br.curve.configurations;
    for (std::size_t i = 0; i + 1 < cs.size() + (br.curve.closed ? 1 : 0); ++i) {
      const auto& a = cs[i];
      const auto& b = cs[(i + 1) % cs.size()];
      double ab = 0, t = 0;
      for (std::size_t p = 0; p < x.points.size(); ++p)
        for (int k = 0; k < 3; ++k) {
          const double u = b.points[p][k] - a.points[p][k];
          ab += u * u;
          t += (x.points[p][k] - a.points[p][k]) * u;
        }
      t = ab > 0 ? std::max(0.0, std::min(1.0, t / ab)) : 0;
      double d = 0;
      for (std::size_t p = 0; p < x.points.size(); ++p)
        for (int k = 0; k < 3; ++k) d = std::max(d, std::abs(x.points[p][k] - a.points[p][k] - t * (b.points[p][k] - a.points[p][k])));
      best = std::min(best, d);
    }
  }
  return best;
}

static bool near_fold(const RI::Family_result& r, double d, double margin)
{
  for (const auto& f : r.folds)
    if (d > f.length.first - margin && d < f.length.second + margin) return true;
  return false;
}

static void test_quad_family()
{
  RI::Scene scene = RI::read_scene(data + "/quad_family.json");
  CHECK(scene.free_distance.declared && scene.free_distance.a == "E1" && scene.free_distance.b == "E2", "quad_family: free distance read");
  CHECK(scene.free_distance.has_range && scene.free_distance.lo == Q(1) && scene.free_distance.hi == Q(8), "quad_family: range read");
  CHECK(scene.distances.size() == 3, "quad_family: 3 fixed distances, found " << scene.distances.size());
  RI::Rigid_body_collection<Traits> input = RI::make_collection<Traits>(scene);
  const RI::Family_result r = RI::solve_family<IT>(input, "E1", "E2", Q(1), Q(8));
  CHECK(r.complete(), "quad_family: complete (diagnosis '" << r.diagnosis << "', " << r.unresolved.size() << " unresolved)");
  CHECK(!r.branches.empty() && !r.folds.empty(), "quad_family: " << r.branches.size() << " branches, " << r.folds.size() << " folds");
  for (const auto& f : r.folds) {
    CHECK(f.certified, "quad_family: fold at " << f.length.first << " certified");
    CHECK(f.length.second - f.length.first < 1e-8, "quad_family: fold enclosure width " << f.length.second - f.length.first);
    CHECK(f.length.first >= 1 && f.length.second <= 8, "quad_family: fold in the range");
    CHECK(f.max_residual < 1e-8, "quad_family: fold residual " << f.max_residual);
  }
  for (const auto& b : r.branches) {
    CHECK(b.curve.certified, "quad_family: branch certified");
    CHECK(b.curve.max_residual < 1e-8, "quad_family: branch residual " << b.curve.max_residual);
    CHECK(b.lengths.size() == b.curve.configurations.size(), "quad_family: a length per frame");
  }
  // the count is 0 at both ends of the range (the quad does not close below 1.28 nor above 6.26)
  CHECK(!r.counts.empty() && r.counts.front().count == 0 && r.counts.back().count == 0, "quad_family: no configuration at the ends");
  CHECK(r.count_at(4) == 16, "quad_family: 16 configurations at length 4 (quad_distinct), found " << r.count_at(4));
  {  // the free distance named by an alias of E2 (a coincidence): the same family
    RI::Rigid_body_collection<Traits> aliased = input;
    aliased.add_alias("E2'", "E2", "test: another name of E2");
    const RI::Family_result ra = RI::solve_family<IT>(aliased, "E1", "E2'", Q(1), Q(8));
    CHECK(ra.complete() && ra.folds.size() == r.folds.size() && ra.branches.size() == r.branches.size() && ra.count_at(4) == 16,
          "quad_family named by an alias: " << ra.folds.size() << " folds, " << ra.branches.size() << " branches, " << ra.count_at(4) << " at 4");
  }

  // the oracle: 20 sample lengths
  std::size_t compared = 0;
  for (int k = 0; k < 20; ++k) {
    double d = 1 + (k + 0.5) * 7.0 / 20;
    if (near_fold(r, d, 0.02)) d += 0.05;
    if (near_fold(r, d, 0.02)) continue;
    const Q dq = rational(d);
    const double dd = CGAL::to_double(dq);
    const RI::Scene_solve_result s = solve_at(scene, dq);
    CHECK(s.complete(), "quad_family: solve at " << dd << " complete");
    CHECK(s.configurations.size() == r.count_at(dd),
          "quad_family: at length " << dd << " solve finds " << s.configurations.size() << " configurations, the family " << r.count_at(dd));
    for (const auto& c : s.configurations) {
      const double size = RI::internal::configuration_size(c.configuration);
      const double gap = to_branches(c.configuration, r);
      CHECK(gap < 0.05 * size, "quad_family: configuration at " << dd << " is " << gap << " from the branches");
    }
    ++compared;
  }
  CHECK(compared >= 15, "quad_family: only " << compared << " sample lengths away from folds");
  // the counts between folds, at their middle
  for (const auto& c : r.counts) {
    const Q dq = rational(0.5 * (c.lo + c.hi));
    CHECK(solve_at(scene, dq).configurations.size() == c.count,
          "quad_family: count on (" << c.lo << ", " << c.hi << ") is " << c.count);
  }
  // on both sides of each fold length: the change
  double last = -1;
  for (const auto& f : r.folds) {
    if (f.length.first <= last + 1e-9) continue;  // its mirror image, at the same length
    last = f.length.second;
    const std::size_t below = solve_at(scene, rational(f.length.first - 1e-3)).configurations.size();
    const std::size_t above = solve_at(scene, rational(f.length.second + 1e-3)).configurations.size();
    CHECK(int(above) - int(below) == f.change && f.change != 0,
          "quad_family: across the fold at " << f.length.first << " solve goes " << below << " -> " << above << ", the fold says " << f.change);
  }
  // each fold configuration: two branch configurations meet there, at a length extreme
  for (const auto& f : r.folds) {
    const double gap = to_branches(f.configuration, r);
    CHECK(gap < 0.05 * RI::internal::configuration_size(f.configuration), "quad_family: fold " << gap << " from the branches");
  }

  // the same family with an inexact kernel: the same folds
  RI::Rigid_body_collection<Epick_traits> input_epick = RI::make_collection<Epick_traits>(scene);
  const RI::Family_result e = RI::solve_family<IT>(input_epick, "E1", "E2", Q(1), Q(8));
  CHECK(e.complete() && e.folds.size() == r.folds.size(), "quad_family (Epick): " << e.folds.size() << " folds, complete " << e.complete());
  for (std::size_t k = 0; k < e.folds.size() && k < r.folds.size(); ++k)
    CHECK(std::abs(e.folds[k].length.first - r.folds[k].length.first) < 1e-9, "quad_family (Epick): fold " << k);

  // a range between two folds: one count, no fold, the branches end on the range
  const RI::Family_result m = RI::solve_family<IT>(input, "E1", "E2", Q(2), Q(3));
  CHECK(m.complete() && m.folds.empty() && m.counts.size() == 1 && m.counts[0].count == 8,
        "quad_family on [2, 3]: " << m.folds.size() << " folds, counts " << m.counts.size() << ", complete " << m.complete());
  for (const auto& b : m.branches)
    CHECK(!b.curve.closed && b.curve.ends[0] == RI::Curve_end::BOUNDARY && b.curve.ends[1] == RI::Curve_end::BOUNDARY,
          "quad_family on [2, 3]: branches end on the range");
}

// ---------------------------------------------------------------- scene file and errors

template <class F>
static void expect_error(const std::string& name, F f, const std::vector<std::string>& needles)
{
  std::string what;
  try {
    f();
  } catch (const RI::Input_error& e) {
    what = e.what();
  }
  bool ok = !what.empty();
  for (const auto& n : needles) ok = ok && what.find(n) != std::string::npos;
  CHECK(ok, name << ": expected an error naming " << needles.front() << ", got '" << what << "'");
}

static void test_input()
{
  // the array form; a pair also in "distances" is taken out of them
  const std::string text = R"({"format": "rigid-incidence-scene/1", "bodies": [
      {"name": "c1", "points": {"A": [0, 0, 0], "B": [1, 0, 0], "C": [0, 1, 0]}},
      {"name": "c2", "points": {"A": [0, 0, 0], "B": [1, 0, 0], "D": [0, 0, 1]}}],
      "distances": [{"between": ["C", "D"], "length": 1}], "free_distance": ["D", "C"]})";
  std::istringstream in(text);
  RI::Scene s = RI::read_scene(in);
  CHECK(s.free_distance.declared && !s.free_distance.has_range && s.free_distance.had_length && s.distances.empty(),
        "array form: the listed distance is taken out");
  RI::Rigid_body_collection<Traits> hinge = RI::make_collection<Traits>(s);
  // a hinge whose free distance joins its two wings: A, B, C, D are then all at fixed
  // distances, one body placed by square roots of the free length: refused, and said so
  expect_error("clique", [&] { RI::solve_family<IT>(hinge, "C", "D", Q(1, 2), Q(3)); }, {"free distance C-D", "square roots"});
  expect_error("unknown point", [&] { RI::solve_family<IT>(hinge, "C", "Q", Q(0), Q(2)); }, {"no point 'Q'"});
  expect_error("one body", [&] { RI::solve_family<IT>(hinge, "A", "C", Q(0), Q(2)); }, {"body 'c1'", "fixes their distance"});
  expect_error("empty range", [&] { RI::solve_family<IT>(hinge, "C", "D", Q(2), Q(2)); }, {"range"});
  expect_error("negative range", [&] { RI::solve_family<IT>(hinge, "C", "D", Q(-1), Q(2)); }, {"range"});
  RI::Rigid_body_collection<Traits> fixed = hinge;
  fixed.add_distance("C", "D", Q(1), "distance C-D");
  expect_error("already fixed", [&] { RI::solve_family<IT>(fixed, "C", "D", Q(0), Q(2)); }, {"already fixes", "C-D"});
}

int main()
{
  test_determinant();
  test_input();
  test_quad_family();
  std::cout << "test_solve_family: " << checks << " checks, " << failures << " failures\n";
  return failures == 0 ? 0 : 1;
}
