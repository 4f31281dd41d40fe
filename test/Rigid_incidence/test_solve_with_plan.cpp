// Copyright (c) 2026 Rigid_incidence contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Plan solving (solve_with_plan, Algorithm 6 of decomposition_subdivision_solver.txt) and the
// solver's inequalities, on random planted block-triangular systems (planted_systems.h): the
// variables fall in random blocks; the factors of an equation involve its own block and the
// blocks before it only, and the coupling A mixes equations within a block only, so the
// system is block triangular. The oracle knows every real root exactly. For every system:
//  - the plan solves it completely, every planted root in the box is in exactly one certified
//    enclosure, no enclosure is spurious;
//  - the undecomposed solver finds the same roots (the same count, approximations within 1e-8),
//    or, where it runs out of boxes, a subset of them;
//  - with a random affine inequality g >= 0 (no root on g = 0): exactly the planted roots with
//    g > 0, with and without the plan;
// and CGAL::Gmpfi as the interval type on a few systems; the same systems with interval
// coefficients (as solve_scene() gives them: a block with inputs once renumbered them away,
// wrong roots); solve_with_plan_over_charts() with each variable of a system of several blocks
// its own chart group, chart 0 its box's lower half and chart 1 its upper half: for every
// assignment of charts, what it found is what solve_with_plan() finds on that assignment's
// system (the oracle), with fewer block solves, and over all assignments every planted root;
// with 2 and 3 threads (Subdivision_solver_parameters::threads), solve_with_plan() and
// solve_with_plan_over_charts() give what one thread gives, bound for bound and in the same
// order, with the same statistics (in double and in Gmpfi, whose default precision is per
// thread); malformed input throws Input_error.
// Usage: test_solve_with_plan [systems [seed]] (or RI_TEST_SYSTEMS=systems in the environment)

#include "planted_systems.h"

#include <CGAL/Rigid_incidence/Input_error.h>
#include <CGAL/Rigid_incidence/Solution_plan.h>
#include <CGAL/Rigid_incidence/Subdivision_solver.h>
#include <CGAL/Rigid_incidence/solve_with_plan.h>

#include <algorithm>
#include <cstdlib>
#include <functional>
#include <iostream>
#include <string>

using namespace planted_systems;

typedef CGAL::Interval_nt<false> I;

// `p` with each coefficient enclosed in a double interval
static RI::Polynomial_system<I> with_interval_coefficients(const RI::Polynomial_system<Q>& p)
{
  RI::Polynomial_system<I> r;
  r.variable_names = p.variable_names;
  r.box = p.box;
  r.labels = p.labels;
  auto convert = [](const RI::Sparse_polynomial<Q>& f) {
    RI::Sparse_polynomial<I> g(f.number_of_variables());
    for (const auto& t : f.terms()) g.add_term(t.first, I(CGAL::to_interval(t.second)));
    return g;
  };
  for (const auto& f : p.equations) r.equations.push_back(convert(f));
  for (const auto& f : p.inequalities) r.inequalities.push_back(convert(f));
  r.inequality_labels = p.inequality_labels;
  return r;
}

// Every planted root of `p` strictly inside the box with g > 0 (g empty: no inequality).
static std::vector<Point> expected_roots(const Planted& p, const Affine* g)
{
  std::vector<Point> r;
  for (const auto& x : p.roots)
    if (in_box(x.x, p.system.box) && (!g || (*g)(x.x) > 0)) r.push_back(x.x);
  return r;
}

