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
#include <CGAL/Rigid_incidence/internal/run_in_child.h>

#include <CGAL/CORE_Expr.h>
#include <CGAL/Gmpq.h>
#include <CGAL/Interval_nt.h>
#include <CGAL/Interval_traits.h>

#include <algorithm>
#include <chrono>
#include <array>
#include <cmath>
#include <deque>
#include <mutex>
#include <limits>
#include <map>
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
  /// from (in this body or in one of its rigid parts), so its two sides coincide (see
  /// `Placement_enumeration::singular`)
  bool singular = false;
  /// where, when `singular`: the body and the point whose height is exactly 0
  std::string singular_reason;
  /// the placement could not be decided at the final precision: a point's height over the
  /// plane of its references (placed through a rigid part or from inexact references) is
  /// not separated from 0, and the enclosure covers both sides (see
  /// `Placement_enumeration::undecided`)
  bool undecided = false;
};

namespace internal {

template <class IT> IT dot(const std::array<IT, 3>& a, const std::array<IT, 3>& b)
{ return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
template <class IT> std::array<IT, 3> sub(const std::array<IT, 3>& a, const std::array<IT, 3>& b)
{ return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
template <class IT> std::array<IT, 3> cross(const std::array<IT, 3>& a, const std::array<IT, 3>& b)
{ return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]}; }

// Two reasons (for a double placement, a singular configuration), each said once.
inline std::string joined_reasons(const std::string& a, const std::string& b)
{
  if (a.empty() || b.find(a) != std::string::npos) return b;
  if (b.empty() || a.find(b) != std::string::npos) return a;
  return a + "; " + b;
}

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

// One step of a body's placement. EXACT: a trilateration in exact rationals: point p is
//   X_p = X_A + a (X_B - X_A) + b (X_C - X_A) + side sqrt(s) (X_B - X_A) x (X_C - X_A),
// where a, b and s come from the six squared distances among p, A, B, C alone (s = h^2 / G,
// h the height of p over the plane ABC, G = |(B - A) x (C - A)|^2 the Gram determinant).
// So the side choices and the rounding of earlier points never enter them, and whether p
// has two sides, one (h = 0: a double placement) or none is decided exactly.
// INTERVAL: a trilateration from three placed points whose own distances are not all known
// exactly (they run through placements): the same formulas in intervals, from the placed
// coordinates; the sign of s is decided per placement in intervals.
// PART: a rigid part of the body superposed on its placed points (each of its placements in
// turn), which places its other points; with nothing left to place, a check.
enum class Placement_step_kind { EXACT, INTERVAL, PART };

struct Placement_step
{
  Placement_step_kind kind = Placement_step_kind::EXACT;
  std::size_t p = 0, A = 0, B = 0, C = 0;
  CGAL::Gmpq a, b, s;
  CGAL::Sign sign = CGAL::POSITIVE;  // of s
  std::vector<std::array<std::size_t, 3>> references;  // INTERVAL: candidate reference triples
  // INTERVAL: per point, the rigid part whose placements give its distance to p (none: the
  // distance is known exactly); `distance_parts` lists those parts once each
  std::vector<std::size_t> distance_part;
  std::vector<std::size_t> distance_parts;
  std::size_t part = 0;                                // PART: which part
  std::vector<std::size_t> places;                     // PART: the points it places
};

// What a body's distances say about its placements, exactly, before a side is chosen.
struct Placement_plan
{
  static constexpr std::size_t none = std::size_t(-1);
  std::string name;
  std::size_t m = 0;
  std::vector<std::string> labels;
  std::vector<std::vector<std::optional<CGAL::Gmpq>>> known;   // squared distances, local indices
  std::vector<std::optional<std::array<CGAL::Gmpq, 3>>> given; // coordinates the body gives
  bool in_given_frame = false;
  bool map_to_given = false;  // placed in a canonical frame, then moved onto the given coordinates
  std::array<std::size_t, 3> base{{0, 0, 0}};  // canonical frame: base[0] at 0, base[1] on +x, base[2] in xy, y > 0
  CGAL::Gmpq d01, c1, y2;                      // |base0 base1|^2; base2 = (c1 sqrt(d01), sqrt(y2), 0)
  std::size_t start_part = none;               // else: the body starts from this part's placements, in its frame
  std::size_t start_third = none;              // a start part with two points: the third point, in the xy plane
  std::vector<Placement_step> steps;           // in placement order
  std::vector<std::array<std::size_t, 4>> orient_idx;
  std::vector<CGAL::Sign> orient_sign;
  // sets of points (local indices) one body with coordinates holds rigidly: a height exactly 0
  // among them is that body's shape, not a double placement (rigidly_degenerate())
  std::vector<std::vector<std::size_t>> rigid_groups;
  std::vector<Placement_plan> parts;              // the plans of the body's rigid parts
  std::vector<std::vector<std::size_t>> part_map; // per part: its local index -> the body's (none: not a point of the body)
  std::string inconsistent;  // nonempty: the distances admit no placement, and why
  std::string singular;      // nonempty: every placement is a double one, and where
  double scale = 1;          // the body's size: its largest distance or coordinate
  double slack = 0;          // rounded input (a kernel of doubles): a relative mismatch it tolerates
};

// Is a height exactly 0 of p over the plane of A, B, C the shape of one body with coordinates
// rather than a coincidence of distances? Yes when one of the plan's rigid groups holds p and
// A, B, C (p in their plane rigidly), or p and two of them on one line with it (an axis of
// three points, see standardize()). Then p has one place and the placement is not a double one.
template <bool exact>
bool rigidly_degenerate(const Placement_plan& P, std::size_t p, std::size_t A, std::size_t B, std::size_t C)
{
  const std::size_t r[3] = {A, B, C};
  for (const auto& g : P.rigid_groups) {
    auto in = [&g](std::size_t q) { return std::find(g.begin(), g.end(), q) != g.end(); };
    if (!in(p)) continue;
    if (in(A) && in(B) && in(C)) return true;
    for (std::size_t u = 0; u < 3; ++u)
      for (std::size_t v = u + 1; v < 3; ++v) {
        const std::size_t q1 = r[u], q2 = r[v];
        if (!in(q1) || !in(q2) || !P.known[p][q1] || !P.known[p][q2] || !P.known[q1][q2]) continue;
        if (triangle_sign<exact>(*P.known[p][q1], *P.known[p][q2], *P.known[q1][q2]) == CGAL::ZERO) return true;
      }
  }
  return false;
}

// How many square roots a plan's exact coordinates may involve along one placement (a bound):
// one per trilaterated point with a nonzero height, and its parts' (frames take none, see
// Placement_frame). An exact sign of a value in such a tower costs a root bound of degree up
// to 2^n.
inline std::size_t square_roots(const Placement_plan& p)
{
  std::size_t n = 0;
  for (const auto& s : p.steps)
    if (s.kind == Placement_step_kind::INTERVAL || (s.kind == Placement_step_kind::EXACT && s.sign == CGAL::POSITIVE)) ++n;
  for (const auto& q : p.parts) n += square_roots(q);
  return n;
}

template <class Traits>
class Placement_planner
{
  typedef Rigid_body_collection<Traits> Collection;
  typedef typename Collection::Body Body;
  typedef CGAL::Gmpq Q;
  static constexpr std::size_t none = Placement_plan::none;

public:
  Placement_planner(const Collection& c, const Body& b) : c_(c), b_(b) {}

