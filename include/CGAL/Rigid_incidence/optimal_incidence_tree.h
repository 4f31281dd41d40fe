// Copyright (c) 2026 Rigid_incidence contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The optimal incidence tree (Section 4.1, Part 1 of
// optimized_incidence_tree_parametrization.txt): over all covering sets, a minimum-weight
// spanning tree of the induced overlap graph; among those, the tree whose distances span the
// fewest tree edges (our addition: equations are written in the frame of the lowest common
// ancestor, not the root's), then the tree and root of minimum depth sum.

#ifndef CGAL_RIGID_INCIDENCE_OPTIMAL_INCIDENCE_TREE_H
#define CGAL_RIGID_INCIDENCE_OPTIMAL_INCIDENCE_TREE_H

#include <CGAL/Rigid_incidence/Input_error.h>
#include <CGAL/Rigid_incidence/Overlap_graph.h>
#include <CGAL/Rigid_incidence/Rigid_body_collection.h>

#include <boost/graph/adjacency_list.hpp>
#include <boost/graph/kruskal_min_spanning_tree.hpp>
#include <boost/graph/connected_components.hpp>

#include <algorithm>
#include <array>
#include <cstdint>
#include <limits>
#include <string>
#include <tuple>
#include <vector>

namespace CGAL {
namespace Rigid_incidence {

/// \ingroup PkgRigidIncidenceRef
/// A rooted incidence tree over a covering set, as `optimal_incidence_tree()` returns it.
struct Incidence_tree
{
  static constexpr std::size_t npos = std::size_t(-1); ///< "no body"
  /// An edge of the tree, oriented from the root.
  struct Edge
  {
    std::size_t parent;  ///< body index of the parent
    std::size_t child;   ///< body index of the child
    int weight;          ///< its weight in the overlap graph
  };

  std::vector<std::size_t> covering_set;  ///< body indices, sorted
  std::vector<std::size_t> non_covering;  ///< the other bodies, sorted
  std::size_t root = npos;                ///< body index of the root
  std::vector<Edge> edges;                ///< breadth-first from the root: a parent before its children
  long weight = 0;                        ///< total edge weight = number of variables of the reduced system
  long depth_sum = 0;                     ///< sum over the tree's bodies of their depth (the root has depth 0)
  /// Sum over the collection's distances of the tree edges between their two points' bodies
  /// (the fewest over the bodies holding each point): the variables of the distance equations.
  long distance_path_sum = 0;
  std::vector<std::size_t> parent;        ///< per body: its parent, npos for the root and non-covering bodies
  std::vector<int> depth;                 ///< per body: its depth, -1 for non-covering bodies

