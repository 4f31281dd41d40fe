// Copyright (c) 2026 Rigid_incidence contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Cayley-Menger determinants from squared distances: exact realizability and degeneracy
// tests for bodies known only by their distances.

#ifndef CGAL_RIGID_INCIDENCE_INTERNAL_CAYLEY_MENGER_H
#define CGAL_RIGID_INCIDENCE_INTERNAL_CAYLEY_MENGER_H

#include <CGAL/number_utils.h>
#include <CGAL/enum.h>

#include <algorithm>
#include <cmath>
#include <initializer_list>

namespace CGAL {
namespace Rigid_incidence {
namespace internal {

// 16 * area^2 of a triangle with squared side lengths a, b, c (Heron's formula):
// positive for a proper triangle, zero for collinear points, negative if unrealizable.
template <class FT>
FT triangle_16_area_squared(const FT& a, const FT& b, const FT& c)
{
  return FT(2) * (a * b + b * c + c * a) - a * a - b * b - c * c;
}

// 288 * volume^2 of a tetrahedron p0 p1 p2 p3 from its squared edge lengths
// dij = |pi - pj|^2: the Cayley-Menger determinant, positive for a proper tetrahedron,
// zero for coplanar points, negative if unrealizable.
template <class FT>
FT tetrahedron_288_volume_squared(const FT& d01, const FT& d02, const FT& d03,
                                  const FT& d12, const FT& d13, const FT& d23)
{
  // With u = p1-p0, v = p2-p0, w = p3-p0 the Gram entries are u.v = (d01 + d02 - d12) / 2 etc.,
  // and 36 V^2 = det(Gram), so 288 V^2 = 8 det(Gram).
  FT uu = d01, vv = d02, ww = d03;
  FT uv = (d01 + d02 - d12) / FT(2), uw = (d01 + d03 - d13) / FT(2), vw = (d02 + d03 - d23) / FT(2);
  FT det = uu * (vv * ww - vw * vw) - uv * (uv * ww - vw * uw) + uw * (uv * vw - vv * uw);
  return FT(8) * det;
}

// Signs of the two determinants above. Exact for an exact FT; for an inexact FT (doubles)
// a value within a relative 1e-9 of the scale (the largest squared distance to the power of
// the degree) counts as zero, since rounded coordinates of collinear or coplanar points give
// a small value of either sign.
template <class FT, bool exact>
CGAL::Sign degeneracy_sign(const FT& value, std::initializer_list<FT> squared, int degree)
{
  if constexpr (exact) return CGAL::sign(value);
  else {
    double scale = 0;
    for (const FT& d : squared) scale = (std::max)(scale, std::abs(CGAL::to_double(d)));
    double v = CGAL::to_double(value);
    if (std::abs(v) <= 1e-9 * std::pow(scale, degree)) return CGAL::ZERO;
    return v > 0 ? CGAL::POSITIVE : CGAL::NEGATIVE;
  }
}

template <bool exact, class FT>
CGAL::Sign triangle_sign(const FT& a, const FT& b, const FT& c)
{ return degeneracy_sign<FT, exact>(triangle_16_area_squared(a, b, c), {a, b, c}, 2); }

template <bool exact, class FT>
CGAL::Sign tetrahedron_sign(const FT& d01, const FT& d02, const FT& d03, const FT& d12, const FT& d13, const FT& d23)
{
  return degeneracy_sign<FT, exact>(tetrahedron_288_volume_squared(d01, d02, d03, d12, d13, d23),
                                    {d01, d02, d03, d12, d13, d23}, 3);
}

} // namespace internal
} // namespace Rigid_incidence
} // namespace CGAL

#endif