  Placement_plan run()
  {
    Placement_plan& P = plan_;
    const std::size_t m = b_.points.size();
    P.name = b_.name;
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
    if (!Traits::has_exact_ft) P.slack = 1e-9;  // as the side decisions below and standardize
    for (const auto& o : b_.orientations) { P.orient_idx.push_back({o.a, o.b, o.c, o.d}); P.orient_sign.push_back(o.sign); }
    {
      // the body's own rigid groups, and the points of each body of the collection with coordinates
      auto local_group = [&](const std::vector<std::size_t>& global) {
        std::vector<std::size_t> g;
        for (std::size_t q : global) if (b_.local(q) != none) g.push_back(b_.local(q));
        if (g.size() >= 3) P.rigid_groups.push_back(g);
      };
      for (const auto& g : b_.rigid_groups) local_group(g);
      std::vector<std::size_t> own;  // its own coordinates (entering as distances when they cannot start the placement)
      for (std::size_t k = 0; k < m; ++k) if (b_.has_coordinates[k]) own.push_back(b_.points[k]);
      local_group(own);
      for (const Body& o : c_.bodies()) {
        std::vector<std::size_t> g;
        for (std::size_t k = 0; k < o.points.size(); ++k) if (o.has_coordinates[k]) g.push_back(o.points[k]);
        local_group(g);
      }
    }
    for (const Body& part : b_.parts) {
      P.parts.push_back(Placement_planner<Traits>(c_, part).run());
      std::vector<std::size_t> map(part.points.size(), none);
      for (std::size_t k = 0; k < part.points.size(); ++k) map[k] = b_.local(part.points[k]);
      P.part_map.push_back(map);
      const Placement_plan& pp = P.parts.back();
      if (!pp.inconsistent.empty() && P.inconsistent.empty())
        P.inconsistent = "body '" + b_.name + "', through its part '" + part.name + "': " + pp.inconsistent;
    }
    std::vector<bool> used(P.parts.size(), false);
    // the given coordinates fix a frame only if three of them are off a line (exactly)
    bool given_spans = false;
    {
      std::vector<std::size_t> g;
      for (std::size_t i = 0; i < m; ++i) if (P.given[i]) g.push_back(i);
      for (std::size_t a = 2; a < g.size() && !given_spans; ++a) {
        const auto &X = *P.given[g[0]], &Y = *P.given[g[1]], &Z = *P.given[g[a]];
        Q u[3], v[3];
        for (int k = 0; k < 3; ++k) { u[k] = Y[k] - X[k]; v[k] = Z[k] - X[k]; }
        given_spans = CGAL::sign(u[1] * v[2] - u[2] * v[1]) != CGAL::ZERO || CGAL::sign(u[2] * v[0] - u[0] * v[2]) != CGAL::ZERO ||
                      CGAL::sign(u[0] * v[1] - u[1] * v[0]) != CGAL::ZERO;
      }
    }
    if (given_spans) { std::vector<bool> trial_used = used; P.in_given_frame = order(placed, trial_used, nullptr); }
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
            std::vector<bool> trial_used = used;
            if (order(trial, trial_used, nullptr)) base = std::array<std::size_t, 3>{i, j, k};
          }
      if (base) {
        P.base = *base;
        const auto [i, j, k] = *base;
        P.d01 = *P.known[i][j];
        P.c1 = (P.d01 + *P.known[i][k] - *P.known[j][k]) / (Q(2) * P.d01);
        P.y2 = *P.known[i][k] - P.c1 * P.c1 * P.d01;  // > 0: a proper triangle
        placed[i] = placed[j] = placed[k] = true;
      } else {
        // no triangle of known distances places the body: start from a rigid part instead
        for (std::size_t j = 0; j < P.parts.size() && P.start_part == none; ++j) {
          std::vector<bool> trial(m, false);
          std::size_t n = 0;
          for (std::size_t q : P.part_map[j]) if (q != none) { trial[q] = true; ++n; }
          std::vector<bool> trial_used(P.parts.size(), false);
          trial_used[j] = true;
          if (n >= 3 && order(trial, trial_used, nullptr)) P.start_part = j;
        }
        // a part with two points fixes their distance (one value per placement): a segment on
        // the x axis, and a third point at known distances from both in the xy plane
        for (std::size_t j = 0; j < P.parts.size() && P.start_part == none; ++j) {
          std::vector<std::size_t> two;
          for (std::size_t q : P.part_map[j]) if (q != none) two.push_back(q);
          if (two.size() != 2) continue;
          for (std::size_t c = 0; c < m && P.start_part == none; ++c) {
            if (c == two[0] || c == two[1] || !P.known[c][two[0]] || !P.known[c][two[1]]) continue;
            std::vector<bool> trial(m, false);
            trial[two[0]] = trial[two[1]] = trial[c] = true;
            std::vector<bool> trial_used(P.parts.size(), false);
            trial_used[j] = true;
            if (order(trial, trial_used, nullptr)) { P.start_part = j; P.start_third = c; }
          }
        }
        if (P.start_part == none)
          throw Input_error("body '" + b_.name + "': its points cannot be placed one after the other from three placed"
                            " points at known distances or from its rigid parts (a placement this version does not support)");
        for (std::size_t q : P.part_map[P.start_part]) if (q != none) placed[q] = true;
        if (P.start_third != none) placed[P.start_third] = true;
        used[P.start_part] = true;
      }
    }
    // the given coordinates cannot start the placement, but the result is still in their frame
    P.map_to_given = !P.in_given_frame && given_spans;
    order(placed, used, &P.steps);
    // the parts that placed nothing are checks: each must fit the placed points
    for (std::size_t j = 0; j < P.parts.size(); ++j)
      if (!used[j]) {
        Placement_step s;
        s.kind = Placement_step_kind::PART;
        s.part = j;
        P.steps.push_back(s);
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

  // Places the points one after the other from `placed`: an exact trilateration where one
  // exists (the first point by index), else a part with three placed points, else a
  // trilateration in intervals. Appends the steps to `steps` if given (and then marks the
  // parts used in `used`); true if every point is placed.
  bool order(std::vector<bool> placed, std::vector<bool>& used, std::vector<Placement_step>* steps)
  {
    const std::size_t m = plan_.m;
    while (true) {
      bool progress = false;
      // a point off the plane of three placed references first: a point in the plane of the
      // only ones it has so far (a double placement) waits for others that may hold it better
      for (bool nonzero : {true, false})
        for (std::size_t p = 0; p < m && !progress; ++p)
          if (!placed[p])
            if (auto tri = reference_triangle(p, placed, nonzero)) {
              if (steps) steps->push_back(step(p, *tri));
              placed[p] = progress = true;
            }
      for (std::size_t j = 0; j < plan_.parts.size() && !progress; ++j) {
        if (used[j]) continue;
        std::size_t on = 0;
        std::vector<std::size_t> places;
        for (std::size_t q : plan_.part_map[j]) {
          if (q == none) continue;
          if (placed[q]) ++on; else places.push_back(q);
        }
        if (on < 3 || places.empty()) continue;
        if (steps) {
          Placement_step s;
          s.kind = Placement_step_kind::PART;
          s.part = j;
          s.places = places;
          steps->push_back(s);
        }
        for (std::size_t q : places) placed[q] = true;
        used[j] = progress = true;
      }
      for (std::size_t p = 0; p < m && !progress; ++p) {
        if (placed[p]) continue;
        // references: placed points at a known distance, or at a distance a rigid part fixes
        // (one value per placement of the part; the part is checked whole later)
        std::vector<std::size_t> refs, from_part(m, none);
        for (std::size_t q = 0; q < m; ++q) {
          if (!placed[q]) continue;
          if (plan_.known[p][q]) { refs.push_back(q); continue; }
          for (std::size_t j = 0; j < plan_.parts.size(); ++j)
            if (!used[j] && holds(j, p) && holds(j, q)) { refs.push_back(q); from_part[q] = j; break; }
        }
        if (refs.size() < 3) continue;
        // reference triples, but none whose own distances put it on a line exactly (a point
        // on the line of two others: it would leave p's place undecided, where waiting for
        // another reference places it)
        std::vector<std::array<std::size_t, 3>> triples;
        for (std::size_t a = 0; a < refs.size() && triples.size() < 20; ++a)
          for (std::size_t b = a + 1; b < refs.size() && triples.size() < 20; ++b)
            for (std::size_t c = b + 1; c < refs.size() && triples.size() < 20; ++c)
              if (!on_a_line(refs[a], refs[b], refs[c])) triples.push_back({refs[a], refs[b], refs[c]});
        if (triples.empty()) continue;
        if (steps) {
          Placement_step s;
          s.kind = Placement_step_kind::INTERVAL;
          s.p = p;
          s.distance_part = from_part;
          for (std::size_t q : refs)
            if (from_part[q] != none &&
                std::find(s.distance_parts.begin(), s.distance_parts.end(), from_part[q]) == s.distance_parts.end())
              s.distance_parts.push_back(from_part[q]);
          s.references = triples;
          steps->push_back(s);
        }
        placed[p] = progress = true;
      }
      if (!progress) break;
    }
    return std::all_of(placed.begin(), placed.end(), [](bool x) { return x; });
  }

  // Do the known distances of i, j, k put them on a line (decided exactly)?
  bool on_a_line(std::size_t i, std::size_t j, std::size_t k) const
  {
    const auto& K = plan_.known;
    return K[i][j] && K[i][k] && K[j][k] && triangle_sign<Traits::has_exact_ft>(*K[i][j], *K[i][k], *K[j][k]) == CGAL::ZERO;
  }

  bool holds(std::size_t part, std::size_t p) const
  { return std::find(plan_.part_map[part].begin(), plan_.part_map[part].end(), p) != plan_.part_map[part].end(); }

  // The first proper triangle of placed points at known distances from p; with `nonzero`, the
  // first over whose plane p has a height that is not 0.
  std::optional<std::array<std::size_t, 3>> reference_triangle(std::size_t p, const std::vector<bool>& placed, bool nonzero) const
  {
    std::vector<std::size_t> refs;
    for (std::size_t q = 0; q < plan_.m; ++q) if (placed[q] && plan_.known[p][q]) refs.push_back(q);
    for (std::size_t a = 0; a < refs.size(); ++a) for (std::size_t b = a + 1; b < refs.size(); ++b)
      for (std::size_t c = b + 1; c < refs.size(); ++c)
        if (proper_triangle(refs[a], refs[b], refs[c]) &&
            (!nonzero || trilateration(p, {refs[a], refs[b], refs[c]}).sign != CGAL::ZERO))
          return std::array<std::size_t, 3>{refs[a], refs[b], refs[c]};
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
    const Placement_step s = trilateration(p, t);
    const Q r1 = *K[p][s.A], r2 = *K[p][s.B], r3 = *K[p][s.C];
    const Q h2 = s.s * (*K[s.A][s.B] * *K[s.A][s.C] - CGAL::square((*K[s.A][s.B] + *K[s.A][s.C] - *K[s.B][s.C]) / Q(2)));
    const std::string who = "'" + plan_.labels[p] + "' over the plane of '" + plan_.labels[s.A] + "', '" + plan_.labels[s.B] +
                            "' and '" + plan_.labels[s.C] + "'";
    if (s.sign == CGAL::NEGATIVE && plan_.inconsistent.empty())
      plan_.inconsistent = "body '" + b_.name + "': the squared distances of " + who + " (" + to_text(r1) + ", " + to_text(r2) + ", " +
                           to_text(r3) + ") admit no real point (its squared height over that plane would be " + to_text(h2) + ")";
    if (s.sign == CGAL::ZERO && !rigidly_degenerate<Traits::has_exact_ft>(plan_, p, s.A, s.B, s.C) && singular_points_++ == 0)
      plan_.singular = "body '" + b_.name + "': the height of " + who + " is exactly 0 (a double placement: its two sides coincide)";
    return s;
  }

  // The exact trilateration of p from the triangle t (see Placement_step), without notes.
  Placement_step trilateration(std::size_t p, const std::array<std::size_t, 3>& t) const
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
    return s;
  }

