// Copyright (c) 2026 Rigid_incidence contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// constraint_independence (the rigidity matroid at a random realization, reduced modulo a
// prime) against an exact oracle written here: the Jacobian of the same constraints at a
// random RATIONAL realization, ranked over Gmpq. Checked: every constraint's independence
// flag (rank of each prefix), every circuit (dependent, and every proper subset independent),
// the paper scenes (generically rigid, the distances that hold their bodies outside the
// covering set), deliberately over-constrained scenes (the extra distance is dependent and its
// circuit names the constraints it conflicts with), free points, and malformed calls.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Gmpq.h>
#include <CGAL/Random.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Rigid_incidence.h>
#include <CGAL/Rigid_incidence/rigidity_matroid.h>

#include "incidence_oracles.h"
#include "random_collections.h"
#include "test_check.h"

#include <array>
#include <iostream>
#include <string>
#include <vector>

namespace RI = CGAL::Rigid_incidence;
typedef CGAL::Gmpq Q;

// ---- the oracle: exact Jacobian over the rationals, ranked by incidence_oracles::rank -----
static std::size_t exact_rank(const std::vector<std::vector<Q>>& m) { return incidence_oracles::rank(m); }

// Rows of the constraints: bodies of D move by (w, t), the first fixed; free points by a
// translation. A point's motion in a distance row is taken through the first body of D (in
// index order) that contains it, as the package documents: another body would give a row that
// differs by incidence rows, the same independence but other circuits.
template <class C>
std::vector<std::vector<Q>> exact_rows(const C& c, const std::vector<std::size_t>& D, const std::vector<RI::Constraint>& ks,
                                       CGAL::Random& rng)
{
  std::vector<std::array<Q, 3>> y(c.number_of_points());
  for (auto& p : y) for (auto& x : p) x = Q(rng.get_int(-5000, 5000), rng.get_int(1, 113));
  std::vector<long> col(c.number_of_bodies(), -2);
  std::size_t n = 0;
  for (std::size_t k = 0; k < D.size(); ++k) { col[D[k]] = k == 0 ? -1 : long(n); if (k) n += 6; }
  std::vector<long> pcol(c.number_of_points(), -2);
  std::vector<bool> in_body(c.number_of_points(), false);
  for (std::size_t b = 0; b < c.number_of_bodies(); ++b) for (std::size_t p : c.body(b).points) in_body[p] = true;
  for (std::size_t p = 0; p < c.number_of_points(); ++p) if (!in_body[p]) { pcol[p] = long(n); n += 3; }
  // d/d(w,t) of (w x y + t) . u for a vector u: (y x u) . w + u . t
  auto motion = [&](std::vector<Q>& row, std::size_t v, const std::array<Q, 3>& u) {
    if (pcol[v] >= 0) { for (int q = 0; q < 3; ++q) row[std::size_t(pcol[v] + q)] += u[std::size_t(q)]; return; }
    long b = -2;
    for (std::size_t k : D) if (c.body(k).contains(v)) { b = col[k]; break; }
    if (b == -1) return;
    const auto& p = y[v];
    std::array<Q, 3> yxu = {p[1] * u[2] - p[2] * u[1], p[2] * u[0] - p[0] * u[2], p[0] * u[1] - p[1] * u[0]};
    for (int q = 0; q < 3; ++q) { row[std::size_t(b + q)] += yxu[std::size_t(q)]; row[std::size_t(b + 3 + q)] += u[std::size_t(q)]; }
  };
  auto body_motion = [&](std::vector<Q>& row, std::size_t body, std::size_t v, const std::array<Q, 3>& u) {
    long b = col[body];
    if (b == -1) return;
    const auto& p = y[v];
    std::array<Q, 3> yxu = {p[1] * u[2] - p[2] * u[1], p[2] * u[0] - p[0] * u[2], p[0] * u[1] - p[1] * u[0]};
    for (int q = 0; q < 3; ++q) { row[std::size_t(b + q)] += yxu[std::size_t(q)]; row[std::size_t(b + 3 + q)] += u[std::size_t(q)]; }
  };
  std::vector<std::vector<Q>> rows;
  for (const RI::Constraint& k : ks) {
    std::vector<Q> row(n, Q(0));
    if (!k.is_distance()) {
      std::array<Q, 3> e{Q(0), Q(0), Q(0)}, me{Q(0), Q(0), Q(0)};
      e[std::size_t(k.incidence.coordinate - 1)] = 1;
      me[std::size_t(k.incidence.coordinate - 1)] = -1;
      body_motion(row, k.incidence.body_a, k.incidence.point, e);
      body_motion(row, k.incidence.body_b, k.incidence.point, me);
    } else {
      std::array<Q, 3> d, md;
      for (int q = 0; q < 3; ++q) { d[std::size_t(q)] = y[k.a][std::size_t(q)] - y[k.b][std::size_t(q)]; md[std::size_t(q)] = -d[std::size_t(q)]; }
      motion(row, k.a, d);
      motion(row, k.b, md);
    }
    rows.push_back(row);
  }
  return rows;
}

