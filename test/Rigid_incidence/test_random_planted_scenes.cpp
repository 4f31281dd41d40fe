// Copyright (c) 2026 Rigid_incidence contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Random planted scenes of odd structure, solved by solve_scene (as `rigid_incidence solve`
// does), against the planted configuration. Each scene is grown from a root body by random
// attachments that keep the dof count at 0: a body on a hinge (2 shared points) closed by a
// distance, a body on a ball joint (1 shared point) held by 3 distances (or a 5-point body,
// two of the distances from one of its points), a body sharing 3
// points (merged; or a flat plate, its fourth point in their plane), a point on the line of
// two others held by its distances to them and a bar (a double point), a braced triangle strip, a free point held by 3 distances, a body turned
// from its host by 0, a quarter, a half or three quarters of a turn about a hinge (roots at a
// chart's centre, on chart borders, at half turns); some with a near-degenerate apex (1e-5
// off its hinge), some scaled by 10^k, |k| <= 50 (issue 27, item 8). Every body is cut out of
// one planted configuration of exact rational points and expressed in its own random rational
// frame, so the planted configuration solves the scene exactly. Checks:
// - a complete answer contains the planted configuration (a dropped placement, chart or root
//   would lose it);
// - every configuration holds in the scene, by an independent check (every pairwise distance
//   of every body, every distance, no body mirrored: the sign of a spanning tetrahedron);
// - no scene is refused (a planted scene is well formed; shared points whose distances run
//   through placements were once refused as "not supported yet", issue 27, item 3);
// - the rest is counted: incomplete answers (honest: unresolved regions, limits), and printed,
//   with the planted configurations found on a chart border (at least one must be).
// Flat scenes (a third argument `flat`): every point of the planted configuration in one plane
// but the off-hinge apexes and quarter-turned bodies, as planar linkages are: heights exactly 0
// through rigid parts, which only exact arithmetic decides (issue 27, item 3).
// Usage: test_random_planted_scenes [SCENES [SEED [flat|- [verbose|- [FIRST]]]]] (default 150
// scenes, the CI's run); the seed and the scene's JSON are printed on failure, to replay with
// `rigid_incidence solve`; with `verbose`, each scene on stderr before it is solved; scenes
// before FIRST are generated but not solved (to replay one scene of a long run).

#include <CGAL/Gmpq.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Rigid_incidence.h>
#include "solve_scene_instances.h"
#include <CGAL/Rigid_incidence/IO/read_scene.h>

#include "planted_scene.h"

#include <array>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <iostream>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace RI = CGAL::Rigid_incidence;
using namespace planted;
typedef RI::Rigid_incidence_traits<CGAL::Simple_cartesian<CGAL::Gmpq>> Traits;

static int failures = 0;
#define CHECK(cond, msg)                                                                    \
  do {                                                                                      \
    if (!(cond)) {                                                                          \
      ++failures;                                                                           \
      std::cerr << "FAILED: " << msg << "  (" << __FILE__ << ":" << __LINE__ << ")\n";     \
    }                                                                                       \
  } while (0)

struct Generated
{
  Scene s;
  std::string frame;
  std::string structure;  // what was attached, for the report
  Rigid root;             // b0's frame: the planted configuration in it is root.apply(global)
};

// x -> b(a(x))
static Rigid compose(const Rigid& b, const Rigid& a)
{
  Rigid m;
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) m.R[r][c] = b.R[r][0] * a.R[0][c] + b.R[r][1] * a.R[1][c] + b.R[r][2] * a.R[2][c];
  m.t = b.apply(a.t);
  return m;
}

// The rotation by `quarters` quarter turns about the axis through `at` along `u`, whose length
// `len` is rational (so that the map is).
static Rigid quarter_turns(const QP& at, const QP& u, const Q& len, int quarters)
{
  const int c = quarters % 4 == 0 ? 1 : quarters % 4 == 2 ? -1 : 0, sn = quarters % 4 == 1 ? 1 : quarters % 4 == 3 ? -1 : 0;
  const QP n = (Q(1) / len) * u;
  const Q nn[3] = {n.x, n.y, n.z};
  const Q k[3][3] = {{0, -n.z, n.y}, {n.z, 0, -n.x}, {-n.y, n.x, 0}};
  Rigid m;
  for (int r = 0; r < 3; ++r)
    for (int s = 0; s < 3; ++s) m.R[r][s] = Q(r == s ? c : 0) + Q(sn) * k[r][s] + Q(1 - c) * nn[r] * nn[s];
  m.t = at - QP{m.R[0][0] * at.x + m.R[0][1] * at.y + m.R[0][2] * at.z, m.R[1][0] * at.x + m.R[1][1] * at.y + m.R[1][2] * at.z,
                m.R[2][0] * at.x + m.R[2][1] * at.y + m.R[2][2] * at.z};
  return m;
}

