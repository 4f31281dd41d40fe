// Copyright (c) 2026 Rigid_incidence contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Standardization of a collection (optimized_incidence_tree_parametrization.txt, Section 3,
// Definitions 1-3; well_formed_optimal_incidences.txt, Definition 1): merge bodies sharing
// three or more non-collinear points, add implied rigid bodies (maximal cliques of fixed
// distances), absorb bodies and distances that are not proper-maximal.

#ifndef CGAL_RIGID_INCIDENCE_STANDARDIZE_H
#define CGAL_RIGID_INCIDENCE_STANDARDIZE_H

#include <CGAL/Rigid_incidence/Rigid_body_collection.h>
#include <CGAL/Rigid_incidence/enclose_coordinates.h>
#include <CGAL/Rigid_incidence/internal/cayley_menger.h>

#include <boost/graph/adjacency_list.hpp>
#include <boost/graph/bron_kerbosch_all_cliques.hpp>

#include <algorithm>
#include <array>
#include <deque>
#include <optional>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace CGAL {
namespace Rigid_incidence {
namespace internal {

template <class Collection>
std::string labels_of(const Collection& c, const std::vector<std::size_t>& pts, const char* sep = ", ")
{
  std::string s;
  for (std::size_t i = 0; i < pts.size(); ++i) s += (i ? sep : "") + ("'" + c.label(pts[i]) + "'");
  return s;
}

// The squared distance between global points p and q as the body knows it (nullopt if unknown).
template <class Body>
auto body_squared(const Body& b, std::size_t p, std::size_t q)
{
  return b.squared(b.local(p), b.local(q));
}

// Bron-Kerbosch visitor: records each maximal clique as sorted global point indices.
struct Clique_collector
{
  std::vector<std::vector<std::size_t>>* out;
  const std::vector<std::size_t>* ids;
  template <class Clique, class G> void clique(const Clique& c, const G&)
  {
    std::vector<std::size_t> k;
    for (auto v : c) k.push_back((*ids)[v]);
    std::sort(k.begin(), k.end());
    out->push_back(k);
  }
};

template <class Traits>
class Standardizer
{
  typedef Rigid_body_collection<Traits> Collection;
  typedef typename Collection::Body Body;
  typedef typename Collection::Distance Distance;
  typedef typename Collection::Squared_distance Squared_distance;
  typedef typename Collection::Orientation Orientation;
  typedef typename Traits::FT FT;
  typedef typename Traits::Point_3 Point_3;

public:
  Standardizer(const Collection& in, std::vector<std::string>* log)
    : c_(in), log_(log), frame_name_(in.frame()), frame_explicit_(in.frame_is_explicit()), frame_holder_(in.frame()) {}

  Collection run()
  {
    turn_collinear_bodies_into_bars();
    check_shared_pairs();
    std::size_t guard = 0, limit = 8 * (c_.number_of_bodies() + c_.distances().size()) + 16;
    bool changed = true;
    while (changed) {
      if (++guard > limit) throw Input_error("standardize: no fixpoint reached (internal error)");
      changed = absorb_distances();
      changed = absorb_bodies() || changed;
      if (changed) continue;
      // before the merges and implied bodies: a point held by two touching spheres becomes
      // a point of the body with the line, exactly, and its other distances then lie in
      // that body, or in the bodies that take it in later (checks on their placements);
      // left to implied bodies it would make their placements double ones, which only a
      // tower of square roots decides
      changed = attach_points_on_lines();
      if (changed) continue;
      changed = merge_one_pair();
      if (changed) continue;
      changed = add_implied_bodies();
    }
    check_shared_pairs();
    // The frame passes to the body that absorbed or merged the frame body; that body keeps
    // the frame body's coordinates (see merge_one_pair and absorb_bodies).
    if (frame_holder_ != frame_name_ && c_.body_index(frame_holder_) != Collection::npos) {
      note("the scene's frame '" + frame_name_ + "' is now body '" + frame_holder_ + "', in the same coordinates");
      c_.set_frame(frame_holder_);
    }
    // (the holder always has coordinates, so primary_first() keeps it primary in every combination)
    return c_;
  }

private:
  Collection c_;
  std::vector<std::string>* log_;
  std::string frame_name_; // the user body whose local frame results are reported in
  bool frame_explicit_;
  std::string frame_holder_; // the body whose coordinates are those of the frame body
  std::set<std::size_t> attached_; // points attach_points_on_lines() put into a body
  std::size_t implied_count_ = 0, merged_count_ = 0;
  std::set<std::vector<std::size_t>> collinear_noted_;  // cliques on one line, noted once
  std::set<std::pair<std::size_t, std::string>> axis_noted_;  // points left out of implied bodies, noted once

  void note(const std::string& s) { if (log_) log_->push_back(s); }

  static void add_source(Body& b, const std::string& s)
  {
    if (std::find(b.sources.begin(), b.sources.end(), s) == b.sources.end()) b.sources.push_back(s);
  }

  // A body of two points is a bar: it fixes one distance (5 dof, not 6) and enters as that
  // distance. Three or more collinear points make a degenerate body that the papers' tree
  // parametrization does not cover: rejected with a clear message.
  void turn_collinear_bodies_into_bars()
  {
    auto& bodies = c_.mutable_bodies();
    std::vector<Body> kept, bars;
    for (const Body& b : bodies) {
      bool collinear = true;
      for (std::size_t i = 2; i < b.points.size() && collinear; ++i)
        collinear = Traits::collinear(b.coordinates[0], b.coordinates[1], b.coordinates[i]);
      if (!collinear) { kept.push_back(b); continue; }
      if (b.points.size() > 2)
        throw Input_error("body '" + b.name + "': its " + std::to_string(b.points.size()) +
                          " points are collinear; a collinear rigid body (5 dof) is not supported: give its two end points"
                          " as a distance, or add a point off the line");
      if (b.name == frame_name_ && frame_explicit_)
        throw Input_error("body '" + b.name + "' is the scene's frame but has only 2 points: a bar has no frame of its"
                          " own; name another body as \"frame\"");
      bars.push_back(b);
    }
    bodies = kept;
    if (bodies.empty())
      throw Input_error("the scene has no rigid body of 3 or more non-collinear points (only bars): nothing to assemble");
    if (!frame_explicit_ && c_.body_index(frame_name_) == Collection::npos) {
      frame_name_ = frame_holder_ = bodies.front().name; // the default frame: the first body that is not a bar
      c_.set_frame(frame_name_);
    }
    for (const Body& b : bars) {
      note("body '" + b.name + "' has 2 points: it is a bar and enters as their distance");
      c_.add_distance(c_.label(b.points[0]), c_.label(b.points[1]), Traits::squared_distance(b.coordinates[0], b.coordinates[1]),
                      "body '" + b.name + "' (a bar)");
    }
  }

