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
  /// every distance the body knows lies in the enclosure of its placement (false: the body
  /// admits no placement, and `coordinates` is empty)
  bool consistent = true;
  int variant = 0;        ///< which placement this is (see `enclose_all_placements()`)
  bool in_given_frame = true; ///< in the frame of the body's coordinates (else a canonical frame)
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

namespace internal {

template <class IT, class Traits>
class Placer
{
  typedef std::array<IT, 3> P;
  typedef typename Traits::FT FT;
  typedef Rigid_body_collection<Traits> Collection;
  typedef typename Collection::Body Body;

public:
  Placer(const Collection& c, const Body& b, std::size_t max_placements)
    : c_(c), b_(b), m_(b.points.size()), max_(max_placements) {}

  // All placements: start from the points with coordinates if they alone let every point be
  // placed, else (or if there are none) from a triangle of distances in a canonical frame, in
  // which case the coordinates given for some points enter as distances and orientations.
  std::vector<Body_enclosure<IT>> run()
  {
    Rounding_guard<IT> protect;
    // table of known squared distances (local indices); coordinates give them too
    known_.assign(m_, std::vector<std::optional<FT>>(m_));
    for (std::size_t i = 0; i < m_; ++i)
      for (std::size_t j = i + 1; j < m_; ++j) known_[i][j] = known_[j][i] = b_.squared(i, j);
    std::vector<P> coords(m_, P{IT(0), IT(0), IT(0)});
    std::vector<bool> placed(m_, false);
    std::size_t given = 0;
    for (std::size_t i = 0; i < m_; ++i)
      if (b_.has_coordinates[i]) {
        coords[i] = P{enclose<IT>(Traits::x(b_.coordinates[i])), enclose<IT>(Traits::y(b_.coordinates[i])),
                      enclose<IT>(Traits::z(b_.coordinates[i]))};
        placed[i] = true;
        ++given;
      }
    for (const auto& o : b_.orientations) { orient_idx_.push_back({o.a, o.b, o.c, o.d}); orient_sign_.push_back(o.sign); }
    in_given_frame_ = given >= 3 && reachable(placed);
    if (!in_given_frame_) {
      // canonical frame; the given coordinates keep their handedness through an orientation
      extra_orientations();
      std::fill(placed.begin(), placed.end(), false);
      std::optional<std::array<std::size_t, 3>> base;
      for (std::size_t i = 0; i < m_ && !base; ++i) for (std::size_t j = i + 1; j < m_ && !base; ++j)
        for (std::size_t k = j + 1; k < m_ && !base; ++k)
          if (known_[i][j] && known_[i][k] && known_[j][k] &&
              triangle_sign<Traits::has_exact_ft>(*known_[i][j], *known_[i][k], *known_[j][k]) == CGAL::POSITIVE) {
            std::vector<bool> trial(m_, false);
            trial[i] = trial[j] = trial[k] = true;
            if (reachable(trial)) base = std::array<std::size_t, 3>{i, j, k};
          }
      if (!base)
        throw Input_error("body '" + b_.name + "': its points cannot be placed one after the other from three placed"
                          " points at known distances (a placement this version does not support)");
      auto [i, j, k] = *base;
      IT d01 = enclose<IT>(*known_[i][j]), d02 = enclose<IT>(*known_[i][k]), d12 = enclose<IT>(*known_[j][k]);
      IT l = CGAL::sqrt(d01);
      IT x = (d01 + d02 - d12) / (IT(2) * l);
      IT y = CGAL::sqrt(nonnegative(d02 - x * x));
      coords[i] = P{IT(0), IT(0), IT(0)};
      coords[j] = P{l, IT(0), IT(0)};
      coords[k] = P{x, y, IT(0)};
      placed[i] = placed[j] = placed[k] = true;
    }
    place(coords, placed);
    return out_;
  }

private:
  const Collection& c_;
  const Body& b_;
  std::size_t m_, max_;
  std::vector<std::vector<std::optional<FT>>> known_;
  std::vector<std::array<std::size_t, 4>> orient_idx_;
  std::vector<CGAL::Sign> orient_sign_;
  bool in_given_frame_ = false;
  std::vector<Body_enclosure<IT>> out_;

  // Can every point be placed by repeated trilateration from the `placed` ones?
  bool reachable(std::vector<bool> placed) const
  {
    bool progress = true;
    while (progress) {
      progress = false;
      for (std::size_t p = 0; p < m_; ++p)
        if (!placed[p] && reference_triangle(p, placed)) { placed[p] = true; progress = true; }
    }
    return std::all_of(placed.begin(), placed.end(), [](bool x) { return x; });
  }

