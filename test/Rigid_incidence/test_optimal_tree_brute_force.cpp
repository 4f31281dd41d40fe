// Copyright (c) 2026 Rigid_incidence contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// optimal_incidence_tree() against an independent brute force.
//
// The oracle (brute_force below) uses nothing of the package but the body point lists of
// the collection: it enumerates EVERY non-empty set S of bodies covering the shared points,
// EVERY labelled spanning tree of the complete graph on S (Pruefer sequences, each tree
// exactly once), with weights 6/3/1 for 0/1/2 common points, and EVERY root. It returns
// the minimum weight, the minimum depth sum among the minimum-weight rooted trees, the
// number of (edge set, root) pairs attaining both, and the smallest tie-break key
// (implied bodies in S, root implied, sorted S, root, sorted edges) among them.
//
// Cases (each run with Simple_cartesian<Gmpq> and Epick):
//  - random collections of 2..8 bodies: chains, cycles, hinges, stars, fans through one
//    point, random subsets of a small pool, random attachment, disconnected pieces; half of
//    them with some bodies turned into implied bodies (coordinates dropped), so that the
//    tie-break on implied bodies matters;
//  - random scenes with distances that go through standardize() (implied bodies appear),
//    and tetra-like scenes (three bodies in a cycle of shared points plus distances);
//  - the paper scenes tetra, tetra_i, quad, pent;
//  - small hand-made edge cases (no shared point, hinge of bodies, two pieces);
//  - small budgets (Incidence_tree_options: max_trees, max_candidates, max_search_nodes,
//    exact_limit 0) on the random and hand-made cases: the tree must stay valid, and what
//    the result claims (proven_optimal, ties_complete) must agree with the oracle;
//  - larger collections: a ring of 22 triangles (weight checked against a cheaper oracle:
//    every covering set, its minimum spanning tree weight by our own Kruskal over the three
//    weight classes; plus validity), a grid of 24 triangles (the covering sets number in
//    the millions: validity and proven_optimal only), and a hinge of 9 bodies with leaves
//    (18 bodies; the cheaper oracle proves the optimal covering set unique and a weight-1
//    clique, hence depth sum 8 and 9 ties). Run times are printed, not asserted.
//
// Usage: test_optimal_tree_brute_force [seed] [number of random cases]

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Gmpq.h>
#include <CGAL/Random.h>
#include <CGAL/Rigid_incidence.h>

#include "random_collections.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cstdlib>
#include <functional>
#include <iostream>
#include <limits>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

namespace RI = CGAL::Rigid_incidence;
using random_collections::Structure;
using random_collections::Generator;
using random_collections::build;
typedef RI::Rigid_incidence_traits<CGAL::Simple_cartesian<CGAL::Gmpq>> Exact_traits;
typedef RI::Rigid_incidence_traits<CGAL::Exact_predicates_inexact_constructions_kernel> Epick_traits;

#include "test_check.h"

typedef std::vector<std::vector<std::size_t>> Body_points; // per body: sorted point ids

// ===================================================================== the oracle
struct Key
{
  long implied = 0;                                   // implied bodies in the covering set
  int root_implied = 0;
  std::vector<std::size_t> set;                       // sorted body indices
  std::size_t root = 0;
  std::vector<std::pair<std::size_t, std::size_t>> edges; // (min, max) body indices, sorted
  bool operator<(const Key& o) const
  { return std::tie(implied, root_implied, set, root, edges) < std::tie(o.implied, o.root_implied, o.set, o.root, o.edges); }
  bool operator==(const Key& o) const
  { return std::tie(implied, root_implied, set, root, edges) == std::tie(o.implied, o.root_implied, o.set, o.root, o.edges); }
};

std::string to_string(const Key& k)
{
  std::ostringstream os;
  os << "{implied " << k.implied << ", root implied " << k.root_implied << ", S [";
  for (std::size_t i = 0; i < k.set.size(); ++i) os << (i ? " " : "") << k.set[i];
  os << "], root " << k.root << ", edges [";
  for (std::size_t i = 0; i < k.edges.size(); ++i) os << (i ? " " : "") << k.edges[i].first << "-" << k.edges[i].second;
  os << "]}";
  return os.str();
}

struct Oracle
{
  long weight = std::numeric_limits<long>::max();
  long path_sum = std::numeric_limits<long>::max();
  long depth_sum = std::numeric_limits<long>::max();
  std::size_t ties = 0;
  Key best;                  // smallest tie-break key among the tied optima
  long covering_sets = 0;
  long trees = 0;
};

// Weight of the pair (i, j): 6, 3, 1 for 0, 1, 2 common points; -1 for 3 or more.
std::vector<std::vector<int>> pair_weights(const Body_points& b)
{
  std::size_t n = b.size();
  std::vector<std::vector<int>> w(n, std::vector<int>(n, 0));
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = 0; j < n; ++j) {
      if (i == j) continue;
      std::size_t common = 0;
      for (std::size_t p : b[i]) if (std::find(b[j].begin(), b[j].end(), p) != b[j].end()) ++common;
      w[i][j] = common == 0 ? 6 : common == 1 ? 3 : common == 2 ? 1 : -1;
    }
  return w;
}

// Per shared point (in two or more bodies): the bodies through it.
// The points a distance names (set by points_of() for the collection at hand): the tree must
// cover them as well as the shared points, since a distance is an equation between them.
static std::set<std::size_t> named_by_distances;
// The distances' pairs of points, for the second criterion (the tree edges between them).
static std::vector<std::pair<std::size_t, std::size_t>> distance_pairs;

// Per point to cover (shared, or named by a distance): the bodies through it.
std::vector<std::vector<std::size_t>> shared_point_bodies(const Body_points& b)
{
  std::map<std::size_t, std::vector<std::size_t>> through;
  for (std::size_t i = 0; i < b.size(); ++i) for (std::size_t p : b[i]) through[p].push_back(i);
  std::vector<std::vector<std::size_t>> r;
  for (const auto& t : through)
    if (t.second.size() >= 2 || named_by_distances.count(t.first)) r.push_back(t.second);
  return r;
}