// A grown scene: `steps` attachments to a root body of 4 points.
static Generated grow(Rng& g, int steps, const Q& scale, bool flat = false)
{
  Generated out;
  Scene& s = out.s;
  int next = 0;
  auto point = [&](const QP& p) { std::string l = "q" + std::to_string(next++); s.add_point(l, p); return l; };
  // distinct from every point so far, and off every line through two of them: on the small
  // grid of g.point(12, 4) a fresh apex fell on its hinge's line now and then (heavy run, seed
  // 7, scenes 2093 and 2606), which frees the body to turn about the hinge: not a rigid scene
  auto off_lines = [&](const QP& p) {
    for (std::size_t a = 0; a < s.global.size(); ++a) {
      if (is_zero(p - s.global[a])) return false;
      for (std::size_t b = a + 1; b < s.global.size(); ++b)
        if (collinear(s.global[a], s.global[b], p)) return false;
    }
    return true;
  };
  auto random_point = [&]() {
    while (true) {
      QP p = scale * g.point(12, 4);
      if (flat) p.z = Q(0);
      if (off_lines(p)) return p;
    }
  };
  std::vector<std::string> placed;  // points of the scene so far
  std::vector<std::vector<std::string>> bodies;
  std::vector<Rigid> maps;  // per body: global -> its local coordinates
  auto body_with = [&](const std::vector<std::string>& ls, const Rigid& m) {
    if (bodies.empty()) out.root = m;
    s.add_body("b" + std::to_string(bodies.size()), ls, m);
    bodies.push_back(ls);
    maps.push_back(m);
  };
  auto body = [&](const std::vector<std::string>& ls) { body_with(ls, scaled_rigid(g, scale)); };
  auto pick = [&](const std::vector<std::string>& from, std::size_t k) {
    std::vector<std::string> v;
    while (v.size() < k) {
      const std::string& c = from[std::size_t(g.uniform(0, int(from.size()) - 1))];
      if (std::find(v.begin(), v.end(), c) == v.end()) v.push_back(c);
    }
    return v;
  };
  auto fresh = [&]() {
    std::string l = point(random_point());
    return l;
  };
  std::vector<std::string> root;
  for (int i = 0; i < 4; ++i) root.push_back(fresh());
  body(root);
  out.frame = "b0";
  placed = root;
  for (int st = 0; st < steps; ++st) {
    // (a rail point, kind 8, one draw in three: through rigid parts its height 0 is often left
    // undecided, at 4096 bits, which costs seconds)
    int kind = g.uniform(0, 8);
    if (kind == 8 && g.uniform(0, 2) != 0) kind = 7;
    const std::size_t host_index = std::size_t(g.uniform(0, int(bodies.size()) - 1));
    const std::vector<std::string> host = bodies[host_index];
    if (kind <= 1) {  // hinge on two points of a body, closed by a distance to an earlier point
      std::vector<std::string> h = pick(host, 2);
      std::vector<std::string> b = h;
      std::string apex;
      if (kind == 1 && g.uniform(0, 2) == 0) {  // an apex 1e-5 off the hinge line
        const QP a = s.at(h[0]), c = s.at(h[1]);
        QP off = cross(c - a, random_point());
        apex = point(a + Q(1, 3) * (c - a) + (Q(1, 100000) / scale) * off);  // off is of the size squared
        out.structure += "flat-hinge ";
      } else {
        apex = fresh();
        out.structure += "hinge ";
      }
      b.push_back(apex);
      if (g.uniform(0, 1)) b.push_back(fresh());
      // an axis of three points now and then: a third point on the hinge's line, in the host
      // and in the new body (read as the hinge of the two farthest)
      std::string axis;
      if (kind == 0 && host.size() >= 3 && g.uniform(0, 3) == 0) {  // (a bar host would become a collinear body)
        static const int lam[4][2] = {{1, 2}, {2, 1}, {-1, 1}, {1, 3}};
        const int* l = lam[g.uniform(0, 3)];
        const QP p = s.at(h[0]) + Q(l[0], l[1]) * (s.at(h[1]) - s.at(h[0]));
        // (not where a point already is: an earlier axis point of the same hinge, seed 7, scene 2279)
        bool taken = false;
        for (const QP& q : s.global) taken = taken || is_zero(p - q);
        if (!taken) {
          axis = point(p);
          s.bodies[host_index].pts.push_back(s.index(axis));
          s.bodies[host_index].local.push_back(maps[host_index].apply(p));
          bodies[host_index].push_back(axis);
          b.push_back(axis);
          out.structure += "axis3 ";
        }
      }
      body(b);
      std::string far;  // off the hinge's line (an axis point): a distance to it does not hold the turn
      do far = placed[std::size_t(g.uniform(0, int(placed.size()) - 1))]; while (far == h[0] || far == h[1] || collinear(s.at(h[0]), s.at(h[1]), s.at(far)));
      s.add_distance(apex, far);
      for (std::size_t i = 2; i < b.size(); ++i) if (b[i] != axis) placed.push_back(b[i]);
    } else if (kind == 2) {  // ball joint: one shared point, three distances
      // (or a 5-point body pinned by three distances, two of them from one of its points)
      const bool pin = g.uniform(0, 2) == 0;
      std::string j = pick(host, 1)[0];
      std::vector<std::string> b{j, fresh(), fresh(), fresh()};
      if (pin) b.push_back(fresh());
      body(b);
      std::vector<std::string> others;
      for (const auto& p : placed) if (p != j) others.push_back(p);
      if (others.size() < 3) { out.structure += "(skip) "; continue; }
      std::vector<std::string> to = pick(others, 3);
      for (int k = 0; k < 3; ++k) s.add_distance(b[std::size_t(pin ? 1 + k / 2 : 1 + k)], to[std::size_t(k)]);
      for (std::size_t i = 1; i < b.size(); ++i) placed.push_back(b[i]);
      out.structure += pin ? "pin5 " : "ball ";
    } else if (kind == 3) {  // three shared points: merged
      std::vector<std::string> b = pick(placed, 3);
      if (collinear(s.at(b[0]), s.at(b[1]), s.at(b[2]))) { out.structure += "(skip) "; continue; }
      b.push_back(fresh());
      body(b);
      placed.push_back(b.back());
      out.structure += "merge ";
    } else if (kind == 4) {  // a braced strip of 2 or 3 triangles on a hinge of the host
      std::vector<std::string> h = pick(host, 2);
      const int k = g.uniform(2, 3);
      std::vector<std::string> p = h;
      for (int i = 0; i < k; ++i) p.push_back(fresh());
      for (int i = 0; i < k; ++i) body({p[std::size_t(i)], p[std::size_t(i + 1)], p[std::size_t(i + 2)]});
      for (int i = 0; i + 3 < int(p.size()); ++i) s.add_distance(p[std::size_t(i)], p[std::size_t(i + 3)]);
      // the first triangle turns about the host's hinge: one more distance to the host
      std::string far;
      do far = placed[std::size_t(g.uniform(0, int(placed.size()) - 1))]; while (far == h[0] || far == h[1] || collinear(s.at(h[0]), s.at(h[1]), s.at(far)));
      s.add_distance(p[2], far);
      for (std::size_t i = 2; i < p.size(); ++i) placed.push_back(p[i]);
      out.structure += "strip" + std::to_string(k) + " ";
    } else if (kind == 5) {  // the free end of a bar, held by two more distances
      std::string f = fresh();
      std::vector<std::string> to = pick(placed, 3);
      body_with({f, to[0]}, scaled_rigid(g, scale));
      s.add_distance(f, to[1]);
      s.add_distance(f, to[2]);
      placed.push_back(f);
      out.structure += "bar ";
    } else if (kind == 7) {  // a flat plate: a body sharing three points with a fourth in their plane
      // (rigid: when it enters a merged body as distances, that point's height 0 over the three
      // is the plate's shape, not a double placement)
      std::vector<std::string> b = pick(placed, 3);
      if (collinear(s.at(b[0]), s.at(b[1]), s.at(b[2]))) { out.structure += "(skip) "; continue; }
      const QP a = s.at(b[0]), u = s.at(b[1]) - a, v = s.at(b[2]) - a;
      const QP p = a + Q(g.uniform(-3, 3), 2) * u + Q(g.uniform(-3, 3), 3) * v;
      if (!off_lines(p)) { out.structure += "(skip) "; continue; }
      b.push_back(point(p));
      body(b);
      placed.push_back(b.back());
      out.structure += "plate ";
    } else if (kind == 8) {  // a rail point: on the line of two placed points, held by its two
      // distances to them (its spheres touch: a double point) and a bar to a third
      std::vector<std::string> uv = pick(placed, 2);
      static const int lam[4][2] = {{1, 3}, {1, 2}, {2, 3}, {3, 2}};
      const int* l = lam[g.uniform(0, 3)];
      const QP p = s.at(uv[0]) + Q(l[0], l[1]) * (s.at(uv[1]) - s.at(uv[0]));
      bool ok = true;  // off every other line through two points
      for (std::size_t a = 0; a < s.global.size() && ok; ++a) {
        ok = !is_zero(p - s.global[a]);
        for (std::size_t c = a + 1; c < s.global.size() && ok; ++c)
          if (!(s.labels[a] == uv[0] && s.labels[c] == uv[1]) && !(s.labels[a] == uv[1] && s.labels[c] == uv[0]))
            ok = !collinear(s.global[a], s.global[c], p);
      }
      if (!ok) { out.structure += "(skip) "; continue; }
      const std::string w = point(p);
      std::string far;
      do far = placed[std::size_t(g.uniform(0, int(placed.size()) - 1))]; while (far == uv[0] || far == uv[1]);
      body_with({w, far}, scaled_rigid(g, scale));
      s.add_distance(w, uv[0]);
      s.add_distance(w, uv[1]);
      placed.push_back(w);
      out.structure += "rail ";
    } else {  // a body turned from its host by k quarter turns about a hinge, closed by a distance
      // the hinge: a host point and a new one at a distance that is a power of two, along a
      // Pythagorean quadruple: quarter turns about it are rational, and the hinge's charts
      // (q = (L a, b u), L the power of two nearest |u|) have their borders at quarter turns
      static const int pq[4][4] = {{1, 2, 2, 3}, {2, 3, 6, 7}, {1, 4, 8, 9}, {2, 6, 9, 11}};
      const int* r = pq[g.uniform(0, 3)];
      const int sh = g.uniform(0, 2);
      Q len(1);
      const long j = std::lround(std::log2(CGAL::to_double(scale))) + g.uniform(0, 2);
      for (long k = 0; k < (j < 0 ? -j : j); ++k) len = j < 0 ? len / Q(2) : len * Q(2);
      const Q f = len / Q(r[3]);
      const QP u = f * QP{Q((g.uniform(0, 1) ? 1 : -1) * r[sh]), Q((g.uniform(0, 1) ? 1 : -1) * r[(sh + 1) % 3]),
                          Q((g.uniform(0, 1) ? 1 : -1) * r[(sh + 2) % 3])};
      const std::string h0 = pick(host, 1)[0];
      const QP at = s.at(h0), p1 = at + u;
      if (!off_lines(p1)) { out.structure += "(skip) "; continue; }
      const std::string h1 = point(p1);
      s.bodies[host_index].pts.push_back(s.index(h1));  // the host gets the hinge's second point
      s.bodies[host_index].local.push_back(maps[host_index].apply(p1));
      bodies[host_index].push_back(h1);
      placed.push_back(h1);
      const int quarters = g.uniform(0, 3);
      std::vector<std::string> b{h0, h1, fresh()};
      if (g.uniform(0, 1)) b.push_back(fresh());
      body_with(b, compose(maps[host_index], quarter_turns(at, u, len, quarters)));
      std::string far;
      do far = placed[std::size_t(g.uniform(0, int(placed.size()) - 1))]; while (far == h0 || far == h1 || collinear(s.at(h0), s.at(h1), s.at(far)));
      s.add_distance(b[2], far);
      for (std::size_t i = 2; i < b.size(); ++i) placed.push_back(b[i]);
      out.structure += "turned" + std::to_string(90 * quarters) + " ";
    }
  }
  return out;
}