// a and b the same, bound for bound and in the same order (a run on several threads against
// one on one thread)
template <class IT>
static bool same_plan_result(const RI::Plan_result<IT>& a, const RI::Plan_result<IT>& b, std::string& why)
{
  auto same_box = [](const std::vector<IT>& x, const std::vector<IT>& y) {
    if (x.size() != y.size()) return false;
    for (std::size_t j = 0; j < x.size(); ++j)
      if (!(x[j].inf() == y[j].inf() && x[j].sup() == y[j].sup())) return false;
    return true;
  };
  if (a.roots.size() != b.roots.size()) { why = std::to_string(a.roots.size()) + " roots against " + std::to_string(b.roots.size()); return false; }
  for (std::size_t i = 0; i < a.roots.size(); ++i)
    if (!same_box(a.roots[i].enclosure, b.roots[i].enclosure) || a.roots[i].approximation != b.roots[i].approximation ||
        a.roots[i].certified != b.roots[i].certified || a.roots[i].precision != b.roots[i].precision) {
      why = "root " + std::to_string(i) + " differs";
      return false;
    }
  if (a.unresolved.size() != b.unresolved.size()) { why = "regions differ in number"; return false; }
  for (std::size_t i = 0; i < a.unresolved.size(); ++i)
    if (a.unresolved[i].block != b.unresolved[i].block || a.unresolved[i].reason != b.unresolved[i].reason ||
        !same_box(a.unresolved[i].box, b.unresolved[i].box)) {
      why = "region " + std::to_string(i) + " differs";
      return false;
    }
  if (a.block_solves != b.block_solves || a.boxes != b.boxes || a.krawczyk_tests != b.krawczyk_tests || a.refinements != b.refinements ||
      a.refinements_sparse != b.refinements_sparse || a.refinements_multiprecision != b.refinements_multiprecision ||
      a.refinements_failed != b.refinements_failed || a.diagnosis != b.diagnosis) {
    why = "statistics differ (" + std::to_string(a.block_solves) + " block solves, " + std::to_string(a.boxes) + " boxes against " +
          std::to_string(b.block_solves) + ", " + std::to_string(b.boxes) + ")";
    return false;
  }
  return true;
}

template <class Root>
static void check_roots(const std::vector<Root>& roots, const std::vector<Point>& expected, const std::string& name)
{
  CHECK(roots.size() == expected.size(), name << ": " << roots.size() << " roots, expected " << expected.size());
  for (const auto& x : expected) {
    int in = 0;
    for (const auto& r : roots) {
      Q_box b;
      if (exact_box(r.enclosure, b) && contains(b, x)) ++in;
    }
    CHECK(in == 1, name << ": planted root " << point_string(x) << " is in " << in << " enclosures");
  }
  for (const auto& r : roots) {
    Q_box b;
    CHECK(exact_box(r.enclosure, b), name << ": an enclosure is not a valid box");
    CHECK(r.certified, name << ": a root is not certified " << box_string(b));
    CHECK(max_width(b) <= Q(1e-9), name << ": an enclosure is " << CGAL::to_double(max_width(b)) << " wide");
  }
}

