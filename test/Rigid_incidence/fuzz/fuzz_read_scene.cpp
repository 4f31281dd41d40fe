// Copyright (c) 2026 Rigid_incidence contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// libFuzzer target: arbitrary bytes -> read_scene -> make_collection (exact kernel and
// Epick) -> standardize -> dof_count -> optimal_incidence_tree (small budgets) -> DOT output;
// with -DRIGID_INCIDENCE_FUZZ_ENCLOSE=1 also the interval placement (enclose_coordinates) of
// every body of the standard collection (exact kernel). That step is off by default because
// enclose_coordinates.h does not compile against CGAL 5.5 as of this writing (it calls
// CGAL::do_intersect on two Interval_nt; Interval_nt::do_overlap is the existing function).
// The only exception a malformed scene may raise is RI::Input_error; any other exception,
// a crash, a sanitizer report, a leak or a hang is a finding.
// Build: CXX=clang++ cmake -DRIGID_INCIDENCE_FUZZ=ON ...; run: scripts/fuzz.sh [SECONDS].

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Gmpq.h>
#include <CGAL/Interval_nt.h>
#include <CGAL/Rigid_incidence.h>

#include <cstddef>
#include <cstdint>
#include <sstream>
#include <string>
#include <vector>

#ifndef RIGID_INCIDENCE_FUZZ_ENCLOSE
#define RIGID_INCIDENCE_FUZZ_ENCLOSE 0
#endif

namespace RI = CGAL::Rigid_incidence;

namespace {

typedef RI::Rigid_incidence_traits<CGAL::Simple_cartesian<CGAL::Gmpq>> Exact_traits;
typedef RI::Rigid_incidence_traits<CGAL::Exact_predicates_inexact_constructions_kernel> Epick_traits;

// Keeps every input fast: larger collections are only read, not analysed.
constexpr std::size_t max_bodies = 30;
constexpr std::size_t max_points = 30;

template <class Collection>
bool small_enough(const Collection& c)
{
  return c.number_of_bodies() <= max_bodies && c.number_of_points() <= max_points;
}

template <class Traits>
void analyse(const RI::Scene& scene, bool enclose)
{
  RI::Rigid_body_collection<Traits> input;
  try {
    input = RI::make_collection<Traits>(scene);
  } catch (const RI::Input_error&) {
    return;
  }
  if (!small_enough(input)) return;
  RI::Rigid_body_collection<Traits> c;
  std::vector<std::string> log;
  try {
    c = RI::standardize(input, &log);
  } catch (const RI::Input_error&) {
    return;
  }
  if (!small_enough(c)) return;
  RI::Dof_count dof = RI::dof_count(c);
  (void)dof.verdict();

  RI::Incidence_tree_options options;
  options.max_search_nodes = 20000;
  options.max_trees = 2000;
  options.max_candidates = 1000;
  RI::Incidence_tree t = RI::optimal_incidence_tree(c, options);
  std::ostringstream dot;
  RI::write_overlap_graph_dot(dot, c, t);

#if RIGID_INCIDENCE_FUZZ_ENCLOSE
  if (enclose) {
    for (std::size_t i = 0; i < c.number_of_bodies(); ++i) {
      const auto& b = c.body(i);
      for (int v = 0; v < b.mirror_variants && v < 2; ++v) {
        try {
          (void)RI::enclose_coordinates<CGAL::Interval_nt<false>>(c, i, v);
        } catch (const RI::Input_error&) {
        }
      }
    }
  }
#else
  (void)enclose;
#endif
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  std::istringstream in(std::string(reinterpret_cast<const char*>(data), size));
  RI::Scene scene;
  try {
    scene = RI::read_scene(in, "fuzz");
  } catch (const RI::Input_error&) {
    return 0;
  }
  analyse<Exact_traits>(scene, true);
  analyse<Epick_traits>(scene, false);
  return 0;
}
