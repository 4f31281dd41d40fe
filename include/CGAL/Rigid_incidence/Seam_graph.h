// Copyright (c) 2026 Rigid_incidence contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The seam graph (Section 5 of well_formed_optimal_incidences.txt) and the connectivity of
// seam paths in a seam forest, maintained incrementally.

#ifndef CGAL_RIGID_INCIDENCE_SEAM_GRAPH_H
#define CGAL_RIGID_INCIDENCE_SEAM_GRAPH_H

#include <CGAL/Rigid_incidence/Rigid_body_collection.h>

#include <algorithm>
#include <cstdint>
#include <map>
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
\brief Which copies of a point a seam forest joins by seam paths.

A seam forest holds all line seam edges and some point seam edges. Two copies of a point v
are joined by a seam path (Section 5) when point seam edges join them, or, recursively, when
for a shared pair e = (v, w) and two bodies c, c' through e the copies (w, c) and (w, c') are
joined: the path goes (v, c) - (w, c), along w's joined copies, then (w, c') - (v, c') on
the partner line seam edge. This class keeps these classes in a union-find and, when a point
seam edge is added, propagates the partner rule with a worklist of points whose classes
grew, so that a whole greedy completion costs about the size of the seam graph times its
pairs' body counts.
*/
class Seam_connectivity
{
public:
  /// No point seam edge yet: every copy on its own.
  explicit Seam_connectivity(const Seam_graph& g) : g_(g), parent_(g.vertices().size()), size_(g.vertices().size(), 1)
  {
    for (std::size_t i = 0; i < parent_.size(); ++i) parent_[i] = i;
  }
  /// `true` if the copies `a` and `b` (vertex indices) are joined by a seam path.
  bool joined(std::size_t a, std::size_t b) { return find(a) == find(b); }
  /// Adds the point seam edge a-b (copies of one point); returns false if a seam path already
  /// joined them (the edge would close a seam cycle).
  bool add_point_seam_edge(std::size_t a, std::size_t b)
  {
    if (!unite(a, b)) return false;
    std::vector<std::size_t> work{g_.vertices()[a].point};
    while (!work.empty()) {
      std::size_t u = work.back();
      work.pop_back();
      for (std::size_t k : g_.pairs_of(u)) {
        const auto& e = g_.shared_pairs()[k];
        const std::size_t other = e.v == u ? e.w : e.v;
        // bodies of e whose copies of u are joined: join their copies of `other`
        std::map<std::size_t, std::size_t> first_in_class; // class of u-copy -> a copy of `other`
        bool grew = false;
        for (std::size_t body : e.bodies) {
          std::size_t cu = find(g_.vertex(u, body)), co = g_.vertex(other, body);
          auto it = first_in_class.find(cu);
          if (it == first_in_class.end()) first_in_class[cu] = co;
          else grew = unite(it->second, co) || grew;
        }
        if (grew) work.push_back(other);
      }
    }
    return true;
  }

private:
  std::size_t find(std::size_t x)
  {
    while (parent_[x] != x) x = parent_[x] = parent_[parent_[x]];
    return x;
  }
  bool unite(std::size_t a, std::size_t b)
  {
    a = find(a); b = find(b);
    if (a == b) return false;
    if (size_[a] < size_[b]) std::swap(a, b);
    parent_[b] = a;
    size_[a] += size_[b];
    return true;
  }
  const Seam_graph& g_;
  std::vector<std::size_t> parent_, size_;
};

} // namespace Rigid_incidence
} // namespace CGAL

#endif
