// Copyright (c) 2026 Rigid_incidence contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// rdof() (closed form), rdof_inclusion_exclusion() and dof_count() against an independent
// oracle: our own inclusion-exclusion over every subset Q of T with |Q| >= 2,
//   rdof(T) = sum (-1)^|Q| dof(intersection of Q),  dof = 0 / 3 / 5 for 0 / 1 / 2 points,
// with the intersections computed on bit sets of points, and our own union-find for the
// connected parts (bodies joined by a shared point or by a distance).
//
// Cases (each run with Simple_cartesian<Gmpq> and Epick):
//  - random collections of 2..10 bodies (chains, cycles, hinges, stars, fans, pools,
//    random attachment, two pieces; see random_collections.h), some with distances between
//    points of different bodies, and random subsets T of their bodies (in random order,
//    plus the empty set, the singletons and all bodies);
//  - the paper scenes: tetra's standard collection (7 bodies) has rdof = 36 = 6 (7 - 1);
//    tetra, quad and pent have dof 0;
//  - hand-made scenes with dof counted by hand: under-, well- and over-constrained, and
//    disconnected ones.
//
// Usage: test_rdof [seed] [number of random collections]

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Gmpq.h>
#include <CGAL/Random.h>
#include <CGAL/Rigid_incidence.h>

#include "random_collections.h"

#include <algorithm>
#include <bitset>
#include <chrono>
#include <cstdlib>
#include <iostream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace RI = CGAL::Rigid_incidence;
using random_collections::Structure;
using random_collections::Generator;
using random_collections::build;
typedef RI::Rigid_incidence_traits<CGAL::Simple_cartesian<CGAL::Gmpq>> Exact_traits;
typedef RI::Rigid_incidence_traits<CGAL::Exact_predicates_inexact_constructions_kernel> Epick_traits;

#include "test_check.h"

typedef std::bitset<256> Points;

// ===================================================================== the oracle
template <class Traits>
std::vector<Points> point_sets(const RI::Rigid_body_collection<Traits>& c)
{
  if (c.number_of_points() > 256) { std::cerr << "oracle: more than 256 points\n"; std::abort(); }
  std::vector<Points> r(c.number_of_bodies());
  for (std::size_t i = 0; i < c.number_of_bodies(); ++i) for (std::size_t p : c.body(i).points) r[i].set(p);
  return r;
}

// sum over Q subset of T, |Q| >= 2, of (-1)^|Q| dof(intersection of Q). Sets *bad if some
// intersection has 3 or more points (not a standard collection).
long my_rdof(const std::vector<Points>& bodies, const std::vector<std::size_t>& T, bool* bad = nullptr)
{
  const std::size_t m = T.size();
  if (m > 20) { std::cerr << "oracle: |T| > 20\n"; std::abort(); }
  long total = 0;
  for (unsigned long Q = 1; Q < (1ul << m); ++Q) {
    int size = __builtin_popcountl(Q);
    if (size < 2) continue;
    Points inter;
    inter.set();
    for (std::size_t i = 0; i < m; ++i) if (Q >> i & 1) inter &= bodies[T[i]];
    std::size_t k = inter.count();
    if (k >= 3 && bad) *bad = true;
    long dof = k == 0 ? 0 : k == 1 ? 3 : k == 2 ? 5 : 6;
    total += (size % 2 == 0 ? dof : -dof);
  }
  return total;
}

// Connected parts: bodies joined by a shared point or by a distance between their points.
template <class Traits>
std::set<std::set<std::size_t>> my_components(const RI::Rigid_body_collection<Traits>& c)
{
  const std::size_t n = c.number_of_bodies();
  std::vector<std::size_t> uf(n);
  for (std::size_t i = 0; i < n; ++i) uf[i] = i;
  auto find = [&](std::size_t x) { while (uf[x] != x) x = uf[x] = uf[uf[x]]; return x; };
  auto unite = [&](std::size_t a, std::size_t b) { uf[find(a)] = find(b); };
  const std::vector<Points> b = point_sets(c);
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = i + 1; j < n; ++j)
      if ((b[i] & b[j]).any()) unite(i, j);
  for (const auto& d : c.distances()) {
    std::size_t bi = n, bj = n;
    for (std::size_t i = 0; i < n; ++i) {
      if (b[i].test(d.a)) bi = i;
      if (b[i].test(d.b)) bj = i;
    }
    if (bi < n && bj < n) unite(bi, bj);
  }
  std::map<std::size_t, std::set<std::size_t>> parts;
  for (std::size_t i = 0; i < n; ++i) parts[find(i)].insert(i);
  std::set<std::set<std::size_t>> r;
  for (const auto& p : parts) r.insert(p.second);
  return r;
}