Oracle brute_force(const Body_points& bodies, const std::vector<bool>& implied)
{
  const std::size_t n = bodies.size();
  Oracle o;
  if (n == 0 || n > 10) return o;
  const std::vector<std::vector<int>> w = pair_weights(bodies);
  std::vector<unsigned> need; // per shared point: mask of bodies through it
  for (const auto& t : shared_point_bodies(bodies)) {
    unsigned m = 0;
    for (std::size_t i : t) m |= 1u << i;
    need.push_back(m);
  }
  for (unsigned S = 1; S < (1u << n); ++S) {
    bool covers = true;
    for (unsigned m : need) if (!(m & S)) { covers = false; break; }
    if (!covers) continue;
    ++o.covering_sets;
    std::vector<std::size_t> v;
    for (std::size_t i = 0; i < n; ++i) if (S >> i & 1) v.push_back(i);
    const std::size_t k = v.size();
    long implied_count = 0;
    for (std::size_t i : v) implied_count += implied[i] ? 1 : 0;

    auto evaluate = [&](const std::vector<std::pair<std::size_t, std::size_t>>& e) { // local indices
      ++o.trees;
      long wt = 0;
      for (const auto& x : e) wt += w[v[x.first]][v[x.second]];
      if (wt > o.weight) return;
      if (wt < o.weight) { o.weight = wt; o.path_sum = o.depth_sum = std::numeric_limits<long>::max(); o.ties = 0; }
      std::vector<std::vector<std::size_t>> adj(k);
      for (const auto& x : e) { adj[x.first].push_back(x.second); adj[x.second].push_back(x.first); }
      // second criterion: per distance the fewest tree edges between a body through each of
      // its points (breadth-first search from every body: all distances in the tree)
      std::vector<std::vector<long>> hops(k, std::vector<long>(k, -1));
      for (std::size_t r = 0; r < k; ++r) {
        std::vector<std::size_t> queue{r};
        hops[r][r] = 0;
        for (std::size_t q = 0; q < queue.size(); ++q)
          for (std::size_t u : adj[queue[q]])
            if (hops[r][u] < 0) { hops[r][u] = hops[r][queue[q]] + 1; queue.push_back(u); }
      }
      auto holds = [&](std::size_t i, std::size_t p) { return std::find(bodies[v[i]].begin(), bodies[v[i]].end(), p) != bodies[v[i]].end(); };
      long ps = 0;
      for (const auto& d : distance_pairs) {
        long fewest = -1;
        for (std::size_t i = 0; i < k; ++i)
          for (std::size_t j = 0; j < k; ++j)
            if (holds(i, d.first) && holds(j, d.second) && (fewest < 0 || hops[i][j] < fewest)) fewest = hops[i][j];
        if (fewest >= 0) ps += fewest;
      }
      if (ps > o.path_sum) return;
      if (ps < o.path_sum) { o.path_sum = ps; o.depth_sum = std::numeric_limits<long>::max(); o.ties = 0; }
      std::vector<std::pair<std::size_t, std::size_t>> body_edges;
      for (const auto& x : e) body_edges.push_back(std::minmax(v[x.first], v[x.second]));
      std::sort(body_edges.begin(), body_edges.end());
      for (std::size_t r = 0; r < k; ++r) {
        std::vector<long> depth(k, -1);
        std::vector<std::size_t> queue{r};
        depth[r] = 0;
        long ds = 0;
        for (std::size_t q = 0; q < queue.size(); ++q)
          for (std::size_t u : adj[queue[q]])
            if (depth[u] < 0) { depth[u] = depth[queue[q]] + 1; ds += depth[u]; queue.push_back(u); }
        if (queue.size() != k) { std::cerr << "oracle: decoded a non-tree\n"; std::abort(); }
        if (ds > o.depth_sum) continue;
        Key key;
        key.implied = implied_count;
        key.root_implied = implied[v[r]] ? 1 : 0;
        key.set = v;
        key.root = v[r];
        key.edges = body_edges;
        if (ds < o.depth_sum) { o.depth_sum = ds; o.ties = 0; o.best = key; }
        ++o.ties;
        if (key < o.best) o.best = key;
      }
    };

    if (k == 1) { evaluate({}); continue; }
    // Every Pruefer sequence of length k - 2 over {0..k-1}: every labelled tree once.
    std::vector<std::size_t> seq(k - 2, 0);
    while (true) {
      std::vector<int> degree(k, 1);
      for (std::size_t x : seq) ++degree[x];
      std::vector<std::pair<std::size_t, std::size_t>> e;
      for (std::size_t x : seq) {
        std::size_t leaf = 0;
        while (degree[leaf] != 1) ++leaf;
        e.push_back({leaf, x});
        --degree[leaf];
        --degree[x];
      }
      std::size_t a = k, b = k;
      for (std::size_t u = 0; u < k; ++u) if (degree[u] == 1) { if (a == k) a = u; else b = u; }
      e.push_back({a, b});
      evaluate(e);
      std::size_t pos = 0;
      while (pos < seq.size() && ++seq[pos] == k) seq[pos++] = 0;
      if (pos == seq.size()) break;
    }
  }
  return o;
}

// ===================================================================== checks
template <class Traits>
Body_points points_of(const RI::Rigid_body_collection<Traits>& c)
{
  Body_points b;
  for (std::size_t i = 0; i < c.number_of_bodies(); ++i) b.push_back(c.body(i).points);
  named_by_distances.clear();
  distance_pairs.clear();
  for (const auto& d : c.distances()) {
    named_by_distances.insert(d.a);
    named_by_distances.insert(d.b);
    distance_pairs.push_back({d.a, d.b});
  }
  return b;
}

template <class Traits>
std::vector<bool> implied_of(const RI::Rigid_body_collection<Traits>& c)
{
  std::vector<bool> r;
  for (std::size_t i = 0; i < c.number_of_bodies(); ++i) {
    bool all = true;
    for (bool h : c.body(i).has_coordinates) all = all && h;
    r.push_back(!all);
  }
  return r;
}

