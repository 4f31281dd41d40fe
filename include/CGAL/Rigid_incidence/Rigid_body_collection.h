// Copyright (c) 2026 Rigid_incidence contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Rigid bodies (labelled points in local coordinates) and fixed distances between points:
// the input of the package, validated against Definition 1 of the papers.

#ifndef CGAL_RIGID_INCIDENCE_RIGID_BODY_COLLECTION_H
#define CGAL_RIGID_INCIDENCE_RIGID_BODY_COLLECTION_H

#include <CGAL/Rigid_incidence/Input_error.h>
#include <CGAL/Rigid_incidence/Rigid_incidence_traits.h>

#include <algorithm>
#include <cstddef>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Rigid_incidence {

/// \ingroup PkgRigidIncidenceRef
/// Where a body of a collection comes from.
enum class Body_origin
{
  USER,    ///< given by the user, with local coordinates
  MERGED,  ///< union of bodies sharing 3 or more non-collinear points (standardize)
  IMPLIED  ///< a maximal set of points all at fixed distances, not in one body (standardize)
};

/// \ingroup PkgRigidIncidenceRef
/// The name of a body origin: "user", "merged" or "implied".
inline const char* to_string(Body_origin o)
{
  switch (o) { case Body_origin::USER: return "user"; case Body_origin::MERGED: return "merged"; default: return "implied"; }
}

/*!
\ingroup PkgRigidIncidenceRef
\brief A collection of rigid bodies sharing labelled points, plus fixed distances.

Points with the same label in different bodies are one physical point (an incidence).
Every body has at least 2 points. A body given by the user carries exact local coordinates;
a body built by `standardize()` from distances (an implied body) carries the squared
distances between its points instead, from which `enclose_coordinates()` places it.

Validation happens as the collection is built: every member function that adds
something throws `Input_error` naming the body, point or distance at fault, and leaves
the collection unchanged.

\tparam Traits a model of `RigidIncidenceTraits`.
*/
template <class Traits>
class Rigid_body_collection
{
public:
  typedef Traits Traits_type;                 ///< the traits class, a model of `RigidIncidenceTraits`
  typedef typename Traits::FT FT;             ///< the number type of coordinates and squared distances
  typedef typename Traits::Point_3 Point_3;   ///< the point type of local coordinates

  /// A squared distance between two points, given by their indices (into `points` of a body,
  /// or global point indices for the collection's distances).
  struct Squared_distance
  {
    std::size_t a;   ///< index of the first point
    std::size_t b;   ///< index of the second point
    FT squared;      ///< the squared distance
  };

  /// The orientation of four points of a body (local indices): the sign of
  /// det(b - a, c - a, d - a). It keeps the handedness of a user body whose points entered
  /// another body as distances, so that a placement cannot bring it back mirrored.
  struct Orientation
  {
    std::size_t a;      ///< first point
    std::size_t b;      ///< second point
    std::size_t c;      ///< third point
    std::size_t d;      ///< fourth point
    CGAL::Sign sign;    ///< POSITIVE or NEGATIVE
  };

  /// A rigid body of the collection: its points (global indices) and what fixes them.
  struct Body
  {
    std::string name;                       ///< unique name (user's, or made by `standardize()`)
    std::vector<std::size_t> points;        ///< global point indices, sorted
    std::vector<bool> has_coordinates;      ///< per point: exact local coordinates known
    std::vector<Point_3> coordinates;       ///< per point, valid where `has_coordinates`
    std::vector<Squared_distance> squared_distances; ///< local indices; pairs not both with coordinates
    Body_origin origin = Body_origin::USER; ///< where the body comes from
    std::vector<std::string> sources;       ///< user bodies and distances this body stands for
    std::vector<Orientation> orientations;  ///< handedness of points without coordinates (see `Orientation`)
    /// Placements up to rigid motion that `standardize()` can tell exactly: 1 when every point
    /// has coordinates, 2 for an implied body spanning space (mirror images), 1 for a planar
    /// one; 0 when coordinates and distances are combined and the placements must be
    /// enumerated (see `enclose_all_placements()`).
    int mirror_variants = 1;
    /// Rigid parts: bodies of their own (each in its own frame, with its own coordinates,
    /// distances and parts) that hold some of this body's points in place where the distances
    /// between them are not known exactly: `standardize()` keeps a body here when it merges
    /// bodies that share three points whose distances run through placements from distances,
    /// or adds an implied body with such a pair. A placement of this body superposes one
    /// placement of each part on its points (see `enumerate_placements()`). A part may hold
    /// points that are not points of this body; only the shared ones count.
    std::vector<Body> parts;
    /// Sets of points (global indices, sorted) that one body with coordinates holds rigidly
    /// although they entered this body as distances (`standardize()` merging a body it cannot
    /// map into this one's frame). A point of such a set exactly on the line or the plane of
    /// others of the set lies there by that body's shape, not by a coincidence of distances:
    /// its placement is not a double one (see `enumerate_placements()`).
    std::vector<std::vector<std::size_t>> rigid_groups;

