// Copyright (c) 2026 Rigid_incidence contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Part 5 of the instantiations solve_scene_instances.h declares: solve_family() (the library
// ri_test_solve_family, which test_solve_family links).

#define RIGID_INCIDENCE_TEST_INSTANTIATE 5
#include "solve_scene_instances.h"

RIGID_INCIDENCE_TEST_SOLVE_FAMILY()
