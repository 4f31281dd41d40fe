// Copyright (c) 2026 Rigid_incidence contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Checks the output of `rigid_incidence analyze SCENE --json` (run by cmake/cli.cmake):
//   cli_json_check FILE [--bodies N] [--implied N] [--weight W] [--depth-sum D] [--root NAME]
//                       [--reduced R] [--naive V] [--ties T] [--covering N] [--well-formed N]
//                       [--remaining N] [--equations N] [--conflicts N] [--generic-dof N] [--body-distances N]
// The output must be valid JSON with every documented key of the right type, and consistent in
// itself, recomputed here from the listed bodies alone: the tree edges form a spanning tree of
// the covering set rooted at `root`; each edge weight is the overlap weight of its two bodies
// (shared points counted from their point lists: 0 -> 6, 1 -> 3, 2 or more -> 1); `weight` is
// the sum of the edge weights; `depth_sum` the sum of the depths; `reduced_variables` the tree
// weight; `implied_bodies` the bodies of origin "implied"; the covering set covers every point
// shared by two or more bodies;
// `naive_variables` is 6 (k - 1) for the k = scene.user_bodies bodies of the scene.
// Then the values given on the command line are compared.

#include <nlohmann/json.hpp>

#include <algorithm>
#include <fstream>
#include <iostream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

using json = nlohmann::json;

static int failures = 0;
#define CHECK(cond, msg) do { if (!(cond)) { ++failures; std::cerr << "FAIL: " << msg << "\n"; } } while (0)

static bool has(const json& j, const char* key, json::value_t t)
{
  if (!j.is_object() || !j.contains(key)) { std::cerr << "FAIL: missing key \"" << key << "\"\n"; ++failures; return false; }
  const json& v = j.at(key);
  bool ok = v.type() == t || (t == json::value_t::number_integer && v.is_number_integer());
  if (!ok) { std::cerr << "FAIL: key \"" << key << "\" has type " << v.type_name() << "\n"; ++failures; }
  return ok;
}