  static std::string to_text(const Q& q)
  {
    std::ostringstream os;
    os << CGAL::to_double(q);
    return os.str();
  }
};

// The frame of a placement's coordinates: a point with coordinates X is E X for a basis E.
// Cartesian (E = I) for interval types. With exact numbers, a body placed in a canonical frame
// uses the basis e1 = B - A, e2 = C - A, e3 = e1 x e2 of its first three points, whose Gram
// matrix M = E^T E = [[uu, uv, 0], [uv, vv, 0], [0, 0, G]] (G = uu vv - uv^2 = det E) is
// rational in their squared distances: a Cartesian frame needs sqrt(uu) and sqrt(G), so the
// exact coordinates would carry two square roots per frame that no choice depends on, and
// every exact sign test (a root bound over the whole tower) would pay for them.
template <class W>
struct Placement_frame
{
  typedef std::array<W, 3> P;
  bool cartesian = true;
  W uu = W(1), uv = W(0), vv = W(1), G = W(1);
  static Placement_frame basis(const W& uu, const W& uv, const W& vv)
  {
    Placement_frame f;
    f.cartesian = false;
    f.uu = uu; f.uv = uv; f.vv = vv; f.G = uu * vv - uv * uv;
    return f;
  }
  W dot(const P& a, const P& b) const
  {
    if (cartesian) return internal::dot(a, b);
    return a[0] * (uu * b[0] + uv * b[1]) + a[1] * (uv * b[0] + vv * b[1]) + G * a[2] * b[2];
  }
  // a x b = det(E) M^-1 (a x b in coordinates) = [[vv, -uv, 0], [-uv, uu, 0], [0, 0, 1]] (a x b)
  P cross(const P& a, const P& b) const
  {
    const P c = internal::cross(a, b);
    if (cartesian) return c;
    return {vv * c[0] - uv * c[1], uu * c[1] - uv * c[0], c[2]};
  }
};

// The rigid motion taking three points (y0, y1, y2, not on a line, in frame fy) to (x0, x1,
// x2, in frame fx), in intervals: a point's coordinates in the basis (u, v, u x v) of the
// first triangle, put on the same basis at the second. Exact values of congruent triangles
// give a rotation.
template <class W>
struct Interval_rigid_map
{
  typedef std::array<W, 3> P;
  Placement_frame<W> fy;
  P y0, u2, v2, w2, x0, u1, v1, w1;
  W uu, vv, uv, G;
  Interval_rigid_map(const P& a, const P& b, const P& c, const P& x, const P& y, const P& z,
                     const Placement_frame<W>& from = Placement_frame<W>(), const Placement_frame<W>& to = Placement_frame<W>())
    : fy(from), y0(a), u2(sub(b, a)), v2(sub(c, a)), w2(from.cross(u2, v2)), x0(x), u1(sub(y, x)), v1(sub(z, x)),
      w1(to.cross(u1, v1)), uu(from.dot(u2, u2)), vv(from.dot(v2, v2)), uv(from.dot(u2, v2)), G(from.dot(w2, w2)) {}
  P operator()(const P& q) const
  {
    const P d = sub(q, y0);
    const W du = fy.dot(d, u2), dv = fy.dot(d, v2);
    const W cu = (vv * du - uv * dv) / G, cv = (uu * dv - uv * du) / G, cw = fy.dot(d, w2) / G;
    P r;
    for (std::size_t c = 0; c < 3; ++c) r[c] = x0[c] + cu * u1[c] + cv * v1[c] + cw * w1[c];
    return r;
  }
};

// The placements of a plan in the interval type W (the caller sets W's rounding or precision).
template <class W>
class Placement_enumerator
{
  typedef std::array<W, 3> P;
  typedef typename CGAL::Interval_traits<W>::Lower Lower;
  typedef typename CGAL::Interval_traits<W>::Upper Upper;
  static constexpr std::size_t none = Placement_plan::none;
  // W = CORE::Expr: exact real algebraic numbers (a tower of square roots over the rationals),
  // whose signs and equalities are decided exactly; the choices intervals leave open at the
  // final precision are made with it (see cached_placements())
  static constexpr bool exact_ = std::is_same<W, CORE::Expr>::value;

public:
  Placement_enumerator(const Placement_plan& plan, std::size_t max_placements) : plan_(plan), max_(max_placements) {}

  /// Stop at `t` (exact arithmetic only: a sign that is 0 costs a root bound, which can take
  /// minutes in a deep tower): `stopped()` then says so, and the list is not to be used.
  void set_deadline(std::chrono::steady_clock::time_point t) { deadline_ = t; }
  bool stopped() const { return stopped_; }

  std::vector<Body_enclosure<W>> run()
  {
    const Placement_plan& Pl = plan_;
    for (std::size_t j = 0; j < Pl.parts.size(); ++j) {
      Placement_enumerator<W> e(Pl.parts[j], max_);
      e.set_deadline(deadline_);
      part_placements_.push_back(e.run());
      if (e.stopped()) { stopped_ = true; return out_; }
      part_frames_.push_back(e.frames());
      if (e.truncated()) part_truncated_ = true;  // the body is incomplete, but its list goes on
      if (!e.undecided().empty()) note_undecided(false, "its part '" + Pl.parts[j].name + "': " + e.undecided(), false);
    }
    for (const auto& s : Pl.steps) {
      if (s.kind != Placement_step_kind::EXACT) { a_.push_back(W(0)); b_.push_back(W(0)); t_.push_back(W(0)); continue; }
      a_.push_back(from_rational(s.a));
      b_.push_back(from_rational(s.b));
      t_.push_back(s.sign == CGAL::POSITIVE ? W(CGAL::sqrt(from_rational(s.s))) : W(0));
    }
    // per step: the distances to check (pairs of placed points, one of them new, not the
    // exact step's references) and the orientations whose last point it places
    std::vector<bool> placed(Pl.m, false);
    x_.assign(Pl.m, P{W(0), W(0), W(0)});
    if (Pl.in_given_frame) {
      for (std::size_t i = 0; i < Pl.m; ++i)
        if (Pl.given[i]) {
          for (int k = 0; k < 3; ++k) x_[i][std::size_t(k)] = from_rational((*Pl.given[i])[std::size_t(k)]);
          placed[i] = true;
        }
    } else if (Pl.start_part == none) {
      if constexpr (exact_) {
        // the basis of the first three points (no square root)
        frame_ = Placement_frame<W>::basis(from_rational(Pl.d01), from_rational(Pl.c1 * Pl.d01),
                                           from_rational(Pl.c1 * Pl.c1 * Pl.d01 + Pl.y2));
        x_[Pl.base[1]] = P{W(1), W(0), W(0)};
        x_[Pl.base[2]] = P{W(0), W(1), W(0)};
      } else {
        const W l = CGAL::sqrt(from_rational(Pl.d01));
        x_[Pl.base[1]] = P{l, W(0), W(0)};
        x_[Pl.base[2]] = P{from_rational(Pl.c1) * l, W(CGAL::sqrt(from_rational(Pl.y2))), W(0)};
      }
      for (std::size_t i : Pl.base) placed[i] = true;
    } else {
      for (std::size_t q : Pl.part_map[Pl.start_part]) if (q != none) placed[q] = true;
      if (Pl.start_third != none) placed[Pl.start_third] = true;
    }
    for (std::size_t p = 0; p < Pl.m; ++p)
      for (std::size_t q = p + 1; q < Pl.m; ++q)
        if (placed[p] && placed[q] && Pl.known[p][q] && Pl.start_part != none) start_checks_.push_back({p, q});
    for (std::size_t o = 0; o < Pl.orient_idx.size(); ++o)
      if (all_placed(Pl.orient_idx[o], placed)) initial_orientations_.push_back(o);
    for (const auto& s : Pl.steps) {
      std::vector<std::size_t> fresh;
      if (s.kind == Placement_step_kind::PART) fresh = s.places; else fresh.push_back(s.p);
      std::vector<std::array<std::size_t, 2>> checks;
      for (std::size_t p : fresh) {
        for (std::size_t q = 0; q < Pl.m; ++q)
          if (placed[q] && Pl.known[p][q] &&
              !(s.kind == Placement_step_kind::EXACT && (q == s.A || q == s.B || q == s.C)))
            checks.push_back({p, q});
        placed[p] = true;
      }
      checks_.push_back(checks);
      std::vector<std::size_t> orient;
      for (std::size_t o = 0; o < Pl.orient_idx.size(); ++o) {
        const auto& q = Pl.orient_idx[o];
        bool touches = false;
        for (std::size_t p : fresh) if (std::find(q.begin(), q.end(), p) != q.end()) touches = true;
        if (touches && all_placed(q, placed)) orient.push_back(o);
      }
      orientations_.push_back(orient);
    }
    if (Pl.start_part == none) {
      for (std::size_t o : initial_orientations_) if (violates(o)) return out_;
      place(0, std::string(), false);
    } else if (Pl.start_third != none) {
      // a segment from each placement of the start part (each length once), then the third point
      const auto& map = Pl.part_map[Pl.start_part];
      std::vector<std::size_t> two;
      for (std::size_t k = 0; k < map.size(); ++k) if (map[k] != none) two.push_back(k);
      const std::size_t A = map[two[0]], B = map[two[1]], C = Pl.start_third;
      std::vector<W> lengths;
      Meet_index lengths_index;
      for (std::size_t ei = 0; ei < part_placements_[Pl.start_part].size(); ++ei) {
        const auto& e = part_placements_[Pl.start_part][ei];
        const P d = sub(e.coordinates[two[0]], e.coordinates[two[1]]);
        const W L2 = part_frames_[Pl.start_part][ei].dot(d, d);
        bool again = false;
        const CGAL::Interval_nt<false> key = Meet_index::key(L2);
        for (std::size_t o : lengths_index.candidates(key))
          if (const W& l = lengths[o]; same(l, L2)) {
            if (narrow_enough(l, 2) && narrow_enough(L2, 2)) again = true;
            else note_undecided(false, "two lengths of '" + Pl.labels[A] + "'-'" + Pl.labels[B] + "' that its part gives are not separated");
          }
        if (again) continue;
        lengths.push_back(L2);
        lengths_index.add(key);
        const W rA = from_rational(*Pl.known[C][A]), rB = from_rational(*Pl.known[C][B]);
        const W uv = (L2 + rA - rB) / W(2), y2 = rA - uv * uv / L2;  // y2: the squared height of C over AB
        bool here_undecided = false;
        W y = W(0);
        if (within_slack_of_zero(y2)) y = W(0);  // rounded input: on the line
        else if (negative(y2)) continue;
        else if (positive(y2)) { if constexpr (!exact_) y = CGAL::sqrt(y2); }  // (exact numbers: the basis of A, B, C)
        else if (exact_) y = W(0);  // exactly on the line
        else {
          y = both_sides(y2, true);
          here_undecided = true;
          note_undecided(false, "the height of '" + Pl.labels[C] + "' over the line of '" + Pl.labels[A] + "' and '" + Pl.labels[B] +
                                    "' is not separated from 0");
        }
        x_[A] = P{W(0), W(0), W(0)};
        if constexpr (exact_) {
          // the basis (B - A, C - A, ...), or, with C on the line AB, B - A and a unit vector across it
          x_[B] = P{W(1), W(0), W(0)};
          if (positive(y2)) { frame_ = Placement_frame<W>::basis(L2, uv, rA); x_[C] = P{W(0), W(1), W(0)}; }
          else { frame_ = Placement_frame<W>::basis(L2, W(0), W(1)); x_[C] = P{uv / L2, W(0), W(0)}; }
        } else {
          const W L = CGAL::sqrt(L2);
          x_[B] = P{L, W(0), W(0)};
          x_[C] = P{uv / L, y, W(0)};
        }
        if (!fits(start_checks_)) continue;
        bool ok = true;
        for (std::size_t o : initial_orientations_) if (violates(o)) { ok = false; break; }
        if (ok) place(0, e.singular_reason, e.undecided || here_undecided);
      }
    } else {
      // the start part's placements, each in its own frame
      const auto& map = Pl.part_map[Pl.start_part];
      for (std::size_t ei = 0; ei < part_placements_[Pl.start_part].size(); ++ei) {
        const auto& e = part_placements_[Pl.start_part][ei];
        frame_ = part_frames_[Pl.start_part][ei];
        for (std::size_t k = 0; k < map.size(); ++k) if (map[k] != none) x_[map[k]] = e.coordinates[k];
        if (!fits(start_checks_)) continue;
        bool ok = true;
        for (std::size_t o : initial_orientations_) if (violates(o)) { ok = false; break; }
        if (ok) place(0, e.singular_reason, e.undecided);
      }
    }
    return out_;
  }

