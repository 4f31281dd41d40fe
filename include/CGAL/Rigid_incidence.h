// Copyright (c) 2026 Rigid_incidence contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Umbrella header of the Rigid_incidence package.

#ifndef CGAL_RIGID_INCIDENCE_H
#define CGAL_RIGID_INCIDENCE_H

#include <CGAL/Rigid_incidence/Input_error.h>
#include <CGAL/Rigid_incidence/Rigid_incidence_traits.h>
#include <CGAL/Rigid_incidence/Rigid_body_collection.h>
#include <CGAL/Rigid_incidence/standardize.h>
#include <CGAL/Rigid_incidence/enclose_coordinates.h>
#include <CGAL/Rigid_incidence/Overlap_graph.h>
#include <CGAL/Rigid_incidence/rdof.h>
#include <CGAL/Rigid_incidence/Incidence.h>
#include <CGAL/Rigid_incidence/is_well_formed.h>
#include <CGAL/Rigid_incidence/well_formed_incidences.h>
#include <CGAL/Rigid_incidence/optimal_incidence_tree.h>
#include <CGAL/Rigid_incidence/rigidity_matroid.h>
#include <CGAL/Rigid_incidence/Polynomial_system.h>
#include <CGAL/Rigid_incidence/Solver_result.h>
#include <CGAL/Rigid_incidence/Subdivision_solver.h>
#include <CGAL/Rigid_incidence/Solution_plan.h>
#include <CGAL/Rigid_incidence/solve_with_plan.h>
#include <CGAL/Rigid_incidence/Curve_tracer.h>
#include <CGAL/Rigid_incidence/trace_curves_with_plan.h>
#include <CGAL/Rigid_incidence/incidence_tree_parametrization.h>
#include <CGAL/Rigid_incidence/Reduced_system.h>
#include <CGAL/Rigid_incidence/Configuration.h>
#include <CGAL/Rigid_incidence/Tree_system.h>
#include <CGAL/Rigid_incidence/solve_tree_system.h>
#include <CGAL/Rigid_incidence/solve_scene.h>
#include <CGAL/Rigid_incidence/solve_family.h>
#include <CGAL/Rigid_incidence/naive_systems.h>
#include <CGAL/Rigid_incidence/IO/read_scene.h>
#include <CGAL/Rigid_incidence/IO/write_dot.h>
#include <CGAL/Rigid_incidence/IO/read_polynomial_system.h>
#include <CGAL/Rigid_incidence/IO/write_plan.h>

#endif
