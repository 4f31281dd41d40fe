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
#include <CGAL/Rigid_incidence/internal/interval_ops.h>
#include <CGAL/Rigid_incidence/internal/parse_number.h>

#include <CGAL/Gmpq.h>
#include <CGAL/Interval_nt.h>
#include <CGAL/Interval_traits.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <deque>
#include <limits>
#include <memory>
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
  /// a double placement: a point lies exactly on the plane of the three points it is placed
  /// from, so its two sides coincide (see `Placement_enumeration::singular`)
  bool singular = false;
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
  else if constexpr (std::is_convertible<typename std::decay<decltype(x.exact())>::type, CGAL::Gmpq>::value)
    return CGAL::Gmpq(x.exact());  // a lazy exact number over Gmpq (Epeck)
  else {
    // another exact number type: print its exact value as p/q and read it back exactly
    std::ostringstream os;
    os << x.exact();
    CGAL::Gmpq q;
    std::string why;
    if (!parse_exact_number(os.str(), q, why, 0)) throw Input_error("cannot convert " + os.str() + " to a rational: " + why);
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

} // namespace internal

namespace internal {

// One trilateration of a body's placement, in exact rationals: point p is
//   X_p = X_A + a (X_B - X_A) + b (X_C - X_A) + side sqrt(s) (X_B - X_A) x (X_C - X_A),
// where a, b and s come from the six squared distances among p, A, B, C alone (s = h^2 / G,
// h the height of p over the plane ABC, G = |(B - A) x (C - A)|^2 the Gram determinant).
// So the side choices and the rounding of earlier points never enter them, and whether p
// has two sides, one (h = 0: a double placement) or none is decided exactly.
struct Placement_step
{
  std::size_t p = 0, A = 0, B = 0, C = 0;
  CGAL::Gmpq a, b, s;
  CGAL::Sign sign = CGAL::POSITIVE;  // of s
};

// What a body's distances say about its placements, exactly, before a side is chosen.
struct Placement_plan
{
  std::size_t m = 0;
  std::vector<std::string> labels;
  std::vector<std::vector<std::optional<CGAL::Gmpq>>> known;   // squared distances, local indices
  std::vector<std::optional<std::array<CGAL::Gmpq, 3>>> given; // coordinates the body gives
  bool in_given_frame = false;
  std::array<std::size_t, 3> base{{0, 0, 0}};  // canonical frame: base[0] at 0, base[1] on +x, base[2] in xy, y > 0
  CGAL::Gmpq d01, c1, y2;                      // |base0 base1|^2; base2 = (c1 sqrt(d01), sqrt(y2), 0)
  std::vector<Placement_step> steps;           // in placement order
  std::vector<std::array<std::size_t, 4>> orient_idx;
  std::vector<CGAL::Sign> orient_sign;
  std::string inconsistent;  // nonempty: the distances admit no placement, and why
  std::string singular;      // nonempty: every placement is a double one, and where
  double scale = 1;          // the body's size: its largest distance or coordinate
};

template <class Traits>
class Placement_planner
{
  typedef Rigid_body_collection<Traits> Collection;
  typedef typename Collection::Body Body;
  typedef CGAL::Gmpq Q;

public:
  Placement_planner(const Collection& c, const Body& b) : c_(c), b_(b) {}

