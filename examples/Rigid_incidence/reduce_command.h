// Copyright (c) 2026 Rigid_incidence contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// `rigid_incidence reduce`: the reduced polynomial system of a scene, as text or JSON.

#ifndef RIGID_INCIDENCE_EXAMPLES_REDUCE_COMMAND_H
#define RIGID_INCIDENCE_EXAMPLES_REDUCE_COMMAND_H

#include <CGAL/Rigid_incidence.h>

#include "solve_command.h"

#include <nlohmann/json.hpp>

#include <iostream>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

namespace reduce_command {

namespace RI = CGAL::Rigid_incidence;

// "0,1,3" -> {0, 1, 3}; an Input_error names what is wrong
inline std::vector<int> parse_charts(const std::string& s)
{
  std::vector<int> out;
  if (s.empty()) return out;
  std::stringstream in(s);
  std::string item;
  while (std::getline(in, item, ',')) {
    if (item.empty() || item.find_first_not_of("0123456789") != std::string::npos || item.size() > 3)
      throw RI::Input_error("--chart: '" + item + "' is not a chart index (expected e.g. --chart 0,1,3)");
    out.push_back(std::stoi(item));
  }
  return out;
}

template <class NT> nlohmann::ordered_json coefficient_json(const NT& x)
{
  if constexpr (std::is_same<NT, CGAL::Gmpq>::value) {
    std::ostringstream os;
    os << x;
    return os.str();
  } else {
    std::pair<double, double> i = CGAL::to_interval(x);
    return nlohmann::ordered_json::array({i.first, i.second});
  }
}

template <class Traits, class NT>
int print(const RI::Rigid_body_collection<Traits>& c, const RI::Incidence_tree& t, const RI::Well_formed_selection& s,
          const std::vector<int>& charts, RI::Rotation_form form, bool json, const std::string& scene_file, long naive,
          const std::string& coefficients)
{
  RI::internal::Rounding_guard<NT> guard;
  (void)guard;
  RI::Reduced_system<Traits, NT> r(c, t, s, charts, form);
  // what a full solve would cost (not estimated: why)
  std::string work_note;
  const std::optional<RI::Scene_solve_work> work = solve_command::estimate_work(c, t, s, work_note);
  const auto& p = r.parametrization();
  const auto& names = p.variable_names();
  // the tree edge (child body) or free point each variable belongs to
  std::vector<std::string> owner(names.size());
  for (const auto& e : p.edges()) {
    std::string what = c.body(e.parent).name + " -> " + c.body(e.child).name;
    for (std::size_t v : e.rotation) owner[v] = what;
    for (std::size_t v : e.translation) owner[v] = what;
  }
  for (std::size_t i = 0; i < names.size(); ++i) if (owner[i].empty()) owner[i] = "free point";
  if (json) {
    nlohmann::ordered_json j;
    j["scene"] = scene_file;
    j["coefficients"] = coefficients;
    j["rotation_form"] = form == RI::Rotation_form::STEREOGRAPHIC ? "stereographic" : "quaternion charts";
    nlohmann::ordered_json vars = nlohmann::ordered_json::array();
    for (std::size_t i = 0; i < names.size(); ++i)
      vars.push_back({{"name", names[i]}, {"edge", owner[i]}, {"box", {p.box()[i].first, p.box()[i].second}}});
    j["variables"] = vars;
    nlohmann::ordered_json charts_j = nlohmann::ordered_json::array();
    for (const auto& e : p.edges()) charts_j.push_back({{"edge", {c.body(e.parent).name, c.body(e.child).name}}, {"chart", e.chart},
                                                         {"charts", e.number_of_charts}});
    j["charts"] = charts_j;
    j["chart_combinations"] = r.number_of_chart_combinations();
    if (work) j["work"] = solve_command::work_json(*work);
    else j["work"] = {{"skipped", work_note}};
    nlohmann::ordered_json eqs = nlohmann::ordered_json::array();
    for (const auto& e : r.equations()) {
      std::vector<std::string> vn;
      for (std::size_t v : e.variables) vn.push_back(names[v]);
      nlohmann::ordered_json terms = nlohmann::ordered_json::array();
      for (const auto& term : e.polynomial.terms()) terms.push_back({coefficient_json(term.second), term.first});
      eqs.push_back({{"origin", e.label}, {"frame", c.body(e.frame).name}, {"variables", vn}, {"degrees", e.degrees},
                     {"total_degree", e.total_degree}, {"terms", terms}});
    }
    j["equations"] = eqs;
    std::vector<std::string> left;
    for (const auto& k : r.left_out()) left.push_back(RI::describe(c, k));
    j["left_out"] = left;
    j["square"] = r.is_square();
    j["diagnostic"] = r.diagnostic();
    j["naive_variables"] = naive;
    std::cout << j.dump(2) << "\n";
    return 0;
  }
  std::cout << "reduced system of " << scene_file << " (" << coefficients << " coefficients, "
            << (form == RI::Rotation_form::STEREOGRAPHIC ? "the papers' stereographic form" : "homogeneous quaternion charts")
            << "): " << r.number_of_variables() << " variables, " << r.number_of_equations()
            << " equations; the naive formulation has 6(k-1) = " << naive << " variables\n";
  std::cout << "\nvariables (box; tree edge):\n";
  for (std::size_t i = 0; i < names.size(); ++i)
    std::cout << "  " << names[i] << "  [" << p.box()[i].first << ", " << p.box()[i].second << "]  " << owner[i] << "\n";
  std::cout << "charts:";
  for (const auto& e : p.edges()) std::cout << " " << c.body(e.child).name << "=" << e.chart << "/" << e.number_of_charts;
  std::cout << "  (" << r.number_of_chart_combinations() << " chart combination" << (r.number_of_chart_combinations() == 1 ? "" : "s") << ")\n";
  // (a solve uses the quaternion charts, whatever --form shows here)
  if (work) std::cout << "work of a full solve" << (form == RI::Rotation_form::STEREOGRAPHIC ? " (in quaternion charts)" : "") << ": "
                      << RI::internal::describe_work(*work) << "\n";
  else std::cout << "work of a full solve: not estimated (" << work_note << ")\n";
  std::cout << "\nequations:\n";
  for (std::size_t k = 0; k < r.equations().size(); ++k) {
    const auto& e = r.equations()[k];
    std::cout << "  f" << k + 1 << ": " << e.label << "  (frame " << c.body(e.frame).name << "; degree";
    for (std::size_t i = 0; i < e.variables.size(); ++i) std::cout << " " << names[e.variables[i]] << "^" << e.degrees[i];
    std::cout << ", total " << e.total_degree << ", " << e.polynomial.terms().size() << " terms)\n      ";
    e.polynomial.write(std::cout, names);
    std::cout << " = 0\n";
  }
  if (!r.is_square()) std::cout << "\nnote: " << r.diagnostic() << "\n";
  return 0;
}

// exact coefficients when every body of the covering set has coordinates, else intervals
template <class Traits>
int reduce(const RI::Rigid_body_collection<Traits>& c, const RI::Incidence_tree& t, const RI::Well_formed_selection& s,
           const std::string& chart_text, const std::string& form_text, std::string coefficients, bool json,
           const std::string& scene_file, long naive)
{
  const std::vector<int> charts = parse_charts(chart_text);
  RI::Rotation_form form = RI::Rotation_form::QUATERNION_CHARTS;
  if (form_text == "stereographic") form = RI::Rotation_form::STEREOGRAPHIC;
  else if (!form_text.empty() && form_text != "charts")
    throw RI::Input_error("--form: '" + form_text + "' (expected charts or stereographic)");
  if (coefficients.empty() || coefficients == "auto") {
    coefficients = RI::exact_coefficients(c, t) ? "exact" : "interval";
  }
  if (coefficients == "exact") return print<Traits, CGAL::Gmpq>(c, t, s, charts, form, json, scene_file, naive, coefficients);
  if (coefficients == "interval")
    return print<Traits, CGAL::Interval_nt<false>>(c, t, s, charts, form, json, scene_file, naive, coefficients);
  throw RI::Input_error("--coefficients: '" + coefficients + "' (expected auto, exact or interval)");
}

} // namespace reduce_command

#endif
