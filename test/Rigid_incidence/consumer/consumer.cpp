// Copyright (c) 2026 Rigid_incidence contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// A program built against the installed package: reads a scene, standardizes it and builds
// its optimal incidence tree. Usage: consumer SCENE.json [EXPECTED_WEIGHT]
// (EXPECTED_WEIGHT defaults to 3, the weight of tetra.json's tree). Exit 0 iff it matches.

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Gmpq.h>
#include <CGAL/Rigid_incidence.h>

#include <cstdlib>
#include <exception>
#include <iostream>
#include <string>

namespace RI = CGAL::Rigid_incidence;
typedef RI::Rigid_incidence_traits<CGAL::Simple_cartesian<CGAL::Gmpq>> Traits;

int main(int argc, char** argv)
{
  if (argc < 2 || argc > 3) {
    std::cerr << "usage: consumer SCENE.json [EXPECTED_WEIGHT]\n";
    return 1;
  }
  const long expected = argc == 3 ? std::atol(argv[2]) : 3;
  try {
    RI::Scene scene = RI::read_scene(std::string(argv[1]));
    RI::Rigid_body_collection<Traits> c = RI::standardize(RI::make_collection<Traits>(scene));
    RI::Incidence_tree t = RI::optimal_incidence_tree(c);
    std::cout << "consumer: " << argv[1] << ": " << c.number_of_bodies() << " bodies, incidence tree weight "
              << t.weight << " (expected " << expected << "), root "
              << (t.root < c.number_of_bodies() ? c.body(t.root).name : std::string("none")) << "\n";
    if (long(t.weight) != expected) {
      std::cerr << "consumer: FAILED: weight " << t.weight << " != " << expected << "\n";
      return 1;
    }
  } catch (const std::exception& e) {
    std::cerr << "consumer: FAILED: " << e.what() << "\n";
    return 1;
  }
  std::cout << "consumer: OK\n";
  return 0;
}
