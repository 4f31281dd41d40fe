// Copyright (c) 2026 Rigid_incidence contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The subdivision solver against planted systems whose real roots are known exactly
// (planted_systems.h: products of rational affine forms, coupled by an invertible rational
// matrix and by linear changes of coordinates). Checked with rationals only:
//  - products of linear factors, uncoupled and coupled, random rational roots, n = 2, 3;
//  - a cluster of two roots 1e-8 apart: both certified, disjoint enclosures;
//  - double roots ((x - 1/3)^2 = 0, y = x; a circle tangent to a line): never two certified
//    roots, never lost: an UNKNOWN box with "multiple" in its reason, or one certified root;
//  - roots exactly on faces and corners of the box (reported), roots just outside it (only as
//    on_boundary roots, if at all);
//  - no root in the box: complete, empty;
//  - a sparse 8-variable system, each equation in 2 variables;
//  - coefficients given as Gmpq, Interval_nt<false>, double (and Gmpfi with MPFI);
//  - Subdivision_solver<Interval_nt<false>> and Subdivision_solver<Gmpfi> at 200 bits
//    (tolerance 1e-45, enclosures narrower than 1e-40);
//  - tolerances 1e-3 .. 1e-12; the solver options (round robin, no preconditioning, no domain
//    reduction); box budgets (PENDING boxes lose no root);
//  - malformed input throws Input_error;
//  - fast mode: approximations of all simple roots within 1e-8, not certified, not complete.

#include "planted_systems.h"

#include <CGAL/Rigid_incidence/Subdivision_solver.h>

#include <chrono>
#include <cstdint>
#include <iostream>
#include <limits>

using namespace planted_systems;
typedef CGAL::Interval_nt<false> I;

static const std::uint64_t seed = 20260522;

template <class IT, class NT>
static bool run(const RI::Polynomial_system<NT>& s, const RI::Subdivision_solver_parameters& prm, RI::Solver_result<IT>& out,
                const std::string& name)
{
  try {
    RI::Subdivision_solver<IT> solver(prm);
    out = solver.solve(s);
    return true;
  } catch (const std::exception& e) {
    CHECK(false, name << ": solve threw " << e.what());
    return false;
  }
}

// solves p (or its system converted to NT) with solver IT and checks it
template <class IT, class NT>
static Tally solve_check(const Planted& p, const RI::Polynomial_system<NT>& s, const RI::Subdivision_solver_parameters& prm,
                         const Expectation& e, const std::string& name)
{
  RI::Solver_result<IT> r;
  if (!run<IT>(s, prm, r, name)) return Tally();
  if (r.statistics.seconds > 1)
    std::cout << "  slow: " << name << ": " << r.statistics.seconds << " s, " << r.statistics.boxes << " boxes\n";
  int before = failures;
  Tally t = check_result(r, p, e, name);
  if (failures > before && failures <= max_messages) std::cerr << "  system of " << name << ":\n" << system_string(p.system);
  return t;
}

static Tally solve_check(const Planted& p, const RI::Subdivision_solver_parameters& prm = RI::Subdivision_solver_parameters(),
                         const Expectation& e = Expectation())
{
  return solve_check<I>(p, p.system, prm, e, p.name);
}

static double seconds_since(std::chrono::steady_clock::time_point t0)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

static Tally total;

// ------------------------------------------------------------------ products of linear factors
static std::vector<Planted> product_systems(Rng& rng)
{
  std::vector<Planted> v;
  Planted p;
  // f1 = (x - 1/3)(x + 2/7), f2 = (y - 3/5)(y + 1/9)(y - 3/2 x): six roots
  std::vector<std::vector<Affine>> f(2);
  f[0] = {coordinate_form(2, 0, Q(1, 3)), coordinate_form(2, 0, Q(-2, 7))};
  Affine l = coordinate_form(2, 1, Q(0));
  l.c[0] = Q(-3, 2);
  f[1] = {coordinate_form(2, 1, Q(3, 5)), coordinate_form(2, 1, Q(-1, 9)), l};
  bool ok = make_planted(f, identity(2), cube(2, -1, 1), p);
  CHECK(ok && p.roots.size() == 6, "setup: product system with " << p.roots.size() << " roots");
  p.name = "product 2x3";
  v.push_back(p);
  std::vector<std::vector<Q>> A = {{Q(2), Q(-1, 3)}, {Q(1, 2), Q(5)}};
  ok = make_planted(f, A, cube(2, -1, 1), p);
  CHECK(ok && p.roots.size() == 6, "setup: coupled product system with " << p.roots.size() << " roots");
  p.name = "product 2x3 coupled by A";
  v.push_back(p);
  // three variables, random rational roots: (x-a1)(x-a2), (y-b1)(y - x + c), (z - x - y)(z - d)
  for (int k = 0; k < 3; ++k) {
    std::vector<std::vector<Affine>> g(3);
    std::vector<Q> a = distinct_rationals(rng, 2, Q(-9, 10), Q(9, 10), 30);
    g[0] = {coordinate_form(3, 0, a[0]), coordinate_form(3, 0, a[1])};
    Affine m = coordinate_form(3, 1, rng.rational(1, 5));
    m.c[0] = -1;
    g[1] = {coordinate_form(3, 1, rng.rational_in(Q(-9, 10), Q(9, 10), 31)), m};
    Affine z = coordinate_form(3, 2, Q(0));
    z.c[0] = Q(-1, 2);
    z.c[1] = Q(-1, 3);
    g[2] = {z, coordinate_form(3, 2, rng.rational_in(Q(-9, 10), Q(9, 10), 29))};
    if (!make_planted(g, random_invertible(rng, 3), cube(3, -1, 1), p)) { --k; continue; }
    p.name = "product 3 variables #" + std::to_string(k);
    v.push_back(p);
  }
  return v;
}

