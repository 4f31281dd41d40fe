// Copyright (c) 2026 Rigid_incidence contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The solution plan of a polynomial system (decomposition_subdivision_solver.txt, Section 3,
// van Sosin and Elber): the variable-constraint bipartite graph (Definition 3.4), a maximum
// matching, the dependency graph (Algorithm 3), its condensation on the equations
// (Algorithm 4), the strongly connected components of that in a topological order
// (Algorithm 2), the inequalities attached to the first block that can test them
// (Algorithm 5), and for one equation fewer than variables the exhaustive search over the
// left-out variable that keeps the largest block smallest (Section 3.4). For systems that are
// not square, the Dulmage-Mendelsohn coarse decomposition names the over-determined part
// (equations redundant or in conflict) and the under-determined part (free variables).

#ifndef CGAL_RIGID_INCIDENCE_SOLUTION_PLAN_H
#define CGAL_RIGID_INCIDENCE_SOLUTION_PLAN_H

#include <CGAL/Rigid_incidence/Input_error.h>
#include <CGAL/Rigid_incidence/Polynomial_system.h>

#include <boost/graph/adjacency_list.hpp>
#include <boost/graph/connected_components.hpp>
#include <boost/graph/max_cardinality_matching.hpp>
#include <boost/graph/strong_components.hpp>
#include <boost/graph/topological_sort.hpp>

#include <algorithm>
#include <cstddef>
#include <deque>
#include <iterator>
#include <limits>
#include <set>
#include <string>
#include <vector>

namespace CGAL {
namespace Rigid_incidence {

/*!
\ingroup PkgRigidIncidenceSolver
\brief One step of a `Solution_plan`: the equations solved together and the variables they
determine, given the variables of earlier blocks.
*/
struct Plan_block
{
  std::vector<std::size_t> equations;     ///< indices into the system's equations, increasing
  std::vector<std::size_t> variables;     ///< the variables solved in this block, increasing
  std::vector<std::size_t> inputs;        ///< variables of earlier blocks its equations use, increasing
  std::vector<std::size_t> inequalities;  ///< inequalities tested in this block (Algorithm 5), increasing
  std::vector<std::size_t> depends_on;    ///< the earlier blocks (indices into `Solution_plan::blocks()`) that give an input

  /// Variables minus equations: 0 for a square block (finitely many roots expected), 1 for
  /// a block whose solution set is a curve, negative for a block of equations left over
  /// (over-determined: they only check the values found before).
  long dimension() const { return long(variables.size()) - long(equations.size()); }
};

/*!
\ingroup PkgRigidIncidenceSolver
\brief The decomposition of a polynomial system into blocks solved one after the other
(decomposition_subdivision_solver.txt, Algorithms 2-5 and Section 3.4).

Only the structure of the system matters: which equation involves which variable. For a
square system with a perfect matching the blocks are the finest block triangular form, which
does not depend on the matching. With one equation fewer than variables, every variable is
tried as the one left out of the matching and the plan whose largest block has the fewest
variables is kept (ties: the plan with more blocks, then the lowest variable index); the
left-out variable is solved in the first block that uses it, which then has a curve of
solutions. An inequality is tested in the block where the last of its variables is solved (an
inequality in no variable: in the first block).

The Dulmage-Mendelsohn coarse decomposition of the system, from the same matching:
- the over-determined part: the equations reached from an equation left unmatched by
  alternating paths, with their variables (more equations than variables: some equations are
  redundant or in conflict);
- the under-determined part: the variables reached from a variable left unmatched, with
  their equations (more variables than equations: a solution set of positive dimension);
- the rest is square and perfectly matched.
*/
class Solution_plan
{
public:
  /// The structure of a system.
  enum Structure {
    WELL_CONSTRAINED,        ///< square, perfectly matched: finitely many solutions expected
    ONE_DEGREE_OF_FREEDOM,   ///< one variable more than the matching covers, no equation left over: curves
    UNDER_CONSTRAINED,       ///< two or more variables left over, no equation left over
    OVER_CONSTRAINED,        ///< some equations left over, every variable matched
    MIXED                    ///< both an over- and an under-determined part
  };

  static constexpr std::size_t none = std::size_t(-1);  ///< "no such index"

  /*!
  The plan of a system of `equation_variables.size()` equations in `number_of_variables`
  variables; `equation_variables[i]` lists the variables equation i involves,
  `inequality_variables[j]` those inequality j involves.
  \throws Input_error if a variable index is out of range.
  */
  Solution_plan(std::size_t number_of_variables, const std::vector<std::vector<std::size_t>>& equation_variables,
                const std::vector<std::vector<std::size_t>>& inequality_variables = {})
      : k_(number_of_variables), eqv_(normalized(equation_variables, "equation")), inv_(normalized(inequality_variables, "inequality"))
  {
    build();
  }

