// Copyright (c) 2026 Rigid_incidence contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The command-line tool: rigid_incidence analyze SCENE.json [--json] [--dot FILE] [--kernel K]

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Gmpq.h>
#include <CGAL/Rigid_incidence.h>

#include <nlohmann/json.hpp>

#include "reduce_command.h"
#include "solve_command.h"
#include "family_command.h"
#include "system_command.h"

#include <chrono>

#include <algorithm>
#include <cerrno>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <optional>
#include <string>
#include <vector>

namespace RI = CGAL::Rigid_incidence;

static const char* usage_text =
  "rigid_incidence: every real configuration of a scene of rigid bodies sharing points.\n"
  "\n"
  "Usage:\n"
  "  rigid_incidence analyze SCENE.json [--json] [--dot FILE] [--dot-seam FILE]\n"
  "                          [--kernel exact|epick|epeck]\n"
  "  rigid_incidence reduce SCENE.json [--json] [--chart I,J,...] [--form charts|stereographic]\n"
  "                         [--coefficients auto|exact|interval] [--kernel exact|epick|epeck]\n"
  "  rigid_incidence solve SCENE.json [--json] [--tolerance EPS] [--precision BITS] [--fast]\n"
  "                        [--svg FILE] [--plot A.x,B.z] [--near CONFIG.json] [--max-boxes N]\n"
  "                        [--max-seconds S] [--quiet] [--no-plan] [--no-sweep] [--threads N]\n"
  "                        [--no-propagation] [--no-consistency] [--max-listed N]\n"
  "                        [--kernel K]\n"
  "  rigid_incidence family SCENE.json [--json] [--svg FILE] [--samples K] [--tolerance EPS]\n"
  "                        [--precision BITS] [--max-boxes N] [--kernel K]\n"
  "  rigid_incidence solve-system FILE [--json] [--tolerance EPS] [--precision BITS] [--fast]\n"
  "                        [--max-boxes N] [--dot FILE] [--no-plan] [--threads N]\n"
  "  rigid_incidence --help\n"
  "\n"
  "Commands:\n"
  "  analyze   Read a scene (format \"rigid-incidence-scene/1\"), standardize it (merge bodies\n"
  "            sharing 3 or more points, add implied bodies, absorb what is not proper-maximal),\n"
  "            count its degrees of freedom, build the overlap graph and the optimal incidence\n"
  "            tree, select a well-formed set of incidences that contains the tree's (the\n"
  "            Optimal Well-formed Incidence Selection Algorithm), rank the system's\n"
  "            constraints in the rigidity matroid at a random realization (generic dof,\n"
  "            the distances holding bodies outside the covering set, the constraints in\n"
  "            conflict when the scene is over-constrained), and print the number of\n"
  "            variables and equations of the reduced system next to the\n"
  "            6(k-1) of the naive formulation (a free rigid motion for each of the k bodies\n"
  "            of the scene, one of them fixed).\n"
  "\n"
  "  family    A scene with a free distance (\"free_distance\": {\"between\": [\"A\", \"B\"],\n"
  "            \"range\": [smallest, largest]}, or [\"A\", \"B\"] for the range 0 to a bound of\n"
  "            every distance in the scene) as a family: its configurations traced as curves\n"
  "            over the length of A-B (the squared length one more variable; certified\n"
  "            topology), the folds where the number of configurations changes (roots of\n"
  "            {F = 0, det(dF/dx) = 0}, each length in a certified interval), and the number\n"
  "            of configurations between folds. --svg FILE: the gallery (configurations at\n"
  "            --samples K lengths, default 6, grouped by branch) and a plot of each body's\n"
  "            rotation since the first frame against the length, folds dashed. --json: {scene,\n"
  "            free_distance {between, range, range_given}, variables, complete, diagnosis,\n"
  "            folds [{length [lo, hi], certified, change, max_residual, charts,\n"
  "            found_in_charts, points}], counts [{from, to, count}], branches [{certified,\n"
  "            closed, ends, max_residual, lengths, points {label: [[x, y, z], ...]}, pieces\n"
  "            [{charts, parameters}]}], unresolved, stats}. `solve` on such a scene solves it\n"
  "            without the free distance (curves of configurations).\n"
  "\n"
  "  reduce    The reduced polynomial system of the scene: its variables (the parameters of\n"
  "            the incidence tree's edges: a hinge's t or s, three quaternion components of a\n"
  "            free rotation, a translation; three coordinates per free point) with their\n"
  "            boxes, and its equations with their origin, degrees and terms. --chart picks\n"
  "            one chart per tree edge (default all 0; 2 charts per hinge, 4 per free\n"
  "            rotation); --form stereographic gives the papers' form instead; coefficients\n"
  "            are exact rationals when every body of the covering set has coordinates,\n"
  "            else certified intervals. --json: {variables [{name, edge, box}], charts,\n"
  "            chart_combinations, equations [{origin, frame, variables, degrees,\n"
  "            total_degree, terms [[coefficient, [exponents]]...]}], left_out, square,\n"
  "            diagnostic, naive_variables}; a coefficient is an exact string (\"p/q\") or an\n"
  "            interval [lo, hi].\n"
  "\n"
  "  solve     Every real configuration of the scene: the reduced system is solved in every\n"
  "            chart combination by the certified interval Bernstein subdivision solver, each\n"
  "            root turned into a configuration (a rotation and translation per body, world\n"
  "            coordinates per point in the scene's frame body) and checked in the original,\n"
  "            unreduced system; roots found in two charts are merged. A configuration is\n"
  "            'certified' when a Krawczyk test proved one root in its box. What could not be\n"
  "            decided is listed as unresolved regions (unknown: e.g. a possible multiple\n"
  "            root; pending: the box budget ran out), and the result says 'complete' only\n"
  "            when there is none. --tolerance EPS (default 1e-12): width of the parameter\n"
  "            enclosures; --precision BITS (default 53: double intervals; more: MPFI);\n"
  "            --fast: double precision, Newton polish, nothing certified; --max-boxes N per\n"
  "            chart combination (default 200000); --max-seconds S: a time limit for the\n"
  "            whole solve (what is not done by then is reported, the answer not complete);\n"
  "            a progress line on standard error when it is a terminal (--quiet: none);\n"
  "            a reduced system of several blocks (its solution plan) is solved block after\n"
  "            block (--no-plan: whole, for comparison); a chain of hinges braced by near\n"
  "            distances (64 chart combinations or more) is solved along its tree by one\n"
  "            sweep, nothing expanded (--no-sweep: per chart combination, for comparison);\n"
  "            before the sweep and the propagation, arc consistency keeps the parts of\n"
  "            each hinge's circle the equations in two hinges allow (--no-consistency:\n"
  "            none, for comparison);\n"
  "            the charts of a tree of hinges are first chosen by propagating the\n"
  "            equations along it, and combinations it excludes are never built\n"
  "            (--no-propagation: every combination, for comparison);\n"
  "            a reduced system of independent parts (no equation, inequality or tree edge\n"
  "            joins them) is answered\n"
  "            factored: each part's solutions, the configurations their product, counted\n"
  "            exactly and listed up to --max-listed N (default 10000; 0: all);\n"
  "            --threads N: threads for the\n"
  "            independent pieces (chart combinations, branches of a plan; default: every\n"
  "            core; 1: sequential), the same answer in the same order with any number;\n"
  "            Ctrl-C (SIGINT) or SIGTERM stops the solve and prints the partial answer,\n"
  "            incomplete, with exit status 130 or 143; --svg FILE: the configurations side by\n"
  "            side as line drawings; --near CONFIG.json: order the configurations by their\n"
  "            distance to a given one ({\"points\": {label: [x, y, z]}} or a solve --json\n"
  "            output; the configurations listed: see --max-listed). --json: {scene, analysis, reduced_system {variables, equations},\n"
  "            complete, certified, diagnosis, configuration_count, listing (null, or why\n"
  "            the list stops), unlisted_not_certified, parts [{placements, bodies, variables, count, unresolved,\n"
  "            solutions [{certified, charts, found_in_charts, parameters}]}] (a factored\n"
  "            answer; else []), solutions [{certified, parameters, charts,\n"
  "            bodies {name: {rotation, translation}}, points {label: [x, y, z]},\n"
  "            max_residual}], unresolved [{class, reason, box, boxes, charts, points}],\n"
  "            curves, stats}. A scene with one degree of freedom (one equation fewer than\n"
  "            parameters), or one the dof count calls finite whose solver finds a curve of\n"
  "            solutions (it flexes), gives curves of configurations: traced per chart\n"
  "            combination with certified topology and joined across chart borders; curves\n"
  "            [{certified, closed, ends, note, max_residual, points {label: [[x, y, z],\n"
  "            ...]}, pieces [{charts, parameters}]}]. With curves, --svg draws each branch as\n"
  "            a strip of frames and a plot of two point coordinates (--plot A.x,B.z; default:\n"
  "            the point that moves most).\n"
  "\n"
  "  solve-system  Every real root of a polynomial system in a box. FILE is PHCpack's input\n"
  "            format (the number of equations [and of variables], then the polynomials, each\n"
  "            ending with ';'; coefficients read exactly, '^' or '**' for powers), followed\n"
  "            by optional lines PHCpack ignores: 'box NAME LO HI', 'box * LO HI' (default\n"
  "            [-10, 10] for every variable) and 'inequality EXPR >= 0;'. The system is\n"
  "            decomposed into blocks (its solution plan: matching, strongly connected\n"
  "            components, Dulmage-Mendelsohn parts when it is not square) solved one after\n"
  "            the other, each root substituted as a certified enclosure into the blocks after\n"
  "            it, then refined on the whole system. --dot FILE: the plan in Graphviz DOT;\n"
  "            --no-plan: solve the whole system at once (for comparison). --json: {system,\n"
  "            title, variables, box, default_box, plan {structure, blocks [{equations,\n"
  "            variables, inputs, inequalities, depends_on, dimension}], order, left_out,\n"
  "            over_determined, under_determined}, complete, diagnosis, solutions [{certified,\n"
  "            values {variable: value}, enclosure {variable: [lo, hi]}, on_boundary,\n"
  "            on_inequality_boundary}], unresolved [{class, reason, block, box}], curves\n"
  "            [{certified, closed, ends, end_regions, on_inequality_boundary, max_residual,\n"
  "            points}], stats}. One equation fewer than variables (one degree of freedom):\n"
  "            the solution curve is traced whole, or along the plan when it has one curve\n"
  "            block, square blocks otherwise, and the whole-system tracer does not\n"
  "            finish in 20000 boxes (Jansen's linkage), each\n"
  "            branch a polyline with certified topology; singular points of the curve (and,\n"
  "            along a plan, folds that cannot be traced whole) are unresolved\n"
  "            regions where branches\n"
  "            end (\"ends\": closed, boundary, unresolved, inequality). Other systems that are\n"
  "            not well-constrained are read and their plan printed, with a diagnosis naming\n"
  "            the free variables or the conflicting equations.\n"
  "\n"
  "Options:\n"
  "  --json         print the analysis as JSON on standard output instead of text; keys:\n"
  "                 scene, bodies (each with name, origin, points, sources, placements),\n"
  "                 implied_bodies, standardization, remaining_distances, dof,\n"
  "                 overlap_graph,\n"
  "                 covering_set, non_covering, incidence_tree {root, edges [[parent, child,\n"
  "                 weight]], weight, distance_path_sum, depth_sum, proven_optimal,\n"
  "                 strategy}, optimal_trees_tied,\n"
  "                 reduced_variables, naive_variables, well_formed_incidences (each\n"
  "                 {point, bodies: [a, b], coordinates: [1,2,3] or [1,2], role: \"tree\" |\n"
  "                 \"remaining\"}), redundant_incidences (each {point, bodies,\n"
  "                 coordinates, point_seam_cycle and/or seam_cycle: the cycle its edge\n"
  "                 closes, as point@body copies}), rigidity_matroid {variables,\n"
  "                 rank, generic_dof, seed, method}, body_distances (each {body, between:\n"
  "                 [a, b]}: the distances that hold a body outside the covering set),\n"
  "                 conflicts (each {constraint, depends_on: [...]}: constraints the others\n"
  "                 already fix), reduced_equations\n"
  "  --dot FILE     write the overlap graph in Graphviz DOT to FILE, the tree highlighted\n"
  "                 (render with: dot -Tsvg FILE -o graph.svg)\n"
  "  --dot-seam FILE write the seam graph of the tree's bodies in Graphviz DOT to FILE,\n"
  "                 the chosen seam tree highlighted\n"
  "  --kernel K     number type of the coordinates: exact (default; CGAL::Simple_cartesian\n"
  "                 over Gmpq, every check exact), epeck (CGAL's exact-constructions kernel)\n"
  "                 or epick (doubles: scene numbers are rounded to the nearest double and\n"
  "                 consistency checks use a relative tolerance of 1e-9)\n"
  "  --help, -h     print this help\n"
  "\n"
  "Exit status: 0 on success, 1 on a usage error, 2 when the scene is malformed (the message\n"
  "names the file, body, point or field at fault).\n";