// random products in random coordinates: grid, triangular or general factors, x = M y + t
static std::vector<Planted> coupled_systems(Rng& rng, int count)
{
  std::vector<Planted> v;
  for (int k = 0; k < count; ++k) {
    std::size_t n = 2 + k % 2;
    std::vector<unsigned> deg(n);
    for (auto& d : deg) d = unsigned(rng.uniform(1, 3));
    std::vector<std::vector<Affine>> f;
    int kind = k % 3;
    if (kind == 0) f = grid_factors(rng, deg, Q(-1), Q(1), 40);
    else if (kind == 1) f = triangular_factors(rng, deg, Q(-1), Q(1), 40);
    else f = general_factors(rng, deg, Q(-1), Q(1), 40);
    Point t(n);
    for (auto& x : t) x = rng.rational(1, 8);
    f = change_coordinates(f, random_coupling(rng, n), t);
    Planted p;
    // a box with the roots well inside (most of them): [-2, 2]^n
    if (!make_planted(f, random_invertible(rng, n), cube(n, -2, 2), p)) { --k; continue; }
    // keep the roots out of the way of the box faces (tested separately)
    bool near_face = false;
    for (const auto& r : p.roots)
      for (std::size_t i = 0; i < n; ++i)
        if (CGAL::abs(CGAL::abs(r.x[i]) - Q(2)) < Q(1, 1000)) near_face = true;
    if (near_face) { --k; continue; }
    p.name = std::string(kind == 0 ? "grid" : kind == 1 ? "triangular" : "general") + " system in random coordinates #" + std::to_string(k);
    v.push_back(p);
  }
  return v;
}

static void test_products(Rng& rng)
{
  auto t0 = std::chrono::steady_clock::now();
  Tally t;
  for (const auto& p : product_systems(rng)) t.add(solve_check(p));
  for (const auto& p : coupled_systems(rng, 30)) t.add(solve_check(p));
  CHECK(t.roots_in_box > 60, "setup: only " << t.roots_in_box << " roots in the boxes");
  std::cout << "products and coupled products: " << t.systems << " systems, " << t.roots_in_box << " roots in the box, "
            << t.certified << " certified, " << seconds_since(t0) << " s\n";
  total.add(t);
}

// ------------------------------------------------------------------ a cluster 1e-8 apart
static void test_cluster(Rng& rng)
{
  Q a(1, 3), b = Q(1, 3) + Q(1, 100000000);
  // on the diagonal: (x - a)(x - b) = 0, y = x
  {
    std::vector<std::vector<Affine>> f(2);
    f[0] = {coordinate_form(2, 0, a), coordinate_form(2, 0, b)};
    Affine d = coordinate_form(2, 1, Q(0));
    d.c[0] = -1;
    f[1] = {d};
    Planted p;
    CHECK(make_planted(f, identity(2), cube(2, -1, 1), p) && p.roots.size() == 2, "setup: cluster");
    p.name = "cluster 1e-8 on the diagonal";
    Tally t = solve_check(p);
    CHECK(t.certified == 2, p.name << ": " << t.certified << " certified roots, expected 2");
    total.add(t);
  }
  // coupled, in random coordinates, with other roots
  for (int k = 0; k < 4; ++k) {
    std::vector<std::vector<Affine>> f(2);
    f[0] = {coordinate_form(2, 0, a), coordinate_form(2, 0, b), coordinate_form(2, 0, Q(-1, 2))};
    f[1] = {coordinate_form(2, 1, Q(1, 5)), coordinate_form(2, 1, Q(-3, 7))};
    f[1][0].c[0] = Q(1, 2);
    Point t0 = {rng.rational(1, 10), rng.rational(1, 10)};
    f = change_coordinates(f, random_coupling(rng, 2), t0);
    Planted p;
    if (!make_planted(f, random_invertible(rng, 2), cube(2, -2, 2), p)) { --k; continue; }
    p.name = "cluster 1e-8 in random coordinates #" + std::to_string(k);
    // in double precision: certified unless beyond the precision (the coupling amplifies the
    // rounding errors of the coefficients ~1e8 times: see attainable_width)
    Tally t = solve_check(p);
    CHECK(t.certified + t.beyond_precision >= t.roots_in_box, p.name << ": " << t.certified << " certified of " << t.roots_in_box);
    std::cout << p.name << ": " << t.certified << " of " << t.roots_in_box << " certified in double precision, " << t.beyond_precision
              << " beyond it\n";
    total.add(t);
#ifdef CGAL_USE_MPFI
    // at 200 bits every root is resolvable: all certified
    RI::Subdivision_solver_parameters prm;
    prm.precision = 200;
    prm.tolerance = 1e-45;
    Expectation e;
    e.tolerance = 1e-40;
    e.unit_roundoff = 0x1p-200;
    Tally u = solve_check<CGAL::Gmpfi>(p, p.system, prm, e, p.name + " [Gmpfi solver]");
    CHECK(u.certified == u.roots_in_box, p.name << " [Gmpfi solver]: " << u.certified << " certified of " << u.roots_in_box);
    total.add(u);
#endif
  }
  std::cout << "clusters: done\n";
}