  std::size_t ties = 1;          ///< rooted trees attaining the three minima (weight, distance paths, depth sum); the tie-break picks one
  bool ties_complete = true;     ///< false if the tie count was capped
  bool proven_optimal = true;    ///< false if a search budget ran out or the heuristic was used
  std::string strategy;          ///< how the tree was found, for reports
  std::size_t covering_sets_examined = 0; ///< covering sets reached by the search (leaves)
  std::size_t search_nodes = 0;           ///< nodes of the covering-set search
  std::size_t trees_examined = 0;         ///< minimum spanning trees enumerated
};

/// \ingroup PkgRigidIncidenceRef
/// Budgets of `optimal_incidence_tree()`.
struct Incidence_tree_options
{
  /// Bodies up to which the exact branch and bound runs (its bit sets hold 64 bodies).
  std::size_t exact_limit = 64;
  /// Nodes of the covering-set search before it stops with the best found.
  std::size_t max_search_nodes = 20000000;
  /// Minimum spanning trees enumerated for the distance-path and depth-sum criteria.
  std::size_t max_trees = 2000000;
  /// Optimal covering sets kept for the second criterion.
  std::size_t max_candidates = 100000;
};

namespace internal {

typedef std::uint64_t Mask;
inline int ctz(Mask m) { return __builtin_ctzll(m); }
inline int popcount(Mask m) { return __builtin_popcountll(m); }

// Connected components of the graph `adj` restricted to `within` that meet `touch`.
inline int components_touching(const Mask* adj, Mask within, Mask touch)
{
  int count = 0;
  Mask seeds = touch & within;
  while (seeds) {
    Mask comp = seeds & (~seeds + 1), frontier = comp;
    while (frontier) {
      int i = ctz(frontier);
      frontier &= frontier - 1;
      Mask nb = adj[i] & within & ~comp;
      comp |= nb;
      frontier |= nb;
    }
    seeds &= ~comp;
    ++count;
  }
  return count;
}

// Depth sums of a tree for every root in O(n): D(child) = D(parent) + n - 2 size(child).
inline std::vector<long> depth_sums_all_roots(std::size_t n, const std::vector<std::vector<std::size_t>>& adj)
{
  std::vector<long> sub(n, 1), D(n, 0);
  std::vector<std::size_t> order, par(n, std::size_t(-1));
  std::vector<int> dep(n, 0);
  order.reserve(n);
  order.push_back(0);
  par[0] = 0;
  for (std::size_t k = 0; k < order.size(); ++k)
    for (std::size_t v : adj[order[k]])
      if (par[v] == std::size_t(-1)) { par[v] = order[k]; dep[v] = dep[order[k]] + 1; order.push_back(v); }
  for (std::size_t k = order.size(); k-- > 1;) sub[par[order[k]]] += sub[order[k]];
  for (std::size_t v = 0; v < n; ++v) D[0] += dep[v];
  for (std::size_t k = 1; k < order.size(); ++k) D[order[k]] = D[par[order[k]]] + long(n) - 2 * sub[order[k]];
  return D;
}

// Total weight of a minimum spanning tree of the overlap graph induced by `set`, with
// Boost's Kruskal on the explicit edges (weights 1 and 3) and weight 6 joining what remains.
inline long mst_weight(const Overlap_graph& og, const std::vector<std::size_t>& set)
{
  typedef boost::adjacency_list<boost::vecS, boost::vecS, boost::undirectedS, boost::no_property,
                                boost::property<boost::edge_weight_t, int>> G;
  std::vector<std::size_t> local(og.number_of_bodies(), std::size_t(-1));
  for (std::size_t i = 0; i < set.size(); ++i) local[set[i]] = i;
  G g(set.size());
  const auto& og_g = og.graph();
  for (auto e : boost::make_iterator_range(boost::edges(og_g))) {
    std::size_t a = boost::source(e, og_g), b = boost::target(e, og_g);
    if (local[a] != std::size_t(-1) && local[b] != std::size_t(-1))
      boost::add_edge(local[a], local[b], og_g[e].weight, g);
  }
  std::vector<boost::graph_traits<G>::edge_descriptor> tree;
  boost::kruskal_minimum_spanning_tree(g, std::back_inserter(tree));
  long w = 0;
  auto wmap = boost::get(boost::edge_weight, g);
  for (auto e : tree) w += wmap[e];
  long components = long(set.size()) - long(tree.size());
  return w + 6 * (components > 0 ? components - 1 : 0);
}

template <class Traits>
class Incidence_tree_search
{
public:
  Incidence_tree_search(const Rigid_body_collection<Traits>& c, const Overlap_graph& og, const Incidence_tree_options& o)
    : c_(c), og_(og), opt_(o), n_(c.number_of_bodies())
  {
    for (std::size_t i = 0; i < n_; ++i)
      for (std::size_t j = i + 1; j < n_; ++j)
        if (og_.shared_points(i, j).size() >= 3)
          throw Input_error("optimal_incidence_tree: bodies '" + c.body(i).name + "' and '" + c.body(j).name +
                            "' share 3 or more points: not a standard collection (call standardize() first)");
    for (std::size_t p : c.points_to_cover()) {
      std::vector<std::size_t> through;
      for (std::size_t i = 0; i < n_; ++i) if (c.body(i).contains(p)) through.push_back(i);
      cover_.push_back(through);
    }
    implied_.resize(n_);
    for (std::size_t i = 0; i < n_; ++i) implied_[i] = !c.body(i).all_coordinates();
    for (const auto& d : c.distances()) {
      std::array<std::vector<std::size_t>, 2> ends;
      for (std::size_t i = 0; i < n_; ++i) {
        if (c.body(i).contains(d.a)) ends[0].push_back(i);
        if (c.body(i).contains(d.b)) ends[1].push_back(i);
      }
      distance_bodies_.push_back(ends);
    }
  }