// The scene as a scene file (for a failure report).
static std::string to_json(const Scene& s, const std::string& frame)
{
  std::ostringstream os;
  auto q = [](const Q& x) { std::ostringstream o; o << '"' << x << '"'; return o.str(); };
  os << "{\"format\": \"rigid-incidence-scene/1\", \"bodies\": [";
  for (std::size_t b = 0; b < s.bodies.size(); ++b) {
    os << (b ? ", " : "") << "{\"name\": \"" << s.bodies[b].name << "\", \"points\": {";
    for (std::size_t i = 0; i < s.bodies[b].pts.size(); ++i) {
      const QP& p = s.bodies[b].local[i];
      os << (i ? ", " : "") << '"' << s.labels[std::size_t(s.bodies[b].pts[i])] << "\": [" << q(p.x) << ", " << q(p.y) << ", " << q(p.z) << "]";
    }
    os << "}}";
  }
  os << "], \"distances\": [";
  for (std::size_t d = 0; d < s.distances.size(); ++d)
    os << (d ? ", " : "") << "{\"between\": [\"" << s.labels[std::size_t(s.distances[d].a)] << "\", \"" << s.labels[std::size_t(s.distances[d].b)]
       << "\"], \"squared\": " << q(s.distances[d].sq) << "}";
  os << "], \"frame\": \"" << frame << "\"}";
  return os.str();
}