// ------------------------------------------------------------------ double roots
// A singular root must be neither lost nor certified twice: one UNKNOWN box with "multiple" in
// its reason containing it, or (at most) one certified root containing it.
static void check_singular(const RI::Solver_result<I>& r, const Planted& p, const std::string& name, bool& unknown_reported)
{
  unknown_reported = false;
  for (const auto& pr : p.roots) {
    if (pr.simple || !in_box(pr.x, p.system.box)) continue;
    std::size_t in_certified = 0, in_multiple = 0, in_other = 0;
    for (const auto& root : r.roots) {
      Q_box b;
      if (exact_box(root.enclosure, b) && contains(b, pr.x)) ++in_certified;
    }
    for (const auto& u : r.unresolved) {
      Q_box b;
      if (!exact_box(u.box, b) || !contains(b, pr.x)) continue;
      if (u.kind == RI::Box_class::UNKNOWN && u.reason.find("multiple") != std::string::npos) ++in_multiple;
      else ++in_other;
    }
    CHECK(in_certified <= 1, name << ": double root " << point_string(pr.x) << " in " << in_certified << " certified enclosures");
    CHECK(in_certified == 1 || in_multiple >= 1,
          name << ": double root " << point_string(pr.x) << " neither certified once nor in an UNKNOWN box with reason \"...multiple...\""
               << " (in " << in_other << " other unresolved boxes"
               << (r.unresolved.empty() ? std::string() : ", first reason \"" + r.unresolved[0].reason + "\"") << ")");
    if (in_certified == 0) {
      unknown_reported = true;
      CHECK(!r.complete(), name << ": complete() with a double root left unresolved");
    }
  }
}

static void test_double_roots()
{
  std::vector<Planted> v;
  Planted p;
  {
    // (x - 1/3)^2 = 0, y - x = 0
    std::vector<std::vector<Affine>> f(2);
    f[0] = {coordinate_form(2, 0, Q(1, 3)), coordinate_form(2, 0, Q(1, 3))};
    Affine d = coordinate_form(2, 1, Q(0));
    d.c[0] = -1;
    f[1] = {d};
    CHECK(make_planted(f, identity(2), cube(2, -1, 1), p, true) && p.roots.size() == 1 && !p.roots[0].simple, "setup: double root");
    p.name = "(x - 1/3)^2 = 0, y = x";
    v.push_back(p);
    // coupled, with a simple root (-1/2, -1/2) as well
    f[0].push_back(coordinate_form(2, 0, Q(-1, 2)));
    CHECK(make_planted(f, std::vector<std::vector<Q>>{{Q(1), Q(2, 3)}, {Q(-1, 4), Q(3)}}, cube(2, -1, 1), p, true) && p.roots.size() == 2,
          "setup: double and simple root");
    p.name = "(x - 1/3)^2 (x + 1/2) = 0, y = x, coupled";
    v.push_back(p);
  }
  {
    // the unit circle tangent to y = 1 at (0, 1): not a product, built by hand
    Planted c;
    c.system.variable_names = {"x", "y"};
    c.system.box = cube(2, -2, 2);
    Poly x = Poly::variable(2, 0), y = Poly::variable(2, 1), one = Poly::constant(2, Q(1));
    c.system.equations = {x * x + y * y - one, y - one};
    c.system.labels = {"circle", "tangent"};
    c.roots = {Planted_root{Point{Q(0), Q(1)}, 2, false}};
    c.name = "circle tangent to a line";
    v.push_back(c);
  }
  for (const auto& q : v) {
    RI::Solver_result<I> r;
    if (!run<I>(q.system, RI::Subdivision_solver_parameters(), r, q.name)) continue;
    Expectation e;
    e.complete = false; // checked in check_singular
    total.add(check_result(r, q, e, q.name));
    bool unknown = false;
    check_singular(r, q, q.name, unknown);
    std::cout << "double root, " << q.name << ": " << (unknown ? "UNKNOWN box" : "certified") << ", " << r.roots.size()
              << " certified, " << r.unresolved.size() << " unresolved" << (r.unresolved.empty() ? "" : " (" + r.unresolved[0].reason + ")")
              << "\n";
  }
}