  std::optional<std::array<std::size_t, 3>> reference_triangle(std::size_t p, const std::vector<bool>& placed) const
  {
    std::vector<std::size_t> refs;
    for (std::size_t q = 0; q < m_; ++q) if (placed[q] && known_[p][q]) refs.push_back(q);
    for (std::size_t a = 0; a < refs.size(); ++a) for (std::size_t b = a + 1; b < refs.size(); ++b)
      for (std::size_t c = b + 1; c < refs.size(); ++c) {
        const auto& x = known_[refs[a]][refs[b]]; const auto& y = known_[refs[a]][refs[c]]; const auto& z = known_[refs[b]][refs[c]];
        if (x && y && z && triangle_sign<Traits::has_exact_ft>(*x, *y, *z) == CGAL::POSITIVE)
          return std::array<std::size_t, 3>{refs[a], refs[b], refs[c]};
      }
    return std::nullopt;
  }

  // In a canonical frame the coordinates given for four points spanning space fix their handedness.
  void extra_orientations()
  {
    std::vector<std::size_t> idx;
    for (std::size_t k = 0; k < m_; ++k) if (b_.has_coordinates[k]) idx.push_back(k);
    for (std::size_t a = 0; a < idx.size(); ++a) for (std::size_t bb = a + 1; bb < idx.size(); ++bb)
      for (std::size_t cc = bb + 1; cc < idx.size(); ++cc) for (std::size_t dd = cc + 1; dd < idx.size(); ++dd) {
        const auto& A = b_.coordinates[idx[a]]; const auto& B = b_.coordinates[idx[bb]];
        const auto& C = b_.coordinates[idx[cc]]; const auto& D = b_.coordinates[idx[dd]];
        FT u[3] = {Traits::x(B) - Traits::x(A), Traits::y(B) - Traits::y(A), Traits::z(B) - Traits::z(A)};
        FT v[3] = {Traits::x(C) - Traits::x(A), Traits::y(C) - Traits::y(A), Traits::z(C) - Traits::z(A)};
        FT w[3] = {Traits::x(D) - Traits::x(A), Traits::y(D) - Traits::y(A), Traits::z(D) - Traits::z(A)};
        CGAL::Sign s = CGAL::sign(u[0] * (v[1] * w[2] - v[2] * w[1]) - u[1] * (v[0] * w[2] - v[2] * w[0]) +
                                  u[2] * (v[0] * w[1] - v[1] * w[0]));
        if (s != CGAL::ZERO) { orient_idx_.push_back({idx[a], idx[bb], idx[cc], idx[dd]}); orient_sign_.push_back(s); return; }
      }
  }

  // Does the placement certainly violate an orientation whose four points are placed?
  bool violates_orientation(const std::vector<P>& x, const std::vector<bool>& placed) const
  {
    for (std::size_t k = 0; k < orient_idx_.size(); ++k) {
      const auto& o = orient_idx_[k];
      if (!(placed[o[0]] && placed[o[1]] && placed[o[2]] && placed[o[3]])) continue;
      IT det = dot(cross(sub(x[o[1]], x[o[0]]), sub(x[o[2]], x[o[0]])), sub(x[o[3]], x[o[0]]));
      typename CGAL::Interval_traits<IT>::Lower lower;
      typename CGAL::Interval_traits<IT>::Upper upper;
      if (orient_sign_[k] == CGAL::POSITIVE && upper(det) < 0) return true;
      if (orient_sign_[k] == CGAL::NEGATIVE && lower(det) > 0) return true;
    }
    return false;
  }

  // Is every known distance between placed points (one of them p) contained in its enclosure?
  bool fits(std::size_t p, const P& xp, const std::vector<P>& x, const std::vector<bool>& placed) const
  {
    for (std::size_t q = 0; q < m_; ++q)
      if (placed[q] && q != p && known_[p][q]) {
        P d = sub(xp, x[q]);
        if (!internal::overlap(dot(d, d), enclose<IT>(*known_[p][q]))) return false;
      }
    return true;
  }

