// Copyright (c) 2026 Rigid_incidence contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Definition 4 of well_formed_optimal_incidences.txt, checked exhaustively: the oracle for
// every incidence selection of the package.

#ifndef CGAL_RIGID_INCIDENCE_IS_WELL_FORMED_H
#define CGAL_RIGID_INCIDENCE_IS_WELL_FORMED_H

#include <CGAL/Rigid_incidence/Incidence.h>
#include <CGAL/Rigid_incidence/Input_error.h>
#include <CGAL/Rigid_incidence/Rigid_body_collection.h>
#include <CGAL/Rigid_incidence/rdof.h>

#include <cstdint>
#include <functional>
#include <map>
#include <string>
#include <vector>

namespace CGAL {
namespace Rigid_incidence {

/// \ingroup PkgRigidIncidenceRef
/// The outcome of `is_well_formed()`: the first violation of Definition 4 found, if any.
struct Well_formedness_report
{
  /// Which property fails.
  enum Violation
  {
    NONE,             ///< well-formed
    INVALID,          ///< an incidence names a point not shared by its two bodies, a body outside D, or a coordinate not in 1..3
    LOCAL_CYCLE,      ///< (a): incidences of one point and one coordinate close a cycle of 3 or more bodies
    SUBSET_OVERCOUNT, ///< (b): a subset T of bodies with |I(D,T)| > rdof(D,T)
    COUNT_MISMATCH    ///< (c): |I(D)| != rdof(D,D)
  };
  Violation violation = NONE;        ///< the first violation found (NONE if well-formed)
  std::vector<std::size_t> subset;   ///< (b): the bodies of T (smallest first found); (c): D
  std::vector<Incidence> cycle;      ///< (a): the incidences of the cycle; INVALID: the incidence
  long count = 0;                    ///< (b), (c): the number of incidences within the subset
  long rdof = 0;                     ///< (b), (c): rdof of the subset
  std::string message;               ///< a sentence naming bodies and points

