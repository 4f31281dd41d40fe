// Copyright (c) 2026 Rigid_incidence contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Checks the output of `rigid_incidence solve-system FILE --json` (run by cmake/cli.cmake)
// against a list of the system's real roots known independently of the package, written as
//   {"source": "...", "variables": ["x", "y", ...], "box": {"x": [LO, HI], "y": [LO, HI], ...},
//    "count": N, "roots": [[x, y, ...], ...], ...}
// (the roots of the PHCpack demo systems in examples/Rigid_incidence/data/systems/phcpack/, taken
// from the solution list the PHCpack file ships and cross-checked by `phc -b`). The run must be
// complete (no unresolved region, no diagnosis), its box must be the one of the list,
// it must report exactly N solutions, all certified, each with its values inside its
// enclosure, inside the box and not on its boundary, and the solutions must match the roots
// one to one: every coordinate within T * max(1, |root coordinate|) (T = 1e-6 unless told).
//   system_json_check OUTPUT ROOTS.json [--tolerance T]

#include "test_check.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

int main(int argc, char** argv)
{
  if (argc < 3) { std::cerr << "usage: system_json_check OUTPUT ROOTS.json [--tolerance T]\n"; return 2; }
  nlohmann::json j, want;
  try {
    std::ifstream in(argv[1]);
    if (!in) { std::cerr << "cannot open " << argv[1] << "\n"; return 2; }
    in >> j;
    std::ifstream rin(argv[2]);
    if (!rin) { std::cerr << "cannot open " << argv[2] << "\n"; return 2; }
    rin >> want;
  } catch (const std::exception& e) {
    std::cerr << "invalid JSON: " << e.what() << "\n";
    return 2;
  }
  double tol = 1e-6;
  for (int i = 3; i + 1 < argc; i += 2)
    if (std::string(argv[i]) == "--tolerance") tol = std::stod(argv[i + 1]);

  for (const char* k : {"system", "variables", "box", "default_box", "plan", "complete", "diagnosis", "solutions", "unresolved", "stats"})
    CHECK(j.contains(k), "missing key " << k);
  for (const char* k : {"variables", "box", "roots"})
    CHECK(want.contains(k), argv[2] << ": missing key " << k);
  if (failures) return 1;

  const std::vector<std::string> names = want["variables"].get<std::vector<std::string>>();
  const std::vector<std::vector<double>> roots = want["roots"].get<std::vector<std::vector<double>>>();
  if (want.contains("count"))
    CHECK(want["count"].get<std::size_t>() == roots.size(), argv[2] << ": count " << want["count"] << " but " << roots.size() << " roots");
  for (const auto& r : roots) CHECK(r.size() == names.size(), argv[2] << ": a root with " << r.size() << " coordinates");

  // the tool read the same system and box
  std::vector<std::string> vars = j["variables"].get<std::vector<std::string>>();
  std::vector<std::string> a = vars, b = names;
  std::sort(a.begin(), a.end());
  std::sort(b.begin(), b.end());
  CHECK(a == b, "the variables of the output are not those of " << argv[2]);
  CHECK(!j["default_box"].get<bool>(), "the default box was used: the file has no box line");
  CHECK(j["box"].size() == vars.size(), "the box has " << j["box"].size() << " intervals for " << vars.size() << " variables");
  std::vector<double> lo(names.size()), hi(names.size());
  for (std::size_t v = 0; v < names.size(); ++v) {
    CHECK(want["box"].contains(names[v]), argv[2] << ": no box for " << names[v]);
    if (!want["box"].contains(names[v])) continue;
    lo[v] = want["box"][names[v]][0].get<double>();
    hi[v] = want["box"][names[v]][1].get<double>();
    for (std::size_t w = 0; w < vars.size() && w < j["box"].size(); ++w)
      if (vars[w] == names[v])
        // the tool rounds the exact bounds outward to doubles: 0.1 may come out one ulp lower
        CHECK(std::abs(j["box"][w][0].get<double>() - lo[v]) <= 1e-12 * (std::max)(1.0, std::abs(lo[v])) &&
                  std::abs(j["box"][w][1].get<double>() - hi[v]) <= 1e-12 * (std::max)(1.0, std::abs(hi[v])),
              "box of " << names[v] << ": " << j["box"][w] << ", expected [" << lo[v] << ", " << hi[v] << "]");
  }
  if (failures) return 1;

  // complete, nothing left over
  CHECK(j["complete"].get<bool>(), "complete is false");
  CHECK(j["diagnosis"].is_null(), "diagnosis: " << j["diagnosis"]);
  CHECK(j["unresolved"].empty(), j["unresolved"].size() << " unresolved region(s)");
  CHECK(j["curves"].empty(), j["curves"].size() << " curve(s)");

  const auto& sols = j["solutions"];
  CHECK(sols.size() == roots.size(), "solutions: " << sols.size() << ", expected " << roots.size());
  std::vector<int> matched_by(roots.size(), -1);
  std::size_t certified = 0;
  for (std::size_t s = 0; s < sols.size(); ++s) {
    const auto& sol = sols[s];
    bool ok = true;
    for (const char* k : {"certified", "values", "enclosure", "on_boundary"})
      if (!sol.contains(k)) { CHECK(false, "solution " << s << ": missing key " << k); ok = false; }
    if (!ok) continue;
    if (sol["certified"].get<bool>()) ++certified;
    else CHECK(false, "solution " << s << " is not certified: " << sol["values"]);
    CHECK(!sol["on_boundary"].get<bool>(), "solution " << s << " is on the boundary of the box");
    std::vector<double> x(names.size(), 0);
    for (std::size_t v = 0; v < names.size(); ++v) {
      const std::string& n = names[v];
      if (!sol["values"].contains(n) || !sol["enclosure"].contains(n)) {
        CHECK(false, "solution " << s << ": no value or enclosure for " << n);
        ok = false;
        continue;
      }
      x[v] = sol["values"][n].get<double>();
      const double elo = sol["enclosure"][n][0].get<double>(), ehi = sol["enclosure"][n][1].get<double>();
      CHECK(elo <= x[v] && x[v] <= ehi, "solution " << s << ": " << n << " = " << x[v] << " outside its enclosure [" << elo << ", " << ehi << "]");
      CHECK(lo[v] < elo && ehi < hi[v], "solution " << s << ": the enclosure of " << n << " is not inside the box");
    }
    if (!ok) continue;
    // the nearest expected root, in the scaled maximum norm
    std::size_t best = roots.size();
    double best_d = 0;
    for (std::size_t r = 0; r < roots.size(); ++r) {
      double d = 0;
      for (std::size_t v = 0; v < names.size(); ++v)
        d = (std::max)(d, std::abs(x[v] - roots[r][v]) / (std::max)(1.0, std::abs(roots[r][v])));
      if (best == roots.size() || d < best_d) { best = r; best_d = d; }
    }
    if (best == roots.size() || best_d > tol) {
      std::ostringstream os;
      for (std::size_t v = 0; v < names.size(); ++v) os << " " << names[v] << " = " << x[v];
      CHECK(false, "solution " << s << " is not within " << tol << " of an expected root:" << os.str()
                               << " (nearest: root " << best << ", scaled distance " << best_d << ")");
      continue;
    }
    CHECK(matched_by[best] < 0, "solutions " << matched_by[best] << " and " << s << " are both near root " << best);
    matched_by[best] = int(s);
  }
  CHECK(certified == roots.size(), "certified: " << certified << ", expected " << roots.size());
  for (std::size_t r = 0; r < roots.size(); ++r)
    if (matched_by[r] < 0) {
      std::ostringstream os;
      for (std::size_t v = 0; v < names.size(); ++v) os << " " << names[v] << " = " << roots[r][v];
      CHECK(false, "expected root " << r << " not found:" << os.str());
    }
  std::cout << "system_json_check " << argv[1] << ": " << sols.size() << " solutions, " << certified << " certified, "
            << roots.size() << " expected; " << checks << " checks, " << failures << " failures\n";
  return failures ? 1 : 0;
}
