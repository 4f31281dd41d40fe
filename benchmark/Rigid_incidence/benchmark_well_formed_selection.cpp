// Copyright (c) 2026 Rigid_incidence contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Benchmark of select_well_formed_incidences for a given tree on collections of 10 to 10,000
// bodies: the time, the size measure |C|(|C| + |X|) of the paper's bound (Theorem 3), and the
// growth exponents fitted (least squares on log-log) to both, written as a Markdown table.
//
// The collections: a strip of triangles p_i p_{i+1} p_{i+2} (neighbours share a pair: hinges,
// the next ones a single point) plus, on every third triangle, a pendant triangle sharing one
// point; the tree is the path along the strip with the pendants hanging from their triangle.
//
// Usage: benchmark_well_formed_selection [OUTPUT_PREFIX] [MAX_BODIES] [REPEATS]

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Real_timer.h>
#include <CGAL/Rigid_incidence.h>

#include <cmath>
#include <fstream>
#include <iostream>
#include <string>
#include <vector>

namespace RI = CGAL::Rigid_incidence;
typedef CGAL::Simple_cartesian<double> K;
typedef RI::Rigid_incidence_traits<K> Traits;

int main(int argc, char** argv)
{
  std::string prefix = argc > 1 ? argv[1] : "well_formed_selection";
  std::size_t max_n = argc > 2 ? std::size_t(std::stoul(argv[2])) : 10000;
  int repeats = argc > 3 ? std::stoi(argv[3]) : 3;
  std::ofstream md(prefix + ".md");
  md << "| bodies C | shared points X | C (C + X) | selected incidences | remaining | time (s, best of " << repeats
     << ") | time / (C (C + X)) (ns) |\n|---:|---:|---:|---:|---:|---:|---:|\n";
  std::vector<double> lx, lt, lb;
  for (std::size_t n = 10; n <= max_n; n *= 10) {
    RI::Rigid_body_collection<Traits> c;
    auto P = [](std::size_t i) { return K::Point_3(double(i), double(i * i % 7), double(i * i * i % 11) + 0.5 * double(i % 2)); };
    std::size_t strip = n - n / 4, pendants = 0;
    std::vector<std::pair<std::size_t, std::size_t>> edges;
    for (std::size_t i = 0; i < strip; ++i) {
      c.add_body("t" + std::to_string(i), {{"p" + std::to_string(i), P(i)}, {"p" + std::to_string(i + 1), P(i + 1)},
                                           {"p" + std::to_string(i + 2), P(i + 2)}});
      if (i > 0) edges.push_back({i - 1, i});
    }
    for (std::size_t i = 0; i + 1 < strip && c.number_of_bodies() < n; i += 3) {
      std::string a = "a" + std::to_string(i), b = "b" + std::to_string(i);
      c.add_body("q" + std::to_string(i), {{"p" + std::to_string(i + 1), P(i + 1)}, {a, K::Point_3(-1.0 * double(i), 1, 2)},
                                           {b, K::Point_3(-1.0 * double(i), 3, 5)}});
      edges.push_back({i, c.number_of_bodies() - 1});
      ++pendants;
    }
    RI::Incidence_tree t = RI::make_incidence_tree(c, 0, edges);
    double best = 1e300;
    RI::Well_formed_selection s;
    for (int r = 0; r < repeats; ++r) {
      CGAL::Real_timer timer;
      timer.start();
      s = RI::select_well_formed_incidences(c, t);
      timer.stop();
      best = std::min(best, timer.time());
    }
    double C = double(c.number_of_bodies()), X = double(c.shared_points().size());
    double bound = C * (C + X);
    md << "| " << c.number_of_bodies() << " | " << std::size_t(X) << " | " << bound << " | " << s.incidences.size() << " | "
       << s.remaining_count << " | " << best << " | " << best / bound * 1e9 << " |\n";
    std::cout << "bodies " << c.number_of_bodies() << " (" << pendants << " pendants), shared points " << X << ": "
              << s.incidences.size() << " incidences, " << best << " s" << std::endl;
    lx.push_back(std::log(C));
    lt.push_back(std::log(std::max(best, 1e-9)));
    lb.push_back(std::log(bound));
  }
  auto slope = [](const std::vector<double>& x, const std::vector<double>& y) {
    double mx = 0, my = 0;
    for (std::size_t i = 0; i < x.size(); ++i) { mx += x[i]; my += y[i]; }
    mx /= double(x.size()); my /= double(y.size());
    double sxy = 0, sxx = 0;
    for (std::size_t i = 0; i < x.size(); ++i) { sxy += (x[i] - mx) * (y[i] - my); sxx += (x[i] - mx) * (x[i] - mx); }
    return sxy / sxx;
  };
  double e_time = slope(lx, lt), e_bound = slope(lx, lb);
  md << "\nFitted growth exponent in C (least squares, log-log): time " << e_time << "; the paper's bound C (C + X) "
     << e_bound << ".\n";
  std::cout << "fitted exponent: time " << e_time << ", bound " << e_bound << "\nwrote " << prefix << ".md\n";
  return 0;
}