  Incidence_tree run()
  {
    Incidence_tree t;
    if (n_ == 0) throw Input_error("optimal_incidence_tree: the collection has no body");
    std::vector<std::size_t> greedy = greedy_covering_set();
    long greedy_w = mst_weight(og_, greedy);
    if (n_ <= opt_.exact_limit && n_ <= 64) {
      exact_search(greedy_w, t);
    } else {
      candidates_.assign(1, greedy);
      best_w_ = greedy_w;
      t.proven_optimal = false;
      t.strategy = "heuristic (more than " + std::to_string(std::min<std::size_t>(opt_.exact_limit, 64)) +
                   " bodies): greedy covering set, then the minimum spanning tree of fewest distance paths and least depth sum; not proven optimal";
    }
    choose_tree(t);
    return t;
  }

private:
  const Rigid_body_collection<Traits>& c_;
  const Overlap_graph& og_;
  Incidence_tree_options opt_;
  std::size_t n_;
  std::vector<std::vector<std::size_t>> cover_; // per point to cover: the bodies through it
  std::vector<bool> implied_;
  std::vector<std::array<std::vector<std::size_t>, 2>> distance_bodies_; // per distance: the bodies through each point
  std::vector<std::vector<std::size_t>> candidates_;
  long best_w_ = std::numeric_limits<long>::max();
  bool candidates_capped_ = false;

  bool covers(const std::vector<bool>& in) const
  {
    for (const auto& through : cover_) {
      bool ok = false;
      for (std::size_t b : through) if (in[b]) { ok = true; break; }
      if (!ok) return false;
    }
    return true;
  }

  // Start from all bodies and drop, implied bodies first, every body whose removal keeps a
  // covering set and does not increase the tree weight; repeat until nothing drops.
  std::vector<std::size_t> greedy_covering_set() const
  {
    std::vector<bool> in(n_, true);
    auto as_list = [&] { std::vector<std::size_t> s; for (std::size_t i = 0; i < n_; ++i) if (in[i]) s.push_back(i); return s; };
    long w = mst_weight(og_, as_list());
    std::vector<std::size_t> order;
    for (std::size_t i = n_; i-- > 0;) if (implied_[i]) order.push_back(i);
    for (std::size_t i = n_; i-- > 0;) if (!implied_[i]) order.push_back(i);
    bool changed = true;
    while (changed) {
      changed = false;
      for (std::size_t b : order) {
        if (!in[b]) continue;
        in[b] = false;
        std::vector<std::size_t> s = as_list();
        if (!s.empty() && covers(in)) {
          long w2 = mst_weight(og_, s);
          if (w2 <= w) { w = w2; changed = true; continue; }
        }
        in[b] = true;
      }
    }
    return as_list();
  }

  // ---------------------------------------------------------------- exact search
  Mask adj1_[64], adj3_[64];
  std::vector<Mask> cover_mask_;
  std::vector<std::vector<std::size_t>> points_of_body_; // indices into cover_
  std::size_t nodes_ = 0, leaves_ = 0;
  bool aborted_ = false;

  // W(S) = |S| + 2 q1 + 3 q3 - 6, with q1 (q3) the components of S in the graph of the edges
  // of weight 1 (of weight <= 3): Kruskal takes |S| - q1 edges of weight 1, q1 - q3 of
  // weight 3 and q3 - 1 of weight 6.
  long weight_of(Mask s) const
  {
    int q1 = components_touching(adj1_, s, s), q3 = components_touching(adj13_, s, s);
    return popcount(s) + 2 * q1 + 3 * q3 - 6;
  }

