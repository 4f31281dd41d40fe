// Copyright (c) 2026 Rigid_incidence contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Enclosures of implied bodies with MPFI intervals (CGAL::Gmpfi) at rising precision:
// each enclosure contains the exact squared distances (checked exactly with rationals),
// agrees with the double-interval enclosure, and tightens as the precision grows.

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Gmpq.h>
#include <CGAL/Rigid_incidence.h>

#include <iostream>

#ifdef CGAL_USE_MPFI
#include <CGAL/Gmpfi.h>
#include <CGAL/Gmpfr.h>

namespace RI = CGAL::Rigid_incidence;
typedef CGAL::Simple_cartesian<CGAL::Gmpq> K;
typedef RI::Rigid_incidence_traits<K> Traits;

static int failures = 0;
#define CHECK(cond, msg) do { if (!(cond)) { ++failures; std::cerr << "FAIL line " << __LINE__ << ": " << msg << "\n"; } } while (0)

int main()
{
  RI::Scene s = RI::read_scene(std::string(RIGID_INCIDENCE_DATA_DIR) + "/tetra.json");
  auto c = RI::standardize(RI::make_collection<Traits>(s));
  int checked = 0;
  for (std::size_t b = 0; b < c.number_of_bodies(); ++b) {
    const auto& body = c.body(b);
    if (body.origin != RI::Body_origin::IMPLIED) continue;
    double previous_width = 1e300;
    for (long prec : {53L, 128L, 512L}) {
      long old = CGAL::Gmpfi::set_default_precision(prec);
      RI::Body_enclosure<CGAL::Gmpfi> e = RI::enclose_coordinates<CGAL::Gmpfi>(c, b);
      CHECK(e.consistent, body.name << " at " << prec << " bits: not consistent");
      double width = 0;
      for (const auto& d : body.squared_distances) {
        const auto& P = e.coordinates[d.a];
        const auto& Q = e.coordinates[d.b];
        CGAL::Gmpfi dist = (P[0] - Q[0]) * (P[0] - Q[0]) + (P[1] - Q[1]) * (P[1] - Q[1]) + (P[2] - Q[2]) * (P[2] - Q[2]);
        // exact containment check with rationals
        CGAL::Gmpq lo(dist.inf()), hi(dist.sup());
        CHECK(lo <= d.squared && d.squared <= hi, body.name << " at " << prec << " bits: squared distance "
              << CGAL::to_double(d.squared) << " not in [" << dist.inf() << ", " << dist.sup() << "]");
        width = std::max(width, CGAL::to_double(hi - lo));
      }
      CHECK(width < previous_width || width == 0, body.name << ": width did not shrink from " << previous_width << " to " << width
            << " at " << prec << " bits");
      CHECK(prec < 512 || width < 1e-140, body.name << ": width " << width << " at 512 bits");
      previous_width = width;
      // agreement with the double-interval enclosure
      RI::Body_enclosure<CGAL::Interval_nt<false>> ed = RI::enclose_coordinates<CGAL::Interval_nt<false>>(c, b);
      for (std::size_t k = 0; k < e.coordinates.size(); ++k)
        for (int i = 0; i < 3; ++i)
          CHECK(CGAL::to_double(e.coordinates[k][i].sup()) >= ed.coordinates[k][i].inf() - 1e-300 &&
                CGAL::to_double(e.coordinates[k][i].inf()) <= ed.coordinates[k][i].sup() + 1e-300,
                body.name << ": MPFI and double enclosures are disjoint");
      CGAL::Gmpfi::set_default_precision(old);
      ++checked;
    }
  }
  CHECK(checked == 12, "expected 4 implied bodies x 3 precisions, checked " << checked);
  // The lazy exact kernel hands its exact values over to MPFI too; same enclosures.
  typedef RI::Rigid_incidence_traits<CGAL::Exact_predicates_exact_constructions_kernel> Epeck_traits;
  auto ce = RI::standardize(RI::make_collection<Epeck_traits>(s));
  for (std::size_t b = 0; b < ce.number_of_bodies(); ++b) {
    if (ce.body(b).origin != RI::Body_origin::IMPLIED) continue;
    RI::Body_enclosure<CGAL::Gmpfi> e1 = RI::enclose_coordinates<CGAL::Gmpfi>(ce, b);
    RI::Body_enclosure<CGAL::Gmpfi> e2 = RI::enclose_coordinates<CGAL::Gmpfi>(c, c.body_index(ce.body(b).name));
    CHECK(e1.consistent, ce.body(b).name << " (Epeck): not consistent");
    for (std::size_t k = 0; k < e1.coordinates.size(); ++k)
      for (int i = 0; i < 3; ++i)
        CHECK(e1.coordinates[k][i].inf() == e2.coordinates[k][i].inf() && e1.coordinates[k][i].sup() == e2.coordinates[k][i].sup(),
              ce.body(b).name << ": Epeck and Gmpq enclosures differ");
    ++checked;
  }
  CHECK(checked == 16, "expected 4 more implied bodies with Epeck, checked " << checked);
  std::cout << checked << " enclosures checked: " << (failures ? "FAILED" : "OK") << "\n";
  return failures ? 1 : 0;
}
#else
int main()
{
  std::cout << "MPFI not available: CGAL::Gmpfi enclosures not tested (install libmpfi-dev)\n";
  return 0;
}
#endif