// ------------------------------------------------------------------ the box boundary
static void test_boundary(Rng& rng)
{
  Tally t;
  {
    // box [0, 1]^2, roots (0, 1) (corner), (0, 1/3), (1/2, 1) (faces), (1/2, 1/3)
    std::vector<std::vector<Affine>> f(2);
    f[0] = {coordinate_form(2, 0, Q(0)), coordinate_form(2, 0, Q(1, 2))};
    f[1] = {coordinate_form(2, 1, Q(1)), coordinate_form(2, 1, Q(1, 3))};
    for (int coupled = 0; coupled < 2; ++coupled) {
      Planted p;
      CHECK(make_planted(f, coupled ? std::vector<std::vector<Q>>{{Q(3), Q(-1)}, {Q(1, 2), Q(2)}} : identity(2), cube(2, 0, 1), p) &&
                p.roots.size() == 4, "setup: boundary");
      p.name = std::string("box [0,1]^2, corner and face roots") + (coupled ? ", coupled" : "");
      Tally u = solve_check(p);
      CHECK(u.boundary_roots == 3 && u.certified == 4, p.name << ": " << u.certified << " certified");
      t.add(u);
    }
  }
  // random forms through the corner (0, 1) of [0, 1]^2 and through a face point
  for (int k = 0; k < 6; ++k) {
    Point corner = {Q(0), Q(1)}, face = {rng.rational_in(Q(0), Q(1), 16), Q(0)};
    std::vector<std::vector<Affine>> f(2);
    for (int j = 0; j < 2; ++j) {
      std::vector<Q> c1 = {rng.rational(4, 3), rng.rational(4, 3)}, c2 = {rng.rational(4, 3), rng.rational(4, 3)};
      c1[j] = rng.uniform(1, 3);
      c2[j] = -rng.uniform(1, 3);
      f[j] = {form_through(c1, corner), form_through(c2, face)};
    }
    Planted p;
    if (!make_planted(f, random_invertible(rng, 2), cube(2, 0, 1), p)) { --k; continue; }
    bool close = false; // other roots well away from the boundary, inside or out
    for (const auto& r : p.roots) {
      if (r.x == corner || r.x == face) continue;
      for (int i = 0; i < 2; ++i)
        if (CGAL::abs(r.x[i]) < Q(1, 100) || CGAL::abs(r.x[i] - 1) < Q(1, 100)) close = true;
    }
    if (close) { --k; continue; }
    p.name = "random forms through a corner and a face point #" + std::to_string(k);
    Tally u = solve_check(p);
    CHECK(u.boundary_roots >= 2, p.name << ": setup, " << u.boundary_roots << " boundary roots");
    t.add(u);
  }
  {
    // a corner in 3D: box [-1, 0.5]^3, grid x in {1/2, -1/3}, y in {-1, 1/7}, z in {1/2, 1/5}:
    // corner (1/2, -1, 1/2), roots on edges and faces, one inside
    std::vector<std::vector<Affine>> f(3);
    f[0] = {coordinate_form(3, 0, Q(1, 2)), coordinate_form(3, 0, Q(-1, 3))};
    f[1] = {coordinate_form(3, 1, Q(-1)), coordinate_form(3, 1, Q(1, 7))};
    f[2] = {coordinate_form(3, 2, Q(1, 2)), coordinate_form(3, 2, Q(1, 5))};
    Planted p;
    CHECK(make_planted(f, random_invertible(rng, 3), cube(3, -1, 0.5), p) && p.roots.size() == 8, "setup: 3D corner");
    p.name = "box [-1, 0.5]^3, corner, edge and face roots";
    Tally u = solve_check(p);
    CHECK(u.boundary_roots == 7 && u.certified == 8, p.name << ": " << u.boundary_roots << " boundary roots, " << u.certified << " certified");
    t.add(u);
  }
  {
    // roots just outside [0, 1]^2 (2^-40 and 2^-45 away) and one inside (1/3, 2/3): the
    // outside ones may come back only flagged on_boundary, the inside one certified
    std::vector<std::vector<Affine>> f(2);
    Q eps1 = Q(1) / Q(1099511627776.0), eps2 = Q(1) / Q(35184372088832.0);
    f[0] = {coordinate_form(2, 0, Q(1) + eps1), coordinate_form(2, 0, Q(1, 3))};
    f[1] = {coordinate_form(2, 1, -eps2), coordinate_form(2, 1, Q(2, 3))};
    for (int coupled = 0; coupled < 2; ++coupled) {
      Planted p;
      CHECK(make_planted(f, coupled ? std::vector<std::vector<Q>>{{Q(1), Q(1, 2)}, {Q(-1, 3), Q(1)}} : identity(2), cube(2, 0, 1), p),
            "setup: outside");
      p.name = std::string("roots just outside [0, 1]^2") + (coupled ? ", coupled" : "");
      Expectation e;
      e.complete = false; // an undecided box at the face is allowed there
      RI::Solver_result<I> r;
      if (!run<I>(p.system, RI::Subdivision_solver_parameters(), r, p.name)) continue;
      Tally u = check_result(r, p, e, p.name);
      CHECK(u.roots_in_box == 1 && u.certified >= 1, p.name << ": " << u.certified << " certified");
      std::cout << p.name << ": " << r.roots.size() << " roots (" << std::count_if(r.roots.begin(), r.roots.end(), [](const RI::Solver_root<I>& x) { return x.on_boundary; })
                << " on boundary), " << r.unresolved.size() << " unresolved\n";
      t.add(u);
    }
  }
  std::cout << "boundary: " << t.systems << " systems, " << t.boundary_roots << " roots on faces/corners, " << t.certified << " certified\n";
  total.add(t);
}

