// Copyright (c) 2026 Rigid_incidence contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Local coordinates of bodies known by distances (implied bodies, merges with them), as
// certified interval enclosures: the square roots a placement from distances needs are
// enclosed, never rounded silently.

#ifndef CGAL_RIGID_INCIDENCE_ENCLOSE_COORDINATES_H
#define CGAL_RIGID_INCIDENCE_ENCLOSE_COORDINATES_H

#include <CGAL/Rigid_incidence/Input_error.h>
#include <CGAL/Rigid_incidence/Rigid_body_collection.h>
#include <CGAL/Rigid_incidence/internal/cayley_menger.h>
#include <CGAL/Rigid_incidence/internal/parse_number.h>

#include <CGAL/Gmpq.h>
#include <CGAL/Interval_nt.h>
#include <CGAL/Interval_traits.h>

#include <array>
#include <optional>
#include <sstream>
#include <string>
#include <type_traits>
#include <vector>

namespace CGAL {
namespace Rigid_incidence {

/// \ingroup PkgRigidIncidenceRef
/// Interval enclosures of the local coordinates of one body, as `enclose_coordinates()` returns them.
template <class IT>
struct Body_enclosure
{
  std::vector<std::array<IT, 3>> coordinates; ///< per point of the body (its `points` order)
  bool consistent = true; ///< every distance the body knows lies in the enclosure of its placement
  int variant = 0;        ///< which mirror image (0 or 1) was placed
};

namespace internal {

template <class IT> IT dot(const std::array<IT, 3>& a, const std::array<IT, 3>& b)
{ return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
template <class IT> std::array<IT, 3> sub(const std::array<IT, 3>& a, const std::array<IT, 3>& b)
{ return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
template <class IT> std::array<IT, 3> cross(const std::array<IT, 3>& a, const std::array<IT, 3>& b)
{ return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]}; }

template <class T> struct is_interval_nt : std::false_type {};
template <bool P> struct is_interval_nt<CGAL::Interval_nt<P>> : std::true_type {};

// The exact rational value of a kernel number (double, Gmpq, or a lazy exact number).
template <class FT> CGAL::Gmpq exact_rational(const FT& x)
{
  if constexpr (std::is_same<FT, double>::value || std::is_same<FT, float>::value) return CGAL::Gmpq(double(x));
  else if constexpr (std::is_same<FT, CGAL::Gmpq>::value) return x;
  else {
    // a lazy exact number: print its exact value as p/q and read it back exactly
    std::ostringstream os;
    os << x.exact();
    CGAL::Gmpq q;
    std::string why;
    if (!parse_exact_number(os.str(), q, why)) throw Input_error("cannot convert " + os.str() + " to a rational: " + why);
    return q;
  }
}

// Do two intervals meet?
template <class IT> bool overlap(const IT& a, const IT& b)
{
  typedef CGAL::Interval_traits<IT> IT_traits;
  typename IT_traits::Lower lower;
  typename IT_traits::Upper upper;
  return !(upper(a) < lower(b) || upper(b) < lower(a));
}

// An enclosure of x: a double interval around it, or (for multi-precision interval types)
// the rational value rounded outward at the type's default precision.
template <class IT, class FT> IT enclose(const FT& x)
{
  if constexpr (is_interval_nt<IT>::value) return IT(CGAL::to_interval(x));
  else return IT(exact_rational(x));
}

// Switches the FPU to rounding upward for double intervals while it lives; MPFI rounds by itself.
template <class IT, bool = is_interval_nt<IT>::value> struct Rounding_guard { typename IT::Protector p; };
template <class IT> struct Rounding_guard<IT, false> {};

// Nonnegative part of an enclosure of a square (round-off can make its lower end negative).
template <class IT> IT nonnegative(const IT& x)
{
  typedef CGAL::Interval_traits<IT> IT_traits;
  typename IT_traits::Lower lower;
  typename IT_traits::Upper upper;
  if (upper(x) < 0) return IT(0);
  if (lower(x) < 0) return typename IT_traits::Construct()(typename IT_traits::Bound(0), upper(x));
  return x;
}

} // namespace internal

/*!
\ingroup PkgRigidIncidenceRef
\brief Encloses the local coordinates of body `body` of `c` in intervals of type `IT`.

Points with exact coordinates are enclosed as given. A body known only by distances is
placed from them: its first point at the origin, the second on the x axis, the third in the
xy plane (y > 0), each further point by trilateration from three placed non-collinear points,
its side of their plane chosen by `variant` (0: positive, 1: the mirror image) for the first
point that has two sides and by a known distance to a fourth point for the others.
Each square root and division is evaluated in interval arithmetic with outward rounding,
so the enclosures contain the exact coordinates of the placement.

\tparam IT `CGAL::Interval_nt<false>` (double intervals), or `CGAL::Gmpfi` (MPFI: the exact
input values are rounded outward at `Gmpfi`'s default precision, which a caller raises with
`CGAL::Gmpfi::set_default_precision()` to make the enclosures as tight as asked).
\throws Input_error if the body's known distances do not suffice to place a point.
*/
template <class IT, class Traits>
Body_enclosure<IT> enclose_coordinates(const Rigid_body_collection<Traits>& c, std::size_t body, int variant = 0)
{
  typedef std::array<IT, 3> P;
  typedef typename Traits::FT FT;
  const auto& b = c.body(body);
  const std::size_t m = b.points.size();
  internal::Rounding_guard<IT> protect;
  Body_enclosure<IT> out;
  out.variant = variant;
  out.coordinates.assign(m, P{IT(0), IT(0), IT(0)});
  std::vector<bool> placed(m, false);
  auto sq = [&](std::size_t i, std::size_t j) { return b.squared(i, j); };
  for (std::size_t i = 0; i < m; ++i)
    if (b.has_coordinates[i]) {
      out.coordinates[i] = P{internal::enclose<IT>(Traits::x(b.coordinates[i])), internal::enclose<IT>(Traits::y(b.coordinates[i])),
                             internal::enclose<IT>(Traits::z(b.coordinates[i]))};
      placed[i] = true;
    }
  std::size_t n_placed = std::count(placed.begin(), placed.end(), true);
  if (n_placed == 0) {
    // base triangle from distances
    std::optional<std::array<std::size_t, 3>> base;
    for (std::size_t i = 0; i < m && !base; ++i) for (std::size_t j = i + 1; j < m && !base; ++j)
      for (std::size_t k = j + 1; k < m && !base; ++k) {
        auto a = sq(i, j), bb = sq(i, k), cc = sq(j, k);
        if (a && bb && cc && CGAL::sign(internal::triangle_16_area_squared(*a, *bb, *cc)) == CGAL::POSITIVE)
          base = std::array<std::size_t, 3>{i, j, k};
      }
    if (!base) throw Input_error("body '" + b.name + "': its distances contain no proper triangle to place it from");
    auto [i, j, k] = *base;
    IT d01 = internal::enclose<IT>(*sq(i, j)), d02 = internal::enclose<IT>(*sq(i, k)), d12 = internal::enclose<IT>(*sq(j, k));
    IT l = CGAL::sqrt(d01);
    IT x = (d01 + d02 - d12) / (IT(2) * l);
    IT y = CGAL::sqrt(internal::nonnegative(d02 - x * x));
    out.coordinates[i] = P{IT(0), IT(0), IT(0)};
    out.coordinates[j] = P{l, IT(0), IT(0)};
    out.coordinates[k] = P{x, y, IT(0)};
    placed[i] = placed[j] = placed[k] = true;
  }
  bool progress = true;
  while (progress) {
    progress = false;
    for (std::size_t p = 0; p < m; ++p) {
      if (placed[p]) continue;
      // three placed points, non-collinear, at known distances from p
      std::vector<std::size_t> refs;
      for (std::size_t q = 0; q < m; ++q) if (placed[q] && sq(p, q)) refs.push_back(q);
      std::optional<std::array<std::size_t, 3>> tri;
      for (std::size_t a = 0; a < refs.size() && !tri; ++a) for (std::size_t bb = a + 1; bb < refs.size() && !tri; ++bb)
        for (std::size_t cc = bb + 1; cc < refs.size() && !tri; ++cc) {
          auto x = sq(refs[a], refs[bb]), y = sq(refs[a], refs[cc]), z = sq(refs[bb], refs[cc]);
          if (x && y && z && CGAL::sign(internal::triangle_16_area_squared(*x, *y, *z)) == CGAL::POSITIVE)
            tri = std::array<std::size_t, 3>{refs[a], refs[bb], refs[cc]};
        }
      if (!tri) continue;
      const P& P1 = out.coordinates[(*tri)[0]];
      P u = internal::sub(out.coordinates[(*tri)[1]], P1), v = internal::sub(out.coordinates[(*tri)[2]], P1);
      P n = internal::cross(u, v);
      IT r1 = internal::enclose<IT>(*sq(p, (*tri)[0])), r2 = internal::enclose<IT>(*sq(p, (*tri)[1])),
         r3 = internal::enclose<IT>(*sq(p, (*tri)[2]));
      IT uu = internal::dot(u, u), vv = internal::dot(v, v), uv = internal::dot(u, v), nn = internal::dot(n, n);
      IT alpha = (r1 - r2 + uu) / IT(2), beta = (r1 - r3 + vv) / IT(2);
      // (X - P1) = a u + b v + t n with a uu + b uv = alpha, a uv + b vv = beta (det = nn)
      IT a = (alpha * vv - beta * uv) / nn, bcoef = (beta * uu - alpha * uv) / nn;
      P w{a * u[0] + bcoef * v[0], a * u[1] + bcoef * v[1], a * u[2] + bcoef * v[2]};
      IT t = CGAL::sqrt(internal::nonnegative((r1 - internal::dot(w, w)) / nn));
      P plus{P1[0] + w[0] + t * n[0], P1[1] + w[1] + t * n[1], P1[2] + w[2] + t * n[2]};
      P minus{P1[0] + w[0] - t * n[0], P1[1] + w[1] - t * n[1], P1[2] + w[2] - t * n[2]};
      // choose the side: by a fourth point at known distance if one tells, else by `variant`
      int side = 0; // +1 plus, -1 minus
      for (std::size_t q : refs) {
        if (q == (*tri)[0] || q == (*tri)[1] || q == (*tri)[2]) continue;
        IT known = internal::enclose<IT>(*sq(p, q));
        P dp = internal::sub(plus, out.coordinates[q]), dm = internal::sub(minus, out.coordinates[q]);
        bool fits_plus = internal::overlap(internal::dot(dp, dp), known);
        bool fits_minus = internal::overlap(internal::dot(dm, dm), known);
        if (fits_plus != fits_minus) { side = fits_plus ? 1 : -1; break; }
      }
      if (side == 0) side = (variant == 0) ? 1 : -1;
      out.coordinates[p] = side > 0 ? plus : minus;
      placed[p] = true;
      progress = true;
    }
  }
  for (std::size_t p = 0; p < m; ++p)
    if (!placed[p]) throw Input_error("body '" + b.name + "': point '" + c.label(b.points[p]) +
                                      "' has too few known distances to be placed");
  for (const auto& d : b.squared_distances) {
    P diff = internal::sub(out.coordinates[d.a], out.coordinates[d.b]);
    if (!internal::overlap(internal::dot(diff, diff), internal::enclose<IT>(FT(d.squared)))) out.consistent = false;
  }
  return out;
}

} // namespace Rigid_incidence
} // namespace CGAL

#endif
