// Copyright (c) 2026 Rigid_incidence contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The whole-scene solves the test programs run over Simple_cartesian<Gmpq> (exact and interval
// coefficients, the precision retry's MPFI solve, solve_family), declared here and
// instantiated once, in solve_scene_instances_*.cpp (the library ri_test_solve_scene that every
// test program links; solve_family() in ri_test_solve_family, which only test_solve_family
// links, so that the sanitizers' smoke build does not compile it), not in each of the ten
// programs that call them: each is one to two minutes of g++ -O3 (the whole pipeline), and
// CI's build of the tests took 36 minutes on 2 cores before. The files build in parallel;
// each instantiates its part and declares the others extern.

#ifndef RIGID_INCIDENCE_TEST_SOLVE_SCENE_INSTANCES_H
#define RIGID_INCIDENCE_TEST_SOLVE_SCENE_INSTANCES_H

#include <CGAL/Gmpq.h>
#include <CGAL/Interval_nt.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Rigid_incidence.h>

namespace CGAL {
namespace Rigid_incidence {
namespace test_instances {
typedef Rigid_incidence_traits<CGAL::Simple_cartesian<CGAL::Gmpq>> Traits;
typedef Rigid_body_collection<Traits> Collection;
typedef CGAL::Interval_nt<false> I;
} // namespace test_instances
} // namespace Rigid_incidence
} // namespace CGAL

// EXTERN is `extern` (a declaration) or nothing (the instantiation)
#define RIGID_INCIDENCE_TEST_UNSCALED(EXTERN, IT, NT)                                                                   \
  EXTERN template CGAL::Rigid_incidence::Scene_solve_result CGAL::Rigid_incidence::internal::solve_scene_unscaled<     \
      IT, NT, CGAL::Rigid_incidence::test_instances::Traits>(                                                          \
      const CGAL::Rigid_incidence::test_instances::Collection&, const CGAL::Rigid_incidence::test_instances::Collection&, \
      const CGAL::Rigid_incidence::Incidence_tree&, const CGAL::Rigid_incidence::Well_formed_selection&,                 \
      const CGAL::Rigid_incidence::Scene_solve_parameters&, double, const CGAL::Rigid_incidence::internal::Scene_retry*, \
      std::set<CGAL::Rigid_incidence::internal::Scene_combination>*);
#define RIGID_INCIDENCE_TEST_SOLVE_SCENE(EXTERN, NT)                                                                    \
  EXTERN template CGAL::Rigid_incidence::Scene_solve_result CGAL::Rigid_incidence::solve_scene<                        \
      CGAL::Rigid_incidence::test_instances::I, NT, CGAL::Rigid_incidence::test_instances::Traits>(                    \
      const CGAL::Rigid_incidence::test_instances::Collection&, const CGAL::Rigid_incidence::test_instances::Collection&, \
      const CGAL::Rigid_incidence::Incidence_tree&, const CGAL::Rigid_incidence::Well_formed_selection&,                 \
      const CGAL::Rigid_incidence::Scene_solve_parameters&);
#define RIGID_INCIDENCE_TEST_SOLVE_FAMILY(EXTERN)                                                                       \
  EXTERN template CGAL::Rigid_incidence::Family_result CGAL::Rigid_incidence::solve_family<                           \
      CGAL::Rigid_incidence::test_instances::I, CGAL::Rigid_incidence::test_instances::Traits>(                        \
      const CGAL::Rigid_incidence::test_instances::Collection&, const std::string&, const std::string&,                 \
      const CGAL::Gmpq&, const CGAL::Gmpq&, const CGAL::Rigid_incidence::Family_parameters&);

// RIGID_INCIDENCE_TEST_INSTANTIATE: which part the including file instantiates (1 to 5), 0 none
#ifndef RIGID_INCIDENCE_TEST_INSTANTIATE
#define RIGID_INCIDENCE_TEST_INSTANTIATE 0
#endif
#if RIGID_INCIDENCE_TEST_INSTANTIATE != 1
RIGID_INCIDENCE_TEST_UNSCALED(extern, CGAL::Rigid_incidence::test_instances::I, CGAL::Gmpq)
#endif
#if RIGID_INCIDENCE_TEST_INSTANTIATE != 2
RIGID_INCIDENCE_TEST_UNSCALED(extern, CGAL::Rigid_incidence::test_instances::I, CGAL::Rigid_incidence::test_instances::I)
#endif
#if defined(CGAL_USE_MPFI) && RIGID_INCIDENCE_TEST_INSTANTIATE != 3
RIGID_INCIDENCE_TEST_UNSCALED(extern, CGAL::Gmpfi, CGAL::Gmpfi)
#endif
#if RIGID_INCIDENCE_TEST_INSTANTIATE != 4
RIGID_INCIDENCE_TEST_SOLVE_SCENE(extern, CGAL::Gmpq)
RIGID_INCIDENCE_TEST_SOLVE_SCENE(extern, CGAL::Rigid_incidence::test_instances::I)
#endif
#if RIGID_INCIDENCE_TEST_INSTANTIATE != 5
RIGID_INCIDENCE_TEST_SOLVE_FAMILY(extern)
#endif

#endif
