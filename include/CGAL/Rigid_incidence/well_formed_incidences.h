// Copyright (c) 2026 Rigid_incidence contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Theorem 1's Well-formed Incidences Algorithm and Section 6's Optimal Well-formed Incidence
// Selection Algorithm (well_formed_optimal_incidences.txt): the incidences of an incidence
// tree, extended greedily through the seam graph to a well-formed set.

#ifndef CGAL_RIGID_INCIDENCE_WELL_FORMED_INCIDENCES_H
#define CGAL_RIGID_INCIDENCE_WELL_FORMED_INCIDENCES_H

#include <CGAL/Rigid_incidence/Incidence.h>
#include <CGAL/Rigid_incidence/Input_error.h>
#include <CGAL/Rigid_incidence/Rigid_body_collection.h>
#include <CGAL/Rigid_incidence/Seam_graph.h>
#include <CGAL/Rigid_incidence/optimal_incidence_tree.h>

#include <algorithm>
#include <map>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Rigid_incidence {

/// \ingroup PkgRigidIncidenceRef
/// The result of `select_well_formed_incidences()` and `well_formed_incidences()`.
struct Well_formed_selection
{
  /// Whether an incidence is eliminated by the tree's parametrization or left as an equation.
  enum Role
  {
    TREE,      ///< eliminated by the incidence tree (Table 1 maps)
    REMAINING  ///< an equation of the reduced system
  };
  std::vector<std::size_t> bodies;  ///< D: the bodies of the tree (its covering set), sorted
  Incidence_set incidences;         ///< the selected, well-formed incidences
  std::vector<Role> roles;          ///< per incidence of `incidences` (in its order)
  std::size_t tree_count = 0;       ///< incidences eliminated by the tree
  std::size_t remaining_count = 0;  ///< incidences left as equations of the reduced system
  /// A point seam edge: the copies of `point` in two bodies.
  struct Seam_edge
  {
    std::size_t point;   ///< the shared point
    std::size_t body_a;  ///< one body
    std::size_t body_b;  ///< the other body
  };
  /// The seam tree F1 (point seam edges whose three coordinates are matched).
  std::vector<Seam_edge> seam_tree;
  /// F*: the point seam edges of the maximal point-seam-cycle-avoiding extension (coordinates 1, 2).
  std::vector<Seam_edge> point_seam_edges;
};

namespace internal {

// Steps (2b), (2c) and (3) of Section 6 from a seam forest F0 (with its edges already in
// `conn`) and the double incidences P.
inline void complete_selection(const Seam_graph& g, Seam_connectivity& conn, Well_formed_selection& out,
                               std::vector<std::pair<std::size_t, std::size_t>> F1,
                               const std::vector<std::pair<std::size_t, std::size_t>>& P,
                               const std::set<Incidence>& from_tree)
{
  std::vector<std::pair<std::size_t, std::size_t>> Fstar;
  // (2b) complete to a seam tree
  for (const auto& pc : g.copies()) {
    const auto& cs = pc.second;
    for (std::size_t i = 0; i < cs.size(); ++i)
      for (std::size_t j = i + 1; j < cs.size(); ++j)
        if (conn.add_point_seam_edge(cs[i], cs[j])) F1.push_back({cs[i], cs[j]});
  }
  // (2c) F1, then P, then every other point seam edge, without point-seam cycles
  std::vector<std::size_t> parent(g.vertices().size());
  for (std::size_t i = 0; i < parent.size(); ++i) parent[i] = i;
  auto find = [&](std::size_t x) { while (parent[x] != x) x = parent[x] = parent[parent[x]]; return x; };
  auto add = [&](std::size_t a, std::size_t b) {
    std::size_t ra = find(a), rb = find(b);
    if (ra == rb) return false;
    parent[ra] = rb;
    Fstar.push_back({a, b});
    return true;
  };
  for (const auto& e : F1)
    if (!add(e.first, e.second)) throw Input_error("well-formed selection: the seam tree has a point-seam cycle (internal error)");
  for (const auto& e : P)
    if (!add(e.first, e.second)) // Lemma 1 (3): cannot happen; a tree incidence must never be dropped silently
      throw Input_error("well-formed selection: a double incidence of the tree closes a point-seam cycle (internal error)");
  for (const auto& pc : g.copies())
    for (std::size_t i = 0; i < pc.second.size(); ++i)
      for (std::size_t j = i + 1; j < pc.second.size(); ++j) add(pc.second[i], pc.second[j]);
  // (3) two coordinates per edge of F*, the third for the edges of F1
  auto incidence = [&](const std::pair<std::size_t, std::size_t>& e, int p) {
    const auto& a = g.vertices()[e.first];
    const auto& b = g.vertices()[e.second];
    return Incidence(a.point, a.body, b.body, p);
  };
  std::vector<Incidence> all;
  for (const auto& e : Fstar) { all.push_back(incidence(e, 1)); all.push_back(incidence(e, 2)); }
  for (const auto& e : F1) all.push_back(incidence(e, 3));
  auto as_seam_edge = [&](const std::pair<std::size_t, std::size_t>& e) {
    return Well_formed_selection::Seam_edge{g.vertices()[e.first].point, g.vertices()[e.first].body, g.vertices()[e.second].body};
  };
  for (const auto& e : F1) out.seam_tree.push_back(as_seam_edge(e));
  for (const auto& e : Fstar) out.point_seam_edges.push_back(as_seam_edge(e));
  out.incidences = Incidence_set(all);
  for (const Incidence& i : out.incidences) {
    bool t = from_tree.count(i) > 0;
    out.roles.push_back(t ? Well_formed_selection::TREE : Well_formed_selection::REMAINING);
    (t ? out.tree_count : out.remaining_count) += 1;
  }
}

} // namespace internal

