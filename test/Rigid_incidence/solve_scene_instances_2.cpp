// Copyright (c) 2026 Rigid_incidence contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Part 2 of the instantiations solve_scene_instances.h declares: the solve with interval coefficients.

#define RIGID_INCIDENCE_TEST_INSTANTIATE 2
#include "solve_scene_instances.h"

RIGID_INCIDENCE_TEST_UNSCALED(, CGAL::Rigid_incidence::test_instances::I, CGAL::Rigid_incidence::test_instances::I)
