// Copyright (c) 2026 Rigid_incidence contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// `rigid_incidence solve-system`: every real root of a polynomial system given as text
// (PHCpack's input format plus box and inequality lines), solved along its solution plan.

#ifndef RIGID_INCIDENCE_EXAMPLES_SYSTEM_COMMAND_H
#define RIGID_INCIDENCE_EXAMPLES_SYSTEM_COMMAND_H

#include <CGAL/Rigid_incidence.h>
#include <CGAL/Rigid_incidence/IO/read_polynomial_system.h>
#include <CGAL/Rigid_incidence/IO/write_plan.h>

#include <nlohmann/json.hpp>

#include "solve_command.h"

#include <chrono>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

namespace system_command {

namespace RI = CGAL::Rigid_incidence;

struct System_options
{
  solve_command::Solve_options solve;  // tolerance, precision, fast, max_boxes
  bool json = false;
  bool no_plan = false;  // solve the whole system at once (for comparison)
  std::string dot;       // write the plan in Graphviz DOT here
};

template <class IT>
nlohmann::ordered_json interval_json(const IT& x)
{
  typedef RI::internal::Interval_ops<IT> O;
  return nlohmann::ordered_json::array({O::lower_double(x), O::upper_double(x)});
}

// the undecomposed solver's or the tracer's regions, in the plan result's shape
template <class IT>
void add_unresolved(RI::Plan_result<IT>& r, const std::vector<RI::Solver_unresolved<IT>>& regions)
{
  for (const auto& u : regions) {
    RI::Plan_unresolved<IT> v;
    v.kind = u.kind;
    v.reason = u.reason;
    v.box = u.box;
    r.unresolved.push_back(v);
  }
}

template <class IT>
int run(const RI::Polynomial_system_file& file, const RI::Solution_plan& plan, const System_options& o, const std::string& path,
        double read_seconds)
{
  const RI::Polynomial_system<CGAL::Gmpq>& sys = file.system;
  RI::Subdivision_solver_parameters p;
  p.tolerance = o.solve.tolerance;
  p.precision = o.solve.precision;
  p.fast = o.solve.fast;
  p.threads = o.solve.threads;
  if (o.solve.max_boxes > 0) p.maximal_boxes = o.solve.max_boxes;
  const auto t0 = std::chrono::steady_clock::now();
  std::string diagnosis;
  RI::Plan_result<IT> r;
  RI::Curve_result<IT> curves;
  bool traced = false, along_plan = false;
  if (o.no_plan) {
    // the undecomposed solver, in the same result shape
    r = RI::internal::plan_result_of_solver(RI::Subdivision_solver<IT>(p).solve(sys),
                                            RI::internal::Interval_ops<IT>::multiprecision ? p.precision : 53);
  } else if (plan.structure() == RI::Solution_plan::WELL_CONSTRAINED) {
    r = RI::solve_with_plan<IT>(sys, plan, p);
  } else if (plan.structure() == RI::Solution_plan::ONE_DEGREE_OF_FREEDOM && sys.number_of_equations() + 1 == sys.number_of_variables() &&
             !o.solve.fast) {
    // one equation fewer than variables: the solution set is a curve
    RI::Curve_tracer_parameters cp;
    cp.precision = o.solve.precision;
    cp.tolerance = (std::max)(o.solve.tolerance, 1e-10);
    if (o.solve.max_boxes > 0) cp.maximal_boxes = o.solve.max_boxes;
    // the whole system at once; when the plan has one curve block and square blocks
    // otherwise (Jansen's linkage: the crank, then one point at a time), with at most 20000
    // boxes, and along the plan if that runs out (the whole-system tracer resolves what the
    // lifting cannot, folds of a later block, but not 12 variables)
    // (a plan whose blocks all merge into the curve block has nothing to lift)
    bool plan_form = false;
    try {
      plan_form = RI::internal::curve_block_first(plan).size() > 1;
    } catch (const RI::Input_error&) {
      plan_form = false;  // not one curve block and square blocks
    }
    RI::Curve_tracer_parameters first = cp;
    if (plan_form) first.maximal_boxes = (std::min<std::size_t>)(first.maximal_boxes, 20000);
    curves = RI::trace_curves<IT>(sys, first);
    if (plan_form && std::any_of(curves.unresolved.begin(), curves.unresolved.end(),
                                 [](const RI::Solver_unresolved<IT>& u) { return u.kind == RI::Box_class::PENDING; })) {
      curves = RI::trace_curves_with_plan<IT>(sys, plan, cp, p);
      along_plan = true;
    }
    traced = true;
    r.block_solves = curves.statistics.block_solves;
    add_unresolved(r, curves.unresolved);
  } else {
    // read, but not a system with isolated roots: say what it is
    std::ostringstream d;
    if (plan.structure() == RI::Solution_plan::ONE_DEGREE_OF_FREEDOM || plan.structure() == RI::Solution_plan::UNDER_CONSTRAINED)
      d << "under_determined: free variables";
    else
      d << "over_determined: equations";
    const auto& part = plan.over_determined_equations().empty() ? plan.under_determined_variables() : plan.over_determined_equations();
    for (std::size_t k : part) d << " " << (plan.over_determined_equations().empty() ? sys.variable_names[k] : std::to_string(k + 1));
    if (plan.structure() == RI::Solution_plan::ONE_DEGREE_OF_FREEDOM)
      d << "; the solution set is a curve" << (o.solve.fast ? ", which --fast does not trace" : ", traced only when there is one equation fewer than variables");
    diagnosis = d.str();
  }
  if (diagnosis.empty()) diagnosis = r.diagnosis;
  const double solve_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  std::size_t certified = 0;
  for (const auto& x : r.roots) certified += x.certified;
  const bool complete = diagnosis.empty() && r.complete() && !o.solve.fast && (!traced || curves.complete());
  if (!o.dot.empty()) {
    std::ofstream out(o.dot);
    if (!out) throw RI::Input_error("cannot write '" + o.dot + "'");
    RI::write_plan_dot(out, plan, sys.variable_names, sys.labels);
  }
  if (o.json) {
    nlohmann::ordered_json j;
    j["system"] = path;
    j["title"] = file.title;
    j["variables"] = sys.variable_names;
    nlohmann::ordered_json box = nlohmann::ordered_json::array();
    for (const auto& b : sys.box) box.push_back({b.first, b.second});
    j["box"] = box;
    j["default_box"] = file.default_box;
    j["plan"] = RI::plan_to_json(plan, sys.variable_names);
    j["complete"] = complete;
    j["diagnosis"] = diagnosis.empty() ? nlohmann::ordered_json(nullptr) : nlohmann::ordered_json(diagnosis);
    nlohmann::ordered_json sols = nlohmann::ordered_json::array();
    for (const auto& x : r.roots) {
      nlohmann::ordered_json values, enclosure;
      for (std::size_t k = 0; k < sys.variable_names.size(); ++k) {
        values[sys.variable_names[k]] = x.approximation[k];
        enclosure[sys.variable_names[k]] = interval_json(x.enclosure[k]);
      }
      sols.push_back({{"certified", x.certified},
                      {"values", values},
                      {"enclosure", enclosure},
                      {"on_boundary", x.on_boundary},
                      {"on_inequality_boundary", x.on_inequality_boundary},
                      {"precision", x.precision}});
    }
    j["solutions"] = sols;
    nlohmann::ordered_json un = nlohmann::ordered_json::array();
    for (const auto& u : r.unresolved) {
      nlohmann::ordered_json b;
      for (std::size_t k = 0; k < sys.variable_names.size() && k < u.box.size(); ++k) b[sys.variable_names[k]] = interval_json(u.box[k]);
      un.push_back({{"class", u.kind == RI::Box_class::PENDING ? "pending" : "unknown"}, {"reason", u.reason}, {"block", traced ? nlohmann::ordered_json(nullptr) : nlohmann::ordered_json(u.block)}, {"box", b}});
    }
    j["unresolved"] = un;
    nlohmann::ordered_json cj = nlohmann::ordered_json::array();
    for (const auto& c : curves.curves) {
      nlohmann::ordered_json ends = nlohmann::ordered_json::array(), regions = nlohmann::ordered_json::array();
      for (int e = 0; e < 2; ++e) {
        ends.push_back(solve_command::curve_end_name(c.ends[e]));
        regions.push_back(c.end_region[e] < 0 ? nlohmann::ordered_json(nullptr) : nlohmann::ordered_json(c.end_region[e]));
      }
      cj.push_back({{"certified", c.certified},
                    {"closed", c.closed},
                    {"ends", ends},
                    {"end_regions", regions},
                    {"on_inequality_boundary", c.on_inequality_boundary},
                    {"max_residual", c.max_residual},
                    {"points", c.points}});
    }
    j["curves"] = cj;
    j["stats"] = {{"blocks", plan.blocks().size()},
                  {"largest_block", plan.largest_block()},
                  {"block_solves", r.block_solves},
                  {"threads", RI::internal::worker_threads(o.solve.threads)},
                  {"boxes", r.boxes},
                  {"krawczyk_tests", r.krawczyk_tests},
                  {"refinements", r.refinements},
                  {"refinements_sparse", r.refinements_sparse},
                  {"refinements_multiprecision", r.refinements_multiprecision},
                  {"refinements_wider_than_tolerance", r.refinements_failed},
                  {"curve_traced_along_plan", along_plan},
                  {"curve_boxes", curves.statistics.boxes},
                  {"face_solves", curves.statistics.face_solves},
                  {"seconds", {{"read", read_seconds}, {"solve", solve_seconds}}}};
    std::cout << std::setw(2) << j << "\n";
    return 0;
  }
  std::cout << "system " << path << (file.title.empty() ? std::string() : " (" + file.title + ")") << ": " << sys.number_of_equations()
            << " equations in " << sys.number_of_variables() << " variables";
  if (!sys.inequalities.empty()) std::cout << ", " << sys.inequalities.size() << " inequalities";
  std::cout << "\n  box:";
  for (std::size_t k = 0; k < sys.variable_names.size(); ++k)
    std::cout << " " << sys.variable_names[k] << " in [" << sys.box[k].first << ", " << sys.box[k].second << "]";
  std::cout << (file.default_box ? " (default box: give 'box' lines to change it)" : "") << "\n";
  RI::write_plan_text(std::cout, plan, sys.variable_names, sys.labels, sys.inequality_labels);
  if (!diagnosis.empty()) std::cout << "diagnosis: " << diagnosis << "\n";
  if (traced)
    std::cout << "the solution set is a curve, traced " << (along_plan ? "along the plan (block 1, then the others lifted over it)" : "as a whole")
              << "; " << (complete ? "complete" : "NOT complete") << "\n";
  else std::cout << r.roots.size() << " real root(s) in the box, " << certified << " certified; " << (complete ? "complete" : "NOT complete") << "\n";
  std::cout << std::setprecision(15);
  for (std::size_t i = 0; i < r.roots.size(); ++i) {
    const auto& x = r.roots[i];
    std::cout << "  " << i + 1 << (x.certified ? " certified:" : " approximate:");
    for (std::size_t k = 0; k < sys.variable_names.size(); ++k) std::cout << " " << sys.variable_names[k] << " = " << x.approximation[k];
    if (x.on_boundary) std::cout << " (on the box boundary)";
    if (x.on_inequality_boundary) std::cout << " (on an inequality's boundary)";
    std::cout << "\n";
  }
  if (traced) {
    std::size_t certified_branches = 0;
    for (const auto& c : curves.curves) certified_branches += c.certified;
    std::cout << curves.curves.size() << " curve branch(es), " << certified_branches << " with certified topology; " << curves.unresolved.size()
              << " unresolved region(s)\n";
    for (std::size_t i = 0; i < curves.curves.size(); ++i) {
      const auto& c = curves.curves[i];
      std::cout << "  branch " << i + 1 << (c.certified ? " (certified)" : " (not certified)") << ": " << c.points.size() << " points, ";
      if (c.closed) std::cout << "closed";
      else std::cout << "from " << solve_command::curve_end_name(c.ends[0]) << " to " << solve_command::curve_end_name(c.ends[1]);
      std::cout << ", max residual " << c.max_residual << (c.on_inequality_boundary ? ", clipped by an inequality" : "") << "\n";
    }
  }
  for (const auto& u : r.unresolved) {
    std::cout << "  unresolved (" << (u.kind == RI::Box_class::PENDING ? "pending" : "unknown");
    if (!traced) std::cout << ", block " << u.block;
    std::cout << "): " << u.reason << "\n";
  }
  std::cout << std::setprecision(6) << "stats: " << r.block_solves << " block solve(s), " << r.boxes << " boxes, " << r.krawczyk_tests
            << " Krawczyk tests, " << solve_seconds << " s\n";
  if (r.refinements_sparse > 0)
    std::cout << "  " << r.refinements_sparse << " root(s) tightened by the whole system's sparse Krawczyk test, " << r.refinements_multiprecision
              << " of them in more than double precision, " << r.refinements_failed << " left wider than the tolerance\n";
  return 0;
}

inline int solve_system(const std::string& path, const System_options& o)
{
  const auto t0 = std::chrono::steady_clock::now();
  RI::Polynomial_system_file file = RI::read_polynomial_system(path);
  RI::Solution_plan plan(file.system);
  const double read_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  if (o.solve.precision > 53) {
#ifdef CGAL_USE_MPFI
    return run<CGAL::Gmpfi>(file, plan, o, path, read_seconds);
#else
    throw RI::Input_error("--precision above 53 needs MPFI (CGAL::Gmpfi), which this build does not have");
#endif
  }
  return run<CGAL::Interval_nt<false>>(file, plan, o, path, read_seconds);
}

} // namespace system_command

#endif