// The collection as text, printed once for a failing case: "b0{p1,p4,p7} b1*{...}" (* implied).
template <class Traits>
std::string describe(const RI::Rigid_body_collection<Traits>& c)
{
  std::string r;
  std::vector<bool> imp = implied_of(c);
  for (std::size_t i = 0; i < c.number_of_bodies(); ++i) {
    r += (i ? " " : "") + std::to_string(i) + ":" + c.body(i).name + (imp[i] ? "*" : "") + "{";
    for (std::size_t k = 0; k < c.body(i).points.size(); ++k) r += (k ? "," : "") + c.label(c.body(i).points[k]);
    r += "}";
  }
  return r;
}

// The returned tree is a rooted spanning tree of a covering set, consistent with itself.
template <class Traits>
void check_valid(const RI::Rigid_body_collection<Traits>& c, const RI::Incidence_tree& t, const std::string& name)
{
  const Body_points bodies = points_of(c);
  const std::size_t n = bodies.size();
  const auto w = pair_weights(bodies);
  const std::size_t npos = RI::Incidence_tree::npos;
  std::vector<int> in(n, -1); // 1 covering, 0 non-covering
  bool ok = std::is_sorted(t.covering_set.begin(), t.covering_set.end()) &&
            std::is_sorted(t.non_covering.begin(), t.non_covering.end());
  for (std::size_t b : t.covering_set) { ok = ok && b < n && in[b] == -1; if (b < n) in[b] = 1; }
  for (std::size_t b : t.non_covering) { ok = ok && b < n && in[b] == -1; if (b < n) in[b] = 0; }
  for (std::size_t b = 0; b < n; ++b) ok = ok && in[b] != -1;
  CHECK(ok, name << ": covering_set and non_covering do not partition the bodies");
  if (!ok) return;
  for (const auto& through : shared_point_bodies(bodies)) {
    bool covered = false;
    for (std::size_t b : through) covered = covered || in[b] == 1;
    CHECK(covered, name << ": a shared point is not covered by the covering set");
  }
  CHECK(t.root < n && in[t.root] == 1, name << ": root " << t.root << " not in the covering set");
  CHECK(t.parent.size() == n && t.depth.size() == n, name << ": parent/depth not sized per body");
  if (!(t.root < n && in[t.root] == 1 && t.parent.size() == n && t.depth.size() == n)) return;
  CHECK(t.edges.size() + 1 == t.covering_set.size(),
        name << ": " << t.edges.size() << " edges for " << t.covering_set.size() << " bodies");
  std::vector<bool> reached(n, false);
  reached[t.root] = true;
  long wsum = 0;
  bool edges_ok = true;
  for (const auto& e : t.edges) {
    bool good = e.parent < n && e.child < n && in[e.parent] == 1 && in[e.child] == 1 && reached[e.parent] &&
                !reached[e.child];
    if (!good) { edges_ok = false; break; }
    reached[e.child] = true;
    CHECK(t.parent[e.child] == e.parent, name << ": parent[" << e.child << "] disagrees with its edge");
    CHECK(t.depth[e.child] == t.depth[e.parent] + 1, name << ": depth of " << e.child << " is not its parent's + 1");
    CHECK(e.weight == w[e.parent][e.child] && e.weight > 0,
          name << ": edge " << e.parent << "-" << e.child << " has weight " << e.weight << ", oracle "
               << w[e.parent][e.child]);
    wsum += w[e.parent][e.child];
  }
  CHECK(edges_ok, name << ": edges are not a breadth-first rooted tree over the covering set");
  for (std::size_t b : t.covering_set) CHECK(reached[b], name << ": body " << b << " not reached from the root");
  CHECK(t.parent[t.root] == npos && t.depth[t.root] == 0, name << ": root has a parent or nonzero depth");
  for (std::size_t b : t.non_covering)
    CHECK(t.parent[b] == npos && t.depth[b] == -1, name << ": non-covering body " << b << " has a parent or depth");
  long dsum = 0;
  for (std::size_t b : t.covering_set) dsum += t.depth[b];
  CHECK(wsum == t.weight, name << ": edge weights sum to " << wsum << ", weight says " << t.weight);
  CHECK(dsum == t.depth_sum, name << ": depths sum to " << dsum << ", depth_sum says " << t.depth_sum);
}

Key key_of(const RI::Incidence_tree& t, const std::vector<bool>& implied)
{
  Key k;
  for (std::size_t b : t.covering_set) k.implied += implied[b] ? 1 : 0;
  k.root_implied = t.root < implied.size() && implied[t.root] ? 1 : 0;
  k.set = t.covering_set;
  k.root = t.root;
  for (const auto& e : t.edges) k.edges.push_back(std::minmax(e.parent, e.child));
  std::sort(k.edges.begin(), k.edges.end());
  return k;
}

struct Stats
{
  long cases = 0, implied_cases = 0, tiebreak_cases = 0, max_ties = 0;
  long budget_runs = 0, budget_unproven = 0;
  double package_seconds = 0, oracle_seconds = 0;
};
static Stats stats;

