// Copyright (c) 2026 Rigid_incidence contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Bodies placed through long chains of trilaterations, solved whole by solve_scene against an
// oracle that trilaterates the configurations in 256-bit MPFR floating point (CORE::Expr's exact
// square roots take minutes on these nested radicals):
// - braced triangle strips (k triangles p_i p_{i+1} p_{i+2} hinged edge to edge, braced by the
//   distances p_i - p_{i+3}): standardization merges them into one body with 2^(k-1)
//   placements, each fold up or down. All of them, certified, for k up to 12 (a cap of 64
//   placements once gave "64 configurations, complete" out of 128); their enclosures are
//   computed at the precision they need;
// - the flat strip (a planted configuration in a plane: every fold at its double point): one
//   configuration, decided exactly, marked singular, to the tolerance;
// - a triangle whose apex is 1e-7 or 1e-10 off its hinge, held by one distance: both
//   configurations, though they are that close (the mirror side was dropped when the height
//   interval touched 0, and configurations that close were merged);
// - the placement limit: a body with more placements than maximal_placements is reported, the
//   result not complete; enclose_all_placements() throws rather than shorten its list.

#include <CGAL/Gmpfr.h>
#include <CGAL/Gmpq.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Rigid_incidence.h>
#include "solve_scene_instances.h"

#include "planted_scene.h"

#include <cmath>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

namespace RI = CGAL::Rigid_incidence;
using namespace planted;
typedef RI::Rigid_incidence_traits<CGAL::Simple_cartesian<CGAL::Gmpq>> Traits;
typedef CGAL::Gmpfr E;
typedef std::array<E, 3> EP;

static int failures = 0;
#define CHECK(cond, msg)                                                        \
  do {                                                                          \
    if (!(cond)) {                                                              \
      ++failures;                                                               \
      std::cerr << "FAILED: " << msg << "  (" << __FILE__ << ":" << __LINE__ << ")\n"; \
    }                                                                           \
  } while (0)