  Placement_plan run()
  {
    Placement_plan& P = plan_;
    const std::size_t m = b_.points.size();
    P.m = m;
    for (std::size_t i = 0; i < m; ++i) P.labels.push_back(c_.label(b_.points[i]));
    P.known.assign(m, std::vector<std::optional<Q>>(m));
    P.given.assign(m, std::nullopt);
    double scale2 = 0, scale1 = 0;
    for (std::size_t i = 0; i < m; ++i)
      for (std::size_t j = i + 1; j < m; ++j)
        if (auto d = b_.squared(i, j)) {
          P.known[i][j] = P.known[j][i] = exact_rational(*d);
          scale2 = (std::max)(scale2, CGAL::to_double(*P.known[i][j]));
        }
    std::vector<bool> placed(m, false);
    std::size_t given = 0;
    for (std::size_t i = 0; i < m; ++i)
      if (b_.has_coordinates[i]) {
        const auto& x = b_.coordinates[i];
        P.given[i] = std::array<Q, 3>{exact_rational(Traits::x(x)), exact_rational(Traits::y(x)), exact_rational(Traits::z(x))};
        for (const Q& v : *P.given[i]) scale1 = (std::max)(scale1, std::abs(CGAL::to_double(v)));
        placed[i] = true;
        ++given;
      }
    P.scale = (std::max)(std::sqrt(scale2), scale1);
    if (!(P.scale > 0) || !std::isfinite(P.scale)) P.scale = 1;
    for (const auto& o : b_.orientations) { P.orient_idx.push_back({o.a, o.b, o.c, o.d}); P.orient_sign.push_back(o.sign); }
    P.in_given_frame = given >= 3 && reachable(placed);
    if (!P.in_given_frame) {
      // canonical frame; the given coordinates keep their handedness through an orientation
      extra_orientations();
      std::fill(placed.begin(), placed.end(), false);
      std::optional<std::array<std::size_t, 3>> base;
      for (std::size_t i = 0; i < m && !base; ++i) for (std::size_t j = i + 1; j < m && !base; ++j)
        for (std::size_t k = j + 1; k < m && !base; ++k)
          if (proper_triangle(i, j, k)) {
            std::vector<bool> trial(m, false);
            trial[i] = trial[j] = trial[k] = true;
            if (reachable(trial)) base = std::array<std::size_t, 3>{i, j, k};
          }
      if (!base)
        throw Input_error("body '" + b_.name + "': its points cannot be placed one after the other from three placed"
                          " points at known distances (a placement this version does not support)");
      P.base = *base;
      const auto [i, j, k] = *base;
      P.d01 = *P.known[i][j];
      P.c1 = (P.d01 + *P.known[i][k] - *P.known[j][k]) / (Q(2) * P.d01);
      P.y2 = *P.known[i][k] - P.c1 * P.c1 * P.d01;  // > 0: a proper triangle
      placed[i] = placed[j] = placed[k] = true;
    }
    // the order: the first point (by index) with a reference triangle, again and again
    while (true) {
      std::size_t next = m;
      std::optional<std::array<std::size_t, 3>> tri;
      for (std::size_t p = 0; p < m && next == m; ++p)
        if (!placed[p]) { tri = reference_triangle(p, placed); if (tri) next = p; }
      if (next == m) break;
      P.steps.push_back(step(next, *tri));
      placed[next] = true;
    }
    if (singular_points_ > 1) P.singular += "; so are " + std::to_string(singular_points_ - 1) + " more of its points";
    return P;
  }

private:
  const Collection& c_;
  const Body& b_;
  Placement_plan plan_;
  std::size_t singular_points_ = 0;

  bool proper_triangle(std::size_t i, std::size_t j, std::size_t k) const
  {
    const auto& K = plan_.known;
    return K[i][j] && K[i][k] && K[j][k] && triangle_sign<Traits::has_exact_ft>(*K[i][j], *K[i][k], *K[j][k]) == CGAL::POSITIVE;
  }

  // Can every point be placed by repeated trilateration from the `placed` ones?
  bool reachable(std::vector<bool> placed) const
  {
    bool progress = true;
    while (progress) {
      progress = false;
      for (std::size_t p = 0; p < plan_.m; ++p)
        if (!placed[p] && reference_triangle(p, placed)) { placed[p] = true; progress = true; }
    }
    return std::all_of(placed.begin(), placed.end(), [](bool x) { return x; });
  }

  std::optional<std::array<std::size_t, 3>> reference_triangle(std::size_t p, const std::vector<bool>& placed) const
  {
    std::vector<std::size_t> refs;
    for (std::size_t q = 0; q < plan_.m; ++q) if (placed[q] && plan_.known[p][q]) refs.push_back(q);
    for (std::size_t a = 0; a < refs.size(); ++a) for (std::size_t b = a + 1; b < refs.size(); ++b)
      for (std::size_t c = b + 1; c < refs.size(); ++c)
        if (proper_triangle(refs[a], refs[b], refs[c])) return std::array<std::size_t, 3>{refs[a], refs[b], refs[c]};
    return std::nullopt;
  }

