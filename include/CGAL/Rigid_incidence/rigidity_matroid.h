// Copyright (c) 2026 Rigid_incidence contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The rigidity matroid of a collection at a random realization: which constraints of the
// system (incidences and distances) are independent, and, for each dependent one, the
// circuit it closes. This decides generic rigidity where the dof count only bounds it, picks
// the distances that rigidify the bodies outside the covering set, and names the constraints
// of an over-constrained scene that are in conflict.

#ifndef CGAL_RIGID_INCIDENCE_RIGIDITY_MATROID_H
#define CGAL_RIGID_INCIDENCE_RIGIDITY_MATROID_H

#include <CGAL/Rigid_incidence/Incidence.h>
#include <CGAL/Rigid_incidence/Input_error.h>
#include <CGAL/Rigid_incidence/Rigid_body_collection.h>
#include <CGAL/Rigid_incidence/optimal_incidence_tree.h>
#include <CGAL/Rigid_incidence/well_formed_incidences.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <map>
#include <random>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Rigid_incidence {

/// \ingroup PkgRigidIncidenceRef
/// One equation of the system of a collection: an incidence or a distance.
struct Constraint
{
  static constexpr std::size_t npos = std::size_t(-1); ///< "none"
  /// Where the constraint comes from.
  enum Origin
  {
    TREE_INCIDENCE,      ///< a well-formed incidence the incidence tree eliminates
    REMAINING_INCIDENCE, ///< a well-formed incidence left as an equation
    BODY_DISTANCE,       ///< a distance between two points of a body outside the covering set
    SCENE_DISTANCE       ///< a distance of the collection (`Rigid_body_collection::distances()`)
  };
  Origin origin = TREE_INCIDENCE; ///< where it comes from
  Incidence incidence;            ///< for an incidence
  std::size_t a = npos;           ///< for a distance: its first point
  std::size_t b = npos;           ///< for a distance: its second point
  std::size_t body = npos;        ///< for a BODY_DISTANCE: the body outside the covering set it belongs to
  std::size_t distance = npos;    ///< for a SCENE_DISTANCE: its index in `distances()`

  /// `true` for a distance, `false` for an incidence.
  bool is_distance() const { return origin == BODY_DISTANCE || origin == SCENE_DISTANCE; }
};

/// \ingroup PkgRigidIncidenceRef
/// The outcome of `constraint_independence()`.
struct Constraint_independence
{
  std::vector<std::size_t> bodies;       ///< the moving bodies (sorted); the first is held fixed
  std::vector<std::size_t> free_points;  ///< the points in no body, each with 3 variables
  std::size_t variables = 0;             ///< 6 (|bodies| - 1) + 3 |free_points|
  std::vector<Constraint> constraints;   ///< in the order the greedy took them
  std::vector<bool> independent;         ///< per constraint: independent of those before it
  /// Per constraint: empty if it is independent, else its fundamental circuit: the indices
  /// (into `constraints`, increasing, itself last) of a minimal dependent set made of it and
  /// independent constraints before it.
  std::vector<std::vector<std::size_t>> circuits;
  std::size_t rank = 0;                  ///< the number of independent constraints
  std::uint64_t seed = 0;                ///< the seed of the random realization

  /// The generic dof of the collection: variables minus rank (0: generically rigid).
  long generic_dof() const { return long(variables) - long(rank); }
  /// The indices of the dependent constraints.
  std::vector<std::size_t> dependent() const
  {
    std::vector<std::size_t> d;
    for (std::size_t i = 0; i < independent.size(); ++i) if (!independent[i]) d.push_back(i);
    return d;
  }
  /// `true` if constraint `i` is dependent only because a body outside the covering set has
  /// more distances than it needs: its circuit lies in that body's own distances, which the
  /// body's rigidity makes consistent. Such a constraint is harmless.
  bool follows_from_its_body(std::size_t i) const
  {
    if (independent[i] || constraints[i].origin != Constraint::BODY_DISTANCE) return false;
    for (std::size_t j : circuits[i])
      if (constraints[j].origin != Constraint::BODY_DISTANCE || constraints[j].body != constraints[i].body) return false;
    return true;
  }
  /// The constraints in conflict: dependent, and not merely a body's own surplus distance
  /// (`follows_from_its_body()`). The scene fixes each of them twice: over-constrained; it has
  /// configurations only if the given values agree.
  std::vector<std::size_t> conflicts() const
  {
    std::vector<std::size_t> d;
    for (std::size_t i = 0; i < independent.size(); ++i) if (!independent[i] && !follows_from_its_body(i)) d.push_back(i);
    return d;
  }
};