/*!
\ingroup PkgRigidIncidenceRef
\brief The Optimal Well-formed Incidence Selection Algorithm (Section 6 of
well_formed_optimal_incidences.txt) for the collection D of the bodies of `tree`.

Works for any spanning tree of D, not only the optimal one (the paper's Section 6 shows the
extension exists for any).
1. Each tree edge gives its seam-graph edges (Section 6.1): an edge of weight 3 (one shared
   point v) the triple incidence of v, an edge of weight 1 (a shared pair v, w, v the smaller
   point index) the triple of v (into Q) and the double of w (into P).
2. (a) Q is a seam forest F0. (b) Point seam edges are added, point by point, whenever their
   two copies are not yet joined by a seam path (`Seam_connectivity`), until none can be: the
   seam tree F1. (c) F1, then P, then any point seam edge are added per point while they close
   no point-seam cycle: F*.
3. Each edge of F* gives coordinates 1 and 2 of its point; each edge of F1 also coordinate 3.
Incidences that come from tree edges are marked TREE, the others REMAINING. Greedy, without
backtracking (the seam-cycle and point-seam-cycle structures are matroids).

\pre the bodies of D pairwise share at most 2 points (a standard collection).
*/
template <class Traits>
Well_formed_selection select_well_formed_incidences(const Rigid_body_collection<Traits>& c, const Incidence_tree& tree)
{
  Well_formed_selection out;
  out.bodies = tree.covering_set;
  std::sort(out.bodies.begin(), out.bodies.end());
  Seam_graph g(c, out.bodies);
  Seam_connectivity conn(g);
  std::set<Incidence> from_tree;
  std::vector<std::pair<std::size_t, std::size_t>> F0, P;
  for (const auto& e : tree.edges) {
    std::vector<std::size_t> shared = c.common_points(e.parent, e.child);
    if (shared.empty()) continue;
    if (shared.size() > 2)
      throw Input_error("select_well_formed_incidences: bodies '" + c.body(e.parent).name + "' and '" + c.body(e.child).name +
                        "' share 3 or more points (not a standard collection)");
    std::size_t a = g.vertex(shared[0], e.parent), b = g.vertex(shared[0], e.child);
    if (!conn.add_point_seam_edge(a, b))
      throw Input_error("select_well_formed_incidences: the tree's triple incidences close a seam cycle: not a tree of D");
    F0.push_back({a, b});
    for (int p : {1, 2, 3}) from_tree.insert(Incidence(shared[0], e.parent, e.child, p));
    if (shared.size() == 2) {
      P.push_back({g.vertex(shared[1], e.parent), g.vertex(shared[1], e.child)});
      for (int p : {1, 2}) from_tree.insert(Incidence(shared[1], e.parent, e.child, p));
    }
  }
  internal::complete_selection(g, conn, out, F0, P, from_tree);
  return out;
}