  // Two bodies sharing two or more points must agree on their distances (a shared pair seen
  // with two lengths has no configuration).
  void check_shared_pairs() const
  {
    const auto& bodies = c_.bodies();
    for (std::size_t i = 0; i < bodies.size(); ++i)
      for (std::size_t j = i + 1; j < bodies.size(); ++j) {
        std::vector<std::size_t> common = c_.common_points(i, j);
        if (common.size() >= 2) check_agreement(bodies[i], bodies[j], common);
      }
  }

  bool absorb_distances()
  {
    auto& ds = c_.mutable_distances();
    auto& bodies = c_.mutable_bodies();
    bool changed = false;
    for (std::size_t k = 0; k < ds.size();) {
      const Distance& d = ds[k];
      std::size_t host = Collection::npos;
      for (std::size_t i = 0; i < bodies.size(); ++i)
        if (bodies[i].contains(d.a) && bodies[i].contains(d.b)) {
          auto known = body_squared(bodies[i], d.a, d.b);
          if (known) {
            if (!c_.same_value(*known, d.squared)) {
              const std::string why = d.name + ": disagrees with body '" + bodies[i].name + "', which fixes the distance of '" +
                                      c_.label(d.a) + "' and '" + c_.label(d.b) + "' to squared " + to_text(*known) + ", not " +
                                      to_text(d.squared);
              // a point the body took in from two touching spheres: the scene's own distances
              // disagree (decided exactly), not a number written twice
              for (std::size_t q : {d.a, d.b})
                if (attached_.count(q))
                  throw No_real_configuration(why + " ('" + c_.label(q) + "' is there because two of its distances' spheres touch"
                                              " on a line of that body): no real configuration");
              throw Input_error(why);
            }
            if (host == Collection::npos) host = i;
          }
        }
      if (host == Collection::npos) {
        // inside bodies that do not know it (two points placed through different distances of
        // a merged body): it holds in every configuration, so it is one of their distances,
        // which their placements must meet (enumerate_placements() checks it, or places by
        // it), not an equation of the reduced system: there it would count twice, against a
        // body that is rigid already (a point's distances to a body it was attached to, to
        // points that the body took in later)
        std::vector<std::size_t> inside;
        for (std::size_t i = 0; i < bodies.size(); ++i)
          if (bodies[i].contains(d.a) && bodies[i].contains(d.b)) inside.push_back(i);
        if (inside.empty()) { ++k; continue; }
        for (std::size_t i : inside) {
          Body& b = bodies[i];
          b.squared_distances.push_back({b.local(d.a), b.local(d.b), d.squared});
          b.mirror_variants = 0;  // (placements enumerated, each checked against it)
          note(d.name + " lies inside body '" + b.name + "', which does not know it exactly: it becomes one of its"
                        " distances, a check on its placements");
          add_source(b, d.name);
        }
        ds.erase(ds.begin() + k);
        changed = true;
        continue;
      }
      note(d.name + " lies inside body '" + bodies[host].name + "' and is absorbed");
      add_source(bodies[host], d.name);
      ds.erase(ds.begin() + k);
      changed = true;
    }
    return changed;
  }

  // A point W held by two distances to points A and V of a body with coordinates whose
  // spheres touch (|AW| + |WV| = |AV|, or one of them the sum of the others, decided exactly:
  // a degenerate triangle) has one place, W = A + t (V - A) with t = (|AW|^2 + |AV|^2 -
  // |WV|^2) / 2|AV|^2, rational: it becomes a point of that body, and the two distances are
  // absorbed. Left as equations the two touching spheres would make every root a double one
  // of the reduced system, which intervals cannot certify (a rail point: a scene of 8 bodies
  // ran for 20 minutes). The root is double in those two equations as well (perturbed, the
  // spheres part or cut a circle): a configuration is singular, and says why, unless the
  // scene's other equations hold W (solve_scene() measures the Jacobian).
  bool attach_points_on_lines()
  {
    // (only with an exact kernel: a tolerance would pin a point that spheres cutting a small
    // circle leave free, or that spheres just missing each other leave nowhere)
    if (!Traits::has_exact_ft) return false;
    auto& ds = c_.mutable_distances();
    auto& bodies = c_.mutable_bodies();
    for (std::size_t i = 0; i < ds.size(); ++i)
      for (std::size_t j = i + 1; j < ds.size(); ++j) {
        const Distance &d1 = ds[i], &d2 = ds[j];
        std::size_t W = Collection::npos;
        for (std::size_t a : {d1.a, d1.b})
          if (a == d2.a || a == d2.b) W = a;
        if (W == Collection::npos) continue;
        const std::size_t A = d1.a == W ? d1.b : d1.a, V = d2.a == W ? d2.b : d2.a;
        if (A == V) continue;
        for (Body& b : bodies) {
          if (!b.all_coordinates() || b.contains(W) || !b.contains(A) || !b.contains(V)) continue;
          const Point_3 &PA = b.coordinates[b.local(A)], &PV = b.coordinates[b.local(V)];
          const FT av = Traits::squared_distance(PA, PV);
          if (triangle_sign<Traits::has_exact_ft>(d1.squared, d2.squared, av) != CGAL::ZERO) continue;
          const FT t = (d1.squared + av - d2.squared) / (FT(2) * av);
          const Point_3 PW = Traits::point(Traits::x(PA) + t * (Traits::x(PV) - Traits::x(PA)), Traits::y(PA) + t * (Traits::y(PV) - Traits::y(PA)),
                                           Traits::z(PA) + t * (Traits::z(PV) - Traits::z(PA)));
          const std::size_t at = std::size_t(std::lower_bound(b.points.begin(), b.points.end(), W) - b.points.begin());
          b.points.insert(b.points.begin() + std::ptrdiff_t(at), W);
          b.has_coordinates.insert(b.has_coordinates.begin() + std::ptrdiff_t(at), true);
          b.coordinates.insert(b.coordinates.begin() + std::ptrdiff_t(at), PW);
          for (auto& e : b.squared_distances) { if (e.a >= at) ++e.a; if (e.b >= at) ++e.b; }
          for (auto& o : b.orientations)
            for (std::size_t* q : {&o.a, &o.b, &o.c, &o.d}) if (*q >= at) ++*q;
          const std::string why = "'" + c_.label(W) + "' is held by " + d1.name + " and " + d2.name + " on the line of '" + c_.label(A) +
                                  "' and '" + c_.label(V) + "' of body '" + b.name + "', where the two spheres touch (a double point of"
                                  " those two equations, decided exactly)";
          note(why + ": it becomes a point of that body, at " + c_.label(A) + " + " + to_text(t) + " (" + c_.label(V) + " - " +
               c_.label(A) + "); a configuration is singular unless the scene's other equations hold it");
          c_.add_singular_note(why);
          attached_.insert(W);
          return true;  // (absorb_distances() takes the two distances into the body, checked)
        }
      }
    return false;
  }

