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
  struct Point { std::string label; CGAL::Gmpq x, y, z; };
  struct Body { std::string name; std::vector<Point> points; };
  struct Distance
  {
    std::string a, b;          ///< the two point labels
    CGAL::Gmpq squared;        ///< the squared distance (exact)
    bool given_as_length = false;
    CGAL::Gmpq length;         ///< the length, when the file gave "length"
  };
  std::string source;          ///< file name (or "<stream>") used in error messages
  std::string name;
  std::vector<Body> bodies;
  std::vector<Distance> distances;
  std::string frame;           ///< empty: the first body
};

} // namespace Rigid_incidence
} // namespace CGAL

#endif
