// Copyright (c) 2026 Rigid_incidence contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Default model of the RigidIncidenceTraits concept: wraps any CGAL 3D kernel.

#ifndef CGAL_RIGID_INCIDENCE_RIGID_INCIDENCE_TRAITS_H
#define CGAL_RIGID_INCIDENCE_RIGID_INCIDENCE_TRAITS_H

#include <CGAL/Gmpq.h>
#include <CGAL/number_utils.h>
#include <CGAL/Algebraic_structure_traits.h>

#include <type_traits>

namespace CGAL {
namespace Rigid_incidence {

/*!
\ingroup PkgRigidIncidenceRef

\brief Default model of `RigidIncidenceTraits` built on a CGAL kernel.

It asks the kernel for nothing more than the package uses: the field number type,
points and vectors, squared distances, collinearity and coplanarity, and the vector
operations needed to place one body in the frame of another.

\tparam Kernel a model of `Kernel`, e.g. `CGAL::Exact_predicates_inexact_constructions_kernel`,
`CGAL::Exact_predicates_exact_constructions_kernel` or `CGAL::Simple_cartesian<CGAL::Gmpq>`.

\cgalModels `RigidIncidenceTraits`
*/
template <class Kernel>
struct Rigid_incidence_traits
{
  typedef Kernel K;
  typedef typename Kernel::FT FT;
  typedef typename Kernel::Point_3 Point_3;
  typedef typename Kernel::Vector_3 Vector_3;

  /// `true` if `FT` is an exact field: consistency checks then compare exactly.
  static constexpr bool has_exact_ft =
    std::is_same<typename CGAL::Algebraic_structure_traits<FT>::Is_exact, CGAL::Tag_true>::value;

  /// Converts an exact rational read from a scene to `FT` (exactly when `FT` can hold it).
  static FT from_rational(const CGAL::Gmpq& q)
  {
    if constexpr (std::is_constructible<FT, CGAL::Gmpq>::value && has_exact_ft)
      return FT(q);
    else
      return FT(CGAL::to_double(q));
  }

  static Point_3 point(const FT& x, const FT& y, const FT& z) { return Point_3(x, y, z); }
  static FT x(const Point_3& p) { return p.x(); }
  static FT y(const Point_3& p) { return p.y(); }
  static FT z(const Point_3& p) { return p.z(); }
  static FT squared_distance(const Point_3& p, const Point_3& q)
  { return Kernel().compute_squared_distance_3_object()(p, q); }
  static bool equal(const Point_3& p, const Point_3& q) { return Kernel().equal_3_object()(p, q); }
  static bool collinear(const Point_3& p, const Point_3& q, const Point_3& r)
  { return Kernel().collinear_3_object()(p, q, r); }
  static bool coplanar(const Point_3& p, const Point_3& q, const Point_3& r, const Point_3& s)
  { return Kernel().coplanar_3_object()(p, q, r, s); }
  static Vector_3 vector(const Point_3& p, const Point_3& q) { return Kernel().construct_vector_3_object()(p, q); }
  static Vector_3 cross_product(const Vector_3& u, const Vector_3& v)
  { return Kernel().construct_cross_product_vector_3_object()(u, v); }
};

} // namespace Rigid_incidence
} // namespace CGAL

#endif // CGAL_RIGID_INCIDENCE_RIGID_INCIDENCE_TRAITS_H
