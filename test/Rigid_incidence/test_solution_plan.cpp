// Copyright (c) 2026 Rigid_incidence contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Solution_plan (decomposition_subdivision_solver.txt, Section 3, Algorithms 2-5 and
// Section 3.4) against independent oracles that never look at the class's matching or its
// dependency graph:
//  - our own augmenting-path matcher (Kuhn) for the size of a maximum matching nu, which
//    gives the structure (nu < m: over-determined part, nu < k: under-determined part);
//  - the Dulmage-Mendelsohn parts by deletion: equation i is in the over-determined part iff
//    nu(G - i) == nu(G) (some maximum matching misses it), its variables are the neighbours
//    of those equations; variable j is in the under-determined part iff nu(G - j) == nu(G),
//    its equations are the neighbours of those variables;
//  - the finest block triangular form by brute force over subsets of equations: among the
//    remaining equations, the minimal nonempty sets S whose unknown variables number |S| are
//    the next blocks (they are disjoint: the tight sets are closed under intersection);
//    remove them, mark their variables known, repeat;
//  - for one equation fewer than variables (Section 3.4): for every variable v that the
//    other variables can match all equations without, the block form of the system with v
//    known, v then added to a first block using it (any block using v that no other block
//    using v precedes in the dependency order: exactly the blocks a topological order can put
//    first); the plan's largest block lies between the minimum over v of the smallest and of
//    the largest choice, and equals the minimum when the choice is forced;
//  - Algorithm 5: an inequality goes to the block (in the plan's order) that solves the last
//    of its variables, read from blocks() alone; if some variable of it is solved by no
//    block, it is unattached.
// Every plan is also checked for the invariants of a plan: each equation in one block, each
// used variable in one block, inputs = used variables not solved in the block, every input
// solved by an earlier block (topological order), depends_on = the blocks giving the inputs,
// block_of_equation / block_of_variable agree with blocks(), matched_variable() a matching of
// maximum size.
//
// Cases:
//  - random square systems, n = 1..9, with a planted perfect matching and extra incidences
//    at several densities, uniform or layered (layered ones have many blocks);
//  - random systems with one equation fewer than variables, planted matching of the
//    equations;
//  - random non-square systems of any shape (structure and Dulmage-Mendelsohn parts);
//  - hand-made cases: Fig. 1 of the paper, triangular, dense, over-, under-constrained,
//    mixed, unused variables, empty systems; the convenience constructor from a
//    Polynomial_system<Gmpq>; malformed input (Input_error naming the equation).
//
// Usage: test_solution_plan [seed] [systems per (n, density)]

#include <CGAL/Gmpq.h>
#include <CGAL/Random.h>
#include <CGAL/Rigid_incidence/Input_error.h>
#include <CGAL/Rigid_incidence/Polynomial_system.h>
#include <CGAL/Rigid_incidence/Solution_plan.h>

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstdlib>
#include <iostream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace RI = CGAL::Rigid_incidence;
typedef RI::Solution_plan Plan;
typedef std::vector<std::vector<std::size_t>> Incidence;
typedef std::set<std::size_t> Set;
static const std::size_t none = Plan::none;

#include "test_check.h"

// ===================================================================== printing
template <class C> std::string list(const C& c)
{
  std::ostringstream s;
  s << "{";
  bool first = true;
  for (std::size_t x : c) { s << (first ? "" : ",") << x; first = false; }
  s << "}";
  return s.str();
}
std::string show(std::size_t k, const Incidence& eqv)
{
  std::ostringstream s;
  s << k << " variables, equations ";
  for (std::size_t i = 0; i < eqv.size(); ++i) s << (i ? " " : "") << i << ":" << list(eqv[i]);
  return s.str();
}
const char* name_of(Plan::Structure s)
{
  switch (s) {
  case Plan::WELL_CONSTRAINED: return "WELL_CONSTRAINED";
  case Plan::ONE_DEGREE_OF_FREEDOM: return "ONE_DEGREE_OF_FREEDOM";
  case Plan::UNDER_CONSTRAINED: return "UNDER_CONSTRAINED";
  case Plan::OVER_CONSTRAINED: return "OVER_CONSTRAINED";
  case Plan::MIXED: return "MIXED";
  }
  return "?";
}
std::string show_plan(const Plan& p)
{
  std::ostringstream s;
  s << name_of(p.structure()) << ", blocks";
  for (const auto& b : p.blocks()) s << " [eq " << list(b.equations) << " var " << list(b.variables) << "]";
  if (p.left_out_variable() != none) s << ", left out " << p.left_out_variable();
  return s.str();
}

// ===================================================================== oracles
int popcount(std::uint32_t x)
{
  int c = 0;
  for (; x; x &= x - 1) ++c;
  return c;
}

// Kuhn's augmenting paths: a maximum matching of the equations, skipping the variables in
// `gone` and the equations in `gone_eq`. Returns its size.
std::size_t my_matching(std::size_t k, const Incidence& eqv, const Set& gone = {}, const Set& gone_eq = {})
{
  const std::size_t m = eqv.size();
  std::vector<std::size_t> mate_var(k, none);
  std::vector<char> seen;
  // recursion depth is at most m
  struct Dfs
  {
    const Incidence& eqv;
    const Set& gone;
    std::vector<std::size_t>& mate_var;
    std::vector<char>& seen;
    bool operator()(std::size_t i)
    {
      for (std::size_t j : eqv[i]) {
        if (gone.count(j) || seen[j]) continue;
        seen[j] = 1;
        if (mate_var[j] == none || (*this)(mate_var[j])) { mate_var[j] = i; return true; }
      }
      return false;
    }
  } dfs{eqv, gone, mate_var, seen};
  std::size_t size = 0;
  for (std::size_t i = 0; i < m; ++i) {
    if (gone_eq.count(i)) continue;
    seen.assign(k, 0);
    if (dfs(i)) ++size;
  }
  return size;
}

struct Oracle_block
{
  Set equations, variables;
  bool operator<(const Oracle_block& o) const
  {
    return equations != o.equations ? equations < o.equations : variables < o.variables;
  }
  bool operator==(const Oracle_block& o) const { return equations == o.equations && variables == o.variables; }
};