  // In a canonical frame the coordinates given for four points spanning space fix their handedness.
  void extra_orientations()
  {
    std::vector<std::size_t> idx;
    for (std::size_t k = 0; k < plan_.m; ++k) if (plan_.given[k]) idx.push_back(k);
    for (std::size_t a = 0; a < idx.size(); ++a) for (std::size_t bb = a + 1; bb < idx.size(); ++bb)
      for (std::size_t cc = bb + 1; cc < idx.size(); ++cc) for (std::size_t dd = cc + 1; dd < idx.size(); ++dd) {
        const auto &A = *plan_.given[idx[a]], &B = *plan_.given[idx[bb]], &C = *plan_.given[idx[cc]], &D = *plan_.given[idx[dd]];
        Q u[3], v[3], w[3];
        for (int k = 0; k < 3; ++k) { u[k] = B[k] - A[k]; v[k] = C[k] - A[k]; w[k] = D[k] - A[k]; }
        CGAL::Sign s = CGAL::sign(u[0] * (v[1] * w[2] - v[2] * w[1]) - u[1] * (v[0] * w[2] - v[2] * w[0]) +
                                  u[2] * (v[0] * w[1] - v[1] * w[0]));
        if (s != CGAL::ZERO) {
          plan_.orient_idx.push_back({idx[a], idx[bb], idx[cc], idx[dd]});
          plan_.orient_sign.push_back(s);
          return;
        }
      }
  }

  Placement_step step(std::size_t p, const std::array<std::size_t, 3>& t)
  {
    const auto& K = plan_.known;
    Placement_step s;
    s.p = p; s.A = t[0]; s.B = t[1]; s.C = t[2];
    const Q uu = *K[s.A][s.B], vv = *K[s.A][s.C], uv = (uu + vv - *K[s.B][s.C]) / Q(2);
    const Q G = uu * vv - uv * uv;  // > 0: a proper triangle
    const Q r1 = *K[p][s.A], r2 = *K[p][s.B], r3 = *K[p][s.C];
    const Q alpha = (r1 - r2 + uu) / Q(2), beta = (r1 - r3 + vv) / Q(2);
    s.a = (alpha * vv - beta * uv) / G;
    s.b = (beta * uu - alpha * uv) / G;
    const Q h2 = r1 - (s.a * s.a * uu + Q(2) * s.a * s.b * uv + s.b * s.b * vv);
    s.s = h2 / G;
    if constexpr (Traits::has_exact_ft) s.sign = CGAL::sign(h2);
    else { // rounded input: a height within 1e-9 of the references' scale is zero, as in standardize
      double scale = (std::max)({CGAL::to_double(r1), CGAL::to_double(uu), CGAL::to_double(vv)});
      double v = CGAL::to_double(h2);
      s.sign = std::abs(v) <= 1e-9 * scale ? CGAL::ZERO : (v > 0 ? CGAL::POSITIVE : CGAL::NEGATIVE);
      if (s.sign == CGAL::ZERO) s.s = 0;
    }
    const std::string who = "'" + plan_.labels[p] + "' over the plane of '" + plan_.labels[s.A] + "', '" + plan_.labels[s.B] +
                            "' and '" + plan_.labels[s.C] + "'";
    if (s.sign == CGAL::NEGATIVE && plan_.inconsistent.empty())
      plan_.inconsistent = "body '" + b_.name + "': the squared distances of " + who + " (" + to_text(r1) + ", " + to_text(r2) + ", " +
                           to_text(r3) + ") admit no real point (its squared height over that plane would be " + to_text(h2) + ")";
    if (s.sign == CGAL::ZERO && singular_points_++ == 0)
      plan_.singular = "body '" + b_.name + "': the height of " + who + " is exactly 0 (a double placement: its two sides coincide)";
    return s;
  }

