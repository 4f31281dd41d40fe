// Copyright (c) 2026 Rigid_incidence contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The overlap graph (Definition 4 of optimized_incidence_tree_parametrization.txt,
// Definition 2 of well_formed_optimal_incidences.txt) on the Boost Graph Library.

#ifndef CGAL_RIGID_INCIDENCE_OVERLAP_GRAPH_H
#define CGAL_RIGID_INCIDENCE_OVERLAP_GRAPH_H

#include <CGAL/Rigid_incidence/Rigid_body_collection.h>

#include <boost/graph/adjacency_list.hpp>

#include <map>
#include <vector>

namespace CGAL {
namespace Rigid_incidence {

/// \ingroup PkgRigidIncidenceRef
/// The edge weight w(k) of Table 1: the dof left to a body attached to another by `k`
/// shared points: w(0) = 6, w(1) = 3, w(2) = 1, w(3) = 0.
inline int overlap_weight(std::size_t shared_points)
{
  static const int w[4] = {6, 3, 1, 0};
  return w[shared_points > 3 ? 3 : shared_points];
}

/*!
\ingroup PkgRigidIncidenceRef
\brief The weighted overlap graph of a collection: a vertex per body, an edge per pair.

The papers' overlap graph is complete; pairs of bodies sharing no point have weight
w(0) = 6. This class stores the edges of bodies that share points (weights 1 and 3)
explicitly as a `boost::adjacency_list` and answers `weight(i, j) == 6` for every other
pair, so that it stays linear in the size of the collection.
*/
class Overlap_graph
{
public:
  /// The property of an edge: its weight and the points the two bodies share.
  struct Edge_property
  {
    int weight;                       ///< w(number of shared points): 1 or 3
    std::vector<std::size_t> shared;  ///< the shared points (global indices)
  };
  /// The graph: a vertex per body (same index), an edge per pair of bodies sharing points.
  typedef boost::adjacency_list<boost::vecS, boost::vecS, boost::undirectedS, boost::no_property, Edge_property> Graph;

  Overlap_graph() = default;

  /// The overlap graph of the collection `c`.
  template <class Traits>
  explicit Overlap_graph(const Rigid_body_collection<Traits>& c) : graph_(c.number_of_bodies())
  {
    // Bodies through each point, then pairs among them: linear in the incidences.
    std::vector<std::vector<std::size_t>> through(c.number_of_points());
    for (std::size_t i = 0; i < c.number_of_bodies(); ++i)
      for (std::size_t p : c.body(i).points) through[p].push_back(i);
    std::map<std::pair<std::size_t, std::size_t>, std::vector<std::size_t>> shared;
    for (std::size_t p = 0; p < through.size(); ++p)
      for (std::size_t a = 0; a < through[p].size(); ++a)
        for (std::size_t b = a + 1; b < through[p].size(); ++b)
          shared[{through[p][a], through[p][b]}].push_back(p);
    for (const auto& s : shared)
      boost::add_edge(s.first.first, s.first.second, Edge_property{overlap_weight(s.second.size()), s.second}, graph_);
  }

  /// The Boost graph of the pairs that share points.
  const Graph& graph() const { return graph_; }
  /// The number of bodies (vertices).
  std::size_t number_of_bodies() const { return boost::num_vertices(graph_); }

  /// w(k) for the pair (i, j); 6 when they share no point.
  int weight(std::size_t i, std::size_t j) const
  {
    auto e = boost::edge(i, j, graph_);
    return e.second ? graph_[e.first].weight : 6;
  }
  /// The points shared by bodies i and j.
  std::vector<std::size_t> shared_points(std::size_t i, std::size_t j) const
  {
    auto e = boost::edge(i, j, graph_);
    return e.second ? graph_[e.first].shared : std::vector<std::size_t>();
  }

private:
  Graph graph_;
};

} // namespace Rigid_incidence
} // namespace CGAL

#endif