  void exact_search(long greedy_w, Incidence_tree& t)
  {
    for (std::size_t i = 0; i < n_; ++i) { adj1_[i] = 0; adj3_[i] = 0; }
    for (std::size_t i = 0; i < n_; ++i)
      for (std::size_t j = 0; j < n_; ++j) {
        if (i == j) continue;
        int w = og_.weight(i, j);
        if (w == 1) adj1_[i] |= Mask(1) << j;
        if (w == 3) adj3_[i] |= Mask(1) << j;
      }
    points_of_body_.assign(n_, {});
    for (std::size_t x = 0; x < cover_.size(); ++x) {
      Mask m = 0;
      for (std::size_t b : cover_[x]) { m |= Mask(1) << b; points_of_body_[b].push_back(x); }
      cover_mask_.push_back(m);
    }
    best_w_ = greedy_w;
    Mask all = (n_ == 64) ? ~Mask(0) : ((Mask(1) << n_) - 1);
    for (std::size_t i = 0; i < n_; ++i) adj13_[i] = adj1_[i] | adj3_[i];
    dfs(0, 0, all);
    t.search_nodes = nodes_;
    t.covering_sets_examined = leaves_;
    if (aborted_) {
      t.proven_optimal = false;
      t.strategy = "branch and bound over covering sets, stopped after " + std::to_string(nodes_) +
                   " nodes (budget): best found, not proven optimal";
      if (candidates_.empty()) { candidates_.assign(1, greedy_covering_set()); best_w_ = greedy_w; }
    } else {
      t.strategy = "exact: branch and bound over all covering sets (" + std::to_string(nodes_) +
                   " nodes), every minimum spanning tree of the optimal ones, every root";
    }
  }
  Mask adj13_[64];

  // Bodies with index < k are decided: `in` holds the chosen ones; `avail` = chosen plus
  // undecided. Each shared point keeps at least one available body.
  void dfs(std::size_t k, Mask in, Mask avail)
  {
    if (aborted_) return;
    if (++nodes_ > opt_.max_search_nodes) { aborted_ = true; return; }
    // Lower bound: components of the final S in either graph are at least the components
    // of `avail` that meet `in`; at least one body more if a point is not covered yet.
    int q1 = in ? components_touching(adj1_, avail, in) : 1;
    int q3 = in ? components_touching(adj13_, avail, in) : 1;
    long more = 0;
    for (const Mask m : cover_mask_) if (!(m & in)) { more = 1; break; }
    long lb = popcount(in) + more + 2 * q1 + 3 * q3 - 6;
    if (lb > best_w_) return;
    if (k == n_) {
      if (!in) return;
      ++leaves_;
      long w = weight_of(in);
      if (w < best_w_) { best_w_ = w; candidates_.clear(); candidates_capped_ = false; }
      if (w == best_w_) {
        if (candidates_.size() < opt_.max_candidates) {
          std::vector<std::size_t> s;
          for (std::size_t i = 0; i < n_; ++i) if (in >> i & 1) s.push_back(i);
          candidates_.push_back(s);
        } else candidates_capped_ = true;
      }
      return;
    }
    Mask bit = Mask(1) << k;
    dfs(k + 1, in | bit, avail);
    // exclude k if every point of k stays coverable
    Mask without = avail & ~bit;
    for (std::size_t x : points_of_body_[k]) if (!(cover_mask_[x] & without)) return;
    dfs(k + 1, in, without);
  }

  // ------------------------- second and third criteria: distance paths, then depth sum
  struct Best
  {
    bool set = false;
    long path_sum = 0;
    long depth_sum = 0;
    std::tuple<long, int, std::vector<std::size_t>, std::size_t, std::vector<std::pair<std::size_t, std::size_t>>> key;
    std::vector<std::size_t> set_bodies;
    std::size_t root = 0;
    std::vector<std::pair<std::size_t, std::size_t>> edges; // body indices
  };