// The finest block triangular form by brute force over subsets of the equations, with the
// variables in `known` given. The blocks come out round by round (a topological order).
// Returns false if some round finds no tight set (no perfect matching: not for this oracle).
bool oracle_blocks(std::size_t k, const Incidence& eqv, const Set& known_in, std::vector<Oracle_block>& out)
{
  out.clear();
  if (k > 31) { std::cerr << "oracle: more than 31 variables\n"; std::abort(); }
  std::vector<std::size_t> remaining(eqv.size());
  for (std::size_t i = 0; i < eqv.size(); ++i) remaining[i] = i;
  std::uint32_t known = 0;
  for (std::size_t j : known_in) known |= std::uint32_t(1) << j;
  while (!remaining.empty()) {
    const std::size_t r = remaining.size();
    if (r > 16) { std::cerr << "oracle: more than 16 equations\n"; std::abort(); }
    std::vector<std::uint32_t> var_mask(r);
    for (std::size_t a = 0; a < r; ++a) {
      std::uint32_t mask = 0;
      for (std::size_t j : eqv[remaining[a]]) mask |= std::uint32_t(1) << j;
      var_mask[a] = mask & ~known;
    }
    // subsets in increasing size: a tight set is minimal iff it contains no minimal tight
    // set found before
    std::vector<std::uint32_t> subsets;
    for (std::uint32_t s = 1; s < (std::uint32_t(1) << r); ++s) subsets.push_back(s);
    std::stable_sort(subsets.begin(), subsets.end(),
                     [](std::uint32_t a, std::uint32_t b) { return popcount(a) < popcount(b); });
    std::vector<std::uint32_t> minimal;
    for (std::uint32_t s : subsets) {
      std::uint32_t vars = 0;
      for (std::size_t a = 0; a < r; ++a) if (s >> a & 1) vars |= var_mask[a];
      if (popcount(vars) != popcount(s)) continue;
      bool contains = false;
      for (std::uint32_t t : minimal) if ((s & t) == t) { contains = true; break; }
      if (!contains) minimal.push_back(s);
    }
    if (minimal.empty()) return false;
    std::uint32_t removed = 0, solved = 0;
    for (std::uint32_t s : minimal) {
      Oracle_block b;
      std::uint32_t vars = 0;
      for (std::size_t a = 0; a < r; ++a)
        if (s >> a & 1) { b.equations.insert(remaining[a]); vars |= var_mask[a]; }
      for (std::size_t j = 0; j < k; ++j) if (vars >> j & 1) b.variables.insert(j);
      if (removed & s) { std::cerr << "oracle: minimal tight sets overlap (oracle error)\n"; std::abort(); }
      removed |= s;
      solved |= vars;
      out.push_back(b);
    }
    known |= solved;
    std::vector<std::size_t> next;
    for (std::size_t a = 0; a < r; ++a) if (!(removed >> a & 1)) next.push_back(remaining[a]);
    remaining = next;
  }
  return true;
}

Incidence normalized(const Incidence& eqv)
{
  Incidence r;
  for (const auto& e : eqv) {
    Set s(e.begin(), e.end());
    r.push_back(std::vector<std::size_t>(s.begin(), s.end()));
  }
  return r;
}

Set used_variables(std::size_t k, const Incidence& eqv)
{
  Set r;
  for (const auto& e : eqv) for (std::size_t j : e) if (j < k) r.insert(j);
  return r;
}

// ===================================================================== checks
// The invariants of every plan, the structure, the Dulmage-Mendelsohn parts and the
// inequalities, against the oracles.
void check_plan(const Plan& p, std::size_t k, const Incidence& eqv_raw, const Incidence& ineq, const std::string& name)
{
  const Incidence eqv = normalized(eqv_raw);
  const std::size_t m = eqv.size();
  const std::string where = name + " (" + show(k, eqv) + "; plan: " + show_plan(p) + ")";
  CHECK(p.number_of_variables() == k && p.number_of_equations() == m,
        where << ": " << p.number_of_equations() << " equations in " << p.number_of_variables() << " variables");
  if (p.number_of_variables() != k || p.number_of_equations() != m) return;
  for (std::size_t i = 0; i < m; ++i)
    CHECK(p.equation_variables(i) == eqv[i], where << ": equation_variables(" << i << ") = " << list(p.equation_variables(i)));

  const auto& blocks = p.blocks();
  const std::size_t nb = blocks.size();
  // each equation in exactly one block, each variable in at most one
  std::vector<std::size_t> eq_block(m, none), var_block(k, none);
  bool partition_ok = true;
  std::size_t largest = 0;
  for (std::size_t b = 0; b < nb; ++b) {
    const auto& B = blocks[b];
    CHECK(!B.equations.empty(), where << ": block " << b << " has no equation");
    CHECK(std::is_sorted(B.equations.begin(), B.equations.end()) && std::is_sorted(B.variables.begin(), B.variables.end()) &&
            std::is_sorted(B.inputs.begin(), B.inputs.end()) && std::is_sorted(B.depends_on.begin(), B.depends_on.end()) &&
            std::is_sorted(B.inequalities.begin(), B.inequalities.end()),
          where << ": block " << b << " has an unsorted list");
    CHECK(B.dimension() == long(B.variables.size()) - long(B.equations.size()), where << ": block " << b << " dimension " << B.dimension());
    largest = (std::max)(largest, B.variables.size());
    for (std::size_t i : B.equations) {
      if (i >= m || eq_block[i] != none) { partition_ok = false; continue; }
      eq_block[i] = b;
    }
    for (std::size_t j : B.variables) {
      if (j >= k || var_block[j] != none) { partition_ok = false; continue; }
      var_block[j] = b;
    }
  }
  CHECK(partition_ok, where << ": an equation or a variable is in two blocks (or out of range)");
  for (std::size_t i = 0; i < m; ++i) {
    CHECK(eq_block[i] != none, where << ": equation " << i << " is in no block");
    CHECK(p.block_of_equation(i) == eq_block[i], where << ": block_of_equation(" << i << ") = " << p.block_of_equation(i) << ", blocks() say " << eq_block[i]);
  }
  const Set used = used_variables(k, eqv);
  for (std::size_t j = 0; j < k; ++j) {
    CHECK(p.block_of_variable(j) == var_block[j], where << ": block_of_variable(" << j << ") = " << p.block_of_variable(j) << ", blocks() say " << var_block[j]);
    CHECK((var_block[j] != none) == (used.count(j) != 0),
          where << ": variable " << j << (used.count(j) ? " is used but solved by no block" : " is used by no equation but solved by a block"));
  }
  CHECK(p.largest_block() == largest, where << ": largest_block() = " << p.largest_block() << ", blocks() say " << largest);
  // inputs, depends_on, topological order
  for (std::size_t b = 0; b < nb; ++b) {
    const auto& B = blocks[b];
    Set uses, inputs, deps;
    for (std::size_t i : B.equations) if (i < m) uses.insert(eqv[i].begin(), eqv[i].end());
    for (std::size_t j : B.variables)
      CHECK(uses.count(j), where << ": block " << b << " solves variable " << j << " that none of its equations uses");
    for (std::size_t j : uses)
      if (!std::binary_search(B.variables.begin(), B.variables.end(), j)) {
        inputs.insert(j);
        if (var_block[j] != none) deps.insert(var_block[j]);
        CHECK(var_block[j] != none && var_block[j] < b,
              where << ": block " << b << " takes input " << j << " from block " << (var_block[j] == none ? std::string("none") : std::to_string(var_block[j]))
                    << ", not an earlier one");
      }
    CHECK(Set(B.inputs.begin(), B.inputs.end()) == inputs && B.inputs.size() == inputs.size(),
          where << ": block " << b << " inputs " << list(B.inputs) << ", expected " << list(inputs));
    CHECK(Set(B.depends_on.begin(), B.depends_on.end()) == deps && B.depends_on.size() == deps.size(),
          where << ": block " << b << " depends_on " << list(B.depends_on) << ", expected " << list(deps));
  }
  // the matching
  const std::size_t nu = my_matching(k, eqv);
  std::size_t matched = 0;
  Set mates;
  bool matching_ok = true;
  for (std::size_t i = 0; i < m; ++i) {
    std::size_t j = p.matched_variable(i);
    if (j == none) continue;
    ++matched;
    if (j >= k || !std::binary_search(eqv[i].begin(), eqv[i].end(), j) || !mates.insert(j).second) matching_ok = false;
  }
  CHECK(matching_ok, where << ": matched_variable() is not a matching of the system");
  CHECK(matched == nu, where << ": matched_variable() matches " << matched << " equations, a maximum matching " << nu);
  // structure
  const bool over = nu < m, under = nu < k;
  const Plan::Structure s = over && under ? Plan::MIXED : over ? Plan::OVER_CONSTRAINED
                          : under ? (k - nu == 1 ? Plan::ONE_DEGREE_OF_FREEDOM : Plan::UNDER_CONSTRAINED) : Plan::WELL_CONSTRAINED;
  CHECK(p.structure() == s, where << ": structure " << name_of(p.structure()) << ", expected " << name_of(s) << " (maximum matching " << nu << ")");
  CHECK((p.left_out_variable() != none) == (s == Plan::ONE_DEGREE_OF_FREEDOM),
        where << ": left_out_variable() = " << (p.left_out_variable() == none ? std::string("none") : std::to_string(p.left_out_variable())));
  // Dulmage-Mendelsohn by deletion
  std::vector<Set> var_eqs(k);
  for (std::size_t i = 0; i < m; ++i) for (std::size_t j : eqv[i]) var_eqs[j].insert(i);
  Set over_eq, over_var, under_eq, under_var, unused;
  for (std::size_t i = 0; i < m; ++i)
    if (my_matching(k, eqv, {}, {i}) == nu) { over_eq.insert(i); over_var.insert(eqv[i].begin(), eqv[i].end()); }
  for (std::size_t j = 0; j < k; ++j) {
    if (my_matching(k, eqv, {j}) == nu) { under_var.insert(j); under_eq.insert(var_eqs[j].begin(), var_eqs[j].end()); }
    if (var_eqs[j].empty()) unused.insert(j);
  }
  auto same = [](const std::vector<std::size_t>& a, const Set& b) {
    return std::is_sorted(a.begin(), a.end()) && Set(a.begin(), a.end()) == b && a.size() == b.size();
  };
  CHECK(same(p.over_determined_equations(), over_eq), where << ": over_determined_equations() " << list(p.over_determined_equations()) << ", expected " << list(over_eq));
  CHECK(same(p.over_determined_variables(), over_var), where << ": over_determined_variables() " << list(p.over_determined_variables()) << ", expected " << list(over_var));
  CHECK(same(p.under_determined_equations(), under_eq), where << ": under_determined_equations() " << list(p.under_determined_equations()) << ", expected " << list(under_eq));
  CHECK(same(p.under_determined_variables(), under_var), where << ": under_determined_variables() " << list(p.under_determined_variables()) << ", expected " << list(under_var));
  CHECK(same(p.unused_variables(), unused), where << ": unused_variables() " << list(p.unused_variables()) << ", expected " << list(unused));
  // Algorithm 5, from blocks() alone
  std::vector<Set> attached(nb);
  Set unattached;
  for (std::size_t q = 0; q < ineq.size(); ++q) {
    std::size_t last = 0;
    bool ok = true;
    for (std::size_t j : ineq[q]) {
      std::size_t b = none;
      for (std::size_t c = 0; c < nb; ++c)
        if (std::binary_search(blocks[c].variables.begin(), blocks[c].variables.end(), j)) b = c;
      if (b == none) { ok = false; break; }
      last = (std::max)(last, b);
    }
    if (ok) attached[last].insert(q);
    else unattached.insert(q);
  }
  for (std::size_t b = 0; b < nb; ++b)
    CHECK(same(blocks[b].inequalities, attached[b]), where << ": block " << b << " tests inequalities " << list(blocks[b].inequalities) << ", expected " << list(attached[b]));
  CHECK(same(p.unattached_inequalities(), unattached), where << ": unattached_inequalities() " << list(p.unattached_inequalities()) << ", expected " << list(unattached));
}