  static std::string to_text(const FT& x)
  {
    std::ostringstream os; os.precision(17); os << x; return os.str();
  }

  bool absorb_bodies()
  {
    auto& bodies = c_.mutable_bodies();
    for (std::size_t i = 0; i < bodies.size(); ++i)
      for (std::size_t j = 0; j < bodies.size(); ++j) {
        if (i == j) continue;
        const Body& small = bodies[i];
        const Body& big = bodies[j];
        if (!std::includes(big.points.begin(), big.points.end(), small.points.begin(), small.points.end())) continue;
        if (small.points.size() == big.points.size() && i < j) continue; // absorb the later of two equal sets
        check_agreement(small, big, small.points);
        note("body '" + small.name + "' lies inside body '" + big.name + "' and is absorbed");
        const bool big_first = primary_first(big, small);
        const bool frame_kept = holds_frame(big_first ? big : small);
        Body host = big_first ? combine(big, small) : combine(small, big);
        host.name = big.name;
        host.origin = big.origin;
        if (frame_kept) frame_holder_ = host.name;
        bodies[j] = host;
        bodies.erase(bodies.begin() + i);
        return true;
      }
    return false;
  }

  // Which of two bodies to combine keeps its frame: the one holding the scene's frame if it
  // has coordinates, else the one with more points with coordinates (ties: the first).
  bool primary_first(const Body& a, const Body& b) const
  {
    auto count = [](const Body& x) { return std::count(x.has_coordinates.begin(), x.has_coordinates.end(), true); };
    if (holds_frame(a) && count(a) > 0) return true;
    if (holds_frame(b) && count(b) > 0) return false;
    return count(a) >= count(b);
  }

  // Four points with coordinates of `b` spanning space (local indices), if any.
  static std::optional<std::array<std::size_t, 4>> spanning_quadruple(const Body& b)
  {
    std::vector<std::size_t> idx;
    for (std::size_t k = 0; k < b.points.size(); ++k) if (b.has_coordinates[k]) idx.push_back(k);
    if (idx.size() < 4) return std::nullopt;
    std::size_t a = idx[0], bb = idx[1];
    for (std::size_t c : idx) {
      if (c == a || c == bb || Traits::collinear(b.coordinates[a], b.coordinates[bb], b.coordinates[c])) continue;
      for (std::size_t d : idx) {
        if (d == a || d == bb || d == c) continue;
        if (orientation_sign(b.coordinates[a], b.coordinates[bb], b.coordinates[c], b.coordinates[d]) != CGAL::ZERO)
          return std::array<std::size_t, 4>{a, bb, c, d};
      }
      return std::nullopt; // all coplanar with a, bb, c
    }
    return std::nullopt;
  }

  static CGAL::Sign orientation_sign(const Point_3& a, const Point_3& b, const Point_3& c, const Point_3& d)
  {
    FT u[3] = {Traits::x(b) - Traits::x(a), Traits::y(b) - Traits::y(a), Traits::z(b) - Traits::z(a)};
    FT v[3] = {Traits::x(c) - Traits::x(a), Traits::y(c) - Traits::y(a), Traits::z(c) - Traits::z(a)};
    FT w[3] = {Traits::x(d) - Traits::x(a), Traits::y(d) - Traits::y(a), Traits::z(d) - Traits::z(a)};
    return CGAL::sign(u[0] * (v[1] * w[2] - v[2] * w[1]) - u[1] * (v[0] * w[2] - v[2] * w[0]) + u[2] * (v[0] * w[1] - v[1] * w[0]));
  }

  // The union of two bodies, in the frame of P. The points of O with coordinates join P's
  // frame when three non-collinear points have coordinates in both (a rational rigid map);
  // otherwise they enter as their pairwise distances plus the orientation of four of them
  // (so that no user body can come back mirrored). Every distance either body knows is kept.
  // With `o_as_part`, O is kept whole as a rigid part of the union: its points are placed
  // by superposing it on three shared points (whose distances are not all known exactly).
  Body combine(const Body& P, const Body& O, bool o_as_part = false) const
  {
    Body m;
    m.name = P.name;
    m.origin = P.origin;
    m.sources = P.sources;
    for (const auto& src : O.sources) add_source(m, src);
    std::set_union(P.points.begin(), P.points.end(), O.points.begin(), O.points.end(), std::back_inserter(m.points));
    m.has_coordinates.assign(m.points.size(), false);
    m.coordinates.assign(m.points.size(), Point_3(0, 0, 0));
    for (std::size_t k = 0; k < P.points.size(); ++k)
      if (P.has_coordinates[k]) {
        std::size_t h = m.local(P.points[k]);
        m.has_coordinates[h] = true;
        m.coordinates[h] = P.coordinates[k];
      }
    // points with coordinates on both sides
    std::vector<std::size_t> both;
    for (std::size_t k = 0; k < O.points.size(); ++k)
      if (O.has_coordinates[k] && P.contains(O.points[k]) && P.has_coordinates[P.local(O.points[k])]) both.push_back(O.points[k]);
    std::optional<std::array<std::size_t, 3>> base;
    for (std::size_t a = 0; a < both.size() && !base; ++a)
      for (std::size_t b = a + 1; b < both.size() && !base; ++b)
        for (std::size_t c = b + 1; c < both.size() && !base; ++c)
          if (!Traits::collinear(P.coordinates[P.local(both[a])], P.coordinates[P.local(both[b])], P.coordinates[P.local(both[c])]))
            base = std::array<std::size_t, 3>{a, b, c};
    bool mapped = false;
    if (base) {
      std::vector<std::optional<Point_3>> images = map_into(P, O, both, *base);
      for (std::size_t k = 0; k < O.points.size(); ++k)
        if (images[k]) {
          std::size_t h = m.local(O.points[k]);
          if (!m.has_coordinates[h]) { m.has_coordinates[h] = true; m.coordinates[h] = *images[k]; }
        }
      mapped = true;
    }
    auto add_distance = [&](std::size_t gu, std::size_t gv, const FT& d) {
      std::size_t mu = m.local(gu), mv = m.local(gv);
      if (m.has_coordinates[mu] && m.has_coordinates[mv]) {
        FT known = Traits::squared_distance(m.coordinates[mu], m.coordinates[mv]);
        if (!c_.same_value(known, d))
          throw Input_error("bodies '" + P.name + "' and '" + O.name + "' disagree on the distance of '" + c_.label(gu) +
                            "' and '" + c_.label(gv) + "' (squared " + to_text(known) + " vs " + to_text(d) + ")");
        return;
      }
      for (const auto& s : m.squared_distances)
        if ((s.a == mu && s.b == mv) || (s.a == mv && s.b == mu)) {
          if (!c_.same_value(s.squared, d))
            throw Input_error("bodies '" + P.name + "' and '" + O.name + "' disagree on the distance of '" + c_.label(gu) +
                              "' and '" + c_.label(gv) + "' (squared " + to_text(s.squared) + " vs " + to_text(d) + ")");
          return;
        }
      m.squared_distances.push_back(Squared_distance{mu, mv, d});
    };
    for (const Body* b : {&P, &O})
      for (std::size_t u = 0; u < b->points.size(); ++u)
        for (std::size_t v = u + 1; v < b->points.size(); ++v) {
          auto d = b->squared(u, v);
          if (d) add_distance(b->points[u], b->points[v], *d);
        }
    for (const Body* b : {&P, &O})
      for (const auto& o : b->orientations)
        m.orientations.push_back(Orientation{m.local(b->points[o.a]), m.local(b->points[o.b]), m.local(b->points[o.c]),
                                             m.local(b->points[o.d]), o.sign});
    // the sets each side holds rigidly; O's points with coordinates too, when they enter as distances
    for (const Body* b : {&P, &O})
      for (const auto& g : b->rigid_groups) add_rigid_group(m, g);
    if (!mapped) {
      std::vector<std::size_t> g;
      for (std::size_t k = 0; k < O.points.size(); ++k) if (O.has_coordinates[k]) g.push_back(O.points[k]);
      add_rigid_group(m, g);
    }
    if (!mapped) {
      if (auto q = spanning_quadruple(O))
        m.orientations.push_back(Orientation{m.local(O.points[(*q)[0]]), m.local(O.points[(*q)[1]]), m.local(O.points[(*q)[2]]),
                                             m.local(O.points[(*q)[3]]),
                                             orientation_sign(O.coordinates[(*q)[0]], O.coordinates[(*q)[1]],
                                                              O.coordinates[(*q)[2]], O.coordinates[(*q)[3]])});
    }
    // orientations now fully inside the coordinates are implied by them
    std::vector<Orientation> kept;
    for (const auto& o : m.orientations)
      if (!(m.has_coordinates[o.a] && m.has_coordinates[o.b] && m.has_coordinates[o.c] && m.has_coordinates[o.d])) kept.push_back(o);
    m.orientations = kept;
    std::vector<Squared_distance> kd;
    for (const auto& d : m.squared_distances)
      if (!(m.has_coordinates[d.a] && m.has_coordinates[d.b])) kd.push_back(d);
    m.squared_distances = kd;
    for (const Body& x : P.parts) add_part(m, x);
    if (o_as_part) add_part(m, O);
    else for (const Body& x : O.parts) add_part(m, x);
    m.mirror_variants = m.all_coordinates() ? 1 : 0; // 0: enumerate with enclose_all_placements()
    return m;
  }

