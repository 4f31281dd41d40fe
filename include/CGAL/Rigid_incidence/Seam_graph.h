// Copyright (c) 2026 Rigid_incidence contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The seam graph (Section 5 of well_formed_optimal_incidences.txt) and the connectivity of
// seam paths in a seam forest, maintained incrementally.

#ifndef CGAL_RIGID_INCIDENCE_SEAM_GRAPH_H
#define CGAL_RIGID_INCIDENCE_SEAM_GRAPH_H

#include <CGAL/Rigid_incidence/Input_error.h>
#include <CGAL/Rigid_incidence/Rigid_body_collection.h>

#include <algorithm>
#include <cstdint>
#include <map>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

namespace CGAL {
namespace Rigid_incidence {

/*!
\ingroup PkgRigidIncidenceRef
\brief The seam graph of the collection D made of some bodies of a collection.

Vertices are the copies (v, c) of every point v shared by two or more bodies c of D. Point
seam edges join every two copies of the same point (a complete graph per point, kept
implicit); line seam edges join, in every body c containing a pair e = (v, w) shared by two or
more bodies of D, the copies (v, c) and (w, c) (one copy of e per body).
*/
class Seam_graph
{
public:
  static constexpr std::size_t npos = std::size_t(-1);  ///< no such vertex
  /// A copy (v, c) of a shared point.
  struct Vertex
  {
    std::size_t point;  ///< the shared point v
    std::size_t body;   ///< the body c
  };
  /// A pair of points shared by two or more bodies of D, with those bodies (sorted).
  struct Shared_pair
  {
    std::size_t v;                   ///< the smaller point index
    std::size_t w;                   ///< the larger point index
    std::vector<std::size_t> bodies; ///< the bodies of D through both
  };

  /// The seam graph of the bodies `D` of `c`.
  template <class Traits>
  Seam_graph(const Rigid_body_collection<Traits>& c, const std::vector<std::size_t>& D) : D_(D)
  {
    std::sort(D_.begin(), D_.end());
    std::map<std::size_t, std::vector<std::size_t>> through;
    for (std::size_t b : D_) for (std::size_t p : c.body(b).points) through[p].push_back(b);
    for (const auto& t : through) {
      if (t.second.size() < 2) continue;
      auto& list = copies_[t.first];
      for (std::size_t b : t.second) {
        index_[key(t.first, b)] = vertices_.size();
        list.push_back(vertices_.size());
        vertices_.push_back(Vertex{t.first, b});
      }
    }
    // pairs shared by two bodies of D, found through the points (linear in the incidences,
    // not quadratic in the bodies): the shared points of every two bodies meeting at a point
    std::map<std::pair<std::size_t, std::size_t>, std::vector<std::size_t>> meet; // (body, body) -> shared points
    for (const auto& t : through)
      for (std::size_t i = 0; i < t.second.size(); ++i)
        for (std::size_t j = i + 1; j < t.second.size(); ++j) meet[{t.second[i], t.second[j]}].push_back(t.first);
    std::map<std::pair<std::size_t, std::size_t>, std::vector<std::size_t>> pairs;
    for (const auto& m : meet)
      if (m.second.size() == 2) pairs[{(std::min)(m.second[0], m.second[1]), (std::max)(m.second[0], m.second[1])}];
    // bodies of D through both points of each pair (those through the first point, filtered)
    for (auto& e : pairs) {
      for (std::size_t b : through[e.first.first])
        if (c.body(b).contains(e.first.second)) e.second.push_back(b);
      pairs_of_point_[e.first.first].push_back(pairs_.size());
      pairs_of_point_[e.first.second].push_back(pairs_.size());
      pairs_.push_back(Shared_pair{e.first.first, e.first.second, e.second});
    }
  }

