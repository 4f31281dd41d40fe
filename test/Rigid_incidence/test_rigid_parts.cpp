// Copyright (c) 2026 Rigid_incidence contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Scenes whose bodies share three points with distances that run through placements (issue
// 27, item 3: once refused as "not supported yet"). standardize() keeps one body as a rigid
// part of the merged or implied body, and enumerate_placements() superposes it. Each scene is
// planted (exact rational points, every body in its own random rational frame) and solved
// as `rigid_incidence solve` does; the answer is compared, configuration by configuration,
// with an independent construction:
// - the chains b0{A,B,C} b1{A,B,D,E} b2{D,E,F} b3{C,F,G} + |GA|, |EC|, and
//   b0{H1,H2,U,V} b1{H1,H2,M,N} b2{E,G,M,U} + |GV|: every configuration by intersecting the
//   circle a hinged point runs on with the sphere a distance puts it on, one hinge after the
//   other (long double);
// - rings of n triangles (one per atom: its two bonds and bond angle; consecutive triangles
//   share a bond; n - 6 torsions fixed by 1-4 distances): the chain of n - 3 atoms by
//   trilateration (2^(n-6) placements), then the closure of the last three atoms as the
//   zeros of one function along the curve where one closure distance holds, found by sign
//   changes over 20000 samples and at the curve's turning points.
// Checks: the same number of configurations, each oracle configuration matched by one of the
// package's (same pairwise distances to 1e-7 of the size: configurations come in mirror
// pairs through the frame's plane), all certified, complete.
// - a flat ring of 9 (every atom in one plane): the planted configuration, a multiple root,
//   must be among the answers, marked singular, and the answer not complete.

#include <CGAL/Gmpq.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Rigid_incidence.h>

#include "planted_scene.h"
#include "test_check.h"
#include "solve_scene_instances.h"

#include <algorithm>
#include <cmath>
#include <iostream>
#include <map>
#include <string>
#include <vector>

namespace RI = CGAL::Rigid_incidence;
using namespace planted;
typedef RI::Rigid_incidence_traits<CGAL::Simple_cartesian<CGAL::Gmpq>> Traits;