struct Options
{
  std::string command = "analyze";
  std::string scene, dot, dot_seam, kernel = "exact";
  std::string charts, form, coefficients;
  bool json = false;
  bool no_plan = false;
  solve_command::Solve_options solve;
  family_command::Family_options family;
};

template <class Traits>
int analyze(const Options& o)
{
  auto t_start = std::chrono::steady_clock::now();
  RI::Scene scene = RI::read_scene(o.scene);
  const RI::Scene as_read = scene;
  Options oo = o;
  if (o.command == "solve") {  // a scene far from unit size is solved at unit size (exactly scaled)
    const long k = solve_command::scene_size_exponent(scene);
    if (k > 20 || k < -20) {
      scene = solve_command::scaled_scene(scene, -k);
      oo.solve.scale_exponent = k;
    }
  }
  RI::Rigid_body_collection<Traits> input = RI::make_collection<Traits>(scene);
  if (o.command == "family") return family_command::family(scene, input, o.family, o.scene);
  std::vector<std::string> log;
  for (const auto& a : input.aliases())
    log.push_back("'" + a.alias + "' and '" + a.label + "' are one point, '" + a.label + "' (" + a.why + ")");
  RI::Rigid_body_collection<Traits> c;
  try {
    c = RI::standardize(input, &log);
  } catch (const RI::No_real_configuration& e) {
    throw RI::No_real_configuration(o.scene + ": " + e.what());
  } catch (const RI::Input_error& e) {
    throw RI::Input_error(o.scene + ": " + e.what());
  }
  RI::Dof_count dof = RI::dof_count(c);
  if (!dof.connected)
    std::cerr << "rigid_incidence: warning: " << o.scene << ": the scene is not connected (" << dof.components.size()
              << " separate parts)\n";
  if (dof.dof != 0)
    std::cerr << "rigid_incidence: warning: " << o.scene << ": " << dof.verdict() << " by the dof count (dof = " << dof.dof
              << ")\n";
  RI::Incidence_tree t = RI::optimal_incidence_tree(c);
  RI::Overlap_graph og(c);
  RI::Well_formed_selection wf = RI::select_well_formed_incidences(c, t);
  if (o.command == "solve" && scene.free_distance.declared)
    std::cerr << "rigid_incidence: note: " << o.scene << ": the distance " << scene.free_distance.a << "-" << scene.free_distance.b
              << " is declared free: solved without it (rigid_incidence family solves the family over its range)\n";
  if (o.command == "solve")
    return solve_command::solve(as_read, input, c, t, wf, dof, oo.solve, o.json, o.scene,
                                std::chrono::duration<double>(std::chrono::steady_clock::now() - t_start).count());
  if (o.command == "reduce")
    return reduce_command::reduce(c, t, wf, o.charts, o.form, o.coefficients, o.json, o.scene, 6 * (long(scene.bodies.size()) - 1));
  RI::Incidence_set redundant = RI::redundant_incidences(c, wf);
  // incidences grouped as the user reads them: per point and pair of bodies, the coordinates
  struct Group { std::size_t point, a, b; std::vector<int> coords; bool tree; };
  auto group = [&](const RI::Incidence_set& set, const std::vector<RI::Well_formed_selection::Role>* roles) {
    std::vector<Group> out;
    std::size_t n = 0;
    for (const RI::Incidence& i : set) {
      bool tree_role = roles && (*roles)[n] == RI::Well_formed_selection::TREE;
      if (!out.empty() && out.back().point == i.point && out.back().a == i.body_a && out.back().b == i.body_b &&
          out.back().tree == tree_role)
        out.back().coords.push_back(i.coordinate);
      else out.push_back(Group{i.point, i.body_a, i.body_b, {i.coordinate}, tree_role});
      ++n;
    }
    return out;
  };
  const std::vector<Group> selected_groups = group(wf.incidences, &wf.roles), redundant_groups = group(redundant, nullptr);
  // Why each redundant incidence was left out (Section 5): coordinates 1 and 2 of an edge
  // that closes a point-seam cycle of F*, coordinate 3 of an edge that closes a seam cycle of
  // the seam tree F1. A cycle is written as the copies (point@body) it passes through.
  const RI::Seam_graph seam(c, wf.bodies);
  auto copies_of = [&](const std::vector<RI::Seam_step>& cyc) {
    std::vector<std::string> out;
    for (const auto& st : cyc) {
      const auto& v = seam.vertices()[st.from];
      out.push_back(c.label(v.point) + "@" + c.body(v.body).name);
    }
    return out;
  };
  struct Reason { std::vector<std::string> point_seam_cycle, seam_cycle; };
  std::vector<Reason> reasons;
  for (const Group& g : redundant_groups) {
    Reason r;
    bool has12 = std::find(g.coords.begin(), g.coords.end(), 1) != g.coords.end();
    bool has3 = std::find(g.coords.begin(), g.coords.end(), 3) != g.coords.end();
    if (has12) r.point_seam_cycle = copies_of(RI::point_seam_cycle(seam, wf, g.point, g.a, g.b));
    if (has3) r.seam_cycle = copies_of(RI::seam_cycle_of(seam, wf, g.point, g.a, g.b));
    reasons.push_back(r);
  }
  // The rigidity matroid at a random realization: which distances hold the bodies outside the
  // covering set, the generic dof, and the constraints in conflict.
  const std::vector<RI::Constraint> ks = RI::system_constraints(c, t, wf);
  RI::Constraint_independence mi;
  std::string matroid_note;
  bool matroid_done = false;
  try {
    mi = RI::constraint_independence(c, t.covering_set, ks);
    matroid_done = true;
  } catch (const RI::Input_error& e) {
    matroid_note = e.what();
  }
  // a dependent constraint is harmless when its circuit lies in one body's own distances
  // (a body of 5 or more points has more distances than it needs); otherwise the scene fixes
  // it twice: over-constrained, and its value must agree or there is no configuration
  std::vector<std::size_t> conflicts, body_distances;
  std::size_t implied_body_distances = 0, equations = 0;
  if (matroid_done) {
    for (std::size_t i = 0; i < ks.size(); ++i) {
      if (mi.independent[i]) {
        if (ks[i].origin != RI::Constraint::TREE_INCIDENCE) ++equations;
        if (ks[i].origin == RI::Constraint::BODY_DISTANCE) body_distances.push_back(i);
        continue;
      }
      if (mi.follows_from_its_body(i)) ++implied_body_distances;
      else conflicts.push_back(i);
    }
  } else {
    equations = wf.remaining_count + c.distances().size();
  }
  const long reduced_variables = t.weight + 3 * dof.free_points;
  // what a full solve would cost: combinations of charts and placements, the system's blocks
  std::string work_note;
  const std::optional<RI::Scene_solve_work> work = solve_command::estimate_work(c, t, wf, work_note);
  if (!o.dot_seam.empty()) {
    std::ofstream dot(o.dot_seam);
    if (!dot) { std::cerr << "rigid_incidence: cannot write " << o.dot_seam << "\n"; return 1; }
    RI::write_seam_graph_dot(dot, c, wf);
  }
  // The naive formulation gives each body of the scene a free rigid motion (6 variables)
  // and fixes one: 6(k-1) for the k bodies the user wrote.
  const long naive = 6 * (long(scene.bodies.size()) - 1);
  auto name = [&](std::size_t b) { return c.body(b).name; };
  // placements of each body up to rigid motion (mirror images, hinge angles)
  // (0 with a note when this version cannot place the body from its distances)
  std::vector<std::size_t> placements(c.number_of_bodies(), 1);
  std::vector<std::string> placement_notes(c.number_of_bodies());
  for (std::size_t i = 0; i < c.number_of_bodies(); ++i) {
    if (c.body(i).mirror_variants > 0) { placements[i] = std::size_t(c.body(i).mirror_variants); continue; }
    try {
      placements[i] = RI::enclose_all_placements<CGAL::Interval_nt<false>>(c, i).size();
    } catch (const RI::Input_error& e) {
      placements[i] = 0;
      placement_notes[i] = e.what();
      continue;
    }
    if (placements[i] == 0) {
      auto e = RI::enumerate_placements<CGAL::Interval_nt<false>>(c, i);
      if (!e.undecided.empty()) { placement_notes[i] = e.undecided; continue; }
      throw RI::No_real_configuration(o.scene + ": " + (e.inconsistent.empty() ? "body '" + c.body(i).name +
                                                                                       "': its distances admit no real placement"
                                                                                 : e.inconsistent));
    }
  }
  auto labels = [&](const std::vector<std::size_t>& pts) {
    std::vector<std::string> l;
    for (std::size_t p : pts) l.push_back(c.label(p));
    return l;
  };

  if (!o.dot.empty()) {
    std::ofstream dot(o.dot);
    if (!dot) { std::cerr << "rigid_incidence: cannot write " << o.dot << "\n"; return 1; }
    RI::write_overlap_graph_dot(dot, c, t);
  }

  if (o.json) {
    nlohmann::ordered_json j;
    j["scene"] = {{"name", scene.name}, {"file", o.scene}, {"kernel", o.kernel}, {"frame", c.frame()},
                  {"user_bodies", scene.bodies.size()}, {"user_distances", scene.distances.size()}};
    nlohmann::ordered_json bodies = nlohmann::ordered_json::array(), implied = nlohmann::ordered_json::array();
    for (std::size_t i = 0; i < c.number_of_bodies(); ++i) {
      const auto& b = c.body(i);
      nlohmann::ordered_json jb = {{"name", b.name}, {"origin", RI::to_string(b.origin)}, {"points", labels(b.points)},
                                   {"sources", b.sources}, {"placements", placements[i]}};
      if (!placement_notes[i].empty()) jb["placement_note"] = placement_notes[i];
      bodies.push_back(jb);
      if (b.origin == RI::Body_origin::IMPLIED) implied.push_back(jb);
    }
    j["bodies"] = bodies;
    j["implied_bodies"] = implied;
    j["standardization"] = log;
    nlohmann::ordered_json remaining = nlohmann::ordered_json::array();
    for (const auto& d : c.distances()) remaining.push_back({{"between", {c.label(d.a), c.label(d.b)}}, {"source", d.name}});
    j["remaining_distances"] = remaining;
    nlohmann::ordered_json comps = nlohmann::ordered_json::array();
    for (const auto& comp : dof.components) { std::vector<std::string> n; for (auto b : comp) n.push_back(name(b)); comps.push_back(n); }
    j["dof"] = {{"bodies", dof.bodies}, {"free_points", dof.free_points}, {"body_dof", dof.body_dof}, {"rdof", dof.removed}, {"distances", dof.distances},
                {"dof", dof.dof}, {"verdict", dof.verdict()}, {"connected", dof.connected}, {"components", comps}};
    nlohmann::ordered_json edges = nlohmann::ordered_json::array();
    const auto& g = og.graph();
    for (auto e : boost::make_iterator_range(boost::edges(g)))
      edges.push_back({name(boost::source(e, g)), name(boost::target(e, g)), g[e].weight});
    j["overlap_graph"] = {{"edges", edges}, {"omitted_weight", 6}};
    std::vector<std::string> cover, non;
    for (auto b : t.covering_set) cover.push_back(name(b));
    for (auto b : t.non_covering) non.push_back(name(b));
    j["covering_set"] = cover;
    j["non_covering"] = non;
    nlohmann::ordered_json tedges = nlohmann::ordered_json::array();
    for (const auto& e : t.edges) tedges.push_back({name(e.parent), name(e.child), e.weight});
    j["incidence_tree"] = {{"root", name(t.root)}, {"edges", tedges}, {"weight", t.weight},
                           {"distance_path_sum", t.distance_path_sum}, {"depth_sum", t.depth_sum},
                           {"proven_optimal", t.proven_optimal}, {"strategy", t.strategy}};
    j["optimal_trees_tied"] = t.ties;
    nlohmann::ordered_json wfj = nlohmann::ordered_json::array(), redj = nlohmann::ordered_json::array();
    for (const Group& g : selected_groups)
      wfj.push_back({{"point", c.label(g.point)}, {"bodies", {name(g.a), name(g.b)}}, {"coordinates", g.coords},
                     {"role", g.tree ? "tree" : "remaining"}});
    for (std::size_t k = 0; k < redundant_groups.size(); ++k) {
      const Group& g = redundant_groups[k];
      nlohmann::ordered_json rj = {{"point", c.label(g.point)}, {"bodies", {name(g.a), name(g.b)}}, {"coordinates", g.coords}};
      if (!reasons[k].point_seam_cycle.empty()) rj["point_seam_cycle"] = reasons[k].point_seam_cycle;
      if (!reasons[k].seam_cycle.empty()) rj["seam_cycle"] = reasons[k].seam_cycle;
      redj.push_back(rj);
    }
    j["well_formed_incidences"] = wfj;
    j["redundant_incidences"] = redj;
    nlohmann::ordered_json bd = nlohmann::ordered_json::array(), cf = nlohmann::ordered_json::array();
    for (std::size_t i : body_distances) bd.push_back({{"body", name(ks[i].body)}, {"between", {c.label(ks[i].a), c.label(ks[i].b)}}});
    for (std::size_t i : conflicts) {
      std::vector<std::string> with;
      for (std::size_t k : mi.circuits[i]) if (k != i) with.push_back(RI::describe(c, ks[k]));
      cf.push_back({{"constraint", RI::describe(c, ks[i])}, {"depends_on", with}});
    }
    if (matroid_done)
      j["rigidity_matroid"] = {{"variables", mi.variables}, {"rank", mi.rank}, {"generic_dof", mi.generic_dof()},
                               {"seed", mi.seed}, {"method", "exact rank modulo 2^61-1 at a random realization"}};
    else
      j["rigidity_matroid"] = {{"skipped", matroid_note}};
    j["body_distances"] = bd;
    j["conflicts"] = cf;
    j["reduced_equations"] = equations;
    j["reduced_variables"] = reduced_variables;
    j["naive_variables"] = naive;
    if (work) j["work"] = solve_command::work_json(*work);
    else j["work"] = {{"skipped", work_note}};
    std::cout << j.dump(2) << "\n";
    return 0;
  }

  std::cout << "scene " << (scene.name.empty() ? std::string("(unnamed)") : scene.name) << " (" << o.scene << "), kernel "
            << o.kernel << ": " << scene.bodies.size() << " bodies, " << scene.distances.size() << " distances\n";
  std::cout << "\nstandardization:\n";
  if (log.empty()) std::cout << "  nothing to do: the collection is standard as given\n";
  for (const auto& l : log) std::cout << "  - " << l << "\n";
  std::cout << "\nstandard collection: " << c.number_of_bodies() << " bodies, " << c.shared_points().size()
            << " shared points, " << c.distances().size() << " remaining distances; frame '" << c.frame() << "'\n";
  for (std::size_t i = 0; i < c.number_of_bodies(); ++i) {
    const auto& b = c.body(i);
    std::cout << "  " << b.name << " [" << RI::to_string(b.origin) << "]:";
    for (auto l : labels(b.points)) std::cout << " " << l;
    if (placements[i] == 0) std::cout << "  (placements not enumerated: " << placement_notes[i] << ")";
    if (placements[i] > 1)
      std::cout << "  (" << placements[i] << " placements: its distances fix it only up to "
                << (b.mirror_variants == 2 ? "a mirror image)" : "a discrete choice)");
    std::cout << "\n";
  }
  for (const auto& d : c.distances())
    std::cout << "  distance " << c.label(d.a) << "-" << c.label(d.b) << " (" << d.name << ")\n";
  if (dof.free_points > 0) {
    std::cout << "  free points (in no body, held only by distances):";
    for (std::size_t p : c.free_points()) std::cout << " " << c.label(p);
    std::cout << "\n";
  }
  std::cout << "\ndof count: 6(k-1)" << (dof.free_points > 0 ? " + 3 (free points)" : "") << " = " << dof.body_dof << ", rdof = " << dof.removed << ", distances = " << dof.distances
            << ", dof = " << dof.dof << ": " << dof.verdict() << " by the count";
  if (!dof.connected) std::cout << "; NOT CONNECTED: " << dof.components.size() << " separate parts";
  std::cout << "\n";
  std::cout << "\noverlap graph (w = 1 shared pair, 3 shared point; pairs sharing nothing have w = 6, omitted):\n";
  const auto& g = og.graph();
  for (auto e : boost::make_iterator_range(boost::edges(g))) {
    std::cout << "  " << name(boost::source(e, g)) << " -- " << name(boost::target(e, g)) << "  w=" << g[e].weight << "  shares";
    for (auto l : labels(g[e].shared)) std::cout << " " << l;
    std::cout << "\n";
  }
  std::cout << "\ncovering set:";
  for (auto b : t.covering_set) std::cout << " " << name(b);
  std::cout << "\nnot in the covering set:";
  if (t.non_covering.empty()) std::cout << " (none)";
  for (auto b : t.non_covering) std::cout << " " << name(b);
  std::cout << "\n\noptimal incidence tree: root " << name(t.root) << ", weight " << t.weight << ", distance paths "
            << t.distance_path_sum << ", depth sum " << t.depth_sum << (t.proven_optimal ? " (proven optimal)" : " (NOT proven optimal)") << "\n";
  for (const auto& e : t.edges) {
    std::cout << "  " << name(e.parent) << " -> " << name(e.child) << "  w=" << e.weight;
    auto sh = og.shared_points(e.parent, e.child);
    if (!sh.empty()) { std::cout << "  shares"; for (auto l : labels(sh)) std::cout << " " << l; }
    std::cout << "\n";
  }
  if (t.ties > 1)
    std::cout << "  " << t.ties << " rooted trees tie on weight, distance paths and depth sum" << (t.ties_complete ? "" : " (at least)")
              << "; the tie-break prefers bodies with the user's coordinates, then the order of the bodies\n";
  std::cout << "  search: " << t.strategy << "\n";
  std::cout << "\nwell-formed incidences of the tree's bodies: " << wf.incidences.size() << " (" << wf.tree_count
            << " eliminated by the tree, " << wf.remaining_count << " remaining)\n";
  for (const Group& g : selected_groups) {
    std::cout << "  " << c.label(g.point) << "  " << name(g.a) << " = " << name(g.b) << "  coordinates";
    for (int p : g.coords) std::cout << " " << p;
    std::cout << (g.tree ? "  (tree)" : "  (remaining)") << "\n";
  }
  std::cout << "redundant incidences left out: " << redundant.size() << "\n";
  if (!redundant_groups.empty())
    std::cout << "  (coordinates 1 2: the point seam edge closes a point-seam cycle of the selection;"
              << " coordinate 3: it closes a seam cycle of the seam tree; cycles as point@body)\n";
  for (std::size_t k = 0; k < redundant_groups.size(); ++k) {
    const Group& g = redundant_groups[k];
    std::cout << "  " << c.label(g.point) << "  " << name(g.a) << " = " << name(g.b) << "  coordinates";
    for (int p : g.coords) std::cout << " " << p;
    std::cout << "\n";
    auto show = [](const char* what, const std::vector<std::string>& cyc) {
      if (cyc.empty()) return;
      std::cout << "      " << what << ":";
      for (const auto& x : cyc) std::cout << " " << x;
      std::cout << " (back to " << cyc.front() << ")\n";
    };
    show("1 2, point-seam cycle", reasons[k].point_seam_cycle);
    show("3, seam cycle", reasons[k].seam_cycle);
  }
  if (matroid_done) {
    std::cout << "\nrigidity matroid at a random realization (exact rank modulo 2^61-1): rank " << mi.rank << " of "
              << mi.variables << " variables, generic dof " << mi.generic_dof()
              << (mi.generic_dof() == 0 ? " (generically rigid)" : " (flexible)") << "\n";
    if (!t.non_covering.empty()) {
      std::cout << "  distances holding the bodies outside the covering set: " << body_distances.size();
      if (implied_body_distances) std::cout << " (" << implied_body_distances << " more follow from those bodies' own rigidity)";
      std::cout << "\n";
      for (std::size_t i : body_distances) std::cout << "    " << RI::describe(c, ks[i]) << "\n";
    }
    if (!conflicts.empty()) {
      std::cout << "  CONFLICTS: " << conflicts.size() << " constraint" << (conflicts.size() > 1 ? "s" : "")
                << " the others already fix (over-constrained: each value must agree with the others exactly,"
                << " or the scene has no configuration):\n";
      for (std::size_t i : conflicts) {
        std::cout << "    " << RI::describe(c, ks[i]) << "\n      depends on:";
        for (std::size_t k : mi.circuits[i]) if (k != i) std::cout << "\n        " << RI::describe(c, ks[k]);
        std::cout << "\n";
      }
    }
  } else {
    std::cout << "\nrigidity matroid: skipped (" << matroid_note << ")\n";
  }
  std::cout << "\nreduced system: " << reduced_variables << " variables";
  if (dof.free_points > 0) std::cout << " (" << t.weight << " of the tree, 3 per free point)";
  std::cout << ", against 6(k-1) = " << naive
            << " for the naive formulation (a free rigid motion for each of the k = " << scene.bodies.size()
            << " bodies of the scene, one fixed); " << equations << " equations (" << wf.remaining_count
            << " remaining incidences, " << c.distances().size() << " remaining distances"
            << (matroid_done ? ", " + std::to_string(body_distances.size()) + " distances holding bodies outside the covering set"
                             : "; the distances holding bodies outside the covering set are not counted")
            << (conflicts.empty() ? "" : ", the conflicting ones left out") << ")\n";
  if (!dof.connected || (matroid_done ? (mi.generic_dof() != 0 || !conflicts.empty()) : dof.dof != 0))
    std::cout << "  note: the scene is " << (dof.connected ? "" : "not connected and ")
              << (matroid_done ? (mi.generic_dof() > 0 ? "under-constrained" : "over-constrained")
                               : dof.verdict() + " by the dof count")
              << ": the variables and the equations will not form a square system with isolated solutions\n";
  if (work) std::cout << "work of a full solve: " << RI::internal::describe_work(*work) << "\n";
  else std::cout << "work of a full solve: not estimated (" << work_note << ")\n";
  return 0;
}