  // Sum over the distances of the tree edges between the two points' bodies, the fewest over
  // the bodies of `s` (local indices in `ends`) holding each point. A distance equation is
  // written in the frame of the two bodies' lowest common ancestor, so these edges' variables
  // are the equation's (Reduced_system picks the same pair of bodies).
  static long distance_paths(std::size_t m, const std::vector<std::vector<std::size_t>>& adj,
                             const std::vector<std::array<std::vector<std::size_t>, 2>>& ends)
  {
    if (ends.empty()) return 0;
    std::vector<std::size_t> par(m, std::size_t(-1)), queue{0};
    std::vector<long> dep(m, -1);
    dep[0] = 0;
    for (std::size_t k = 0; k < queue.size(); ++k)
      for (std::size_t v : adj[queue[k]])
        if (dep[v] < 0) { dep[v] = dep[queue[k]] + 1; par[v] = queue[k]; queue.push_back(v); }
    auto path = [&](std::size_t a, std::size_t b) {
      long len = 0;
      while (a != b) {
        if (dep[a] < dep[b]) std::swap(a, b);
        a = par[a];
        ++len;
      }
      return len;
    };
    long sum = 0;
    for (const auto& e : ends) {
      long best = std::numeric_limits<long>::max();
      for (std::size_t a : e[0]) for (std::size_t b : e[1]) best = std::min(best, path(a, b));
      if (best != std::numeric_limits<long>::max()) sum += best;
    }
    return sum;
  }

  void choose_tree(Incidence_tree& t)
  {
    Best best;
    std::size_t ties = 0, trees = 0;
    bool capped = candidates_capped_;
    for (const auto& s : candidates_) {
      if (trees > opt_.max_trees) { capped = true; break; }
      std::vector<std::size_t> local(n_, std::size_t(-1));
      for (std::size_t i = 0; i < s.size(); ++i) local[s[i]] = i;
      std::vector<std::array<std::vector<std::size_t>, 2>> ends;
      for (const auto& d : distance_bodies_) {
        std::array<std::vector<std::size_t>, 2> e;
        for (int k = 0; k < 2; ++k)
          for (std::size_t b : d[k]) if (local[b] != std::size_t(-1)) e[k].push_back(local[b]);
        if (!e[0].empty() && !e[1].empty()) ends.push_back(e);
      }
      enumerate_msts(s, [&](const std::vector<std::pair<std::size_t, std::size_t>>& tree_edges) {
        ++trees;
        std::size_t m = s.size();
        std::vector<std::vector<std::size_t>> adj(m);
        for (const auto& e : tree_edges) { adj[e.first].push_back(e.second); adj[e.second].push_back(e.first); }
        const long P = distance_paths(m, adj, ends);
        if (best.set && P > best.path_sum) return trees <= opt_.max_trees;
        std::vector<long> D = depth_sums_all_roots(m, adj);
        long implied_count = 0;
        for (std::size_t b : s) implied_count += implied_[b] ? 1 : 0;
        std::vector<std::pair<std::size_t, std::size_t>> body_edges;
        for (const auto& e : tree_edges)
          body_edges.push_back(std::minmax(s[e.first], s[e.second]));
        std::sort(body_edges.begin(), body_edges.end());
        for (std::size_t r = 0; r < m; ++r) {
          const bool better = !best.set || P < best.path_sum || D[r] < best.depth_sum;
          if (!better && D[r] > best.depth_sum) continue;
          if (better) ties = 0;
          ++ties;
          auto key = std::make_tuple(implied_count, implied_[s[r]] ? 1 : 0, s, s[r], body_edges);
          if (better || key < best.key) {
            best.set = true; best.path_sum = P; best.depth_sum = D[r]; best.key = key;
            best.set_bodies = s; best.root = s[r]; best.edges = body_edges;
          }
        }
        return trees <= opt_.max_trees;
      });
    }
    if (trees > opt_.max_trees) capped = true; // the last candidate's enumeration may have stopped too
    if (capped) { t.ties_complete = false; t.proven_optimal = false;
      t.strategy += "; the enumeration of trees for the distance paths and depth sum was capped: not proven optimal on them"; }
    t.trees_examined = trees;
    t.ties = ties;
    t.weight = best_w_;
    t.depth_sum = best.depth_sum;
    t.distance_path_sum = best.path_sum;
    t.covering_set = best.set_bodies;
    t.root = best.root;
    t.parent.assign(n_, Incidence_tree::npos);
    t.depth.assign(n_, -1);
    std::vector<bool> in(n_, false);
    for (std::size_t b : t.covering_set) in[b] = true;
    for (std::size_t i = 0; i < n_; ++i) if (!in[i]) t.non_covering.push_back(i);
    // orient breadth-first from the root
    std::vector<std::vector<std::size_t>> adj(n_);
    for (const auto& e : best.edges) { adj[e.first].push_back(e.second); adj[e.second].push_back(e.first); }
    for (auto& a : adj) std::sort(a.begin(), a.end());
    std::vector<std::size_t> queue{t.root};
    t.depth[t.root] = 0;
    for (std::size_t k = 0; k < queue.size(); ++k)
      for (std::size_t v : adj[queue[k]])
        if (t.depth[v] < 0 && v != t.root) {
          t.depth[v] = t.depth[queue[k]] + 1;
          t.parent[v] = queue[k];
          t.edges.push_back(Incidence_tree::Edge{queue[k], v, og_.weight(queue[k], v)});
          queue.push_back(v);
        }
    long w = 0, d = 0;
    for (const auto& e : t.edges) w += e.weight;
    for (std::size_t b : t.covering_set) d += t.depth[b];
    CGAL_assertion(w == t.weight && d == t.depth_sum);
    (void)w; (void)d;
  }

