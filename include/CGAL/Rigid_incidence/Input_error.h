// Copyright (c) 2026 Rigid_incidence contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The one exception type for malformed scenes and collections.

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

} // namespace Rigid_incidence
} // namespace CGAL

#endif