// A well-constrained plan against the subset oracle.
void check_well_constrained(const Plan& p, std::size_t k, const Incidence& eqv, const std::string& name)
{
  const std::string where = name + " (" + show(k, normalized(eqv)) + "; plan: " + show_plan(p) + ")";
  CHECK(p.structure() == Plan::WELL_CONSTRAINED, where << ": not WELL_CONSTRAINED");
  CHECK(p.left_out_variable() == none, where << ": left_out_variable() " << p.left_out_variable());
  for (std::size_t b = 0; b < p.blocks().size(); ++b)
    CHECK(p.blocks()[b].variables.size() == p.blocks()[b].equations.size() && p.blocks()[b].dimension() == 0,
          where << ": block " << b << " is not square");
  std::vector<Oracle_block> oracle;
  bool ok = oracle_blocks(k, normalized(eqv), {}, oracle);
  CHECK(ok, where << ": the oracle finds no block (test error: no perfect matching)");
  std::set<Oracle_block> expected(oracle.begin(), oracle.end()), got;
  for (const auto& b : p.blocks())
    got.insert(Oracle_block{Set(b.equations.begin(), b.equations.end()), Set(b.variables.begin(), b.variables.end())});
  CHECK(got == expected && got.size() == p.blocks().size(), where << ": blocks differ from the finest block triangular form (" << oracle.size() << " blocks)");
}

struct Left_out_oracle
{
  bool feasible = false;
  std::vector<Oracle_block> blocks;    // of the system with v known, in a topological order
  std::vector<std::size_t> receivers;  // the blocks a topological order can give v to
  std::size_t lo = 0, hi = 0;          // smallest and largest "largest block" over the receivers
};

// Section 3.4 for one left-out variable v.
Left_out_oracle left_out_oracle(std::size_t k, const Incidence& eqv, std::size_t v)
{
  Left_out_oracle r;
  if (my_matching(k, eqv, {v}) != eqv.size()) return r;
  r.feasible = true;
  if (!oracle_blocks(k, eqv, {v}, r.blocks)) { std::cerr << "oracle: no block although matched (oracle error)\n"; std::abort(); }
  const std::size_t nb = r.blocks.size();
  // dependencies between the blocks, and their transitive closure
  std::vector<std::size_t> block_of_var(k, none);
  for (std::size_t b = 0; b < nb; ++b) for (std::size_t j : r.blocks[b].variables) block_of_var[j] = b;
  std::vector<std::vector<char>> before(nb, std::vector<char>(nb, 0));  // before[a][b]: a precedes b
  for (std::size_t b = 0; b < nb; ++b)
    for (std::size_t i : r.blocks[b].equations)
      for (std::size_t j : eqv[i])
        if (j != v && block_of_var[j] != b) before[block_of_var[j]][b] = 1;
  for (std::size_t c = 0; c < nb; ++c)
    for (std::size_t a = 0; a < nb; ++a)
      if (before[a][c])
        for (std::size_t b = 0; b < nb; ++b)
          if (before[c][b]) before[a][b] = 1;
  std::vector<char> uses(nb, 0);
  for (std::size_t b = 0; b < nb; ++b)
    for (std::size_t i : r.blocks[b].equations)
      if (std::binary_search(eqv[i].begin(), eqv[i].end(), v)) uses[b] = 1;
  std::size_t base = 0;
  for (const auto& b : r.blocks) base = (std::max)(base, b.variables.size());
  r.lo = r.hi = base;  // v used by no equation: it goes nowhere
  bool first = true;
  for (std::size_t b = 0; b < nb; ++b) {
    if (!uses[b]) continue;
    bool minimal = true;
    for (std::size_t a = 0; a < nb; ++a) if (a != b && uses[a] && before[a][b]) minimal = false;
    if (!minimal) continue;
    r.receivers.push_back(b);
    std::size_t size = (std::max)(base, r.blocks[b].variables.size() + 1);
    if (first) { r.lo = r.hi = size; first = false; }
    r.lo = (std::min)(r.lo, size);
    r.hi = (std::max)(r.hi, size);
  }
  return r;
}

