// Copyright (c) 2026 Rigid_incidence contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// libFuzzer target: arbitrary bytes -> read_scene -> make_collection (exact kernel and
// Epick) -> standardize -> dof_count -> optimal_incidence_tree (small budgets) -> DOT output
// -> enclose_all_placements<Interval_nt<false>> of every body of the standard collection (up
// to 8 placements each).
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

// Any step may reject the input with RI::Input_error (e.g. optimal_incidence_tree when
// standardization leaves no body); the caller catches that and nothing else.
template <class Traits>
void analyse(const RI::Scene& scene)
{
  RI::Rigid_body_collection<Traits> input = RI::make_collection<Traits>(scene);
  if (!small_enough(input)) return;
  std::vector<std::string> log;
  RI::Rigid_body_collection<Traits> c = RI::standardize(input, &log);
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
  // the well-formed selection; on small trees also the exhaustive Definition 4 check
  RI::Well_formed_selection wf = RI::select_well_formed_incidences(c, t);
  RI::write_seam_graph_dot(dot, c, wf);
  (void)RI::redundant_incidences(c, wf);
  if (wf.bodies.size() <= 10) (void)RI::is_well_formed(c, wf.incidences, wf.bodies);

  for (std::size_t i = 0; i < c.number_of_bodies(); ++i) {
    try {
      (void)RI::enclose_all_placements<CGAL::Interval_nt<false>>(c, i, 8);
    } catch (const RI::Input_error&) {
    }
  }
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
  try {
    analyse<Exact_traits>(scene);
  } catch (const RI::Input_error&) {
  }
  try {
    analyse<Epick_traits>(scene);
  } catch (const RI::Input_error&) {
  }
  return 0;
}