/*!
\ingroup PkgRigidIncidenceRef
\brief Theorem 1's Well-formed Incidences Algorithm for the bodies `D` of `c`: the greedy
completion of the empty seam forest to a seam tree and its maximal point-seam-cycle-avoiding
extension, converted to incidences. All of them are REMAINING (no tree eliminates any).
*/
template <class Traits>
Well_formed_selection well_formed_incidences(const Rigid_body_collection<Traits>& c, std::vector<std::size_t> D)
{
  Well_formed_selection out;
  std::sort(D.begin(), D.end());
  out.bodies = D;
  Seam_graph g(c, out.bodies);
  Seam_connectivity conn(g);
  internal::complete_selection(g, conn, out, {}, {}, {});
  return out;
}

/*!
\ingroup PkgRigidIncidenceRef
\brief The incidences of the full system of D that a selection leaves out as redundant: every
coordinate of every shared point between every two bodies of D through it, minus the selected ones.
*/
template <class Traits>
Incidence_set redundant_incidences(const Rigid_body_collection<Traits>& c, const Well_formed_selection& s)
{
  Seam_graph g(c, s.bodies);
  std::vector<Incidence> out;
  for (const auto& pc : g.copies())
    for (std::size_t i = 0; i < pc.second.size(); ++i)
      for (std::size_t j = i + 1; j < pc.second.size(); ++j)
        for (int p : {1, 2, 3}) {
          Incidence inc(pc.first, g.vertices()[pc.second[i]].body, g.vertices()[pc.second[j]].body, p);
          if (!s.incidences.contains(inc)) out.push_back(inc);
        }
  return Incidence_set(out);
}

namespace internal {

// The vertices (point, body_a) and (point, body_b) of `g`, checked against the selection.
inline std::pair<std::size_t, std::size_t> redundant_edge_vertices(const Seam_graph& g, const Well_formed_selection& s,
                                                                   std::size_t point, std::size_t body_a,
                                                                   std::size_t body_b, const char* where)
{
  if (g.bodies() != s.bodies)
    throw Input_error(std::string(where) + ": the seam graph is not the one of the selection's bodies");
  std::size_t a = g.vertex(point, body_a), b = g.vertex(point, body_b);
  if (a == Seam_graph::npos || b == Seam_graph::npos || a == b)
    throw Input_error(std::string(where) + ": not a point seam edge of the seam graph (two bodies of D through a shared point)");
  return {a, b};
}

inline bool same_seam_edge(const Well_formed_selection::Seam_edge& e, std::size_t point, std::size_t body_a, std::size_t body_b)
{
  return e.point == point && ((e.body_a == body_a && e.body_b == body_b) || (e.body_a == body_b && e.body_b == body_a));
}

} // namespace internal