namespace internal {

// Arithmetic modulo the Mersenne prime 2^61 - 1.
struct Mod_p
{
  static constexpr std::uint64_t p = (std::uint64_t(1) << 61) - 1;
  static std::uint64_t reduce(unsigned __int128 x)
  {
    std::uint64_t lo = std::uint64_t(x & p), hi = std::uint64_t(x >> 61);
    std::uint64_t r = lo + hi;
    r = (r & p) + (r >> 61);
    return r >= p ? r - p : r;
  }
  static std::uint64_t add(std::uint64_t a, std::uint64_t b) { std::uint64_t r = a + b; return r >= p ? r - p : r; }
  static std::uint64_t sub(std::uint64_t a, std::uint64_t b) { return a >= b ? a - b : a + p - b; }
  static std::uint64_t mul(std::uint64_t a, std::uint64_t b) { return reduce((unsigned __int128)a * b); }
  static std::uint64_t pow(std::uint64_t a, std::uint64_t e)
  {
    std::uint64_t r = 1;
    for (; e; e >>= 1, a = mul(a, a)) if (e & 1) r = mul(r, a);
    return r;
  }
  static std::uint64_t inv(std::uint64_t a) { return pow(a, p - 2); }
};

} // namespace internal

/*!
\ingroup PkgRigidIncidenceRef
\brief The system's constraints in the order the reduced system takes them: the selection's
incidences (TREE first, then REMAINING), then every distance between two points of each body
outside the covering set that lie in the covering set's bodies (the body's own rigidity; the
greedy keeps the ones needed), then the collection's distances.

The points of a body outside the covering set that no covering body contains are private to
it: nothing else refers to them, so they need no equation. A distance between two points that
lie together in one covering body is left out too: that body's rigidity holds it, and
`standardize()` checked that the two bodies agree on it (a shared pair). For the same
reason a pair that several bodies outside the covering set fix is listed once.
*/
template <class Traits>
std::vector<Constraint> system_constraints(const Rigid_body_collection<Traits>& c, const Incidence_tree& tree,
                                           const Well_formed_selection& s)
{
  std::vector<Constraint> out;
  for (int pass = 0; pass < 2; ++pass)
    for (std::size_t i = 0; i < s.incidences.size(); ++i) {
      const bool t = s.roles[i] == Well_formed_selection::TREE;
      if (t != (pass == 0)) continue;
      Constraint k;
      k.origin = t ? Constraint::TREE_INCIDENCE : Constraint::REMAINING_INCIDENCE;
      k.incidence = *(s.incidences.begin() + std::ptrdiff_t(i));
      out.push_back(k);
    }
  std::vector<bool> covered(c.number_of_points(), false);
  for (std::size_t b : tree.covering_set) for (std::size_t p : c.body(b).points) covered[p] = true;
  auto in_one_covering_body = [&](std::size_t p, std::size_t q) {
    for (std::size_t b : tree.covering_set)
      if (c.body(b).contains(p) && c.body(b).contains(q)) return true;
    return false;
  };
  std::set<std::pair<std::size_t, std::size_t>> emitted; // a pair two bodies fix is one constraint
  for (std::size_t b : tree.non_covering) {
    std::vector<std::size_t> pts;
    for (std::size_t p : c.body(b).points) if (covered[p]) pts.push_back(p);
    for (std::size_t i = 0; i < pts.size(); ++i)
      for (std::size_t j = i + 1; j < pts.size(); ++j) {
        if (in_one_covering_body(pts[i], pts[j])) continue;
        if (!emitted.insert({pts[i], pts[j]}).second) continue; // standardize() checked the bodies agree on it
        Constraint k;
        k.origin = Constraint::BODY_DISTANCE;
        k.a = pts[i];
        k.b = pts[j];
        k.body = b;
        out.push_back(k);
      }
  }
  for (std::size_t d = 0; d < c.distances().size(); ++d) {
    Constraint k;
    k.origin = Constraint::SCENE_DISTANCE;
    k.a = c.distances()[d].a;
    k.b = c.distances()[d].b;
    k.distance = d;
    out.push_back(k);
  }
  return out;
}