template <class Traits>
void check_against_oracle(const RI::Rigid_body_collection<Traits>& c, const Oracle& o, const std::string& name)
{
  const int failures_before = failures;
  struct Dump { const int& before; const RI::Rigid_body_collection<Traits>& c; const std::string& name;
    ~Dump() { if (failures > before) std::cerr << "  collection of " << name << ": " << describe(c) << "\n"; } }
    dump{failures_before, c, name};
  ++stats.cases;
  RI::Incidence_tree t;
  try {
    auto t0 = std::chrono::steady_clock::now();
    t = RI::optimal_incidence_tree(c);
    stats.package_seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  } catch (const std::exception& e) {
    CHECK(false, name << ": optimal_incidence_tree threw: " << e.what());
    return;
  }
  CHECK(t.weight == o.weight, name << ": weight " << t.weight << ", oracle " << o.weight);
  CHECK(t.distance_path_sum == o.path_sum, name << ": distance paths " << t.distance_path_sum << ", oracle " << o.path_sum);
  CHECK(t.depth_sum == o.depth_sum, name << ": depth sum " << t.depth_sum << ", oracle " << o.depth_sum);
  CHECK(t.ties == o.ties, name << ": ties " << t.ties << ", oracle " << o.ties);
  CHECK(t.proven_optimal, name << ": not proven optimal (" << t.strategy << ")");
  CHECK(t.ties_complete, name << ": ties not complete");
  check_valid(c, t, name);
  const std::vector<bool> implied = implied_of(c);
  const Key k = key_of(t, implied);
  // The first tie-break: fewest implied bodies among the tied optima.
  CHECK(k.implied == o.best.implied,
        name << ": covering set has " << k.implied << " implied bodies, the tied optima allow " << o.best.implied);
  // The full documented tie-break order.
  CHECK(k == o.best, name << ": tie-break picked " << to_string(k) << ", oracle " << to_string(o.best));
  if (std::count(implied.begin(), implied.end(), true)) ++stats.implied_cases;
  if (o.ties > 1 && std::count(implied.begin(), implied.end(), true)) ++stats.tiebreak_cases;
  stats.max_ties = std::max<long>(stats.max_ties, long(o.ties));
}

// With small budgets (Incidence_tree_options), the result may be suboptimal but must say so:
// whatever it claims as proven must match the oracle, and the tree must stay valid.
template <class Traits>
void check_budgets(const RI::Rigid_body_collection<Traits>& c, const Oracle& o, const std::string& name,
                   std::size_t variant)
{
  const int failures_before = failures;
  struct Dump { const int& before; const RI::Rigid_body_collection<Traits>& c; const std::string& name;
    ~Dump() { if (failures > before) std::cerr << "  collection of " << name << ": " << describe(c) << "\n"; } }
    dump{failures_before, c, name};
  struct Budget { const char* what; RI::Incidence_tree_options opt; };
  std::vector<Budget> budgets(4);
  budgets[0].what = "max_trees";        budgets[0].opt.max_trees = 1 + variant % 6;
  budgets[1].what = "max_candidates";   budgets[1].opt.max_candidates = 1;
  budgets[2].what = "max_search_nodes"; budgets[2].opt.max_search_nodes = 2 + variant % 9;
  budgets[3].what = "exact_limit 0";    budgets[3].opt.exact_limit = 0;
  for (const Budget& b : budgets) {
    std::ostringstream nm;
    nm << name << " {" << b.what << " = "
       << (b.what[4] == 't' ? b.opt.max_trees : b.what[4] == 'c' ? b.opt.max_candidates
           : b.what[4] == 's' ? b.opt.max_search_nodes : b.opt.exact_limit) << "}";
    RI::Incidence_tree t;
    try { t = RI::optimal_incidence_tree(c, b.opt); }
    catch (const std::exception& e) { CHECK(false, nm.str() << ": threw: " << e.what()); continue; }
    ++stats.budget_runs;
    if (!t.proven_optimal) ++stats.budget_unproven;
    check_valid(c, t, nm.str());
    CHECK(t.weight >= o.weight, nm.str() << ": weight " << t.weight << " below the optimum " << o.weight);
    if (b.opt.exact_limit == 0)
      CHECK(!t.proven_optimal, nm.str() << ": the heuristic claims a proven optimum");
    if (t.proven_optimal) {
      CHECK(t.weight == o.weight && t.distance_path_sum == o.path_sum && t.depth_sum == o.depth_sum,
            nm.str() << ": proven_optimal, but weight " << t.weight << ", distance paths " << t.distance_path_sum
                     << ", depth sum " << t.depth_sum << "; oracle " << o.weight << ", " << o.path_sum << ", " << o.depth_sum);
      if (t.ties_complete)
        CHECK(t.ties == o.ties, nm.str() << ": proven_optimal and ties_complete, but ties " << t.ties << " ("
                                         << t.trees_examined << " trees examined); oracle " << o.ties);
    }
  }
}

Oracle timed_oracle(const Body_points& b, const std::vector<bool>& implied)
{
  auto t0 = std::chrono::steady_clock::now();
  Oracle o = brute_force(b, implied);
  stats.oracle_seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return o;
}

// ===================================================================== the cases
void random_cases(unsigned seed0, int count)
{
  static const char* shapes[] = {"chain", "cycle", "hinge", "star", "fan", "pool", "attach", "two pieces"};
  std::map<std::string, int> per_shape;
  for (int k = 0; k < count; ++k) {
    const unsigned seed = seed0 + unsigned(k);
    CGAL::Random rng(seed);
    Generator g(rng);
    int which = k % 8;
    int n = rng.get_int(2, 9);
    g.generate(which, n);
    if (g.s.bodies.size() < 2) { g.s.bodies.clear(); g.shape(6, n < 2 ? 2 : n); }
    if (g.s.bodies.size() < 2 || g.s.bodies.size() > 8) { CHECK(false, "generator: seed " << seed << " gave " << g.s.bodies.size() << " bodies"); continue; }
    g.shuffle_bodies();
    g.s.implied.assign(g.s.bodies.size(), false);
    if (k % 2 == 1)
      for (std::size_t i = 0; i < g.s.bodies.size(); ++i) g.s.implied[i] = rng.get_double() < 0.35;
    // every third case: 1 to 3 distances between points of two different bodies (the second
    // criterion, the tree edges between each distance's bodies)
    if (k % 3 == 2)
      for (int d = rng.get_int(1, 4); d > 0; --d) {
        const std::size_t a = std::size_t(rng.get_int(0, int(g.s.bodies.size())));
        const std::size_t b = (a + 1 + std::size_t(rng.get_int(0, int(g.s.bodies.size()) - 1))) % g.s.bodies.size();
        const int p = g.s.bodies[a][std::size_t(rng.get_int(0, int(g.s.bodies[a].size())))];
        const int q = g.s.bodies[b][std::size_t(rng.get_int(0, int(g.s.bodies[b].size())))];
        if (p != q) g.s.distances.push_back({p, q});
      }
    ++per_shape[shapes[which]];
    std::ostringstream name;
    name << "random case " << k << " (seed " << seed << ", " << g.s.shape << ", " << g.s.bodies.size() << " bodies"
         << (k % 2 ? ", some implied" : "") << ", " << g.s.distances.size() << " distances)";
    auto ce = build<Exact_traits>(g.s);
    auto ci = build<Epick_traits>(g.s);
    Oracle o = timed_oracle(points_of(ce), implied_of(ce));
    CHECK(points_of(ci) == points_of(ce), name.str() << ": the two kernels built different collections");
    check_against_oracle(ce, o, name.str() + " [Gmpq]");
    check_against_oracle(ci, o, name.str() + " [Epick]");
    check_budgets(ce, o, name.str() + " [Gmpq]", std::size_t(k));
  }
  std::cout << "random collections: " << count << " (";
  for (const auto& p : per_shape) std::cout << p.first << " " << p.second << (p.first == per_shape.rbegin()->first ? "" : ", ");
  std::cout << ")\n";
}

