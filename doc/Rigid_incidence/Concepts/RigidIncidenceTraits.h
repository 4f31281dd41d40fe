// Copyright (c) 2026 Rigid_incidence contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Documentation of the RigidIncidenceTraits concept (not compiled).

/*!
\ingroup PkgRigidIncidenceConcepts
\cgalConcept
\headerfile RigidIncidenceTraits.h <CGAL/Rigid_incidence/Rigid_incidence_traits.h>

\brief The number type, the geometric objects and the few constructions and predicates
that the package needs from a kernel.

Every class and function of the package that handles coordinates is a template on a model
of this concept (the parameter `Traits`, for example `Rigid_body_collection<Traits>`).
All members are static: the package never constructs a traits object. A concept has no
header of its own; the include line above names the header of the default model.

<b>Exactness.</b> With an exact field `FT` (`has_exact_ft == true`), every check of the
package is exact: coincident points, collinearity, agreement of shared distances, the
Cayley-Menger tests of `standardize()`, the rational map that merges two bodies. With an
inexact `FT` (doubles), the numbers of a scene are rounded to the nearest `FT` when it is
read, values that should agree are compared with a relative tolerance
(`Rigid_body_collection::consistency_tolerance`, default \f$10^{-9}\f$), and a Cayley-Menger
determinant counts as zero within \f$10^{-9}\f$ of its scale (the largest squared distance
to the power of its degree).

<b>Further requirements on the types.</b> Besides the functions below, the package uses:
- `FT`: a model of CGAL's `FieldNumberType`, constructible from `int`, for which
  `CGAL::sign()`, `CGAL::to_double()` and `CGAL::to_interval()` are defined
  (`CGAL::Algebraic_structure_traits<FT>::Is_exact` gives `has_exact_ft`);
- `Point_3`: default constructible, copyable, constructible from three `int` (the origin
  is used as a placeholder).

The points of any CGAL 3D kernel fulfill them.

\cgalHasModels `CGAL::Rigid_incidence::Rigid_incidence_traits<Kernel>`, for every CGAL 3D kernel `Kernel`
(the package is tested with `CGAL::Simple_cartesian<CGAL::Gmpq>`, `CGAL::Exact_predicates_exact_constructions_kernel`
and `CGAL::Exact_predicates_inexact_constructions_kernel`).
*/
class RigidIncidenceTraits
{
public:
  /// \name Types
  /// @{

  /// The field number type of coordinates and squared distances.
  typedef unspecified_type FT;

  /// A point in 3D space (local coordinates of a point of a body).
  typedef unspecified_type Point_3;

  /// @}

  /// \name Constants
  /// @{

  /// \brief `true` if `FT` is an exact field.
  ///
  /// The package then compares values exactly; else it compares them with a relative tolerance.
  static const bool has_exact_ft;

  /// @}

  /// \name Conversion and Constructions
  /// @{

  /// \brief Converts an exact rational, as read from a scene file, to `FT`.
  ///
  /// The conversion is exact when `FT` is an exact field; else it gives the nearest value
  /// of `FT`. Returns `false`, leaving `out` unchanged, when `FT` cannot represent `q` well
  /// enough for the package's computations (the default model: an inexact `FT` accepts 0
  /// and \f$10^{-50} \le |q| \le 10^{50}\f$).
  static bool from_rational(const CGAL::Gmpq& q, FT& out);

  /// As above, but throws `CGAL::Rigid_incidence::Input_error`, its message starting with
  /// `where`, when `q` cannot be represented.
  static FT from_rational(const CGAL::Gmpq& q, const std::string& where);

  /// The point with coordinates `(x, y, z)`.
  static Point_3 point(const FT& x, const FT& y, const FT& z);

  /// The x coordinate of `p`.
  static FT x(const Point_3& p);

  /// The y coordinate of `p`.
  static FT y(const Point_3& p);

  /// The z coordinate of `p`.
  static FT z(const Point_3& p);

  /// The squared Euclidean distance of `p` and `q`.
  static FT squared_distance(const Point_3& p, const Point_3& q);

  /// @}

  /// \name Predicates
  /// @{

  /// `true` if `p` and `q` are the same point.
  static bool equal(const Point_3& p, const Point_3& q);

  /// `true` if `p`, `q` and `r` lie on a common line.
  static bool collinear(const Point_3& p, const Point_3& q, const Point_3& r);

  /// @}
};