static E qe(const Q& q) { return E(q.numerator()) / E(q.denominator()); }
static EP ep(const QP& p) { return EP{qe(p.x), qe(p.y), qe(p.z)}; }
static E edot(const EP& a, const EP& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
static EP esub(const EP& a, const EP& b) { return EP{a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
static EP ecross(const EP& a, const EP& b)
{ return EP{a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]}; }

// The oracle: the points at squared distances r1, r2, r3 from A, B, C (two: the scenes are
// generic, and a squared height below 2^-200 of the scale is an error of the test).
static std::vector<EP> trilaterate(const EP& A, const EP& B, const EP& C, const Q& r1, const Q& r2, const Q& r3)
{
  EP u = esub(B, A), v = esub(C, A), n = ecross(u, v);
  E uu = edot(u, u), vv = edot(v, v), uv = edot(u, v), nn = edot(n, n);
  E alpha = (qe(r1) - qe(r2) + uu) / E(2), beta = (qe(r1) - qe(r3) + vv) / E(2);
  E a = (alpha * vv - beta * uv) / nn, b = (beta * uu - alpha * uv) / nn;
  EP w{A[0] + a * u[0] + b * v[0], A[1] + a * u[1] + b * v[1], A[2] + a * u[2] + b * v[2]};
  EP d = esub(w, A);
  E t2 = (qe(r1) - edot(d, d)) / nn;
  if (CGAL::abs(t2) < E(std::ldexp(1.0, -200)) * (qe(r1) + uu + vv) / nn) {
    CHECK(false, "oracle: a squared height too close to 0 to decide in 256 bits");
    return {};
  }
  if (t2 < 0) return {};
  E t = CGAL::sqrt(t2);
  return {EP{w[0] + t * n[0], w[1] + t * n[1], w[2] + t * n[2]}, EP{w[0] - t * n[0], w[1] - t * n[1], w[2] - t * n[2]}};
}

typedef std::vector<std::array<double, 3>> Points;  // by the scene's label order
static std::array<double, 3> to3(const EP& p) { return {CGAL::to_double(p[0]), CGAL::to_double(p[1]), CGAL::to_double(p[2])}; }

static RI::Scene_solve_result solve(const Scene& s, const std::string& frame, std::size_t maximal_placements = RI::default_maximal_placements)
{
  RI::Rigid_body_collection<Traits> input = make_collection<Traits>(s);
  input.set_frame(frame);
  RI::Rigid_body_collection<Traits> c = RI::standardize(input);
  RI::Incidence_tree t = RI::optimal_incidence_tree(c);
  RI::Well_formed_selection wf = RI::select_well_formed_incidences(c, t);
  const bool exact = RI::exact_coefficients(c, t);
  RI::Scene_solve_parameters p;
  p.maximal_placements = maximal_placements;
  if (exact) return RI::solve_scene<CGAL::Interval_nt<false>, CGAL::Gmpq>(input, c, t, wf, p);
  return RI::solve_scene<CGAL::Interval_nt<false>, CGAL::Interval_nt<false>>(input, c, t, wf, p);
}

// Matches the configurations one to one with the oracle's point sets (labels of `s`) within
// `tol`; returns the number matched.
static std::size_t match(const Scene& s, const RI::Scene_solve_result& r, const std::vector<Points>& oracle, double tol,
                         const std::string& what)
{
  std::vector<bool> used(oracle.size(), false);
  std::size_t matched = 0;
  for (const auto& x : r.configurations) {
    long best = -1;
    double bd = tol;
    for (std::size_t o = 0; o < oracle.size(); ++o) {
      if (used[o]) continue;
      double d = 0;
      for (std::size_t i = 0; i < s.labels.size(); ++i) {
        const auto& p = x.configuration.point(s.labels[i]);
        for (int k = 0; k < 3; ++k) d = (std::max)(d, std::abs(p[std::size_t(k)] - oracle[o][i][std::size_t(k)]));
      }
      if (d <= bd) { bd = d; best = long(o); }
    }
    if (best >= 0) { used[std::size_t(best)] = true; ++matched; }
    else CHECK(false, what << ": a configuration matches no oracle configuration within " << tol);
  }
  return matched;
}

// Is `planted` among the configurations, within `tol`?
static bool among(const Scene& s, const RI::Scene_solve_result& r, const Points& planted, double tol)
{
  for (const auto& x : r.configurations) {
    double d = 0;
    for (std::size_t i = 0; i < s.labels.size(); ++i) {
      const auto& p = x.configuration.point(s.labels[i]);
      for (int k = 0; k < 3; ++k) d = (std::max)(d, std::abs(p[std::size_t(k)] - planted[i][std::size_t(k)]));
    }
    if (d <= tol) return true;
  }
  return false;
}

// A braced strip of k triangles over planted points (flat: all in the plane z = 0), each
// triangle in its own random rational frame; the frame body is t0.
static Scene strip(Rng& g, int k, bool flat, Rigid* t0_map)
{
  std::vector<std::string> ls;
  for (int i = 0; i < k + 2; ++i) ls.push_back("p" + std::to_string(i));
  Scene s;
  while (true) {
    s = Scene();
    for (int i = 0; i < k + 2; ++i) {
      // a zigzag along x, so that consecutive triangles are proper
      QP p{Q(3 * i) + g.rational(4, 5), Q(i % 2 ? 3 : -3) + g.rational(4, 5), flat ? Q(0) : g.rational(9, 4)};
      s.add_point(ls[std::size_t(i)], p);
    }
    bool ok = true;  // no three consecutive points collinear, no four coplanar (unless flat)
    for (int i = 0; i + 2 < k + 2 && ok; ++i) {
      if (collinear(s.global[std::size_t(i)], s.global[std::size_t(i + 1)], s.global[std::size_t(i + 2)])) ok = false;
      if (!flat && i + 3 < k + 2 &&
          orientation(s.global[std::size_t(i)], s.global[std::size_t(i + 1)], s.global[std::size_t(i + 2)], s.global[std::size_t(i + 3)]) == 0)
        ok = false;
    }
    if (ok) break;
  }
  for (int i = 0; i < k; ++i) {
    Rigid m = random_rigid(g);
    if (i == 0) *t0_map = m;
    s.add_body("t" + std::to_string(i), {ls[std::size_t(i)], ls[std::size_t(i + 1)], ls[std::size_t(i + 2)]}, m);
  }
  for (int i = 0; i + 3 < k + 2; ++i) s.add_distance(ls[std::size_t(i)], ls[std::size_t(i + 3)]);
  return s;
}

// Every configuration of the strip in t0's frame, exactly: p0 p1 p2 where t0 has them, each
// further point trilaterated from the three before it.
static std::vector<Points> strip_oracle(const Scene& s, const Rigid& t0)
{
  const std::size_t n = s.labels.size();
  std::vector<std::vector<EP>> partial{{ep(t0.apply(s.global[0])), ep(t0.apply(s.global[1])), ep(t0.apply(s.global[2]))}};
  for (std::size_t j = 3; j < n; ++j) {
    std::vector<std::vector<EP>> next;
    for (const auto& x : partial)
      for (const EP& p : trilaterate(x[j - 3], x[j - 2], x[j - 1], s.sq(int(j), int(j - 3)), s.sq(int(j), int(j - 2)), s.sq(int(j), int(j - 1)))) {
        next.push_back(x);
        next.back().push_back(p);
      }
    partial.swap(next);
  }
  std::vector<Points> out;
  for (const auto& x : partial) {
    Points p;
    for (const EP& q : x) p.push_back(to3(q));
    out.push_back(p);
  }
  return out;
}

static Points planted_in(const Scene& s, const Rigid& m)
{
  Points p;
  for (const QP& q : s.global) {
    QP y = m.apply(q);
    p.push_back({CGAL::to_double(y.x), CGAL::to_double(y.y), CGAL::to_double(y.z)});
  }
  return p;
}

static void strips(Rng& g)
{
  for (int k : {2, 3, 5, 8, 10, 12}) {
    Rigid m0;
    Scene s = strip(g, k, false, &m0);
    const std::string what = "strip k = " + std::to_string(k);
    RI::Scene_solve_result r = solve(s, "t0");
    std::vector<Points> oracle = strip_oracle(s, m0);
    const std::size_t expected = std::size_t(1) << (k - 1);
    CHECK(oracle.size() == expected, what << ": the oracle found " << oracle.size() << " configurations, expected " << expected);
    CHECK(r.configurations.size() == expected, what << ": " << r.configurations.size() << " configurations, expected " << expected);
    CHECK(r.complete(), what << ": not complete");
    std::size_t cert = 0;
    for (const auto& x : r.configurations) cert += x.certified && !x.singular;
    CHECK(cert == r.configurations.size(), what << ": " << cert << " certified simple configurations of " << r.configurations.size());
    CHECK(match(s, r, oracle, 1e-9, what) == expected, what << ": not every oracle configuration found");
    CHECK(among(s, r, planted_in(s, m0), 1e-9), what << ": the planted configuration is missing");
    CHECK(r.placements.size() == 1 && r.placements[0].placements == expected && r.placements[0].relative_width <= std::ldexp(1.0, -44),
          what << ": placement report " << (r.placements.empty() ? std::string("missing") : std::to_string(r.placements[0].placements) +
                                                " placements, width " + std::to_string(r.placements[0].relative_width)));
    std::cout << what << ": " << r.configurations.size() << " configurations; placements enclosed at "
              << (r.placements.empty() ? 0u : r.placements[0].precision) << " bits" << std::endl;
  }
  { // the placement limit: never a shortened list that calls itself complete
    Rigid m0;
    Scene s = strip(g, 8, false, &m0);
    RI::Scene_solve_result r = solve(s, "t0", 100);
    CHECK(!r.complete() && !r.limits.empty() && r.configurations.size() == 100,
          "strip k = 8 with maximal_placements = 100: " << r.configurations.size() << " configurations, complete " << r.complete());
    RI::Rigid_body_collection<Traits> c = RI::standardize(make_collection<Traits>(s));
    bool threw = false;
    try { RI::enclose_all_placements<CGAL::Interval_nt<false>>(c, 0, 100); } catch (const RI::Input_error&) { threw = true; }
    CHECK(threw, "enclose_all_placements with 100 of 128 placements: no Input_error");
    auto e = RI::enumerate_placements<CGAL::Interval_nt<false>>(c, 0, 100);
    CHECK(!e.complete && e.placements.size() == 100, "enumerate_placements(100): complete " << e.complete << ", " << e.placements.size());
  }
}

static void flat_strips(Rng& g)
{
  for (int k : {2, 4, 6, 9}) {
    Rigid m0;
    Scene s = strip(g, k, true, &m0);
    const std::string what = "flat strip k = " + std::to_string(k);
    RI::Scene_solve_result r = solve(s, "t0");
    // the planted configuration, exactly (in a plane, every fold is at its double point, so it
    // is the only one; CORE's exact zero test on the nested radicals would take too long)
    std::vector<Points> oracle{planted_in(s, m0)};
    CHECK(r.configurations.size() == 1 && r.complete(), what << ": " << r.configurations.size() << " configurations, complete " << r.complete());
    if (r.configurations.size() != 1) continue;
    CHECK(r.configurations[0].singular && !r.configurations[0].singular_reason.empty(), what << ": not marked singular");
    // to the tolerance (it was 2.5e-4 off at k = 6 when the zero height was an interval)
    CHECK(match(s, r, oracle, 1e-12, what) == 1, what << ": not the oracle's configuration to 1e-12");
  }
}

// A root body R {H1, H2, A, B} and a triangle T {H1, H2, Q} hinged on H1 H2, Q `off` away from
// the line H1 H2, held by the distance Q - A: two configurations, about 1.4 `off` apart.
static void near_hinge(Rng& g)
{
  for (const Q& off : {Q(1, 10000000), Q(1, 100000) * Q(1, 100000)}) {
    Scene s;
    s.add_point("H1", QP{Q(0), Q(0), Q(0)});
    s.add_point("H2", QP{Q(2), Q(0), Q(0)});
    s.add_point("A", QP{Q(1, 3), Q(3, 2), Q(1, 2)});
    s.add_point("B", QP{Q(5, 4), Q(-1), Q(2)});
    s.add_point("Q", QP{Q(7, 5), off * Q(3, 5), off * Q(4, 5)});
    Rigid mr = random_rigid(g);
    s.add_body("R", {"H1", "H2", "A", "B"}, mr);
    s.add_body("T", {"H1", "H2", "Q"}, random_rigid(g));
    s.add_distance("Q", "A");
    const std::string what = "apex " + std::to_string(CGAL::to_double(off)) + " off its hinge";
    RI::Scene_solve_result r = solve(s, "R");
    std::vector<Points> oracle;
    for (const EP& q : trilaterate(ep(mr.apply(s.at("H1"))), ep(mr.apply(s.at("H2"))), ep(mr.apply(s.at("A"))), s.sq("Q", "H1"),
                                   s.sq("Q", "H2"), s.sq("Q", "A"))) {
      Points p = planted_in(s, mr);
      p[4] = to3(q);
      oracle.push_back(p);
    }
    CHECK(oracle.size() == 2, what << ": the oracle found " << oracle.size());
    CHECK(r.configurations.size() == 2 && r.complete(), what << ": " << r.configurations.size() << " configurations, complete " << r.complete());
    CHECK(match(s, r, oracle, 1e-3 * CGAL::to_double(off), what) == 2, what << ": not both oracle configurations");
  }
}

// A braced strip of 3 triangles with one more distance p0 - p4 of the wrong length (the five
// points' distances are all fixed, and only the 5-point Cayley-Menger determinant is off): no
// side of p4 fits, so the scene has no real configuration, a complete answer (or standardize
// says so), never an error or an incomplete answer.
static void excluded_sides(Rng& g)
{
  for (const Q& f : {Q(10001, 10000), Q(9999, 10000), Q(11, 10), Q(3, 2)}) {
    Rigid m0;
    Scene s = strip(g, 3, false, &m0);
    s.add_distance_value("p0", "p4", f * s.sq("p0", "p4"));
    const std::string what = "strip k = 3 with |p0 p4|^2 times " + std::to_string(CGAL::to_double(f));
    try {
      RI::Scene_solve_result r = solve(s, "t0");
      CHECK(r.configurations.empty() && !r.no_configuration.empty() && r.complete(),
            what << ": " << r.configurations.size() << " configurations, no_configuration '" << r.no_configuration << "', complete " << r.complete());
      std::cout << what << ": " << r.no_configuration << std::endl;
    } catch (const RI::No_real_configuration& e) {
      // standardize decided it from a Cayley-Menger determinant: also right
      std::cout << what << ": " << e.what() << std::endl;
    } catch (const std::exception& e) {
      CHECK(false, what << ": " << e.what());
    }
  }
}

int main()
{
  CGAL::Gmpfr::set_default_precision(256);
  Rng g(20261127);
  strips(g);
  flat_strips(g);
  near_hinge(g);
  excluded_sides(g);
  if (failures) { std::cerr << failures << " check(s) failed\n"; return 1; }
  std::cout << "test_placement_chains: all checks passed\n";
  return 0;
}
