// Copyright (c) 2026 Rigid_incidence contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Removed degrees of freedom (Definition 3 (i) of well_formed_optimal_incidences.txt) and
// the dof count of a collection.

#ifndef CGAL_RIGID_INCIDENCE_RDOF_H
#define CGAL_RIGID_INCIDENCE_RDOF_H

#include <CGAL/Rigid_incidence/Input_error.h>
#include <CGAL/Rigid_incidence/Rigid_body_collection.h>

#include <boost/graph/adjacency_list.hpp>
#include <boost/graph/connected_components.hpp>

#include <algorithm>
#include <map>
#include <string>
#include <vector>

namespace CGAL {
namespace Rigid_incidence {

/// \ingroup PkgRigidIncidenceRef
/// dof of the intersection of rigid bodies: 0 for no point, 3 for a point, 5 for a pair,
/// 6 for three or more points (a rigid body).
inline int intersection_dof(std::size_t points)
{
  static const int d[4] = {0, 3, 5, 6};
  return d[points > 3 ? 3 : points];
}

/*!
\ingroup PkgRigidIncidenceRef
\brief rdof(D, T) by its definition: the inclusion-exclusion sum
\f$\sum_{Q \subseteq T, |Q| > 1} (-1)^{|Q|} \mathrm{dof}(\bigcap_{c \in Q} c)\f$.

Exponential in |T| (subsets whose intersection is empty are skipped, which prunes most of
them); refuses subsets of more than 30 bodies. It is the oracle for `rdof()`.
*/
template <class Traits>
long rdof_inclusion_exclusion(const Rigid_body_collection<Traits>& c, const std::vector<std::size_t>& subset)
{
  if (subset.size() > 30) throw Input_error("rdof_inclusion_exclusion: at most 30 bodies");
  long total = 0;
  // Depth-first over subsets Q in increasing index order, carrying the intersection.
  struct Frame { std::size_t last; std::vector<std::size_t> inter; std::size_t size; };
  std::vector<Frame> st;
  for (std::size_t i = 0; i < subset.size(); ++i) st.push_back(Frame{i, c.body(subset[i]).points, 1});
  while (!st.empty()) {
    Frame f = std::move(st.back());
    st.pop_back();
    if (f.size >= 2) total += ((f.size % 2 == 0) ? 1 : -1) * intersection_dof(f.inter.size());
    for (std::size_t j = f.last + 1; j < subset.size(); ++j) {
      std::vector<std::size_t> inter;
      const auto& pj = c.body(subset[j]).points;
      std::set_intersection(f.inter.begin(), f.inter.end(), pj.begin(), pj.end(), std::back_inserter(inter));
      if (inter.empty()) continue; // every superset also has dof 0
      st.push_back(Frame{j, std::move(inter), f.size + 1});
    }
  }
  return total;
}

/*!
\ingroup PkgRigidIncidenceRef
\brief rdof(D, T) in closed form, linear in the incidences.

The paper states \f$5\sum_e(\#e-1) + 3\sum_v(\#v-1)\f$. Rebuilt by Moebius inversion:
with \f$n_v\f$ the number of bodies of T through point v and \f$n_e\f$ the number through
a pair e of points shared by two or more of them, dof(Q) = 3|∩Q| − [|∩Q| = 2] gives
\f$\mathrm{rdof} = 3\sum_v (n_v - 1) - \sum_e (n_e - 1)\f$, which is the paper's form with
\f$\#e = n_e\f$ and \f$\#v = n_v - \sum_{e \ni v} (n_e - 1)\f$ (a body that meets v through a
shared pair is counted there, not at v). Valid when no two bodies share more than two
points (a standard collection).
*/
template <class Traits>
long rdof(const Rigid_body_collection<Traits>& c, const std::vector<std::size_t>& subset)
{
  std::map<std::size_t, long> n_v;
  for (std::size_t b : subset) for (std::size_t p : c.body(b).points) ++n_v[p];
  std::map<std::pair<std::size_t, std::size_t>, long> n_e;
  for (std::size_t a = 0; a < subset.size(); ++a)
    for (std::size_t b = a + 1; b < subset.size(); ++b) {
      auto common = c.common_points(subset[a], subset[b]);
      if (common.size() == 2) n_e[{common[0], common[1]}] = 0;
    }
  for (auto& e : n_e)
    for (std::size_t b : subset)
      if (c.body(b).contains(e.first.first) && c.body(b).contains(e.first.second)) ++e.second;
  std::map<std::size_t, long> sharp_v; // #v of the paper
  for (const auto& v : n_v) sharp_v[v.first] = v.second;
  long pairs = 0;
  for (const auto& e : n_e) {
    pairs += e.second - 1;
    sharp_v[e.first.first] -= e.second - 1;
    sharp_v[e.first.second] -= e.second - 1;
  }
  long points = 0;
  for (const auto& v : sharp_v) points += v.second - 1;
  return 5 * pairs + 3 * points;
}

/// \ingroup PkgRigidIncidenceRef
/// The dof count of a collection and whether its bodies form one connected scene.
struct Dof_count
{
  long bodies = 0;          ///< number of bodies k
  long free_points = 0;     ///< points in no body (the far ends of bars), 3 dof each
  long body_dof = 0;        ///< 6 (k - 1) + 3 (free points): the dof of k free bodies, one of them fixed, and the free points
  long removed = 0;         ///< rdof(D, D): removed by the shared points
  long distances = 0;       ///< distances not absorbed into a body: one equation each
  long dof = 0;             ///< body_dof - removed - distances
  bool connected = true;    ///< the bodies and free points form one connected scene
  std::vector<std::vector<std::size_t>> components; ///< body indices per connected part (free points are not listed)