  /// The bodies of D, sorted.
  const std::vector<std::size_t>& bodies() const { return D_; }
  /// All vertices (copies).
  const std::vector<Vertex>& vertices() const { return vertices_; }
  /// The vertex (v, c), or `npos`.
  std::size_t vertex(std::size_t point, std::size_t body) const
  {
    auto it = index_.find(key(point, body));
    return it == index_.end() ? npos : it->second;
  }
  /// The copies of each shared point (vertex indices): point seam edges join any two of them.
  const std::map<std::size_t, std::vector<std::size_t>>& copies() const { return copies_; }
  /// The shared pairs; pair k has a line seam edge (v, c)-(w, c) for each of its bodies c.
  const std::vector<Shared_pair>& shared_pairs() const { return pairs_; }
  /// Indices into `shared_pairs()` of the pairs containing `point`.
  const std::vector<std::size_t>& pairs_of(std::size_t point) const
  {
    static const std::vector<std::size_t> none;
    auto it = pairs_of_point_.find(point);
    return it == pairs_of_point_.end() ? none : it->second;
  }
  /// Number of line seam edges.
  std::size_t number_of_line_seam_edges() const
  {
    std::size_t n = 0;
    for (const auto& e : pairs_) n += e.bodies.size();
    return n;
  }

private:
  static std::uint64_t key(std::size_t p, std::size_t b) { return (std::uint64_t(p) << 32) ^ std::uint64_t(b); }
  std::vector<std::size_t> D_;
  std::vector<Vertex> vertices_;
  std::unordered_map<std::uint64_t, std::size_t> index_;
  std::map<std::size_t, std::vector<std::size_t>> copies_;
  std::vector<Shared_pair> pairs_;
  std::map<std::size_t, std::vector<std::size_t>> pairs_of_point_;
};

/*!
\ingroup PkgRigidIncidenceRef
\brief One edge of a seam path or seam cycle, traversed from the vertex `from` to the vertex
`to` (indices into `Seam_graph::vertices()`).

A `POINT` step is a point seam edge: it joins two copies (v, c) and (v, c') of one point v.
A `LINE` step is a line seam edge: it joins the copies (v, c) and (w, c) of the two points of
a shared pair e = (v, w) in one body c through e.
*/
struct Seam_step
{
  /// The type of seam edge a step traverses.
  enum Kind
  {
    POINT, ///< a point seam edge (v, c) - (v, c')
    LINE   ///< a line seam edge (v, c) - (w, c) of a shared pair (v, w)
  };
  Kind kind;         ///< point or line seam edge
  std::size_t from;  ///< the vertex the step leaves
  std::size_t to;    ///< the vertex the step reaches
};

/*!
\ingroup PkgRigidIncidenceRef
\brief Which copies of a point a seam forest joins by seam paths, and the seam paths
themselves.

A seam forest holds all line seam edges and some point seam edges. Two copies of a point v
are joined by a seam path (Section 5) when point seam edges join them, or, recursively, when
for a shared pair e = (v, w) and two bodies c, c' through e the copies (w, c) and (w, c') are
joined: the path goes (v, c) - (w, c), along w's joined copies, then (w, c') - (v, c') on
the partner line seam edge. This class keeps these classes in a union-find and, when a point
seam edge is added, propagates the partner rule with a worklist of points whose classes
grew, so that a whole greedy completion costs about the size of the seam graph times its
pairs' body counts.

Every successful union also records its reason, in O(1): either a point seam edge a-b that
was added, or a derived join of (w, c)-(w, c') because the copies (v, c) and (v, c') were
already joined, through the shared pair (v, w). These reasons form an explanation forest on
the vertices; `seam_path()` expands the path between two copies in that forest into an
explicit seam path, and `seam_cycle()` explains why `add_point_seam_edge()` refused an edge.
*/
class Seam_connectivity
{
public:
  /// The default bound on the number of steps `seam_path()` and `seam_cycle()` return.
  static constexpr std::size_t default_max_steps = 1000000;

  /// No point seam edge yet: every copy on its own.
  explicit Seam_connectivity(const Seam_graph& g) : g_(g), parent_(g.vertices().size()), size_(g.vertices().size(), 1)
  {
    for (std::size_t i = 0; i < parent_.size(); ++i) parent_[i] = i;
  }
  /// `true` if the copies `a` and `b` (vertex indices) are joined by a seam path.
  bool joined(std::size_t a, std::size_t b) { return find(a) == find(b); }
  /// Adds the point seam edge a-b (copies of one point); returns false if a seam path already
  /// joined them (the edge would close a seam cycle).
  /// \throws Input_error if `a` or `b` is not a vertex, or if they are not two distinct
  /// copies of one point.
  bool add_point_seam_edge(std::size_t a, std::size_t b)
  {
    check_point_seam_edge(a, b, "add_point_seam_edge");
    if (!unite(a, b, Seam_graph::npos, Seam_graph::npos, Seam_graph::npos)) return false;
    std::vector<std::size_t> work{g_.vertices()[a].point};
    while (!work.empty()) {
      std::size_t u = work.back();
      work.pop_back();
      for (std::size_t k : g_.pairs_of(u)) {
        const auto& e = g_.shared_pairs()[k];
        const std::size_t other = e.v == u ? e.w : e.v;
        // bodies of e whose copies of u are joined: join their copies of `other`
        // class of u-copy -> (a copy of `other`, the copy of u in the same body)
        std::map<std::size_t, std::pair<std::size_t, std::size_t>> first_in_class;
        bool grew = false;
        for (std::size_t body : e.bodies) {
          std::size_t vu = g_.vertex(u, body);
          std::size_t cu = find(vu), co = g_.vertex(other, body);
          auto it = first_in_class.find(cu);
          if (it == first_in_class.end()) first_in_class[cu] = {co, vu};
          else grew = unite(it->second.first, co, it->second.second, vu, k) || grew;
        }
        if (grew) work.push_back(other);
      }
    }
    return true;
  }