// ------------------------------------------------------------------ no root in the box
static void test_no_root()
{
  std::vector<Planted> v;
  {
    std::vector<std::vector<Affine>> f(2);
    Affine s = coordinate_form(2, 1, Q(0));
    s.c[0] = 1; // y + x
    f[0] = {coordinate_form(2, 0, Q(2)), coordinate_form(2, 0, Q(-3))};
    f[1] = {coordinate_form(2, 1, Q(5)), s};
    Planted p;
    CHECK(make_planted(f, std::vector<std::vector<Q>>{{Q(1), Q(1)}, {Q(1), Q(-1)}}, cube(2, -1, 1), p) && p.roots.size() == 4, "setup: no root");
    p.name = "real roots outside the box";
    v.push_back(p);
  }
  {
    Planted c;
    c.system.variable_names = {"x", "y"};
    c.system.box = cube(2, -1, 1);
    Poly x = Poly::variable(2, 0), y = Poly::variable(2, 1), one = Poly::constant(2, Q(1));
    c.system.equations = {x * x + y * y + one, x - y};
    c.system.labels = {"no real point", "diagonal"};
    c.name = "x^2 + y^2 + 1 = 0, x = y";
    v.push_back(c);
  }
  {
    // three variables: x^2 + y^2 + z^2 = 1/4, x + y + z = 2 (the plane misses the sphere), z = x y
    Planted c;
    c.system.variable_names = {"x", "y", "z"};
    c.system.box = cube(3, -1, 1);
    Poly x = Poly::variable(3, 0), y = Poly::variable(3, 1), z = Poly::variable(3, 2);
    c.system.equations = {x * x + y * y + z * z - Poly::constant(3, Q(1, 4)), x + y + z - Poly::constant(3, Q(2)), z - x * y};
    c.system.labels = {"sphere", "plane", "saddle"};
    c.name = "sphere, plane and saddle without common point";
    v.push_back(c);
  }
  for (const auto& p : v) {
    RI::Solver_result<I> r;
    if (!run<I>(p.system, RI::Subdivision_solver_parameters(), r, p.name)) continue;
    total.add(check_result(r, p, Expectation(), p.name));
    CHECK(r.roots.empty() && r.unresolved.empty() && r.complete(),
          p.name << ": " << r.roots.size() << " roots, " << r.unresolved.size() << " unresolved, expected none");
  }
  std::cout << "no root: done\n";
}