// The independent check of a configuration: every pairwise distance of every body, every
// distance, and no body mirrored, relative to the scene's size. Returns the worst relative error.
static double scene_error(const Scene& s, const RI::Configuration& c, double size, std::string& why)
{
  auto at = [&](int i) { return c.point(s.labels[std::size_t(i)]); };
  auto d2 = [](const std::array<double, 3>& a, const std::array<double, 3>& b) {
    double r = 0;
    for (int k = 0; k < 3; ++k) r += (a[std::size_t(k)] - b[std::size_t(k)]) * (a[std::size_t(k)] - b[std::size_t(k)]);
    return r;
  };
  double worst = 0;
  for (const auto& b : s.bodies) {
    for (std::size_t i = 0; i < b.pts.size(); ++i)
      for (std::size_t j = i + 1; j < b.pts.size(); ++j) {
        const double want = CGAL::to_double(sqdist(b.local[i], b.local[j]));
        const double e = std::abs(d2(at(b.pts[i]), at(b.pts[j])) - want) / (size * size);
        if (e > worst) { worst = e; why = "body " + b.name; }
      }
    // handedness: a tetrahedron of the body's points with a clear volume keeps its sign
    for (std::size_t i = 3; i < b.pts.size(); ++i) {
      const int o = orientation(b.local[0], b.local[1], b.local[2], b.local[i]);
      if (o == 0) continue;
      const QP u = b.local[1] - b.local[0], v = b.local[2] - b.local[0], w = b.local[i] - b.local[0];
      const double vol = CGAL::to_double(dot(cross(u, v), w));
      if (std::abs(vol) < 1e-6 * std::pow(size, 3)) continue;
      auto p0 = at(b.pts[0]), p1 = at(b.pts[1]), p2 = at(b.pts[2]), p3 = at(b.pts[i]);
      double a[3], bb[3], cc[3];
      for (int k = 0; k < 3; ++k) { a[k] = p1[std::size_t(k)] - p0[std::size_t(k)]; bb[k] = p2[std::size_t(k)] - p0[std::size_t(k)]; cc[k] = p3[std::size_t(k)] - p0[std::size_t(k)]; }
      const double det = a[0] * (bb[1] * cc[2] - bb[2] * cc[1]) - a[1] * (bb[0] * cc[2] - bb[2] * cc[0]) + a[2] * (bb[0] * cc[1] - bb[1] * cc[0]);
      if ((det > 0) != (o > 0)) { worst = 1; why = "body " + b.name + " mirrored"; }
    }
  }
  for (const auto& d : s.distances) {
    const double e = std::abs(d2(at(d.a), at(d.b)) - CGAL::to_double(d.sq)) / (size * size);
    if (e > worst) { worst = e; why = d.name; }
  }
  return worst;
}