// ------------------------------------------------------------------ long double geometry
typedef long double R;
struct V { R x, y, z; };
static V operator+(V a, V b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
static V operator-(V a, V b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
static V operator*(R s, V a) { return {s * a.x, s * a.y, s * a.z}; }
static R dot(V a, V b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
static V cross(V a, V b) { return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x}; }
static R sq(V a, V b) { return dot(a - b, a - b); }
static V ld(const QP& p) { return {R(CGAL::to_double(p.x)), R(CGAL::to_double(p.y)), R(CGAL::to_double(p.z))}; }

// The two points at squared distances dp, dq, dr from p, q, r (none if they do not exist).
static std::vector<V> trilaterate(V p, V q, V r, R dp, R dq, R dr)
{
  const V u = q - p, v = r - p;
  const R uu = dot(u, u), vv = dot(v, v), uv = dot(u, v), G = uu * vv - uv * uv;
  const R al = (dp - dq + uu) / 2, be = (dp - dr + vv) / 2;
  const R a = (al * vv - be * uv) / G, b = (be * uu - al * uv) / G;
  const R s = (dp - (a * a * uu + 2 * a * b * uv + b * b * vv)) / G;
  if (s < 0) return {};
  const V w = p + a * u + b * v, n = cross(u, v);
  const R t = std::sqrt(s);
  return {w + t * n, w - t * n};
}

// The circle of points at squared distances dp and dq from p and q.
struct Circle
{
  V c, e1, e2;
  R r = 0;
  V at(R t) const { return c + r * (std::cos(t) * e1 + std::sin(t) * e2); }
  // the angles where it meets the sphere of squared radius d2 around s
  std::vector<R> meet(V s, R d2) const
  {
    const V w = c - s;
    const R al = 2 * r * dot(w, e1), be = 2 * r * dot(w, e2), ga = d2 - dot(w, w) - r * r;
    const R h = std::hypot(al, be);
    if (std::abs(ga) > h) return {};
    const R ph = std::atan2(be, al), ac = std::acos(ga / h);
    return {ph + ac, ph - ac};
  }
};
static Circle circle(V p, V q, R dp, R dq)
{
  const V ax = q - p;
  const R L = std::sqrt(dot(ax, ax));
  const V n = (1 / L) * ax;
  const R x = (dp - dq + L * L) / (2 * L);
  Circle C;
  C.c = p + x * n;
  C.r = std::sqrt(std::max(R(0), dp - x * x));
  V e = std::abs(n.x) < 0.9L ? cross(n, V{1, 0, 0}) : cross(n, V{0, 1, 0});
  C.e1 = (1 / std::sqrt(dot(e, e))) * e;
  C.e2 = cross(n, C.e1);
  return C;
}

// Where point y goes when the triangle (a, b, c) is moved rigidly onto (x0, x1, x2).
static V carry(V a, V b, V c, V y, V x0, V x1, V x2)
{
  const V u2 = b - a, v2 = c - a, w2 = cross(u2, v2), u1 = x1 - x0, v1 = x2 - x0, w1 = cross(u1, v1);
  const R uu = dot(u2, u2), vv = dot(v2, v2), uv = dot(u2, v2), G = dot(w2, w2);
  const V d = y - a;
  const R du = dot(d, u2), dv = dot(d, v2);
  return x0 + ((vv * du - uv * dv) / G) * u1 + ((uu * dv - uv * du) / G) * v1 + (dot(d, w2) / G) * w1;
}

typedef std::map<std::string, V> Config;

// ------------------------------------------------------------------ the package's answer
struct Answer
{
  std::vector<Config> configurations;
  std::vector<bool> singular;  // per configuration
  bool complete = false, certified = true;
};

static Answer solve(const Scene& s, const std::string& frame, unsigned maximal_coefficient_precision = 256)
{
  RI::Rigid_body_collection<Traits> input = make_collection<Traits>(s);
  input.set_frame(frame);
  RI::Rigid_body_collection<Traits> c = RI::standardize(input);
  RI::Incidence_tree t = RI::optimal_incidence_tree(c);
  RI::Well_formed_selection wf = RI::select_well_formed_incidences(c, t);
  RI::Scene_solve_parameters parameters;
  parameters.maximal_coefficient_precision = maximal_coefficient_precision;
  RI::Scene_solve_result r = RI::solve_scene<CGAL::Interval_nt<false>, CGAL::Interval_nt<false>>(input, c, t, wf, parameters);
  Answer a;
  a.complete = r.complete();
  for (const auto& x : r.configurations) {
    a.certified = a.certified && x.certified;
    Config m;
    for (const auto& l : s.labels) {
      const auto p = x.configuration.point(l);
      m[l] = V{R(p[0]), R(p[1]), R(p[2])};
    }
    a.configurations.push_back(m);
    a.singular.push_back(x.singular);
  }
  return a;
}

// The pairwise distances of a configuration, in label order (the same for a mirror image).
static std::vector<R> shape(const Config& c)
{
  std::vector<R> d;
  for (auto i = c.begin(); i != c.end(); ++i)
    for (auto j = std::next(i); j != c.end(); ++j) d.push_back(std::sqrt(sq(i->second, j->second)));
  return d;
}
static R shape_distance(const std::vector<R>& a, const std::vector<R>& b)
{
  R m = 0;
  for (std::size_t i = 0; i < a.size(); ++i) m = std::max(m, std::abs(a[i] - b[i]));
  return m;
}
static R frame_distance(const Config& a, const Config& b)
{
  R m = 0;
  for (const auto& p : a) m = std::max(m, std::sqrt(sq(p.second, b.at(p.first))));
  return m;
}

// Every oracle configuration matched one to one; `same_frame`: by position (both in the
// frame of b0), else by shape (with multiplicities).
static void compare(const std::string& what, const Answer& got, const std::vector<Config>& want, R size, bool same_frame)
{
  CHECK(got.complete, what << ": not complete");
  CHECK(got.certified, what << ": a configuration is not certified");
  CHECK(got.configurations.size() == want.size(), what << ": " << got.configurations.size() << " configurations, the construction gives "
                                                       << want.size());
  std::vector<bool> used(got.configurations.size(), false);
  for (std::size_t w = 0; w < want.size(); ++w) {
    bool found = false;
    for (std::size_t k = 0; k < got.configurations.size() && !found; ++k) {
      if (used[k]) continue;
      const R d = same_frame ? frame_distance(want[w], got.configurations[k]) : shape_distance(shape(want[w]), shape(got.configurations[k]));
      if (d <= 1e-7L * size) used[k] = found = true;
    }
    CHECK(found, what << ": configuration " << w + 1 << " of the construction is missing");
  }
}

static R scene_size(const Scene& s)
{
  R m = 0;
  for (std::size_t i = 0; i < s.global.size(); ++i)
    for (std::size_t j = i + 1; j < s.global.size(); ++j) m = std::max(m, std::sqrt(sq(ld(s.global[i]), ld(s.global[j]))));
  return m;
}

// ------------------------------------------------------------------ the chains
// b0{A,B,C} (frame) b1{A,B,D,E} b2{D,E,F} b3{C,F,G}, |GA|, |EC|
static void chain_one(Rng& g, int k)
{
  Scene s = generic_points(g, {"A", "B", "C", "D", "E", "F", "G"});
  Rigid root = random_rigid(g);
  s.add_body("b0", {"A", "B", "C"}, root);
  s.add_body("b1", {"A", "B", "D", "E"}, random_rigid(g));
  s.add_body("b2", {"D", "E", "F"}, random_rigid(g));
  s.add_body("b3", {"C", "F", "G"}, random_rigid(g));
  s.add_distance("G", "A");
  s.add_distance("E", "C");
  auto P = [&](const std::string& l) { return ld(root.apply(s.at(l))); };  // planted, in b0's frame
  auto d = [&](const std::string& a, const std::string& b) { return R(CGAL::to_double(s.sq(a, b))); };
  std::vector<Config> want;
  const V A = P("A"), B = P("B"), C = P("C");
  for (R t1 : circle(A, B, d("E", "A"), d("E", "B")).meet(C, d("E", "C"))) {
    const V E = circle(A, B, d("E", "A"), d("E", "B")).at(t1);
    const V D = carry(A, B, P("E"), P("D"), A, B, E);
    const Circle cf = circle(D, E, d("F", "D"), d("F", "E"));
    for (R t2 : cf.meet(C, d("C", "F"))) {
      const V F = cf.at(t2);
      const Circle cg = circle(C, F, d("G", "C"), d("G", "F"));
      for (R t3 : cg.meet(A, d("G", "A"))) want.push_back(Config{{"A", A}, {"B", B}, {"C", C}, {"D", D}, {"E", E}, {"F", F}, {"G", cg.at(t3)}});
    }
  }
  compare("chain 1, scene " + std::to_string(k), solve(s, "b0"), want, scene_size(s), true);
}

// b0{H1,H2,U,V} (frame) b1{H1,H2,M,N} b2{E,G,M,U}, |GV|
static void chain_two(Rng& g, int k)
{
  Scene s = generic_points(g, {"H1", "H2", "U", "V", "M", "N", "E", "G"});
  Rigid root = random_rigid(g);
  s.add_body("b0", {"H1", "H2", "U", "V"}, root);
  s.add_body("b1", {"H1", "H2", "M", "N"}, random_rigid(g));
  s.add_body("b2", {"E", "G", "M", "U"}, random_rigid(g));
  s.add_distance("G", "V");
  auto P = [&](const std::string& l) { return ld(root.apply(s.at(l))); };
  auto d = [&](const std::string& a, const std::string& b) { return R(CGAL::to_double(s.sq(a, b))); };
  std::vector<Config> want;
  const V H1 = P("H1"), H2 = P("H2"), U = P("U"), Vv = P("V");
  const Circle cm = circle(H1, H2, d("M", "H1"), d("M", "H2"));
  for (R t1 : cm.meet(U, d("M", "U"))) {
    const V M = cm.at(t1), N = carry(H1, H2, P("M"), P("N"), H1, H2, M);
    const Circle cg = circle(M, U, d("G", "M"), d("G", "U"));
    for (R t2 : cg.meet(Vv, d("G", "V"))) {
      const V G = cg.at(t2), E = carry(P("M"), P("U"), P("G"), P("E"), M, U, G);
      want.push_back(Config{{"H1", H1}, {"H2", H2}, {"U", U}, {"V", Vv}, {"M", M}, {"N", N}, {"E", E}, {"G", G}});
    }
  }
  compare("chain 2, scene " + std::to_string(k), solve(s, "b0"), want, scene_size(s), true);
}

// ------------------------------------------------------------------ rings
static std::string atom(int k, int n) { return "A" + std::to_string(((k % n) + n) % n); }

static void ring(Rng& g, int n, int k)
{
  std::vector<std::string> ls;
  for (int i = 0; i < n; ++i) ls.push_back(atom(i, n));
  Scene s;
  const long double pi = std::acos(-1.0L);
  for (int i = 0; i < n; ++i) {  // around a circle of radius 5, each coordinate off by up to 1/4
    const R a = 2 * pi * i / n;
    s.add_point(ls[std::size_t(i)], QP{Q(int(std::lround(40 * std::cos(a))) + g.uniform(-2, 2), 8),
                                       Q(int(std::lround(40 * std::sin(a))) + g.uniform(-2, 2), 8), Q(g.uniform(-8, 8), 8)});
  }
  for (int i = 0; i < n; ++i) s.add_body("b" + std::to_string(i), {atom(i - 1, n), atom(i, n), atom(i + 1, n)}, random_rigid(g));
  for (int i = 1; i < n - 5; ++i) s.add_distance(atom(i - 1, n), atom(i + 2, n));
  auto d = [&](int a, int b) { return R(CGAL::to_double(s.sq(atom(a, n), atom(b, n)))); };

  // the chain A0 .. A(n-4): a canonical start, then each atom from the three before it
  const R L = std::sqrt(d(0, 1)), x2 = (d(0, 1) + d(0, 2) - d(1, 2)) / (2 * L);
  std::vector<std::vector<V>> chains{{V{0, 0, 0}, V{L, 0, 0}, V{x2, std::sqrt(d(0, 2) - x2 * x2), 0}}};
  for (int i = 1; i < n - 5; ++i) {
    std::vector<std::vector<V>> next;
    for (const auto& c : chains)
      for (const V& x : trilaterate(c[std::size_t(i - 1)], c[std::size_t(i)], c[std::size_t(i + 1)], d(i + 2, i - 1), d(i + 2, i), d(i + 2, i + 1))) {
        next.push_back(c);
        next.back().push_back(x);
      }
    chains = next;
  }
  // the closure: X = A(n-3) on its circle about A(n-5) A(n-4) (angle t), Z = A(n-1) where its
  // circle about A1 A0 meets the sphere |XZ| (branch), Y = A(n-2) from A(n-4), X, A0 (side);
  // a configuration where |YZ| holds
  std::vector<Config> want;
  const int N = 20000;
  for (const auto& c : chains) {
    const Circle cx = circle(c[std::size_t(n - 5)], c[std::size_t(n - 4)], d(n - 3, n - 5), d(n - 3, n - 4));
    const Circle cz = circle(c[1], c[0], d(n - 1, 1), d(n - 1, 0));
    struct Point_of { bool ok; Config q; R f; };
    auto at = [&](R t, int branch, int side) {
      Point_of o{false, {}, 0};
      const V X = cx.at(t);
      std::vector<R> t2 = cz.meet(X, d(n - 3, n - 1));
      if (t2.empty()) return o;
      const V Z = cz.at(t2[std::size_t(branch)]);
      std::vector<V> Y = trilaterate(c[std::size_t(n - 4)], X, c[0], d(n - 2, n - 4), d(n - 2, n - 3), d(n - 2, 0));
      if (Y.empty()) return o;
      o.ok = true;
      for (int i = 0; i <= n - 4; ++i) o.q[atom(i, n)] = c[std::size_t(i)];
      o.q[atom(n - 3, n)] = X;
      o.q[atom(n - 2, n)] = Y[std::size_t(side)];
      o.q[atom(n - 1, n)] = Z;
      o.f = sq(Y[std::size_t(side)], Z) - d(n - 2, n - 1);
      return o;
    };
    auto root_between = [&](R lo, R hi, int branch, int side) {
      Point_of a = at(lo, branch, side);
      for (int it = 0; it < 80; ++it) {
        const R m = (lo + hi) / 2;
        Point_of p = at(m, branch, side);
        if (!p.ok) break;
        if ((a.f < 0) == (p.f < 0)) { lo = m; a = p; } else hi = m;
      }
      return a.q;
    };
    // samples of the four (branch, side) pieces of the curve; a piece ends where Z's branches
    // join (its partner: the other branch) or where Y's two sides join (the other side)
    std::vector<Point_of> v[2][2];
    for (int b = 0; b < 2; ++b)
      for (int sd = 0; sd < 2; ++sd)
        for (int i = 0; i <= N; ++i) v[b][sd].push_back(at(2 * pi * i / N, b, sd));
    for (int b = 0; b < 2; ++b)
      for (int sd = 0; sd < 2; ++sd) {
        const auto& w = v[b][sd];
        for (int i = 0; i < N; ++i) {
          const R t0 = 2 * pi * i / N, t1 = 2 * pi * (i + 1) / N;
          if (w[std::size_t(i)].ok && w[std::size_t(i + 1)].ok) {
            if ((w[std::size_t(i)].f < 0) != (w[std::size_t(i + 1)].f < 0)) want.push_back(root_between(t0, t1, b, sd));
            continue;
          }
          if (w[std::size_t(i)].ok == w[std::size_t(i + 1)].ok) continue;
          // the piece ends between t0 and t1: find where, and which piece it joins there
          R in = w[std::size_t(i)].ok ? t0 : t1, out = w[std::size_t(i)].ok ? t1 : t0;
          for (int it = 0; it < 80; ++it) { const R m = (in + out) / 2; (at(m, b, sd).ok ? in : out) = m; }
          const bool z_ends = cz.meet(cx.at(out), d(n - 3, n - 1)).empty();
          const int pb = z_ends ? 1 - b : b, ps = z_ends ? sd : 1 - sd;
          if (pb * 2 + ps < b * 2 + sd) continue;  // each join once
          const R te = w[std::size_t(i)].ok ? t0 : t1;
          const Point_of here = at(te, b, sd), there = at(te, pb, ps), end = at(in, b, sd);
          if (!there.ok || (here.f < 0) == (there.f < 0)) continue;
          // a zero on this piece between te and the end, or else on the partner
          if ((here.f < 0) != (end.f < 0)) want.push_back(root_between(te, in, b, sd));
          else want.push_back(root_between(te, in, pb, ps));
        }
      }
  }
  const std::string what = "ring of " + std::to_string(n) + ", scene " + std::to_string(k);
  Answer got = solve(s, "b0");
  compare(what, got, want, scene_size(s), false);
  std::cout << what << ": " << got.configurations.size() << " configurations, the construction " << want.size() << "\n";
}

// A flat ring: every atom in one plane, so every torsion is at its extreme (cis or trans) and
// the planted configuration is a multiple root (issue 27, item 2: it came out as 0
// configurations). It must be among the answers, marked singular, and the answer not complete
// (a multiple root is not certified). The coefficients stop at 128 bits (the test's time).
static void flat_ring(Rng& g, int n)
{
  Scene s;
  const long double pi = std::acos(-1.0L);
  for (int i = 0; i < n; ++i) {
    const R a = 2 * pi * i / n;
    s.add_point(atom(i, n), QP{Q(int(std::lround(40 * std::cos(a))) + g.uniform(-2, 2), 8),
                               Q(int(std::lround(40 * std::sin(a))) + g.uniform(-2, 2), 8), Q(0)});
  }
  for (int i = 0; i < n; ++i) s.add_body("b" + std::to_string(i), {atom(i - 1, n), atom(i, n), atom(i + 1, n)}, random_rigid(g));
  for (int i = 1; i < n - 5; ++i) s.add_distance(atom(i - 1, n), atom(i + 2, n));
  Config planted;
  for (std::size_t i = 0; i < s.labels.size(); ++i) planted[s.labels[i]] = ld(s.global[i]);
  const std::string what = "flat ring of " + std::to_string(n);
  Answer got = solve(s, "b0", 128);
  bool found = false;
  for (std::size_t k = 0; k < got.configurations.size(); ++k)
    if (shape_distance(shape(planted), shape(got.configurations[k])) <= 1e-5L * scene_size(s)) {
      found = true;
      CHECK(got.singular[k], what << ": the flat configuration is not marked singular");
    }
  CHECK(found, what << ": the flat configuration is missing (" << got.configurations.size() << " configurations)");
  CHECK(!got.complete, what << ": complete, with a multiple root");
  std::cout << what << ": " << got.configurations.size() << " configuration(s), the flat one singular\n";
}

int main(int argc, char** argv)
{
  const int scenes = argc > 1 ? std::atoi(argv[1]) : 10;
  Rng g(20261127);
  for (int k = 0; k < scenes; ++k) {
    chain_one(g, k);
    chain_two(g, k);
  }
  for (int n : {9, 11, 13}) ring(g, n, 0);
  flat_ring(g, 9);
  std::cout << "test_rigid_parts: " << scenes << " scenes of each chain, rings of 9, 11 and 13; " << failures << " failure(s)\n";
  return failures ? 1 : 0;
}