    /// Local index of global point `p`, or `npos`.
    std::size_t local(std::size_t p) const
    {
      auto it = std::lower_bound(points.begin(), points.end(), p);
      return (it != points.end() && *it == p) ? std::size_t(it - points.begin()) : npos;
    }
    /// `true` if global point `p` is a point of the body.
    bool contains(std::size_t p) const { return local(p) != npos; }
    /// `true` if every point of the body has exact local coordinates and no part is left to
    /// check (the body is not known by distances only).
    bool all_coordinates() const
    { return parts.empty() && std::all_of(has_coordinates.begin(), has_coordinates.end(), [](bool b) { return b; }); }
    /// The squared distance between the local points `i` and `j`, when the body knows it exactly.
    std::optional<FT> squared(std::size_t i, std::size_t j) const
    {
      if (i == j) return FT(0);
      if (has_coordinates[i] && has_coordinates[j]) return Traits::squared_distance(coordinates[i], coordinates[j]);
      for (const auto& d : squared_distances)
        if ((d.a == i && d.b == j) || (d.a == j && d.b == i)) return d.squared;
      return std::nullopt;
    }
  };

  /// A fixed distance between two points of the collection.
  struct Distance
  {
    std::size_t a;      ///< global index of the first point
    std::size_t b;      ///< global index of the second point
    FT squared;         ///< the squared distance
    std::string name;   ///< for messages, e.g. "distance G1-D2"
  };

  /// Returned for "no such point or body".
  static constexpr std::size_t npos = std::size_t(-1);

  // ---------------------------------------------------------------- points
  /// The number of distinct point labels (physical points).
  std::size_t number_of_points() const { return labels_.size(); }
  /// The label of point `p`.
  const std::string& label(std::size_t p) const { return labels_[p]; }
  /// The index of the point labelled `l`, or `npos`.
  std::size_t point_index(const std::string& l) const
  {
    auto it = index_.find(l);
    return it == index_.end() ? npos : it->second;
  }

  // ---------------------------------------------------------------- bodies
  /// The number of bodies.
  std::size_t number_of_bodies() const { return bodies_.size(); }
  /// Body `i`.
  const Body& body(std::size_t i) const { return bodies_[i]; }
  /// All bodies, in index order.
  const std::vector<Body>& bodies() const { return bodies_; }
  /// The index of the body named `name`, or `npos`.
  std::size_t body_index(const std::string& body_name) const
  {
    for (std::size_t i = 0; i < bodies_.size(); ++i) if (bodies_[i].name == body_name) return i;
    return npos;
  }