std::set<std::set<std::size_t>> as_sets(const std::vector<std::vector<std::size_t>>& v)
{
  std::set<std::set<std::size_t>> r;
  for (const auto& x : v) r.insert(std::set<std::size_t>(x.begin(), x.end()));
  return r;
}

std::string list(const std::vector<std::size_t>& T)
{
  std::string r = "{";
  for (std::size_t i = 0; i < T.size(); ++i) r += (i ? "," : "") + std::to_string(T[i]);
  return r + "}";
}

// rdof of T three ways, and, for T = all bodies, dof_count against the oracle.
template <class Traits>
void check_rdof(const RI::Rigid_body_collection<Traits>& c, const std::vector<std::size_t>& T, const std::string& name)
{
  const std::vector<Points> b = point_sets(c);
  bool bad = false;
  long mine = my_rdof(b, T, &bad);
  CHECK(!bad, name << ": T = " << list(T) << " has two bodies sharing 3 or more points (test error)");
  long closed = RI::rdof(c, T);
  long ie = RI::rdof_inclusion_exclusion(c, T);
  CHECK(closed == mine, name << ": rdof(T = " << list(T) << ") = " << closed << ", oracle " << mine);
  CHECK(ie == mine, name << ": rdof_inclusion_exclusion(T = " << list(T) << ") = " << ie << ", oracle " << mine);
}

template <class Traits>
RI::Dof_count check_dof_count(const RI::Rigid_body_collection<Traits>& c, const std::string& name)
{
  const std::size_t k = c.number_of_bodies();
  std::vector<std::size_t> all(k);
  for (std::size_t i = 0; i < k; ++i) all[i] = i;
  long removed = my_rdof(point_sets(c), all);
  long distances = long(c.distances().size());
  long dof = 6 * (long(k) - 1) - removed - distances;
  RI::Dof_count d = RI::dof_count(c);
  CHECK(d.bodies == long(k), name << ": dof_count bodies " << d.bodies << ", expected " << k);
  CHECK(d.body_dof == 6 * (long(k) - 1), name << ": body_dof " << d.body_dof << ", expected " << 6 * (long(k) - 1));
  CHECK(d.removed == removed, name << ": removed " << d.removed << ", oracle " << removed);
  CHECK(d.distances == distances, name << ": distances " << d.distances << ", expected " << distances);
  CHECK(d.dof == dof, name << ": dof " << d.dof << ", oracle " << dof);
  const std::string verdict = dof == 0 ? "well-constrained" : dof > 0 ? "under-constrained" : "over-constrained";
  CHECK(d.verdict() == verdict, name << ": verdict '" << d.verdict() << "', expected '" << verdict << "'");
  auto parts = my_components(c);
  CHECK(as_sets(d.components) == parts,
        name << ": " << d.components.size() << " components, oracle " << parts.size());
  CHECK(d.connected == (parts.size() <= 1), name << ": connected " << d.connected << ", oracle " << (parts.size() <= 1));
  return d;
}