template <class C>
void check_against_oracle(const C& c, const std::vector<std::size_t>& D, const std::vector<RI::Constraint>& ks,
                          const RI::Constraint_independence& r, const std::string& what, CGAL::Random& rng, bool circuits = true)
{
  auto rows = exact_rows(c, D, ks, rng);
  CHECK(r.constraints.size() == ks.size() && r.independent.size() == ks.size() && r.circuits.size() == ks.size(), what << ": sizes");
  std::vector<std::vector<Q>> prefix;
  std::size_t rank = 0;
  for (std::size_t i = 0; i < ks.size(); ++i) {
    prefix.push_back(rows[i]);
    std::size_t rk = exact_rank(prefix);
    bool indep = rk > rank;
    rank = rk;
    CHECK(indep == bool(r.independent[i]), what << ": constraint " << i << " (" << RI::describe(c, ks[i]) << "): oracle says "
                                                << (indep ? "independent" : "dependent"));
    if (!r.independent[i] && circuits) {
      const auto& z = r.circuits[i];
      CHECK(!z.empty() && z.back() == i, what << ": circuit of " << i << " does not end with it");
      std::vector<std::vector<Q>> m;
      for (std::size_t j : z) m.push_back(rows[j]);
      CHECK(exact_rank(m) == z.size() - 1, what << ": circuit of " << i << " is not dependent with corank 1");
      for (std::size_t drop = 0; drop < z.size(); ++drop) {
        std::vector<std::vector<Q>> sub;
        for (std::size_t j = 0; j < z.size(); ++j) if (j != drop) sub.push_back(rows[z[j]]);
        CHECK(exact_rank(sub) == sub.size(), what << ": circuit of " << i << " is not minimal");
      }
    } else if (r.independent[i]) {
      CHECK(r.circuits[i].empty(), what << ": an independent constraint has a circuit");
    }
  }
  CHECK(rank == r.rank, what << ": rank " << r.rank << ", oracle " << rank);
}

template <class Traits>
RI::Rigid_body_collection<Traits> paper(const std::string& f)
{
  return RI::standardize(RI::make_collection<Traits>(RI::read_scene(std::string(RIGID_INCIDENCE_DATA_DIR) + "/" + f)));
}