  /// The plan of `system`: the variables each of its equations, and each of its inequalities,
  /// involves with positive degree.
  template <class NT>
  explicit Solution_plan(const Polynomial_system<NT>& system)
      : Solution_plan(system.number_of_variables(), supports(system.equations), supports(system.inequalities))
  {
  }

  /// The plan of the equations of `system` with the inequalities `inequality_variables` instead
  /// of the system's own (`inequality_variables[j]`: the variables inequality j involves; `{}`
  /// for a plan without inequalities, which `solve_with_plan()` takes only for a system without
  /// them).
  template <class NT>
  Solution_plan(const Polynomial_system<NT>& system, const std::vector<std::vector<std::size_t>>& inequality_variables)
      : Solution_plan(system.number_of_variables(), supports(system.equations), inequality_variables)
  {
  }

  /// Number of variables.
  std::size_t number_of_variables() const { return k_; }
  /// Number of equations.
  std::size_t number_of_equations() const { return eqv_.size(); }
  /// The variables equation `i` involves, increasing.
  const std::vector<std::size_t>& equation_variables(std::size_t i) const { return eqv_.at(i); }
  /// Number of inequalities.
  std::size_t number_of_inequalities() const { return inv_.size(); }
  /// The variables inequality `q` involves, increasing.
  const std::vector<std::size_t>& inequality_variables(std::size_t q) const { return inv_.at(q); }

  /// The blocks in the order they are solved (a topological order of the dependencies).
  const std::vector<Plan_block>& blocks() const { return blocks_; }
  /// The block that solves variable `j`, or `none` if no block does (a variable no equation uses).
  std::size_t block_of_variable(std::size_t j) const { return block_of_var_.at(j); }
  /// The block that holds equation `i`.
  std::size_t block_of_equation(std::size_t i) const { return block_of_eq_.at(i); }
  /// The largest number of variables solved in one block.
  std::size_t largest_block() const
  {
    std::size_t r = 0;
    for (const auto& b : blocks_) r = (std::max)(r, b.variables.size());
    return r;
  }

  /// The variable matched to equation `i` in the matching the plan was made from, or `none`.
  std::size_t matched_variable(std::size_t i) const { return mate_eq_.at(i); }
  /// The structure of the system, from the matching.
  Structure structure() const { return structure_; }
  /// The variable the exhaustive search of Section 3.4 left out of the matching (one degree of
  /// freedom only), else `none`.
  std::size_t left_out_variable() const { return left_out_; }

  /// Equations of the over-determined part, increasing (empty if there is none).
  const std::vector<std::size_t>& over_determined_equations() const { return over_eq_; }
  /// Variables of the over-determined part, increasing.
  const std::vector<std::size_t>& over_determined_variables() const { return over_var_; }
  /// Equations of the under-determined part, increasing.
  const std::vector<std::size_t>& under_determined_equations() const { return under_eq_; }
  /// Variables of the under-determined part, increasing (empty if there is none).
  const std::vector<std::size_t>& under_determined_variables() const { return under_var_; }
  /// Variables no equation involves, increasing (part of the under-determined part).
  const std::vector<std::size_t>& unused_variables() const { return unused_; }
  /// Inequalities no block can test (an inequality in a variable no block solves).
  const std::vector<std::size_t>& unattached_inequalities() const { return unattached_; }

private:
  typedef boost::adjacency_list<boost::vecS, boost::vecS, boost::undirectedS> Bipartite;
  typedef boost::adjacency_list<boost::vecS, boost::vecS, boost::directedS> Digraph;

  std::vector<std::vector<std::size_t>> normalized(std::vector<std::vector<std::size_t>> v, const char* what) const
  {
    for (std::size_t i = 0; i < v.size(); ++i) {
      for (std::size_t j : v[i])
        if (j >= k_)
          throw Input_error(std::string("Solution_plan: ") + what + " " + std::to_string(i) + " involves variable " + std::to_string(j) +
                            ", but the system has " + std::to_string(k_) + " variables");
      std::sort(v[i].begin(), v[i].end());
      v[i].erase(std::unique(v[i].begin(), v[i].end()), v[i].end());
    }
    return v;
  }
  template <class P> static std::vector<std::vector<std::size_t>> supports(const std::vector<P>& polynomials)
  {
    std::vector<std::vector<std::size_t>> r;
    for (const auto& f : polynomials) r.push_back(f.variables());
    return r;
  }

