// Copyright (c) 2026 Rigid_incidence contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The Optimal Well-formed Incidence Selection Algorithm (Section 6 of
// well_formed_optimal_incidences.txt): the incidences of an incidence tree, extended greedily
// through the seam graph to a well-formed set.

#ifndef CGAL_RIGID_INCIDENCE_WELL_FORMED_INCIDENCES_H
#define CGAL_RIGID_INCIDENCE_WELL_FORMED_INCIDENCES_H

#include <CGAL/Rigid_incidence/Incidence.h>
#include <CGAL/Rigid_incidence/Input_error.h>
#include <CGAL/Rigid_incidence/Rigid_body_collection.h>
#include <CGAL/Rigid_incidence/optimal_incidence_tree.h>

#include <boost/pending/disjoint_sets.hpp>

#include <algorithm>
#include <map>
#include <utility>
#include <vector>

namespace CGAL {
namespace Rigid_incidence {

/// \ingroup PkgRigidIncidenceRef
/// The result of `select_well_formed_incidences()`.
struct Well_formed_selection
{
  /// Whether an incidence is eliminated by the tree's parametrization or left as an equation.
  enum Role { TREE, REMAINING };
  std::vector<std::size_t> bodies;  ///< D: the bodies of the tree (its covering set), sorted
  Incidence_set incidences;         ///< the selected, well-formed incidences
  std::vector<Role> roles;          ///< per incidence of `incidences` (in its order)
  std::size_t tree_count = 0;       ///< incidences eliminated by the tree
  std::size_t remaining_count = 0;  ///< incidences left as equations of the reduced system
};

namespace internal {

// Copies (v, c) of the shared points of D: the vertices of the seam graph.
class Seam_copies
{
public:
  template <class Traits>
  Seam_copies(const Rigid_body_collection<Traits>& c, const std::vector<std::size_t>& D)
  {
    for (std::size_t b : D)
      for (std::size_t p : c.body(b).points) bodies_of_[p].push_back(b);
    for (auto it = bodies_of_.begin(); it != bodies_of_.end();)
      it = it->second.size() < 2 ? bodies_of_.erase(it) : std::next(it);
    for (const auto& pb : bodies_of_)
      for (std::size_t b : pb.second) { index_[{pb.first, b}] = count_++; }
  }
  std::size_t size() const { return count_; }
  std::size_t id(std::size_t p, std::size_t b) const { return index_.at({p, b}); }
  bool shared(std::size_t p) const { return bodies_of_.count(p) > 0; }
  const std::map<std::size_t, std::vector<std::size_t>>& bodies_of() const { return bodies_of_; }

private:
  std::map<std::size_t, std::vector<std::size_t>> bodies_of_; // shared point -> bodies of D through it
  std::map<std::pair<std::size_t, std::size_t>, std::size_t> index_;
  std::size_t count_ = 0;
};

} // namespace internal

/*!
\ingroup PkgRigidIncidenceRef
\brief The Optimal Well-formed Incidence Selection Algorithm (Section 6 of
well_formed_optimal_incidences.txt) for the collection D of the bodies of `tree`.

1. Each tree edge gives its seam-graph edges (Section 6.1): an edge of weight 3 (one shared
   point v) the triple incidence of v, an edge of weight 1 (a shared pair v, w, v the smaller
   point index) the triple of v (into Q) and the double of w (into P).
2. (a) Q is a seam forest F0. (b) Point seam edges are added to it, point by point and pair of
   bodies by pair of bodies, whenever their two copies are not yet joined by a seam path, until
   none can be: the seam tree F1. Seam-path connectivity is kept as a union-find over the copies
   (v, c), closed under the partner rule of seam paths: if the copies of w in c and c' are
   joined and c, c' both contain the pair (v, w), the copies of v in c and c' are joined.
   (c) F1 and P are extended, per point, to a spanning tree of the point's copies (no
   point-seam cycle): F*.
3. Each edge of F* gives coordinates 1 and 2 of its point; each edge of F1 also coordinate 3.
Incidences that come from tree edges are marked TREE, the others REMAINING.

\pre the tree's edges have weight 1 or 3 (a tree edge of weight 6 joins bodies sharing no
point and eliminates no incidence; it is accepted and contributes none).
*/
template <class Traits>
Well_formed_selection select_well_formed_incidences(const Rigid_body_collection<Traits>& c, const Incidence_tree& tree)
{
  Well_formed_selection out;
  out.bodies = tree.covering_set;
  std::sort(out.bodies.begin(), out.bodies.end());
  internal::Seam_copies copies(c, out.bodies);
  const std::size_t n = copies.size();
  std::vector<std::size_t> rank_seam(n), parent_seam(n), rank_point(n), parent_point(n);
  boost::disjoint_sets<std::size_t*, std::size_t*> seam(rank_seam.data(), parent_seam.data());   // seam paths
  boost::disjoint_sets<std::size_t*, std::size_t*> point(rank_point.data(), parent_point.data()); // point seam edges
  for (std::size_t i = 0; i < n; ++i) { seam.make_set(i); point.make_set(i); }

  // shared pairs of D: (v, w) -> bodies of D containing both
  std::map<std::pair<std::size_t, std::size_t>, std::vector<std::size_t>> pairs;
  for (std::size_t a = 0; a < out.bodies.size(); ++a)
    for (std::size_t b = a + 1; b < out.bodies.size(); ++b) {
      auto common = c.common_points(out.bodies[a], out.bodies[b]);
      if (common.size() == 2) pairs[{common[0], common[1]}];
    }
  for (auto& e : pairs)
    for (std::size_t b : out.bodies)
      if (c.body(b).contains(e.first.first) && c.body(b).contains(e.first.second)) e.second.push_back(b);

  // Close the seam union-find under the partner rule, to a fixpoint.
  auto close = [&]() {
    bool changed = true;
    while (changed) {
      changed = false;
      for (const auto& e : pairs) {
        const auto& S = e.second;
        for (std::size_t i = 0; i < S.size(); ++i)
          for (std::size_t j = i + 1; j < S.size(); ++j)
            for (int side = 0; side < 2; ++side) {
              std::size_t v = side ? e.first.second : e.first.first, w = side ? e.first.first : e.first.second;
              if (seam.find_set(copies.id(w, S[i])) == seam.find_set(copies.id(w, S[j])) &&
                  seam.find_set(copies.id(v, S[i])) != seam.find_set(copies.id(v, S[j]))) {
                seam.union_set(copies.id(v, S[i]), copies.id(v, S[j]));
                changed = true;
              }
            }
      }
    }
  };

  std::map<Incidence, Well_formed_selection::Role> chosen;
  std::vector<std::pair<std::size_t, std::pair<std::size_t, std::size_t>>> F1, Fstar; // (point, (body, body))
  // 1. and 2(a): Q(S_D) into the seam forest, P(S_D) kept for 2(c)
  std::vector<std::pair<std::size_t, std::pair<std::size_t, std::size_t>>> P;
  for (const auto& e : tree.edges) {
    std::vector<std::size_t> shared = c.common_points(e.parent, e.child);
    if (shared.empty()) continue;
    if (shared.size() > 2) throw Input_error("select_well_formed_incidences: bodies share 3 or more points (not standard)");
    std::size_t v = shared[0];
    seam.union_set(copies.id(v, e.parent), copies.id(v, e.child));
    F1.push_back({v, {e.parent, e.child}});
    if (shared.size() == 2) P.push_back({shared[1], {e.parent, e.child}});
  }
  close();
  // 2(b): complete to a seam tree
  for (const auto& pb : copies.bodies_of()) {
    const std::size_t v = pb.first;
    const auto& bs = pb.second;
    for (std::size_t i = 0; i < bs.size(); ++i)
      for (std::size_t j = i + 1; j < bs.size(); ++j)
        if (seam.find_set(copies.id(v, bs[i])) != seam.find_set(copies.id(v, bs[j]))) {
          seam.union_set(copies.id(v, bs[i]), copies.id(v, bs[j]));
          F1.push_back({v, {bs[i], bs[j]}});
          close();
        }
  }
  // 2(c): F1, then P, then any edge, per point without point-seam cycles
  auto add_point_edge = [&](std::size_t v, std::size_t a, std::size_t b) {
    if (point.find_set(copies.id(v, a)) == point.find_set(copies.id(v, b))) return false;
    point.union_set(copies.id(v, a), copies.id(v, b));
    Fstar.push_back({v, {a, b}});
    return true;
  };
  for (const auto& f : F1)
    if (!add_point_edge(f.first, f.second.first, f.second.second))
      throw Input_error("select_well_formed_incidences: the seam tree has a point-seam cycle (internal error)");
  for (const auto& f : P) add_point_edge(f.first, f.second.first, f.second.second);
  for (const auto& pb : copies.bodies_of())
    for (std::size_t i = 0; i < pb.second.size(); ++i)
      for (std::size_t j = i + 1; j < pb.second.size(); ++j) add_point_edge(pb.first, pb.second[i], pb.second[j]);
  // 3: incidences; roles from the tree's triples (Q) and doubles (P)
  std::map<Incidence, bool> from_tree;
  for (const auto& e : tree.edges) {
    std::vector<std::size_t> shared = c.common_points(e.parent, e.child);
    if (shared.size() >= 1) for (int p : {1, 2, 3}) from_tree[Incidence(shared[0], e.parent, e.child, p)] = true;
    if (shared.size() == 2) for (int p : {1, 2}) from_tree[Incidence(shared[1], e.parent, e.child, p)] = true;
  }
  std::vector<Incidence> all;
  for (const auto& f : Fstar) for (int p : {1, 2}) all.push_back(Incidence(f.first, f.second.first, f.second.second, p));
  for (const auto& f : F1) all.push_back(Incidence(f.first, f.second.first, f.second.second, 3));
  out.incidences = Incidence_set(all);
  for (const Incidence& i : out.incidences) {
    bool t = from_tree.count(i) > 0;
    out.roles.push_back(t ? Well_formed_selection::TREE : Well_formed_selection::REMAINING);
    (t ? out.tree_count : out.remaining_count) += 1;
  }
  return out;
}

} // namespace Rigid_incidence
} // namespace CGAL

#endif
