// Copyright (c) 2026 Rigid_incidence contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// is_well_formed (Definition 4 of well_formed_optimal_incidences.txt) against an independent
// oracle: the exact rank (rationals) of the Jacobian of the incidence equations (equation (1)
// of the paper, an infinitesimal rotation and translation per body, one body fixed) at a
// random rational configuration. A well-formed set has full rank and rdof(D, D) rows; the
// deliberately redundant sets are rank deficient and must be rejected with the right reason.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Gmpq.h>
#include <CGAL/Random.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Rigid_incidence.h>
#include <CGAL/Rigid_incidence/is_well_formed.h>

#include "incidence_oracles.h"

#include <iostream>
#include <map>
#include <string>
#include <vector>

namespace RI = CGAL::Rigid_incidence;
using namespace incidence_oracles;

static int failures = 0, checks = 0;
#define CHECK(cond, msg) do { ++checks; if (!(cond)) { ++failures; std::cerr << "FAIL line " << __LINE__ << ": " << msg << "\n"; } } while (0)

template <class Traits>
void run(const char* kernel)
{
  CGAL::Random rng(20261122);
  const std::string K = std::string(" [") + kernel + "]";
  auto load = [](const std::string& f) {
    return RI::standardize(RI::make_collection<Traits>(RI::read_scene(std::string(RIGID_INCIDENCE_DATA_DIR) + "/" + f)));
  };
  // tetra: the weight-3 tree over the covering set eliminates 15 incidences = rdof(D, D)
  {
    auto c = load("tetra.json");
    auto t = RI::optimal_incidence_tree(c);
    RI::Incidence_set I = tree_incidences(c, t);
    auto r = RI::is_well_formed(c, I, t.covering_set);
    CHECK(I.size() == 15, "tetra" << K << ": " << I.size() << " tree incidences, expected 15");
    CHECK(r.well_formed(), "tetra" << K << ": " << r.message);
    CHECK(jacobian_rank(c, I, t.covering_set, rng) == 15, "tetra" << K << ": the 15 incidences are not independent");
    // one more incidence of the same point pair: redundant, (b) on the two bodies
    const auto& e = t.edges.front();
    auto shared = c.common_points(e.parent, e.child);
    RI::Incidence_set J = I;
    J.insert(RI::Incidence(shared[1], e.parent, e.child, 3));
    auto rj = RI::is_well_formed(c, J, t.covering_set);
    CHECK(rj.violation == RI::Well_formedness_report::SUBSET_OVERCOUNT && rj.subset.size() == 2 && rj.count == 6 && rj.rdof == 5,
          "tetra + 6th incidence of a pair" << K << ": " << rj.message);
    CHECK(jacobian_rank(c, J, t.covering_set, rng) == 15, "tetra + 6th incidence" << K << ": rank should stay 15");
    // one less: essential incidences missing, (c)
    RI::Incidence_set L(std::vector<RI::Incidence>(I.begin() + 1, I.end()));
    auto rl = RI::is_well_formed(c, L, t.covering_set);
    CHECK(rl.violation == RI::Well_formedness_report::COUNT_MISMATCH && rl.count == 14 && rl.rdof == 15,
          "tetra - 1" << K << ": " << rl.message);
    CHECK(jacobian_rank(c, L, t.covering_set, rng) == 14, "tetra - 1" << K << ": still independent");
    // all bodies of tetra: the three implied triangles add their incidences, rdof(D, D) = 36
    std::vector<std::size_t> all;
    for (std::size_t b = 0; b < c.number_of_bodies(); ++b) all.push_back(b);
    CHECK(RI::rdof(c, all) == 36, "tetra" << K << ": rdof of the 7 bodies");
  }
  // a local incidence cycle: three bodies through one point, coordinate 1 matched around them
  {
    RI::Rigid_body_collection<Traits> c;
    typedef typename Traits::Point_3 P;
    c.add_body("a", {{"V", P(0, 0, 0)}, {"A1", P(1, 0, 0)}, {"A2", P(0, 1, 0)}});
    c.add_body("b", {{"V", P(0, 0, 0)}, {"B1", P(1, 0, 0)}, {"B2", P(0, 1, 0)}});
    c.add_body("d", {{"V", P(0, 0, 0)}, {"D1", P(1, 0, 0)}, {"D2", P(0, 1, 0)}});
    std::size_t v = c.point_index("V");
    RI::Incidence_set I;
    I.insert(v, 0, 1, {1});
    I.insert(v, 1, 2, {1});
    I.insert(v, 0, 2, {1});
    auto r = RI::is_well_formed(c, I, {0, 1, 2});
    CHECK(r.violation == RI::Well_formedness_report::LOCAL_CYCLE && r.cycle.size() == 3, "local cycle" << K << ": " << r.message);
    CHECK(jacobian_rank(c, I, {0, 1, 2}, rng) == 2, "local cycle" << K << ": rank should be 2");
    // the well-formed choice: two triples (a spanning tree of the point's copies)
    RI::Incidence_set W;
    W.insert(v, 0, 1, {1, 2, 3});
    W.insert(v, 1, 2, {1, 2, 3});
    auto rw = RI::is_well_formed(c, W, {0, 1, 2});
    CHECK(rw.well_formed(), "star of triples" << K << ": " << rw.message);
    CHECK(jacobian_rank(c, W, {0, 1, 2}, rng) == 6, "star of triples" << K << ": rank");
    // an invalid incidence: a point the bodies do not share
    RI::Incidence_set X;
    X.insert(RI::Incidence(c.point_index("A1"), 0, 1, 1));
    CHECK(RI::is_well_formed(c, X, {0, 1, 2}).violation == RI::Well_formedness_report::INVALID, "invalid incidence" << K);
  }
  // all six incidences of a shared pair: (b) fails on the pair, the Jacobian has rank 5
  {
    RI::Rigid_body_collection<Traits> c;
    typedef typename Traits::Point_3 P;
    c.add_body("a", {{"U", P(0, 0, 0)}, {"W", P(1, 0, 0)}, {"A", P(0, 1, 0)}});
    c.add_body("b", {{"U", P(0, 0, 0)}, {"W", P(1, 0, 0)}, {"B", P(0, 0, 1)}});
    RI::Incidence_set I;
    I.insert(c.point_index("U"), 0, 1, {1, 2, 3});
    I.insert(c.point_index("W"), 0, 1, {1, 2, 3});
    auto r = RI::is_well_formed(c, I, {0, 1});
    CHECK(r.violation == RI::Well_formedness_report::SUBSET_OVERCOUNT && r.count == 6 && r.rdof == 5, "pair, 6 incidences" << K << ": " << r.message);
    CHECK(jacobian_rank(c, I, {0, 1}, rng) == 5, "pair, 6 incidences" << K << ": rank should be 5");
  }
  // quad and pent: the tree's incidences plus, for pent, the triple of q5 between c2 and c3
  for (const char* f : {"quad.json", "pent.json"}) {
    auto c = load(f);
    auto t = RI::optimal_incidence_tree(c);
    RI::Incidence_set I = tree_incidences(c, t);
    long rd = RI::rdof(c, t.covering_set);
    if (std::string(f) == "pent.json") {
      std::size_t c2 = c.body_index("c2"), c3 = c.body_index("c3");
      I.insert(c.point_index("q5"), c2, c3, {1, 2, 3});
      CHECK(rd == 23, f << K << ": rdof of the covering set " << rd << ", expected 23");
    } else {
      CHECK(rd == 20, f << K << ": rdof of the covering set " << rd << ", expected 20 (4 hinges on the square)");
    }
    auto r = RI::is_well_formed(c, I, t.covering_set);
    CHECK(r.well_formed() && long(I.size()) == rd, f << K << ": " << r.message);
    CHECK(long(jacobian_rank(c, I, t.covering_set, rng)) == rd, f << K << ": the selected incidences are dependent");
  }
}

int main()
{
  run<RI::Rigid_incidence_traits<CGAL::Simple_cartesian<CGAL::Gmpq>>>("exact");
  run<RI::Rigid_incidence_traits<CGAL::Exact_predicates_inexact_constructions_kernel>>("epick");
  std::cout << checks << " checks, " << failures << " failures: " << (failures ? "FAILED" : "OK") << "\n";
  return failures ? 1 : 0;
}