int main(int argc, char** argv)
{
  if (argc < 2) { std::cerr << "usage: cli_json_check FILE [--key value]...\n"; return 2; }
  std::ifstream in(argv[1]);
  if (!in) { std::cerr << "cannot open " << argv[1] << "\n"; return 2; }
  std::stringstream ss;
  ss << in.rdbuf();
  json j;
  try {
    j = json::parse(ss.str());
  } catch (const std::exception& e) {
    std::cerr << "FAIL: the output is not valid JSON: " << e.what() << "\n";
    return 1;
  }
  std::map<std::string, std::string> expect;
  for (int i = 2; i + 1 < argc; i += 2) expect[argv[i]] = argv[i + 1];

  using T = json::value_t;
  if (!j.is_object()) { std::cerr << "FAIL: top level is not an object\n"; return 1; }
  bool ok = has(j, "bodies", T::array) & has(j, "implied_bodies", T::array) & has(j, "dof", T::object) &
            has(j, "covering_set", T::array) & has(j, "incidence_tree", T::object) &
            has(j, "reduced_variables", T::number_integer) & has(j, "naive_variables", T::number_integer) &
            has(j, "optimal_trees_tied", T::number_integer);
  if (!ok) return 1;
  const json& t = j["incidence_tree"];
  ok = has(t, "root", T::string) & has(t, "edges", T::array) & has(t, "weight", T::number_integer) &
       has(t, "depth_sum", T::number_integer);
  if (!ok) return 1;
  const json& dof = j["dof"];
  has(dof, "dof", T::number_integer);

  // bodies: name -> set of point labels; implied ones
  std::map<std::string, std::set<std::string>> points;
  std::set<std::string> implied_expected;
  std::map<std::string, int> owners;
  for (const json& b : j["bodies"]) {
    if (!has(b, "name", T::string) || !has(b, "points", T::array)) return 1;
    std::string n = b["name"];
    CHECK(!points.count(n), "body listed twice: " << n);
    for (const json& p : b["points"]) { points[n].insert(p.get<std::string>()); }
    for (const auto& p : points[n]) ++owners[p];
    if (b.contains("origin") && b["origin"] == "implied") implied_expected.insert(n);
  }
  std::set<std::string> implied_listed;
  for (const json& b : j["implied_bodies"]) implied_listed.insert(b.at("name").get<std::string>());
  CHECK(implied_listed == implied_expected, "implied_bodies differs from the bodies of origin \"implied\"");

  std::set<std::string> cover;
  for (const json& b : j["covering_set"]) {
    std::string n = b;
    CHECK(points.count(n), "covering set names an unknown body " << n);
    cover.insert(n);
  }
  CHECK(cover.size() == j["covering_set"].size(), "covering set lists a body twice");
  for (const auto& [p, k] : owners)
    if (k >= 2) {
      bool covered = false;
      for (const auto& n : cover) covered = covered || points[n].count(p);
      CHECK(covered, "shared point " << p << " is in no body of the covering set");
    }

  // the tree
  const std::string root = t["root"];
  CHECK(cover.count(root), "root " << root << " is not in the covering set");
  std::map<std::string, std::string> parent;
  long weight = 0;
  for (const json& e : t["edges"]) {
    if (!e.is_array() || e.size() != 3 || !e[0].is_string() || !e[1].is_string() || !e[2].is_number_integer()) {
      CHECK(false, "edge is not [parent, child, weight]: " << e.dump());
      continue;
    }
    std::string p = e[0], c = e[1];
    long w = e[2];
    CHECK(cover.count(p) && cover.count(c), "edge " << p << " -> " << c << " leaves the covering set");
    CHECK(!parent.count(c) && c != root, "body " << c << " has two parents (or is the root)");
    parent[c] = p;
    std::size_t shared = 0;
    for (const auto& l : points[p]) shared += points[c].count(l);
    long ow = shared == 0 ? 6 : shared == 1 ? 3 : 1;
    CHECK(w == ow, "edge " << p << " -> " << c << " has weight " << w << ", the bodies share " << shared
                           << " points (overlap weight " << ow << ")");
    weight += w;
  }
  CHECK(t["edges"].size() + 1 == cover.size(), "the tree has " << t["edges"].size() << " edges for " << cover.size() << " bodies");
  long depth_sum = 0;
  for (const auto& n : cover) {
    long d = 0;
    std::string x = n;
    while (x != root && parent.count(x) && d <= long(cover.size())) { x = parent[x]; ++d; }
    CHECK(x == root, "body " << n << " does not reach the root");
    depth_sum += d;
  }
  CHECK(weight == t["weight"].get<long>(), "weight " << t["weight"] << " but the edges sum to " << weight);
  CHECK(depth_sum == t["depth_sum"].get<long>(), "depth_sum " << t["depth_sum"] << " but the depths sum to " << depth_sum);
  // reduced variables: the tree's weight, and 3 per free point (a point in no body)
  long free_points = has(j, "dof", T::object) && has(j["dof"], "free_points", T::number_integer) ? j["dof"]["free_points"].get<long>() : 0;
  CHECK(j["reduced_variables"].get<long>() == weight + 3 * free_points,
        "reduced_variables " << j["reduced_variables"] << " != tree weight + 3 (free points)");
  // naive formulation: a free rigid motion for each of the k bodies of the scene, one fixed
  // (--help; commit f92bedc); the scene's k is scene.user_bodies
  if (has(j, "scene", T::object) && has(j["scene"], "user_bodies", T::number_integer)) {
    long k = j["scene"]["user_bodies"].get<long>();
    CHECK(j["naive_variables"].get<long>() == 6 * (k - 1), "naive_variables " << j["naive_variables"] << " != 6(" << k << " - 1)");
  }
  CHECK(j["optimal_trees_tied"].get<long>() >= 1, "optimal_trees_tied < 1");

  // well-formed incidences (issue 4): each {point, bodies [a, b], coordinates, role}; the
  // tree's ones are exactly those of its edges (a triple and, for a shared pair, a double)
  long wf_total = 0, wf_tree = 0, wf_remaining = 0;
  if (has(j, "well_formed_incidences", T::array) && has(j, "redundant_incidences", T::array) &&
      has(j, "reduced_equations", T::number_integer)) {
    for (const auto& w : j["well_formed_incidences"]) {
      bool ok = has(w, "point", T::string) && has(w, "bodies", T::array) && w["bodies"].size() == 2 &&
                has(w, "coordinates", T::array) && has(w, "role", T::string);
      CHECK(ok, "a well_formed_incidences entry lacks point, bodies [a, b], coordinates or role");
      if (!ok) continue;
      const std::string role = w["role"].get<std::string>();
      CHECK(role == "tree" || role == "remaining", "role " << role);
      long n = long(w["coordinates"].size());
      for (const auto& p : w["coordinates"]) CHECK(p.is_number_integer() && p.get<int>() >= 1 && p.get<int>() <= 3, "coordinate " << p);
      wf_total += n;
      (role == "tree" ? wf_tree : wf_remaining) += n;
    }
    // every redundant incidence says which cycle its point seam edge closes: a point-seam
    // cycle (3 or more copies of its point) for coordinates 1, 2; a seam cycle for 3
    for (const auto& r : j["redundant_incidences"]) {
      bool c12 = false, c3 = false;
      if (has(r, "coordinates", T::array))
        for (const auto& p : r["coordinates"]) { c12 = c12 || p == 1 || p == 2; c3 = c3 || p == 3; }
      if (c12) {
        bool ok = has(r, "point_seam_cycle", T::array) && r["point_seam_cycle"].size() >= 3;
        CHECK(ok, "redundant incidence of " << r.value("point", std::string("?")) << ": no point-seam cycle of 3 or more copies");
        if (ok)
          for (const auto& x : r["point_seam_cycle"])
            CHECK(x.is_string() && x.get<std::string>().rfind(r["point"].get<std::string>() + "@", 0) == 0,
                  "a point-seam cycle passes through another point: " << x);
      }
      if (c3) CHECK(has(r, "seam_cycle", T::array) && r["seam_cycle"].size() >= 3,
                    "redundant coordinate 3 of " << r.value("point", std::string("?")) << ": no seam cycle");
    }
    // every tree edge eliminates 3 incidences per shared point minus 1 per shared pair: 6 - weight
    long eliminated = 0;
    for (const auto& e : t["edges"]) eliminated += 6 - e[2].get<long>();
    CHECK(wf_tree == eliminated, "tree incidences " << wf_tree << ", but the tree's edges eliminate " << eliminated);
  }
  // expected values
  auto num = [&](const std::string& k, long got) {
    if (expect.count(k)) CHECK(std::to_string(got) == expect[k], k << ": got " << got << ", expected " << expect[k]);
  };
  num("--bodies", long(points.size()));
  num("--implied", long(implied_listed.size()));
  num("--weight", t["weight"].get<long>());
  num("--depth-sum", t["depth_sum"].get<long>());
  num("--reduced", j["reduced_variables"].get<long>());
  num("--naive", j["naive_variables"].get<long>());
  num("--ties", j["optimal_trees_tied"].get<long>());
  num("--covering", long(cover.size()));
  num("--well-formed", wf_total);
  num("--remaining", wf_remaining);
  // the rigidity matroid (issue 4's conflicts, issue 5's distances for bodies outside the cover)
  bool matroid = has(j, "rigidity_matroid", T::object) && has(j["rigidity_matroid"], "generic_dof", T::number_integer) &&
                 has(j, "conflicts", T::array) && has(j, "body_distances", T::array) && has(j, "reduced_equations", T::number_integer);
  CHECK(matroid, "rigidity_matroid {generic_dof}, conflicts, body_distances or reduced_equations missing");
  if (matroid) {
    const auto& m = j["rigidity_matroid"];
    CHECK(m["generic_dof"].get<long>() == m["variables"].get<long>() - m["rank"].get<long>(), "generic_dof != variables - rank");
    for (const auto& k : j["conflicts"])
      CHECK(has(k, "constraint", T::string) && has(k, "depends_on", T::array) && !k["depends_on"].empty(),
            "a conflict lacks constraint or depends_on");
    for (const auto& k : j["body_distances"])
      CHECK(has(k, "body", T::string) && has(k, "between", T::array) && k["between"].size() == 2, "a body distance lacks body or between");
    num("--equations", j["reduced_equations"].get<long>());
    num("--conflicts", long(j["conflicts"].size()));
    num("--generic-dof", m["generic_dof"].get<long>());
    num("--body-distances", long(j["body_distances"].size()));
  }
  if (expect.count("--root")) CHECK(root == expect["--root"], "root: got " << root << ", expected " << expect["--root"]);
  for (const auto& [k, v] : expect) {
    static const std::set<std::string> known = {"--bodies", "--implied", "--weight", "--depth-sum", "--root",
                                                "--reduced", "--naive", "--ties", "--covering",
                                                "--well-formed", "--remaining", "--equations", "--conflicts",
                                                "--generic-dof", "--body-distances"};
    if (!known.count(k)) { std::cerr << "cli_json_check: unknown option " << k << "\n"; return 2; }
  }
  std::cout << "cli_json_check " << argv[1] << ": " << failures << " failures\n";
  return failures == 0 ? 0 : 1;
}
