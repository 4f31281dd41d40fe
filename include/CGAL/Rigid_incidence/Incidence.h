// Copyright (c) 2026 Rigid_incidence contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Incidences (v, {c_j, c_l}, p) of equation (2) of well_formed_optimal_incidences.txt:
// coordinate p of the shared point v agrees in the bodies c_j and c_l.

#ifndef CGAL_RIGID_INCIDENCE_INCIDENCE_H
#define CGAL_RIGID_INCIDENCE_INCIDENCE_H

#include <algorithm>
#include <cstddef>
#include <initializer_list>
#include <tuple>
#include <utility>
#include <vector>

namespace CGAL {
namespace Rigid_incidence {

/*!
\ingroup PkgRigidIncidenceRef
\brief One scalar incidence (v, {a, b}, p): coordinate p (1, 2 or 3) of point v is the same
in body a and in body b (equation (2) of well_formed_optimal_incidences.txt).

Bodies and points are indices into a `Rigid_body_collection`; the pair of bodies is kept
ordered (a < b), so that equal incidences compare equal.
*/
struct Incidence
{
  std::size_t point = 0;   ///< the shared point v (global point index)
  std::size_t body_a = 0;  ///< the smaller body index of the pair
  std::size_t body_b = 0;  ///< the larger body index of the pair
  int coordinate = 1;      ///< p: 1, 2 or 3

  Incidence() = default;
  /// The incidence (v, {a, b}, p); the bodies may be given in either order.
  Incidence(std::size_t v, std::size_t a, std::size_t b, int p)
    : point(v), body_a((std::min)(a, b)), body_b((std::max)(a, b)), coordinate(p) {}

  /// Lexicographic order on (point, body_a, body_b, coordinate).
  friend bool operator<(const Incidence& x, const Incidence& y)
  { return std::tie(x.point, x.body_a, x.body_b, x.coordinate) < std::tie(y.point, y.body_a, y.body_b, y.coordinate); }
  /// Equality of all four fields.
  friend bool operator==(const Incidence& x, const Incidence& y)
  { return std::tie(x.point, x.body_a, x.body_b, x.coordinate) == std::tie(y.point, y.body_a, y.body_b, y.coordinate); }
  /// Inequality.
  friend bool operator!=(const Incidence& x, const Incidence& y) { return !(x == y); }
};

/*!
\ingroup PkgRigidIncidenceRef
\brief A set of incidences, kept sorted and without duplicates.
*/
class Incidence_set
{
public:
  typedef std::vector<Incidence>::const_iterator const_iterator; ///< iterates in sorted order

  /// The empty set.
  Incidence_set() = default;
  /// The set of the given incidences (duplicates are kept once).
  explicit Incidence_set(std::vector<Incidence> v) : items_(std::move(v))
  {
    std::sort(items_.begin(), items_.end());
    items_.erase(std::unique(items_.begin(), items_.end()), items_.end());
  }

  /// Adds `i`; returns false if it was already there.
  bool insert(const Incidence& i)
  {
    auto it = std::lower_bound(items_.begin(), items_.end(), i);
    if (it != items_.end() && *it == i) return false;
    items_.insert(it, i);
    return true;
  }
  /// Adds the incidences (v, {a, b}, p) for each p in `coordinates`.
  void insert(std::size_t v, std::size_t a, std::size_t b, std::initializer_list<int> coordinates)
  {
    for (int p : coordinates) insert(Incidence(v, a, b, p));
  }
  /// `true` if `i` is in the set.
  bool contains(const Incidence& i) const { return std::binary_search(items_.begin(), items_.end(), i); }
  std::size_t size() const { return items_.size(); }        ///< number of incidences
  bool empty() const { return items_.empty(); }              ///< `true` if there is none
  const_iterator begin() const { return items_.begin(); }    ///< first incidence
  const_iterator end() const { return items_.end(); }        ///< past the last incidence
  const std::vector<Incidence>& items() const { return items_; } ///< the incidences, sorted

private:
  std::vector<Incidence> items_;
};

} // namespace Rigid_incidence
} // namespace CGAL

#endif