  static std::string to_text(const Q& q)
  {
    std::ostringstream os;
    os << CGAL::to_double(q);
    return os.str();
  }
};

// The placements of a plan in the interval type W (the caller sets W's rounding or precision).
template <class W>
class Placement_enumerator
{
  typedef std::array<W, 3> P;

public:
  Placement_enumerator(const Placement_plan& plan, std::size_t max_placements) : plan_(plan), max_(max_placements) {}

  std::vector<Body_enclosure<W>> run()
  {
    const Placement_plan& Pl = plan_;
    for (const auto& s : Pl.steps) {
      a_.push_back(from_rational(s.a));
      b_.push_back(from_rational(s.b));
      t_.push_back(s.sign == CGAL::POSITIVE ? W(CGAL::sqrt(from_rational(s.s))) : W(0));
    }
    // per step: the distances to check (placed points other than the references) and the
    // orientations whose last point it places
    std::vector<bool> placed(Pl.m, false);
    x_.assign(Pl.m, P{W(0), W(0), W(0)});
    if (Pl.in_given_frame) {
      for (std::size_t i = 0; i < Pl.m; ++i)
        if (Pl.given[i]) {
          for (int k = 0; k < 3; ++k) x_[i][std::size_t(k)] = from_rational((*Pl.given[i])[std::size_t(k)]);
          placed[i] = true;
        }
    } else {
      const W l = CGAL::sqrt(from_rational(Pl.d01));
      x_[Pl.base[1]] = P{l, W(0), W(0)};
      x_[Pl.base[2]] = P{from_rational(Pl.c1) * l, W(CGAL::sqrt(from_rational(Pl.y2))), W(0)};
      for (std::size_t i : Pl.base) placed[i] = true;
    }
    for (std::size_t o = 0; o < Pl.orient_idx.size(); ++o)
      if (all_placed(Pl.orient_idx[o], placed)) initial_orientations_.push_back(o);
    for (const auto& s : Pl.steps) {
      std::vector<std::size_t> checks;
      for (std::size_t q = 0; q < Pl.m; ++q)
        if (placed[q] && q != s.A && q != s.B && q != s.C && Pl.known[s.p][q]) checks.push_back(q);
      checks_.push_back(checks);
      placed[s.p] = true;
      std::vector<std::size_t> orient;
      for (std::size_t o = 0; o < Pl.orient_idx.size(); ++o) {
        const auto& q = Pl.orient_idx[o];
        if (std::find(q.begin(), q.end(), s.p) != q.end() && all_placed(q, placed)) orient.push_back(o);
      }
      orientations_.push_back(orient);
    }
    for (std::size_t o : initial_orientations_) if (violates(o)) return out_;
    place(0);
    return out_;
  }

  bool truncated() const { return truncated_; }

private:
  const Placement_plan& plan_;
  std::size_t max_;
  bool truncated_ = false;
  std::vector<W> a_, b_, t_;
  std::vector<std::vector<std::size_t>> checks_, orientations_;
  std::vector<std::size_t> initial_orientations_;
  std::vector<P> x_;
  std::vector<Body_enclosure<W>> out_;

  static W from_rational(const CGAL::Gmpq& q)
  {
    if constexpr (is_interval_nt<W>::value) return W(CGAL::to_interval(q));
    else return W(q);
  }
  static bool all_placed(const std::array<std::size_t, 4>& q, const std::vector<bool>& placed)
  { return placed[q[0]] && placed[q[1]] && placed[q[2]] && placed[q[3]]; }

  // Does the placement so far certainly violate orientation o?
  bool violates(std::size_t o) const
  {
    const auto& q = plan_.orient_idx[o];
    W det = dot(cross(sub(x_[q[1]], x_[q[0]]), sub(x_[q[2]], x_[q[0]])), sub(x_[q[3]], x_[q[0]]));
    typename CGAL::Interval_traits<W>::Lower lower;
    typename CGAL::Interval_traits<W>::Upper upper;
    if (plan_.orient_sign[o] == CGAL::POSITIVE && upper(det) < 0) return true;
    if (plan_.orient_sign[o] == CGAL::NEGATIVE && lower(det) > 0) return true;
    return false;
  }

