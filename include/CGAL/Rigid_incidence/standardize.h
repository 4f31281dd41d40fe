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
  typedef typename Traits::FT FT;
  typedef typename Traits::Point_3 Point_3;

public:
  Standardizer(const Collection& in, std::vector<std::string>* log) : c_(in), log_(log), frame_name_(in.frame()) {}

  Collection run()
  {
    turn_collinear_bodies_into_bars();
    std::size_t guard = 0, limit = 8 * (c_.number_of_bodies() + c_.distances().size()) + 16;
    bool changed = true;
    while (changed) {
      if (++guard > limit) throw Input_error("standardize: no fixpoint reached (internal error)");
      changed = absorb_distances();
      changed = absorb_bodies() || changed;
      if (changed) continue;
      changed = merge_one_pair();
      if (changed) continue;
      changed = add_implied_bodies();
    }
    // The frame passes to the body that absorbed or merged the frame body; that body keeps
    // the frame body's coordinates (see merge_one_pair and absorb_bodies).
    if (!frame_name_.empty() && c_.body_index(frame_name_) == Collection::npos)
      for (const Body& b : c_.bodies())
        if (holds_frame(b)) {
          note("the scene's frame '" + frame_name_ + "' is now body '" + b.name + "', in the same coordinates");
          c_.set_frame(b.name);
          break;
        }
    return c_;
  }