  // Every minimum spanning tree of the overlap graph induced by `s` (local indices): the
  // trees whose edges of weight <= w span the same components as Kruskal's for every w.
  template <class F>
  void enumerate_msts(const std::vector<std::size_t>& s, F&& report) const
  {
    std::size_t m = s.size();
    std::vector<std::vector<std::pair<std::size_t, std::size_t>>> classes(3);
    for (std::size_t a = 0; a < m; ++a)
      for (std::size_t b = a + 1; b < m; ++b) {
        int w = og_.weight(s[a], s[b]);
        classes[w == 1 ? 0 : (w == 3 ? 1 : 2)].push_back({a, b});
      }
    // pairs joined by more distances first: the first trees enumerated are those of few
    // distance paths, which matters when max_trees cuts the enumeration (n bodies sharing
    // nothing have n^(n-2) spanning trees)
    if (!distance_bodies_.empty()) {
      auto links = [&](const std::pair<std::size_t, std::size_t>& e) {
        long k = 0;
        for (const auto& d : distance_bodies_) {
          const bool a0 = std::binary_search(d[0].begin(), d[0].end(), s[e.first]), a1 = std::binary_search(d[1].begin(), d[1].end(), s[e.first]);
          const bool b0 = std::binary_search(d[0].begin(), d[0].end(), s[e.second]), b1 = std::binary_search(d[1].begin(), d[1].end(), s[e.second]);
          k += (a0 && b1) || (a1 && b0) ? 1 : 0;
        }
        return k;
      };
      for (auto& cls : classes) {
        std::vector<std::pair<long, std::pair<std::size_t, std::size_t>>> keyed;
        for (const auto& e : cls) keyed.push_back({-links(e), e});
        std::stable_sort(keyed.begin(), keyed.end(), [](const auto& x, const auto& y) { return x.first < y.first; });
        for (std::size_t i = 0; i < cls.size(); ++i) cls[i] = keyed[i].second;
      }
    }
    std::vector<std::size_t> uf(m);
    for (std::size_t i = 0; i < m; ++i) uf[i] = i;
    std::vector<std::pair<std::size_t, std::size_t>> chosen;
    bool go_on = true;
    enumerate_class(0, uf, classes, chosen, report, go_on);
  }