// Scenes with distances through standardize(): implied bodies appear.
static std::string last_refusal;

template <class Traits>
bool standardized(const Structure& s, RI::Rigid_body_collection<Traits>& out)
{
  try { out = RI::standardize(build<Traits>(s)); return true; }
  catch (const RI::Input_error& e) { last_refusal = e.what(); return false; }
}

void standardize_cases(unsigned seed0, int count)
{
  int run = 0, refused = 0, too_big = 0, with_implied = 0;
  std::string refusal;
  for (int k = 0; k < count; ++k) {
    const unsigned seed = seed0 + 100000u + unsigned(k);
    CGAL::Random rng(seed);
    Generator g(rng);
    if (k % 3 == 0) {
      // tetra-like: three bodies in a cycle of shared points, distances between their
      // private points (each distance closes a triangle through a shared point)
      g.s.shape = "tetra-like";
      std::vector<int> P = g.fresh(3);
      std::vector<std::vector<int>> own;
      for (int i = 0; i < 3; ++i) {
        own.push_back(g.fresh(rng.get_int(1, 3)));
        g.add(g.concat({P[i], P[(i + 1) % 3]}, own.back()));
      }
      for (int i = 0; i < 3; ++i)
        if (i == 0 || rng.get_double() < 0.7)
          g.s.distances.push_back({g.pick(own[i], 1)[0], g.pick(own[(i + 1) % 3], 1)[0]});
    } else {
      g.s.shape = "random+distances: ";
      g.generate(rng.get_int(0, 8), rng.get_int(2, 7));
      std::vector<int> pts = g.points_from(0);
      int nd = rng.get_int(1, 4);
      for (int attempt = 0; attempt < 50 && int(g.s.distances.size()) < nd; ++attempt) {
        std::vector<int> ab = g.pick(pts, 2);
        bool together = false;
        for (const auto& b : g.s.bodies)
          together = together || (std::count(b.begin(), b.end(), ab[0]) && std::count(b.begin(), b.end(), ab[1]));
        if (!together) g.s.distances.push_back({ab[0], ab[1]});
      }
    }
    g.shuffle_bodies();
    std::ostringstream name;
    name << "standardized case " << k << " (seed " << seed << ", " << g.s.shape << ")";
    RI::Rigid_body_collection<Exact_traits> ce;
    RI::Rigid_body_collection<Epick_traits> ci;
    bool ok_e = standardized(g.s, ce), ok_i = standardized(g.s, ci);
    CHECK(ok_e == ok_i, name.str() << ": standardize succeeds with one kernel only");
    if (!ok_e || !ok_i) { ++refused; refusal = last_refusal; continue; }
    if (ce.number_of_bodies() > 8) { ++too_big; continue; }
    ++run;
    std::vector<bool> imp = implied_of(ce);
    if (std::count(imp.begin(), imp.end(), true)) ++with_implied;
    Oracle o = timed_oracle(points_of(ce), imp);
    check_against_oracle(ce, o, name.str() + " [Gmpq]");
    Oracle oi = (points_of(ci) == points_of(ce) && implied_of(ci) == imp) ? o : timed_oracle(points_of(ci), implied_of(ci));
    check_against_oracle(ci, oi, name.str() + " [Epick]");
  }
  std::cout << "standardized scenes: " << run << " checked (" << with_implied << " with implied bodies); skipped: "
            << too_big << " with more than 8 bodies, " << refused << " refused by standardize"
            << (refused ? " (last: " + refusal + ")" : std::string()) << "\n";
  CHECK(with_implied >= count / 4, "too few standardized scenes with implied bodies: " << with_implied);
}

template <class Traits>
RI::Rigid_body_collection<Traits> paper_collection(const std::string& file)
{
  return RI::standardize(RI::make_collection<Traits>(RI::read_scene(std::string(RIGID_INCIDENCE_DATA_DIR) + "/" + file)));
}

// The oracle runs once on the exact collection; the Epick collection is compared with the
// same oracle when its bodies are the same (else with its own).
void paper_scene(const std::string& file, long expected_ties)
{
  auto ce = paper_collection<Exact_traits>(file);
  auto ci = paper_collection<Epick_traits>(file);
  Oracle o = timed_oracle(points_of(ce), implied_of(ce));
  if (expected_ties > 0) CHECK(long(o.ties) == expected_ties, file << ": oracle finds " << o.ties << " ties, expected " << expected_ties);
  check_against_oracle(ce, o, file + " [Gmpq]");
  CHECK(points_of(ci) == points_of(ce) && implied_of(ci) == implied_of(ce), file << ": the kernels standardize differently");
  Oracle oi = (points_of(ci) == points_of(ce) && implied_of(ci) == implied_of(ce)) ? o : timed_oracle(points_of(ci), implied_of(ci));
  check_against_oracle(ci, oi, file + " [Epick]");
  std::cout << "  " << file << ": " << ce.number_of_bodies() << " bodies, oracle weight " << o.weight << ", depth sum "
            << o.depth_sum << ", ties " << o.ties << ", " << o.covering_sets << " covering sets, " << o.trees << " trees\n";
}