  bool truncated() const { return truncated_ || part_truncated_; }
  /// per placement run() returned: the frame of its coordinates (Cartesian but for exact numbers)
  const std::vector<Placement_frame<W>>& frames() const { return out_frames_; }
  /// nonempty: some placements could not be decided in this precision, and which
  std::string undecided() const
  {
    return undecided_count_ > 1 ? undecided_ + "; and " + std::to_string(undecided_count_ - 1) + " more such choices" : undecided_;
  }

private:
  const Placement_plan& plan_;
  std::size_t max_;
  bool truncated_ = false, part_truncated_ = false;
  std::chrono::steady_clock::time_point deadline_ = std::chrono::steady_clock::time_point::max();
  bool stopped_ = false;
  std::string undecided_;
  std::size_t undecided_count_ = 0;
  std::vector<W> a_, b_, t_;
  std::vector<std::vector<std::array<std::size_t, 2>>> checks_;
  std::vector<std::array<std::size_t, 2>> start_checks_;
  std::vector<std::vector<std::size_t>> orientations_;
  std::vector<std::size_t> initial_orientations_;
  std::vector<std::vector<Body_enclosure<W>>> part_placements_;
  std::vector<std::vector<Placement_frame<W>>> part_frames_;
  std::vector<P> x_;
  Placement_frame<W> frame_;  // of x_
  std::vector<Body_enclosure<W>> out_;
  std::vector<Placement_frame<W>> out_frames_;

  static W from_rational(const CGAL::Gmpq& q)
  {
    if constexpr (is_interval_nt<W>::value) return W(CGAL::to_interval(q));
    else if constexpr (exact_) return W(CORE::BigRat(q.mpq()));
    else return W(q);
  }
  static bool all_placed(const std::array<std::size_t, 4>& q, const std::vector<bool>& placed)
  { return placed[q[0]] && placed[q[1]] && placed[q[2]] && placed[q[3]]; }
  static bool positive(const W& x)
  {
    if constexpr (exact_) return CGAL::sign(x) == CGAL::POSITIVE;
    else return Lower()(x) > 0;
  }
  // Do two numbers possibly have one value (intervals that meet; exact numbers that are equal)?
  static bool same(const W& a, const W& b)
  {
    if constexpr (exact_) return CGAL::compare(a, b) == CGAL::EQUAL;
    else return internal::overlap(a, b);
  }
  // An enclosure narrow enough (2^-40 of the body's size, or of its square) to call two that
  // meet one value.
  bool narrow_enough(const W& x, int power = 1) const
  {
    if constexpr (exact_) return true;
    else {
      const double w = CGAL::to_double(Upper()(x)) - CGAL::to_double(Lower()(x));
      return w <= std::ldexp(1.0, -40) * (power == 1 ? plan_.scale : plan_.scale * plan_.scale);
    }
  }
  // With rounded input: a squared length within the slack of 0 counts as 0.
  bool within_slack_of_zero(const W& x) const
  {
    if constexpr (exact_) return false;  // exact input only
    else {
      if (plan_.slack == 0) return false;
      const double e = plan_.slack * plan_.scale * plan_.scale;
      return CGAL::to_double(Lower()(x)) >= -e && CGAL::to_double(Upper()(x)) <= e;
    }
  }
  // Do two enclosures meet, within the slack of rounded input (a length, or a squared one)?
  bool meet(const W& a, const W& b, int power) const
  {
    if constexpr (exact_) return same(a, b);
    else {
      if (plan_.slack == 0) return same(a, b);
      const double e = plan_.slack * (power == 1 ? plan_.scale : plan_.scale * plan_.scale);
      return internal::overlap(a + typename CGAL::Interval_traits<W>::Hull()(W(-e), W(e)), b);
    }
  }
  static bool negative(const W& x)
  {
    if constexpr (exact_) return CGAL::sign(x) == CGAL::NEGATIVE;
    else return Upper()(x) < 0;
  }
  // An enclosure of both signs of a square root: [-sqrt(upper(S)), sqrt(upper(S))] (intervals only)
  static W both_sides(const W& S, bool from_zero)
  {
    if constexpr (exact_) { CGAL_assertion(false); return W(0); }
    else {
      const W top = CGAL::sqrt(W(Upper()(S)));
      return typename CGAL::Interval_traits<W>::Hull()(from_zero ? W(0) : W(-top), top);
    }
  }
  // How a choice exact arithmetic makes is worded: "exactly" where intervals say "certainly".
  static const char* certainly() { return exact_ ? "exactly" : "certainly"; }

  // (`consequence` false: what the part's own note says already)
  void note_undecided(bool dropped, const std::string& what, bool consequence = true)
  {
    if (undecided_count_++ == 0)
      undecided_ = "body '" + plan_.name + "': " + what +
                   (!consequence ? "" : dropped ? "; that placement is left out" : "; that placement is kept, enclosing both sides");
  }

  // Does the placement so far certainly violate orientation o?
  bool violates(std::size_t o) const
  {
    const auto& q = plan_.orient_idx[o];
    W det = frame_.dot(frame_.cross(sub(x_[q[1]], x_[q[0]]), sub(x_[q[2]], x_[q[0]])), sub(x_[q[3]], x_[q[0]]));
    if (plan_.orient_sign[o] == CGAL::POSITIVE && negative(det)) return true;
    if (plan_.orient_sign[o] == CGAL::NEGATIVE && positive(det)) return true;
    return false;
  }

  // Do the placed points meet these known distances (within the enclosures)?
  bool fits(const std::vector<std::array<std::size_t, 2>>& checks) const
  {
    for (const auto& c : checks) {
      P d = sub(x_[c[0]], x_[c[1]]);
      if (!meet(frame_.dot(d, d), from_rational(*plan_.known[c[0]][c[1]]), 2)) return false;
    }
    return true;
  }

  // The Gram determinant of the triangle (a, b, c) relative to its sides' lengths: a lower
  // bound (negative: not certainly a proper triangle).
  static double flatness(const Placement_frame<W>& f, const P& a, const P& b, const P& c)
  {
    const P u = sub(b, a), v = sub(c, a);
    const W uu = f.dot(u, u), vv = f.dot(v, v), uv = f.dot(u, v);
    if constexpr (exact_) {
      const W g = uu * vv - uv * uv;
      if (CGAL::sign(g) != CGAL::POSITIVE) return -1;
      const double r = CGAL::to_double(g / (uu * vv));
      return r > 0 ? r : std::numeric_limits<double>::min();  // off a line, however little
    } else {
      const double den = CGAL::to_double(Upper()(uu)) * CGAL::to_double(Upper()(vv));
      const double g = CGAL::to_double(Lower()(uu * vv - uv * uv));
      return den > 0 ? g / den : -1;
    }
  }