// A plan with one equation fewer than variables, every equation matched, against Section 3.4.
void check_one_dof(const Plan& p, std::size_t k, const Incidence& eqv_raw, const std::string& name, bool* forced_out = nullptr)
{
  const Incidence eqv = normalized(eqv_raw);
  const std::string where = name + " (" + show(k, eqv) + "; plan: " + show_plan(p) + ")";
  CHECK(p.structure() == Plan::ONE_DEGREE_OF_FREEDOM, where << ": not ONE_DEGREE_OF_FREEDOM");
  const std::size_t v = p.left_out_variable();
  CHECK(v != none && v < k, where << ": no left-out variable");
  if (v == none || v >= k) return;
  const Set used = used_variables(k, eqv);
  // the dimensions: one curve block holding v, unless v is a variable no equation uses
  std::size_t curves = 0;
  for (std::size_t b = 0; b < p.blocks().size(); ++b) {
    const auto& B = p.blocks()[b];
    CHECK(B.dimension() == 0 || B.dimension() == 1, where << ": block " << b << " has dimension " << B.dimension());
    if (B.dimension() == 1) {
      ++curves;
      CHECK(std::binary_search(B.variables.begin(), B.variables.end(), v), where << ": block " << b << " has dimension 1 but does not hold the left-out variable");
    }
  }
  if (used.count(v)) CHECK(curves == 1, where << ": " << curves << " blocks of dimension 1, expected 1");
  else {
    CHECK(curves == 0 && p.block_of_variable(v) == none, where << ": the left-out variable " << v << " is used by no equation, yet is solved in a block");
    CHECK(used.size() + 1 == k, where << ": the left-out variable " << v << " is unused but so is another one (test error)");
  }
  // the left-out variable's own decomposition
  const Left_out_oracle mine = left_out_oracle(k, eqv, v);
  CHECK(mine.feasible, where << ": the equations have no perfect matching without the left-out variable " << v);
  if (!mine.feasible) return;
  std::set<Oracle_block> expected(mine.blocks.begin(), mine.blocks.end());
  std::set<Oracle_block> got;
  std::size_t receiver = none;
  for (std::size_t b = 0; b < p.blocks().size(); ++b) {
    const auto& B = p.blocks()[b];
    Oracle_block o{Set(B.equations.begin(), B.equations.end()), Set(B.variables.begin(), B.variables.end())};
    if (o.variables.erase(v)) receiver = b;
    got.insert(o);
  }
  CHECK(got == expected && got.size() == p.blocks().size(),
        where << ": blocks without the left-out variable differ from the finest block form of the system with " << v << " known");
  if (receiver != none && got == expected) {
    // the receiving block must be one a topological order can put first among v's users
    Set rec_eqs(p.blocks()[receiver].equations.begin(), p.blocks()[receiver].equations.end());
    bool allowed = false;
    for (std::size_t b : mine.receivers) allowed |= mine.blocks[b].equations == rec_eqs;
    CHECK(allowed, where << ": the left-out variable " << v << " goes to block " << receiver << ", not a first block using it");
  }
  // the exhaustive search
  std::size_t lo = none, hi = none;
  bool forced = true;
  std::vector<Left_out_oracle> all(k);
  for (std::size_t u = 0; u < k; ++u) {
    all[u] = left_out_oracle(k, eqv, u);
    if (!all[u].feasible) continue;
    lo = (std::min)(lo, all[u].lo);
    hi = (std::min)(hi, all[u].hi);
    if (all[u].lo != all[u].hi) forced = false;
  }
  CHECK(lo <= p.largest_block() && p.largest_block() <= hi,
        where << ": largest_block() " << p.largest_block() << ", the best left-out variable gives between " << lo << " and " << hi);
  CHECK(p.largest_block() <= all[v].hi && p.largest_block() >= all[v].lo,
        where << ": largest_block() " << p.largest_block() << ", left-out variable " << v << " gives " << all[v].lo << ".." << all[v].hi);
  if (forced) {
    CHECK(p.largest_block() == lo, where << ": largest_block() " << p.largest_block() << ", the best left-out variable gives " << lo);
    // ties: more blocks, then the lowest variable, as build() implements it (the class
    // comment says only "ties: the lowest variable index"; they differ e.g. on 6 variables,
    // equations {0,1,2,3,4} {0,5} {0,3} {2,4} {3,5}: leaving out 1 or 2 both give a largest
    // block of 3, with 2 and 3 blocks; the class leaves out 2)
    std::size_t best = none, best_count = 0;
    for (std::size_t u = 0; u < k; ++u)
      if (all[u].feasible && all[u].lo == lo && (best == none || all[u].blocks.size() > best_count)) {
        best = u;
        best_count = all[u].blocks.size();
      }
    CHECK(v == best, where << ": left-out variable " << v << ", expected " << best << " (largest block " << lo << ", then most blocks, then lowest index)");
  }
  if (forced_out) *forced_out = forced;
}

// ===================================================================== random systems
// n equations; equation i involves perm[i] plus extra incidences with probability
// `density`; layered: extra incidence (i, j) only if the level of j's planted equation is at
// most the level of i (many blocks).
Incidence random_square(CGAL::Random& rnd, std::size_t n, double density, bool layered)
{
  std::vector<std::size_t> perm(n), level(n);
  for (std::size_t i = 0; i < n; ++i) perm[i] = i;
  for (std::size_t i = n; i > 1; --i) std::swap(perm[i - 1], perm[std::size_t(rnd.get_int(0, int(i)))]);
  std::size_t levels = std::size_t(rnd.get_int(1, int(n) + 1));
  for (std::size_t i = 0; i < n; ++i) level[i] = std::size_t(rnd.get_int(0, int(levels)));
  std::vector<std::size_t> eq_of(n);
  for (std::size_t i = 0; i < n; ++i) eq_of[perm[i]] = i;
  Incidence eqv(n);
  for (std::size_t i = 0; i < n; ++i) {
    eqv[i].push_back(perm[i]);
    for (std::size_t j = 0; j < n; ++j) {
      if (j == perm[i]) continue;
      if (layered && level[eq_of[j]] > level[i]) continue;
      if (rnd.get_double() < density) eqv[i].push_back(j);
    }
    // random order, sometimes a repeated variable: the plan normalizes
    for (std::size_t a = eqv[i].size(); a > 1; --a) std::swap(eqv[i][a - 1], eqv[i][std::size_t(rnd.get_int(0, int(a)))]);
    if (rnd.get_int(0, 8) == 0) eqv[i].push_back(eqv[i][0]);
  }
  return eqv;
}

Incidence random_inequalities(CGAL::Random& rnd, std::size_t k)
{
  Incidence r;
  if (k == 0) return r;
  int count = rnd.get_int(0, 5);
  for (int q = 0; q < count; ++q) {
    std::vector<std::size_t> vars;
    int size = rnd.get_int(1, 4);
    for (int a = 0; a < size; ++a) vars.push_back(std::size_t(rnd.get_int(0, int(k))));
    r.push_back(vars);
  }
  return r;
}

