// Copyright (c) 2026 Rigid_incidence contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Checks the output of `rigid_incidence solve SCENE --json` (run by cmake/cli.cmake) against
// the scene file itself, independently of the library: every solution must keep every body
// of the file rigid (all pairwise distances of its points as the file gives them), keep every
// distance of the file, and its points must come out the same where bodies share a label
// (they are printed once per label); its printed body poses must map the file's coordinates
// onto the printed points.
//   solve_json_check OUTPUT SCENE [--solutions N] [--complete true|false] [--certified N] [--singular N]
//                    [--diagnosis PREFIX] [--unresolved-reason SUBSTRING] [--no-solutions-count]
//                    [--tolerance T] [--distinct D] [--coefficient-precision-at-least BITS] [--count N]
// --distinct: two solutions must differ by more than D times the scene's size (default 1e-7;
// tetra_i's two configurations are 1.5e-15 apart).

#include "test_check.h"

#include <nlohmann/json.hpp>

#include <array>
#include <cmath>
#include <fstream>
#include <iostream>
#include <map>
#include <set>
#include <string>
#include <vector>

typedef std::array<double, 3> P3;

static double num(const nlohmann::json& v)
{
  if (v.is_number()) return v.get<double>();
  // scene numbers are strings ("1/3", "0.25", "-2")
  std::string s = v.get<std::string>();
  auto slash = s.find('/');
  if (slash != std::string::npos) return std::stod(s.substr(0, slash)) / std::stod(s.substr(slash + 1));
  return std::stod(s);
}

static double dist(const P3& a, const P3& b)
{
  return std::sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) + (a[2] - b[2]) * (a[2] - b[2]));
}

