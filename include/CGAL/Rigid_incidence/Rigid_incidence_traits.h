// Copyright (c) 2026 Rigid_incidence contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Default model of the RigidIncidenceTraits concept: wraps any CGAL 3D kernel.

#ifndef CGAL_RIGID_INCIDENCE_RIGID_INCIDENCE_TRAITS_H
#define CGAL_RIGID_INCIDENCE_RIGID_INCIDENCE_TRAITS_H

#include <CGAL/Gmpq.h>
#include <CGAL/Gmpz.h>
#include <CGAL/Rigid_incidence/Input_error.h>
#include <CGAL/number_utils.h>
#include <CGAL/Algebraic_structure_traits.h>

#include <cmath>
#include <sstream>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Rigid_incidence {

namespace internal {
// FT is a lazy exact number whose exact type ET can be made from a GMP rational (Epeck's FT:
// Lazy_exact_nt of Boost.Multiprecision's gmp_rational)
template <class FT, class = void>
struct Exact_from_mpq : std::false_type {};
template <class FT>
struct Exact_from_mpq<FT, std::void_t<typename FT::ET>>
    : std::integral_constant<bool, std::is_constructible<typename FT::ET, mpq_srcptr>::value &&
                                       std::is_constructible<FT, typename FT::ET>::value> {};
} // namespace internal

/*!
\ingroup PkgRigidIncidenceRef

\brief Default model of `RigidIncidenceTraits` built on a CGAL kernel.

It asks the kernel for nothing more than the package uses: the field number type,
points, their coordinates, squared distances, equality and collinearity, and the
operations needed to place one body in the frame of another.

\tparam Kernel a model of `Kernel`, e.g. `CGAL::Exact_predicates_inexact_constructions_kernel`,
`CGAL::Exact_predicates_exact_constructions_kernel` or `CGAL::Simple_cartesian<CGAL::Gmpq>`.

\cgalModels `RigidIncidenceTraits`
*/
template <class Kernel>
struct Rigid_incidence_traits
{
  typedef Kernel K;                            ///< the kernel
  typedef typename Kernel::FT FT;              ///< the kernel's field number type
  typedef typename Kernel::Point_3 Point_3;    ///< the kernel's 3D point

  /// `true` if `FT` is an exact field: consistency checks then compare exactly.
  static constexpr bool has_exact_ft =
    std::is_same<typename CGAL::Algebraic_structure_traits<FT>::Is_exact, CGAL::Tag_true>::value;

  /// Magnitude limit of `from_rational()` for an inexact `FT`: squared distances and the
  /// Cayley-Menger determinants of standardize() (degree 6 in coordinates) must stay finite.
  static constexpr double inexact_range = 1e50;

  /// Converts an exact rational read from a scene to `FT`: exactly when `FT` is an exact
  /// field, else to the nearest double. Returns false (and leaves `out` unchanged) when an
  /// inexact `FT` cannot represent it: |q| > `inexact_range`, or 0 < |q| < 1/`inexact_range`.
  static bool from_rational(const CGAL::Gmpq& q, FT& out)
  {
    if constexpr (std::is_constructible<FT, CGAL::Gmpq>::value && has_exact_ft) {
      out = FT(q);
      return true;
    } else if constexpr (has_exact_ft && internal::Exact_from_mpq<FT>::value) {
      // a lazy exact number (Epeck's FT) from its exact type, e.g. Boost.Multiprecision's
      // GMP rational: exactly, never through a double
      out = FT(typename FT::ET(q.mpq()));
      return true;
    } else if constexpr (has_exact_ft) {
      // any other exact field: numerator and denominator built from 30-bit digits
      out = from_integer(q.numerator()) / from_integer(q.denominator());
      return true;
    } else {
      if (q == 0) { out = FT(0); return true; }
      CGAL::Gmpq a = q < 0 ? CGAL::Gmpq(-q) : q;
      if (a > CGAL::Gmpq(inexact_range) || a < CGAL::Gmpq(1) / CGAL::Gmpq(inexact_range)) return false;
      // to_interval rounds outward; of its two ends take the nearer (mpq_get_d would truncate)
      std::pair<double, double> i = CGAL::to_interval(q);
      double d = i.first;
      if (i.first != i.second && CGAL::Gmpq(i.second) - q < q - CGAL::Gmpq(i.first)) d = i.second;
      out = FT(d);
      return true;
    }
  }

  /// The integer `z` in `FT`, exactly when `FT` is exact (Horner's rule on 30-bit digits).
  static FT from_integer(const CGAL::Gmpz& z)
  {
    const bool negative = z < 0;
    CGAL::Gmpz a = negative ? CGAL::Gmpz(-z) : z;
    std::vector<long> digits;
    while (a != 0) {
      CGAL::Gmpz r;
      mpz_fdiv_r_2exp(r.mpz(), a.mpz(), 30);
      digits.push_back(mpz_get_si(r.mpz()));
      mpz_fdiv_q_2exp(a.mpz(), a.mpz(), 30);
    }
    FT out(0);
    for (std::size_t i = digits.size(); i-- > 0;) out = out * FT(1 << 30) + FT(int(digits[i]));
    return negative ? -out : out;
  }

  /// As above, throwing `Input_error` (with `where` in the message) when `q` is out of range.
  static FT from_rational(const CGAL::Gmpq& q, const std::string& where = "a number")
  {
    FT out;
    if (!from_rational(q, out))
    {
      double d = CGAL::to_double(q);
      std::ostringstream os;
      os.precision(6);
      if (d == 0) os << "a nonzero number below 1e-308 in magnitude";
      else if (std::isfinite(d)) os << d;
      else os << (q < 0 ? "-" : "") << "a number beyond 1e308";
      throw Input_error(where + ": " + os.str() +
                        " is outside the range this kernel's double coordinates handle (1e-50 <= |x| <= 1e50, or 0);"
                        " use an exact kernel");
    }
    return out;
  }

  /// The point (x, y, z).
  static Point_3 point(const FT& x, const FT& y, const FT& z) { return Point_3(x, y, z); }
  /// The x coordinate of `p`.
  static FT x(const Point_3& p) { return p.x(); }
  /// The y coordinate of `p`.
  static FT y(const Point_3& p) { return p.y(); }
  /// The z coordinate of `p`.
  static FT z(const Point_3& p) { return p.z(); }
  /// The squared distance of `p` and `q`.
  static FT squared_distance(const Point_3& p, const Point_3& q)
  { return Kernel().compute_squared_distance_3_object()(p, q); }
  /// `true` if `p` and `q` are the same point.
  static bool equal(const Point_3& p, const Point_3& q) { return Kernel().equal_3_object()(p, q); }
  /// `true` if `p`, `q` and `r` lie on a line.
  static bool collinear(const Point_3& p, const Point_3& q, const Point_3& r)
  { return Kernel().collinear_3_object()(p, q, r); }
};

} // namespace Rigid_incidence
} // namespace CGAL

#endif // CGAL_RIGID_INCIDENCE_RIGID_INCIDENCE_TRAITS_H