  static void add_rigid_group(Body& m, const std::vector<std::size_t>& g)
  {
    if (g.size() < 3) return;  // two points are a distance
    for (const auto& h : m.rigid_groups) if (std::includes(h.begin(), h.end(), g.begin(), g.end())) return;
    m.rigid_groups.push_back(g);
  }

  // (a part once: by content, since a body keeps its name when it absorbs another)
  void add_part(Body& m, const Body& part) const
  {
    const std::string key = placement_key(c_, part);
    for (const Body& x : m.parts) if (placement_key(c_, x) == key) return;
    m.parts.push_back(part);
  }

  // Every pairwise distance both bodies know among `pts` must agree.
  void check_agreement(const Body& a, const Body& b, const std::vector<std::size_t>& pts) const
  {
    for (std::size_t u = 0; u < pts.size(); ++u)
      for (std::size_t v = u + 1; v < pts.size(); ++v) {
        auto da = body_squared(a, pts[u], pts[v]);
        auto db = body_squared(b, pts[u], pts[v]);
        if (da && db && !c_.same_value(*da, *db))
          throw Input_error("bodies '" + a.name + "' and '" + b.name + "' disagree on the distance of their shared points '" +
                            c_.label(pts[u]) + "' and '" + c_.label(pts[v]) + "' (squared " + to_text(*da) + " vs " +
                            to_text(*db) + ")");
      }
  }

  typedef std::vector<std::vector<std::optional<FT>>> Distance_matrix;

  // Squared distances among `pts` as known exactly by body a or b (nullopt where neither
  // knows: two points placed from distances in a merged body).
  Distance_matrix distance_matrix(const Body& a, const Body* b, const std::vector<std::size_t>& pts) const
  {
    Distance_matrix m(pts.size(), std::vector<std::optional<FT>>(pts.size(), FT(0)));
    for (std::size_t u = 0; u < pts.size(); ++u)
      for (std::size_t v = u + 1; v < pts.size(); ++v) {
        auto d = body_squared(a, pts[u], pts[v]);
        if (!d && b) d = body_squared(*b, pts[u], pts[v]);
        m[u][v] = m[v][u] = d;
      }
    return m;
  }

  static bool known(const Distance_matrix& dm, std::initializer_list<std::pair<std::size_t, std::size_t>> pairs)
  {
    for (const auto& p : pairs) if (!dm[p.first][p.second]) return false;
    return true;
  }