  // Depth first over the sides of each step: a side is kept unless a known distance or an
  // orientation certainly excludes it; a step with s = 0 has one side.
  void place(std::size_t k)
  {
    if (truncated_) return;
    const auto& steps = plan_.steps;
    if (k == steps.size()) {
      if (out_.size() >= max_) { truncated_ = true; return; }
      Body_enclosure<W> e;
      e.coordinates = x_;
      e.variant = int(out_.size());
      e.in_given_frame = plan_.in_given_frame;
      e.consistent = true;
      e.singular = !plan_.singular.empty();
      out_.push_back(std::move(e));
      return;
    }
    const Placement_step& s = steps[k];
    const P& A = x_[s.A];
    const P u = sub(x_[s.B], A), v = sub(x_[s.C], A), n = cross(u, v);
    P w;
    for (std::size_t i = 0; i < 3; ++i) w[i] = A[i] + a_[k] * u[i] + b_[k] * v[i];
    for (int side : {1, -1}) {
      if (side < 0 && s.sign != CGAL::POSITIVE) break;
      P xp;
      for (std::size_t i = 0; i < 3; ++i) xp[i] = side > 0 ? w[i] + t_[k] * n[i] : w[i] - t_[k] * n[i];
      bool fits = true;
      for (std::size_t q : checks_[k]) {
        P d = sub(xp, x_[q]);
        if (!internal::overlap(dot(d, d), from_rational(*plan_.known[s.p][q]))) { fits = false; break; }
      }
      if (!fits) continue;
      x_[s.p] = xp;
      bool ok = true;
      for (std::size_t o : orientations_[k]) if (violates(o)) { ok = false; break; }
      if (ok) place(k + 1);
    }
  }
};

// The widest coordinate enclosure of a list of placements, in units of `scale`.
template <class W>
double relative_width(const std::vector<Body_enclosure<W>>& all, double scale)
{
  double w = 0;
  for (const auto& e : all)
    for (const auto& x : e.coordinates)
      for (const W& v : x) {
        std::pair<double, double> i = CGAL::to_interval(v);
        double d = i.second - i.first;
        if (!(d <= std::numeric_limits<double>::max())) return std::numeric_limits<double>::infinity();
        w = (std::max)(w, d / scale);
      }
  return w;
}

template <class IT, class W>
std::vector<Body_enclosure<IT>> convert_enclosures(std::vector<Body_enclosure<W>>&& all)
{
  if constexpr (std::is_same<IT, W>::value) return std::move(all);
  else {
    std::vector<Body_enclosure<IT>> out;
    for (const auto& e : all) {
      Body_enclosure<IT> f;
      f.consistent = e.consistent;
      f.variant = e.variant;
      f.in_given_frame = e.in_given_frame;
      f.singular = e.singular;
      for (const auto& x : e.coordinates) {
        std::array<IT, 3> y;
        // Gmpfi to double intervals rounds outward; double intervals into Gmpfi are exact
        for (std::size_t k = 0; k < 3; ++k) y[k] = IT(CGAL::to_interval(x[k]));
        f.coordinates.push_back(y);
      }
      out.push_back(std::move(f));
    }
    return out;
  }
}

// A text that determines a body's placements: its labels, exact coordinates, distances and
// orientations (the key of the placement cache).
template <class Traits>
std::string placement_key(const Rigid_body_collection<Traits>& c, const typename Rigid_body_collection<Traits>::Body& b)
{
  std::ostringstream os;
  auto field = [&os](const std::string& t) { os << t.size() << ':' << t << ';'; };  // length-prefixed: no two keys alike
  field(b.name);
  for (std::size_t i = 0; i < b.points.size(); ++i) {
    field(c.label(b.points[i]));
    if (b.has_coordinates[i])
      os << '(' << exact_rational(Traits::x(b.coordinates[i])) << ' ' << exact_rational(Traits::y(b.coordinates[i])) << ' '
         << exact_rational(Traits::z(b.coordinates[i])) << ')';
    os << '\n';
  }
  for (const auto& d : b.squared_distances) os << d.a << '-' << d.b << ' ' << exact_rational(d.squared) << '\n';
  for (const auto& o : b.orientations) os << o.a << ' ' << o.b << ' ' << o.c << ' ' << o.d << ' ' << int(o.sign) << '\n';
  return os.str();
}

} // namespace internal

