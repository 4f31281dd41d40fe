// Copyright (c) 2026 Rigid_incidence contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The exception types for malformed scenes and collections, and for scenes with no real
// configuration.

#ifndef CGAL_RIGID_INCIDENCE_INPUT_ERROR_H
#define CGAL_RIGID_INCIDENCE_INPUT_ERROR_H

#include <stdexcept>
#include <string>

namespace CGAL {
namespace Rigid_incidence {

/*!
\ingroup PkgRigidIncidenceRef
\brief Thrown for malformed input: the message names the file, body, point or field at fault.

Every check of the package that rejects input throws this type, so a program can
report the message and exit with status 2, as the command-line tool does.
*/
class Input_error : public std::runtime_error
{
public:
  /// An error with the message `what`.
  explicit Input_error(const std::string& what) : std::runtime_error(what) {}
};

/*!
\ingroup PkgRigidIncidenceRef
\brief Thrown for a well-formed scene that has no real configuration, decided exactly: fixed
distances that violate the triangle inequality, or admit no real tetrahedron or placement.
The message names the points and distances.

It derives from `Input_error` so that a program that only knows that type still stops; the
command-line tool catches it first and answers "0 configurations, complete" (exit status 0).
*/
class No_real_configuration : public Input_error
{
public:
  /// The scene has no real configuration, and `what` says why.
  explicit No_real_configuration(const std::string& what) : Input_error(what) {}
};

} // namespace Rigid_incidence
} // namespace CGAL

#endif