template <class Traits>
void hand_made(const std::string& kernel)
{
  std::size_t variant = 0; // selects the small budgets of check_budgets
  auto run = [&](const std::string& name, const std::vector<std::vector<int>>& bodies, std::vector<bool> implied,
                 long weight, long depth_sum, std::size_t ties) {
    Structure s;
    int np = 0;
    for (const auto& b : bodies) for (int p : b) np = std::max(np, p + 1);
    for (int p = 0; p < np; ++p) s.coords.push_back({p, p * p, p * p * p}); // distinct (moment curve)
    s.bodies = bodies;
    s.implied = implied.empty() ? std::vector<bool>(bodies.size(), false) : implied;
    auto c = build<Traits>(s);
    Oracle o = timed_oracle(points_of(c), implied_of(c));
    // hand-computed values first, so that the oracle itself is checked
    CHECK(o.weight == weight && o.depth_sum == depth_sum && o.ties == ties,
          name << ": oracle gives weight " << o.weight << ", depth sum " << o.depth_sum << ", ties " << o.ties
               << "; by hand " << weight << ", " << depth_sum << ", " << ties);
    check_against_oracle(c, o, name + " [" + kernel + "]");
    check_budgets(c, o, name + " [" + kernel + "]", variant++);
  };
  // No shared point: any single body is a covering set of weight 0.
  run("two separate bodies", {{0, 1, 2}, {3, 4, 5}}, {}, 0, 0, 2);
  run("three separate bodies", {{0, 1, 2}, {3, 4}, {5, 6, 7}}, {true, false, false}, 0, 0, 3);
  // A hinge: every body holds the shared pair; one body covers it.
  run("hinge of four", {{0, 1, 2}, {0, 1, 3}, {0, 1, 4}, {0, 1, 5}}, {}, 0, 0, 4);
  // A chain of three sharing pairs: the middle body holds every shared point.
  run("chain of three (pairs)", {{0, 1, 2}, {1, 2, 3, 4}, {3, 4, 5}}, {}, 0, 0, 1);
  // A cycle of four bodies sharing pairs: {b0, b2} covers (one weight-6 edge), but any three
  // consecutive bodies form a path of two weight-1 edges: 4 paths, rooted in the middle.
  run("cycle of four (pairs)", {{0, 1, 2, 3}, {2, 3, 4, 5}, {4, 5, 6, 7}, {6, 7, 0, 1}}, {}, 2, 2, 4);
  // Two pieces, each a pair of bodies sharing a point: one body of each piece covers, and
  // the two join by a weight-6 edge: 4 covering pairs x 2 roots.
  run("two pieces", {{0, 1, 2}, {2, 3, 4}, {5, 6, 7}, {7, 8, 9}}, {}, 6, 1, 8);
  // A triangle of bodies pairwise sharing single points: any two of them cover the three
  // shared points (one weight-3 edge): 3 pairs x 2 roots.
  run("triangle of points", {{0, 1, 5}, {1, 2, 6}, {2, 0, 7}}, {}, 3, 1, 6);
  // With a fourth body across the three shared points, it alone covers them.
  run("triangle plus cross body", {{0, 1, 5}, {1, 2, 6}, {2, 0, 7}, {0, 1, 2}}, {}, 0, 0, 1);
  // Tie-break on implied bodies: b0 (implied) and b1 each cover both shared points alone;
  // the one with coordinates must win.
  run("implied tie", {{0, 1, 2}, {0, 1, 3}, {1, 4, 5}, {0, 6, 7}}, {true, false, false, false}, 0, 0, 2);
  // A hinge of 4 bodies {0,1,a_i}, each with a leaf body {a_i,b_i,c_i}: the only optimal
  // covering set is the 4 hinge bodies (weight 3); its 4^2 = 16 spanning trees all weigh 3,
  // the 4 stars have depth sum 3. With max_trees = 5 (variant 10 below) the enumeration of
  // the single candidate is cut short, which must be reported.
  variant = 10; // -> max_trees = 1 + 10 % 6 = 5 in check_budgets
  run("hinge of 4 with leaves", {{0, 1, 2}, {0, 1, 5}, {0, 1, 8}, {0, 1, 11},
                                 {2, 3, 4}, {5, 6, 7}, {8, 9, 10}, {11, 12, 13}}, {}, 3, 3, 4);
  // A diamond of pairs: A, B, C, D share the pairs AB, AC, BC, BD, CD (weight 1), A and D
  // share nothing; a private point of each is shared with a leaf body, so that the only
  // optimal covering set is {A, B, C, D} (weight 3). Its 8 minimum spanning trees include
  // 2 stars (centres B and C, depth sum 3) and 6 paths (depth sum 4); the package meets
  // paths first. With max_trees = 1 (variant 6) the cut enumeration must be reported.
  variant = 6; // -> max_trees = 1
  run("diamond of pairs with leaves", {{1, 2, 3, 4, 11}, {1, 2, 5, 6, 7, 8, 12}, {3, 4, 5, 6, 9, 10, 13}, {7, 8, 9, 10, 14},
                                       {11, 21, 31}, {12, 22, 32}, {13, 23, 33}, {14, 24, 34}}, {}, 3, 3, 2);
  // Stacked plates: four bodies sharing nothing, each held by three distances to the one
  // below. Every spanning tree weighs 18; the distances span the fewest tree edges (9) on
  // the path b0-b1-b2-b3 alone, rooted at b1 or b2 (depth sum 4), where the paper's depth
  // sum alone would take a star (depth sum 3, distances across two edges).
  {
    Structure s;
    for (int p = 0; p < 12; ++p) s.coords.push_back({p, p * p, p * p * p});
    s.bodies = {{0, 1, 2}, {3, 4, 5}, {6, 7, 8}, {9, 10, 11}};
    s.implied.assign(4, false);
    for (int k = 0; k < 3; ++k)
      for (int j = 0; j < 3; ++j) s.distances.push_back({3 * k + j, 3 * (k + 1) + (j + 1) % 3});
    auto c = build<Traits>(s);
    Oracle o = timed_oracle(points_of(c), implied_of(c));
    CHECK(o.weight == 18 && o.path_sum == 9 && o.depth_sum == 4 && o.ties == 2,
          "stacked plates: oracle gives weight " << o.weight << ", distance paths " << o.path_sum << ", depth sum "
                                                 << o.depth_sum << ", ties " << o.ties << "; by hand 18, 9, 4, 2");
    check_against_oracle(c, o, "stacked plates [" + kernel + "]");
    RI::Incidence_tree t = RI::optimal_incidence_tree(c);
    CHECK(t.edges.size() == 3 && t.root == 1, "stacked plates: root " << t.root << ", expected b1");
    for (const auto& e : t.edges)
      CHECK(e.parent + 1 == e.child || e.child + 1 == e.parent,
            "stacked plates: tree edge " << e.parent << "-" << e.child << " joins plates that are not stacked");
  }
}