// Whether the planted configuration is a singular point of the scene (independently of the
// package): the exact rank of the Jacobian, modulo the prime 2^61 - 1, of a world-coordinate
// formulation at the planted configuration falls short of its 3 unknowns per point. The
// frame body's points are fixed; every other body of 3 or more points holds its base triangle
// by 3 squared distances and each further point q at X_0 + a (X_1 - X_0) + b (X_2 - X_0) +
// c (X_1 - X_0) x (X_2 - X_0), with a, b, c from its local coordinates (a rigid body, not a
// framework of distances: a point in the plane of three others stays rigid); bars and distances
// are squared-distance equations. Full rank: the planted configuration is an isolated simple
// root, which the package must not call singular; short of it, in a complete answer of isolated
// configurations, a multiple one, which it must.
static bool planted_is_singular(const Scene& s, const std::string& frame)
{
  typedef unsigned __int128 U2;
  const std::uint64_t P = (std::uint64_t(1) << 61) - 1;
  auto mulm = [&](std::uint64_t a, std::uint64_t b) { return std::uint64_t((U2(a) * b) % P); };
  auto powm = [&](std::uint64_t a, std::uint64_t e) { std::uint64_t r = 1; for (; e; e >>= 1, a = mulm(a, a)) if (e & 1) r = mulm(r, a); return r; };
  auto modz = [&](const CGAL::Gmpz& z) {
    CGAL::Gmpz m = z % CGAL::Gmpz(long(P));
    if (m < 0) m += CGAL::Gmpz(long(P));
    return std::uint64_t(mpz_get_ui(m.mpz()));
  };
  auto mod = [&](const Q& q) { return mulm(modz(q.numerator()), powm(modz(q.denominator()), P - 2)); };
  const std::size_t n = 3 * s.labels.size();
  std::vector<std::vector<Q>> rows;
  auto add = [&](std::vector<Q>& row, int point, int k, const Q& v) { row[3 * std::size_t(point) + std::size_t(k)] += v; };
  auto coords = [](const QP& p) { return std::array<Q, 3>{p.x, p.y, p.z}; };
  auto distance_row = [&](int a, int b) {
    std::vector<Q> row(n, Q(0));
    const auto d = coords(s.global[std::size_t(a)] - s.global[std::size_t(b)]);
    for (int k = 0; k < 3; ++k) { add(row, a, k, 2 * d[std::size_t(k)]); add(row, b, k, -2 * d[std::size_t(k)]); }
    rows.push_back(row);
  };
  for (const auto& b : s.bodies) {
    if (b.name == frame) {
      for (int q : b.pts)
        for (int k = 0; k < 3; ++k) { std::vector<Q> row(n, Q(0)); add(row, q, k, Q(1)); rows.push_back(row); }
      continue;
    }
    if (b.pts.size() == 2) { distance_row(b.pts[0], b.pts[1]); continue; }
    std::size_t i1 = 0, i2 = 0;  // a base triangle off a line, with point 0
    for (std::size_t x = 1; x < b.pts.size() && i2 == 0; ++x)
      for (std::size_t y = x + 1; y < b.pts.size() && i2 == 0; ++y)
        if (!collinear(b.local[0], b.local[x], b.local[y])) { i1 = x; i2 = y; }
    if (i2 == 0) throw std::logic_error("test scene: body " + b.name + " on a line");
    distance_row(b.pts[0], b.pts[i1]);
    distance_row(b.pts[0], b.pts[i2]);
    distance_row(b.pts[i1], b.pts[i2]);
    const QP ul = b.local[i1] - b.local[0], vl = b.local[i2] - b.local[0], wl = cross(ul, vl);
    const Q det = dot(ul, cross(vl, wl));
    const QP u = s.global[std::size_t(b.pts[i1])] - s.global[std::size_t(b.pts[0])];
    const QP v = s.global[std::size_t(b.pts[i2])] - s.global[std::size_t(b.pts[0])];
    // [w]x, the matrix of x -> w x x
    auto crossm = [](const QP& w, int r, int c) {
      const Q m[3][3] = {{0, -w.z, w.y}, {w.z, 0, -w.x}, {-w.y, w.x, 0}};
      return m[r][c];
    };
    for (std::size_t i = 1; i < b.pts.size(); ++i) {
      if (i == i1 || i == i2) continue;
      const QP d = b.local[i] - b.local[0];
      // d = a ul + b vl + c wl, by Cramer's rule
      const Q a = dot(d, cross(vl, wl)) / det, bb = dot(ul, cross(d, wl)) / det, c = dot(ul, cross(vl, d)) / det;
      for (int r = 0; r < 3; ++r) {
        std::vector<Q> row(n, Q(0));
        add(row, b.pts[i], r, Q(1));
        for (int k = 0; k < 3; ++k) {
          const Q id = r == k ? Q(1) : Q(0);
          add(row, b.pts[0], k, -(Q(1) - a - bb) * id - c * crossm(v - u, r, k));
          add(row, b.pts[i1], k, -a * id + c * crossm(v, r, k));
          add(row, b.pts[i2], k, -bb * id - c * crossm(u, r, k));
        }
        rows.push_back(row);
      }
    }
  }
  for (const auto& d : s.distances) distance_row(d.a, d.b);
  // rank modulo P
  std::vector<std::vector<std::uint64_t>> m;
  for (const auto& row : rows) { std::vector<std::uint64_t> r; for (const Q& x : row) r.push_back(mod(x)); m.push_back(r); }
  std::size_t rank = 0;
  for (std::size_t col = 0; col < n && rank < m.size(); ++col) {
    std::size_t piv = rank;
    while (piv < m.size() && m[piv][col] == 0) ++piv;
    if (piv == m.size()) continue;
    std::swap(m[piv], m[rank]);
    const std::uint64_t inv = powm(m[rank][col], P - 2);
    for (std::size_t r = 0; r < m.size(); ++r) {
      if (r == rank || m[r][col] == 0) continue;
      const std::uint64_t f = mulm(m[r][col], inv);
      for (std::size_t c2 = col; c2 < n; ++c2) m[r][c2] = (m[r][c2] + P - mulm(f, m[rank][c2])) % P;
    }
    ++rank;
  }
  return rank < n;
}