  /*!
  \brief A seam path from the copy `a` to the copy `b` of one point, in the current seam
  forest; empty if `a == b`.

  The path is the path between `a` and `b` in the explanation forest of the unions, with each
  derived join of (w, c)-(w, c') through the pair (v, w) expanded, recursively, into the
  `LINE` step (w, c) -> (v, c), a seam path (v, c) ~ (v, c'), and the partner `LINE` step
  (v, c') -> (w, c'). Its `POINT` steps are point seam edges added by
  `add_point_seam_edge()`; its `LINE` steps come in partner pairs (the same shared pair, two
  bodies), nested like brackets, as in Section 5 of well_formed_optimal_incidences.txt. A
  derived join only uses joins made before it, so the expansion terminates; it can still be
  long (each level of derivation can multiply the length), hence the bound `max_steps`.

  Costs O(V + J) to root the explanation forest (V vertices, J unions; done once after each
  change of the forest) plus the length of the path.
  \throws Input_error if `a` or `b` is not a vertex, if they are not joined, or if the path
  would have more than `max_steps` steps.
  */
  std::vector<Seam_step> seam_path(std::size_t a, std::size_t b, std::size_t max_steps = default_max_steps)
  {
    check_vertex(a, "seam_path");
    check_vertex(b, "seam_path");
    std::vector<Seam_step> out;
    if (a == b) return out;
    if (!joined(a, b)) throw Input_error("seam_path: the two copies are not joined by a seam path");
    root_forest();
    // tasks, last first: a LINE step to emit, a forest path to expand, or a join to expand
    struct Task { int type; std::size_t from, to, id; };
    enum { EMIT_LINE, PATH, JOIN };
    std::vector<Task> tasks{Task{PATH, a, b, joins_.size()}};
    std::vector<std::pair<std::size_t, bool>> edges;
    while (!tasks.empty()) {
      // every pending task emits at least one step
      if (out.size() + tasks.size() > max_steps)
        throw Input_error("seam_path: the seam path has more than " + std::to_string(max_steps) + " steps");
      Task t = tasks.back();
      tasks.pop_back();
      if (t.type == EMIT_LINE) { out.push_back(Seam_step{Seam_step::LINE, t.from, t.to}); continue; }
      if (t.type == PATH) {
        forest_path(t.from, t.to, edges);
        for (std::size_t n = edges.size(); n-- > 0;) {
          const std::size_t id = edges[n].first;
          if (id >= t.id) // the order stamps: a derived join is explained by earlier joins only
            throw Input_error("seam_path: a join is explained by a later join (internal error)");
          const Join& j = joins_[id];
          tasks.push_back(edges[n].second ? Task{JOIN, j.x, j.y, id} : Task{JOIN, j.y, j.x, id});
        }
        continue;
      }
      const Join& j = joins_[t.id];
      if (j.pair == Seam_graph::npos) { out.push_back(Seam_step{Seam_step::POINT, t.from, t.to}); continue; }
      const bool forward = t.from == j.x;
      const std::size_t u_from = forward ? j.ux : j.uy, u_to = forward ? j.uy : j.ux;
      // LINE from -> u_from, the seam path u_from ~ u_to (earlier joins), LINE u_to -> to
      tasks.push_back(Task{EMIT_LINE, u_to, t.to, 0});
      tasks.push_back(Task{PATH, u_from, u_to, t.id});
      tasks.push_back(Task{EMIT_LINE, t.from, u_from, 0});
    }
    return out;
  }

  /*!
  \brief The seam cycle that the point seam edge a-b closes, for an edge that
  `add_point_seam_edge()` refused: the `POINT` step a -> b followed by `seam_path(b, a)`.

  Empty if a-b is itself an edge of the seam forest (it was added, so it closes nothing).
  \throws Input_error if `a` and `b` are not two distinct copies of one point, if they are
  not joined (the edge closes no seam cycle), or if the cycle would have more than
  `max_steps` steps.
  */
  std::vector<Seam_step> seam_cycle(std::size_t a, std::size_t b, std::size_t max_steps = default_max_steps)
  {
    check_point_seam_edge(a, b, "seam_cycle");
    if (!joined(a, b)) throw Input_error("seam_cycle: the two copies are not joined: the edge closes no seam cycle");
    std::vector<Seam_step> path = seam_path(b, a, max_steps == 0 ? 0 : max_steps - 1);
    if (path.size() == 1 && path[0].kind == Seam_step::POINT) return {}; // the forest's own edge a-b
    std::vector<Seam_step> out;
    out.reserve(path.size() + 1);
    out.push_back(Seam_step{Seam_step::POINT, a, b});
    out.insert(out.end(), path.begin(), path.end());
    return out;
  }

private:
  // The reason of a union: the point seam edge x-y (pair == npos), or the derived join of x-y
  // (copies of one point w) because their partners ux, uy (copies of v in the same bodies)
  // were joined, through the shared pair `pair` = (v, w). The index in joins_ is its stamp.
  struct Join { std::size_t x, y, ux, uy, pair; };

