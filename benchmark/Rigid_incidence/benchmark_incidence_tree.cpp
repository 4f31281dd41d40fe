// Copyright (c) 2026 Rigid_incidence contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Benchmark of optimal_incidence_tree: time of the exact branch and bound against the
// greedy heuristic, on random standard collections of growing size, side by side in one
// run, written as a table (Markdown) and a CSV.
//
// Usage: benchmark_incidence_tree [OUTPUT_PREFIX] [MAX_BODIES] [REPEATS]

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Random.h>
#include <CGAL/Real_timer.h>
#include <CGAL/Rigid_incidence.h>

#include <fstream>
#include <iostream>
#include <set>
#include <string>
#include <vector>

namespace RI = CGAL::Rigid_incidence;
typedef CGAL::Simple_cartesian<double> K;
typedef RI::Rigid_incidence_traits<K> Traits;

// A random standard collection: bodies of 3 or 4 points drawn near each other along a
// strip of points, no two sharing 3 or more, none inside another.
static RI::Rigid_body_collection<Traits> random_collection(std::size_t n, CGAL::Random& rng)
{
  RI::Rigid_body_collection<Traits> c;
  std::size_t pool = n + 3;
  std::vector<std::set<std::size_t>> sets;
  std::size_t guard = 0;
  while (sets.size() < n && ++guard < 100000) {
    std::size_t size = 3 + (rng.get_int(0, 3) == 0 ? 1 : 0);
    std::size_t start = std::size_t(rng.get_int(0, int(pool - 4)));
    std::set<std::size_t> s;
    while (s.size() < size) s.insert(start + std::size_t(rng.get_int(0, 5)) % (pool - start));
    bool ok = true;
    for (const auto& t : sets) {
      std::size_t common = 0;
      for (auto p : s) common += t.count(p);
      if (common >= 3 || common == std::min(s.size(), t.size())) { ok = false; break; }
    }
    if (ok) sets.push_back(s);
  }
  for (std::size_t i = 0; i < sets.size(); ++i) {
    std::vector<std::pair<std::string, K::Point_3>> pts;
    for (auto p : sets[i]) pts.emplace_back("p" + std::to_string(p), K::Point_3(double(p), double(p * p % 7), double(p * p * p % 11)));
    c.add_body("b" + std::to_string(i), pts);
  }
  return c;
}

int main(int argc, char** argv)
{
  std::string prefix = argc > 1 ? argv[1] : "incidence_tree";
  std::size_t max_n = argc > 2 ? std::size_t(std::stoul(argv[2])) : 40;
  int repeats = argc > 3 ? std::stoi(argv[3]) : 5;
  CGAL::Random rng(20261122);
  std::ofstream csv(prefix + ".csv"), md(prefix + ".md");
  csv << "bodies,instance,exact_seconds,exact_nodes,proven,exact_weight,greedy_seconds,greedy_weight,ratio_time\n";
  md << "| bodies | instances | exact: mean s | exact: max s | proven optimal | greedy: mean s | greedy weight excess (mean) |\n";
  md << "|---:|---:|---:|---:|---:|---:|---:|\n";
  for (std::size_t n = 5; n <= max_n; n += 5) {
    double te_sum = 0, te_max = 0, tg_sum = 0, excess = 0;
    int proven = 0;
    for (int r = 0; r < repeats; ++r) {
      auto c = random_collection(n, rng);
      RI::Incidence_tree_options exact, greedy;
      greedy.exact_limit = 0;
      CGAL::Real_timer t1, t2;
      t1.start(); RI::Incidence_tree a = RI::optimal_incidence_tree(c, exact); t1.stop();
      t2.start(); RI::Incidence_tree b = RI::optimal_incidence_tree(c, greedy); t2.stop();
      te_sum += t1.time(); te_max = std::max(te_max, t1.time()); tg_sum += t2.time();
      excess += double(b.weight - a.weight);
      proven += a.proven_optimal;
      csv << n << "," << r << "," << t1.time() << "," << a.search_nodes << "," << a.proven_optimal << "," << a.weight << ","
          << t2.time() << "," << b.weight << "," << (t2.time() > 0 ? t1.time() / t2.time() : 0) << "\n";
    }
    md << "| " << n << " | " << repeats << " | " << te_sum / repeats << " | " << te_max << " | " << proven << "/" << repeats
       << " | " << tg_sum / repeats << " | " << excess / repeats << " |\n";
    std::cout << "n=" << n << " exact mean " << te_sum / repeats << " s (max " << te_max << "), proven " << proven << "/"
              << repeats << ", greedy mean " << tg_sum / repeats << " s, greedy excess weight " << excess / repeats << std::endl;
  }
  std::cout << "wrote " << prefix << ".md and " << prefix << ".csv\n";
  return 0;
}