int main(int argc, char** argv)
{
  if (argc < 3) { std::cerr << "usage: solve_json_check OUTPUT SCENE [--key value]...\n"; return 2; }
  nlohmann::json j, scene;
  {
    std::ifstream in(argv[1]);
    if (!in) { std::cerr << "cannot open " << argv[1] << "\n"; return 2; }
    in >> j;
    std::ifstream sin(argv[2]);
    if (!sin) { std::cerr << "cannot open " << argv[2] << "\n"; return 2; }
    sin >> scene;
  }
  std::map<std::string, std::string> expect;
  for (int i = 3; i + 1 < argc; i += 2) expect[argv[i]] = argv[i + 1];
  const double tol = expect.count("--tolerance") ? std::stod(expect["--tolerance"]) : 1e-8;

  for (const char* k : {"scene", "analysis", "reduced_system", "complete", "diagnosis", "solutions", "unresolved", "stats"})
    CHECK(j.contains(k), "missing key " << k);
  if (failures) return 1;

  // the scene as the file gives it
  std::map<std::string, std::map<std::string, P3>> bodies;
  for (const auto& b : scene["bodies"]) {
    auto& m = bodies[b["name"].get<std::string>()];
    for (auto it = b["points"].begin(); it != b["points"].end(); ++it)
      m[it.key()] = {num(it.value()[0]), num(it.value()[1]), num(it.value()[2])};
  }
  double scale = 1;
  for (const auto& b : bodies)
    for (const auto& p : b.second)
      for (const auto& q : b.second) scale = std::max(scale, dist(p.second, q.second));

  const auto& sols = j["solutions"];
  long certified = 0, singular = 0;
  for (std::size_t s = 0; s < sols.size(); ++s) {
    const auto& sol = sols[s];
    for (const char* k : {"certified", "parameters", "bodies", "points", "max_residual"})
      CHECK(sol.contains(k), "solution " << s << ": missing key " << k);
    if (sol.value("certified", false)) ++certified;
    if (sol.value("singular", false)) ++singular;
    // the precision that found it: the answer's, or a lower one kept from an earlier pass (a
    // retry solves again only the combinations that left something uncertain)
    if (sol.contains("coefficient_precision") && j.contains("coefficient_precision")) {
      const long own = sol["coefficient_precision"].get<long>(), top = j["coefficient_precision"].get<long>();
      CHECK(own == top || (!j["precision_history"].empty() && own >= 53 && own < top),
            "solution " << s << ": coefficient_precision " << own << " beside the answer's " << top);
    }
    std::map<std::string, P3> pts;
    for (auto it = sol["points"].begin(); it != sol["points"].end(); ++it)
      pts[it.key()] = {it.value()[0].get<double>(), it.value()[1].get<double>(), it.value()[2].get<double>()};
    double worst = 0;
    // every body rigid
    for (const auto& b : bodies) {
      for (const auto& p : b.second)
        for (const auto& q : b.second) {
          if (p.first >= q.first) continue;
          CHECK(pts.count(p.first) && pts.count(q.first), "solution " << s << ": point " << p.first << " or " << q.first << " missing");
          if (!pts.count(p.first) || !pts.count(q.first)) continue;
          double e = std::abs(dist(pts[p.first], pts[q.first]) - dist(p.second, q.second));
          worst = std::max(worst, e);
          CHECK(e <= tol * scale, "solution " << s << ": body " << b.first << " distance " << p.first << "-" << q.first << " off by " << e);
        }
      // the printed pose maps the file's coordinates onto the printed points
      const auto& bj = sol["bodies"][b.first];
      if (b.second.size() >= 3 && !bj["rotation"].is_null()) {
        for (const auto& p : b.second) {
          P3 x;
          for (int r = 0; r < 3; ++r)
            x[r] = bj["rotation"][r][0].get<double>() * p.second[0] + bj["rotation"][r][1].get<double>() * p.second[1] +
                   bj["rotation"][r][2].get<double>() * p.second[2] + bj["translation"][r].get<double>();
          double e = dist(x, pts[p.first]);
          CHECK(e <= 1e3 * tol * scale, "solution " << s << ": the pose of " << b.first << " puts " << p.first << " off by " << e);
        }
      }
    }
    // every distance
    if (scene.contains("distances"))
      for (const auto& d : scene["distances"]) {
        std::string a = d["between"][0], b = d["between"][1];
        double want = d.contains("length") ? num(d["length"]) : std::sqrt(num(d["squared"]));
        if (!pts.count(a) || !pts.count(b)) { CHECK(false, "solution " << s << ": distance point missing"); continue; }
        double e = std::abs(dist(pts[a], pts[b]) - want);
        worst = std::max(worst, e);
        CHECK(e <= tol * scale, "solution " << s << ": distance " << a << "-" << b << " off by " << e);
      }
    // every orientation inequality: det(B - A, C - A, D - A) >= 0 (<= 0 with "sign": "negative"),
    // unless the solution is marked as on an inequality's boundary
    if (scene.contains("inequalities") && !(sol.contains("on_inequality_boundary") && sol["on_inequality_boundary"].get<bool>()))
      for (const auto& q : scene["inequalities"]) {
        std::array<P3, 4> X;
        for (int k = 0; k < 4; ++k) X[k] = pts[q["orientation"][k].get<std::string>()];
        P3 u, v, w;
        for (int i = 0; i < 3; ++i) { u[i] = X[1][i] - X[0][i]; v[i] = X[2][i] - X[0][i]; w[i] = X[3][i] - X[0][i]; }
        double det = u[0] * (v[1] * w[2] - v[2] * w[1]) - u[1] * (v[0] * w[2] - v[2] * w[0]) + u[2] * (v[0] * w[1] - v[1] * w[0]);
        if (q.contains("sign") && q["sign"] == "negative") det = -det;
        CHECK(det > 0, "solution " << s << ": orientation inequality " << q["orientation"].dump() << " violated (" << det << ")");
      }
    CHECK(sol["max_residual"].get<double>() <= tol * scale, "solution " << s << ": reported residual " << sol["max_residual"]);
    // distinct configurations
    for (std::size_t t = 0; t < s; ++t) {
      double d = 0;
      for (auto it = sols[t]["points"].begin(); it != sols[t]["points"].end(); ++it) {
        P3 q = {it.value()[0].get<double>(), it.value()[1].get<double>(), it.value()[2].get<double>()};
        d = std::max(d, dist(q, pts[it.key()]));
      }
      const double distinct = expect.count("--distinct") ? std::stod(expect["--distinct"]) : 1e-7;
      CHECK(d > distinct * scale, "solutions " << t << " and " << s << " are the same configuration");
    }
  }
  auto want_bool = [&](const std::string& k, bool got) {
    if (expect.count(k)) CHECK((expect[k] == "true") == got, k << ": got " << got << ", expected " << expect[k]);
  };
  want_bool("--complete", j["complete"].get<bool>());
  // the exact count against the list and the factored answer: every solution listed unless
  // `listing` says why not; the parts' counts multiplied per placement combination (the
  // combinations without parts contribute their listed solutions)
  if (j.contains("configuration_count") && j["configuration_count"].is_number()) {
    const double count = j["configuration_count"].get<double>();
    if (j["listing"].is_null()) CHECK(count == double(sols.size()), "configuration_count " << count << " but " << sols.size() << " listed, no listing note");
    else CHECK(count > double(sols.size()), "configuration_count " << count << " with " << sols.size() << " listed and a listing note");
    if (j.contains("parts") && !j["parts"].empty()) {
      std::map<std::string, double> product;
      for (const auto& q : j["parts"]) {
        CHECK(q["count"].get<double>() == double(q["solutions"].size()), "a part's count is not its solutions'");
        auto it = product.emplace(q["placements"].dump(), 1.0).first;
        it->second *= q["count"].get<double>();
      }
      double sum = 0;
      for (const auto& x : product) sum += x.second;
      if (j["listing"].is_null()) CHECK(sum <= count, "the parts' products " << sum << " exceed the count " << count);
      else CHECK(sum <= count && sum > 0, "the parts' products " << sum << " against the count " << count);
    }
  }
  if (expect.count("--count")) CHECK(j["configuration_count"].dump() == expect["--count"], "configuration_count " << j["configuration_count"].dump() << ", expected " << expect["--count"]);
  if (expect.count("--solutions")) CHECK(long(sols.size()) == std::stol(expect["--solutions"]), "solutions: " << sols.size() << ", expected " << expect["--solutions"]);
  if (expect.count("--singular")) CHECK(singular == std::stol(expect["--singular"]), "singular: " << singular << ", expected " << expect["--singular"]);
  if (expect.count("--certified")) CHECK(certified == std::stol(expect["--certified"]), "certified: " << certified << ", expected " << expect["--certified"]);
  if (expect.count("--diagnosis")) {
    std::string d = j["diagnosis"].is_null() ? std::string() : j["diagnosis"].get<std::string>();
    CHECK(d.rfind(expect["--diagnosis"], 0) == 0, "diagnosis '" << d << "' does not start with " << expect["--diagnosis"]);
  }
  if (expect.count("--unresolved-reason")) {
    bool any = false;
    for (const auto& u : j["unresolved"]) {
      CHECK(u.contains("class") && u.contains("reason") && u.contains("box") && u.contains("points"), "unresolved entry incomplete");
      if (u["reason"].get<std::string>().find(expect["--unresolved-reason"]) != std::string::npos) any = true;
    }
    CHECK(any, "no unresolved region with reason containing '" << expect["--unresolved-reason"] << "'");
  }
  if (expect.count("--coefficient-precision-at-least"))
    CHECK(j["coefficient_precision"].get<long>() >= std::stol(expect["--coefficient-precision-at-least"]) && !j["precision_history"].empty(),
          "coefficient_precision " << j["coefficient_precision"] << ", precision_history " << j["precision_history"].dump());
  if (j["complete"].get<bool>()) CHECK(j["unresolved"].empty() && j["diagnosis"].is_null(), "complete with unresolved regions or a diagnosis");
  std::cout << "solve_json_check " << argv[1] << ": " << sols.size() << " solutions, " << checks << " checks, " << failures << " failures\n";
  return failures ? 1 : 0;
}