  // Of the points `idx` (the first 8), the three farthest from a line; false if no three
  // are certainly off a line.
  static bool widest_triangle(const Placement_frame<W>& f, const std::vector<P>& x, const std::vector<std::size_t>& idx,
                              std::array<std::size_t, 3>& r)
  {
    double best = 0;
    const std::size_t n = (std::min)(idx.size(), std::size_t(8));
    for (std::size_t i = 0; i < n; ++i) for (std::size_t j = i + 1; j < n; ++j) for (std::size_t l = j + 1; l < n; ++l) {
      const double fl = flatness(f, x[idx[i]], x[idx[j]], x[idx[l]]);
      if (fl > best) { best = fl; r = {idx[i], idx[j], idx[l]}; }
    }
    return best > 0;
  }

  void emit(const std::string& singular, bool undecided)
  {
    if (out_.size() >= max_) { truncated_ = true; return; }
    Body_enclosure<W> e;
    e.coordinates = x_;
    e.in_given_frame = plan_.in_given_frame;
    if (plan_.map_to_given) {
      // placed in a canonical frame, then moved to the given coordinates (three of them
      // farthest from a line carry the motion; the given points keep their exact values)
      std::vector<std::size_t> g;
      for (std::size_t i = 0; i < plan_.m; ++i) if (plan_.given[i]) g.push_back(i);
      std::array<std::size_t, 3> r{{0, 0, 0}};
      if (!widest_triangle(frame_, x_, g, r)) {
        note_undecided(true, std::string("its points with coordinates are not ") + certainly() + " off a line in a placement");
        return;
      }
      auto given = [&](std::size_t i) {
        P q;
        for (std::size_t k = 0; k < 3; ++k) q[k] = from_rational((*plan_.given[i])[k]);
        return q;
      };
      const Interval_rigid_map<W> motion(x_[r[0]], x_[r[1]], x_[r[2]], given(r[0]), given(r[1]), given(r[2]), frame_);
      for (std::size_t i = 0; i < plan_.m; ++i) {
        const P y = motion(x_[i]);
        if (!plan_.given[i]) { e.coordinates[i] = y; continue; }
        const P q = given(i);
        for (std::size_t k = 0; k < 3; ++k)
          if (!meet(y[k], q[k], 1)) return;  // the given coordinates certainly do not fit
        e.coordinates[i] = q;
      }
      e.in_given_frame = true;
    }
    e.variant = int(out_.size());
    e.consistent = true;
    e.singular_reason = also(plan_.singular, singular);
    e.singular = !e.singular_reason.empty();
    e.undecided = undecided;
    out_.push_back(std::move(e));
    out_frames_.push_back(plan_.map_to_given ? Placement_frame<W>() : frame_);
  }

  static std::string also(const std::string& a, const std::string& b) { return joined_reasons(a, b); }

  // After step k placed its points: its distance and orientation checks, then the next step.
  void next(std::size_t k, const std::string& singular, bool undecided)
  {
    if (!fits(checks_[k])) return;
    for (std::size_t o : orientations_[k]) if (violates(o)) return;
    place(k + 1, singular, undecided);
  }

  // Depth first over the sides of each step and the placements of each part: a choice is
  // kept unless a known distance or an orientation certainly excludes it; a step with s = 0
  // has one side.
  void place(std::size_t k, const std::string& singular, bool undecided)
  {
    if (truncated_ || stopped_) return;
    if constexpr (exact_)
      if (std::chrono::steady_clock::now() > deadline_) { stopped_ = true; return; }
    const auto& steps = plan_.steps;
    if (k == steps.size()) { emit(singular, undecided); return; }
    const Placement_step& s = steps[k];
    if (s.kind == Placement_step_kind::PART) { superpose(k, singular, undecided); return; }
    if (s.kind == Placement_step_kind::INTERVAL) {
      std::vector<std::optional<W>> r2(plan_.m);
      for (std::size_t q = 0; q < plan_.m; ++q) if (plan_.known[s.p][q]) r2[q] = from_rational(*plan_.known[s.p][q]);
      with_part_distances(k, 0, r2, singular, undecided);
      return;
    }
    trilaterate(k, s.A, s.B, s.C, a_[k], b_[k], t_[k], s.sign == CGAL::POSITIVE, singular, undecided);
  }

  // The distances of an interval step that rigid parts fix: the product of their placements
  // (placements giving the same lengths count once), then the trilateration.
  void with_part_distances(std::size_t k, std::size_t i, std::vector<std::optional<W>>& r2, const std::string& singular,
                           bool undecided)
  {
    const Placement_step& s = plan_.steps[k];
    if (i == s.distance_parts.size()) { interval_step(k, r2, singular, undecided); return; }
    const std::size_t j = s.distance_parts[i];
    const auto& map = plan_.part_map[j];
    auto local = [&](std::size_t q) { return std::size_t(std::find(map.begin(), map.end(), q) - map.begin()); };
    const std::size_t lp = local(s.p);
    std::vector<std::size_t> qs;
    for (std::size_t q = 0; q < plan_.m; ++q) if (s.distance_part[q] == j) qs.push_back(q);
    std::vector<std::vector<W>> seen;
    Meet_index seen_index;
    for (std::size_t ei = 0; ei < part_placements_[j].size(); ++ei) {
      const auto& e = part_placements_[j][ei];
      std::vector<W> L;
      for (std::size_t q : qs) { const P d = sub(e.coordinates[lp], e.coordinates[local(q)]); L.push_back(part_frames_[j][ei].dot(d, d)); }
      bool again = false;
      const CGAL::Interval_nt<false> key = Meet_index::key(L);
      for (std::size_t o : seen_index.candidates(key)) {
        const std::vector<W>& other = seen[o];
        bool same = true, narrow = true;
        for (std::size_t c = 0; c < L.size(); ++c) {
          same = same && this->same(L[c], other[c]);
          narrow = narrow && narrow_enough(L[c], 2) && narrow_enough(other[c], 2);
        }
        if (!same) continue;
        if (narrow) { again = true; break; }
        note_undecided(false, "two lengths from '" + plan_.labels[s.p] + "' that its part '" + plan_.parts[j].name +
                                  "' gives are not separated");
      }
      if (again) continue;
      seen.push_back(L);
      seen_index.add(key);
      for (std::size_t c = 0; c < qs.size(); ++c) r2[qs[c]] = L[c];
      with_part_distances(k, i + 1, r2, also(singular, e.singular_reason), undecided || e.undecided);
    }
  }

  // A trilateration from placed points whose distances are not all known exactly: the
  // reference triple farthest from a line, then a, b and s from the placed points.
  void interval_step(std::size_t k, const std::vector<std::optional<W>>& r2, std::string singular, bool undecided)
  {
    const Placement_step& s = plan_.steps[k];
    std::size_t A = 0, B = 0, C = 0;
    bool two_sides = false, here_undecided = false;
    W a(0), b(0), t(0);
    {
      double best = 0;
      bool found = false;
      for (const auto& r : s.references) {
        double f = flatness(frame_, x_[r[0]], x_[r[1]], x_[r[2]]);
        if (f > best) { best = f; A = r[0]; B = r[1]; C = r[2]; found = true; }
      }
      if (!found) {
        note_undecided(true, "the points '" + plan_.labels[s.p] + "' is placed from are not " + certainly() + " off a line");
        return;
      }
      // a, b and the squared height over G of p from the triple (A, B, C)
      auto from = [&](std::size_t A1, std::size_t B1, std::size_t C1, W& a1, W& b1, W& H2, W& S1) {
        const P u = sub(x_[B1], x_[A1]), v = sub(x_[C1], x_[A1]);
        const W uu = frame_.dot(u, u), vv = frame_.dot(v, v), uv = frame_.dot(u, v), G = uu * vv - uv * uv;
        const W r1 = *r2[A1], r2B = *r2[B1], r3 = *r2[C1];
        const W alpha = (r1 - r2B + uu) / W(2), beta = (r1 - r3 + vv) / W(2);
        a1 = (alpha * vv - beta * uv) / G;
        b1 = (beta * uu - alpha * uv) / G;
        H2 = r1 - (a1 * a1 * uu + W(2) * a1 * b1 * uv + b1 * b1 * vv);
        S1 = H2 / G;
      };
      W H2(0), S(0);
      from(A, B, C, a, b, H2, S);
      if (!within_slack_of_zero(H2) && !positive(S) && !negative(S)) {
        // p not certainly off the plane of the flattest triple (exactly on it, in exact
        // arithmetic): a triple it is certainly off (or certainly has no real point for) decides
        // its sides, and the distances to the others are checks; none: the first stays
        for (const auto& r : s.references) {
          if (flatness(frame_, x_[r[0]], x_[r[1]], x_[r[2]]) <= 0) continue;
          W a1(0), b1(0), H21(0), S1(0);
          from(r[0], r[1], r[2], a1, b1, H21, S1);
          if (!positive(S1) && !negative(S1)) continue;
          A = r[0]; B = r[1]; C = r[2]; a = a1; b = b1; H2 = H21; S = S1;
          break;
        }
      }
      if (within_slack_of_zero(H2)) { t = W(0); two_sides = false; }  // rounded input: on the plane
      else if (negative(S)) return;  // no real point on this branch
      else if (positive(S)) { t = CGAL::sqrt(S); two_sides = true; }
      else if (exact_) {  // s = 0 exactly: a double placement, unless a body with coordinates holds p there
        t = W(0);
        two_sides = false;
        if (!rigidly_degenerate<true>(plan_, s.p, A, B, C))
          singular = also(singular, "body '" + plan_.name + "': the height of '" + plan_.labels[s.p] + "' over the plane of '" +
                                      plan_.labels[A] + "', '" + plan_.labels[B] + "' and '" + plan_.labels[C] +
                                      "' is exactly 0 (a double placement: its two sides coincide)");
      }
      else {
        // s not separated from 0: one placement enclosing both sides (and the double point)
        t = both_sides(S, false);
        two_sides = false;
        here_undecided = true;
        note_undecided(false, "the height of '" + plan_.labels[s.p] + "' over the plane of '" + plan_.labels[A] + "', '" +
                                  plan_.labels[B] + "' and '" + plan_.labels[C] + "' is not separated from 0");
      }
    }
    trilaterate(k, A, B, C, a, b, t, two_sides, singular, undecided || here_undecided);
  }