  static std::size_t find(std::vector<std::size_t>& uf, std::size_t x)
  {
    while (uf[x] != x) x = uf[x] = uf[uf[x]];
    return x;
  }

  template <class F>
  void enumerate_class(std::size_t cls, std::vector<std::size_t> uf,
                       const std::vector<std::vector<std::pair<std::size_t, std::size_t>>>& classes,
                       std::vector<std::pair<std::size_t, std::size_t>>& chosen, F& report, bool& go_on) const
  {
    if (!go_on) return;
    if (cls == 3) { go_on = report(chosen); return; }
    // edges of this class joining different components so far, and how many Kruskal takes
    std::vector<std::pair<std::size_t, std::size_t>> cand;
    for (const auto& e : classes[cls]) if (find(uf, e.first) != find(uf, e.second)) cand.push_back(e);
    std::vector<std::size_t> tmp = uf;
    std::size_t need = 0;
    for (const auto& e : cand) {
      std::size_t a = find(tmp, e.first), b = find(tmp, e.second);
      if (a != b) { tmp[a] = b; ++need; }
    }
    choose_forest(cls, 0, need, uf, cand, classes, chosen, report, go_on);
  }

  template <class F>
  void choose_forest(std::size_t cls, std::size_t i, std::size_t need, std::vector<std::size_t>& uf,
                     const std::vector<std::pair<std::size_t, std::size_t>>& cand,
                     const std::vector<std::vector<std::pair<std::size_t, std::size_t>>>& classes,
                     std::vector<std::pair<std::size_t, std::size_t>>& chosen, F& report, bool& go_on) const
  {
    if (!go_on) return;
    if (need == 0) { enumerate_class(cls + 1, uf, classes, chosen, report, go_on); return; }
    if (cand.size() - i < need) return;
    const auto& e = cand[i];
    std::size_t a = find(uf, e.first), b = find(uf, e.second);
    if (a != b) {
      std::vector<std::size_t> uf2 = uf;
      uf2[a] = b;
      chosen.push_back(e);
      choose_forest(cls, i + 1, need - 1, uf2, cand, classes, chosen, report, go_on);
      chosen.pop_back();
    }
    choose_forest(cls, i + 1, need, uf, cand, classes, chosen, report, go_on);
  }
};

} // namespace internal

/*!
\ingroup PkgRigidIncidenceRef
\brief The optimal incidence tree of a standard collection (Section 4.1, Part 1).

First criterion: over all covering sets S of the shared points and of the points that
distances name (`Rigid_body_collection::points_to_cover()`: a distance is an equation between
points the tree must place), the minimum total weight
of a spanning tree of the overlap graph induced by S (weights w(2)=1, w(1)=3, w(0)=6).
Second (not in the paper): over all minimum spanning trees of all optimal covering sets, the
minimum `Incidence_tree::distance_path_sum`, the tree edges between the bodies of each
distance's two points. The paper writes every equation in the root's frame, where a body's
depth makes its degree; `Reduced_system` writes each in the frame of the lowest common ancestor
of its bodies, where the edges between them are its variables. Stacked platforms, all pairs of
plates of weight 6, show the difference: the star (depth sum 3 for three plates on a base)
makes the legs between plates 1 and 2 equations in both plates' variables, the path (depth sum
6) makes every plate's legs equations in its own 6 variables, and the reduced system falls into
independent parts. Third: over those trees and all their roots, the minimum sum of depths.
Remaining ties are broken, in this order, by fewer implied
bodies in the covering set (their coordinates need square roots), a root that is not
implied, the smaller sorted list of body indices, the smaller root index, the smaller
sorted edge list; `Incidence_tree::ties` counts the rooted trees that tie on the three criteria.

Strategy. Up to `options.exact_limit` bodies (at most 64), an exact branch and bound over
covering sets: a body is in or out in index order; a branch is cut when a point can no longer
be covered or when the lower bound |I| + 2 q1 + 3 q3 - 6 on the weight (I the bodies taken,
q1, q3 the components, in the graphs of weight-1 and weight-<=3 edges, of the available
bodies that meet I) exceeds the best weight; the initial bound is the greedy solution
below. Every minimum spanning tree of every optimal covering set is then enumerated (class
by class, as Kruskal's algorithm sees them) with the depth sums of all roots computed in
linear time. Beyond that limit, or when a budget of `options` runs out, the result is the
greedy covering set (start from all bodies and drop, implied first, each body whose removal
keeps a cover and does not increase the weight of a minimum spanning tree computed with
Boost's Kruskal), and `proven_optimal` is false.

\pre `collection` is standard: no two bodies share 3 or more points (see `standardize()`).
*/
template <class Traits>
Incidence_tree optimal_incidence_tree(const Rigid_body_collection<Traits>& collection,
                                      const Incidence_tree_options& options = Incidence_tree_options())
{
  Overlap_graph og(collection);
  internal::Incidence_tree_search<Traits> search(collection, og, options);
  return search.run();
}

/*!
\ingroup PkgRigidIncidenceRef
\brief An incidence tree given by the user: `edges` (pairs of body indices) must form a
spanning tree of their bodies, rooted at `root`; weights come from the overlap graph.

For `select_well_formed_incidences()` with a tree of one's own choice (the paper shows that
the well-formed extension works for any spanning tree). The tree's bodies must cover the
points they share with each other; covering all shared points of the collection is not
required (the tree then defines its own sub-collection D).
\throws Input_error if the edges do not form a tree containing `root`, or name a body twice.
*/
template <class Traits>
Incidence_tree make_incidence_tree(const Rigid_body_collection<Traits>& c, std::size_t root,
                                   const std::vector<std::pair<std::size_t, std::size_t>>& edges)
{
  const std::size_t n = c.number_of_bodies();
  if (root >= n) throw Input_error("make_incidence_tree: no body " + std::to_string(root));
  Incidence_tree t;
  std::vector<std::vector<std::size_t>> adj(n);
  std::vector<bool> in(n, false);
  in[root] = true;
  for (const auto& e : edges) {
    if (e.first >= n || e.second >= n || e.first == e.second)
      throw Input_error("make_incidence_tree: edge (" + std::to_string(e.first) + ", " + std::to_string(e.second) + ") is not a pair of bodies");
    adj[e.first].push_back(e.second);
    adj[e.second].push_back(e.first);
    in[e.first] = in[e.second] = true;
  }
  for (std::size_t b = 0; b < n; ++b) (in[b] ? t.covering_set : t.non_covering).push_back(b);
  if (edges.size() + 1 != t.covering_set.size())
    throw Input_error("make_incidence_tree: " + std::to_string(edges.size()) + " edges on " + std::to_string(t.covering_set.size()) +
                      " bodies: not a tree");
  Overlap_graph og(c);
  t.root = root;
  t.parent.assign(n, Incidence_tree::npos);
  t.depth.assign(n, -1);
  t.depth[root] = 0;
  std::vector<std::size_t> queue{root};
  for (std::size_t k = 0; k < queue.size(); ++k)
    for (std::size_t v : adj[queue[k]])
      if (t.depth[v] < 0) {
        t.depth[v] = t.depth[queue[k]] + 1;
        t.parent[v] = queue[k];
        t.edges.push_back(Incidence_tree::Edge{queue[k], v, og.weight(queue[k], v)});
        t.weight += og.weight(queue[k], v);
        t.depth_sum += t.depth[v];
        queue.push_back(v);
      }
  if (queue.size() != t.covering_set.size()) throw Input_error("make_incidence_tree: the edges are not connected: not a tree");
  t.ties = 1;
  t.proven_optimal = false;
  t.strategy = "given by the user";
  return t;
}

} // namespace Rigid_incidence
} // namespace CGAL

#endif