template <class Traits>
void run(const char* kernel)
{
  CGAL::Random rng(11);
  const std::string K = std::string(" [") + kernel + "]";
  // the paper scenes: generically rigid; no dependent incidence; the bodies outside the
  // covering set keep exactly 6 - (what the covering set already fixes) distances each
  for (const char* f : {"tetra.json", "quad.json", "pent.json"}) {
    auto c = paper<Traits>(f);
    auto t = RI::optimal_incidence_tree(c);
    auto s = RI::select_well_formed_incidences(c, t);
    auto ks = RI::system_constraints(c, t, s);
    auto r = RI::constraint_independence(c, t.covering_set, ks);
    check_against_oracle(c, t.covering_set, ks, r, f + K, rng);
    CHECK(r.generic_dof() == 0, f << K << ": generic dof " << r.generic_dof());
    for (std::size_t i = 0; i < ks.size(); ++i)
      if (!ks[i].is_distance() || ks[i].origin == RI::Constraint::SCENE_DISTANCE)
        CHECK(r.independent[i], f << K << ": " << RI::describe(c, ks[i]) << " dependent");
    // equations of the reduced system = variables (the tree's weight): square
    std::size_t equations = 0;
    for (std::size_t i = 0; i < ks.size(); ++i) equations += r.independent[i] && ks[i].origin != RI::Constraint::TREE_INCIDENCE;
    CHECK(long(equations) == t.weight, f << K << ": " << equations << " equations, " << t.weight << " variables");
    // a different seed gives the same matroid
    auto r2 = RI::constraint_independence(c, t.covering_set, ks, 99);
    CHECK(r2.independent == r.independent, f << K << ": seed changes the result");
  }
  // over-constrained: tetra with one more distance between points its bodies already fix
  {
    auto c = paper<Traits>("tetra.json");
    auto t = RI::optimal_incidence_tree(c);
    auto s = RI::select_well_formed_incidences(c, t);
    auto ks = RI::system_constraints(c, t, s);
    RI::Constraint extra;
    extra.origin = RI::Constraint::SCENE_DISTANCE;
    extra.a = c.point_index("G1");
    extra.b = c.point_index("G2");
    ks.push_back(extra);
    auto r = RI::constraint_independence(c, t.covering_set, ks);
    check_against_oracle(c, t.covering_set, ks, r, "tetra + G1-G2" + K, rng);
    CHECK(!r.independent.back() && r.circuits.back().size() >= 2, "tetra + G1-G2" << K << ": the extra distance is independent");
    CHECK(r.generic_dof() == 0, "tetra + G1-G2" << K << ": generic dof " << r.generic_dof());
    // a distance inside one body is dependent on nothing but itself being zero motion: a
    // circuit of size 1
    RI::Constraint inside;
    inside.origin = RI::Constraint::SCENE_DISTANCE;
    inside.a = c.point_index("G1");
    inside.b = c.point_index("D1");
    auto r1 = RI::constraint_independence(c, t.covering_set, {inside});
    CHECK(!r1.independent[0] && r1.circuits[0] == std::vector<std::size_t>{0}, "a distance inside one body" << K);
  }
  // over-constrained by incidences: a ring of four hinges (6(k-1) = 18 < rdof = 20); the
  // covering set is three bodies, the fourth is held by distances, two of which conflict
  {
    auto c = paper<Traits>("hinge_ring.json");
    auto t = RI::optimal_incidence_tree(c);
    auto s = RI::select_well_formed_incidences(c, t);
    auto ks = RI::system_constraints(c, t, s);
    auto r = RI::constraint_independence(c, t.covering_set, ks);
    check_against_oracle(c, t.covering_set, ks, r, "hinge ring" + K, rng);
    CHECK(RI::dof_count(c).dof == -2 && r.generic_dof() == 0, "hinge ring" << K << ": generic dof " << r.generic_dof());
    std::size_t dependent = r.dependent().size(), body = 0;
    for (std::size_t i = 0; i < ks.size(); ++i) body += ks[i].origin == RI::Constraint::BODY_DISTANCE;
    CHECK(t.non_covering.size() == 1 && body == 4 && dependent == 2, "hinge ring" << K << ": " << body << " body distances, "
                                                                              << dependent << " dependent");
  }
  // free points: a hinge c1-c2 and the far end E of a bar C-E held by a distance D-E
  {
    RI::Rigid_body_collection<Traits> c0;
    typedef typename Traits::FT FT;
    auto P = [](int x, int y, int z) { return Traits::point(FT(x), FT(y), FT(z)); };
    c0.add_body("c1", {{"A", P(0, 0, 0)}, {"B", P(1, 0, 0)}, {"C", P(0, 1, 0)}});
    c0.add_body("c2", {{"A", P(0, 0, 0)}, {"B", P(1, 0, 0)}, {"D", P(0, 0, 1)}});
    c0.add_body("bar", {{"C", P(0, 0, 0)}, {"E", P(1, 0, 0)}});
    c0.add_distance("D", "E", FT(3));
    auto c = RI::standardize(c0);
    CHECK(c.free_points().size() == 1 && c.label(c.free_points()[0]) == "E", "free point E" << K);
    auto dc = RI::dof_count(c);
    CHECK(dc.body_dof == 6 + 3 && dc.dof == 2 && dc.connected, "free point dof count" << K << ": " << dc.dof);
    auto t = RI::optimal_incidence_tree(c);
    CHECK(t.covering_set.size() == 2, "the covering set must hold D (a distance names it)" << K);
    auto s = RI::select_well_formed_incidences(c, t);
    auto ks = RI::system_constraints(c, t, s);
    auto r = RI::constraint_independence(c, t.covering_set, ks);
    check_against_oracle(c, t.covering_set, ks, r, "free point" + K, rng);
    CHECK(r.variables == 9 && r.generic_dof() == 2, "free point" << K << ": generic dof " << r.generic_dof());
  }
  // random collections with random distances: the oracle on every constraint; generic dof is
  // never below the count's dof
  int done = 0;
  for (int n = 0; n < 200 && done < 40; ++n) {
    random_collections::Generator g(rng);
    g.generate(n % 8, 2 + n % 7);
    const int extra = rng.get_int(0, 4);
    for (int e = 0; e < extra && g.s.coords.size() >= 2; ++e) {
      int a = rng.get_int(0, int(g.s.coords.size())), b = rng.get_int(0, int(g.s.coords.size()));
      if (a != b) g.s.distances.push_back({a, b});
    }
    RI::Rigid_body_collection<Traits> c;
    try {
      c = RI::standardize(random_collections::build<Traits>(g.s));
    } catch (const RI::Input_error&) {
      continue;
    }
    if (c.number_of_bodies() > 7 || !RI::dof_count(c).connected) continue;
    auto t = RI::optimal_incidence_tree(c);
    auto s = RI::select_well_formed_incidences(c, t);
    auto ks = RI::system_constraints(c, t, s);
    auto r = RI::constraint_independence(c, t.covering_set, ks, std::uint64_t(n));
    const std::string what = "random " + std::to_string(n) + " (" + g.s.shape + ")" + K;
    check_against_oracle(c, t.covering_set, ks, r, what, rng, ks.size() < 60);
    for (std::size_t i = 0; i < ks.size(); ++i)
      if (!ks[i].is_distance()) CHECK(r.independent[i], what << ": a well-formed incidence is dependent");
    ++done;
  }
  CHECK(done >= 40, "only " << done << " random collections" << K);
  std::cout << kernel << ": " << done << " random collections\n";
  // malformed calls name what is wrong
  {
    auto c = paper<Traits>("tetra.json");
    auto t = RI::optimal_incidence_tree(c);
    RI::Constraint bad;
    bad.origin = RI::Constraint::TREE_INCIDENCE;
    bad.incidence = RI::Incidence(c.point_index("G1"), t.covering_set[0], t.covering_set[1], 1);
    bool threw = false;
    try { RI::constraint_independence(c, t.covering_set, {bad}); } catch (const RI::Input_error& e) {
      threw = std::string(e.what()).find("G1") != std::string::npos;
    }
    CHECK(threw, "an incidence through a point its bodies do not share" << K);
    threw = false;
    try { RI::constraint_independence(c, t.covering_set, {}, 1, 3); } catch (const RI::Input_error&) { threw = true; }
    CHECK(threw, "the variable limit" << K);
  }
}

int main()
{
  run<RI::Rigid_incidence_traits<CGAL::Simple_cartesian<CGAL::Gmpq>>>("exact");
  run<RI::Rigid_incidence_traits<CGAL::Exact_predicates_inexact_constructions_kernel>>("epick");
  std::cout << checks << " checks, " << failures << " failures: " << (failures ? "FAILED" : "OK") << "\n";
  return failures ? 1 : 0;
}