  // Drops the points `ps`, which lie on the axis through the global points u and v strictly
  // between or beyond them, from body b, if nothing is lost: each such point w sits on the
  // axis at a parameter t (w = u + t (v - u)) that the squared distances a = |uw|^2,
  // e = |wv|^2, c = |uv|^2 fix rationally, t = (a + c - e) / 2c (w is on the line), and by
  // Stewart's theorem a point X of b satisfies
  //   |Xw|^2 = (1 - t) |Xu|^2 + t |Xv|^2 - t (1 - t) c,
  // so a distance X-w of b says as much as the one of X-u, X-v it completes (added to b when
  // b lacks it; checked when b has both). Not dropped (false, b unchanged) when a handedness
  // (orientation) or a rigid part holds such a point, or when b knows neither X-u nor X-v for
  // a distance X-w; *why says which. Throws No_real_configuration when the distances of b
  // contradict the axis.
  // `axis_squared(p, q)` is the squared distance of two axis points (known to both bodies).
  template <class Axis_squared>
  bool drop_axis_points(Body& b, const std::vector<std::size_t>& ps, std::size_t u, std::size_t v, const Axis_squared& axis_squared,
                        std::string* why)
  {
    for (std::size_t w : ps) {
      for (const Body& part : b.parts)
        if (part.contains(w)) { *why = "its rigid part '" + part.name + "' holds '" + c_.label(w) + "'"; return false; }
      for (const Orientation& o : b.orientations)
        for (std::size_t q : {o.a, o.b, o.c, o.d})
          if (b.points[q] == w) { *why = "the handedness it keeps involves '" + c_.label(w) + "'"; return false; }
    }
    const std::size_t lu = b.local(u), lv = b.local(v);
    // a point with coordinates stays unless the axis's ends have them too (then it is on their
    // line in the body's own coordinates, and the frame they span is the same without it)
    for (std::size_t w : ps)
      if (b.has_coordinates[b.local(w)] && (!b.has_coordinates[lu] || !b.has_coordinates[lv])) {
        *why = "'" + c_.label(w) + "' has coordinates there and '" + c_.label(u) + "' or '" + c_.label(v) + "' has not";
        return false;
      }
    const FT c = axis_squared(u, v);
    std::vector<Squared_distance> added;
    for (std::size_t w : ps) {
      const std::size_t lw = b.local(w);
      const FT t = (axis_squared(u, w) + c - axis_squared(w, v)) / (FT(2) * c);
      for (std::size_t x = 0; x < b.points.size(); ++x) {
        if (x == lu || x == lv || std::find(ps.begin(), ps.end(), b.points[x]) != ps.end()) continue;
        if (b.has_coordinates[x] && b.has_coordinates[lw]) continue;  // no distance X-w is stored
        const std::optional<FT> xw = b.squared(x, lw);
        if (!xw) continue;
        std::optional<FT> xu = b.squared(x, lu), xv = b.squared(x, lv);
        for (const Squared_distance& d : added)
          if (d.a == x) (d.b == lu ? xu : xv) = d.squared;
        const std::string at = "body '" + b.name + "': '" + c_.label(b.points[x]) + "'";
        if (xu && xv) {
          if (!c_.same_value((FT(1) - t) * *xu + t * *xv - t * (FT(1) - t) * c, *xw))
            throw No_real_configuration(at + " is at squared distances " + to_text(*xu) + ", " + to_text(*xv) + " and " + to_text(*xw) +
                                        " from '" + c_.label(u) + "', '" + c_.label(v) + "' and '" + c_.label(w) +
                                        "', three points on one line, which no real point is (Stewart's theorem)");
          continue;
        }
        if (!xu && !xv) {
          *why = "'" + c_.label(b.points[x]) + "' is held at a distance from '" + c_.label(w) + "' and from neither '" + c_.label(u) +
                 "' nor '" + c_.label(v) + "'";
          return false;
        }
        // t is neither 0 nor 1: w is none of u, v.
        const FT missing = xu ? (*xw - (FT(1) - t) * *xu + t * (FT(1) - t) * c) / t : (*xw - t * *xv + t * (FT(1) - t) * c) / (FT(1) - t);
        if (CGAL::is_negative(missing))
          throw No_real_configuration(at + " is at squared distance " + to_text(*xw) + " from '" + c_.label(w) + "' and " +
                                      to_text(xu ? *xu : *xv) + " from '" + c_.label(xu ? u : v) + "', which puts its squared distance"
                                      " from '" + c_.label(xu ? v : u) + "' (on the same line) at " + to_text(missing) + " < 0");
        added.push_back(Squared_distance{x, xu ? lv : lu, missing});
      }
    }
    b.squared_distances.insert(b.squared_distances.end(), added.begin(), added.end());
    for (std::size_t w : ps) {
      const std::size_t k = b.local(w);
      std::vector<Squared_distance> kept;
      for (Squared_distance d : b.squared_distances) {
        if (d.a == k || d.b == k) continue;
        if (d.a > k) --d.a;
        if (d.b > k) --d.b;
        kept.push_back(d);
      }
      b.squared_distances = std::move(kept);
      for (Orientation& o : b.orientations)
        for (std::size_t* q : {&o.a, &o.b, &o.c, &o.d}) if (*q > k) --*q;
      b.points.erase(b.points.begin() + std::ptrdiff_t(k));
      b.has_coordinates.erase(b.has_coordinates.begin() + std::ptrdiff_t(k));
      b.coordinates.erase(b.coordinates.begin() + std::ptrdiff_t(k));
      for (auto& g : b.rigid_groups) g.erase(std::remove(g.begin(), g.end(), w), g.end());
    }
    return true;
  }

  bool merge_one_pair()
  {
    auto& bodies = c_.mutable_bodies();
    for (std::size_t i = 0; i < bodies.size(); ++i)
      for (std::size_t j = i + 1; j < bodies.size(); ++j) {
        std::vector<std::size_t> common = c_.common_points(i, j);
        if (common.size() < 3) continue;
        check_agreement(bodies[i], bodies[j], common);
        auto dm = distance_matrix(bodies[i], &bodies[j], common);
        std::optional<std::array<std::size_t, 3>> base = non_collinear_triple(dm);
        if (!base && !all_known(dm)) {
          // The shared points' distances run through placements: whether they are off a line
          // is decided per placement (enumerate_placements), with the other body as a rigid part.
          Body merged = merge(bodies[i], bodies[j], true);
          note("bodies '" + bodies[i].name + "' and '" + bodies[j].name + "' share the points " + labels_of(c_, common) +
               ", whose distances run through placements, and are merged into '" + merged.name + "' (one kept as a rigid part)");
          bodies.erase(bodies.begin() + j);
          bodies[i] = merged;
          return true;
        }
        if (!base) {
          // Collinear: they share an axis (a hinge). Its two farthest points carry it; every
          // other shared point lies on it at the same place in both bodies (its distances to
          // those two agree, checked above), so one body need not hold it: dropped there, the
          // hinge is the usual pair of shared points and nothing is lost (a body that shared
          // the point with the dropping body shares it with the other one, at the same place).
          std::size_t u0 = 0, v0 = 1;
          for (std::size_t u = 0; u < common.size(); ++u)
            for (std::size_t v = u + 1; v < common.size(); ++v)
              if (*dm[u][v] > *dm[u0][v0]) { u0 = u; v0 = v; }
          std::vector<std::size_t> extra;
          for (std::size_t w = 0; w < common.size(); ++w) if (w != u0 && w != v0) extra.push_back(common[w]);
          std::size_t from = Collection::npos;
          std::string why[2];
          auto axis_squared = [&](std::size_t p, std::size_t q) {
            const std::size_t a = std::size_t(std::find(common.begin(), common.end(), p) - common.begin());
            const std::size_t e = std::size_t(std::find(common.begin(), common.end(), q) - common.begin());
            return *dm[a][e];
          };
          for (std::size_t cand : {j, i})
            if (from == Collection::npos && drop_axis_points(bodies[cand], extra, common[u0], common[v0], axis_squared, &why[cand == i]))
              from = cand;
          if (from == Collection::npos)
            throw Input_error("bodies '" + bodies[i].name + "' and '" + bodies[j].name + "' share " + std::to_string(common.size()) +
                              " collinear points (" + labels_of(c_, common) + "), an axis; it is the hinge of its two farthest points '" +
                              c_.label(common[u0]) + "' and '" + c_.label(common[v0]) + "' once one body leaves the others out, which"
                              " neither can: in '" + bodies[j].name + "', " + why[0] + "; in '" + bodies[i].name + "', " + why[1] +
                              " (give the axis by 2 shared points)");
          note("bodies '" + bodies[i].name + "' and '" + bodies[j].name + "' share " + std::to_string(common.size()) + " collinear points (" +
               labels_of(c_, common) + "): a hinge on its two farthest points '" + c_.label(common[u0]) + "' and '" +
               c_.label(common[v0]) + "'; the others lie on it in both bodies and are left to '" +
               bodies[from == i ? j : i].name + "' alone");
          return true;
        }
        Body merged = merge(bodies[i], bodies[j]);
        note("bodies '" + bodies[i].name + "' and '" + bodies[j].name + "' share " + std::to_string(common.size()) +
             " non-collinear points (" + labels_of(c_, common) + ") and are merged into '" + merged.name + "'");
        bodies.erase(bodies.begin() + j);
        bodies[i] = merged;
        return true;
      }
    return false;
  }