private:
  Collection c_;
  std::vector<std::string>* log_;
  std::string frame_name_; // the user body whose local frame results are reported in
  std::size_t implied_count_ = 0, merged_count_ = 0;

  void note(const std::string& s) { if (log_) log_->push_back(s); }

  static void add_source(Body& b, const std::string& s)
  {
    if (std::find(b.sources.begin(), b.sources.end(), s) == b.sources.end()) b.sources.push_back(s);
  }

  // A body whose points are all collinear is a bar: it fixes only its pairwise distances
  // (5 dof, not 6), so it enters as distances.
  void turn_collinear_bodies_into_bars()
  {
    auto& bodies = c_.mutable_bodies();
    std::vector<Body> kept;
    std::vector<Body> bars;
    for (const Body& b : bodies) {
      bool collinear = true;
      for (std::size_t i = 2; i < b.points.size() && collinear; ++i)
        collinear = Traits::collinear(b.coordinates[0], b.coordinates[1], b.coordinates[i]);
      if (collinear) bars.push_back(b); else kept.push_back(b);
    }
    bodies = kept;
    for (const Body& b : bars) {
      if (b.name == frame_name_)
        throw Input_error("body '" + b.name + "' is the scene's frame but has all its points on one line: a bar has no frame"
                          " of its own; name another body as \"frame\"");
      note("body '" + b.name + "' has all its points on one line: it is a bar and enters as distances");
      for (std::size_t i = 0; i < b.points.size(); ++i)
        for (std::size_t j = i + 1; j < b.points.size(); ++j)
          c_.add_distance(c_.label(b.points[i]), c_.label(b.points[j]),
                          Traits::squared_distance(b.coordinates[i], b.coordinates[j]),
                          "body '" + b.name + "' (a bar)");
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
            if (!c_.same_value(*known, d.squared))
              throw Input_error(d.name + ": disagrees with body '" + bodies[i].name +
                                "', which fixes the distance of '" + c_.label(d.a) + "' and '" + c_.label(d.b) +
                                "' to squared " + to_text(*known) + ", not " + to_text(d.squared));
            if (host == Collection::npos) host = i;
          }
        }
      if (host == Collection::npos) { ++k; continue; }
      note(d.name + " lies inside body '" + bodies[host].name + "' and is absorbed");
      add_source(bodies[host], d.name);
      ds.erase(ds.begin() + k);
      changed = true;
    }
    return changed;
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
        std::vector<Point_3> reframed;
        if (small.all_coordinates() && big.all_coordinates()) {
          // distances agree; a rotation must superpose them too (not a mirror image)
          auto dm = distance_matrix(small, nullptr, small.points);
          auto base = non_collinear_triple(dm);
          if (base) {
            std::vector<Point_3> images = map_into(small, big, small.points, *base);
            if (holds_frame(small)) reframed = images; // keep the scene's frame
          }
        }
        note("body '" + small.name + "' lies inside body '" + big.name + "' and is absorbed");
        Body& host = bodies[j];
        for (const auto& s : small.sources) add_source(host, s);
        if (!reframed.empty()) {
          host.coordinates = reframed;
          note("body '" + host.name + "' is expressed in the frame of '" + frame_name_ + "', the scene's frame");
        }
        adopt_coordinates(host, small);
        host.mirror_variants = std::max(host.mirror_variants, host.all_coordinates() ? 1 : small.mirror_variants);
        bodies.erase(bodies.begin() + i);
        return true;
      }
    return false;
  }

  // A body known by distances only that absorbs a body with coordinates takes them over:
  // exact coordinates are worth keeping (no square root is needed to place those points).
  void adopt_coordinates(Body& host, const Body& small) const
  {
    if (!small.all_coordinates() || std::any_of(host.has_coordinates.begin(), host.has_coordinates.end(), [](bool b) { return b; }))
      return;
    std::vector<Squared_distance> kept;
    for (std::size_t k = 0; k < small.points.size(); ++k) {
      std::size_t h = host.local(small.points[k]);
      host.has_coordinates[h] = true;
      host.coordinates[h] = small.coordinates[k];
    }
    for (const auto& d : host.squared_distances)
      if (!(host.has_coordinates[d.a] && host.has_coordinates[d.b])) kept.push_back(d);
    host.squared_distances = kept;
    // The points placed from distances relative to the adopted ones have one placement if
    // the adopted points span space, else two (mirror images in their plane).
    std::vector<std::vector<FT>> dm(small.points.size(), std::vector<FT>(small.points.size(), FT(0)));
    for (std::size_t u = 0; u < small.points.size(); ++u)
      for (std::size_t v = u + 1; v < small.points.size(); ++v) dm[u][v] = dm[v][u] = *small.squared(u, v);
    bool all_adopted = host.all_coordinates();
    if (all_adopted || spans_space(dm)) host.mirror_variants = 1;
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

  // Squared distances among `pts` as known by body a or b (all must be known).
  std::vector<std::vector<FT>> distance_matrix(const Body& a, const Body* b, const std::vector<std::size_t>& pts) const
  {
    std::vector<std::vector<FT>> m(pts.size(), std::vector<FT>(pts.size(), FT(0)));
    for (std::size_t u = 0; u < pts.size(); ++u)
      for (std::size_t v = u + 1; v < pts.size(); ++v) {
        auto d = body_squared(a, pts[u], pts[v]);
        if (!d && b) d = body_squared(*b, pts[u], pts[v]);
        if (!d) throw Input_error("standardize: the distance of '" + c_.label(pts[u]) + "' and '" + c_.label(pts[v]) +
                                  "' is needed but not known exactly (a placement through two implied bodies); not supported yet");
        m[u][v] = m[v][u] = *d;
      }
    return m;
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
        if (!base)
          throw Input_error("bodies '" + bodies[i].name + "' and '" + bodies[j].name + "' share " + std::to_string(common.size()) +
                            " collinear points (" + labels_of(c_, common) +
                            "): they share only an axis, which must be given by exactly 2 shared points");
        // the merged body keeps the coordinates (the frame) of the body holding the scene's frame
        bool swap = holds_frame(bodies[j]) && bodies[j].all_coordinates();
        Body merged = swap ? merge(bodies[j], bodies[i], common, *base, dm) : merge(bodies[i], bodies[j], common, *base, dm);
        note("bodies '" + bodies[i].name + "' and '" + bodies[j].name + "' share " + std::to_string(common.size()) +
             " non-collinear points (" + labels_of(c_, common) + ") and are merged into '" + merged.name + "'");
        bodies.erase(bodies.begin() + j);
        bodies[i] = merged;
        return true;
      }
    return false;
  }

  static std::optional<std::array<std::size_t, 3>> non_collinear_triple(const std::vector<std::vector<FT>>& dm)
  {
    std::size_t n = dm.size();
    for (std::size_t a = 0; a < n; ++a)
      for (std::size_t b = a + 1; b < n; ++b)
        for (std::size_t c = b + 1; c < n; ++c)
          if (CGAL::sign(triangle_16_area_squared(dm[a][b], dm[a][c], dm[b][c])) != CGAL::ZERO)
            return std::array<std::size_t, 3>{a, b, c};
    return std::nullopt;
  }

  // Does the matrix have 4 points spanning 3D?
  static bool spans_space(const std::vector<std::vector<FT>>& dm)
  {
    std::size_t n = dm.size();
    for (std::size_t a = 0; a < n; ++a) for (std::size_t b = a + 1; b < n; ++b)
      for (std::size_t c = b + 1; c < n; ++c) for (std::size_t d = c + 1; d < n; ++d)
        if (CGAL::sign(tetrahedron_288_volume_squared(dm[a][b], dm[a][c], dm[a][d], dm[b][c], dm[b][d], dm[c][d])) != CGAL::ZERO)
          return true;
    return false;
  }

  // The images in A's frame of all of B's points, under the rigid motion taking B's frame to
  // A's: the rotation maps the frame (u, v, u x v) of three shared points in B to the same
  // frame in A, M = [u1 v1 w1] [u2 v2 w2]^{-1}. It is rational (no square root: exact with an
  // exact kernel). Throws if a shared point does not land on itself (mirror images).
  std::vector<Point_3> map_into(const Body& A, const Body& B, const std::vector<std::size_t>& common,
                                const std::array<std::size_t, 3>& base) const
  {
    std::size_t pa = common[base[0]], pb = common[base[1]], pc = common[base[2]];
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
    std::vector<Point_3> images;
    for (const Point_3& p : B.coordinates) {
      FT d[3] = {Traits::x(p) - Traits::x(a2), Traits::y(p) - Traits::y(a2), Traits::z(p) - Traits::z(a2)};
      images.push_back(Traits::point(Traits::x(a1) + M[0][0] * d[0] + M[0][1] * d[1] + M[0][2] * d[2],
                                     Traits::y(a1) + M[1][0] * d[0] + M[1][1] * d[1] + M[1][2] * d[2],
                                     Traits::z(a1) + M[2][0] * d[0] + M[2][1] * d[1] + M[2][2] * d[2]));
    }
    const FT scale = Traits::squared_distance(a1, b1); // a mismatch is measured against the shared frame's size
    for (std::size_t p : common) {
      FT d2 = Traits::squared_distance(images[B.local(p)], A.coordinates[A.local(p)]);
      if (!c_.same_value(d2 + scale, scale))
        throw Input_error("bodies '" + A.name + "' and '" + B.name + "' share points " + labels_of(c_, common) +
                          " whose pairwise distances agree but which no rotation superposes (point '" + c_.label(p) +
                          "'): one body holds the mirror image of the other");
    }
    return images;
  }

  bool holds_frame(const Body& b) const
  {
    return std::find(b.sources.begin(), b.sources.end(), frame_name_) != b.sources.end();
  }

  Body merge(const Body& A, const Body& B, const std::vector<std::size_t>& common,
             const std::array<std::size_t, 3>& base, const std::vector<std::vector<FT>>& dm)
  {
    Body m;
    m.name = "merged" + std::to_string(++merged_count_) + "(" + A.name + "+" + B.name + ")";
    m.origin = Body_origin::MERGED;
    m.sources = A.sources;
    for (const auto& src : B.sources) add_source(m, src);
    std::set_union(A.points.begin(), A.points.end(), B.points.begin(), B.points.end(), std::back_inserter(m.points));
    m.has_coordinates.assign(m.points.size(), false);
    m.coordinates.assign(m.points.size(), Point_3(0, 0, 0));
    if (A.all_coordinates() && B.all_coordinates()) {
      std::vector<Point_3> images = map_into(A, B, common, base);
      for (std::size_t k = 0; k < m.points.size(); ++k) {
        std::size_t p = m.points[k];
        m.coordinates[k] = A.contains(p) ? A.coordinates[A.local(p)] : images[B.local(p)];
        m.has_coordinates[k] = true;
      }
      return m;
    }
    // At least one of them is known by distances only: keep the coordinates of one body that
    // has them all, and carry every pairwise distance the two bodies know.
    const Body* with = A.all_coordinates() ? &A : (B.all_coordinates() ? &B : nullptr);
    const Body* other = (with == &A) ? &B : &A;
    for (std::size_t k = 0; k < m.points.size(); ++k)
      if (with && with->contains(m.points[k])) {
        m.has_coordinates[k] = true;
        m.coordinates[k] = with->coordinates[with->local(m.points[k])];
      }
    for (const Body* b : {&A, &B})
      for (std::size_t u = 0; u < b->points.size(); ++u)
        for (std::size_t v = u + 1; v < b->points.size(); ++v) {
          std::size_t mu = m.local(b->points[u]), mv = m.local(b->points[v]);
          if (m.has_coordinates[mu] && m.has_coordinates[mv]) continue;
          auto d = b->squared(u, v);
          if (!d) continue;
          bool dup = false;
          for (const auto& s : m.squared_distances)
            if ((s.a == mu && s.b == mv) || (s.a == mv && s.b == mu)) dup = true;
          if (!dup) m.squared_distances.push_back(Squared_distance{mu, mv, *d});
        }
    // Placed from three or more coplanar points, the other body's points have two mirror
    // placements; from four points spanning space they have one.
    bool other_has_more = other->points.size() > common.size();
    int mv = (with && (spans_space(dm) || !other_has_more)) ? 1 : 2;
    if (!with) mv = std::max(A.mirror_variants, B.mirror_variants);
    m.mirror_variants = std::max(mv, with ? with->mirror_variants : 1);
    (void)base;
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
    if (ids.size() < 3 || ds.empty()) return false; // without a distance no clique leaves the bodies
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
    for (const auto& k : cliques) {
      bool inside = false;
      for (const Body& b : bodies)
        if (std::includes(b.points.begin(), b.points.end(), k.begin(), k.end())) { inside = true; break; }
      if (inside) continue;
      add_implied(k);
      added = true;
    }
    return added;
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

  void add_implied(const std::vector<std::size_t>& k)
  {
    std::vector<std::string> sources;
    std::vector<std::vector<FT>> dm(k.size(), std::vector<FT>(k.size(), FT(0)));
    for (std::size_t u = 0; u < k.size(); ++u)
      for (std::size_t v = u + 1; v < k.size(); ++v) {
        auto d = fixed_squared(k[u], k[v], &sources);
        if (!d) throw Input_error("standardize: the distance of '" + c_.label(k[u]) + "' and '" + c_.label(k[v]) +
                                  "' is fixed but not known exactly (it runs through an implied placement); not supported yet");
        dm[u][v] = dm[v][u] = *d;
      }
    const std::string who = "implied body {" + labels_of(c_, k, ",") + "}";
    // Realizability, exactly from the squared distances (Cayley-Menger determinants).
    bool planar_nondegenerate = false;
    for (std::size_t a = 0; a < k.size(); ++a) for (std::size_t b = a + 1; b < k.size(); ++b)
      for (std::size_t c = b + 1; c < k.size(); ++c) {
        CGAL::Sign s = CGAL::sign(triangle_16_area_squared(dm[a][b], dm[a][c], dm[b][c]));
        if (s == CGAL::NEGATIVE)
          throw Input_error(who + ": the fixed distances between '" + c_.label(k[a]) + "', '" + c_.label(k[b]) + "' and '" +
                            c_.label(k[c]) + "' violate the triangle inequality: no real configuration");
        if (s == CGAL::POSITIVE) planar_nondegenerate = true;
      }
    if (!planar_nondegenerate)
      throw Input_error(who + ": its fixed distances put all its points on one line (a degenerate body)");
    bool spatial = false;
    if (k.size() <= 12) {
      for (std::size_t a = 0; a < k.size(); ++a) for (std::size_t b = a + 1; b < k.size(); ++b)
        for (std::size_t c = b + 1; c < k.size(); ++c) for (std::size_t d = c + 1; d < k.size(); ++d) {
          CGAL::Sign s = CGAL::sign(tetrahedron_288_volume_squared(dm[a][b], dm[a][c], dm[a][d], dm[b][c], dm[b][d], dm[c][d]));
          if (s == CGAL::NEGATIVE)
            throw Input_error(who + ": the fixed distances among '" + c_.label(k[a]) + "', '" + c_.label(k[b]) + "', '" +
                              c_.label(k[c]) + "' and '" + c_.label(k[d]) + "' admit no real configuration");
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
      for (std::size_t v = u + 1; v < k.size(); ++v) b.squared_distances.push_back(Squared_distance{u, v, dm[u][v]});
    std::sort(sources.begin(), sources.end());
    sources.erase(std::unique(sources.begin(), sources.end()), sources.end());
    b.sources = sources;
    b.mirror_variants = spatial ? 2 : 1;
    note(who + " is added as body '" + b.name + "' (from " + [&] { std::string s; for (std::size_t i = 0; i < sources.size(); ++i) s += (i ? ", " : "") + sources[i]; return s; }() + ")");
    c_.mutable_bodies().push_back(b);
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
  an exact kernel); bodies sharing 3 or more collinear points are rejected;
- every maximal set of 3 or more points whose pairs are all at fixed distances (inside a
  body or joined by a distance) and that is not inside one body becomes an implied body,
  after checking that its distances can be realized (Cayley-Menger determinants, exactly).
  Implied bodies keep their squared distances, and the bodies and distances that imply them.

A body whose points are collinear is a bar and enters as distances between its points.
The result keeps the frame and the name of the input. `log`, if given, receives one line
per step taken.

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