void random_square_systems(CGAL::Random& rnd, int per_cell, std::size_t& systems, std::size_t& blocks)
{
  const double densities[] = {0.0, 0.1, 0.2, 0.35, 0.6};
  for (std::size_t n = 1; n <= 9; ++n)
    for (double d : densities)
      for (int layered = 0; layered < 2; ++layered)
        for (int t = 0; t < per_cell; ++t) {
          Incidence eqv = random_square(rnd, n, d, layered != 0);
          Incidence ineq = random_inequalities(rnd, n);
          std::ostringstream name;
          name << "square n=" << n << " density " << d << (layered ? " layered" : "") << " #" << t;
          Plan p(n, eqv, ineq);
          check_plan(p, n, eqv, ineq, name.str());
          check_well_constrained(p, n, eqv, name.str());
          ++systems;
          blocks += p.blocks().size();
        }
}

void random_one_dof_systems(CGAL::Random& rnd, int per_cell, std::size_t& systems, std::size_t& forced_count)
{
  const double densities[] = {0.0, 0.1, 0.25, 0.5};
  for (std::size_t k = 2; k <= 9; ++k)
    for (double d : densities)
      for (int layered = 0; layered < 2; ++layered)
        for (int t = 0; t < per_cell; ++t) {
          // a square system in k variables, minus one equation: its planted variable is
          // then free (a variable no equation involves, if no extra incidence hits it)
          Incidence sq = random_square(rnd, k, d, layered != 0);
          sq.erase(sq.begin() + rnd.get_int(0, int(k)));
          Incidence ineq = random_inequalities(rnd, k);
          std::ostringstream name;
          name << "one dof k=" << k << " density " << d << (layered ? " layered" : "") << " #" << t;
          Plan p(k, sq, ineq);
          check_plan(p, k, sq, ineq, name.str());
          bool forced = false;
          check_one_dof(p, k, sq, name.str(), &forced);
          ++systems;
          forced_count += forced;
        }
}

void random_any_systems(CGAL::Random& rnd, int count, std::map<std::string, int>& seen)
{
  for (int t = 0; t < count; ++t) {
    std::size_t m = std::size_t(rnd.get_int(0, 9)), k = std::size_t(rnd.get_int(0, 9));
    double d = 0.05 + 0.5 * rnd.get_double();
    Incidence eqv(m);
    for (std::size_t i = 0; i < m; ++i)
      for (std::size_t j = 0; j < k; ++j)
        if (rnd.get_double() < d) eqv[i].push_back(j);
    Incidence ineq = random_inequalities(rnd, k);
    std::ostringstream name;
    name << "any m=" << m << " k=" << k << " #" << t;
    Plan p(k, eqv, ineq);
    check_plan(p, k, eqv, ineq, name.str());
    if (p.structure() == Plan::WELL_CONSTRAINED) check_well_constrained(p, k, eqv, name.str());
    if (p.structure() == Plan::ONE_DEGREE_OF_FREEDOM && m + 1 == k) check_one_dof(p, k, eqv, name.str());
    // over- and under-determined parts are disjoint
    Set oe(p.over_determined_equations().begin(), p.over_determined_equations().end());
    Set ov(p.over_determined_variables().begin(), p.over_determined_variables().end());
    for (std::size_t i : p.under_determined_equations()) CHECK(!oe.count(i), name.str() << ": equation " << i << " is both over- and under-determined");
    for (std::size_t j : p.under_determined_variables()) CHECK(!ov.count(j), name.str() << ": variable " << j << " is both over- and under-determined");
    ++seen[name_of(p.structure())];
  }
}

// ===================================================================== hand-made cases
struct Expected_block
{
  std::vector<std::size_t> equations, variables, inputs, depends_on;
};

void check_blocks_in_order(const Plan& p, const std::vector<Expected_block>& e, const std::string& name)
{
  CHECK(p.blocks().size() == e.size(), name << ": " << p.blocks().size() << " blocks, expected " << e.size() << " (" << show_plan(p) << ")");
  if (p.blocks().size() != e.size()) return;
  for (std::size_t b = 0; b < e.size(); ++b) {
    const auto& B = p.blocks()[b];
    CHECK(B.equations == e[b].equations && B.variables == e[b].variables && B.inputs == e[b].inputs && B.depends_on == e[b].depends_on,
          name << ": block " << b << " = eq " << list(B.equations) << " var " << list(B.variables) << " in " << list(B.inputs) << " after "
               << list(B.depends_on) << "; expected eq " << list(e[b].equations) << " var " << list(e[b].variables) << " in "
               << list(e[b].inputs) << " after " << list(e[b].depends_on));
  }
}