  static bool all_known(const Distance_matrix& dm)
  {
    for (const auto& row : dm) for (const auto& x : row) if (!x) return false;
    return true;
  }

  // Three points known (from exact distances) not to lie on a line.
  static std::optional<std::array<std::size_t, 3>> non_collinear_triple(const Distance_matrix& dm)
  {
    std::size_t n = dm.size();
    for (std::size_t a = 0; a < n; ++a)
      for (std::size_t b = a + 1; b < n; ++b)
        for (std::size_t c = b + 1; c < n; ++c)
          if (known(dm, {{a, b}, {a, c}, {b, c}}) &&
              triangle_sign<Traits::has_exact_ft>(*dm[a][b], *dm[a][c], *dm[b][c]) != CGAL::ZERO)
            return std::array<std::size_t, 3>{a, b, c};
    return std::nullopt;
  }

  // The images in A's frame of B's points with coordinates, under the rigid motion taking
  // B's frame to A's: the rotation maps the frame (u, v, u x v) of three shared points in B
  // to the same frame in A, M = [u1 v1 w1] [u2 v2 w2]^{-1}. It is rational (no square root:
  // exact with an exact kernel). `shared` are global points with coordinates in both, `base`
  // indexes three non-collinear ones. Throws if a shared point does not land on itself
  // (mirror images).
  std::vector<std::optional<Point_3>> map_into(const Body& A, const Body& B, const std::vector<std::size_t>& shared,
                                               const std::array<std::size_t, 3>& base) const
  {
    std::size_t pa = shared[base[0]], pb = shared[base[1]], pc = shared[base[2]];
    const Point_3 a1 = A.coordinates[A.local(pa)], b1 = A.coordinates[A.local(pb)], c1 = A.coordinates[A.local(pc)];
    const Point_3 a2 = B.coordinates[B.local(pa)], b2 = B.coordinates[B.local(pb)], c2 = B.coordinates[B.local(pc)];
    auto diff = [](const Point_3& p, const Point_3& q) {
      return std::array<FT, 3>{Traits::x(q) - Traits::x(p), Traits::y(q) - Traits::y(p), Traits::z(q) - Traits::z(p)};
    };
    auto cross = [](const std::array<FT, 3>& a, const std::array<FT, 3>& b) {
      return std::array<FT, 3>{a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
    };
    std::array<FT, 3> u1 = diff(a1, b1), v1 = diff(a1, c1), w1 = cross(u1, v1);
    std::array<FT, 3> u2 = diff(a2, b2), v2 = diff(a2, c2), w2 = cross(u2, v2);
    FT S[3][3], T[3][3]; // columns u, v, w
    for (int r = 0; r < 3; ++r) {
      S[r][0] = u2[r]; S[r][1] = v2[r]; S[r][2] = w2[r];
      T[r][0] = u1[r]; T[r][1] = v1[r]; T[r][2] = w1[r];
    }
    FT det = S[0][0] * (S[1][1] * S[2][2] - S[1][2] * S[2][1]) - S[0][1] * (S[1][0] * S[2][2] - S[1][2] * S[2][0]) +
             S[0][2] * (S[1][0] * S[2][1] - S[1][1] * S[2][0]);
    FT inv[3][3];
    inv[0][0] = (S[1][1] * S[2][2] - S[1][2] * S[2][1]) / det; inv[0][1] = (S[0][2] * S[2][1] - S[0][1] * S[2][2]) / det;
    inv[0][2] = (S[0][1] * S[1][2] - S[0][2] * S[1][1]) / det; inv[1][0] = (S[1][2] * S[2][0] - S[1][0] * S[2][2]) / det;
    inv[1][1] = (S[0][0] * S[2][2] - S[0][2] * S[2][0]) / det; inv[1][2] = (S[0][2] * S[1][0] - S[0][0] * S[1][2]) / det;
    inv[2][0] = (S[1][0] * S[2][1] - S[1][1] * S[2][0]) / det; inv[2][1] = (S[0][1] * S[2][0] - S[0][0] * S[2][1]) / det;
    inv[2][2] = (S[0][0] * S[1][1] - S[0][1] * S[1][0]) / det;
    FT M[3][3];
    for (int r = 0; r < 3; ++r)
      for (int k = 0; k < 3; ++k) M[r][k] = T[r][0] * inv[0][k] + T[r][1] * inv[1][k] + T[r][2] * inv[2][k];
    std::vector<std::optional<Point_3>> images(B.points.size());
    for (std::size_t k = 0; k < B.points.size(); ++k) {
      if (!B.has_coordinates[k]) continue;
      const Point_3& p = B.coordinates[k];
      FT d[3] = {Traits::x(p) - Traits::x(a2), Traits::y(p) - Traits::y(a2), Traits::z(p) - Traits::z(a2)};
      images[k] = Traits::point(Traits::x(a1) + M[0][0] * d[0] + M[0][1] * d[1] + M[0][2] * d[2],
                                Traits::y(a1) + M[1][0] * d[0] + M[1][1] * d[1] + M[1][2] * d[2],
                                Traits::z(a1) + M[2][0] * d[0] + M[2][1] * d[1] + M[2][2] * d[2]);
    }
    const FT scale = Traits::squared_distance(a1, b1); // a mismatch is measured against the shared frame's size
    for (std::size_t p : shared) {
      FT d2 = Traits::squared_distance(*images[B.local(p)], A.coordinates[A.local(p)]);
      if (!c_.same_value(d2 + scale, scale))
        throw Input_error("bodies '" + A.name + "' and '" + B.name + "' share points " + labels_of(c_, shared) +
                          " whose pairwise distances agree but which no rotation superposes (point '" + c_.label(p) +
                          "'): one body holds the mirror image of the other");
    }
    return images;
  }

  // Does `b` hold the frame body's coordinates (in the frame body's frame)?
  bool holds_frame(const Body& b) const { return b.name == frame_holder_; }

  Body merge(const Body& A, const Body& B, bool other_as_part = false)
  {
    const bool a_first = primary_first(A, B);
    const bool frame_kept = holds_frame(a_first ? A : B);
    Body m = a_first ? combine(A, B, other_as_part) : combine(B, A, other_as_part);
    m.name = "merged" + std::to_string(++merged_count_) + "(" + A.name + "+" + B.name + ")";
    m.origin = Body_origin::MERGED;
    if (frame_kept) frame_holder_ = m.name;
    return m;
  }

  // Implied rigid bodies: maximal sets of >= 3 points with every pair at a fixed distance
  // (in a common body or joined by a distance), not all in one body.
  bool add_implied_bodies()
  {
    auto& bodies = c_.mutable_bodies();
    auto& ds = c_.mutable_distances();
    // Only points that are shared or end a distance can lie in such a set: a point seen by
    // one body alone is adjacent to that body's points only.
    std::vector<int> count(c_.number_of_points(), 0);
    for (const Body& b : bodies) for (std::size_t p : b.points) ++count[p];
    std::vector<bool> relevant(c_.number_of_points(), false);
    for (std::size_t p = 0; p < count.size(); ++p) relevant[p] = count[p] >= 2;
    for (const Distance& d : ds) relevant[d.a] = relevant[d.b] = true;
    std::vector<std::size_t> ids, vertex_of(c_.number_of_points(), Collection::npos);
    for (std::size_t p = 0; p < relevant.size(); ++p) if (relevant[p]) { vertex_of[p] = ids.size(); ids.push_back(p); }
    if (ids.size() < 3) return false;
    typedef boost::adjacency_list<boost::setS, boost::vecS, boost::undirectedS> Graph;
    Graph g(ids.size());
    for (const Body& b : bodies)
      for (std::size_t u = 0; u < b.points.size(); ++u)
        for (std::size_t v = u + 1; v < b.points.size(); ++v)
          if (relevant[b.points[u]] && relevant[b.points[v]])
            boost::add_edge(vertex_of[b.points[u]], vertex_of[b.points[v]], g);
    for (const Distance& d : ds) boost::add_edge(vertex_of[d.a], vertex_of[d.b], g);
    std::vector<std::vector<std::size_t>> cliques;
    Clique_collector vis{&cliques, &ids};
    boost::bron_kerbosch_all_cliques(g, vis, 3);
    std::sort(cliques.begin(), cliques.end());
    bool added = false;
    for (const auto& k0 : cliques) {
      const std::vector<std::size_t> k = without_axis_points(k0);
      if (k.size() < 3) continue;
      bool inside = false;
      for (const Body& b : bodies)
        if (std::includes(b.points.begin(), b.points.end(), k.begin(), k.end())) { inside = true; break; }
      if (inside) continue;
      if (add_implied(k)) added = true;
    }
    return added;
  }

  // A clique without its points that lie between two others of it on a line that one body
  // with coordinates holds (an axis given by three points): that body places such a point, and
  // in an implied body it would be placed at height 0 from distances alone.
  std::vector<std::size_t> without_axis_points(std::vector<std::size_t> k)
  {
    bool again = true;
    while (again) {
      again = false;
      for (std::size_t a = 0; a < k.size() && !again; ++a)
        for (std::size_t u = 0; u < k.size() && !again; ++u)
          for (std::size_t v = u + 1; v < k.size() && !again; ++v) {
            if (u == a || v == a) continue;
            for (const Body& o : c_.bodies()) {
              const std::size_t la = o.local(k[a]), lu = o.local(k[u]), lv = o.local(k[v]);
              if (la == Collection::npos || lu == Collection::npos || lv == Collection::npos) continue;
              if (!o.has_coordinates[la] || !o.has_coordinates[lu] || !o.has_coordinates[lv]) continue;
              const Point_3 &P = o.coordinates[la], &U = o.coordinates[lu], &V = o.coordinates[lv];
              if (!Traits::collinear(U, P, V)) continue;
              const FT uv = Traits::squared_distance(U, V);
              if (Traits::squared_distance(U, P) > uv || Traits::squared_distance(P, V) > uv) continue;  // not between
              if (axis_noted_.insert({k[a], o.name}).second)
                note("'" + c_.label(k[a]) + "' lies between '" + c_.label(k[u]) + "' and '" + c_.label(k[v]) + "' on a line of body '" +
                     o.name + "': left out of the implied bodies (that body places it)");
              k.erase(k.begin() + std::ptrdiff_t(a));
              again = true;
              break;
            }
          }
    }
    return k;
  }

  std::optional<FT> fixed_squared(std::size_t p, std::size_t q, std::vector<std::string>* sources) const
  {
    for (const Distance& d : c_.distances())
      if ((d.a == p && d.b == q) || (d.a == q && d.b == p)) { if (sources) sources->push_back(d.name); return d.squared; }
    for (const Body& b : c_.bodies())
      if (b.contains(p) && b.contains(q)) {
        auto v = body_squared(b, p, q);
        if (v) { if (sources) sources->push_back(b.name); return v; }
      }
    return std::nullopt;
  }

  // Adds the implied body of clique k; false if it is not a body (its points on one line).
  bool add_implied(const std::vector<std::size_t>& k)
  {
    std::vector<std::string> sources;
    // A pair can be fixed (both points in one body) without its distance being known exactly
    // (both placed from distances in a merged body): the implied body then carries the
    // distances that are known, and its placements are enumerated later.
    Distance_matrix dm(k.size(), std::vector<std::optional<FT>>(k.size(), FT(0)));
    for (std::size_t u = 0; u < k.size(); ++u)
      for (std::size_t v = u + 1; v < k.size(); ++v) dm[u][v] = dm[v][u] = fixed_squared(k[u], k[v], &sources);
    const bool complete = all_known(dm);
    const std::string who = "implied body {" + labels_of(c_, k, ",") + "}";
    // Realizability, exactly from the squared distances (Cayley-Menger determinants).
    bool planar_nondegenerate = false;
    for (std::size_t a = 0; a < k.size(); ++a) for (std::size_t b = a + 1; b < k.size(); ++b)
      for (std::size_t c = b + 1; c < k.size(); ++c) {
        if (!known(dm, {{a, b}, {a, c}, {b, c}})) continue;
        CGAL::Sign s = triangle_sign<Traits::has_exact_ft>(*dm[a][b], *dm[a][c], *dm[b][c]);
        if (s == CGAL::NEGATIVE)
          throw No_real_configuration(who + ": the fixed distances between '" + c_.label(k[a]) + "', '" + c_.label(k[b]) + "' and '" +
                                      c_.label(k[c]) + "' (squared " + to_text(*dm[a][b]) + ", " + to_text(*dm[a][c]) + ", " +
                                      to_text(*dm[b][c]) + ") violate the triangle inequality: no real configuration");
        if (s == CGAL::POSITIVE) planar_nondegenerate = true;
      }
    if (!planar_nondegenerate && complete) {
      // Points on one line are not a rigid body (they turn about the line): no body is added,
      // and the distances stay equations of the reduced system. There they are at an extreme
      // (a collinear triangle is the longest or flattest its sides allow), so the roots are
      // multiple: singular configurations, not certified (solve_scene()).
      if (collinear_noted_.insert(k).second)
        note(who + ": its fixed distances put all its points on one line; not added as a body (a body on a line turns"
                   " about it), its distances stay equations whose roots are multiple (singular configurations)");
      return false;
    }
    bool spatial = false;
    if (k.size() <= 12) {
      for (std::size_t a = 0; a < k.size(); ++a) for (std::size_t b = a + 1; b < k.size(); ++b)
        for (std::size_t c = b + 1; c < k.size(); ++c) for (std::size_t d = c + 1; d < k.size(); ++d) {
          if (!known(dm, {{a, b}, {a, c}, {a, d}, {b, c}, {b, d}, {c, d}})) continue;
          CGAL::Sign s = tetrahedron_sign<Traits::has_exact_ft>(*dm[a][b], *dm[a][c], *dm[a][d], *dm[b][c], *dm[b][d], *dm[c][d]);
          if (s == CGAL::NEGATIVE)
            throw No_real_configuration(who + ": the fixed distances among '" + c_.label(k[a]) + "', '" + c_.label(k[b]) + "', '" +
                                        c_.label(k[c]) + "' and '" + c_.label(k[d]) + "' admit no real configuration (a negative"
                                        " Cayley-Menger volume)");
          if (s == CGAL::POSITIVE) spatial = true;
        }
    } else spatial = true; // conservative: report the mirror ambiguity
    Body b;
    std::vector<std::string> names;
    for (std::size_t p : k) names.push_back(c_.label(p));
    std::sort(names.begin(), names.end());
    b.name = "I" + std::to_string(++implied_count_) + "{";
    for (std::size_t i = 0; i < names.size(); ++i) b.name += (i ? "," : "") + names[i];
    b.name += "}";
    b.origin = Body_origin::IMPLIED;
    b.points = k;
    b.has_coordinates.assign(k.size(), false);
    b.coordinates.assign(k.size(), Point_3(0, 0, 0));
    for (std::size_t u = 0; u < k.size(); ++u)
      for (std::size_t v = u + 1; v < k.size(); ++v)
        if (dm[u][v]) b.squared_distances.push_back(Squared_distance{u, v, *dm[u][v]});
    std::sort(sources.begin(), sources.end());
    sources.erase(std::unique(sources.begin(), sources.end()), sources.end());
    b.sources = sources;
    // a clique of distances: its mirror image satisfies them too; with a distance unknown, enumerate
    b.mirror_variants = !complete ? 0 : (spatial ? 2 : 1);
    // a pair fixed by a body that does not know its distance exactly: that body is a rigid
    // part of the implied body (its placements fix the pair)
    for (std::size_t u = 0; u < k.size(); ++u)
      for (std::size_t v = u + 1; v < k.size(); ++v)
        if (!dm[u][v])
          for (const Body& o : c_.bodies())
            if (o.contains(k[u]) && o.contains(k[v])) { add_part(b, o); break; }
    note(who + " is added as body '" + b.name + "' (from " + [&] { std::string s; for (std::size_t i = 0; i < sources.size(); ++i) s += (i ? ", " : "") + sources[i]; return s; }() + ")");
    c_.mutable_bodies().push_back(b);
    return true;
  }
};

} // namespace internal

/*!
\ingroup PkgRigidIncidenceRef
\brief Turns a collection into a standard collection (Definition 3 of
optimized_incidence_tree_parametrization.txt).

Repeated until nothing changes:
- a distance between two points of one body is absorbed into it, after checking that the
  body fixes the same value;
- a body whose points all lie in another body is absorbed, after checking that the
  distances they share agree;
- two bodies sharing 3 or more non-collinear points are merged (their relative placement is
  determined; with coordinates on both sides the placement is a rational map, exact with
  an exact kernel); bodies sharing 3 or more collinear points share an axis: the hinge of its
  two farthest points, the other shared points dropped from one of the bodies (they lie on the
  axis at the same place in both; a body that knows such a point by distances gets, by
  Stewart's theorem, the distances to the axis's ends they imply), refused only when neither
  body can drop them (a rigid part or a handedness holds one, or a distance to it has no
  counterpart to either end);
- every maximal set of 3 or more points whose pairs are all at fixed distances (inside a
  body or joined by a distance) and that is not inside one body becomes an implied body,
  after checking that its distances can be realized (Cayley-Menger determinants, exactly);
  a set whose points lie on one line is not a body (it turns about the line): it is noted,
  and its distances stay distances (their roots are multiple: see `solve_scene()`).
  Implied bodies keep their squared distances, and the bodies and distances that imply them.

Absorption and merging keep the coordinates of one body (the one holding the scene's frame,
else the one with more points with coordinates) and bring the other's into its frame by the
rational rigid map when three non-collinear points have coordinates on both sides; otherwise
the other's points enter as distances plus an orientation (`Rigid_body_collection::Orientation`),
so that no user body can come back mirrored. Two bodies sharing two or more points must agree
on their distances.

A body of 2 points is a bar and enters as its distance; a body of 3 or more collinear points
(5 dof) is rejected. The result keeps the name of the input; its `frame()` names the body that
holds the frame body's coordinates. `log`, if given, receives one line per step taken.

Two bodies sharing three or more points whose distances are not all known exactly (they run
through placements from distances) are merged too: the union keeps one of them whole as a
rigid part (`Rigid_body_collection::Body::parts`), and whether the shared points are off a
line is decided per placement by `enumerate_placements()`. An implied body with a pair whose
distance is not known exactly keeps the body fixing that pair as a rigid part.

\throws Input_error naming the bodies, points or distances that disagree.
*/
template <class Traits>
Rigid_body_collection<Traits> standardize(const Rigid_body_collection<Traits>& collection,
                                          std::vector<std::string>* log = nullptr)
{
  internal::Standardizer<Traits> s(collection, log);
  return s.run();
}

} // namespace Rigid_incidence
} // namespace CGAL

#endif