  // Point p of step k at X_A + a (X_B - X_A) + b (X_C - X_A) +- t (X_B - X_A) x (X_C - X_A).
  void trilaterate(std::size_t k, std::size_t A, std::size_t B, std::size_t C, const W& a, const W& b, const W& t,
                   bool two_sides, const std::string& singular, bool undecided)
  {
    const Placement_step& s = plan_.steps[k];
    const P& XA = x_[A];
    const P u = sub(x_[B], XA), v = sub(x_[C], XA), n = frame_.cross(u, v);
    P w;
    for (std::size_t i = 0; i < 3; ++i) w[i] = XA[i] + a * u[i] + b * v[i];
    for (int side : {1, -1}) {
      if (side < 0 && !two_sides) break;
      P xp;
      for (std::size_t i = 0; i < 3; ++i) xp[i] = side > 0 ? w[i] + t * n[i] : w[i] - t * n[i];
      x_[s.p] = xp;
      next(k, singular, undecided);
    }
  }

  // Values kept so far (placements of a part in a superposition, lengths of a start part's
  // segment), looked up by a necessary condition of meeting: the enclosures of one number per
  // value (a length; for a placement, one fixed generic linear form of its coordinates), in
  // double intervals rounded outward, meet. Scanning every kept value made the merged parts of
  // long strips and molecular rings quadratic (2^14 placements of a 20-atom ring's part: 1.3e8
  // comparisons in MPFR).
  struct Meet_index
  {
    typedef CGAL::Interval_nt<false> D;
    std::multimap<double, std::size_t> by_lower;  // finite keys: lower bound -> value
    std::vector<std::size_t> unbounded;           // values whose key is not finite (always candidates)
    double widest = 0;                            // the widest finite key
    std::size_t size = 0;

    // weight j of a linear form: 1 + frac(j * golden ratio), distinct, no symmetry of the form
    static double weight(std::size_t j)
    {
      return 1 + (double(j) * 0.6180339887498949 - std::floor(double(j) * 0.6180339887498949));
    }
    // a placement's key (its coordinates), a list of lengths' key, a length's key
    static D key(const std::vector<P>& x)
    {
      typename D::Protector protect;
      D k(0);
      std::size_t j = 0;
      for (const P& q : x)
        for (std::size_t c = 0; c < 3; ++c) k += D(weight(j++)) * D(CGAL::to_interval(q[c]));
      return k;
    }
    static D key(const std::vector<W>& x)
    {
      typename D::Protector protect;
      D k(0);
      for (std::size_t j = 0; j < x.size(); ++j) k += D(weight(j)) * D(CGAL::to_interval(x[j]));
      return k;
    }
    static D key(const W& x) { return D(CGAL::to_interval(x)); }
    // the values whose keys may meet `k`, in the order they were added
    std::vector<std::size_t> candidates(const D& k) const
    {
      if (!std::isfinite(k.inf()) || !std::isfinite(k.sup())) {
        std::vector<std::size_t> all(size);
        for (std::size_t i = 0; i < size; ++i) all[i] = i;
        return all;
      }
      // a key [lo, hi] meets k when lo <= sup k and hi >= inf k, so lo >= inf k - widest
      typename D::Protector protect;
      const double from = (D(k.inf()) - D(widest)).inf();
      std::vector<std::size_t> r = unbounded;
      for (auto it = by_lower.lower_bound(from); it != by_lower.end() && it->first <= k.sup(); ++it) r.push_back(it->second);
      std::sort(r.begin(), r.end());
      return r;
    }
    void add(const D& k)
    {
      const std::size_t i = size++;
      if (!std::isfinite(k.inf()) || !std::isfinite(k.sup())) {
        unbounded.push_back(i);
        return;
      }
      by_lower.emplace(k.inf(), i);
      typename D::Protector protect;
      widest = (std::max)(widest, (D(k.sup()) - D(k.inf())).sup());
    }
  };

  // A part superposed on its placed points, one placement after the other: the rigid motion
  // that takes three of them (the farthest from a line) to their places maps the others;
  // a placement whose images miss a placed point is excluded. Two placements of the part
  // that put the body's points at the same places count once.
  void superpose(std::size_t k, const std::string& singular, bool undecided)
  {
    const Placement_step& s = plan_.steps[k];
    const auto& map = plan_.part_map[s.part];
    std::vector<std::size_t> on;  // the part's local indices of points placed before this step
    for (std::size_t i = 0; i < map.size(); ++i)
      if (map[i] != none && std::find(s.places.begin(), s.places.end(), map[i]) == s.places.end()) on.push_back(i);
    std::vector<std::vector<P>> seen;
    Meet_index seen_index;
    bool checked = false;
    for (std::size_t ei = 0; ei < part_placements_[s.part].size(); ++ei) {
      const auto& e = part_placements_[s.part][ei];
      const Placement_frame<W>& fy = part_frames_[s.part][ei];
      const auto& y = e.coordinates;
      std::vector<P> image(map.size());
      if (on.size() >= 3) {
        std::array<std::size_t, 3> r{{0, 0, 0}};
        if (!widest_triangle(fy, y, on, r)) {
          note_undecided(true, "the points it shares with its part '" + plan_.parts[s.part].name + "' are not " + certainly() +
                                   " off a line");
          continue;
        }
        const Interval_rigid_map<W> motion(y[r[0]], y[r[1]], y[r[2]], x_[map[r[0]]], x_[map[r[1]]], x_[map[r[2]]], fy, frame_);
        for (std::size_t i = 0; i < map.size(); ++i) if (map[i] != none) image[i] = motion(y[i]);
      } else if (on.empty()) {
        for (std::size_t i = 0; i < map.size(); ++i) image[i] = y[i];
      } else {
        // one or two points shared: their distance must be the part's (a check only)
        bool ok = true;
        for (std::size_t i = 0; i < on.size(); ++i) for (std::size_t j = i + 1; j < on.size(); ++j) {
          P d1 = sub(x_[map[on[i]]], x_[map[on[j]]]), d2 = sub(y[on[i]], y[on[j]]);
          if (!meet(frame_.dot(d1, d1), fy.dot(d2, d2), 2)) ok = false;
        }
        if (!ok) continue;
        for (std::size_t i : on) image[i] = x_[map[i]];
      }
      bool ok = true;
      for (std::size_t i : on)
        for (std::size_t c = 0; c < 3 && ok; ++c) ok = meet(image[i][c], x_[map[i]][c], 1);
      if (!ok) continue;
      if (s.places.empty()) {
        // a check: one fitting placement is enough (it places nothing)
        if (!checked) { checked = true; place(k + 1, also(singular, e.singular_reason), undecided || e.undecided); }
        continue;
      }
      std::vector<P> mine;
      for (std::size_t i = 0; i < map.size(); ++i) if (map[i] != none) mine.push_back(image[i]);
      bool again = false;
      const CGAL::Interval_nt<false> key = Meet_index::key(mine);
      for (std::size_t o : seen_index.candidates(key)) {
        const std::vector<P>& other = seen[o];
        bool same = true;
        for (std::size_t i = 0; i < mine.size() && same; ++i)
          for (std::size_t c = 0; c < 3 && same; ++c) same = this->same(mine[i][c], other[i][c]);
        if (!same) continue;
        // overlapping enclosures are one placement only when they are narrow; else the
        // precision is raised (until then both are kept)
        bool narrow = true;
        for (std::size_t i = 0; i < mine.size() && narrow; ++i)
          for (std::size_t c = 0; c < 3 && narrow; ++c) narrow = narrow_enough(mine[i][c]) && narrow_enough(other[i][c]);
        if (narrow) { again = true; break; }
        note_undecided(false, "two placements of its part '" + plan_.parts[s.part].name + "' are not separated");
      }
      if (again) continue;
      seen.push_back(std::move(mine));
      seen_index.add(key);
      for (std::size_t i = 0; i < map.size(); ++i)
        if (map[i] != none && std::find(s.places.begin(), s.places.end(), map[i]) != s.places.end()) x_[map[i]] = image[i];
      next(k, also(singular, e.singular_reason), undecided || e.undecided);
    }
  }
};

// The widest coordinate enclosure of a list of placements, in units of `scale` (or of the
// coordinate, where it is larger).
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
        // relative to the coordinate itself where it is larger than the body: a point far
        // from the others (at 1e308) is enclosed to a unit in the last place of its double,
        // which no precision narrows
        w = (std::max)(w, d / (std::max)({scale, std::abs(i.first), std::abs(i.second)}));
      }
  return w;
}