void hand_made()
{
  // Fig. 1: Ax, Ay, Bx, By = 0, 1, 2, 3; c0, c1 on A, c2, c3 on A and B.
  {
    const std::string name = "Fig. 1";
    Incidence eqv = {{0, 1}, {0, 1}, {0, 1, 2, 3}, {0, 1, 2, 3}};
    Incidence ineq = {{2}, {0}, {1, 3}, {0, 1}};
    Plan p(4, eqv, ineq);
    check_plan(p, 4, eqv, ineq, name);
    check_well_constrained(p, 4, eqv, name);
    check_blocks_in_order(p, {{{0, 1}, {0, 1}, {}, {}}, {{2, 3}, {2, 3}, {0, 1}, {0}}}, name);
    if (p.blocks().size() == 2) {
      CHECK(p.blocks()[0].inequalities == std::vector<std::size_t>({1, 3}), name << ": block 0 tests " << list(p.blocks()[0].inequalities) << ", expected {1,3}");
      CHECK(p.blocks()[1].inequalities == std::vector<std::size_t>({0, 2}), name << ": block 1 tests " << list(p.blocks()[1].inequalities) << ", expected {0,2}");
    }
    CHECK(p.largest_block() == 2, name << ": largest block " << p.largest_block());
  }
  // triangular: equation i involves variables 0..i (listed backwards): n blocks of one, in order
  for (std::size_t n = 1; n <= 8; ++n) {
    const std::string name = "triangular n=" + std::to_string(n);
    Incidence eqv(n);
    for (std::size_t i = 0; i < n; ++i) for (std::size_t j = i + 1; j-- > 0;) eqv[i].push_back(j);
    Plan p(n, eqv);
    check_plan(p, n, eqv, {}, name);
    check_well_constrained(p, n, eqv, name);
    std::vector<Expected_block> e;
    for (std::size_t i = 0; i < n; ++i) {
      Expected_block b{{i}, {i}, {}, {}};
      for (std::size_t j = 0; j < i; ++j) { b.inputs.push_back(j); b.depends_on.push_back(j); }
      e.push_back(b);
    }
    check_blocks_in_order(p, e, name);
    CHECK(p.largest_block() == 1, name << ": largest block " << p.largest_block());
  }
  // dense: one block
  for (std::size_t n = 1; n <= 8; ++n) {
    const std::string name = "dense n=" + std::to_string(n);
    Incidence eqv(n);
    std::vector<std::size_t> all;
    for (std::size_t j = 0; j < n; ++j) all.push_back(j);
    for (auto& e : eqv) e = all;
    Plan p(n, eqv);
    check_plan(p, n, eqv, {}, name);
    check_well_constrained(p, n, eqv, name);
    check_blocks_in_order(p, {{all, all, {}, {}}}, name);
  }
  // two independent 2x2 blocks and a chain: no dependency between the first two
  {
    const std::string name = "two independent blocks, then one using both";
    Incidence eqv = {{0, 1}, {0, 1}, {2, 3}, {2, 3}, {1, 4, 3}};
    Plan p(5, eqv, {{4}, {0, 2}});
    check_plan(p, 5, eqv, {{4}, {0, 2}}, name);
    check_well_constrained(p, 5, eqv, name);
    if (p.blocks().size() == 3) {
      CHECK(p.blocks()[2].equations == std::vector<std::size_t>({4}) && p.blocks()[2].depends_on == std::vector<std::size_t>({0, 1}) &&
              p.blocks()[2].inputs == std::vector<std::size_t>({1, 3}),
            name << ": last block " << list(p.blocks()[2].equations) << " after " << list(p.blocks()[2].depends_on));
      CHECK(p.blocks()[2].inequalities == std::vector<std::size_t>({0}), name << ": inequality on x4 not in the last block");
      CHECK(p.blocks()[0].depends_on.empty() && p.blocks()[1].depends_on.empty(), name << ": the first two blocks depend on something");
    }
  }
  // over-constrained: 3 equations in x, y, one in z
  {
    const std::string name = "over-constrained";
    Incidence eqv = {{0, 1}, {0, 1}, {1, 0}, {2}};
    Plan p(3, eqv);
    check_plan(p, 3, eqv, {}, name);
    CHECK(p.structure() == Plan::OVER_CONSTRAINED, name << ": " << name_of(p.structure()));
    CHECK(p.over_determined_equations() == std::vector<std::size_t>({0, 1, 2}), name << ": over equations " << list(p.over_determined_equations()));
    CHECK(p.over_determined_variables() == std::vector<std::size_t>({0, 1}), name << ": over variables " << list(p.over_determined_variables()));
    CHECK(p.under_determined_equations().empty() && p.under_determined_variables().empty() && p.unused_variables().empty(),
          name << ": an under-determined part");
    long negative = 0;
    for (const auto& b : p.blocks()) negative += b.dimension() < 0 ? -b.dimension() : 0;
    CHECK(negative == 1, name << ": blocks of negative dimension sum to " << -negative << ", expected -1");
  }
  // under-constrained by one: 1 equation in x, y; 1 in z
  {
    const std::string name = "one degree of freedom";
    Incidence eqv = {{0, 1}, {2}};
    Plan p(3, eqv, {{0}, {1}, {2}, {0, 2}});
    check_plan(p, 3, eqv, {{0}, {1}, {2}, {0, 2}}, name);
    check_one_dof(p, 3, eqv, name);
    CHECK(p.structure() == Plan::ONE_DEGREE_OF_FREEDOM, name << ": " << name_of(p.structure()));
    CHECK(p.under_determined_variables() == std::vector<std::size_t>({0, 1}), name << ": under variables " << list(p.under_determined_variables()));
    CHECK(p.under_determined_equations() == std::vector<std::size_t>({0}), name << ": under equations " << list(p.under_determined_equations()));
    CHECK(p.over_determined_equations().empty() && p.over_determined_variables().empty(), name << ": an over-determined part");
    CHECK(p.left_out_variable() == 0 || p.left_out_variable() == 1, name << ": left out " << p.left_out_variable());
    CHECK(p.largest_block() == 2, name << ": largest block " << p.largest_block() << ", expected 2 ({x, y} from one equation)");
    if (p.block_of_variable(0) != none) CHECK(p.block_of_variable(0) == p.block_of_variable(1), name << ": x and y in different blocks");
  }
  // Section 3.4 by hand: x0 from e0 (alone); e1 in x0, x1, x2. Leaving out x1 or x2 gives
  // blocks {e0: x0}, {e1: x1, x2} (largest 2); leaving out x0 is impossible (e0 unmatched).
  {
    const std::string name = "one dof, chain";
    Incidence eqv = {{0}, {0, 1, 2}};
    Plan p(3, eqv);
    check_plan(p, 3, eqv, {}, name);
    check_one_dof(p, 3, eqv, name);
    CHECK(p.left_out_variable() == 1, name << ": left out " << p.left_out_variable() << ", expected 1 (lowest of the ties)");
    check_blocks_in_order(p, {{{0}, {0}, {}, {}}, {{1}, {1, 2}, {0}, {0}}}, name);
  }
  // Section 3.4 on a path: e0 in x0, x1; e1 in x1, x2; e2 in x2, x3. Every left-out variable
  // gives three blocks of one equation, and the left-out variable joins one of them: the
  // largest block has 2 variables whichever is left out.
  {
    const std::string name = "one dof, path";
    Incidence eqv = {{0, 1}, {1, 2}, {2, 3}};
    Plan p(4, eqv);
    check_plan(p, 4, eqv, {}, name);
    check_one_dof(p, 4, eqv, name);
    CHECK(p.largest_block() == 2, name << ": largest block " << p.largest_block() << ", expected 2");
    CHECK(p.blocks().size() == 3, name << ": " << p.blocks().size() << " blocks, expected 3");
  }
  // Section 3.4 where the left-out variable matters: e0, e1 both in x0, x1, x2; e2 in x2, x3.
  // Leaving out x3: {e2: x2, x3}, then {e0, e1: x0, x1}: largest 2. Leaving out x0 (or x1):
  // {e0, e1: x0, x1, x2}, then {e2: x3}: largest 3. Leaving out x2: {e0, e1: x0, x1} and
  // {e2: x3}, independent, x2 joins whichever comes first: largest 3 or 2.
  {
    const std::string name = "one dof, the left-out variable matters";
    Incidence eqv = {{0, 1, 2}, {0, 1, 2}, {2, 3}};
    Plan p(4, eqv);
    check_plan(p, 4, eqv, {}, name);
    check_one_dof(p, 4, eqv, name);
    CHECK(p.left_out_variable() == 2 || p.left_out_variable() == 3, name << ": left out " << p.left_out_variable() << ", expected 2 or 3");
    CHECK(p.largest_block() == 2, name << ": largest block " << p.largest_block() << ", expected 2");
    // either way e2 solves x2 and x3 first, and e0, e1 take x2 from it
    check_blocks_in_order(p, {{{2}, {2, 3}, {}, {}}, {{0, 1}, {0, 1}, {2}, {0}}}, name);
  }
  // A longer chain: e0, e1 in x0, x1, x2; e2 in x0, x3; e3 in x3, x4. Leaving out x4:
  // {e3: x3, x4}, {e2: x0}, {e0, e1: x1, x2}: largest 2. Leaving out x3: {e3: x4}, {e2: x0}
  // and {e0, e1: x1, x2}, x3 joins e3 or e2: largest 2. Leaving out x1 (x2): {e0, e1: x0, x2
  // (x1)} plus the left-out variable: largest 3. Leaving out x0: {e0, e1: x1, x2}, {e2: x3},
  // {e3: x4}, x0 joins e0, e1 (3) or e2 (2), whichever comes first. The minimum is 2.
  {
    const std::string name = "one dof, a longer chain";
    Incidence eqv = {{0, 1, 2}, {0, 1, 2}, {0, 3}, {3, 4}};
    Plan p(5, eqv);
    check_plan(p, 5, eqv, {}, name);
    check_one_dof(p, 5, eqv, name);
    CHECK(p.largest_block() == 2, name << ": largest block " << p.largest_block() << ", expected 2");
  }
  // unused variable: e0 in x0, e1 in x1, x2 in nothing
  {
    const std::string name = "unused variable";
    Incidence eqv = {{0}, {1}};
    Incidence ineq = {{2}, {0, 1}, {0, 2}};
    Plan p(3, eqv, ineq);
    check_plan(p, 3, eqv, ineq, name);
    check_one_dof(p, 3, eqv, name);
    CHECK(p.unused_variables() == std::vector<std::size_t>({2}), name << ": unused " << list(p.unused_variables()));
    CHECK(p.under_determined_variables() == std::vector<std::size_t>({2}), name << ": under variables " << list(p.under_determined_variables()));
    CHECK(p.left_out_variable() == 2, name << ": left out " << p.left_out_variable());
    CHECK(p.block_of_variable(2) == none, name << ": the unused variable is in block " << p.block_of_variable(2));
    CHECK(p.unattached_inequalities() == std::vector<std::size_t>({0, 2}), name << ": unattached " << list(p.unattached_inequalities()));
  }
  // under-constrained by two
  {
    const std::string name = "under-constrained";
    Incidence eqv = {{0, 1, 2}};
    Plan p(3, eqv);
    check_plan(p, 3, eqv, {}, name);
    CHECK(p.structure() == Plan::UNDER_CONSTRAINED, name << ": " << name_of(p.structure()));
    CHECK(p.under_determined_variables() == std::vector<std::size_t>({0, 1, 2}), name << ": under variables " << list(p.under_determined_variables()));
    CHECK(p.blocks().size() == 1 && p.blocks()[0].dimension() == 2, name << ": " << show_plan(p));
  }
  // mixed: e0, e1 in x; e2 in y, z
  {
    const std::string name = "mixed";
    Incidence eqv = {{0}, {0}, {1, 2}};
    Plan p(3, eqv);
    check_plan(p, 3, eqv, {}, name);
    CHECK(p.structure() == Plan::MIXED, name << ": " << name_of(p.structure()));
    CHECK(p.over_determined_equations() == std::vector<std::size_t>({0, 1}) && p.over_determined_variables() == std::vector<std::size_t>({0}),
          name << ": over " << list(p.over_determined_equations()) << " " << list(p.over_determined_variables()));
    CHECK(p.under_determined_equations() == std::vector<std::size_t>({2}) && p.under_determined_variables() == std::vector<std::size_t>({1, 2}),
          name << ": under " << list(p.under_determined_equations()) << " " << list(p.under_determined_variables()));
  }
  // over-constrained and an unused variable: MIXED
  {
    const std::string name = "over-constrained with an unused variable";
    Incidence eqv = {{0}, {0}};
    Plan p(2, eqv, {{1}, {0}});
    check_plan(p, 2, eqv, {{1}, {0}}, name);
    CHECK(p.structure() == Plan::MIXED, name << ": " << name_of(p.structure()));
    CHECK(p.unused_variables() == std::vector<std::size_t>({1}), name << ": unused " << list(p.unused_variables()));
  }
  // empty systems
  {
    Plan p(0, {});
    check_plan(p, 0, {}, {}, "no equation, no variable");
    CHECK(p.structure() == Plan::WELL_CONSTRAINED && p.blocks().empty(), "no equation, no variable: " << show_plan(p));
    Plan q(1, {}, {{0}});
    check_plan(q, 1, {}, {{0}}, "one variable, no equation");
    CHECK(q.structure() == Plan::ONE_DEGREE_OF_FREEDOM && q.left_out_variable() == 0 && q.blocks().empty(), "one variable, no equation: " << show_plan(q));
    Plan r(2, {});
    check_plan(r, 2, {}, {}, "two variables, no equation");
    CHECK(r.structure() == Plan::UNDER_CONSTRAINED, "two variables, no equation: " << name_of(r.structure()));
    Plan s(0, {{}, {}});
    check_plan(s, 0, {{}, {}}, {}, "two equations in no variable");
    CHECK(s.structure() == Plan::OVER_CONSTRAINED, "two equations in no variable: " << name_of(s.structure()));
  }
}

