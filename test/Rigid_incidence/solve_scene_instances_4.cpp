// Copyright (c) 2026 Rigid_incidence contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Part 4 of the instantiations solve_scene_instances.h declares: solve_scene().

#define RIGID_INCIDENCE_TEST_INSTANTIATE 4
#include "solve_scene_instances.h"

RIGID_INCIDENCE_TEST_SOLVE_SCENE(, CGAL::Gmpq)
RIGID_INCIDENCE_TEST_SOLVE_SCENE(, CGAL::Rigid_incidence::test_instances::I)