// ------------------------------------------------------------------ sparse, 8 variables
static void test_sparse(Rng& rng)
{
  const std::size_t n = 8;
  Tally t;
  for (int k = 0; k < 3; ++k) {
    // f_i in (x_i, x_{i+1 mod 8}); two planted roots P and Q, two factors in 3 equations
    Point P(n), R(n);
    for (std::size_t i = 0; i < n; ++i) {
      P[i] = rng.rational_in(Q(-3, 4), Q(3, 4), 32);
      R[i] = rng.rational_in(Q(-3, 4), Q(3, 4), 32);
    }
    std::vector<std::vector<Affine>> f(n);
    bool ok = true;
    for (std::size_t i = 0; i < n; ++i) {
      std::size_t j = (i + 1) % n;
      if (i % 3 == 0) {
        std::vector<Q> c1(n, Q(0)), c2(n, Q(0));
        c1[i] = rng.uniform(1, 3); c1[j] = rng.uniform(1, 3) * Q(rng.coin() ? 1 : -1, 2);
        c2[i] = -rng.uniform(1, 3); c2[j] = rng.uniform(1, 3) * Q(rng.coin() ? 1 : -1, 2);
        f[i] = {form_through(c1, P), form_through(c2, R)};
      } else {
        // the line through (P_i, P_j) and (R_i, R_j) in the (x_i, x_j) plane
        std::vector<Q> c(n, Q(0));
        c[i] = R[j] - P[j];
        c[j] = P[i] - R[i];
        if (c[i] == 0 || c[j] == 0) ok = false; // keep both variables in every equation
        f[i] = {form_through(c, P)};
      }
    }
    Planted p;
    if (!ok || !make_planted(f, identity(n), cube(n, -1, 1), p)) { --k; continue; }
    for (std::size_t i = 0; i < n; ++i)
      CHECK(p.system.equations[i].variables().size() == 2, "setup: sparse equation " << i << " in " << p.system.equations[i].variables().size() << " variables");
    p.name = "sparse 8 variables #" + std::to_string(k);
    auto t0 = std::chrono::steady_clock::now();
    Tally u = solve_check(p);
    CHECK(u.roots_in_box >= 2, p.name << ": setup, " << u.roots_in_box << " roots in the box");
    std::cout << p.name << ": " << p.roots.size() << " roots, " << u.roots_in_box << " in the box, " << u.certified << " certified, "
              << seconds_since(t0) << " s\n";
    t.add(u);
  }
  total.add(t);
}

// ------------------------------------------------------------------ other coefficient types
static void test_coefficient_types(Rng& rng)
{
  Tally t;
  // Interval_nt<false> coefficients: enclosures of the rational ones (1/3 is not a double)
  std::vector<Planted> v = product_systems(rng);
  for (const auto& p : coupled_systems(rng, 9)) v.push_back(p);
  for (const auto& p : v) t.add(solve_check<I>(p, to_interval_system(p.system), RI::Subdivision_solver_parameters(), Expectation(),
                                                p.name + " [Interval_nt coefficients]"));
  // double coefficients: dyadic roots and a dyadic coupling, so the double system is exact
  {
    std::vector<std::vector<Affine>> f(2);
    f[0] = {coordinate_form(2, 0, Q(1, 4)), coordinate_form(2, 0, Q(-3, 8))};
    Affine s = coordinate_form(2, 1, Q(1, 8));
    s.c[0] = Q(1, 2);
    f[1] = {coordinate_form(2, 1, Q(1, 2)), s};
    Planted p;
    CHECK(make_planted(f, std::vector<std::vector<Q>>{{Q(1), Q(1, 2)}, {Q(-3, 4), Q(2)}}, cube(2, -1, 1), p) && p.roots.size() == 4,
          "setup: dyadic");
    p.name = "dyadic system [double coefficients]";
    t.add(solve_check<I>(p, to_double_system(p.system), RI::Subdivision_solver_parameters(), Expectation(), p.name));
  }
  std::cout << "coefficient types: " << t.systems << " systems, " << t.certified << " certified\n";
  total.add(t);
}

// ------------------------------------------------------------------ Gmpfi
static void test_gmpfi(Rng& rng)
{
#ifdef CGAL_USE_MPFI
  auto t0 = std::chrono::steady_clock::now();
  RI::Subdivision_solver_parameters prm;
  prm.precision = 200;
  prm.tolerance = 1e-45;
  Expectation e;
  e.tolerance = 1e-40; // required: narrower than 1e-40 (the tolerance asked is 1e-45)
  e.unit_roundoff = 0x1p-200;
  Tally t;
  std::vector<Planted> v = product_systems(rng);
  for (const auto& p : coupled_systems(rng, 6)) v.push_back(p);
  for (const auto& p : v) {
    t.add(solve_check<CGAL::Gmpfi>(p, p.system, prm, e, p.name + " [Gmpfi solver]"));
    t.add(solve_check<CGAL::Gmpfi>(p, to_gmpfi_system(p.system, 200), prm, e, p.name + " [Gmpfi solver, Gmpfi coefficients]"));
  }
  // the Gmpfi solver with Interval_nt coefficients: the enclosures cannot beat the coefficients
  for (std::size_t k = 0; k < 2; ++k) {
    Expectation loose;
    loose.tolerance = 0;
    t.add(solve_check<CGAL::Gmpfi>(v[k], to_interval_system(v[k].system), prm, loose, v[k].name + " [Gmpfi solver, Interval_nt coefficients]"));
  }
  // the cluster 1e-8 apart, at 200 bits
  {
    std::vector<std::vector<Affine>> f(2);
    f[0] = {coordinate_form(2, 0, Q(1, 3)), coordinate_form(2, 0, Q(1, 3) + Q(1, 100000000))};
    f[1] = {coordinate_form(2, 1, Q(1, 5))};
    f[1][0].c[0] = Q(1, 2);
    Planted p;
    CHECK(make_planted(f, std::vector<std::vector<Q>>{{Q(1), Q(1, 2)}, {Q(-1, 3), Q(1)}}, cube(2, -1, 1), p), "setup: Gmpfi cluster");
    p.name = "cluster 1e-8 [Gmpfi solver]";
    Tally u = solve_check<CGAL::Gmpfi>(p, p.system, prm, e, p.name);
    CHECK(u.certified == 2, p.name << ": " << u.certified << " certified");
    t.add(u);
  }
  std::cout << "Gmpfi at 200 bits: " << t.systems << " systems, " << t.certified << " certified, " << seconds_since(t0) << " s\n";
  total.add(t);
#else
  (void)rng;
  std::cout << "Gmpfi: not built (no MPFI)\n";
#endif
}