// An enclosure in IT of an exact number: CORE's own double interval, or for a multi-precision
// IT an interval at IT's default precision p around a rational approximation c (relative
// precision p + 8), on the side of c where the exact sign of x - c puts x, checked exactly.
template <class IT>
IT enclose_exact(const CORE::Expr& x)
{
  if constexpr (is_interval_nt<IT>::value) return IT(CGAL::to_interval(x));
  else {
    const long bits = long(IT::get_default_precision());
    const CGAL::Gmpq c(x.approx(bits + 8, CORE::extLong::getPosInfty()).BigRatValue().get_mp());
    const CORE::Expr cx(CORE::BigRat(c.mpq()));
    const CGAL::Sign side = CGAL::sign(x - cx);
    if (side == CGAL::ZERO) return IT(c);
    CGAL::Gmpq d = CGAL::abs(c);
    for (long k = 0; k < bits; ++k) d /= 2;
    if (CGAL::is_zero(d)) return IT(CGAL::to_interval(x));  // (not reached: c is 0 only where x is)
    typename CGAL::Interval_traits<IT>::Hull hull;
    while (true) {
      const CGAL::Gmpq far = side == CGAL::POSITIVE ? c + d : c - d;
      if (CGAL::sign(CORE::Expr(CORE::BigRat(far.mpq())) - x) == (side == CGAL::POSITIVE ? CGAL::POSITIVE : CGAL::NEGATIVE))
        return hull(IT(c), IT(far));
      d *= 2;
    }
  }
}

// An enclosure in IT with e's flags and no coordinates yet.
template <class IT, class W>
Body_enclosure<IT> with_flags_of(const Body_enclosure<W>& e)
{
  Body_enclosure<IT> f;
  f.consistent = e.consistent;
  f.variant = e.variant;
  f.in_given_frame = e.in_given_frame;
  f.singular = e.singular;
  f.singular_reason = e.singular_reason;
  f.undecided = e.undecided;
  return f;
}

// Exact placements, enclosed in IT, in Cartesian coordinates: those in the basis of a
// canonical frame are put in the canonical frame (A at 0, B on +x, C in the xy plane,
// y > 0): E = [[l, uv / l, 0], [0, sqrt(G) / l, 0], [0, 0, sqrt(G)]], l = sqrt(uu), in IT.
template <class IT>
std::vector<Body_enclosure<IT>> convert_exact_enclosures(const std::vector<Body_enclosure<CORE::Expr>>& all,
                                                         const std::vector<Placement_frame<CORE::Expr>>& frames)
{
  std::vector<Body_enclosure<IT>> out;
  for (std::size_t k = 0; k < all.size(); ++k) {
    const auto& e = all[k];
    const auto& fr = frames[k];
    Body_enclosure<IT> f;
    f = with_flags_of<IT>(e);
    for (const auto& x : e.coordinates) {
      std::array<IT, 3> y{{enclose_exact<IT>(x[0]), enclose_exact<IT>(x[1]), enclose_exact<IT>(x[2])}};
      if (!fr.cartesian) {
        const IT uu = enclose_exact<IT>(fr.uu), uv = enclose_exact<IT>(fr.uv), G = enclose_exact<IT>(fr.G);
        Rounding_guard<IT> guard;  // (CORE itself computes in the FPU's default rounding)
        const IT l = CGAL::sqrt(uu), g = CGAL::sqrt(G);
        y = {l * y[0] + uv / l * y[1], g / l * y[1], g * y[2]};
      }
      f.coordinates.push_back(y);
    }
    out.push_back(std::move(f));
  }
  return out;
}