  /// "well-constrained", "under-constrained" or "over-constrained" by the count.
  std::string verdict() const
  {
    if (dof == 0) return "well-constrained";
    return dof > 0 ? "under-constrained" : "over-constrained";
  }
};

/*!
\ingroup PkgRigidIncidenceRef
\brief Counts the dof of a (standard) collection: 6(k-1) + 3 f - rdof(D, D) - (number of
distances), with f the points in no body (`Rigid_body_collection::free_points()`).

The count is necessary, not sufficient, for generic rigidity (deciding body-multi-pin
rigidity in general is as hard as 3D bar-and-joint rigidity, see the papers); the rank of
the rigidity matroid (`constraint_independence()`) decides it at a generic realization.
Bodies are connected through shared points and distances.
*/
template <class Traits>
Dof_count dof_count(const Rigid_body_collection<Traits>& c)
{
  Dof_count r;
  const std::size_t k = c.number_of_bodies();
  std::vector<std::size_t> all(k);
  for (std::size_t i = 0; i < k; ++i) all[i] = i;
  const std::vector<std::size_t> free = c.free_points();
  r.bodies = long(k);
  r.free_points = long(free.size());
  r.body_dof = 6 * (long(k) - 1) + 3 * r.free_points;
  r.removed = rdof(c, all);
  r.distances = long(c.distances().size());
  r.dof = r.body_dof - r.removed - r.distances;
  // vertices: the bodies, then the free points
  std::vector<std::size_t> vertex_of(c.number_of_points(), std::size_t(-1));
  for (std::size_t f = 0; f < free.size(); ++f) vertex_of[free[f]] = k + f;
  boost::adjacency_list<boost::vecS, boost::vecS, boost::undirectedS> g(k + free.size());
  std::vector<std::vector<std::size_t>> through(c.number_of_points());
  for (std::size_t i = 0; i < k; ++i) for (std::size_t p : c.body(i).points) through[p].push_back(i);
  for (std::size_t p = 0; p < through.size(); ++p) if (through[p].empty()) through[p].push_back(vertex_of[p]);
  for (const auto& t : through) for (std::size_t a = 1; a < t.size(); ++a) boost::add_edge(t[0], t[a], g);
  for (const auto& d : c.distances()) boost::add_edge(through[d.a][0], through[d.b][0], g);
  std::vector<int> comp(k + free.size());
  int nc = comp.empty() ? 0 : boost::connected_components(g, comp.data());
  r.components.assign(std::size_t(nc), {});
  for (std::size_t i = 0; i < k; ++i) r.components[std::size_t(comp[i])].push_back(i);
  r.components.erase(std::remove_if(r.components.begin(), r.components.end(),
                                    [](const std::vector<std::size_t>& v) { return v.empty(); }),
                     r.components.end());
  r.connected = nc <= 1;
  return r;
}

} // namespace Rigid_incidence
} // namespace CGAL

#endif