/*!
\ingroup PkgRigidIncidenceRef
\brief The rigidity matroid at a random realization: greedy over `constraints` in their order,
each one independent or dependent on those kept before it, with its fundamental circuit.

The bodies `D` move (a rotation and a translation each, the first body fixed) and so do the
points in no body (`Rigid_body_collection::free_points()`, a translation each). At a
realization where every point v sits at a random position y_v, the linearized equations
(equation (1) of well_formed_optimal_incidences.txt) are: for an incidence (v, {c, c'}, p)
the p-th coordinate of (w_c x y_v + t_c) - (w_c' x y_v + t_c'); for a distance between u and
v, 2 (y_u - y_v) . (m_u - m_v), m the motion of the point through the first body of D
containing it (the incidences tie the others to it), or its own translation for a free point.

The rows are reduced over the integers modulo the prime 2^61 - 1 at positions drawn uniformly
from that field (seeded by `seed`). Independence found this way is proved: a nonzero minor
modulo p is nonzero over the rationals, so the constraints are independent at a real
realization and hence generically. A dependency is generic except with probability at most
(2 r) / 2^61 for r constraints (Schwartz-Zippel: a minor is a polynomial of degree at most
2 r in the positions), that is below 1e-15 for any scene this package can take; call again
with another seed to confirm one. The cost is O(m r (n + r)) for m constraints, rank r and
n variables (dense rows: about a second at 1,000 variables); refused beyond `max_variables`
variables (default 1,500).

\pre the points of every constraint lie in bodies of `D` or in no body at all.
*/
template <class Traits>
Constraint_independence constraint_independence(const Rigid_body_collection<Traits>& c, std::vector<std::size_t> D,
                                                const std::vector<Constraint>& constraints,
                                                std::uint64_t seed = 20261122, std::size_t max_variables = 1500)
{
  typedef internal::Mod_p F;
  Constraint_independence r;
  std::sort(D.begin(), D.end());
  D.erase(std::unique(D.begin(), D.end()), D.end());
  r.bodies = D;
  r.free_points = c.free_points();
  r.seed = seed;
  r.constraints = constraints;
  if (D.empty()) throw Input_error("constraint_independence: no body");
  const std::size_t np = c.number_of_points();
  std::vector<std::size_t> column(c.number_of_bodies(), Constraint::npos); // first of the 6 columns of a body
  std::vector<bool> fixed(c.number_of_bodies(), false);
  fixed[D[0]] = true;
  std::size_t n = 0;
  for (std::size_t k = 1; k < D.size(); ++k) { column[D[k]] = n; n += 6; }
  std::vector<std::size_t> point_column(np, Constraint::npos);
  for (std::size_t p : r.free_points) { point_column[p] = n; n += 3; }
  r.variables = n;
  if (n > max_variables)
    throw Input_error("constraint_independence: " + std::to_string(n) + " variables, more than the dense rank test allows (" +
                      std::to_string(max_variables) + ")");
  // the body that carries each point's motion: the first body of D containing it
  std::vector<std::size_t> carrier(np, Constraint::npos);
  for (std::size_t b : D) for (std::size_t p : c.body(b).points) if (carrier[p] == Constraint::npos) carrier[p] = b;
  std::mt19937_64 rng(seed);
  std::vector<std::array<std::uint64_t, 3>> y(np);
  for (auto& v : y) for (auto& x : v) x = rng() % F::p;

  auto point_name = [&](std::size_t p) { return p < np ? "'" + c.label(p) + "'" : std::to_string(p); };
  // row += s * (d/d(motion) of coordinate q of the motion of point v through body b)
  auto add_point_motion = [&](std::vector<std::uint64_t>& row, std::size_t b, std::size_t v, std::uint64_t s, int q) {
    if (fixed[b]) return;
    const std::size_t col = column[b];
    const auto& p = y[v];
    // coordinate q of w x p + t: q=0: w1 p2 - w2 p1; q=1: w2 p0 - w0 p2; q=2: w0 p1 - w1 p0
    const int i1 = (q + 1) % 3, i2 = (q + 2) % 3;
    row[col + std::size_t(i1)] = F::add(row[col + std::size_t(i1)], F::mul(s, p[std::size_t(i2)]));
    row[col + std::size_t(i2)] = F::sub(row[col + std::size_t(i2)], F::mul(s, p[std::size_t(i1)]));
    row[col + 3 + std::size_t(q)] = F::add(row[col + 3 + std::size_t(q)], s);
  };
  auto motion_of = [&](std::vector<std::uint64_t>& row, std::size_t v, std::uint64_t s, int q, const std::string& what) {
    if (v >= np) throw Input_error("constraint_independence: " + what + " names point " + std::to_string(v) + ", not in the collection");
    if (carrier[v] != Constraint::npos) add_point_motion(row, carrier[v], v, s, q);
    else if (point_column[v] != Constraint::npos)
      row[point_column[v] + std::size_t(q)] = F::add(row[point_column[v] + std::size_t(q)], s);
    else
      throw Input_error("constraint_independence: " + what + " names point " + point_name(v) +
                        ", which lies in bodies outside the given ones");
  };

  // incremental echelon basis: reduced rows, their pivots, and their combinations of constraints
  std::vector<std::vector<std::uint64_t>> basis;
  std::vector<std::size_t> pivot;
  std::vector<std::map<std::size_t, std::uint64_t>> combo; // basis row = sum combo[k][j] * row(constraint j)
  for (std::size_t i = 0; i < constraints.size(); ++i) {
    const Constraint& k = constraints[i];
    std::vector<std::uint64_t> row(n, 0);
    if (!k.is_distance()) {
      const Incidence& inc = k.incidence;
      const std::string what = "incidence of point " + point_name(inc.point);
      if (inc.coordinate < 1 || inc.coordinate > 3) throw Input_error("constraint_independence: " + what + ": coordinate not in 1..3");
      for (std::size_t b : {inc.body_a, inc.body_b})
        if (b >= c.number_of_bodies() || !std::binary_search(D.begin(), D.end(), b) || inc.point >= np || !c.body(b).contains(inc.point))
          throw Input_error("constraint_independence: " + what + " names body " + std::to_string(b) +
                            ", not a given body through that point");
      add_point_motion(row, inc.body_a, inc.point, 1, inc.coordinate - 1);
      add_point_motion(row, inc.body_b, inc.point, F::p - 1, inc.coordinate - 1);
    } else {
      const std::string what = "distance " + point_name(k.a) + "-" + point_name(k.b);
      if (k.a >= np || k.b >= np || k.a == k.b) throw Input_error("constraint_independence: " + what + ": not two points of the collection");
      for (int q = 0; q < 3; ++q) {
        std::uint64_t d = F::mul(2, F::sub(y[k.a][std::size_t(q)], y[k.b][std::size_t(q)]));
        motion_of(row, k.a, d, q, what);
        motion_of(row, k.b, F::p - d, q, what);
      }
    }
    // reduce against the basis, keeping the combination
    std::map<std::size_t, std::uint64_t> comb{{i, 1}};
    for (std::size_t bi = 0; bi < basis.size(); ++bi) {
      const std::uint64_t f = row[pivot[bi]];
      if (f == 0) continue;
      const auto& br = basis[bi]; // normalized: br[pivot] == 1
      for (std::size_t j = 0; j < n; ++j)
        if (br[j]) row[j] = F::sub(row[j], F::mul(f, br[j]));
      for (const auto& e : combo[bi]) {
        std::uint64_t& x = comb[e.first];
        x = F::sub(x, F::mul(f, e.second));
      }
    }
    std::size_t pv = Constraint::npos;
    for (std::size_t j = 0; j < n; ++j) if (row[j]) { pv = j; break; }
    if (pv == Constraint::npos) {
      r.independent.push_back(false);
      std::vector<std::size_t> circuit;
      for (const auto& e : comb) if (e.second) circuit.push_back(e.first);
      r.circuits.push_back(circuit); // sorted (map order); i is the largest
      continue;
    }
    const std::uint64_t inv = F::inv(row[pv]);
    for (auto& x : row) if (x) x = F::mul(x, inv);
    for (auto& e : comb) e.second = F::mul(e.second, inv);
    for (auto it = comb.begin(); it != comb.end();) it = it->second ? std::next(it) : comb.erase(it);
    basis.push_back(std::move(row));
    pivot.push_back(pv);
    combo.push_back(std::move(comb));
    r.independent.push_back(true);
    r.circuits.push_back({});
  }
  r.rank = basis.size();
  return r;
}

/*!
\ingroup PkgRigidIncidenceRef
\brief A sentence naming a constraint: its point(s), bodies, coordinate or distance.
*/
template <class Traits>
std::string describe(const Rigid_body_collection<Traits>& c, const Constraint& k)
{
  auto body = [&](std::size_t b) { return "'" + c.body(b).name + "'"; };
  switch (k.origin) {
  case Constraint::TREE_INCIDENCE:
  case Constraint::REMAINING_INCIDENCE:
    return std::string(k.origin == Constraint::TREE_INCIDENCE ? "tree" : "remaining") + " incidence " + c.label(k.incidence.point) +
           " " + body(k.incidence.body_a) + " = " + body(k.incidence.body_b) + " coordinate " + std::to_string(k.incidence.coordinate);
  case Constraint::BODY_DISTANCE:
    return "distance " + c.label(k.a) + "-" + c.label(k.b) + " of body " + body(k.body);
  case Constraint::SCENE_DISTANCE:
  default:
    return "distance " + c.label(k.a) + "-" + c.label(k.b) +
           (k.distance < c.distances().size() ? " (" + c.distances()[k.distance].name + ")" : std::string());
  }
}

} // namespace Rigid_incidence
} // namespace CGAL

#endif
