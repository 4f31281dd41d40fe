// Copyright (c) 2026 Rigid_incidence contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The subdivision solver on many random planted systems (planted_systems.h): n = 1 .. 4
// variables, 1 .. 3 factors (the degree) per equation, grid, triangular or general affine
// factors, in random coordinates (x = M y + t) or not, coupled by a random invertible A or
// not, over random boxes (some with a face through a root), with exact (Gmpq) or Interval_nt
// coefficients. The oracle knows every real root exactly (every root of such a system is real).
// For every system:
//  - no planted root in the closed box is missed: it is in a certified enclosure or in an
//    unresolved box;
//  - no certified enclosure is spurious: it contains exactly one planted root;
//  - certified enclosures are pairwise disjoint, in the box unless flagged on_boundary, at most
//    the tolerance wide (or at the double-precision limit);
//  - every simple root resolvable in double precision is certified, and the result is complete
//    when no root is beyond the precision and none lies just outside the box.
// Usage: test_subdivision_solver_random [systems [seed]]

#include "planted_systems.h"

#include <CGAL/Rigid_incidence/Subdivision_solver.h>

#include <chrono>
#include <cstdlib>
#include <iostream>

using namespace planted_systems;
typedef CGAL::Interval_nt<false> I;

int main(int argc, char** argv)
{
  const int systems = argc > 1 ? std::atoi(argv[1]) : 1500;
  const std::uint64_t seed = argc > 2 ? std::strtoull(argv[2], nullptr, 10) : 1234567;
  std::cout << "test_subdivision_solver_random: seed " << seed << ", " << systems << " systems\n";
  Rng rng(seed);
  auto t0 = std::chrono::steady_clock::now();
  Tally total;
  std::size_t planted_roots = 0, outside_near = 0, interval_inputs = 0, face_boxes = 0;
  double slowest = 0;
  std::string slowest_name;
  for (int k = 0; k < systems; ++k) {
    // n: 1 .. 4, more small systems than large ones; at most 27 roots (complex or real)
    std::size_t n = std::size_t(1 + (k % 10 < 2 ? 0 : k % 10 < 5 ? 1 : k % 10 < 8 ? 2 : 3));
    std::vector<unsigned> deg(n);
    unsigned product = 1;
    for (auto& d : deg) {
      d = unsigned(rng.uniform(1, 3));
      while (product * d > (n == 4 ? 12u : 27u)) --d;
      product *= d;
    }
    int kind = int(rng.uniform(0, 3));
    std::vector<std::vector<Affine>> f;
    if (kind == 0) f = grid_factors(rng, deg, Q(-3, 2), Q(3, 2), 24);
    else if (kind == 1) f = triangular_factors(rng, deg, Q(-3, 2), Q(3, 2), 24);
    else if (kind == 2) f = general_factors(rng, deg, Q(-3, 2), Q(3, 2), 24);
    else f = shared_point_factors(rng, deg, Q(-1), Q(1), 24);
    bool coordinates = rng.coin(0.5);
    if (coordinates) {
      Point t(n);
      for (auto& x : t) x = rng.rational(1, 8);
      f = change_coordinates(f, random_coupling(rng, n), t);
    }
    bool coupled = rng.coin(0.8);
    std::vector<std::vector<Q>> A = coupled ? random_invertible(rng, n) : identity(n);
    Planted p;
    if (!make_planted(f, A, cube(n, -1, 1), p)) { --k; continue; }
    // the box: [-1, 1]^n, random dyadic intervals, or (half of the time) the hull of a few
    // planted roots with a random dyadic margin, rounded outwards to multiples of 1/8
    std::vector<std::pair<double, double>> box(n);
    if (rng.coin(0.5) && !p.roots.empty()) {
      std::vector<Q> lo(n), hi(n);
      std::size_t m = std::size_t(rng.uniform(1, 4));
      for (std::size_t a = 0; a < m; ++a) {
        const Point& x = p.roots[std::size_t(rng.uniform(0, long(p.roots.size()) - 1))].x;
        for (std::size_t i = 0; i < n; ++i) {
          if (a == 0 || x[i] < lo[i]) lo[i] = x[i];
          if (a == 0 || x[i] > hi[i]) hi[i] = x[i];
        }
      }
      for (std::size_t i = 0; i < n; ++i) {
        box[i].first = std::floor(CGAL::to_double(lo[i]) * 8 - double(rng.uniform(1, 4))) / 8;
        box[i].second = std::ceil(CGAL::to_double(hi[i]) * 8 + double(rng.uniform(1, 4))) / 8;
      }
    } else {
      for (auto& b : box) {
        if (rng.coin(0.5)) { b = {-1, 1}; continue; }
        double lo = double(rng.uniform(-16, 8)) / 8, hi = lo + double(rng.uniform(4, 24)) / 8;
        b = {lo, hi};
      }
    }
    p.system.box = box;
    // sometimes a face of the box through a planted root (when its coordinate is a double)
    if (!p.roots.empty() && rng.coin(0.2)) {
      const Point& x = p.roots[std::size_t(rng.uniform(0, long(p.roots.size()) - 1))].x;
      std::size_t i = std::size_t(rng.uniform(0, long(n) - 1));
      double d = CGAL::to_double(x[i]);
      if (Q(d) == x[i]) {
        if (rng.coin() && d < box[i].second) box[i].first = d;
        else if (d > box[i].first) box[i].second = d;
        p.system.box = box;
        ++face_boxes;
      }
    }
    p.name = "random #" + std::to_string(k) + (k % 10 == 3 ? " [smear]" : k % 10 == 5 ? " [round robin]" : "") + " (n " + std::to_string(n) + ", " +
             (kind == 0 ? "grid" : kind == 1 ? "triangular" : kind == 2 ? "general" : "shared points") + (coordinates ? ", new coordinates" : "") +
             (coupled ? ", coupled" : "") + ")";
    planted_roots += p.roots.size();
    // a planted root just outside the box may be left undecided: no completeness then
    bool near_outside = false;
    for (const auto& r : p.roots)
      if (!in_box(r.x, box) && distance_to_box(r.x, box) < Q(1, 1000000)) near_outside = true;
    if (near_outside) ++outside_near;
    Expectation e;
    e.complete = !near_outside;
    bool interval = k % 10 == 7;
    if (interval) ++interval_inputs;
    auto s0 = std::chrono::steady_clock::now();
    RI::Solver_result<I> r;
    try {
      RI::Subdivision_solver_parameters prm;
      if (k % 10 == 3) prm.split = RI::Split_strategy::SMEAR;  // every split strategy finds every root
      if (k % 10 == 5) prm.split = RI::Split_strategy::ROUND_ROBIN;
      RI::Subdivision_solver<I> solver(prm);
      r = interval ? solver.solve(to_interval_system(p.system)) : solver.solve(p.system);
    } catch (const std::exception& ex) {
      CHECK(false, p.name << ": solve threw " << ex.what() << "\n" << system_string(p.system));
      continue;
    }
    double sec = std::chrono::duration<double>(std::chrono::steady_clock::now() - s0).count();
    if (sec > slowest) { slowest = sec; slowest_name = p.name; }
    int before = failures;
    total.add(check_result(r, p, e, p.name + (interval ? " [Interval_nt coefficients]" : "")));
    if (failures > before && failures <= max_messages) std::cerr << "  system:\n" << system_string(p.system);
  }
  double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  std::cout << "test_subdivision_solver_random: " << total.systems << " systems (" << interval_inputs << " with Interval_nt coefficients, "
            << face_boxes << " with a face through a root), " << planted_roots << " planted roots, " << total.roots_in_box
            << " in the boxes (" << total.boundary_roots << " on faces), " << total.certified << " certified, " << total.unresolved
            << " unresolved boxes, " << total.beyond_precision << " roots beyond double precision, " << total.complete << " complete; "
            << outside_near << " systems with a root just outside; slowest " << slowest << " s (" << slowest_name << "); " << checks
            << " checks, " << failures << " failures, " << seconds << " s\n";
  return failures == 0 ? 0 : 1;
}