// The convenience constructor from a Polynomial_system<Gmpq>: Fig. 1 as bar lengths, plus an
// equation where x2 cancels out (variables() drops it).
void from_polynomial_system()
{
  typedef RI::Sparse_polynomial<CGAL::Gmpq> Poly;
  RI::Polynomial_system<CGAL::Gmpq> s;
  s.variable_names = {"Ax", "Ay", "Bx", "By", "C"};
  s.box.assign(5, {-10.0, 10.0});
  const std::size_t n = 5;
  auto x = [&](std::size_t i) { return Poly::variable(n, i); };
  auto c = [&](int v) { return Poly::constant(n, CGAL::Gmpq(v)); };
  auto sq = [](const Poly& p) { return p * p; };
  const CGAL::Gmpq minus_one(-1);
  s.equations.push_back(sq(x(0)) + sq(x(1)) + c(-4));                                          // |A - O1| = 2
  s.equations.push_back(sq(x(0) + c(-3)) + sq(x(1)) + c(-5));                                  // |A - O2|
  s.equations.push_back(sq(x(0) + minus_one * x(2)) + sq(x(1) + minus_one * x(3)) + c(-1));    // |A - B|
  s.equations.push_back(sq(x(2) + c(-1)) + sq(x(3)) + c(-2) + x(0) * x(1));                   // |B - O3|, with A
  s.equations.push_back(x(4) + x(2) + minus_one * x(2) + c(-7));                               // C = 7: x2 cancels
  s.labels.assign(s.equations.size(), "");
  const std::string name = "Polynomial_system<Gmpq>";
  Plan p(s, {{4}, {2, 3}});
  Incidence expected = {{0, 1}, {0, 1}, {0, 1, 2, 3}, {0, 1, 2, 3}, {4}};
  check_plan(p, 5, expected, {{4}, {2, 3}}, name);
  check_well_constrained(p, 5, expected, name);
  CHECK(p.equation_variables(4) == std::vector<std::size_t>({4}), name << ": equation 4 involves " << list(p.equation_variables(4)) << ", expected {4}");
  std::size_t a = p.block_of_equation(0), b = p.block_of_equation(2), e = p.block_of_equation(4);
  CHECK(a == p.block_of_equation(1) && b == p.block_of_equation(3) && a < b && e != a && e != b,
        name << ": " << show_plan(p));
  CHECK(p.blocks().size() == 3, name << ": " << p.blocks().size() << " blocks, expected 3");
  if (b < p.blocks().size()) CHECK(p.blocks()[b].inequalities == std::vector<std::size_t>({1}), name << ": block of B tests " << list(p.blocks()[b].inequalities));
}