int main(int argc, char** argv)
{
  // (the sanitizer build sets RI_TEST_SYSTEMS to run fewer: the same code, several times slower)
  const int systems = argc > 1 ? std::atoi(argv[1]) : std::getenv("RI_TEST_SYSTEMS") ? std::atoi(std::getenv("RI_TEST_SYSTEMS")) : 120;
  const std::uint64_t seed = argc > 2 ? std::strtoull(argv[2], nullptr, 10) : 20261123;
  std::cout << "test_solve_with_plan: seed " << seed << ", " << systems << " systems\n";
  Rng rng(seed);
  std::size_t solved = 0, roots = 0, blocks = 0, plan_boxes = 0, plain_boxes = 0, plan_boxes_compared = 0, undecomposed_incomplete = 0, refinements = 0, refinements_failed = 0, sparse_refinements = 0, kept = 0, gmpfi_runs = 0,
              interval_runs = 0, chart_runs = 0, chart_block_solves = 0, chart_separate_solves = 0, threaded_runs = 0, pending_regions = 0;
  bool refusal_checked = false;
  for (int s = 0; s < systems; ++s) {
    // blocks of 1 to 3 variables, 2 to 6 variables in all, 1 to 3 factors per equation
    const std::size_t n = std::size_t(rng.uniform(2, 6));
    std::vector<unsigned> degrees(n);
    for (auto& d : degrees) d = unsigned(rng.uniform(1, 3));
    std::vector<std::vector<std::size_t>> members;
    std::vector<std::vector<Q>> A;
    const auto factors = block_triangular_factors(rng, degrees, -1, members, A);
    Planted p;
    if (!make_planted(factors, A, cube(n, -2, 2), p)) continue;  // not zero-dimensional, or a singular root
    // no root near the box's faces (a root just outside may come back flagged on_boundary)
    bool near_face = false;
    for (const auto& x : p.roots)
      for (std::size_t i = 0; i < n; ++i) {
        double d = (std::min)(std::abs(CGAL::to_double(x.x[i]) - 2), std::abs(CGAL::to_double(x.x[i]) + 2));
        if (d < 1e-6) near_face = true;
      }
    if (near_face) continue;
    const std::string name = "system " + std::to_string(s) + " (" + std::to_string(n) + " variables)";
    RI::Solution_plan plan(p.system);
    CHECK(plan.structure() == RI::Solution_plan::WELL_CONSTRAINED, name << ": not well-constrained");
    CHECK(plan.blocks().size() >= members.size(), name << ": " << plan.blocks().size() << " blocks, planted " << members.size());
    blocks += plan.blocks().size();
    ++solved;

    const std::vector<Point> all = expected_roots(p, nullptr);
    roots += all.size();
    auto pr = RI::solve_with_plan(p.system, plan);
    CHECK(pr.complete(), name << ": the plan's solve is not complete");
    check_roots(pr.roots, all, name + " with the plan");
    plan_boxes += pr.boxes;
    if (plan.blocks().size() > 1 && s % 2 == 1) {
      for (unsigned t : {2u, 3u}) {
        RI::Subdivision_solver_parameters prm;
        prm.threads = t;
        std::string why;
        CHECK(same_plan_result(RI::solve_with_plan(p.system, plan, prm), pr, why),
              name << ": with " << t << " threads, not what one thread gives: " << why);
      }
      {
        // a budget of 12 boxes per block solve: regions left pending in many branches, whose
        // order (unlike the roots', sorted) is the order the branches are merged in
        RI::Subdivision_solver_parameters small;
        small.maximal_boxes = 12;
        const auto one = RI::solve_with_plan(p.system, plan, small);
        small.threads = 2;
        std::string why;
        CHECK(same_plan_result(RI::solve_with_plan(p.system, plan, small), one, why),
              name << ": with 12 boxes per block solve and 2 threads, not what one thread gives: " << why);
        pending_regions += one.unresolved.size();
      }
      ++threaded_runs;
    }
    if (plan.blocks().size() > 1 && s % 3 == 0) {
      const RI::Polynomial_system<I> ip = with_interval_coefficients(p.system);
      auto ir = RI::solve_with_plan(ip, RI::Solution_plan(ip));
      CHECK(ir.complete(), name << ": the plan's solve with interval coefficients is not complete");
      check_roots(ir.roots, all, name + " with the plan and interval coefficients");
      ++interval_runs;
    }
    if (plan.blocks().size() > 1 && n <= 5 && s % 2 == 0) {
      // halves of the box as charts: 2^n assignments, each solved whole along the plan too
      auto make = [&](const std::vector<int>& charts) {
        RI::Polynomial_system<Q> h = p.system;
        for (std::size_t j = 0; j < n; ++j) {
          const double mid = 0.5 * h.box[j].first + 0.5 * h.box[j].second;
          h.box[j] = charts[j] == 0 ? std::make_pair(h.box[j].first, mid) : std::make_pair(mid, h.box[j].second);
        }
        return h;
      };
      std::vector<std::size_t> group(n);
      for (std::size_t j = 0; j < n; ++j) group[j] = j;
      const std::function<RI::Polynomial_system<Q>(const std::vector<int>&)> f = make;
      const auto oc = RI::solve_with_plan_over_charts<CGAL::Interval_nt<false>, Q>(plan, group, std::vector<int>(n, 2), f);
      {
        RI::Subdivision_solver_parameters prm;
        prm.threads = 2;
        const auto oc2 = RI::solve_with_plan_over_charts<CGAL::Interval_nt<false>, Q>(plan, group, std::vector<int>(n, 2), f, prm);
        std::string why;
        CHECK(oc2.found.size() == oc.found.size(), name << ": over charts with 2 threads, " << oc2.found.size() << " assignments, one thread " << oc.found.size());
        for (std::size_t i = 0; i < oc.found.size() && i < oc2.found.size(); ++i)
          CHECK(oc2.found[i].charts == oc.found[i].charts && same_plan_result(oc2.found[i].result, oc.found[i].result, why),
                name << ": over charts with 2 threads, assignment " << i << " differs: " << why);
        CHECK(same_plan_result(oc2.totals, oc.totals, why), name << ": over charts with 2 threads, totals differ: " << why);
      }
      std::vector<int> charts(n, 0);
      std::size_t separate_solves = 0, found_roots = 0;
      std::size_t next = 0;  // into oc.found, in lexicographic order of the charts
      std::vector<std::vector<int>> order;
      for (;;) {
        order.push_back(charts);
        std::size_t k = n;
        while (k > 0 && ++charts[k - 1] == 2) charts[--k] = 0;
        if (k == 0) break;
      }
      std::sort(order.begin(), order.end());
      for (const auto& a : order) {
        const auto alone = RI::solve_with_plan(make(a), plan);
        separate_solves += alone.block_solves;
        const RI::Plan_result<CGAL::Interval_nt<false>>* mine = nullptr;
        if (next < oc.found.size() && oc.found[next].charts == a) mine = &oc.found[next++].result;
        const std::size_t got = mine ? mine->roots.size() : 0;
        CHECK(got == alone.roots.size(), name << ": over charts, " << got << " roots in one assignment, alone " << alone.roots.size());
        CHECK((mine ? mine->unresolved.size() : 0) == alone.unresolved.size(), name << ": over charts, regions differ from alone");
        for (std::size_t i = 0; mine && i < got && i < alone.roots.size(); ++i)
          for (std::size_t j = 0; j < n; ++j)
            CHECK(std::abs(mine->roots[i].approximation[j] - alone.roots[i].approximation[j]) < 1e-8, name << ": over charts, another root");
        found_roots += got;
      }
      CHECK(next == oc.found.size(), name << ": over charts, an assignment found twice or out of order");
      CHECK(oc.totals.block_solves <= separate_solves, name << ": over charts, " << oc.totals.block_solves << " block solves, alone " << separate_solves);
      CHECK(found_roots >= all.size(), name << ": over charts, " << found_roots << " roots for " << all.size() << " planted");
      chart_block_solves += oc.totals.block_solves;
      chart_separate_solves += separate_solves;
      ++chart_runs;
    }
    refinements += pr.refinements;
    refinements_failed += pr.refinements_failed;
    // exact coefficients: every root of several blocks within the tolerance, but those the
    // result counts as left wider (the whole system's dense test, else its sparse test in
    // double and then in MPFR)
    if (plan.blocks().size() > 1) {
      std::size_t wide = 0;
      const double tolerance = RI::Subdivision_solver_parameters().tolerance;
      for (const auto& r : pr.roots) {
        double w = 0;
        bool inside = true;  // (the approximation is a point of the final enclosure, not of the blocks' product)
        for (std::size_t j = 0; j < r.enclosure.size(); ++j) {
          const auto& x = r.enclosure[j];
          w = (std::max)(w, x.sup() - x.inf());
          inside = inside && x.inf() <= r.approximation[j] && r.approximation[j] <= x.sup();
        }
        wide += r.certified && w > tolerance;
        CHECK(inside, name << ": a root's approximation outside its enclosure");
      }
      CHECK(wide <= pr.refinements_failed, name << ": " << wide << " roots wider than the tolerance, " << pr.refinements_failed << " counted");
      sparse_refinements += pr.refinements_sparse;
    }
    // the undecomposed solver (costly beyond 4 variables: every tenth system there)
    const bool undecomposed = n <= 4 || s % 10 == 0;
    if (undecomposed) {
      auto whole = RI::Subdivision_solver<>().solve(p.system);
      plain_boxes += whole.statistics.boxes;
      plan_boxes_compared += pr.boxes;
      if (!whole.complete()) {
        // the undecomposed solver ran out of boxes: its roots must still be among the plan's
        ++undecomposed_incomplete;
        CHECK(whole.roots.size() <= pr.roots.size(), name << ": undecomposed " << whole.roots.size() << " roots, plan " << pr.roots.size());
      } else
      CHECK(whole.roots.size() == pr.roots.size(), name << ": undecomposed " << whole.roots.size() << " roots, plan " << pr.roots.size());
      for (const auto& w : whole.roots) {
        int same = 0;
        for (const auto& r : pr.roots) {
          bool close = true;
          for (std::size_t j = 0; j < n; ++j) close = close && std::abs(w.approximation[j] - r.approximation[j]) < 1e-8;
          same += close;
        }
        CHECK(same == 1, name << ": a root of the undecomposed solver is near " << same << " roots of the plan");
      }
    }

    // an affine inequality g >= 0, away from every root
    Affine g;
    g.c.assign(n, Q(0));
    for (std::size_t j = 0; j < n; ++j) g.c[j] = rng.rational(3, 2);
    g.c0 = rng.rational(1, 4);
    bool on_g = false;
    for (const auto& x : p.roots) if (CGAL::abs(g(x.x)) < Q(1, 1000000)) on_g = true;
    if (!on_g) {
      RI::Polynomial_system<Q> q = p.system;
      q.inequalities.push_back(affine_poly(g));
      RI::Solution_plan qplan(q);
      CHECK(qplan.number_of_inequalities() == 1 && qplan.inequality_variables(0) == q.inequalities[0].variables(),
            name << ": the plan of a system takes its inequalities");
      if (!refusal_checked) {  // a plan made without the inequality would let roots with g < 0 through: refused
        bool thrown = false;
        try { RI::solve_with_plan(q, RI::Solution_plan(q, {})); } catch (const RI::Input_error& e) {
          thrown = std::string(e.what()).find("0 inequalities, the system has 1") != std::string::npos;
        }
        CHECK(thrown, name << ": a plan without the system's inequality is not refused");
        refusal_checked = true;
      }
      const std::vector<Point> want = expected_roots(p, &g);
      kept += want.size();
      auto qr = RI::solve_with_plan(q, qplan);
      CHECK(qr.complete(), name << ": the plan's solve with an inequality is not complete");
      check_roots(qr.roots, want, name + " with the plan and g >= 0");
      if (undecomposed) {
        auto qw = RI::Subdivision_solver<>().solve(q);
        CHECK(qw.complete(), name << ": the solve with an inequality is not complete");
        check_roots(qw.roots, want, name + " with g >= 0");
        CHECK(qw.roots.size() + qw.statistics.rejected_roots <= all.size(),
              name << ": " << qw.roots.size() << " kept + " << qw.statistics.rejected_roots << " rejected > " << all.size());
      }
    }
#ifdef CGAL_USE_MPFI
    if (s % 20 == 0) {
      RI::Subdivision_solver_parameters prm;
      prm.precision = 80;
      auto gr = RI::solve_with_plan<CGAL::Gmpfi>(p.system, plan, prm);
      CHECK(gr.complete(), name << ": the plan's solve in Gmpfi is not complete");
      if (plan.blocks().size() > 1) {  // (the workers must compute at 80 bits too)
        prm.threads = 2;
        std::string why;
        CHECK(same_plan_result(RI::solve_with_plan<CGAL::Gmpfi>(p.system, plan, prm), gr, why),
              name << ": in Gmpfi with 2 threads, not what one thread gives: " << why);
      }
      check_roots(gr.roots, all, name + " with the plan in Gmpfi");
      ++gmpfi_runs;
    }
#endif
  }
  CHECK(solved >= std::size_t(systems) / 2, "only " << solved << " systems were usable");
  CHECK(interval_runs > 0 || systems < 20, "no system of several blocks solved with interval coefficients");
  CHECK(chart_runs > 0 || systems < 20, "no system solved over charts");
  CHECK(threaded_runs > 0 || systems < 20, "no system of several blocks solved on several threads");
  CHECK(pending_regions > 0 || systems < 20, "no region left pending with 12 boxes per block solve");
  CHECK(chart_block_solves < chart_separate_solves || systems < 20, "over charts: no block solve saved");
  CHECK(refinements_failed * 100 <= refinements, refinements_failed << " of " << refinements << " whole-system refinements failed");

  // malformed input
  {
    RI::Polynomial_system<Q> s;
    s.variable_names = {"x", "y"};
    s.box = cube(2, -1, 1);
    auto x = Poly::variable(2, 0), y = Poly::variable(2, 1);
    s.equations = {x * x - Poly::constant(2, Q(1, 4)), x * y - Poly::constant(2, Q(1, 8))};
    RI::Solution_plan plan(s);
    CHECK(plan.blocks().size() == 2, "x^2 = 1/4, xy = 1/8: two blocks, got " << plan.blocks().size());
    auto r = RI::solve_with_plan(s, plan);
    CHECK(r.roots.size() == 2 && r.complete(), "x^2 = 1/4, xy = 1/8: " << r.roots.size() << " roots");
    {  // the plan of y^2 = 1/4, xy = 1/8 (same size, y first) for this system: refused
      RI::Polynomial_system<Q> swapped = s;
      swapped.equations[0] = y * y - Poly::constant(2, Q(1, 4));
      std::string what;
      try { RI::solve_with_plan(s, RI::Solution_plan(swapped)); } catch (const RI::Input_error& e) { what = e.what(); }
      CHECK(what.find("equation 0 involves variable 0") != std::string::npos, "a plan of another system of the same size: " << what);
    }
    RI::Polynomial_system<Q> t = s;
    t.equations.push_back(x + y);
    t.variable_names.push_back("z");
    t.box.push_back({-1, 1});
    for (auto& f : t.equations) {
      Poly g(3);
      for (const auto& term : f.terms()) { auto e = term.first; e.push_back(0); g.add_term(e, term.second); }
      f = g;
    }
    std::string what;
    try { RI::solve_with_plan(t, plan); } catch (const RI::Input_error& e) { what = e.what(); }
    CHECK(what.find("the plan is for 2 equations") != std::string::npos, "a plan of another system: " << what);
    // 3 equations in x, y (z unused): over- and under-determined parts named
    what.clear();
    try { RI::solve_with_plan(t, RI::Solution_plan(t)); } catch (const RI::Input_error& e) { what = e.what(); }
    CHECK(what.find("over-determined") != std::string::npos && what.find("equation 0") != std::string::npos,
          "over-determined system: " << what);
    // x^2 = 1/4, x + y = 0 in x, y, z: z is free
    RI::Polynomial_system<Q> u = t;
    u.equations = {t.equations[0], Poly::variable(3, 0) + Poly::variable(3, 1)};
    what.clear();
    try { RI::solve_with_plan(u, RI::Solution_plan(u)); } catch (const RI::Input_error& e) { what = e.what(); }
    CHECK(what.find("under-determined") != std::string::npos && what.find("z") != std::string::npos, "under-determined system: " << what);
  }

  std::cout << solved << " systems, " << roots << " roots in the boxes, " << blocks << " blocks; boxes with the plan " << plan_boxes
            << " (" << plan_boxes_compared << " on the systems also solved undecomposed, which took " << plain_boxes
            << " and ran out of boxes on " << undecomposed_incomplete << "); " << refinements << " roots refined on the whole system ("
            << sparse_refinements << " by the sparse test, " << refinements_failed << " left wider than the tolerance); " << kept << " roots kept by the inequalities; " << gmpfi_runs << " Gmpfi runs, "
            << interval_runs << " with interval coefficients; " << chart_runs << " over charts (box halves): " << chart_block_solves
            << " block solves, " << chart_separate_solves << " for each assignment alone; " << threaded_runs
            << " solved again on 2 and 3 threads (" << pending_regions << " regions left pending with 12 boxes, in the same order; oneTBB " << (RI::internal::parallel_available() ? "on" : "off: sequential") << ")\n";
  std::cout << checks << " checks, " << failures << " failures\n";
  return failures == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