/// \ingroup PkgRigidIncidenceRef
/// Every placement of one body, as `enumerate_placements()` returns them, with how they were enclosed.
template <class IT>
struct Placement_enumeration
{
  std::vector<Body_enclosure<IT>> placements; ///< variants 0, 1, ...
  /// false: the enumeration stopped at `max_placements` and more placements exist
  bool complete = true;
  /// bits of the interval arithmetic the enclosures were computed in (53: double intervals);
  /// raised automatically until the enclosures are narrow enough (see `enumerate_placements()`)
  unsigned precision = 53;
  /// the widest coordinate enclosure, relative to the body's size
  double relative_width = 0;
  /// nonempty: the body's distances admit no real placement (decided exactly), and why
  std::string inconsistent;
  /// nonempty: every placement is a double one (a point exactly on the plane of its three
  /// references, decided exactly), and where
  std::string singular;
};

/// \ingroup PkgRigidIncidenceRef
/// The default limit on the placements of one body (2^14): a body with more is enumerated
/// up to it and reported incomplete.
constexpr std::size_t default_maximal_placements = std::size_t(1) << 14;

/// \ingroup PkgRigidIncidenceRef
/// The highest precision, in bits, the placement enumeration raises its arithmetic to.
constexpr unsigned maximal_placement_precision = 4096;

namespace internal {

// The enumeration of enumerate_placements(), shared with the per-thread cache.
template <class IT, class Traits>
std::shared_ptr<const Placement_enumeration<IT>> cached_placements(const Rigid_body_collection<Traits>& c, std::size_t body,
                                                                  std::size_t max_placements)
{
  const auto& b = c.body(body);
  std::string key = placement_key(c, b) + std::to_string(max_placements);
  unsigned start = 53;
#ifdef CGAL_USE_MPFI
  if constexpr (!is_interval_nt<IT>::value) {
    start = unsigned(CGAL::Gmpfi::get_default_precision());
    key += " " + std::to_string(start);
  }
#endif
  thread_local std::deque<std::pair<std::string, std::shared_ptr<const Placement_enumeration<IT>>>> cache;
  for (const auto& e : cache) if (e.first == key) return e.second;

  Placement_plan plan = Placement_planner<Traits>(c, b).run();
  auto out = std::make_shared<Placement_enumeration<IT>>();
  out->inconsistent = plan.inconsistent;
  out->singular = plan.singular;
  if (plan.inconsistent.empty()) {
    const double target = is_interval_nt<IT>::value ? std::ldexp(1.0, -44) : std::ldexp(1.0, 12 - int(start));
    bool done = false;
    if constexpr (is_interval_nt<IT>::value) {
      typename CGAL::Interval_nt<false>::Protector protect;
      Placement_enumerator<CGAL::Interval_nt<false>> e(plan, max_placements);
      auto all = e.run();
      out->relative_width = relative_width(all, plan.scale);
      out->complete = !e.truncated();
      out->precision = 53;
      out->placements = convert_enclosures<IT>(std::move(all));
      done = out->relative_width <= target;
    }
#ifdef CGAL_USE_MPFI
    for (unsigned bits = is_interval_nt<IT>::value ? 128 : start; !done; bits *= 2) {
      Solver_precision_guard<CGAL::Gmpfi> guard(bits);
      Placement_enumerator<CGAL::Gmpfi> e(plan, max_placements);
      auto all = e.run();
      out->relative_width = relative_width(all, plan.scale);
      out->complete = !e.truncated();
      out->precision = bits;
      out->placements = convert_enclosures<IT>(std::move(all));
      done = out->relative_width <= target || 2 * bits > (std::max)(maximal_placement_precision, 4 * start);
    }
#endif
    (void)done;
    // every side of some point certainly excluded by a further distance or an orientation:
    // no real placement either (interval exclusion is rigorous)
    if (out->complete && out->placements.empty())
      out->inconsistent = "body '" + b.name + "': no placement fits all its distances and orientations (each side of a"
                          " trilaterated point is excluded by a further distance or an orientation, in intervals at " +
                          std::to_string(out->precision) + " bits)";
  }
  cache.emplace_back(key, out);
  if (cache.size() > 32) cache.pop_front();
  return out;
}

} // namespace internal