// ===================================================================== random collections
template <class Traits>
void random_case(const Structure& s, CGAL::Random& rng, const std::string& name, long& subsets)
{
  RI::Rigid_body_collection<Traits> c = build<Traits>(s);
  const std::size_t n = c.number_of_bodies();
  std::vector<std::vector<std::size_t>> Ts;
  Ts.push_back({});
  std::vector<std::size_t> all(n);
  for (std::size_t i = 0; i < n; ++i) { all[i] = i; Ts.push_back({i}); }
  Ts.push_back(all);
  for (int r = 0; r < 12; ++r) {
    std::vector<std::size_t> T;
    for (std::size_t i = 0; i < n; ++i) if (rng.get_double() < 0.6) T.push_back(i);
    for (std::size_t i = T.size(); i > 1; --i) std::swap(T[i - 1], T[std::size_t(rng.get_int(0, int(i)))]);
    Ts.push_back(T);
  }
  for (const auto& T : Ts) check_rdof(c, T, name);
  subsets += long(Ts.size());
  check_dof_count(c, name);
}

void random_cases(unsigned seed0, int count)
{
  long subsets = 0;
  int with_distances = 0, disconnected = 0;
  std::map<std::string, int> per_shape;
  static const char* shapes[] = {"chain", "cycle", "hinge", "star", "fan", "pool", "attach", "two pieces"};
  for (int k = 0; k < count; ++k) {
    const unsigned seed = seed0 + unsigned(k);
    CGAL::Random rng(seed);
    Generator g(rng);
    int which = k % 8;
    g.generate(which, rng.get_int(2, 11));
    if (g.s.bodies.size() < 2) g.shape(6, 3);
    g.shuffle_bodies();
    ++per_shape[shapes[which]];
    // distances between points of different bodies, in one case out of three
    if (k % 3 == 0) {
      std::vector<int> pts = g.points_from(0);
      int nd = rng.get_int(1, 4);
      for (int attempt = 0; attempt < 50 && int(g.s.distances.size()) < nd; ++attempt) {
        std::vector<int> ab = g.pick(pts, 2);
        bool together = false;
        for (const auto& b : g.s.bodies)
          together = together || (std::count(b.begin(), b.end(), ab[0]) && std::count(b.begin(), b.end(), ab[1]));
        bool dup = false;
        for (const auto& d : g.s.distances)
          dup = dup || (d.first == ab[0] && d.second == ab[1]) || (d.first == ab[1] && d.second == ab[0]);
        if (!together && !dup) g.s.distances.push_back({ab[0], ab[1]});
      }
      ++with_distances;
    }
    std::ostringstream name;
    name << "random case " << k << " (seed " << seed << ", " << g.s.shape << ", " << g.s.bodies.size() << " bodies, "
         << g.s.distances.size() << " distances)";
    {
      CGAL::Random r1(seed ^ 0x5a5a5a5au), r2(seed ^ 0x5a5a5a5au); // the same subsets for both kernels
      random_case<Exact_traits>(g.s, r1, name.str() + " [Gmpq]", subsets);
      random_case<Epick_traits>(g.s, r2, name.str() + " [Epick]", subsets);
    }
    if (my_components(build<Exact_traits>(g.s)).size() > 1) ++disconnected;
  }
  std::cout << "random collections: " << count << " (";
  for (const auto& p : per_shape) std::cout << p.first << " " << p.second << (p.first == per_shape.rbegin()->first ? "" : ", ");
  std::cout << "), " << with_distances << " with distances, " << disconnected << " disconnected; " << subsets
            << " subsets T checked (both kernels)\n";
}

// ===================================================================== fixed cases
template <class Traits>
void paper_scenes(const std::string& kernel)
{
  for (const std::string file : {"tetra.json", "tetra_i.json", "quad.json", "pent.json"}) {
    auto c = RI::standardize(RI::make_collection<Traits>(RI::read_scene(std::string(RIGID_INCIDENCE_DATA_DIR) + "/" + file)));
    const std::string name = file + " [" + kernel + "]";
    std::vector<std::size_t> all(c.number_of_bodies());
    for (std::size_t i = 0; i < all.size(); ++i) all[i] = i;
    check_rdof(c, all, name);
    RI::Dof_count d = check_dof_count(c, name);
    CHECK(d.dof == 0 && d.verdict() == "well-constrained", name << ": dof " << d.dof << ", the paper says 0");
    CHECK(d.connected, name << ": not connected");
    if (file == "tetra.json") {
      CHECK(c.number_of_bodies() == 7, name << ": " << c.number_of_bodies() << " bodies, expected 7");
      CHECK(RI::rdof(c, all) == 36, name << ": rdof " << RI::rdof(c, all) << ", expected 36 = 6 (7 - 1)");
    }
    // every subset of the paper scenes (at most 9 bodies)
    for (unsigned m = 0; m < (1u << all.size()); ++m) {
      std::vector<std::size_t> T;
      for (std::size_t i = 0; i < all.size(); ++i) if (m >> i & 1) T.push_back(i);
      check_rdof(c, T, name);
    }
    std::cout << "  " << name << ": " << c.number_of_bodies() << " bodies, rdof " << d.removed << ", "
              << d.distances << " distances, dof " << d.dof << "\n";
  }
}