int main(int argc, char** argv)
{
  std::vector<std::string> args(argv + 1, argv + argc);
  if (args.empty()) { std::cerr << usage_text; return 1; }
  if (args[0] == "--help" || args[0] == "-h" || args[0] == "help") { std::cout << usage_text; return 0; }
  if (args[0] != "analyze" && args[0] != "reduce" && args[0] != "solve" && args[0] != "solve-system" && args[0] != "family") { std::cerr << "rigid_incidence: unknown command '" << args[0] << "' (see --help)\n"; return 1; }
  Options o;
  o.command = args[0];
  for (std::size_t i = 1; i < args.size(); ++i) {
    const std::string& a = args[i];
    if (a == "--json") o.json = true;
    else if (a == "--no-plan") {
      if (o.command != "solve-system" && o.command != "solve") { std::cerr << "rigid_incidence: --no-plan is an option of solve and solve-system\n"; return 1; }
      o.no_plan = true;
      o.solve.no_plan = true;
    } else if (a == "--no-sweep") {
      if (o.command != "solve") { std::cerr << "rigid_incidence: --no-sweep is an option of solve\n"; return 1; }
      o.solve.no_sweep = true;
    } else if (a == "--no-consistency") {
      if (o.command != "solve") { std::cerr << "rigid_incidence: --no-consistency is an option of solve\n"; return 1; }
      o.solve.no_consistency = true;
    } else if (a == "--no-propagation") {
      if (o.command != "solve") { std::cerr << "rigid_incidence: --no-propagation is an option of solve\n"; return 1; }
      o.solve.no_propagation = true;
    } else if (a == "--fast") {
      if (o.command != "solve" && o.command != "solve-system") { std::cerr << "rigid_incidence: --fast is an option of solve\n"; return 1; }
      o.solve.fast = true;
    } else if (a == "--quiet") {
      if (o.command != "solve") { std::cerr << "rigid_incidence: --quiet is an option of solve\n"; return 1; }
      o.solve.quiet = true;
    } else if (a == "--max-seconds") {
      if (i + 1 >= args.size()) { std::cerr << "rigid_incidence: " << a << " needs a value\n"; return 1; }
      if (o.command != "solve") { std::cerr << "rigid_incidence: --max-seconds is an option of solve\n"; return 1; }
      try {
        o.solve.max_seconds = solve_command::parse_positive(a, args[++i]);
      } catch (const RI::Input_error& e) {
        std::cerr << "rigid_incidence: " << e.what() << "\n";
        return 1;
      }
    } else if (a == "--max-listed") {
      if (i + 1 >= args.size()) { std::cerr << "rigid_incidence: " << a << " needs a value\n"; return 1; }
      if (o.command != "solve") { std::cerr << "rigid_incidence: --max-listed is an option of solve\n"; return 1; }
      const std::string& v = args[++i];
      char* end = nullptr;
      errno = 0;
      const unsigned long long k = v.empty() || v[0] == '-' ? 0 : std::strtoull(v.c_str(), &end, 10);
      if (v.empty() || v[0] == '-' || !end || *end != '\0' || errno == ERANGE) {
        std::cerr << "rigid_incidence: --max-listed: '" << v << "' is not a whole number of configurations (0: all)\n";
        return 1;
      }
      o.solve.max_listed = std::size_t(k);
    } else if (a == "--threads") {
      if (i + 1 >= args.size()) { std::cerr << "rigid_incidence: " << a << " needs a value\n"; return 1; }
      if (o.command != "solve" && o.command != "solve-system") { std::cerr << "rigid_incidence: --threads is an option of solve and solve-system\n"; return 1; }
      const std::string& v = args[++i];
      try {
        const double k = solve_command::parse_positive(a, v);
        if (k != std::floor(k) || k > 1024) throw RI::Input_error(a + ": '" + v + "' is not a whole number of threads (1 .. 1024)");
        o.solve.threads = unsigned(k);
      } catch (const RI::Input_error& e) {
        std::cerr << "rigid_incidence: " << e.what() << "\n";
        return 1;
      }
    } else if (a == "--samples") {
      if (i + 1 >= args.size()) { std::cerr << "rigid_incidence: " << a << " needs a value\n"; return 1; }
      if (o.command != "family") { std::cerr << "rigid_incidence: --samples is an option of family\n"; return 1; }
      const std::string& v = args[++i];
      try {
        double k = solve_command::parse_positive(a, v);
        if (k != std::floor(k) || k > 100) throw RI::Input_error(a + ": '" + v + "' is not a whole number of lengths (1 .. 100)");
        o.family.samples = std::size_t(k);
      } catch (const RI::Input_error& e) {
        std::cerr << "rigid_incidence: " << e.what() << "\n";
        return 1;
      }
    } else if (a == "--tolerance" || a == "--precision" || a == "--svg" || a == "--near" || a == "--max-boxes" || a == "--plot") {
      if (i + 1 >= args.size()) { std::cerr << "rigid_incidence: " << a << " needs a value\n"; return 1; }
      const bool system_option = a != "--svg" && a != "--near" && a != "--plot";
      const bool family_option = a != "--near" && a != "--plot";
      if (o.command != "solve" && !(system_option && o.command == "solve-system") && !(family_option && o.command == "family")) {
        std::cerr << "rigid_incidence: " << a << " is an option of solve" << (system_option ? ", solve-system" : "")
                  << (family_option ? " and family" : "") << "\n";
        return 1;
      }
      const std::string& v = args[++i];
      try {
        if (a == "--tolerance") o.solve.tolerance = solve_command::parse_positive(a, v);
        else if (a == "--precision") {
          double b = solve_command::parse_positive(a, v);
          if (b != std::floor(b) || b < 2 || b > 100000) throw RI::Input_error(a + ": '" + v + "' is not a number of bits (2 .. 100000)");
          o.solve.precision = unsigned(b);
        } else if (a == "--max-boxes") {
          double b = solve_command::parse_positive(a, v);
          if (b != std::floor(b) || b > 1e12) throw RI::Input_error(a + ": '" + v + "' is not a whole number of boxes");
          o.solve.max_boxes = std::size_t(b);
        } else if (a == "--svg") o.solve.svg = v;
        else if (a == "--plot") o.solve.plot = v;
        else o.solve.near = v;
      } catch (const RI::Input_error& e) {
        std::cerr << "rigid_incidence: " << e.what() << "\n";
        return 1;
      }
    }
    else if (a == "--help" || a == "-h") { std::cout << usage_text; return 0; }
    else if (a == "--dot" || a == "--kernel" || a == "--dot-seam" || a == "--chart" || a == "--form" || a == "--coefficients") {
      if (i + 1 >= args.size()) { std::cerr << "rigid_incidence: " << a << " needs a value\n"; return 1; }
      if ((a == "--chart" || a == "--form" || a == "--coefficients") && o.command != "reduce") {
        std::cerr << "rigid_incidence: " << a << " is an option of reduce\n";
        return 1;
      }
      if ((a == "--dot" || a == "--dot-seam") && o.command != "analyze" && !(a == "--dot" && o.command == "solve-system")) {
        std::cerr << "rigid_incidence: " << a << " is an option of analyze\n";
        return 1;
      }
      (a == "--dot" ? o.dot : a == "--dot-seam" ? o.dot_seam : a == "--chart" ? o.charts : a == "--form" ? o.form
                                                                 : a == "--coefficients" ? o.coefficients : o.kernel) = args[++i];
    } else if (!a.empty() && a[0] == '-') { std::cerr << "rigid_incidence: unknown option '" << a << "' (see --help)\n"; return 1; }
    else if (o.scene.empty()) o.scene = a;
    else { std::cerr << "rigid_incidence: more than one scene given ('" << a << "')\n"; return 1; }
  }
  if (o.scene.empty()) { std::cerr << "rigid_incidence: " << o.command << " needs a " << (o.command == "solve-system" ? "system" : "scene") << " file\n"; return 1; }
  o.family.solve = o.solve;
  o.family.json = o.json;
  try {
    if (o.command == "solve-system") {
      system_command::System_options so;
      so.solve = o.solve;
      so.json = o.json;
      so.no_plan = o.no_plan;
      so.dot = o.dot;
      return system_command::solve_system(o.scene, so);
    }
    if (o.kernel == "exact") return analyze<RI::Rigid_incidence_traits<CGAL::Simple_cartesian<CGAL::Gmpq>>>(o);
    if (o.kernel == "epick") return analyze<RI::Rigid_incidence_traits<CGAL::Exact_predicates_inexact_constructions_kernel>>(o);
    if (o.kernel == "epeck") return analyze<RI::Rigid_incidence_traits<CGAL::Exact_predicates_exact_constructions_kernel>>(o);
    std::cerr << "rigid_incidence: unknown kernel '" << o.kernel << "' (exact, epick or epeck)\n";
    return 1;
  } catch (const RI::No_real_configuration& e) {
    // a well-formed scene without a real configuration: a complete answer, not an error
    if (o.json) {
      nlohmann::ordered_json j;
      j["scene"] = o.scene;
      j["complete"] = true;
      j["certified"] = true;
      j["diagnosis"] = nullptr;
      j["no_configuration"] = e.what();
      j["solutions"] = nlohmann::ordered_json::array();
      j["unresolved"] = nlohmann::ordered_json::array();
      j["curves"] = nlohmann::ordered_json::array();
      std::cout << j.dump(2) << "\n";
    } else {
      std::cout << "scene " << o.scene << ": no real configuration: " << e.what() << "\n";
      if (o.command == "solve") std::cout << "0 configuration(s), all certified: complete\n";
    }
    return 0;
  } catch (const RI::Input_error& e) {
    std::cerr << "rigid_incidence: error: " << e.what() << "\n";
    return 2;
  } catch (const std::bad_alloc&) {
    // a clear message instead of an abort: the solver refuses systems whose arrays would not
    // fit (maximal_coefficients), but the machine's memory may still run out on a long solve
    std::cerr << "rigid_incidence: error: out of memory while working on " << o.scene << "\n";
    return 3;
  }
}