  /*!
    Adds a body with local coordinates. Throws `Input_error` if the name is empty or taken,
    if it has fewer than 2 points, a label twice, or two coincident points.
    Returns the body's index.
  */
  std::size_t add_body(const std::string& body_name, const std::vector<std::pair<std::string, Point_3>>& pts)
  {
    const std::string where = "body '" + body_name + "'";
    if (body_name.empty()) throw Input_error("a body has an empty name");
    if (body_index(body_name) != npos) throw Input_error(where + ": duplicate body name");
    if (pts.size() < 2)
      throw Input_error(where + ": a body needs at least 2 points, it has " + std::to_string(pts.size()));
    for (std::size_t i = 0; i < pts.size(); ++i) {
      if (pts[i].first.empty()) throw Input_error(where + ": empty point label");
      for (std::size_t j = 0; j < i; ++j) {
        if (pts[i].first == pts[j].first)
          throw Input_error(where + ": point '" + pts[i].first + "': duplicate label inside the body");
        if (Traits::equal(pts[i].second, pts[j].second))
          throw Input_error(where + ": points '" + pts[j].first + "' and '" + pts[i].first + "' coincide");
      }
    }
    std::vector<std::pair<std::size_t, Point_3>> ids;
    for (const auto& p : pts) ids.emplace_back(intern(p.first), p.second);
    std::sort(ids.begin(), ids.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
    Body b;
    b.name = body_name;
    for (const auto& p : ids) { b.points.push_back(p.first); b.coordinates.push_back(p.second); }
    b.has_coordinates.assign(ids.size(), true);
    b.origin = Body_origin::USER;
    b.sources.push_back(body_name);
    bodies_.push_back(std::move(b));
    return bodies_.size() - 1;
  }

  /*!
    Adds a fixed squared distance between the points labelled `a` and `b`. Throws
    `Input_error` if a label names no point of any body, if the value is not positive, or if
    another distance on the same pair disagrees (an equal one is accepted once).
  */
  void add_distance(const std::string& a, const std::string& b, const FT& squared, const std::string& distance_name = "")
  {
    const std::string where = distance_name.empty() ? "distance '" + a + "'-'" + b + "'" : distance_name;
    std::size_t pa = point_index(a), pb = point_index(b);
    if (pa == npos) throw Input_error(where + ": names unknown point '" + a + "'");
    if (pb == npos) throw Input_error(where + ": names unknown point '" + b + "'");
    if (pa == pb) throw Input_error(where + ": joins a point to itself");
    if (!(squared > FT(0))) throw Input_error(where + ": a distance must be positive");
    for (const Distance& d : distances_)
      if ((d.a == pa && d.b == pb) || (d.a == pb && d.b == pa)) {
        if (same_value(d.squared, squared)) return;
        throw Input_error(where + ": disagrees with " + d.name + " on the same pair of points");
      }
    distances_.push_back(Distance{pa, pb, squared, where});
  }

  /// The fixed distances (those not absorbed into a body).
  const std::vector<Distance>& distances() const { return distances_; }

  /// A label that names a point of the collection under another label (a coincidence: a
  /// distance of 0 in the scene, see `make_collection()`).
  struct Alias
  {
    std::string alias;  ///< the other label
    std::string label;  ///< the label of the point in the collection
    std::string why;    ///< what makes them one point
  };
  /// Declares `alias` another name of point `label`; configurations give it the same place.
  void add_alias(const std::string& alias, const std::string& label, const std::string& why)
  {
    if (point_index(label) == npos) throw Input_error("alias '" + alias + "': names unknown point '" + label + "'");
    if (point_index(alias) != npos) throw Input_error("alias '" + alias + "': is a point of the collection");
    for (const Alias& a : aliases_)
      if (a.alias == alias) throw Input_error("alias '" + alias + "': given twice");
    aliases_.push_back(Alias{alias, label, why});
  }
  /// The aliases, in the order they were declared.
  const std::vector<Alias>& aliases() const { return aliases_; }
  /// Why every configuration of the collection is a multiple root of its scene's equations
  /// although `standardize()` resolved the cause exactly (a point held on a line of a body by
  /// two distances whose spheres touch there); empty: no such cause. `solve_scene()` marks
  /// every configuration `singular` with these reasons, unless the scene's Jacobian there has
  /// full rank (further equations hold the point: see `jacobian_conditioning()`).
  const std::vector<std::string>& singular_notes() const { return singular_notes_; }
  /// Adds a reason to `singular_notes()`.
  void add_singular_note(const std::string& why) { singular_notes_.push_back(why); }
  /// The label of the point `l` names: `l` itself, or the label an alias `l` stands for.
  const std::string& resolve_alias(const std::string& l) const
  {
    for (const Alias& a : aliases_)
      if (a.alias == l) return a.label;
    return l;
  }

  /// Names the body in whose local frame results are reported (default: the first body).
  void set_frame(const std::string& body_name)
  {
    if (body_index(body_name) == npos) throw Input_error("frame: names no body: '" + body_name + "'");
    frame_ = body_name;
  }
  /// The name of the frame body: the one named by `set_frame()`, else the first body.
  std::string frame() const { return frame_.empty() && !bodies_.empty() ? bodies_.front().name : frame_; }
  /// `true` if the frame was named with `set_frame()` (else it is the first body).
  bool frame_is_explicit() const { return !frame_.empty(); }

  std::string name;  ///< the scene's name, for reports

  /// Compares two values exactly when `FT` is exact, else with a relative tolerance
  /// (`consistency_tolerance`, default 1e-9): an inexact kernel rounds scene coordinates.
  bool same_value(const FT& x, const FT& y) const
  {
    if constexpr (Traits::has_exact_ft) return x == y;
    else {
      double a = CGAL::to_double(x), b = CGAL::to_double(y);
      double scale = (std::max)(std::abs(a), std::abs(b)); // relative at every scale
      return std::abs(a - b) <= consistency_tolerance * scale;
    }
  }
  double consistency_tolerance = 1e-9; ///< relative tolerance of `same_value()` for an inexact `FT`

  /// The points shared by two or more bodies (the set X of the papers).
  std::vector<std::size_t> shared_points() const
  {
    std::vector<int> count(labels_.size(), 0);
    for (const Body& b : bodies_) for (std::size_t p : b.points) ++count[p];
    std::vector<std::size_t> x;
    for (std::size_t p = 0; p < count.size(); ++p) if (count[p] >= 2) x.push_back(p);
    return x;
  }

  /// The points in no body: after `standardize()` the far ends of bars, held only by
  /// distances. Each has 3 dof of its own.
  std::vector<std::size_t> free_points() const
  {
    std::vector<bool> in(labels_.size(), false);
    for (const Body& b : bodies_) for (std::size_t p : b.points) in[p] = true;
    std::vector<std::size_t> x;
    for (std::size_t p = 0; p < in.size(); ++p) if (!in[p]) x.push_back(p);
    return x;
  }

  /// The points an incidence tree must cover: the shared points and the points of bodies
  /// that a distance names (a distance is an equation between two points, so their bodies
  /// must be placed by the tree), sorted.
  std::vector<std::size_t> points_to_cover() const
  {
    std::vector<int> count(labels_.size(), 0);
    for (const Body& b : bodies_) for (std::size_t p : b.points) ++count[p];
    std::vector<bool> take(labels_.size(), false);
    for (std::size_t p = 0; p < count.size(); ++p) take[p] = count[p] >= 2;
    for (const Distance& d : distances_) {
      if (count[d.a] > 0) take[d.a] = true;
      if (count[d.b] > 0) take[d.b] = true;
    }
    std::vector<std::size_t> x;
    for (std::size_t p = 0; p < take.size(); ++p) if (take[p]) x.push_back(p);
    return x;
  }

  /// The points common to bodies `i` and `j` (global indices, sorted).
  std::vector<std::size_t> common_points(std::size_t i, std::size_t j) const
  {
    std::vector<std::size_t> c;
    std::set_intersection(bodies_[i].points.begin(), bodies_[i].points.end(),
                          bodies_[j].points.begin(), bodies_[j].points.end(), std::back_inserter(c));
    return c;
  }

  // -------------------------------------------- low-level access used by standardize()
  /// Write access to the bodies, for `standardize()`: it bypasses the checks of `add_body()`.
  std::vector<Body>& mutable_bodies() { return bodies_; }
  /// Write access to the distances, for `standardize()`: it bypasses the checks of `add_distance()`.
  std::vector<Distance>& mutable_distances() { return distances_; }

private:
  std::size_t intern(const std::string& l)
  {
    auto it = index_.find(l);
    if (it != index_.end()) return it->second;
    labels_.push_back(l);
    index_[l] = labels_.size() - 1;
    return labels_.size() - 1;
  }

  std::vector<std::string> labels_;
  std::map<std::string, std::size_t> index_;
  std::vector<Body> bodies_;
  std::vector<Distance> distances_;
  std::vector<Alias> aliases_;
  std::vector<std::string> singular_notes_;
  std::string frame_;
};

} // namespace Rigid_incidence
} // namespace CGAL

#endif