int main(int argc, char** argv)
{
  const int scenes = argc > 1 ? std::atoi(argv[1]) : 150;
  const unsigned seed = argc > 2 ? unsigned(std::atol(argv[2])) : 20261127u;
  const bool flat = argc > 3 && std::string(argv[3]) == "flat";
  const bool verbose = argc > 4 && std::string(argv[4]) == "verbose";  // each scene on stderr before it is solved
  // scenes before FIRST are generated (the random sequence is the same) but not solved
  const int first = argc > 5 ? std::atoi(argv[5]) : 0;
  Rng g(seed);
  int planted_singular = 0;  // complete answers whose planted configuration is a singular point
  int solved = 0, complete = 0, incomplete = 0, refused = 0, skipped = 0, configurations = 0, on_border = 0;
  auto t0 = std::chrono::steady_clock::now();
  for (int n = 0; n < scenes; ++n) {
    const int steps = g.uniform(1, 4);
    const int e = g.uniform(0, 5) == 0 ? g.uniform(-50, 50) : 0;  // 10^e
    Q scale(1);
    for (int k = 0; k < (e < 0 ? -e : e); ++k) scale = e < 0 ? scale / Q(10) : scale * Q(10);
    Generated gen = grow(g, steps, scale, flat);
    const std::string what = "scene " + std::to_string(n) + " (seed " + std::to_string(seed) + ", scale 1e" + std::to_string(e) + ": " + gen.structure + ")";
    if (n < first) continue;
    if (verbose) std::cerr << what << "\n  " << to_json(gen.s, gen.frame) << std::endl;
    RI::Scene_solve_result r;
    try {
      RI::Rigid_body_collection<Traits> input = make_collection<Traits>(gen.s);
      input.set_frame(gen.frame);
      RI::Rigid_body_collection<Traits> c = RI::standardize(input);
      RI::Dof_count dof = RI::dof_count(c);
      if (dof.dof != 0 || !dof.connected) { ++skipped; continue; }
      RI::Incidence_tree t = RI::optimal_incidence_tree(c);
      RI::Well_formed_selection wf = RI::select_well_formed_incidences(c, t);
      const bool exact = RI::exact_coefficients(c, t);
      RI::Scene_solve_parameters p;
      p.solver.maximal_boxes = 20000;
      // multiple roots everywhere (every fold at its double point), or a rail point's touching
      // spheres left to the reduced system (a double root, retried at more bits until the box
      // budget ends, in every chart combination): not worth more precision
      if (flat || gen.structure.find("rail") != std::string::npos) {
        p.solver.maximal_boxes = 5000;
        p.maximal_coefficient_precision = 53;
      }
      if (exact) r = RI::solve_scene<CGAL::Interval_nt<false>, CGAL::Gmpq>(input, c, t, wf, p);
      else r = RI::solve_scene<CGAL::Interval_nt<false>, CGAL::Interval_nt<false>>(input, c, t, wf, p);
    } catch (const RI::Input_error& ex) {
      // a well-formed scene with a planted configuration is never refused (issue 27, item 3)
      ++refused;
      CHECK(false, what << ": refused: " << ex.what() << "\n  " << to_json(gen.s, gen.frame));
      continue;
    }
    ++solved;
    if (!r.diagnosis.empty()) {  // not square, or flexes: diagnosed, not answered
      ++incomplete;
      std::cout << what << ": diagnosed: " << r.diagnosis << "\n";
      continue;
    }
    // the planted configuration, in the frame of b0
    double size = 0;
    for (const auto& b : gen.s.bodies)
      for (std::size_t i = 0; i < b.local.size(); ++i)
        for (std::size_t j = i + 1; j < b.local.size(); ++j) size = std::max(size, std::sqrt(CGAL::to_double(sqdist(b.local[i], b.local[j]))));
    bool planted = false, planted_singular_flag = false;
    double nearest = std::numeric_limits<double>::infinity();  // of the planted configuration, relative
    for (const auto& x : r.configurations) {
      std::string why;
      const double err = scene_error(gen.s, x.configuration, size, why);
      // tighter than the library's own threshold (1e-6), so that a wrong placement it lets
      // through is caught here
      CHECK(err <= 1e-9, what << ": a configuration is off by " << err << " (relative) at " << why << "\n  " << to_json(gen.s, gen.frame));
      // planted: every point where the planted configuration has it in b0's frame
      double dev = 0;
      for (std::size_t i = 0; i < gen.s.labels.size(); ++i) {
        const auto p = x.configuration.point(gen.s.labels[i]);
        const QP w = gen.root.apply(gen.s.global[i]);
        dev = std::max(dev, std::abs(p[0] - CGAL::to_double(w.x)) + std::abs(p[1] - CGAL::to_double(w.y)) + std::abs(p[2] - CGAL::to_double(w.z)));
      }
      nearest = std::min(nearest, dev / size);
      // to the library's own threshold: the points of a body outside the covering set come from
      // a rigid fit in doubles, which an apex 1e-5 off its hinge makes 1e5 times less accurate
      // (4e-7 of the size measured); a dropped placement or root is farther by far
      // (an apex 1e-5 off its hinge turns the body about the hinge by an angle known 1e5 times
      // less well than the distance that holds it: 1.2e-6 measured, seed 3, scene 597)
      const bool same = dev <= (gen.structure.find("flat-hinge") != std::string::npos ? 1e-4 : 1e-6) * size;
      planted = planted || same;
      if (same) planted_singular_flag = x.singular;
      if (same && x.on_chart_border) ++on_border;
    }
    configurations += int(r.configurations.size());
    // no configuration twice
    for (std::size_t a = 0; a < r.configurations.size(); ++a)
      for (std::size_t b = a + 1; b < r.configurations.size(); ++b) {
        double d = 0;
        for (const auto& l : gen.s.labels) {
          const auto p = r.configurations[a].configuration.point(l), q = r.configurations[b].configuration.point(l);
          for (int k = 0; k < 3; ++k) d = std::max(d, std::abs(p[std::size_t(k)] - q[std::size_t(k)]));
        }
        CHECK(d > 1e-9 * size, what << ": configurations " << a + 1 << " and " << b + 1 << " are the same\n  " << to_json(gen.s, gen.frame));
      }
    if (r.complete()) {
      ++complete;
      std::ostringstream pl;
      for (std::size_t i = 0; i < gen.s.labels.size(); ++i) {
        const QP w = gen.root.apply(gen.s.global[i]);
        pl << " " << gen.s.labels[i] << " = (" << CGAL::to_double(w.x) << ", " << CGAL::to_double(w.y) << ", " << CGAL::to_double(w.z) << ")";
      }
      CHECK(planted, what << ": complete with " << r.configurations.size() << " configurations, without the planted one (nearest "
                          << nearest << " of the size away):" << pl.str()
                          << "\n  " << to_json(gen.s, gen.frame));
      // singular exactly when the Jacobian at the planted configuration is short of rank
      const bool singular = planted_is_singular(gen.s, gen.frame);
      if (singular) ++planted_singular;
      CHECK(!planted || planted_singular_flag == singular,
            what << ": the planted configuration is " << (singular ? "" : "not ") << "a singular point (exact Jacobian rank), but the"
                 << " answer calls it " << (planted_singular_flag ? "singular" : "a simple root") << "\n  " << to_json(gen.s, gen.frame));
    } else {
      ++incomplete;
      // visible, not a failure: why this scene's answer is not complete
      std::string why = !r.limits.empty() ? "limit: " + r.limits.front()
                        : !r.unresolved.empty() ? std::to_string(r.unresolved.size()) + " unresolved region(s), the first: " + r.unresolved.front().reason
                        : "configurations not certified";
      std::cout << what << ": not complete (" << r.configurations.size() << " configurations; " << why << ")\n";
    }
  }
  const double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  std::cout << "test_random_planted_scenes: " << scenes << " scenes (seed " << seed << "): " << solved << " solved (" << complete
            << " complete, " << incomplete << " not complete or diagnosed), " << configurations << " configurations; " << refused
            << " refused, " << skipped << " not well-constrained by the count; " << on_border
            << " planted configurations found on a chart border; " << planted_singular
            << " complete answers whose planted configuration is singular; " << secs << " s\n";
  // a regression to "everything incomplete" must not pass: on the seeds measured, all but 1 or 2
  // of 300 solved scenes are complete
  // (flat scenes: multiple roots and placements decided exactly, not counted)
  CHECK(flat || first > 0 || solved == 0 || 10 * complete >= 9 * solved, complete << " complete answers of " << solved << " solved scenes");
  // the quarter turns put roots on chart borders: a generator that no longer does tests less
  CHECK(flat || first > 0 || scenes < 100 || on_border > 0, "no planted configuration on a chart border in " << scenes << " scenes");
  if (failures) { std::cerr << failures << " check(s) failed\n"; return 1; }
  return 0;
}