/*!
\ingroup PkgRigidIncidenceRef
\brief Why coordinates 1 and 2 of the point seam edge (point, body_a) - (point, body_b) are
redundant in the selection `s`: the point-seam cycle the edge closes with F*
(`s.point_seam_edges`).

The selection takes coordinates 1 and 2 of the point seam edges of F*, a maximal extension
of the seam tree that closes no point-seam cycle. The incidences (point, {body_a, body_b}, 1)
and (point, {body_a, body_b}, 2) of an edge outside F* are redundant because the edge closes
a point-seam cycle with F*: this cycle is returned as the `POINT` step
(point, body_a) -> (point, body_b) followed by the path of F* edges among the copies of
`point` back to (point, body_a) (found by breadth-first search, so the cycle is simple).
Empty if the edge is in F*. `g` is the seam graph of `s.bodies`, e.g.
`Seam_graph(c, s.bodies)` for the collection `c` of the selection.
\throws Input_error if `g` is not the seam graph of `s.bodies`, if the edge is not a point
seam edge of `g`, or if F* does not join its two copies (`s` is not a selection of this
package).
*/
inline std::vector<Seam_step> point_seam_cycle(const Seam_graph& g, const Well_formed_selection& s, std::size_t point,
                                               std::size_t body_a, std::size_t body_b)
{
  const std::pair<std::size_t, std::size_t> ab = internal::redundant_edge_vertices(g, s, point, body_a, body_b, "point_seam_cycle");
  std::map<std::size_t, std::vector<std::size_t>> adj; // F* among the copies of `point`
  for (const auto& e : s.point_seam_edges) {
    if (e.point != point) continue;
    if (internal::same_seam_edge(e, point, body_a, body_b)) return {};
    std::size_t x = g.vertex(point, e.body_a), y = g.vertex(point, e.body_b);
    if (x == Seam_graph::npos || y == Seam_graph::npos)
      throw Input_error("point_seam_cycle: an edge of F* is not a point seam edge of the seam graph");
    adj[x].push_back(y);
    adj[y].push_back(x);
  }
  // breadth-first search from (point, body_b) to (point, body_a)
  std::map<std::size_t, std::size_t> from{{ab.second, ab.second}};
  std::vector<std::size_t> queue{ab.second};
  for (std::size_t q = 0; q < queue.size() && !from.count(ab.first); ++q)
    for (std::size_t y : adj[queue[q]])
      if (from.emplace(y, queue[q]).second) queue.push_back(y);
  if (!from.count(ab.first))
    throw Input_error("point_seam_cycle: F* does not join the two copies (not a maximal point-seam-cycle-avoiding extension)");
  std::vector<Seam_step> out{Seam_step{Seam_step::POINT, ab.first, ab.second}};
  std::vector<Seam_step> back; // from (point, body_a) back to (point, body_b), reversed below
  for (std::size_t v = ab.first; v != ab.second; v = from[v]) back.push_back(Seam_step{Seam_step::POINT, from[v], v});
  out.insert(out.end(), back.rbegin(), back.rend());
  return out;
}

/*!
\ingroup PkgRigidIncidenceRef
\brief Why coordinate 3 of the point seam edge (point, body_a) - (point, body_b) is redundant
in the selection `s`: the seam cycle the edge closes with the seam tree F1 (`s.seam_tree`).

The selection takes coordinate 3 of the point seam edges of the seam tree F1 only. The
incidence (point, {body_a, body_b}, 3) of an edge outside F1 (whether or not the edge is in
F*, whose coordinates 1 and 2 are taken) is redundant because its two copies are already
joined by a seam path of F1, so the edge closes a seam cycle. This function rebuilds a
`Seam_connectivity` from the edges of F1 and returns that cycle
(`Seam_connectivity::seam_cycle()`): the `POINT` step (point, body_a) -> (point, body_b)
followed by a seam path of F1 back, whose `POINT` steps are edges of F1 and whose `LINE`
steps come in partner pairs. Empty if the edge is in F1. `g` is the seam graph of
`s.bodies`. Costs about a greedy completion of the seam graph plus the cycle's length.
\throws Input_error if `g` is not the seam graph of `s.bodies`, if the edge is not a point
seam edge of `g`, if F1 has a seam cycle or does not join the edge's copies (`s` is not a
selection of this package), or if the cycle is longer than
`Seam_connectivity::default_max_steps`.
*/
inline std::vector<Seam_step> seam_cycle_of(const Seam_graph& g, const Well_formed_selection& s, std::size_t point,
                                             std::size_t body_a, std::size_t body_b)
{
  const std::pair<std::size_t, std::size_t> ab = internal::redundant_edge_vertices(g, s, point, body_a, body_b, "seam_cycle_of");
  for (const auto& e : s.seam_tree)
    if (internal::same_seam_edge(e, point, body_a, body_b)) return {};
  Seam_connectivity conn(g);
  for (const auto& e : s.seam_tree) {
    std::size_t x = g.vertex(e.point, e.body_a), y = g.vertex(e.point, e.body_b);
    if (x == Seam_graph::npos || y == Seam_graph::npos)
      throw Input_error("seam_cycle_of: an edge of the seam tree is not a point seam edge of the seam graph");
    if (!conn.add_point_seam_edge(x, y)) throw Input_error("seam_cycle_of: the seam tree has a seam cycle");
  }
  if (!conn.joined(ab.first, ab.second))
    throw Input_error("seam_cycle_of: the seam tree does not join the two copies (not a seam tree)");
  return conn.seam_cycle(ab.first, ab.second);
}

} // namespace Rigid_incidence
} // namespace CGAL

#endif
