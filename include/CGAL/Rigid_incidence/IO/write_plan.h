// Copyright (c) 2026 Rigid_incidence contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// A solution plan as text, as JSON (nlohmann) and as a Graphviz DOT drawing.

#ifndef CGAL_RIGID_INCIDENCE_IO_WRITE_PLAN_H
#define CGAL_RIGID_INCIDENCE_IO_WRITE_PLAN_H

#include <CGAL/Rigid_incidence/IO/write_dot.h>
#include <CGAL/Rigid_incidence/Solution_plan.h>

#include <nlohmann/json.hpp>

#include <ostream>
#include <string>
#include <vector>

namespace CGAL {
namespace Rigid_incidence {
namespace internal {
inline std::string plan_name(const std::vector<std::string>& names, std::size_t i, const char* prefix)
{
  return i < names.size() && !names[i].empty() ? names[i] : prefix + std::to_string(i);
}
inline std::string plan_list(const std::vector<std::size_t>& v, const std::vector<std::string>& names, const char* prefix)
{
  std::string r;
  for (std::size_t k = 0; k < v.size(); ++k) r += (k ? ", " : "") + plan_name(names, v[k], prefix);
  return r;
}
inline const char* plan_structure_name(Solution_plan::Structure s)
{
  switch (s) {
  case Solution_plan::WELL_CONSTRAINED: return "well_constrained";
  case Solution_plan::ONE_DEGREE_OF_FREEDOM: return "one_degree_of_freedom";
  case Solution_plan::UNDER_CONSTRAINED: return "under_constrained";
  case Solution_plan::OVER_CONSTRAINED: return "over_constrained";
  default: return "mixed";
  }
}
} // namespace internal

/*!
\ingroup PkgRigidIncidenceIO
\brief Writes `plan` as text: one line per block in the order of solving, with its equations
(`equation_names`, else f0, f1, ...), the variables it solves (`variable_names`, else x0, x1,
...), its inputs and inequalities; then the over- and under-determined parts if any.
*/
inline void write_plan_text(std::ostream& os, const Solution_plan& plan, const std::vector<std::string>& variable_names = {},
                            const std::vector<std::string>& equation_names = {}, const std::vector<std::string>& inequality_names = {})
{
  using internal::plan_list;
  os << "solution plan: " << plan.number_of_equations() << " equations in " << plan.number_of_variables() << " variables, "
     << internal::plan_structure_name(plan.structure()) << "; " << plan.blocks().size() << " block(s), the largest solves "
     << plan.largest_block() << " variable(s)\n";
  if (plan.left_out_variable() != Solution_plan::none)
    os << "  one degree of freedom: " << internal::plan_name(variable_names, plan.left_out_variable(), "x")
       << " left out of the matching (the choice with the smallest largest block, Section 3.4)\n";
  for (std::size_t b = 0; b < plan.blocks().size(); ++b) {
    const Plan_block& k = plan.blocks()[b];
    os << "  block " << b << ": solve " << plan_list(k.equations, equation_names, "f") << " for "
       << (k.variables.empty() ? std::string("(nothing: a check)") : plan_list(k.variables, variable_names, "x"));
    if (!k.inputs.empty()) os << " given " << plan_list(k.inputs, variable_names, "x");
    if (k.dimension() == 1) os << " (a curve)";
    else if (k.dimension() > 1) os << " (dimension " << k.dimension() << ")";
    if (!k.inequalities.empty()) os << "; inequalities " << plan_list(k.inequalities, inequality_names, "g");
    os << "\n";
  }
  if (!plan.over_determined_equations().empty())
    os << "  over-determined part (redundant or conflicting): equations " << plan_list(plan.over_determined_equations(), equation_names, "f")
       << " in variables " << plan_list(plan.over_determined_variables(), variable_names, "x") << "\n";
  if (!plan.under_determined_variables().empty())
    os << "  under-determined part (free): variables " << plan_list(plan.under_determined_variables(), variable_names, "x")
       << (plan.under_determined_equations().empty() ? std::string()
                                                      : " in equations " + plan_list(plan.under_determined_equations(), equation_names, "f"))
       << "\n";
  if (!plan.unused_variables().empty())
    os << "  variables no equation involves: " << plan_list(plan.unused_variables(), variable_names, "x") << "\n";
  if (!plan.unattached_inequalities().empty())
    os << "  inequalities no block can test: " << plan_list(plan.unattached_inequalities(), inequality_names, "g") << "\n";
}

/*!
\ingroup PkgRigidIncidenceIO
\brief `plan` as JSON: {structure, blocks: [{equations: [indices], variables: [names],
inputs: [names], inequalities: [indices], depends_on: [block indices], dimension}], order:
[block indices in the order of solving], left_out, over_determined: {equations, variables},
under_determined: {equations, variables}, unused_variables, unattached_inequalities}.
*/
inline nlohmann::ordered_json plan_to_json(const Solution_plan& plan, const std::vector<std::string>& variable_names = {})
{
  auto names = [&](const std::vector<std::size_t>& v) {
    nlohmann::ordered_json a = nlohmann::ordered_json::array();
    for (std::size_t j : v) a.push_back(internal::plan_name(variable_names, j, "x"));
    return a;
  };
  nlohmann::ordered_json j;
  j["structure"] = internal::plan_structure_name(plan.structure());
  nlohmann::ordered_json blocks = nlohmann::ordered_json::array(), order = nlohmann::ordered_json::array();
  for (std::size_t b = 0; b < plan.blocks().size(); ++b) {
    const Plan_block& k = plan.blocks()[b];
    blocks.push_back({{"equations", k.equations},
                      {"variables", names(k.variables)},
                      {"inputs", names(k.inputs)},
                      {"inequalities", k.inequalities},
                      {"depends_on", k.depends_on},
                      {"dimension", k.dimension()}});
    order.push_back(b);
  }
  j["blocks"] = blocks;
  j["order"] = order;
  j["left_out"] = plan.left_out_variable() == Solution_plan::none ? nlohmann::ordered_json(nullptr)
                                                                  : nlohmann::ordered_json(internal::plan_name(variable_names, plan.left_out_variable(), "x"));
  j["over_determined"] = {{"equations", plan.over_determined_equations()}, {"variables", names(plan.over_determined_variables())}};
  j["under_determined"] = {{"equations", plan.under_determined_equations()}, {"variables", names(plan.under_determined_variables())}};
  j["unused_variables"] = names(plan.unused_variables());
  j["unattached_inequalities"] = plan.unattached_inequalities();
  return j;
}

/*!
\ingroup PkgRigidIncidenceIO
\brief Writes `plan` in Graphviz DOT: the variable-constraint graph (Definition 3.4), equations
as boxes, variables as ellipses, one cluster per block labelled with its place in the order;
matched pairs bold, the other incidences (a variable used as an input, or within a block) thin;
arrows between blocks point the way information flows.
*/
inline void write_plan_dot(std::ostream& os, const Solution_plan& plan, const std::vector<std::string>& variable_names = {},
                           const std::vector<std::string>& equation_names = {})
{
  using internal::dot_escape;
  using internal::dot_quote;
  os << "digraph plan {\n  label=" << dot_quote("solution plan: " + std::to_string(plan.blocks().size()) + " block(s), largest " +
                                                std::to_string(plan.largest_block()) + " (bold: matched pairs)")
     << ";\n  compound=true; node [fontname=Helvetica]; edge [fontname=Helvetica, arrowhead=none];\n";
  for (std::size_t b = 0; b < plan.blocks().size(); ++b) {
    const Plan_block& k = plan.blocks()[b];
    os << "  subgraph cluster_" << b << " {\n    label=" << dot_quote("block " + std::to_string(b) + (k.dimension() == 1 ? " (curve)" : ""))
       << "; style=rounded;\n";
    for (std::size_t i : k.equations)
      os << "    e" << i << " [shape=box, label=" << dot_quote(dot_escape(internal::plan_name(equation_names, i, "f"))) << "];\n";
    for (std::size_t v : k.variables)
      os << "    v" << v << " [shape=ellipse, label=" << dot_quote(dot_escape(internal::plan_name(variable_names, v, "x"))) << "];\n";
    os << "  }\n";
  }
  for (std::size_t v = 0; v < plan.number_of_variables(); ++v)
    if (plan.block_of_variable(v) == Solution_plan::none)
      os << "  v" << v << " [shape=ellipse, style=dashed, label=" << dot_quote(dot_escape(internal::plan_name(variable_names, v, "x"))) << "];\n";
  for (std::size_t i = 0; i < plan.number_of_equations(); ++i)
    for (std::size_t v : plan.equation_variables(i)) {
      const bool matched = plan.matched_variable(i) == v;
      const bool input = plan.block_of_variable(v) != plan.block_of_equation(i);
      // an input points from the block that solves it to the equation that uses it
      os << "  v" << v << " -> e" << i << " [" << (matched ? "style=bold" : input ? "arrowhead=normal, color=gray40" : "color=gray60") << "];\n";
    }
  os << "}\n";
}

} // namespace Rigid_incidence
} // namespace CGAL

#endif
