// Copyright (c) 2026 Rigid_incidence contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Plan solving (decomposition_subdivision_solver.txt, Algorithm 6): the blocks of a
// Solution_plan are solved one after the other, each root of a block substituted (as its
// certified enclosure) into the blocks after it, branching over every root.

#ifndef CGAL_RIGID_INCIDENCE_SOLVE_WITH_PLAN_H
#define CGAL_RIGID_INCIDENCE_SOLVE_WITH_PLAN_H

#include <CGAL/Rigid_incidence/Input_error.h>
#include <CGAL/Rigid_incidence/Polynomial_system.h>
#include <CGAL/Rigid_incidence/Solution_plan.h>
#include <CGAL/Rigid_incidence/Solver_result.h>
#include <CGAL/Rigid_incidence/Subdivision_solver.h>
#include <CGAL/Rigid_incidence/internal/interval_ops.h>
#include <CGAL/Rigid_incidence/internal/parallel.h>
#include <CGAL/Rigid_incidence/internal/sparse_krawczyk.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <exception>
#include <functional>
#include <memory>
#include <mutex>
#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

namespace CGAL {
namespace Rigid_incidence {

/// \ingroup PkgRigidIncidenceSolver
/// A solution of the whole system found by `solve_with_plan()`.
template <class IT>
struct Plan_root
{
  std::vector<IT> enclosure;          ///< per variable, an interval containing the root
  std::vector<double> approximation;  ///< per variable, a point of the enclosure as a double
  /// every block's root was certified: the system has exactly one root in the product of
  /// the blocks' uniqueness boxes (block triangular: each block's proof holds for every value
  /// of its inputs in their enclosures), and it lies in `enclosure`
  bool certified = false;
  bool on_boundary = false;             ///< some block's root meets the search box's boundary
  bool on_inequality_boundary = false;  ///< some inequality may be 0 there
  /// bits of the interval arithmetic that gave `enclosure` its width (53: double; more where
  /// the whole system's Krawczyk test ran in `CGAL::Gmpfi` to reach the tolerance)
  unsigned precision = 53;
};

/// \ingroup PkgRigidIncidenceSolver
/// A region of one block the solver could not decide, with the values of the blocks before it.
template <class IT>
struct Plan_unresolved
{
  std::size_t block = 0;           ///< index into `Solution_plan::blocks()`
  Box_class kind = Box_class::UNKNOWN;  ///< `UNKNOWN` or `PENDING`
  std::string reason;              ///< the block solver's reason
  /// per variable: the enclosures of the variables solved before this block, the unresolved
  /// box for this block's variables, the search box for the variables after it
  std::vector<IT> box;
};

/// \ingroup PkgRigidIncidenceSolver
/// The result of `solve_with_plan()`.
template <class IT>
struct Plan_result
{
  std::vector<Plan_root<IT>> roots;             ///< the roots of the whole system, sorted by approximation
  std::vector<Plan_unresolved<IT>> unresolved;  ///< what a block left undecided
  std::string diagnosis;               ///< the first block diagnosis met, if any
  std::size_t block_solves = 0;        ///< sub-systems solved (a block once per combination of the roots before it)
  /// block solves not run again: a block no earlier value enters (an independent part) is
  /// solved once per assignment of its own charts, its roots reused for every combination of
  /// the roots before it
  std::size_t block_solves_reused = 0;
  std::size_t boxes = 0;               ///< boxes over all block solves
  std::size_t krawczyk_tests = 0;      ///< Krawczyk tests over all block solves
  std::size_t refinements = 0;         ///< roots tightened on the whole system
  /// of those, the ones tightened by the Krawczyk test on the whole system's sparse
  /// polynomials (the dense test could not run, the whole system beyond the dense arrays, or
  /// left the root wider than the tolerance)
  std::size_t refinements_sparse = 0;
  /// of those, the ones that needed `CGAL::Gmpfi` (exact coefficients, MPFI available) to reach
  /// the tolerance: the widths double precision reached were those of the chain of blocks
  std::size_t refinements_multiprecision = 0;
  /// of `refinements`, the ones left wider than the tolerance (certified, and as wide as the
  /// precision allowed: `Plan_root::precision` says which)
  std::size_t refinements_failed = 0;
  double seconds = 0;                  ///< wall-clock time
  /// every root certified and nothing unresolved
  bool complete() const
  {
    if (!unresolved.empty()) return false;
    for (const auto& r : roots) if (!r.certified) return false;
    return true;
  }
};

namespace internal {

// f with the variables `known` replaced by their enclosures, as a polynomial in the block's
// variables `local` (f's variables must all be known or in `local`).
template <class IT, class NT>
Sparse_polynomial<IT> restrict_polynomial(const Sparse_polynomial<NT>& f, const std::vector<std::size_t>& local, const std::vector<IT>& value,
                                          const std::vector<char>& known)
{
  typedef Interval_ops<IT> O;
  Sparse_polynomial<IT> r(local.size());
  std::vector<std::size_t> where(f.number_of_variables(), std::size_t(-1));
  for (std::size_t k = 0; k < local.size(); ++k) where[local[k]] = k;
  for (const auto& t : f.terms()) {
    IT c = O::from(t.second);
    typename Sparse_polynomial<IT>::Exponent e(local.size(), 0);
    for (std::size_t j = 0; j < t.first.size(); ++j) {
      if (t.first[j] == 0) continue;
      if (where[j] != std::size_t(-1)) e[where[j]] = t.first[j];
      else {
        // (a plan made for the system never leaves one unknown: a plain check, not an assertion
        // compiled out of a release build)
        if (!known[j]) throw std::logic_error("solve_with_plan: variable " + std::to_string(j) + " used before its block is solved");
        for (unsigned p = 0; p < t.first[j]; ++p) c = c * value[j];
      }
    }
    r.add_term(e, c);
  }
  return r;
}

// f and g term by term, coefficients bound for bound (not as numbers: an interval is only
// the same interval)
template <class NT>
bool identical_polynomials(const Sparse_polynomial<NT>& f, const Sparse_polynomial<NT>& g)
{
  if (f.number_of_variables() != g.number_of_variables() || f.terms().size() != g.terms().size()) return false;
  auto i = f.terms().begin();
  for (auto j = g.terms().begin(); j != g.terms().end(); ++i, ++j) {
    if (i->first != j->first) return false;
    if constexpr (std::is_same<NT, CGAL::Gmpq>::value) {
      if (i->second != j->second) return false;
    } else {
      typedef Interval_ops<NT> O;
      if (!(O::lower(i->second) == O::lower(j->second)) || !(O::upper(i->second) == O::upper(j->second))) return false;
    }
  }
  return true;
}

// The same equations, inequalities and box, coefficient for coefficient.
template <class NT>
bool identical_systems(const Polynomial_system<NT>& a, const Polynomial_system<NT>& b)
{
  if (a.equations.size() != b.equations.size() || a.inequalities.size() != b.inequalities.size() || a.box != b.box) return false;
  for (std::size_t i = 0; i < a.equations.size(); ++i)
    if (!identical_polynomials(a.equations[i], b.equations[i])) return false;
  for (std::size_t q = 0; q < a.inequalities.size(); ++q)
    if (!identical_polynomials(a.inequalities[q], b.inequalities[q])) return false;
  return true;
}

// f renumbered to the variables `local` (increasing; f involves no other variable)
template <class NT>
Sparse_polynomial<NT> renumbered(const Sparse_polynomial<NT>& f, const std::vector<std::size_t>& local)
{
  Sparse_polynomial<NT> r(local.size());
  for (const auto& t : f.terms()) {
    typename Sparse_polynomial<NT>::Exponent e(local.size(), 0);
    for (std::size_t k = 0; k < local.size(); ++k) e[k] = t.first[local[k]];
    r.add_term(e, t.second);
  }
  return r;
}

// The equations and inequalities of an independent part of `s` (independent_parts()) in the
// part's own variables, with their names, box and labels.
template <class NT>
Polynomial_system<NT> part_system(const Polynomial_system<NT>& s, const Independent_part& part)
{
  Polynomial_system<NT> r;
  for (std::size_t j : part.variables) {
    r.variable_names.push_back(j < s.variable_names.size() ? s.variable_names[j] : "x" + std::to_string(j));
    r.box.push_back(s.box[j]);
  }
  for (std::size_t i : part.equations) {
    r.equations.push_back(renumbered(s.equations[i], part.variables));
    r.labels.push_back(i < s.labels.size() ? s.labels[i] : std::string());
  }
  for (std::size_t q : part.inequalities) {
    r.inequalities.push_back(renumbered(s.inequalities[q], part.variables));
    r.inequality_labels.push_back(q < s.inequality_labels.size() ? s.inequality_labels[q] : std::string());
  }
  return r;
}

template <class IT, class NT> struct Plan_run
{
  typedef Interval_ops<IT> O;
  const Polynomial_system<NT>* sys;  // the system of the current charts
  const Solution_plan& plan;
  const Subdivision_solver_parameters& P;
  Plan_result<IT> result;  // the roots and regions (with charts: the totals only)
  // With charts (solve_with_plan_over_charts()): per variable its chart group (npos: one
  // chart), per group its number of charts, the system of an assignment of charts; the
  // current assignment (groups no block has reached yet at chart 0), and what each full
  // assignment found.
  const std::vector<std::size_t>* group = nullptr;
  const std::vector<int>* radix = nullptr;
  std::function<Polynomial_system<NT>(const std::vector<int>&)> make_system;
  std::vector<int> charts;
  std::vector<char> assigned;
  std::map<std::vector<int>, Plan_result<IT>> by_charts;
  Plan_result<IT>& target() { return group ? by_charts[charts] : result; }
  std::vector<IT> value;
  std::vector<char> known;
  // refine() refused the whole system (too large for its dense arrays: the same for every root
  // and chart): not tried again, by any branch
  std::shared_ptr<std::atomic<bool>> whole_too_large = std::make_shared<std::atomic<bool>>(false);
  // A block no earlier value enters (an independent part of the system, such as the next
  // plate of stacked platforms written in its own parent's frame) has the same system on every
  // branch: it is solved once per assignment of its own charts and its result reused (issue
  // 28, item 1: the parts' work adds up instead of multiplying). Shared by all branches.
  struct Own_solve
  {
    std::once_flag once;
    Polynomial_system<NT> system;  // the block's system it was solved for (checked on reuse)
    Solver_result<IT> result;
  };
  struct Own_solves
  {
    std::mutex lock;
    std::map<std::pair<std::size_t, std::vector<int>>, std::shared_ptr<Own_solve>> by_block_and_charts;
  };
  std::shared_ptr<Own_solves> own_solves = std::make_shared<Own_solves>();

  const std::chrono::steady_clock::time_point start = std::chrono::steady_clock::now();
  Plan_run(const Plan_run&) = delete;

  Plan_run(const Polynomial_system<NT>& s, const Solution_plan& p, const Subdivision_solver_parameters& q)
      : sys(&s), plan(p), P(q), value(s.number_of_variables()), known(s.number_of_variables(), 0)
  {
  }
  // a branch of `o`: its state (the system, charts, values so far), nothing found yet
  struct Branch_tag {};
  Plan_run(const Plan_run& o, Branch_tag)
      : sys(o.sys), plan(o.plan), P(o.P), group(o.group), radix(o.radix), make_system(o.make_system), charts(o.charts),
        assigned(o.assigned), value(o.value), known(o.known), whole_too_large(o.whole_too_large), own_solves(o.own_solves),
        start(o.start)
  {
  }
  // what a branch found, after what this run found (the order of a sequential run)
  void merge(Plan_run& o)
  {
    Plan_result<IT>& a = result;
    Plan_result<IT>& b = o.result;
    for (auto& r : b.roots) a.roots.push_back(std::move(r));
    for (auto& u : b.unresolved) a.unresolved.push_back(std::move(u));
    if (a.diagnosis.empty()) a.diagnosis = b.diagnosis;
    a.block_solves += b.block_solves;
    a.block_solves_reused += b.block_solves_reused;
    a.boxes += b.boxes;
    a.krawczyk_tests += b.krawczyk_tests;
    a.refinements += b.refinements;
    a.refinements_sparse += b.refinements_sparse;
    a.refinements_multiprecision += b.refinements_multiprecision;
    a.refinements_failed += b.refinements_failed;
    for (auto& x : o.by_charts) {
      Plan_result<IT>& t = by_charts[x.first];
      for (auto& r : x.second.roots) t.roots.push_back(std::move(r));
      for (auto& u : x.second.unresolved) t.unresolved.push_back(std::move(u));
    }
  }
  // branch(k, run) for k in [0, n): on this run, one after the other, with one thread; else
  // each on a run of its own in parallel (Subdivision_solver_parameters::threads), merged in
  // the order of k. A branch leaves the state it changed as it found it.
  template <class F> void fork(std::size_t n, const F& branch)
  {
    if (n <= 1 || worker_threads(P.threads) <= 1) {
      for (std::size_t k = 0; k < n; ++k) branch(k, *this);
      return;
    }
    std::vector<std::unique_ptr<Plan_run>> runs(n);
    parallel_for_each_index(n, P.threads, [&](std::size_t k) {
      runs[k].reset(new Plan_run(*this, Branch_tag()));
      branch(k, *runs[k]);
    });
    for (auto& r : runs) merge(*r);
  }

  double elapsed() const { return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(); }
  // why the blocks still to solve are not (the interrupt, or maximal_seconds for the whole
  // plan, not for each block solve), or empty
  std::string stop_reason() const
  {
    if (P.interrupt && P.interrupt->load(std::memory_order_relaxed)) return "interrupted";
    if (P.maximal_seconds > 0 && elapsed() > P.maximal_seconds) return "time budget exhausted";
    return std::string();
  }

  std::vector<IT> current_box(std::size_t b, const std::vector<IT>& local_box) const
  {
    std::vector<IT> box(sys->number_of_variables());
    const auto& vars = plan.blocks()[b].variables;
    for (std::size_t j = 0; j < box.size(); ++j) box[j] = known[j] ? value[j] : O::make(O::bound_from_double(sys->box[j].first), O::bound_from_double(sys->box[j].second));
    for (std::size_t k = 0; k < vars.size() && k < local_box.size(); ++k) box[vars[k]] = local_box[k];
    return box;
  }

  // `own`: no input enters the block, and its polynomials are renumbered with their own
  // coefficients (CT = NT); otherwise the inputs are substituted (CT = IT). Chosen by `own`,
  // not by the types: with interval coefficients NT is IT, and the inputs must still be
  // substituted (renumbering alone dropped them: wrong roots).
  // the block's equations and inequalities in its own variables, the inputs replaced by
  // `at` (where `known`)
  template <class CT> Polynomial_system<CT> block_system(const Plan_block& blk, bool own, const std::vector<IT>& at) const
  {
    auto restrict = [&](const Sparse_polynomial<NT>& f) -> Sparse_polynomial<CT> {
      if constexpr (std::is_same<CT, NT>::value)
        if (own) return renumbered(f, blk.variables);  // (exact: the block has no input)
      if constexpr (std::is_same<CT, IT>::value) return restrict_polynomial<IT>(f, blk.variables, at, known);
      else throw std::logic_error("solve_with_plan: a block with inputs solved with exact coefficients");
    };
    Polynomial_system<CT> s;
    for (std::size_t j : blk.variables) {
      s.variable_names.push_back(j < sys->variable_names.size() ? sys->variable_names[j] : "x" + std::to_string(j));
      s.box.push_back(sys->box[j]);
    }
    for (std::size_t i : blk.equations) {
      s.equations.push_back(restrict(sys->equations[i]));
      s.labels.push_back(i < sys->labels.size() ? sys->labels[i] : std::string());
    }
    for (std::size_t q : blk.inequalities) s.inequalities.push_back(restrict(sys->inequalities[q]));
    for (const auto& f : s.equations)
      if (f.is_zero())
        throw Input_error("solve_with_plan: an equation of block " + std::to_string(&blk - &plan.blocks()[0]) +
                          " vanishes identically once the values before it are substituted");
    return s;
  }
  // exact coefficients while nothing before the block enters it (its equations and
  // inequalities involve its own variables only)
  bool own_block(const Plan_block& blk) const
  {
    bool own = true;
    for (std::size_t i : blk.equations)
      for (std::size_t j : sys->equations[i].variables()) own = own && std::binary_search(blk.variables.begin(), blk.variables.end(), j);
    for (std::size_t q : blk.inequalities)
      for (std::size_t j : sys->inequalities[q].variables()) own = own && std::binary_search(blk.variables.begin(), blk.variables.end(), j);
    return own;
  }
  template <class CT> Solver_result<IT> solve_block(const Plan_block& blk, bool last, bool own)
  {
    return solve_block_system<CT>(block_system<CT>(blk, own, value), last);
  }
  template <class CT> Solver_result<IT> solve_block_system(const Polynomial_system<CT>& s, bool last)
  {
    Subdivision_solver_parameters q = P;
    // the roots of a block with blocks after it become their coefficients: tighter enclosures
    // keep those coefficients narrow
    if (!last) q.tolerance = P.tolerance * 1e-3;
    if (P.maximal_seconds > 0) q.maximal_seconds = (std::max)(P.maximal_seconds - elapsed(), 1e-3);
    return Subdivision_solver<IT>(q).solve(s);
  }

  void go(std::size_t b, bool certified, bool boundary, bool ineq_boundary)
  {
    if (b == plan.blocks().size()) {
      Plan_root<IT> r;
      r.enclosure = value;
      r.precision = O::multiprecision ? P.precision : O::bits();
      if (certified && plan.blocks().size() > 1 && widest(value) > P.tolerance) {
        // the blocks' enclosures carry the widths of the inputs through the chain (interval
        // coefficients evaluated term by term): the Krawczyk test on the whole system, from
        // their product, tightens the root to the tolerance (the root it proves unique in a
        // box holding the product is the one the blocks proved there). A product already
        // within the tolerance (blocks without inputs: independent parts) needs no test: the
        // blocks proved it.
        ++result.refinements;
        bool done = false;
        if (!*whole_too_large) try {
            if (auto t = Subdivision_solver<IT>(P).refine(*sys, value)) {
              r.enclosure = t->enclosure;
              done = widest(r.enclosure) <= P.tolerance;
            }
          } catch (const Input_error&) {
            // the whole system is beyond the solver's dense arrays (what the plan is for: two
            // stacked platforms): not tried again
            *whole_too_large = true;
          }
        // else the same test on the sparse polynomials (any size), in more bits where double
        // precision stops short; the blocks' certified enclosure stands where it cannot narrow
        if (!done) {
          ++result.refinements_sparse;
          if (!refine_sparse(r.enclosure, r.precision)) ++result.refinements_failed;
          else if (!O::multiprecision && r.precision > O::bits()) ++result.refinements_multiprecision;
        }
      }
      // (a point of the final enclosure: the blocks' product is wider than a refined root)
      for (const IT& v : r.enclosure) {
        const double m = 0.5 * O::lower_double(v) + 0.5 * O::upper_double(v);
        r.approximation.push_back((std::min)((std::max)(m, O::lower_double(v)), O::upper_double(v)));
      }
      r.certified = certified;
      r.on_boundary = boundary;
      r.on_inequality_boundary = ineq_boundary;
      target().roots.push_back(r);
      return;
    }
    const std::string stop = stop_reason();
    if (!stop.empty()) {
      // this block, for these values of the blocks before it, is left pending (with the
      // blocks after it)
      Plan_unresolved<IT> v;
      v.block = b;
      v.kind = Box_class::PENDING;
      v.reason = stop;
      v.box = current_box(b, std::vector<IT>());
      target().unresolved.push_back(v);
      return;
    }
    if (group) {
      // the chart groups of this block's variables no block before it has chosen: each
      // assignment of their charts is a system of its own for this block and those after it
      std::vector<std::size_t> fresh;
      for (std::size_t j : plan.blocks()[b].variables) {
        const std::size_t g = (*group)[j];
        if (g != std::size_t(-1) && !assigned[g] && std::find(fresh.begin(), fresh.end(), g) == fresh.end()) fresh.push_back(g);
      }
      if (!fresh.empty()) {
        for (std::size_t g : fresh) assigned[g] = 1;
        std::vector<std::vector<int>> assignments;
        std::vector<int> local(fresh.size(), 0);
        for (;;) {
          assignments.push_back(local);
          std::size_t k = 0;
          while (k < fresh.size() && ++local[k] == (*radix)[fresh[k]]) local[k++] = 0;
          if (k == fresh.size()) break;
        }
        fork(assignments.size(), [&](std::size_t a, Plan_run& run) {
          const Polynomial_system<NT>* outer = run.sys;
          for (std::size_t k = 0; k < fresh.size(); ++k) run.charts[fresh[k]] = assignments[a][k];
          const Polynomial_system<NT> s = run.make_system(run.charts);
          // the plan's promise: the blocks before this one do not see these charts (made from
          // the union of the charts' supports; checked, a system built directly could differ)
          for (std::size_t e = 0; e < b; ++e) {
            for (std::size_t i : plan.blocks()[e].equations)
              if (!identical_polynomials(s.equations[i], outer->equations[i]))
                throw Input_error("solve_with_plan_over_charts: the charts of block " + std::to_string(b) + " change equation " +
                                  std::to_string(i) + " of block " + std::to_string(e) + ", solved before them");
            for (std::size_t q : plan.blocks()[e].inequalities)
              if (!identical_polynomials(s.inequalities[q], outer->inequalities[q]))
                throw Input_error("solve_with_plan_over_charts: the charts of block " + std::to_string(b) + " change inequality " +
                                  std::to_string(q) + " of block " + std::to_string(e) + ", solved before them");
          }
          run.sys = &s;
          run.solve_block_and_go(b, certified, boundary, ineq_boundary);
          run.sys = outer;
        });
        for (std::size_t g : fresh) { assigned[g] = 0; charts[g] = 0; }
        return;
      }
    }
    solve_block_and_go(b, certified, boundary, ineq_boundary);
  }

  static double widest(const std::vector<IT>& x)
  {
    double w = 0;
    for (const IT& v : x) w = (std::max)(w, O::upper_double(v) - O::lower_double(v));
    return w;
  }

  // `at`, a root the blocks certified (exactly one root of the whole system in it), narrowed
  // by the Krawczyk test on the whole system's sparse polynomials (no dense arrays) in IT, and
  // then, with exact coefficients and MPFI, in CGAL::Gmpfi at twice the bits while wider than
  // the tolerance, up to `Subdivision_solver_parameters::maximal_precision`: the widths the
  // chain of blocks leaves are those of double precision times the blocks' conditioning, not
  // the coefficients'. `bits`: the precision of the last test that narrowed it. False: still
  // wider than the tolerance.
  bool refine_sparse(std::vector<IT>& at, unsigned& bits) const
  {
    try {
      {
        Solver_precision_guard<IT> guard(P.precision);
        const Sparse_krawczyk_system<IT> whole(sys->equations);
        std::vector<IT> x = at;
        const Sparse_krawczyk_outcome o = sparse_krawczyk_tighten(whole, x, P.tolerance);
        // (disjoint from a box the blocks proved holds a root: not possible in exact terms;
        // the blocks' enclosure is kept)
        if (o.empty) return false;
        at = x;
        if (o.width <= P.tolerance) return true;
      }
#ifdef CGAL_USE_MPFI
      if constexpr (!O::multiprecision && (std::is_same<NT, CGAL::Gmpq>::value || std::is_same<NT, double>::value)) {
        for (unsigned b = 2 * O::bits(); b <= P.maximal_precision; b *= 2) {
          typedef Interval_ops<CGAL::Gmpfi> G;
          Solver_precision_guard<CGAL::Gmpfi> guard(b);
          const Sparse_krawczyk_system<CGAL::Gmpfi> whole(sys->equations);
          std::vector<CGAL::Gmpfi> x;
          for (const IT& v : at) x.push_back(G::from(v));
          const Sparse_krawczyk_outcome o = sparse_krawczyk_tighten(whole, x, P.tolerance);
          if (o.empty) return false;
          for (std::size_t j = 0; j < at.size(); ++j) {
            const std::pair<double, double> e = x[j].to_interval();  // (outward)
            at[j] = O::make((std::max)(O::lower(at[j]), e.first), (std::min)(O::upper(at[j]), e.second));
          }
          bits = b;
          if (widest(at) <= P.tolerance) return true;
        }
      }
#endif
    } catch (const Input_error&) {
      // not square (a plan of a system with more equations than variables)
    }
    return widest(at) <= P.tolerance;
  }

  void solve_block_and_go(std::size_t b, bool certified, bool boundary, bool ineq_boundary)
  {
    const Plan_block& blk = plan.blocks()[b];
    const bool last = b + 1 == plan.blocks().size();
    const bool own = own_block(blk);
    Solver_result<IT> res;
    bool solved_here = true;
    if (own) {
      // solved once per assignment of the block's own charts (the charts of other groups do not
      // enter its equations; the system is compared term by term on reuse all the same)
      Polynomial_system<NT> s = block_system<NT>(blk, true, value);
      std::vector<int> mine;
      if (group)
        for (std::size_t j : blk.variables)
          if ((*group)[j] != std::size_t(-1)) mine.push_back(charts[(*group)[j]]);
      std::shared_ptr<Own_solve> e;
      {
        std::lock_guard<std::mutex> hold(own_solves->lock);
        auto& slot = own_solves->by_block_and_charts[std::make_pair(b, mine)];
        if (!slot) slot = std::make_shared<Own_solve>();
        e = slot;
      }
      bool computed = false;
      // (the solve inside is sequential: no other branch can run on this thread meanwhile)
      std::call_once(e->once, [&] {
        e->result = solve_block_system<NT>(s, last);
        e->system = s;
        computed = true;
      });
      if (identical_systems(s, e->system)) {
        res = e->result;
        solved_here = computed;
      } else {
        res = solve_block_system<NT>(s, last);
      }
    } else {
      res = solve_block<IT>(blk, last, false);
    }
    if (solved_here) {
      ++result.block_solves;
      result.boxes += res.statistics.boxes;
      result.krawczyk_tests += res.statistics.krawczyk_tests;
    } else {
      ++result.block_solves_reused;
    }
    if (result.diagnosis.empty() && !res.diagnosis.empty()) result.diagnosis = "block " + std::to_string(b) + ": " + res.diagnosis;
    for (const auto& u : res.unresolved) {
      Plan_unresolved<IT> v;
      v.block = b;
      v.kind = u.kind;
      v.reason = u.reason;
      v.box = current_box(b, u.box);
      target().unresolved.push_back(v);
    }
    fork(res.roots.size(), [&](std::size_t k, Plan_run& run) {
      const auto& r = res.roots[k];
      const Polynomial_system<NT>* mine = run.sys;
      for (std::size_t v = 0; v < blk.variables.size(); ++v) {
        run.value[blk.variables[v]] = r.enclosure[v];
        run.known[blk.variables[v]] = 1;
      }
      run.go(b + 1, certified && r.certified, boundary || r.on_boundary, ineq_boundary || r.on_inequality_boundary);
      run.sys = mine;  // (a block after it may have chosen charts: their system is gone)
    });
    for (std::size_t j : blk.variables) known[j] = 0;
  }
};

} // namespace internal

namespace internal {

// Throws Input_error unless `plan` was made for `system`: as many variables, equations and
// inequalities (a plan made without the system's inequalities would let roots that violate
// them through).
template <class NT>
void check_plan(const Polynomial_system<NT>& system, const Solution_plan& plan, const char* who)
{
  if (plan.number_of_variables() != system.number_of_variables() || plan.number_of_equations() != system.number_of_equations())
    throw Input_error(std::string(who) + ": the plan is for " + std::to_string(plan.number_of_equations()) + " equations in " +
                      std::to_string(plan.number_of_variables()) + " variables, the system has " + std::to_string(system.number_of_equations()) +
                      " in " + std::to_string(system.number_of_variables()));
  if (plan.number_of_inequalities() != system.inequalities.size())
    throw Input_error(std::string(who) + ": the plan is for " + std::to_string(plan.number_of_inequalities()) + " inequalities, the system has " +
                      std::to_string(system.inequalities.size()) + " (make the plan with Solution_plan(system))");
  // and each polynomial involves only variables the plan knows it involves (a plan of another
  // system of the same size would solve blocks in the wrong order, or test an inequality early)
  auto within = [&](const std::vector<std::size_t>& used, const std::vector<std::size_t>& planned, const std::string& what) {
    for (std::size_t j : used)
      if (!std::binary_search(planned.begin(), planned.end(), j))
        throw Input_error(std::string(who) + ": " + what + " involves variable " + std::to_string(j) + ", which the plan does not have it involve" +
                          " (the plan was made for another system)");
  };
  for (std::size_t i = 0; i < system.equations.size(); ++i) within(system.equations[i].variables(), plan.equation_variables(i), "equation " + std::to_string(i));
  for (std::size_t q = 0; q < system.inequalities.size(); ++q)
    within(system.inequalities[q].variables(), plan.inequality_variables(q), "inequality " + std::to_string(q));
}

} // namespace internal

namespace internal {

// Throws Input_error unless `plan` is well-constrained with every inequality attached to a
// block (the over- or under-determined part named, with the variable names of `system`).
template <class NT>
void check_solvable(const Polynomial_system<NT>& system, const Solution_plan& plan, const char* who)
{
  auto names = [&](const std::vector<std::size_t>& v, bool variables) {
    std::string r;
    for (std::size_t k = 0; k < v.size(); ++k) {
      std::size_t j = v[k];
      r += (k ? ", " : "") + (variables ? (j < system.variable_names.size() ? system.variable_names[j] : "x" + std::to_string(j))
                                        : "equation " + std::to_string(j));
    }
    return r;
  };
  if (!plan.over_determined_equations().empty())
    throw Input_error(std::string(who) + ": the system is over-determined: " + names(plan.over_determined_equations(), false) +
                      " (redundant or in conflict) in " + names(plan.over_determined_variables(), true));
  if (!plan.under_determined_variables().empty())
    throw Input_error(std::string(who) + ": the system is under-determined (free variables " + names(plan.under_determined_variables(), true) +
                      "): its solution set is not finite; curves are not traced by solve_with_plan");
  for (std::size_t q : plan.unattached_inequalities())
    throw Input_error(std::string(who) + ": inequality " + std::to_string(q) + " involves a variable no block solves");
}

// A solve along a solution plan as the solver's result for the whole system: its roots, and
// its regions, those of a block with blocks after it named by their block (the box holds the
// search box for the later blocks' variables: never taken for a possible multiple root)
template <class IT>
Solver_result<IT> solver_result_of_plan(const Plan_result<IT>& p, std::size_t blocks)
{
  Solver_result<IT> r;
  for (const auto& x : p.roots) {
    Solver_root<IT> y;
    y.enclosure = x.enclosure;
    y.approximation = x.approximation;
    y.certified = x.certified;
    y.on_boundary = x.on_boundary;
    y.on_inequality_boundary = x.on_inequality_boundary;
    r.roots.push_back(y);
  }
  for (const auto& u : p.unresolved) {
    Solver_unresolved<IT> v;
    v.kind = u.kind;
    v.reason = u.block + 1 == blocks ? u.reason
                                     : "block " + std::to_string(u.block + 1) + " of " + std::to_string(blocks) +
                                           " of the solution plan (the blocks after it not solved there): " + u.reason;
    v.box = u.box;
    r.unresolved.push_back(v);
  }
  r.diagnosis = p.diagnosis;
  r.statistics.boxes = p.boxes;
  r.statistics.krawczyk_tests = p.krawczyk_tests;
  r.statistics.seconds = p.seconds;
  return r;
}

// The undecomposed solver's result in the plan's shape (one block; `precision`: bits of the
// solver's arithmetic)
template <class IT>
Plan_result<IT> plan_result_of_solver(const Solver_result<IT>& s, unsigned precision)
{
  Plan_result<IT> r;
  r.block_solves = 1;
  r.boxes = s.statistics.boxes;
  r.krawczyk_tests = s.statistics.krawczyk_tests;
  r.diagnosis = s.diagnosis;
  r.seconds = s.statistics.seconds;
  for (const auto& x : s.roots) {
    Plan_root<IT> y;
    y.enclosure = x.enclosure;
    y.approximation = x.approximation;
    y.certified = x.certified;
    y.on_boundary = x.on_boundary;
    y.on_inequality_boundary = x.on_inequality_boundary;
    y.precision = precision;
    r.roots.push_back(y);
  }
  for (const auto& u : s.unresolved) {
    Plan_unresolved<IT> v;
    v.kind = u.kind;
    v.reason = u.reason;
    v.box = u.box;
    r.unresolved.push_back(v);
  }
  return r;
}

} // namespace internal

/*!
\ingroup PkgRigidIncidenceSolver
\brief Every real root of `system` in its box, solved block after block along `plan`
(decomposition_subdivision_solver.txt, Algorithm 6).

The blocks are solved in the plan's order. A block without inputs is solved with the
system's own coefficients; the others with interval coefficients: each input replaced by the
enclosure of the root it comes from (tightened to a thousandth of `parameters.tolerance`), so
that the roots the block certifies are certified for every value of the inputs in their
enclosures, and no root is lost at a block boundary. Each root of a block branches: the blocks
after it are solved once per combination of the roots before them. Each block's inequalities
(attached by `Solution_plan`, Algorithm 5) prune its boxes. Unresolved regions of a block are
reported with the values of the blocks before it.

\tparam IT the solver's interval type (`CGAL::Interval_nt<false>` or `CGAL::Gmpfi`).
\throws Input_error if `plan` was not made for `system` (different numbers of variables, equations
or inequalities), if the system is
not well-constrained (the over- or under-determined part is named), or if an equation
vanishes identically after substitution.
*/
template <class IT = CGAL::Interval_nt<false>, class NT>
Plan_result<IT> solve_with_plan(const Polynomial_system<NT>& system_in, const Solution_plan& plan,
                                const Subdivision_solver_parameters& parameters = Subdivision_solver_parameters())
{
  internal::check_plan(system_in, plan, "solve_with_plan");
  // exact scaling first: a block's coefficients become intervals once earlier roots are
  // substituted, and 1e-400 would then underflow
  Polynomial_system<NT> scaled;
  const Polynomial_system<NT>& system = internal::scaled_to_unit(system_in, scaled);
  if (system.box.size() != system.number_of_variables())
    throw Input_error("solve_with_plan: the box has " + std::to_string(system.box.size()) + " intervals for " +
                      std::to_string(system.number_of_variables()) + " variables");
  internal::check_solvable(system, plan, "solve_with_plan");
  internal::Solver_precision_guard<IT> guard(parameters.precision);
  internal::Plan_run<IT, NT> run(system, plan, parameters);
  const auto start = std::chrono::steady_clock::now();
  run.go(0, true, false, false);
  run.result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::sort(run.result.roots.begin(), run.result.roots.end(),
            [](const Plan_root<IT>& a, const Plan_root<IT>& b) { return a.approximation < b.approximation; });
  return run.result;
}

/// \ingroup PkgRigidIncidenceSolver
/// What `solve_with_plan_over_charts()` found with one assignment of charts.
template <class IT>
struct Plan_chart_roots
{
  std::vector<int> charts;  ///< per chart group, its chart
  /// the roots of the system of these charts, sorted by approximation, and the regions a block
  /// left undecided with these charts for its own groups and those before it (the groups of the
  /// blocks after it, not reached, at chart 0: the region stands for all of their charts)
  Plan_result<IT> result;
};

/// \ingroup PkgRigidIncidenceSolver
/// The result of `solve_with_plan_over_charts()`.
template <class IT>
struct Plan_charts_result
{
  /// the assignments of charts in which something was found (roots or regions), in
  /// lexicographic order of `charts`; every other assignment has no root: an earlier block,
  /// solved in its own charts, had none for it
  std::vector<Plan_chart_roots<IT>> found;
  /// the totals over every block solve (`block_solves`, `boxes`, `krawczyk_tests`,
  /// `refinements`, `refinements_sparse`, `refinements_multiprecision`, `refinements_failed`, `seconds`) and the first
  /// diagnosis met; its `roots`
  /// and `unresolved` are empty (they are in `found`)
  Plan_result<IT> totals;
};

/*!
\ingroup PkgRigidIncidenceSolver
\brief `solve_with_plan()` over every assignment of charts to groups of variables, each
group's chart chosen by the first block that solves one of its variables.

A scene's reduced system has one chart per hinge (a variable and its inverse,
`Reduced_system(base, charts)`); solving each combination of charts whole repeats every block
for each chart of the variables after it, and a block with no root in its charts is solved
again for every chart of the others. Here block \f$b\f$ is solved once per assignment of the
charts of its own new groups, for each combination of the roots before it, and only the
assignments under roots are visited: the roots found are those of `solve_with_plan()` on each
full assignment's system, with a fraction of the block solves (issue 28, item 1).

`group[j]` is the chart group of variable \f$j\f$ (`std::size_t(-1)`: the variable has one chart),
`charts_per_group[g]` the charts of group \f$g\f$, and `make_system(charts)` the system of an
assignment (one chart per group); the equations and inequalities of a block must not depend on
the charts of the groups of later blocks, so `plan` must be made from the union of the
supports of the systems (a variable an equation involves in any chart); each system built is
checked against it.
\throws Input_error as `solve_with_plan()`, for each system built, or if `group` does not
have one entry per variable or names a group beyond `charts_per_group`.
*/
template <class IT, class NT>
Plan_charts_result<IT> solve_with_plan_over_charts(const Solution_plan& plan, const std::vector<std::size_t>& group,
                                                   const std::vector<int>& charts_per_group,
                                                   const std::function<Polynomial_system<NT>(const std::vector<int>&)>& make_system,
                                                   const Subdivision_solver_parameters& parameters = Subdivision_solver_parameters())
{
  const char* who = "solve_with_plan_over_charts";
  if (group.size() != plan.number_of_variables())
    throw Input_error(std::string(who) + ": " + std::to_string(group.size()) + " chart groups given for " +
                      std::to_string(plan.number_of_variables()) + " variables");
  for (std::size_t g : group)
    if (g != std::size_t(-1) && g >= charts_per_group.size())
      throw Input_error(std::string(who) + ": chart group " + std::to_string(g) + " of " + std::to_string(charts_per_group.size()));
  for (int n : charts_per_group)
    if (n < 1) throw Input_error(std::string(who) + ": a chart group without charts");
  auto build = [&](const std::vector<int>& charts) {
    Polynomial_system<NT> s = make_system(charts);
    internal::check_plan(s, plan, who);
    if (s.box.size() != s.number_of_variables())
      throw Input_error(std::string(who) + ": the box has " + std::to_string(s.box.size()) + " intervals for " +
                        std::to_string(s.number_of_variables()) + " variables");
    Polynomial_system<NT> scaled;
    const Polynomial_system<NT>& t = internal::scaled_to_unit(s, scaled);
    return &t == &scaled ? scaled : s;
  };
  // The system of an assignment of charts, built once: the branches under the roots of a block
  // ask for the same assignments again (each root of a block asks for every chart of the next).
  // At most 4096 kept; beyond, built on each request.
  struct Built
  {
    std::once_flag once;
    Polynomial_system<NT> system;
    std::exception_ptr error;
  };
  struct Built_systems
  {
    std::mutex lock;
    std::map<std::vector<int>, std::shared_ptr<Built>> by_charts;
  };
  auto built = std::make_shared<Built_systems>();
  const std::function<Polynomial_system<NT>(const std::vector<int>&)> build_once = [built, build](const std::vector<int>& charts) {
    std::shared_ptr<Built> e;
    {
      std::lock_guard<std::mutex> hold(built->lock);
      auto it = built->by_charts.find(charts);
      if (it != built->by_charts.end()) e = it->second;
      else if (built->by_charts.size() < 4096) e = built->by_charts[charts] = std::make_shared<Built>();
    }
    if (!e) return build(charts);
    std::call_once(e->once, [&] {
      try {
        e->system = build(charts);
      } catch (...) {
        e->error = std::current_exception();
      }
    });
    if (e->error) std::rethrow_exception(e->error);
    return e->system;
  };
  const std::vector<int> zero(charts_per_group.size(), 0);
  const Polynomial_system<NT> first = build(zero);
  internal::check_solvable(first, plan, who);
  internal::Solver_precision_guard<IT> guard(parameters.precision);
  internal::Plan_run<IT, NT> run(first, plan, parameters);
  run.group = &group;
  run.radix = &charts_per_group;
  run.make_system = build_once;
  run.charts = zero;
  run.assigned.assign(charts_per_group.size(), 0);
  const auto start = std::chrono::steady_clock::now();
  run.go(0, true, false, false);
  Plan_charts_result<IT> out;
  out.totals = run.result;
  out.totals.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  for (auto& x : run.by_charts) {
    Plan_chart_roots<IT> f;
    f.charts = x.first;
    f.result = std::move(x.second);
    std::sort(f.result.roots.begin(), f.result.roots.end(),
              [](const Plan_root<IT>& a, const Plan_root<IT>& b) { return a.approximation < b.approximation; });
    out.found.push_back(std::move(f));
  }
  return out;
}

} // namespace Rigid_incidence
} // namespace CGAL

#endif