template <class Traits>
void hand_made(const std::string& kernel)
{
  typedef typename Traits::FT FT;
  // bodies as lists of point labels; the coordinates of point i are (i, i^2, i^3): no three
  // of them collinear, no four coplanar (moment curve)
  auto make = [](const std::vector<std::vector<int>>& bodies, const std::vector<std::pair<int, int>>& distances) {
    RI::Rigid_body_collection<Traits> c;
    auto pt = [](int p) { return Traits::point(FT(p), FT(p * p), FT(p * p * p)); };
    for (std::size_t i = 0; i < bodies.size(); ++i) {
      std::vector<std::pair<std::string, typename Traits::Point_3>> pts;
      for (int p : bodies[i]) pts.emplace_back("p" + std::to_string(p), pt(p));
      c.add_body("b" + std::to_string(i), pts);
    }
    for (const auto& d : distances)
      c.add_distance("p" + std::to_string(d.first), "p" + std::to_string(d.second),
                     Traits::squared_distance(pt(d.first), pt(d.second)));
    return c;
  };
  struct Case
  {
    std::string name;
    std::vector<std::vector<int>> bodies;
    std::vector<std::pair<int, int>> distances;
    long rdof, dof;               // by hand
    std::size_t components;
    std::string verdict;
  };
  const std::vector<Case> cases = {
    // two triangles sharing one point: a ball joint leaves 3 rotations
    {"two triangles sharing a point", {{0, 1, 2}, {0, 3, 4}}, {}, 3, 3, 1, "under-constrained"},
    {"... plus one distance", {{0, 1, 2}, {0, 3, 4}}, {{1, 3}}, 3, 2, 1, "under-constrained"},
    {"... plus three distances", {{0, 1, 2}, {0, 3, 4}}, {{1, 3}, {2, 4}, {1, 4}}, 3, 0, 1, "well-constrained"},
    {"... plus four distances", {{0, 1, 2}, {0, 3, 4}}, {{1, 3}, {2, 4}, {1, 4}, {2, 3}}, 3, -1, 1, "over-constrained"},
    // two triangles on a common axis: one rotation left
    {"two triangles sharing a pair", {{0, 1, 2}, {0, 1, 3}}, {}, 5, 1, 1, "under-constrained"},
    {"... plus one distance", {{0, 1, 2}, {0, 1, 3}}, {{2, 3}}, 5, 0, 1, "well-constrained"},
    {"... with a third body on the axis", {{0, 1, 2}, {0, 1, 3}, {0, 1, 4}}, {}, 10, 2, 1, "under-constrained"},
    // three bodies pairwise sharing disjoint pairs: 3 hinges for 2 free bodies
    {"three bodies sharing pairs in a cycle", {{1, 2, 5, 6}, {1, 2, 3, 4}, {3, 4, 5, 6}}, {}, 15, -3, 1, "over-constrained"},
    // one point in four bodies: 3 (4 - 1)
    {"four bodies through one point", {{0, 1, 2}, {0, 3, 4}, {0, 5, 6}, {0, 7, 8}}, {}, 9, 9, 1, "under-constrained"},
    // a pair in A and B, one of its points also in C: 5 + 3 + 3 - 3 = 8
    {"pair and point", {{0, 1, 2}, {0, 1, 3}, {0, 4, 5}}, {}, 8, 4, 1, "under-constrained"},
    // separate bodies
    {"two separate bodies", {{0, 1, 2}, {3, 4, 5}}, {}, 0, 6, 2, "under-constrained"},
    {"two separate bodies joined by a distance", {{0, 1, 2}, {3, 4, 5}}, {{2, 3}}, 0, 5, 1, "under-constrained"},
    {"a pair of bodies and a separate one", {{0, 1, 2}, {2, 3, 4}, {5, 6, 7}}, {}, 3, 9, 2, "under-constrained"},
    {"three separate bars", {{0, 1}, {2, 3}, {4, 5}}, {}, 0, 12, 3, "under-constrained"},
    // a single body: nothing to count
    {"one body", {{0, 1, 2, 3}}, {}, 0, 0, 1, "well-constrained"},
  };
  for (const Case& k : cases) {
    const std::string name = k.name + " [" + kernel + "]";
    auto c = make(k.bodies, k.distances);
    std::vector<std::size_t> all(c.number_of_bodies());
    for (std::size_t i = 0; i < all.size(); ++i) all[i] = i;
    // the hand values check the oracle, then the package is checked against both
    CHECK(my_rdof(point_sets(c), all) == k.rdof && my_components(c).size() == k.components,
          name << ": the oracle disagrees with the hand count (test error)");
    check_rdof(c, all, name);
    RI::Dof_count d = check_dof_count(c, name);
    CHECK(d.removed == k.rdof && d.dof == k.dof && d.verdict() == k.verdict && d.components.size() == k.components &&
            d.connected == (k.components == 1),
          name << ": dof_count gives rdof " << d.removed << ", dof " << d.dof << " (" << d.verdict() << "), "
               << d.components.size() << " components; by hand " << k.rdof << ", " << k.dof << " (" << k.verdict
               << "), " << k.components);
  }
  // Through standardize(): two triangles sharing a point plus one distance between them
  // become A, B and the implied body {0, 1, 3} (it shares {0, 1} with A and {0, 3} with B):
  // rdof = 3 + 5 + 5 - 3 = 10, dof = 12 - 10 = 2, as before standardization.
  {
    const std::string name = "two triangles, a point, a distance, standardized [" + kernel + "]";
    auto c = RI::standardize(make({{0, 1, 2}, {0, 3, 4}}, {{1, 3}}));
    std::size_t implied = 0;
    for (std::size_t i = 0; i < c.number_of_bodies(); ++i) implied += c.body(i).origin == RI::Body_origin::IMPLIED;
    CHECK(c.number_of_bodies() == 3 && implied == 1 && c.distances().empty(),
          name << ": " << c.number_of_bodies() << " bodies, " << implied << " implied, " << c.distances().size()
               << " distances; expected 3, 1, 0");
    std::vector<std::size_t> all(c.number_of_bodies());
    for (std::size_t i = 0; i < all.size(); ++i) all[i] = i;
    check_rdof(c, all, name);
    RI::Dof_count d = check_dof_count(c, name);
    CHECK(d.removed == 10 && d.dof == 2, name << ": rdof " << d.removed << ", dof " << d.dof << "; by hand 10, 2");
  }
}

int main(int argc, char** argv)
{
  unsigned seed = argc > 1 ? unsigned(std::strtoul(argv[1], nullptr, 10)) : 20260202u;
  int count = argc > 2 ? std::atoi(argv[2]) : 300;
  std::cout << "seed " << seed << " (rerun: test_rdof " << seed << " " << count << ")\n";
  auto t0 = std::chrono::steady_clock::now();
  hand_made<Exact_traits>("Gmpq");
  hand_made<Epick_traits>("Epick");
  std::cout << "paper scenes:\n";
  paper_scenes<Exact_traits>("Gmpq");
  paper_scenes<Epick_traits>("Epick");
  random_cases(seed, count);
  double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  std::cout << checks << " checks, " << secs << " s\n";
  if (failures) std::cout << "FAILED: " << failures << " failures (seed " << seed << ")\n";
  else std::cout << "OK\n";
  return failures ? 1 : 0;
}