/*!
\ingroup PkgRigidIncidenceRef
\brief Encloses every placement of body `body` of `c` (up to rigid motion) in intervals of
type `IT`, raising the precision of the arithmetic until the enclosures are narrow.

Points with coordinates are enclosed as given, in the body's frame, when every other point
can be placed from them; otherwise the body is placed in a canonical frame from its
distances: a first point at the origin, a second on the x axis, a third in the xy plane
(y > 0), and the given coordinates enter as distances and an orientation (so that a user
body never comes back mirrored). Each further point is trilaterated from three placed
non-collinear points at known distances: its coordinates in the frame of the three points
(two in their plane, its squared height over it) are rationals of the six distances, so
whether it has two sides, one (a height exactly 0: a double placement, `singular`) or none
(the body is inconsistent) is decided exactly, for a kernel with exact numbers; for a kernel
of doubles a squared height within 1e-9 of the references' scale counts as 0. Both sides are
followed, and a side is dropped only where a further known distance or an orientation
certainly excludes it (its interval misses the value); a distance whose enclosure still
contains the value is taken as met, so a mismatch narrower than the final enclosures (about
2^-precision of the body's size) is not detected.

The chain of trilaterations widens the enclosures (each point inherits the widths of its
references), so they are computed first in double intervals and, if the widest one exceeds
2^-44 of the body's size (for `IT = CGAL::Gmpfi`: 2^(12 - p) at its default precision p),
again with `CGAL::Gmpfi` at 128, 256, ... bits up to `maximal_placement_precision`; the
result says which precision it used and how wide it is. Without MPFI (`CGAL_USE_MPFI`
undefined) the double enclosures are returned as they are.

The enumerations are cached per thread by the body's content, so that asking for one
placement after another costs one enumeration.

\tparam IT `CGAL::Interval_nt<false>` (double intervals), or `CGAL::Gmpfi`
\param c the collection (typically the output of `standardize()`)
\param body the index of the body in `c`
\param max_placements stop after this many placements (then `complete` is false)
\throws Input_error if the body's distances do not let its points be placed one after the other.
*/
template <class IT, class Traits>
Placement_enumeration<IT> enumerate_placements(const Rigid_body_collection<Traits>& c, std::size_t body,
                                               std::size_t max_placements = default_maximal_placements)
{
  return *internal::cached_placements<IT>(c, body, max_placements);
}

/*!
\ingroup PkgRigidIncidenceRef
\brief Every placement of body `body` of `c` (up to rigid motion), enclosed in intervals of
type `IT`: the `placements` of `enumerate_placements()`, which says how they are computed.

\param c the collection (typically the output of `standardize()`)
\param body the index of the body in `c`
\param max_placements the most placements the caller accepts
\throws Input_error if the body's distances do not let its points be placed one after the
other, or if it has more than `max_placements` placements (never a silently shortened list).
*/
template <class IT, class Traits>
std::vector<Body_enclosure<IT>> enclose_all_placements(const Rigid_body_collection<Traits>& c, std::size_t body,
                                                       std::size_t max_placements = default_maximal_placements)
{
  auto e = internal::cached_placements<IT>(c, body, max_placements);
  if (!e->complete)
    throw Input_error("body '" + c.body(body).name + "' has more than " + std::to_string(max_placements) + " placements");
  return e->placements;
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
  const std::size_t cap = (std::max)(default_maximal_placements, std::size_t((std::max)(variant, 0)) + 1);
  auto en = internal::cached_placements<IT>(c, body, cap);
  const std::vector<Body_enclosure<IT>>& all = en->placements;
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