// ------------------------------------------------------------------ tolerances and options
static void test_tolerances_and_options(Rng& rng)
{
  std::vector<Planted> v = product_systems(rng);
  for (const auto& p : coupled_systems(rng, 6)) v.push_back(p);
  Tally t;
  for (double tol : {1e-3, 1e-6, 1e-9, 1e-12}) {
    RI::Subdivision_solver_parameters prm;
    prm.tolerance = tol;
    Expectation e;
    e.tolerance = tol;
    for (const auto& p : v) t.add(solve_check<I>(p, p.system, prm, e, p.name + " [tolerance " + std::to_string(tol) + "]"));
  }
  for (int option = 0; option < 5; ++option) {
    RI::Subdivision_solver_parameters prm;
    std::string what;
    switch (option) {
    case 0: prm.split = RI::Split_strategy::ROUND_ROBIN; what = "round robin"; break;
    case 1: prm.preconditioning = false; what = "no preconditioning"; break;
    case 2: prm.domain_reduction = false; what = "no domain reduction"; break;
    case 3: prm.preconditioning = false; prm.domain_reduction = false; prm.split = RI::Split_strategy::ROUND_ROBIN; what = "plain bisection"; break;
    default: prm.minimal_width = 1e-6; what = "minimal width 1e-6"; break;
    }
    for (const auto& p : v) t.add(solve_check<I>(p, p.system, prm, Expectation(), p.name + " [" + what + "]"));
  }
  // budgets: whatever is left is PENDING, and no root is lost
  for (std::size_t budget : {1, 3, 10, 40}) {
    RI::Subdivision_solver_parameters prm;
    prm.maximal_boxes = budget;
    Expectation e;
    e.complete = false;
    e.certify_simple = false;
    for (const auto& p : v) {
      RI::Solver_result<I> r;
      std::string name = p.name + " [" + std::to_string(budget) + " boxes]";
      if (!run<I>(p.system, prm, r, name)) continue;
      t.add(check_result(r, p, e, name));
      CHECK(r.statistics.boxes <= budget, name << ": " << r.statistics.boxes << " boxes visited");
      bool pending = false;
      for (const auto& u : r.unresolved) pending = pending || u.kind == RI::Box_class::PENDING;
      // one box: solved in it (complete), or what is left is PENDING
      if (budget == 1) CHECK(r.complete() || pending, name << ": incomplete without a PENDING box after a budget of one box");
    }
  }
  std::cout << "tolerances and options: " << t.systems << " solves, " << t.certified << " certified\n";
  total.add(t);
}

// ------------------------------------------------------------------ malformed input
template <class F> static void expect_input_error(F f, const std::string& what)
{
  bool thrown = false;
  try {
    f();
  } catch (const RI::Input_error&) {
    thrown = true;
  } catch (const std::exception& e) {
    CHECK(false, what << ": threw " << e.what() << " instead of Input_error");
    return;
  }
  CHECK(thrown, what << ": no Input_error");
}