  // Depth first over the sides of each trilaterated point: a side is kept when it fits every
  // known distance and orientation so far; both are kept when both fit.
  void place(std::vector<P> x, std::vector<bool> placed)
  {
    if (out_.size() >= max_) return;
    std::size_t next = m_;
    std::optional<std::array<std::size_t, 3>> tri;
    for (std::size_t p = 0; p < m_ && next == m_; ++p)
      if (!placed[p]) { tri = reference_triangle(p, placed); if (tri) next = p; }
    if (next == m_) {
      Body_enclosure<IT> e;
      e.coordinates = x;
      e.variant = int(out_.size());
      e.in_given_frame = in_given_frame_;
      e.consistent = true;
      out_.push_back(e);
      return;
    }
    const std::size_t p = next;
    const P& P1 = x[(*tri)[0]];
    P u = sub(x[(*tri)[1]], P1), v = sub(x[(*tri)[2]], P1);
    P n = cross(u, v);
    IT r1 = enclose<IT>(*known_[p][(*tri)[0]]), r2 = enclose<IT>(*known_[p][(*tri)[1]]), r3 = enclose<IT>(*known_[p][(*tri)[2]]);
    IT uu = dot(u, u), vv = dot(v, v), uv = dot(u, v), nn = dot(n, n);
    IT alpha = (r1 - r2 + uu) / IT(2), beta = (r1 - r3 + vv) / IT(2);
    // X - P1 = a u + b v + t n with a uu + b uv = alpha, a uv + b vv = beta (determinant nn)
    IT a = (alpha * vv - beta * uv) / nn, bcoef = (beta * uu - alpha * uv) / nn;
    P w{a * u[0] + bcoef * v[0], a * u[1] + bcoef * v[1], a * u[2] + bcoef * v[2]};
    IT t = CGAL::sqrt(nonnegative((r1 - dot(w, w)) / nn));
    typename CGAL::Interval_traits<IT>::Lower lower;
    bool on_plane = !(lower(t) > 0); // t may be 0: one side only
    for (int side : {1, -1}) {
      if (side < 0 && on_plane) break;
      P xp{P1[0] + w[0] + IT(side) * t * n[0], P1[1] + w[1] + IT(side) * t * n[1], P1[2] + w[2] + IT(side) * t * n[2]};
      if (!fits(p, xp, x, placed)) continue;
      std::vector<P> x2 = x;
      std::vector<bool> placed2 = placed;
      x2[p] = xp;
      placed2[p] = true;
      if (violates_orientation(x2, placed2)) continue;
      place(x2, placed2);
    }
  }
};

} // namespace internal

/*!
\ingroup PkgRigidIncidenceRef
\brief Encloses every placement of body `body` of `c` (up to rigid motion) in intervals of type `IT`.

Points with coordinates are enclosed as given, in the body's frame, when every other point
can be placed from them; otherwise the body is placed in a canonical frame from its
distances: a first point at the origin, a second on the x axis, a third in the xy plane
(y > 0), and the given coordinates enter as distances and an orientation (so that a user
body never comes back mirrored). Each further point is trilaterated from three placed
non-collinear points at known distances; both sides of their plane are followed whenever both
fit every known distance and orientation so far, so the placements returned are all those
the body's distances allow (a spatial clique of distances gives its two mirror images; two
bodies on a hinge closed by a distance give the hinge's two angles). Square roots and
divisions are evaluated with outward rounding, so each enclosure contains the exact
coordinates of its placement; where intervals cannot tell two sides apart (a point nearly
on the plane of its references) both are returned, never neither.

\tparam IT `CGAL::Interval_nt<false>` (double intervals), or `CGAL::Gmpfi` (MPFI: the exact
input values are rounded outward at `Gmpfi`'s default precision, which a caller raises with
`CGAL::Gmpfi::set_default_precision()` to make the enclosures as tight as asked).
\param c the collection (typically the output of `standardize()`)
\param body the index of the body in `c`
\param max_placements stop after this many placements
\throws Input_error if the body's distances do not let its points be placed one after the other.
*/
template <class IT, class Traits>
std::vector<Body_enclosure<IT>> enclose_all_placements(const Rigid_body_collection<Traits>& c, std::size_t body,
                                                       std::size_t max_placements = 64)
{
  internal::Placer<IT, Traits> placer(c, c.body(body), max_placements);
  return placer.run();
}

/*!
\ingroup PkgRigidIncidenceRef
\brief The placement number `variant` of `enclose_all_placements()` (0: the first).

For a body whose points all have coordinates, there is one placement: its coordinates.
For a spatial clique of distances, variants 0 and 1 are mirror images.
\param c the collection
\param body the index of the body in `c`
\param variant which placement, from 0
\throws Input_error if the body has fewer placements, with the number it has; a body whose
distances admit no placement gives an enclosure with `consistent == false`.
*/
template <class IT, class Traits>
Body_enclosure<IT> enclose_coordinates(const Rigid_body_collection<Traits>& c, std::size_t body, int variant = 0)
{
  std::vector<Body_enclosure<IT>> all = enclose_all_placements<IT>(c, body, std::size_t(variant) + 1);
  if (variant < 0 || std::size_t(variant) >= all.size()) {
    // the body's distances admit no placement (or fewer): report it as inconsistent
    if (all.empty()) {
      Body_enclosure<IT> e;
      e.consistent = false;
      e.variant = variant;
      return e;
    }
    throw Input_error("body '" + c.body(body).name + "' has " + std::to_string(all.size()) + " placement(s), not a number " +
                      std::to_string(variant + 1));
  }
  return all[std::size_t(variant)];
}

} // namespace Rigid_incidence
} // namespace CGAL

#endif