  /// `true` if the set is well-formed.
  bool well_formed() const { return violation == NONE; }
};

/*!
\ingroup PkgRigidIncidenceRef
\brief Checks Definition 4 of well_formed_optimal_incidences.txt for the incidences `I` of the
collection of maximal rigid bodies D made of the bodies `D` of `c`:
(a) no local incidence cycle, (b) \f$|I(D,T)| \le \mathrm{rdof}(D,T)\f$ for every subset T of D,
(c) \f$|I(D)| = \mathrm{rdof}(D,D)\f$.

(a) is checked per point and coordinate with a union-find over the bodies; (b) over every
subset of D by increasing size, so the subset reported is a smallest one; this is exponential
and refused beyond `max_bodies` bodies (default 16). rdof is the closed form of `rdof()`.
*/
template <class Traits>
Well_formedness_report is_well_formed(const Rigid_body_collection<Traits>& c, const Incidence_set& I,
                                      const std::vector<std::size_t>& D, std::size_t max_bodies = 16)
{
  Well_formedness_report r;
  if (D.size() > max_bodies || D.size() > 62)
    throw Input_error("is_well_formed: " + std::to_string(D.size()) + " bodies, more than the exhaustive check allows (" +
                      std::to_string(max_bodies) + ")");
  std::map<std::size_t, std::size_t> local; // body -> position in D
  for (std::size_t k = 0; k < D.size(); ++k) local[D[k]] = k;
  auto body_name = [&](std::size_t b) { return "'" + c.body(b).name + "'"; };
  // validity
  for (const Incidence& i : I) {
    bool ok = i.coordinate >= 1 && i.coordinate <= 3 && i.body_a != i.body_b && local.count(i.body_a) && local.count(i.body_b) &&
              i.point < c.number_of_points() && c.body(i.body_a).contains(i.point) && c.body(i.body_b).contains(i.point);
    if (!ok) {
      r.violation = Well_formedness_report::INVALID;
      r.cycle = {i};
      r.message = "incidence (point " + (i.point < c.number_of_points() ? "'" + c.label(i.point) + "'" : std::to_string(i.point)) +
                  ", bodies " + std::to_string(i.body_a) + " and " + std::to_string(i.body_b) + ", coordinate " +
                  std::to_string(i.coordinate) + ") does not join two bodies of D through a point they share";
      return r;
    }
  }
  // (a) local incidence cycles: per (point, coordinate), the incidences must form a forest
  std::map<std::pair<std::size_t, int>, std::vector<Incidence>> groups;
  for (const Incidence& i : I) groups[{i.point, i.coordinate}].push_back(i);
  for (const auto& g : groups) {
    std::map<std::size_t, std::vector<std::pair<std::size_t, Incidence>>> adj;
    std::map<std::size_t, std::size_t> parent;
    std::function<std::size_t(std::size_t)> find = [&](std::size_t x) {
      if (!parent.count(x)) parent[x] = x;
      return parent[x] == x ? x : parent[x] = find(parent[x]);
    };
    for (const Incidence& i : g.second) {
      std::size_t ra = find(i.body_a), rb = find(i.body_b);
      if (ra == rb) {
        // the cycle: i plus the path from body_a to body_b among the incidences seen so far
        std::map<std::size_t, std::pair<std::size_t, Incidence>> came;
        std::vector<std::size_t> queue{i.body_a};
        came[i.body_a] = {i.body_a, i};
        for (std::size_t k = 0; k < queue.size() && !came.count(i.body_b); ++k)
          for (const auto& e : adj[queue[k]])
            if (!came.count(e.first)) { came[e.first] = {queue[k], e.second}; queue.push_back(e.first); }
        r.violation = Well_formedness_report::LOCAL_CYCLE;
        r.cycle.push_back(i);
        for (std::size_t x = i.body_b; x != i.body_a; x = came[x].first) r.cycle.push_back(came[x].second);
        r.message = "local incidence cycle (Definition 4 (a)): coordinate " + std::to_string(g.first.second) + " of point '" +
                    c.label(g.first.first) + "' is matched around " + std::to_string(r.cycle.size()) + " bodies:";
        for (const Incidence& e : r.cycle) r.message += " " + body_name(e.body_a) + "-" + body_name(e.body_b);
        return r;
      }
      parent[ra] = rb;
      adj[i.body_a].push_back({i.body_b, i});
      adj[i.body_b].push_back({i.body_a, i});
    }
  }
  // (b) every subset T, by increasing size
  const std::size_t n = D.size();
  std::vector<std::uint64_t> mask;
  for (const Incidence& i : I) mask.push_back((std::uint64_t(1) << local[i.body_a]) | (std::uint64_t(1) << local[i.body_b]));
  for (std::size_t k = 2; k <= n; ++k) {
    // Gosper's hack over the k-subsets of n
    std::uint64_t t = (std::uint64_t(1) << k) - 1, limit = std::uint64_t(1) << n;
    while (t < limit) {
      long count = 0;
      for (std::uint64_t m : mask) count += ((m & t) == m);
      if (count > 0) {
        std::vector<std::size_t> T;
        for (std::size_t b = 0; b < n; ++b) if (t >> b & 1) T.push_back(D[b]);
        long rd = Rigid_incidence::rdof(c, T);
        if (count > rd) {
          r.violation = Well_formedness_report::SUBSET_OVERCOUNT;
          r.subset = T;
          r.count = count;
          r.rdof = rd;
          r.message = "Definition 4 (b): the " + std::to_string(count) + " incidences among bodies";
          for (std::size_t b : T) r.message += " " + body_name(b);
          r.message += " exceed their rdof " + std::to_string(rd) + " (redundant incidences)";
          return r;
        }
      }
      std::uint64_t lowest = t & (~t + 1), ripple = t + lowest;
      t = (((ripple ^ t) >> 2) / lowest) | ripple;
    }
  }
  // (c)
  long rd = Rigid_incidence::rdof(c, D);
  if (long(I.size()) != rd) {
    r.violation = Well_formedness_report::COUNT_MISMATCH;
    r.subset = D;
    r.count = long(I.size());
    r.rdof = rd;
    r.message = "Definition 4 (c): " + std::to_string(I.size()) + " incidences, but rdof(D, D) = " + std::to_string(rd) +
                (long(I.size()) < rd ? " (essential incidences are missing)" : "");
    return r;
  }
  r.message = "well-formed: " + std::to_string(I.size()) + " incidences = rdof(D, D)";
  return r;
}

} // namespace Rigid_incidence
} // namespace CGAL

#endif
