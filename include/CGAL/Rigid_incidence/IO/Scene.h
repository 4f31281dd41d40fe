// Copyright (c) 2026 Rigid_incidence contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// A scene as the user wrote it, with every number kept as an exact rational.

#ifndef CGAL_RIGID_INCIDENCE_IO_SCENE_H
#define CGAL_RIGID_INCIDENCE_IO_SCENE_H

#include <CGAL/Gmpq.h>
#include <string>
#include <vector>

namespace CGAL {
namespace Rigid_incidence {

/*!
\ingroup PkgRigidIncidenceIO
\brief A scene exactly as read from a file of format "rigid-incidence-scene/1".

Every coordinate and distance is an exact rational (`CGAL::Gmpq`); a kernel is chosen
only when the scene is turned into a `Rigid_body_collection` by `make_collection()`.
*/
struct Scene
{
  /// A labelled point with its local coordinates.
  struct Point
  {
    std::string label;  ///< the point's label
    CGAL::Gmpq x;       ///< x coordinate
    CGAL::Gmpq y;       ///< y coordinate
    CGAL::Gmpq z;       ///< z coordinate
  };
  /// A body: its name and its points, in the order of the file.
  struct Body
  {
    std::string name;           ///< the body's name
    std::vector<Point> points;  ///< its points
  };
  /// A fixed distance between two labelled points.
  struct Distance
  {
    std::string a;             ///< the first point label
    std::string b;             ///< the second point label
    CGAL::Gmpq squared;        ///< the squared distance (exact)
    bool given_as_length = false; ///< the file gave "length" rather than "squared"
    CGAL::Gmpq length;         ///< the length, when the file gave "length"
  };
  /// An inequality constraint: the orientation of four labelled points, det(B - A, C - A,
  /// D - A) >= 0 (D on the side of the plane through A, B, C that (B - A) x (C - A) points to;
  /// `negative`: <= 0, the other side).
  struct Inequality
  {
    std::vector<std::string> points;  ///< the labels A, B, C, D
    bool negative = false;            ///< the file gave "sign": "negative"
  };
  /// A distance declared free ("free_distance"): the scene moves with it, and
  /// `solve_family()` solves it as curves over the distance's range.
  struct Free_distance
  {
    bool declared = false;     ///< the file declares a free distance
    std::string a;             ///< the first point label
    std::string b;             ///< the second point label
    bool has_range = false;    ///< the file gave "range" (else a bound from the scene is used)
    CGAL::Gmpq lo;             ///< the smallest length of the range
    CGAL::Gmpq hi;             ///< the largest length of the range
    bool had_length = false;   ///< the pair is also in "distances" (that length is not imposed)
    CGAL::Gmpq nominal_squared;///< the squared length given there
  };
  std::string source;          ///< file name (or "<stream>") used in error messages
  std::string name;            ///< the scene's name (may be empty)
  std::vector<Body> bodies;    ///< the bodies, in the order of the file
  std::vector<Distance> distances; ///< the distances, in the order of the file
  std::vector<Inequality> inequalities; ///< the inequality constraints, in the order of the file
  std::string frame;           ///< empty: the first body
  /// The free distance, if declared. It is not in `distances`: a scene with a free distance
  /// is solved without it (a curve of configurations), or as a family by `solve_family()`.
  Free_distance free_distance;
};

} // namespace Rigid_incidence
} // namespace CGAL

#endif
