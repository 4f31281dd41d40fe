// Copyright (c) 2026 Rigid_incidence contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Part 3 of the instantiations solve_scene_instances.h declares: the precision retry (MPFI).

#define RIGID_INCIDENCE_TEST_INSTANTIATE 3
#include "solve_scene_instances.h"

#ifdef CGAL_USE_MPFI
RIGID_INCIDENCE_TEST_UNSCALED(, CGAL::Gmpfi, CGAL::Gmpfi)
#endif