void malformed()
{
  auto expect_error = [](std::size_t k, const Incidence& eqv, const Incidence& ineq, const std::string& must_name, const std::string& name) {
    bool thrown = false, other = false;
    std::string what;
    try {
      Plan p(k, eqv, ineq);
    } catch (const RI::Input_error& e) {
      thrown = true;
      what = e.what();
    } catch (...) {
      other = true;
    }
    CHECK(thrown && !other, name << ": no Input_error thrown" << (other ? " (another exception)" : ""));
    CHECK(what.find(must_name) != std::string::npos, name << ": the message '" << what << "' does not name '" << must_name << "'");
  };
  Incidence eqv(13, std::vector<std::size_t>{0, 1, 2});
  eqv[12] = {1, 3};
  expect_error(3, eqv, {}, "equation 12", "variable 3 of 3 in equation 12");
  expect_error(2, {{0}, {1, 7}}, {}, "equation 1", "variable 7 of 2 in equation 1");
  expect_error(0, {{0}}, {}, "equation 0", "variable 0 of 0 in equation 0");
  expect_error(2, {{0}, {1}}, {{0}, {1}, {2}}, "inequality 2", "variable 2 of 2 in inequality 2");
  expect_error(2, {{0}, {1}}, {{0}, {std::size_t(-1)}}, "inequality 1", "variable size_t(-1) in inequality 1");
  bool thrown = false;
  try {
    Plan p(3, {{2, 0}, {1}, {0, 1, 2}}, {{2}});
  } catch (...) {
    thrown = true;
  }
  CHECK(!thrown, "a valid system throws");
}

// independent_parts() against a flood fill over the variables (an oracle written apart: each
// part grown from its first variable by repeated passes over the equations, inequalities and
// groups), on random supports with groups of 1 to 3 variables; and its errors
static void independent_parts_against_flood_fill(CGAL::Random& rnd, int rounds)
{
  for (int round = 0; round < rounds; ++round) {
    const std::size_t n = std::size_t(rnd.get_int(0, 14));
    std::vector<std::vector<std::size_t>> eqv(std::size_t(rnd.get_int(0, 10))), inv(std::size_t(rnd.get_int(0, 3)));
    for (auto* list : {&eqv, &inv})
      for (auto& vs : *list) {
        const int k = n == 0 ? 0 : rnd.get_int(0, 4);
        for (int j = 0; j < k; ++j) vs.push_back(std::size_t(rnd.get_int(0, int(n))));
        std::sort(vs.begin(), vs.end());
        vs.erase(std::unique(vs.begin(), vs.end()), vs.end());
      }
    std::vector<std::size_t> group;
    if (rnd.get_bool()) {
      std::size_t g = 0;
      for (std::size_t j = 0; j < n;) {
        const std::size_t len = std::size_t(rnd.get_int(1, 4));
        const bool none = rnd.get_int(0, 4) == 0;
        for (std::size_t k = 0; k < len && j < n; ++k, ++j) group.push_back(none ? std::size_t(-1) : g);
        if (!none) ++g;
      }
    }
    const auto parts = RI::independent_parts(n, eqv, inv, group);
    // the oracle
    std::vector<long> part_of(n, -1);
    std::size_t count = 0;
    for (std::size_t s = 0; s < n; ++s) {
      if (part_of[s] >= 0) continue;
      part_of[s] = long(count);
      for (bool grew = true; grew;) {
        grew = false;
        auto join = [&](const std::vector<std::size_t>& vs) {
          bool in = false;
          for (std::size_t j : vs) in = in || part_of[j] == long(count);
          if (in)
            for (std::size_t j : vs)
              if (part_of[j] != long(count)) { part_of[j] = long(count); grew = true; }
        };
        for (const auto* list : {&eqv, &inv})
          for (const auto& vs : *list) join(vs);
        for (std::size_t j = 0; j < group.size(); ++j) {
          if (group[j] == std::size_t(-1)) continue;
          std::vector<std::size_t> same;
          for (std::size_t k = 0; k < group.size(); ++k) if (group[k] == group[j]) same.push_back(k);
          join(same);
        }
      }
      ++count;
    }
    CHECK(parts.size() == count, "independent_parts: " << parts.size() << " parts, the flood fill " << count);
    if (parts.size() != count) continue;
    std::vector<std::size_t> eq_seen, in_seen;
    for (std::size_t k = 0; k < parts.size(); ++k) {
      for (std::size_t j : parts[k].variables) CHECK(part_of[j] == long(k), "independent_parts: variable " << j << " in part " << k);
      CHECK(parts[k].variables.size() == std::size_t(std::count(part_of.begin(), part_of.end(), long(k))), "independent_parts: part " << k << "'s size");
      for (std::size_t i : parts[k].equations) {
        eq_seen.push_back(i);
        CHECK(eqv[i].empty() ? k == 0 : part_of[eqv[i][0]] == long(k), "independent_parts: equation " << i << " in part " << k);
      }
      for (std::size_t q : parts[k].inequalities) {
        in_seen.push_back(q);
        CHECK(inv[q].empty() ? k == 0 : part_of[inv[q][0]] == long(k), "independent_parts: inequality " << q << " in part " << k);
      }
      for (std::size_t g : parts[k].groups) {
        bool found = false;
        for (std::size_t j : parts[k].variables) found = found || (!group.empty() && group[j] == g);
        CHECK(found, "independent_parts: group " << g << " in part " << k << " without a variable of it");
      }
    }
    std::sort(eq_seen.begin(), eq_seen.end());
    std::sort(in_seen.begin(), in_seen.end());
    CHECK(n == 0 || (eq_seen.size() == eqv.size() && std::adjacent_find(eq_seen.begin(), eq_seen.end()) == eq_seen.end() &&
                     in_seen.size() == inv.size()),
          "independent_parts: every equation and inequality in exactly one part");
  }
  bool threw = false;
  try { RI::independent_parts(2, {{0, 5}}); } catch (const RI::Input_error& e) { threw = std::string(e.what()).find("variable 5 of 2") != std::string::npos; }
  CHECK(threw, "independent_parts: a variable beyond n is refused");
  threw = false;
  try { RI::independent_parts(3, {{0}}, {}, {0, 0}); } catch (const RI::Input_error& e) { threw = std::string(e.what()).find("2 groups for 3 variables") != std::string::npos; }
  CHECK(threw, "independent_parts: groups of the wrong size are refused");
}

int main(int argc, char** argv)
{
  unsigned seed = argc > 1 ? unsigned(std::strtoul(argv[1], nullptr, 10)) : 20260311u;
  int per_cell = argc > 2 ? std::atoi(argv[2]) : 8;
  std::cout << "seed " << seed << " (rerun: test_solution_plan " << seed << " " << per_cell << ")\n";
  auto t0 = std::chrono::steady_clock::now();
  CGAL::Random rnd(seed);
  hand_made();
  from_polynomial_system();
  malformed();
  independent_parts_against_flood_fill(rnd, 50 * per_cell);
  std::size_t square = 0, blocks = 0, one_dof = 0, forced = 0;
  random_square_systems(rnd, per_cell, square, blocks);
  std::cout << "  " << square << " square systems, " << blocks << " blocks\n";
  random_one_dof_systems(rnd, per_cell, one_dof, forced);
  std::cout << "  " << one_dof << " systems with one degree of freedom (" << forced << " with the best largest block forced)\n";
  std::map<std::string, int> seen;
  random_any_systems(rnd, 100 * per_cell, seen);
  std::cout << "  " << 100 * per_cell << " systems of any shape:";
  for (const auto& s : seen) std::cout << " " << s.first << " " << s.second;
  std::cout << "\n";
  double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  std::cout << checks << " checks, " << secs << " s\n";
  if (failures) std::cout << "FAILED: " << failures << " failures (seed " << seed << ")\n";
  else std::cout << "OK\n";
  return failures ? 1 : 0;
}