static void test_malformed()
{
  Planted p;
  std::vector<std::vector<Affine>> f(2);
  f[0] = {coordinate_form(2, 0, Q(1, 3))};
  f[1] = {coordinate_form(2, 1, Q(1, 5))};
  make_planted(f, identity(2), cube(2, -1, 1), p);
  RI::Subdivision_solver<I> solver;
  const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
  auto with_box = [&](std::vector<std::pair<double, double>> b) { System s = p.system; s.box = b; return s; };
  expect_input_error([&] { solver.solve(with_box({{-1, 1}, {1, -1}})); }, "lo > hi");
  expect_input_error([&] { solver.solve(with_box({{0.5, 0.5}, {-1, 1}})); }, "empty box (lo == hi)");
  expect_input_error([&] { solver.solve(with_box({{nan, 1}, {-1, 1}})); }, "NaN lower bound");
  expect_input_error([&] { solver.solve(with_box({{-1, 1}, {-1, nan}})); }, "NaN upper bound");
  expect_input_error([&] { solver.solve(with_box({{-inf, 1}, {-1, 1}})); }, "infinite bound");
  expect_input_error([&] { solver.solve(with_box({{-1, 1}})); }, "box of 1 interval for 2 variables");
  expect_input_error([&] { solver.solve(with_box({})); }, "no box");
  {
    System s = p.system; // 3 variables, 2 equations
    s.variable_names.push_back("z");
    s.box.push_back({-1, 1});
    for (auto& e : s.equations) {
      Poly q(3);
      for (const auto& term : e.terms()) { Poly::Exponent x = term.first; x.push_back(0); q.add_term(x, term.second); }
      e = q;
    }
    expect_input_error([&] { solver.solve(s); }, "2 equations in 3 variables");
  }
  {
    System s = p.system; // 2 variables, 3 equations
    s.equations.push_back(s.equations[0] + s.equations[1]);
    s.labels.push_back("extra");
    expect_input_error([&] { solver.solve(s); }, "3 equations in 2 variables");
  }
  {
    System s = p.system; // an equation in 3 variables in a 2-variable system
    Poly q(3);
    q.add_term(Poly::Exponent{1, 0, 0}, Q(1));
    s.equations[1] = q;
    expect_input_error([&] { solver.solve(s); }, "equation with 3 variables in a system of 2");
  }
  expect_input_error([&] { solver.solve(to_interval_system(with_box({{2, -2}, {-1, 1}}))); }, "lo > hi, Interval_nt coefficients");
  {
    System s = p.system; // an identically zero equation
    s.equations[1] = Poly(2);
    expect_input_error([&] { solver.solve(s); }, "identically zero equation");
  }
  expect_input_error([&] { solver.solve(System()); }, "no variable");
#ifdef CGAL_USE_MPFI
  expect_input_error([&] { RI::Subdivision_solver<CGAL::Gmpfi>().solve(with_box({{0, 1}, {nan, nan}})); }, "NaN box, Gmpfi solver");
#endif
  std::cout << "malformed input: done\n";
}

// ------------------------------------------------------------------ fast mode
static void test_fast(Rng& rng)
{
  std::vector<Planted> v = product_systems(rng);
  for (const auto& p : coupled_systems(rng, 12)) v.push_back(p);
  RI::Subdivision_solver_parameters prm;
  prm.fast = true;
  std::size_t found = 0, roots = 0;
  for (const auto& p : v) {
    RI::Solver_result<I> r;
    if (!run<I>(p.system, prm, r, p.name + " [fast]")) continue;
    CHECK(r.fast && !r.complete(), p.name << " [fast]: fast " << r.fast << ", complete " << r.complete());
    for (const auto& root : r.roots) CHECK(!root.certified, p.name << " [fast]: a root is certified");
    for (const auto& pr : p.roots) {
      if (!pr.simple || !in_box(pr.x, p.system.box)) continue;
      ++roots;
      bool hit = false;
      for (const auto& root : r.roots) {
        if (root.approximation.size() != pr.x.size()) continue;
        bool close = true;
        for (std::size_t i = 0; i < pr.x.size(); ++i)
          close = close && std::abs(root.approximation[i] - CGAL::to_double(pr.x[i])) <= 1e-8;
        hit = hit || close;
      }
      if (hit) ++found;
      CHECK(hit, p.name << " [fast]: no approximation within 1e-8 of " << point_string(pr.x));
      if (!hit && failures <= max_messages) std::cerr << system_string(p.system);
    }
    // no approximation far from every root
    for (const auto& root : r.roots) {
      bool near = false;
      for (const auto& pr : p.roots) {
        if (root.approximation.size() != pr.x.size()) continue;
        bool close = true;
        for (std::size_t i = 0; i < pr.x.size(); ++i)
          close = close && std::abs(root.approximation[i] - CGAL::to_double(pr.x[i])) <= 1e-6;
        near = near || close;
      }
      CHECK(near, p.name << " [fast]: approximation far from every root");
    }
  }
  std::cout << "fast mode: " << found << " of " << roots << " simple roots approximated\n";
}

int main()
{
  std::cout << "test_subdivision_solver: seed " << seed << "\n";
  auto t0 = std::chrono::steady_clock::now();
  Rng rng(seed);
  test_products(rng);
  test_cluster(rng);
  test_double_roots();
  test_boundary(rng);
  test_no_root();
  test_sparse(rng);
  test_coefficient_types(rng);
  test_gmpfi(rng);
  test_tolerances_and_options(rng);
  test_malformed();
  test_fast(rng);
  std::cout << "test_subdivision_solver: " << total.systems << " solves, " << total.roots_in_box << " roots in boxes, " << total.certified
            << " certified, " << checks << " checks, " << failures << " failures, " << seconds_since(t0) << " s\n";
  return failures == 0 ? 0 : 1;
}