  // A maximum matching of the variable-constraint graph (Definition 3.4; vertices: equations
  // 0..m-1, then variables m..m+k-1), leaving out variable `skip` if it is not `none`.
  // Returns the number of matched pairs; mate_eq / mate_var get the partners.
  std::size_t match(std::size_t skip, std::vector<std::size_t>& mate_eq, std::vector<std::size_t>& mate_var) const
  {
    const std::size_t m = eqv_.size();
    mate_eq.assign(m, none);
    mate_var.assign(k_, none);
    if (m == 0 || k_ == 0) return 0;
    Bipartite g(m + k_);
    for (std::size_t i = 0; i < m; ++i)
      for (std::size_t j : eqv_[i])
        if (j != skip) boost::add_edge(i, m + j, g);
    std::vector<Bipartite::vertex_descriptor> mate(m + k_);
    boost::edmonds_maximum_cardinality_matching(g, &mate[0]);
    const auto null = boost::graph_traits<Bipartite>::null_vertex();
    std::size_t size = 0;
    for (std::size_t i = 0; i < m; ++i)
      if (mate[i] != null) {
        mate_eq[i] = mate[i] - m;
        mate_var[mate[i] - m] = i;
        ++size;
      }
    return size;
  }

  // Algorithms 3, 4 and 2: the blocks from a matching, in a topological order.
  void blocks_from(const std::vector<std::size_t>& mate_eq, std::vector<Plan_block>& out, std::vector<std::size_t>& block_of_eq,
                   std::vector<std::size_t>& block_of_var) const
  {
    const std::size_t m = eqv_.size();
    std::vector<std::size_t> mate_var(k_, none);
    for (std::size_t i = 0; i < m; ++i)
      if (mate_eq[i] != none) mate_var[mate_eq[i]] = i;
    // the condensed dependency graph H: M_a -> M_b when M_b uses the variable matched to M_a
    // (in G' the path M_a -> t -> M_b through one variable vertex)
    Digraph h(m);
    for (std::size_t b = 0; b < m; ++b)
      for (std::size_t t : eqv_[b]) {
        std::size_t a = mate_var[t];
        if (a != none && a != b) boost::add_edge(a, b, h);
      }
    std::vector<std::size_t> comp(m);
    const std::size_t nc = m == 0 ? 0 : std::size_t(boost::strong_components(h, &comp[0]));
    // the SCC graph, a DAG, in a topological order
    Digraph dag(nc);
    std::set<std::pair<std::size_t, std::size_t>> seen;
    for (std::size_t a = 0; a < m; ++a) {
      auto es = boost::out_edges(a, h);
      for (auto e = es.first; e != es.second; ++e) {
        std::size_t b = boost::target(*e, h);
        if (comp[a] != comp[b] && seen.insert({comp[a], comp[b]}).second) boost::add_edge(comp[a], comp[b], dag);
      }
    }
    std::vector<std::size_t> rev;
    boost::topological_sort(dag, std::back_inserter(rev));  // reverse topological order
    std::vector<std::size_t> position(nc);
    for (std::size_t p = 0; p < nc; ++p) position[rev[nc - 1 - p]] = p;
    out.assign(nc, Plan_block());
    block_of_eq.assign(m, none);
    block_of_var.assign(k_, none);
    for (std::size_t i = 0; i < m; ++i) {
      const std::size_t p = position[comp[i]];
      out[p].equations.push_back(i);
      block_of_eq[i] = p;
      if (mate_eq[i] != none) {
        out[p].variables.push_back(mate_eq[i]);
        block_of_var[mate_eq[i]] = p;
      }
    }
    // a variable left unmatched is solved in the first block that uses it (Section 3.3: the
    // condensation merges input variables into the first subsystem using them)
    for (std::size_t j = 0; j < k_; ++j) {
      if (block_of_var[j] != none) continue;
      std::size_t first = none;
      for (std::size_t i = 0; i < m; ++i)
        if (std::binary_search(eqv_[i].begin(), eqv_[i].end(), j)) first = (std::min)(first, block_of_eq[i]);
      if (first == none) continue;  // no equation uses it
      out[first].variables.push_back(j);
      block_of_var[j] = first;
    }
    for (std::size_t p = 0; p < nc; ++p) {
      Plan_block& b = out[p];
      std::sort(b.variables.begin(), b.variables.end());
      std::set<std::size_t> in, dep;
      for (std::size_t i : b.equations)
        for (std::size_t j : eqv_[i])
          if (block_of_var[j] != p) {
            in.insert(j);
            dep.insert(block_of_var[j]);
          }
      b.inputs.assign(in.begin(), in.end());
      b.depends_on.assign(dep.begin(), dep.end());
    }
  }
  // The Dulmage-Mendelsohn coarse decomposition: alternating paths from the unmatched
  // equations (over-determined part) and from the unmatched variables (under-determined part).
  void dulmage_mendelsohn()
  {
    const std::size_t m = eqv_.size();
    std::vector<std::vector<std::size_t>> var_eqs(k_);
    for (std::size_t i = 0; i < m; ++i)
      for (std::size_t j : eqv_[i]) var_eqs[j].push_back(i);
    // from unmatched equations: equation -> any variable it uses -> that variable's equation
    std::vector<char> eq_in(m, 0), var_in(k_, 0);
    std::deque<std::size_t> q;
    for (std::size_t i = 0; i < m; ++i)
      if (mate_eq_[i] == none) { eq_in[i] = 1; q.push_back(i); }
    while (!q.empty()) {
      std::size_t i = q.front();
      q.pop_front();
      for (std::size_t j : eqv_[i]) {
        if (var_in[j]) continue;
        var_in[j] = 1;
        std::size_t a = mate_var_[j];
        if (a != none && !eq_in[a]) { eq_in[a] = 1; q.push_back(a); }
      }
    }
    for (std::size_t i = 0; i < m; ++i) if (eq_in[i]) over_eq_.push_back(i);
    for (std::size_t j = 0; j < k_; ++j) if (var_in[j]) over_var_.push_back(j);
    // from unmatched variables: variable -> any equation using it -> that equation's variable
    std::vector<char> eq_u(m, 0), var_u(k_, 0);
    for (std::size_t j = 0; j < k_; ++j)
      if (mate_var_[j] == none) { var_u[j] = 1; q.push_back(j); }
    while (!q.empty()) {
      std::size_t j = q.front();
      q.pop_front();
      for (std::size_t i : var_eqs[j]) {
        if (eq_u[i]) continue;
        eq_u[i] = 1;
        std::size_t t = mate_eq_[i];
        if (t != none && !var_u[t]) { var_u[t] = 1; q.push_back(t); }
      }
    }
    for (std::size_t i = 0; i < m; ++i) if (eq_u[i]) under_eq_.push_back(i);
    for (std::size_t j = 0; j < k_; ++j) if (var_u[j]) under_var_.push_back(j);
    for (std::size_t j = 0; j < k_; ++j) if (var_eqs[j].empty()) unused_.push_back(j);
  }