// ===================================================================== larger collections
// Cheaper oracle: every covering set (depth-first, a body out only if its shared points stay
// coverable), with the weight of its minimum spanning tree by Kruskal over the three weight
// classes (1, then 3, then 6 to join what remains).
long covering_set_min_weight(const Body_points& bodies, long* sets_out,
                             std::vector<std::vector<std::size_t>>* optimal_sets = nullptr)
{
  const std::size_t n = bodies.size();
  const auto w = pair_weights(bodies);
  const auto need = shared_point_bodies(bodies);
  std::vector<std::vector<std::size_t>> points_of_body(n); // indices into need
  for (std::size_t x = 0; x < need.size(); ++x) for (std::size_t b : need[x]) points_of_body[b].push_back(x);
  std::vector<int> in(n, 1);   // 1: in (or undecided), 0: out
  std::vector<int> avail(need.size());
  for (std::size_t x = 0; x < need.size(); ++x) avail[x] = int(need[x].size());
  long best = std::numeric_limits<long>::max(), sets = 0;
  std::vector<std::size_t> uf(n);
  std::function<std::size_t(std::size_t)> find = [&](std::size_t x) { while (uf[x] != x) x = uf[x] = uf[uf[x]]; return x; };
  auto kruskal = [&]() {
    std::vector<std::size_t> S;
    for (std::size_t i = 0; i < n; ++i) if (in[i]) S.push_back(i);
    for (std::size_t i : S) uf[i] = i;
    long total = 0, edges = 0;
    for (int cls : {1, 3, 6})
      for (std::size_t a = 0; a < S.size(); ++a)
        for (std::size_t b = a + 1; b < S.size(); ++b)
          if (w[S[a]][S[b]] == cls) {
            std::size_t ra = find(S[a]), rb = find(S[b]);
            if (ra != rb) { uf[ra] = rb; total += cls; ++edges; }
          }
    if (edges + 1 != long(S.size())) { std::cerr << "kruskal: not spanning\n"; std::abort(); }
    return total;
  };
  std::function<void(std::size_t)> dfs = [&](std::size_t k) {
    if (k == n) {
      bool nonempty = std::count(in.begin(), in.end(), 1) > 0;
      if (!nonempty) return;
      ++sets;
      long w = kruskal();
      if (w < best && optimal_sets) optimal_sets->clear();
      if (w <= best && optimal_sets) {
        std::vector<std::size_t> S;
        for (std::size_t i = 0; i < n; ++i) if (in[i]) S.push_back(i);
        optimal_sets->push_back(S);
      }
      best = std::min(best, w);
      return;
    }
    dfs(k + 1); // k in
    bool can_drop = true;
    for (std::size_t x : points_of_body[k]) can_drop = can_drop && avail[x] > 1;
    if (!can_drop) return;
    in[k] = 0;
    for (std::size_t x : points_of_body[k]) --avail[x];
    dfs(k + 1);
    for (std::size_t x : points_of_body[k]) ++avail[x];
    in[k] = 1;
  };
  dfs(0);
  if (sets_out) *sets_out = sets;
  return best;
}

template <class Traits>
void large_case(const std::string& name, const std::vector<std::vector<int>>& bodies, bool weight_oracle)
{
  Structure s;
  int np = 0;
  for (const auto& b : bodies) for (int p : b) np = std::max(np, p + 1);
  CGAL::Random rng(4242);
  Generator g(rng);
  for (int p = 0; p < np; ++p) g.fresh();
  s.coords = g.s.coords;
  s.bodies = bodies;
  auto c = build<Traits>(s);
  auto t0 = std::chrono::steady_clock::now();
  RI::Incidence_tree t;
  try { t = RI::optimal_incidence_tree(c); }
  catch (const std::exception& e) { CHECK(false, name << ": threw " << e.what()); return; }
  double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  CHECK(t.proven_optimal, name << ": not proven optimal (" << t.strategy << ")");
  check_valid(c, t, name);
  std::cout << "  " << name << ": " << c.number_of_bodies() << " bodies, weight " << t.weight << ", depth sum "
            << t.depth_sum << ", ties " << t.ties << ", |S| = " << t.covering_set.size() << ", " << t.search_nodes
            << " search nodes; optimal_incidence_tree took " << secs << " s";
  if (weight_oracle) {
    long sets = 0;
    auto t1 = std::chrono::steady_clock::now();
    long w = covering_set_min_weight(points_of(c), &sets);
    double osecs = std::chrono::duration<double>(std::chrono::steady_clock::now() - t1).count();
    CHECK(t.weight == w, name << ": weight " << t.weight << ", covering-set oracle " << w);
    std::cout << "; weight oracle: " << sets << " covering sets, " << osecs << " s";
  } else std::cout << "; validity only";
  std::cout << "\n";
}