  void check_vertex(std::size_t a, const char* where) const
  {
    if (a >= g_.vertices().size()) throw Input_error(std::string(where) + ": no such vertex of the seam graph");
  }
  void check_point_seam_edge(std::size_t a, std::size_t b, const char* where) const
  {
    check_vertex(a, where);
    check_vertex(b, where);
    if (a == b || g_.vertices()[a].point != g_.vertices()[b].point)
      throw Input_error(std::string(where) + ": not a point seam edge (two distinct copies of one point)");
  }
  std::size_t find(std::size_t x)
  {
    while (parent_[x] != x) x = parent_[x] = parent_[parent_[x]];
    return x;
  }
  bool unite(std::size_t x, std::size_t y, std::size_t ux, std::size_t uy, std::size_t pair)
  {
    std::size_t a = find(x), b = find(y);
    if (a == b) return false;
    if (size_[a] < size_[b]) std::swap(a, b);
    parent_[b] = a;
    size_[a] += size_[b];
    joins_.push_back(Join{x, y, ux, uy, pair});
    return true;
  }
  // Roots every tree of the explanation forest (parent join and depth per vertex), once per
  // change of the forest.
  void root_forest()
  {
    if (rooted_joins_ == joins_.size() && up_.size() == parent_.size()) return;
    const std::size_t n = parent_.size();
    std::vector<std::size_t> start(n + 1, 0), adj(2 * joins_.size());
    for (const Join& j : joins_) { ++start[j.x + 1]; ++start[j.y + 1]; }
    for (std::size_t i = 0; i < n; ++i) start[i + 1] += start[i];
    std::vector<std::size_t> fill(start.begin(), start.end() - 1);
    for (std::size_t id = 0; id < joins_.size(); ++id) { adj[fill[joins_[id].x]++] = id; adj[fill[joins_[id].y]++] = id; }
    up_.assign(n, Seam_graph::npos);
    depth_.assign(n, 0);
    std::vector<char> seen(n, 0);
    std::vector<std::size_t> queue;
    for (std::size_t r = 0; r < n; ++r) {
      if (seen[r]) continue;
      seen[r] = 1;
      queue.assign(1, r);
      for (std::size_t q = 0; q < queue.size(); ++q) {
        const std::size_t v = queue[q];
        for (std::size_t i = start[v]; i < start[v + 1]; ++i) {
          const Join& j = joins_[adj[i]];
          const std::size_t w = j.x == v ? j.y : j.x;
          if (seen[w]) continue;
          seen[w] = 1;
          up_[w] = adj[i];
          depth_[w] = depth_[v] + 1;
          queue.push_back(w);
        }
      }
    }
    rooted_joins_ = joins_.size();
  }
  std::size_t up_vertex(std::size_t v) const
  {
    const Join& j = joins_[up_[v]];
    return j.x == v ? j.y : j.x;
  }
  // The joins on the explanation forest's path from a to b (joined), in order, each with
  // `true` if it is traversed from its x to its y.
  void forest_path(std::size_t a, std::size_t b, std::vector<std::pair<std::size_t, bool>>& out) const
  {
    out.clear();
    std::vector<std::pair<std::size_t, bool>> back; // from b upwards, reversed at the end
    while (a != b) {
      if (depth_[a] >= depth_[b]) {
        const std::size_t id = up_[a];
        out.push_back({id, joins_[id].x == a});
        a = up_vertex(a);
      } else {
        const std::size_t id = up_[b];
        back.push_back({id, joins_[id].y == b}); // traversed towards b
        b = up_vertex(b);
      }
    }
    out.insert(out.end(), back.rbegin(), back.rend());
  }

  const Seam_graph& g_;
  std::vector<std::size_t> parent_, size_;
  std::vector<Join> joins_;                         // the explanation forest, in union order
  std::size_t rooted_joins_ = Seam_graph::npos;     // joins_.size() when up_/depth_ were built
  std::vector<std::size_t> up_, depth_;             // per vertex: join to its parent, depth
};

} // namespace Rigid_incidence
} // namespace CGAL

#endif