  void build()
  {
    const std::size_t m = eqv_.size();
    std::size_t size = match(none, mate_eq_, mate_var_);
    dulmage_mendelsohn();
    const bool over = size < m, under = size < k_;
    structure_ = over && under ? MIXED : over ? OVER_CONSTRAINED : under ? (k_ - size == 1 ? ONE_DEGREE_OF_FREEDOM : UNDER_CONSTRAINED) : WELL_CONSTRAINED;
    blocks_from(mate_eq_, blocks_, block_of_eq_, block_of_var_);
    if (structure_ == ONE_DEGREE_OF_FREEDOM) {
      // Section 3.4: leave out each variable in turn; keep the plan whose largest block is
      // smallest (then the one with more blocks, then the lowest variable)
      std::size_t best = largest_block(), best_count = blocks_.size();
      left_out_ = none;
      for (std::size_t j = 0; j < k_; ++j)
        if (mate_var_[j] == none) left_out_ = j;
      for (std::size_t v = 0; v < k_; ++v) {
        std::vector<std::size_t> me, mv;
        if (match(v, me, mv) != m) continue;
        std::vector<Plan_block> b;
        std::vector<std::size_t> be, bv;
        blocks_from(me, b, be, bv);
        std::size_t largest = 0;
        for (const auto& x : b) largest = (std::max)(largest, x.variables.size());
        if (largest < best || (largest == best && b.size() > best_count) ||
            (largest == best && b.size() == best_count && v < left_out_)) {
          best = largest;
          best_count = b.size();
          left_out_ = v;
          mate_eq_ = me;
          mate_var_ = mv;
          blocks_ = b;
          block_of_eq_ = be;
          block_of_var_ = bv;
        }
      }
    }
    attach_inequalities();
  }