// A hinge of m bodies {0, 1, a_i}, each a_i also in a leaf body {a_i, b_i, c_i}. The
// covering-set oracle shows that the m hinge bodies are the only optimal covering set; they
// pairwise share the pair {0, 1}, so every one of their m^(m-2) spanning trees is a minimum
// one, and the minimum depth sum is m - 1, attained by the m stars only: ties = m. For
// m = 9 there are 9^7 = 4782969 trees, more than the default max_trees (2000000): the
// package must either find the stars and count them or report an incomplete enumeration.
template <class Traits>
void hinge_with_leaves(int m, const std::string& kernel)
{
  std::vector<std::vector<int>> bodies;
  for (int i = 0; i < m; ++i) bodies.push_back({0, 1, 2 + 3 * i});
  for (int i = 0; i < m; ++i) bodies.push_back({2 + 3 * i, 3 + 3 * i, 4 + 3 * i});
  Structure s;
  s.bodies = bodies;
  for (int p = 0; p < 2 + 3 * m; ++p) s.coords.push_back({p, p * p, p * p * p});
  auto c = build<Traits>(s);
  const std::string name = "hinge of " + std::to_string(m) + " with leaves [" + kernel + "]";
  long sets = 0;
  std::vector<std::vector<std::size_t>> opt;
  long w = covering_set_min_weight(points_of(c), &sets, &opt);
  std::vector<std::size_t> hinge;
  for (int i = 0; i < m; ++i) hinge.push_back(std::size_t(i));
  const auto pw = pair_weights(points_of(c));
  bool clique = true;
  for (int i = 0; i < m; ++i) for (int j = i + 1; j < m; ++j) clique = clique && pw[i][j] == 1;
  CHECK(w == m - 1 && opt.size() == 1 && opt[0] == hinge && clique,
        name << ": the oracle does not find the hinge bodies as the only optimal covering set (test error)");
  auto t0 = std::chrono::steady_clock::now();
  RI::Incidence_tree t = RI::optimal_incidence_tree(c);
  double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  check_valid(c, t, name);
  CHECK(t.weight == w, name << ": weight " << t.weight << ", oracle " << w);
  if (t.proven_optimal)
    CHECK(t.depth_sum == m - 1, name << ": proven_optimal, but depth sum " << t.depth_sum << ", oracle " << m - 1);
  if (t.proven_optimal && t.ties_complete)
    CHECK(t.ties == std::size_t(m), name << ": proven_optimal and ties_complete, but ties " << t.ties << " ("
                                        << t.trees_examined << " trees examined); oracle " << m);
  std::cout << "  " << name << ": " << c.number_of_bodies() << " bodies, weight " << t.weight << ", depth sum "
            << t.depth_sum << ", ties " << t.ties << (t.ties_complete ? "" : " (incomplete)")
            << (t.proven_optimal ? ", proven" : ", not proven") << ", " << t.trees_examined
            << " trees examined; optimal_incidence_tree took " << secs << " s; weight oracle: " << sets
            << " covering sets\n";
}

template <class Traits>
void large_cases(const std::string& kernel)
{
  // A closed strip of m = 11 quadrilaterals, each split into two triangles: 22 triangles,
  // consecutive ones share an edge (a pair of points), every point is in 3 triangles.
  {
    const int m = 11;
    std::vector<std::vector<int>> tri;
    for (int i = 0; i < m; ++i) {
      int p = i, q = m + i, p1 = (i + 1) % m, q1 = m + (i + 1) % m;
      tri.push_back({p, q, p1});
      tri.push_back({q, p1, q1});
    }
    large_case<Traits>("ring of 22 triangles [" + kernel + "]", tri, true);
  }
  // A 4 x 3 grid of squares, each split into two triangles: 24 triangles, 20 points,
  // inner points in 6 triangles. Covering sets number in the millions here, so only the
  // validity of the returned tree (and proven_optimal) is checked.
  {
    const int a = 4, b = 3;
    auto id = [&](int x, int y) { return y * (a + 1) + x; };
    std::vector<std::vector<int>> tri;
    for (int x = 0; x < a; ++x)
      for (int y = 0; y < b; ++y) {
        tri.push_back({id(x, y), id(x + 1, y), id(x + 1, y + 1)});
        tri.push_back({id(x, y), id(x, y + 1), id(x + 1, y + 1)});
      }
    large_case<Traits>("grid of 24 triangles [" + kernel + "]", tri, false);
  }
  hinge_with_leaves<Traits>(9, kernel);
}

int main(int argc, char** argv)
{
  unsigned seed = argc > 1 ? unsigned(std::strtoul(argv[1], nullptr, 10)) : 20260101u;
  int count = argc > 2 ? std::atoi(argv[2]) : 240;
  std::cout << "seed " << seed << " (rerun: test_optimal_tree_brute_force " << seed << " " << count << ")\n";
  auto t0 = std::chrono::steady_clock::now();

  hand_made<Exact_traits>("Gmpq");
  hand_made<Epick_traits>("Epick");
  random_cases(seed, count);
  standardize_cases(seed, 60);
  std::cout << "paper scenes (Gmpq and Epick):\n";
  paper_scene("tetra.json", 1);
  paper_scene("tetra_i.json", 0);
  paper_scene("quad.json", 1);
  paper_scene("pent.json", 6);
  std::cout << "larger collections [Gmpq]:\n";
  large_cases<Exact_traits>("Gmpq");
  std::cout << "larger collections [Epick]:\n";
  large_cases<Epick_traits>("Epick");

  double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  std::cout << stats.cases << " oracle comparisons (" << stats.implied_cases << " with implied bodies, "
            << stats.tiebreak_cases << " with ties and implied bodies, max ties " << stats.max_ties << "), "
            << stats.budget_runs << " runs with small budgets (" << stats.budget_unproven << " not proven), " << checks
            << " checks; oracle " << stats.oracle_seconds << " s, package " << stats.package_seconds << " s, total "
            << secs << " s\n";
  if (failures) std::cout << "FAILED: " << failures << " failures (seed " << seed << ")\n";
  else std::cout << "OK\n";
  return failures ? 1 : 0;
}