template <class IT, class W>
std::vector<Body_enclosure<IT>> convert_enclosures(std::vector<Body_enclosure<W>>&& all)
{
  if constexpr (std::is_same<IT, W>::value) return std::move(all);
  else {
    std::vector<Body_enclosure<IT>> out;
    for (const auto& e : all) {
      Body_enclosure<IT> f;
      f = with_flags_of<IT>(e);
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
  // a rational exactly, in base 32 (linear time: the decimal form was a fifth of a 13-body
  // tree's solve, the key being made again for each placement combination)
  std::string digits;
  auto exact = [&](const CGAL::Gmpq& q) {
    for (mpz_srcptr z : {mpq_numref(q.mpq()), mpq_denref(q.mpq())}) {
      digits.resize(mpz_sizeinbase(z, 32) + 2);
      mpz_get_str(&digits[0], 32, z);
      os << digits.c_str() << (z == mpq_numref(q.mpq()) ? '/' : ' ');
    }
  };
  field(b.name);
  for (std::size_t i = 0; i < b.points.size(); ++i) {
    field(c.label(b.points[i]));
    if (b.has_coordinates[i]) {
      os << '(';
      exact(exact_rational(Traits::x(b.coordinates[i])));
      exact(exact_rational(Traits::y(b.coordinates[i])));
      exact(exact_rational(Traits::z(b.coordinates[i])));
      os << ')';
    }
    os << '\n';
  }
  for (const auto& d : b.squared_distances) {
    os << d.a << '-' << d.b << ' ';
    exact(exact_rational(d.squared));
    os << '\n';
  }
  for (const auto& o : b.orientations) os << o.a << ' ' << o.b << ' ' << o.c << ' ' << o.d << ' ' << int(o.sign) << '\n';
  for (const auto& g : b.rigid_groups) {
    os << "rigid";
    for (std::size_t q : g) field(c.label(q));
    os << '\n';
  }
  // the planner's rigid groups from the collection's other bodies (their points with coordinates)
  for (const auto& o : c.bodies()) {
    std::size_t k = 0;
    for (std::size_t i = 0; i < o.points.size(); ++i) k += o.has_coordinates[i] && b.contains(o.points[i]);
    if (k < 3 || &o == &b) continue;
    os << "held";
    for (std::size_t i = 0; i < o.points.size(); ++i) if (o.has_coordinates[i] && b.contains(o.points[i])) field(c.label(o.points[i]));
    os << '\n';
  }
  for (const auto& part : b.parts) field(placement_key(c, part));
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
  /// nonempty: a choice that only intervals can decide (a point placed through a rigid part
  /// or from references whose distances are not known exactly) was not decided at the
  /// final precision, and where: such a placement is kept enclosing both sides (`undecided`),
  /// or, where three shared points are not certainly off a line, left out. The answer of a
  /// solve that uses this body is then not complete.
  std::string undecided;
  /// the choices intervals left open were made in exact arithmetic (`CORE::Expr`, real
  /// algebraic numbers): every placement is decided, its coordinates enclosed from their exact
  /// values (see `enumerate_placements()`)
  bool decided_exactly = false;
};

/// \ingroup PkgRigidIncidenceRef
/// The precision, in bits, from which a choice the intervals still leave open (a height not
/// separated from 0, two placements not separated) is made in exact arithmetic instead: a
/// value not separated from 0 at this precision is most likely 0 exactly, which no precision
/// separates.
constexpr unsigned exact_decision_precision = 256;

/// \ingroup PkgRigidIncidenceRef
/// The most square roots a body's exact coordinates may involve (a bound from its placement
/// plan: one per point trilaterated with a nonzero height, its rigid parts' included) for the
/// choices intervals leave open to be made exactly: an exact sign that is 0 costs a root bound
/// of degree up to 2^n (11 ran for minutes). Above it the choices stay undecided and the answer
/// is not complete.
constexpr std::size_t maximal_exact_square_roots = 6;

/// \ingroup PkgRigidIncidenceRef
/// The longest the exact decisions of one body's placements may take, in seconds: the cost of
/// an exact sign that is 0 grows with the size of the rationals as well as with the tower (a
/// body of 6 square roots over 100-digit rationals ran for over 20 minutes). Past it the
/// choices stay undecided, as above, and the answer is not complete. (Wall-clock time: on a
/// slower machine fewer bodies are decided.)
constexpr double maximal_exact_seconds = 10;

/// \ingroup PkgRigidIncidenceRef
/// The default limit on the placements of one body (2^14): a body with more is enumerated
/// up to it and reported incomplete.
constexpr std::size_t default_maximal_placements = std::size_t(1) << 14;

/// \ingroup PkgRigidIncidenceRef
/// The highest precision, in bits, the placement enumeration raises its arithmetic to.
constexpr unsigned maximal_placement_precision = 4096;

namespace internal {

// The exact pass of cached_placements(): the choices intervals leave open made in CORE::Expr,
// the placements enclosed in IT.
template <class IT>
struct Exact_placements
{
  bool done = false;  // false: stopped at the time limit, or failed (then `why` says how)
  bool cut = false;   // stopped by the solve's interrupt or time limit (not to be cached)
  std::string why;
  std::vector<Body_enclosure<IT>> placements;
  bool truncated = false;
  std::string undecided;  // what exact arithmetic leaves undecided
};

template <class IT>
Exact_placements<IT> exact_placements_here(const Placement_plan& plan, std::size_t max_placements, double seconds)
{
  // CORE computes in the FPU's default rounding, whatever the caller's
  CGAL::Protect_FPU_rounding<true> nearest(CGAL_FE_TONEAREST);
  Placement_enumerator<CORE::Expr> e(plan, max_placements);
  e.set_deadline(std::chrono::steady_clock::now() +
                 std::chrono::duration_cast<std::chrono::steady_clock::duration>(std::chrono::duration<double>(seconds)));
  auto all = e.run();
  Exact_placements<IT> x;
  if (e.stopped()) return x;
  x.done = true;
  x.truncated = e.truncated();
  x.undecided = e.undecided();
  x.placements = convert_exact_enclosures<IT>(all, e.frames());
  return x;
}

template <class IT>
std::string write_exact_placements(const Exact_placements<IT>& x)
{
  Answer_writer w;
  w.integer(x.done); w.integer(x.truncated); w.text(x.undecided);
  w.integer((long long)x.placements.size());
  for (const auto& e : x.placements) {
    w.integer(e.consistent); w.integer(e.variant); w.integer(e.in_given_frame); w.integer(e.singular); w.integer(e.undecided);
    w.text(e.singular_reason);
    w.integer((long long)e.coordinates.size());
    for (const auto& p : e.coordinates) for (const IT& c : p) w.number(c);
  }
  return w.str();
}

template <class IT>
Exact_placements<IT> read_exact_placements(const std::string& s)
{
  Answer_reader r(s);
  Exact_placements<IT> x;
  x.done = r.integer() != 0; x.truncated = r.integer() != 0; x.undecided = r.text();
  const long long n = r.integer();
  for (long long k = 0; k < n; ++k) {
    Body_enclosure<IT> e;
    e.consistent = r.integer() != 0; e.variant = int(r.integer()); e.in_given_frame = r.integer() != 0;
    e.singular = r.integer() != 0; e.undecided = r.integer() != 0;
    e.singular_reason = r.text();
    const long long m = r.integer();
    for (long long q = 0; q < m; ++q) {
      std::array<IT, 3> p;
      for (IT& c : p) r.number(c);
      e.coordinates.push_back(p);
    }
    x.placements.push_back(std::move(e));
  }
  if (!r.at_end()) throw std::runtime_error("a broken answer from the process of the exact decisions");
  return x;
}

// The exact pass, bounded by `seconds` however long one exact sign takes: run in a child
// process killed at the limit (CORE checks no clock inside a sign, and a sign that is 0 in a
// deep tower ran for over 20 minutes); where there is no fork(), here, stopped between steps.
template <class IT>
Exact_placements<IT> exact_placements(const Placement_plan& plan, std::size_t max_placements, double seconds)
{
  const Child_run c = run_in_child([&] { return write_exact_placements(exact_placements_here<IT>(plan, max_placements, seconds)); },
                                   seconds);
  if (c.status == Child_run::NOT_STARTED) return exact_placements_here<IT>(plan, max_placements, seconds);
  Exact_placements<IT> x;
  if (c.status == Child_run::DONE) {
    try { return read_exact_placements<IT>(c.answer); }
    catch (const std::exception& e) { x.why = std::string("the exact decisions failed: ") + e.what(); }
  } else if (c.status == Child_run::FAILED) x.why = "the exact decisions failed: " + c.why;
  else if (c.status == Child_run::STOPPED) {
    x.cut = true;
    x.why = "the exact decisions were cut by the solve's interrupt or time limit";
  }
  return x;  // TIMED_OUT: not done, no `why` (the caller says the limit)
}

// The enumeration of enumerate_placements(), shared through a cache of the last 32.
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
  // one cache for every thread (the parallel solves build systems of one scene on several):
  // looked up and filled under its lock, an enumeration computed outside it (two threads may
  // both compute one; the first stored is kept, and they are equal)
  static std::mutex cache_mutex;
  static std::deque<std::pair<std::string, std::shared_ptr<const Placement_enumeration<IT>>>> cache;
  {
    std::lock_guard<std::mutex> lock(cache_mutex);
    for (const auto& e : cache) if (e.first == key) return e.second;
  }

  Placement_plan plan = Placement_planner<Traits>(c, b).run();
  auto out = std::make_shared<Placement_enumeration<IT>>();
  bool cacheable = true;
  out->inconsistent = plan.inconsistent;
  out->singular = plan.singular;
  if (plan.inconsistent.empty()) {
    const double target = is_interval_nt<IT>::value ? std::ldexp(1.0, -44) : std::ldexp(1.0, 12 - int(start));
    bool done = false;
    const std::size_t roots = square_roots(plan);
    const bool exact_possible = plan.slack == 0 && roots <= maximal_exact_square_roots;
    if constexpr (is_interval_nt<IT>::value) {
      typename CGAL::Interval_nt<false>::Protector protect;
      Placement_enumerator<CGAL::Interval_nt<false>> e(plan, max_placements);
      auto all = e.run();
      out->relative_width = relative_width(all, plan.scale);
      out->complete = !e.truncated();
      out->precision = 53;
      out->undecided = e.undecided();
      out->placements = convert_enclosures<IT>(std::move(all));
      done = out->relative_width <= target && out->undecided.empty();
    }
#ifdef CGAL_USE_MPFI
    for (unsigned bits = is_interval_nt<IT>::value ? 128 : start; !done; bits *= 2) {
      Solver_precision_guard<CGAL::Gmpfi> guard(bits);
      Placement_enumerator<CGAL::Gmpfi> e(plan, max_placements);
      auto all = e.run();
      out->relative_width = relative_width(all, plan.scale);
      out->complete = !e.truncated();
      out->precision = bits;
      out->undecided = e.undecided();
      out->placements = convert_enclosures<IT>(std::move(all));
      done = (out->relative_width <= target && out->undecided.empty()) ||
             2 * bits > (std::max)(maximal_placement_precision, 4 * start) ||
             (!out->undecided.empty() && exact_possible && bits >= exact_decision_precision);
    }
#endif
    (void)done;
    if (!out->undecided.empty() && plan.slack == 0 && roots > maximal_exact_square_roots)
      out->undecided += "; not decided exactly either: its coordinates may lie in a tower of " + std::to_string(roots) +
                        " square roots, more than the limit of exact decisions (maximal_exact_square_roots = " +
                        std::to_string(maximal_exact_square_roots) + ")";
    else if (!out->undecided.empty() && plan.slack == 0) {
      // exact input: the open choices are made exactly (a height exactly 0 is a double placement)
      Exact_placements<IT> x = exact_placements<IT>(plan, max_placements, maximal_exact_seconds);
      cacheable = !x.cut;
      if (!x.done) {
        // the answer of the last interval pass stands, undecided, and says why
        out->undecided += "; not decided exactly either: " +
                          (x.why.empty() ? "the exact decisions (a tower of up to " + std::to_string(roots) +
                                               " square roots) were stopped after " + std::to_string(int(maximal_exact_seconds)) +
                                               " s (maximal_exact_seconds)"
                                         : x.why);
      } else {
        out->complete = !x.truncated;
        out->undecided = x.undecided;  // only what exact arithmetic leaves: three points exactly on a line
        out->placements = std::move(x.placements);
        out->relative_width = relative_width(out->placements, plan.scale);
        out->decided_exactly = true;
        if (!out->undecided.empty()) out->undecided = "in exact arithmetic, " + out->undecided;
      }
    }
    // every side of some point certainly excluded by a further distance or an orientation:
    // no real placement either (interval exclusion is rigorous)
    if (!out->undecided.empty() && !out->decided_exactly)
      out->undecided = "at " + std::to_string(out->precision) + " bits, " + out->undecided;
    if (out->complete && out->placements.empty() && out->undecided.empty())
      out->inconsistent = "body '" + b.name + "': no placement fits all its distances and orientations (each side of a"
                          " trilaterated point is excluded by a further distance or an orientation, " +
                          (out->decided_exactly ? std::string("exactly") : "in intervals at " + std::to_string(out->precision) + " bits") + ")";
  }
  if (!cacheable) return out;  // (a later solve decides it again)
  std::lock_guard<std::mutex> lock(cache_mutex);
  for (const auto& e : cache) if (e.first == key) return e.second;
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

A body with rigid parts (`Rigid_body_collection::Body::parts`, made by `standardize()` where
shared points' distances run through placements) is placed with two more kinds of steps,
where no exact trilateration is left: a part with three placed points is superposed on them
once per placement of its own (enumerated the same way, recursively), which places its other
points or, with nothing left to place, checks them; and a point at known distances from
three placed points whose own distances are not known exactly is trilaterated in intervals.
Those decisions (a height's sign, three points off a line) are made in intervals, raised in
precision like the widths; with exact input, those still open at `exact_decision_precision`
are made exactly, in `CORE::Expr` (`decided_exactly`), for a body whose exact coordinates
involve at most `maximal_exact_square_roots` square roots. One still open then is reported in
`undecided` (the placement kept enclosing both sides, or left out), never dropped silently.
A body with coordinates that cannot start its placement is placed in a canonical frame and
moved onto its coordinates. With rounded input (a kernel of doubles) a placed point meets a
coordinate or a distance within 1e-9 of the body's size.

The enumerations are cached per thread by the body's content, so that asking for one
placement after another costs one enumeration.

\tparam IT `CGAL::Interval_nt<false>` (double intervals), or `CGAL::Gmpfi`
\param c the collection (typically the output of `standardize()`)
\param body the index of the body in `c`
\param max_placements stop after this many placements (then `complete` is false)
\throws Input_error if the body's distances and rigid parts do not let its points be placed
one after the other.
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
other, if it has more than `max_placements` placements, or if some were left undecided
(`Placement_enumeration::undecided`): never a silently shortened list.
*/
template <class IT, class Traits>
std::vector<Body_enclosure<IT>> enclose_all_placements(const Rigid_body_collection<Traits>& c, std::size_t body,
                                                       std::size_t max_placements = default_maximal_placements)
{
  auto e = internal::cached_placements<IT>(c, body, max_placements);
  if (!e->complete)
    throw Input_error("body '" + c.body(body).name + "' has more than " + std::to_string(max_placements) + " placements");
  if (!e->undecided.empty())
    throw Input_error("the placements of body '" + c.body(body).name + "' are not all decided: " + e->undecided);
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