  // Algorithm 5: an inequality goes to the block where the last of its variables is solved.
  void attach_inequalities()
  {
    for (std::size_t q = 0; q < inv_.size(); ++q) {
      std::size_t last = 0;
      bool ok = !blocks_.empty();
      for (std::size_t j : inv_[q]) {
        if (block_of_var_[j] == none) { ok = false; break; }
        last = (std::max)(last, block_of_var_[j]);
      }
      if (ok) blocks_[last].inequalities.push_back(q);
      else unattached_.push_back(q);
    }
  }

  std::size_t k_;
  std::vector<std::vector<std::size_t>> eqv_, inv_;
  std::vector<std::size_t> mate_eq_, mate_var_;
  std::vector<Plan_block> blocks_;
  std::vector<std::size_t> block_of_eq_, block_of_var_;
  Structure structure_ = WELL_CONSTRAINED;
  std::size_t left_out_ = none;
  std::vector<std::size_t> over_eq_, over_var_, under_eq_, under_var_, unused_, unattached_;
};

/*!
\ingroup PkgRigidIncidenceSolver
\brief One independent part of a system (see `independent_parts()`).
*/
struct Independent_part
{
  std::vector<std::size_t> variables;     ///< increasing
  std::vector<std::size_t> equations;     ///< the equations in these variables, increasing
  std::vector<std::size_t> inequalities;  ///< the inequalities in these variables, increasing
  std::vector<std::size_t> groups;        ///< the groups of these variables (see below), increasing
};

/*!
\ingroup PkgRigidIncidenceSolver
\brief The independent parts of a system of `n` variables: the connected components of the
graph on its variables where an equation (its variables `equations[i]`), an inequality
(`inequalities[q]`) or a group joins the variables it involves (`group[j]`, the group of
variable \f$j\f$, `std::size_t(-1)` for none; empty: no groups; a scene's chart groups: the
variables of one tree edge, which change charts together).

The solutions of the system are the product of its parts' solutions: each equation and
inequality involves one part's variables only. The parts are ordered by their first variable;
an equation or inequality without variables goes to the first part. No variables: no part.
\throws Input_error if a variable index is not below `n`, or `group` is neither empty nor of size `n`.
*/
inline std::vector<Independent_part> independent_parts(std::size_t n, const std::vector<std::vector<std::size_t>>& equations,
                                                       const std::vector<std::vector<std::size_t>>& inequalities = {},
                                                       const std::vector<std::size_t>& group = {})
{
  if (!group.empty() && group.size() != n)
    throw Input_error("independent_parts: " + std::to_string(group.size()) + " groups for " + std::to_string(n) + " variables");
  std::vector<Independent_part> parts;
  if (n == 0) return parts;
  boost::adjacency_list<boost::vecS, boost::vecS, boost::undirectedS> g(n);
  for (const auto* list : {&equations, &inequalities})
    for (const auto& vs : *list)
      for (std::size_t j : vs) {
        if (j >= n) throw Input_error("independent_parts: variable " + std::to_string(j) + " of " + std::to_string(n));
        if (j != vs[0]) boost::add_edge(vs[0], j, g);
      }
  std::vector<std::size_t> first_of_group;
  for (std::size_t j = 0; j < group.size(); ++j) {
    const std::size_t k = group[j];
    if (k == std::size_t(-1)) continue;
    if (k >= first_of_group.size()) first_of_group.resize(k + 1, std::size_t(-1));
    if (first_of_group[k] == std::size_t(-1)) first_of_group[k] = j;
    else boost::add_edge(first_of_group[k], j, g);
  }
  std::vector<std::size_t> component(n);
  boost::connected_components(g, component.data());
  // renumbered by first variable
  std::vector<std::size_t> index(n, std::size_t(-1));
  for (std::size_t j = 0; j < n; ++j) {
    std::size_t& k = index[component[j]];
    if (k == std::size_t(-1)) {
      k = parts.size();
      parts.emplace_back();
    }
    parts[k].variables.push_back(j);
    if (!group.empty() && group[j] != std::size_t(-1)) parts[k].groups.push_back(group[j]);
  }
  for (auto& p : parts) {
    std::sort(p.groups.begin(), p.groups.end());
    p.groups.erase(std::unique(p.groups.begin(), p.groups.end()), p.groups.end());
  }
  for (std::size_t i = 0; i < equations.size(); ++i)
    parts[equations[i].empty() ? 0 : index[component[equations[i][0]]]].equations.push_back(i);
  for (std::size_t q = 0; q < inequalities.size(); ++q)
    parts[inequalities[q].empty() ? 0 : index[component[inequalities[q][0]]]].inequalities.push_back(q);
  return parts;
}

} // namespace Rigid_incidence
} // namespace CGAL

#endif
