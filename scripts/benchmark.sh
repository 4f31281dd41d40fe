#!/usr/bin/env bash
# Builds and runs the benchmarks; writes readable tables (Markdown) and CSV under
# build-bench/results/. Not part of the test run.
# Usage: scripts/benchmark.sh [MAX_BODIES (default 40)] [REPEATS (default 5)]
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
"$root/scripts/install_deps.sh"
build="${BENCH_BUILD_DIR:-$root/build-bench}"
cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release -DRIGID_INCIDENCE_BUILD_BENCHMARKS=ON \
      -DRIGID_INCIDENCE_BUILD_TESTS=OFF -DRIGID_INCIDENCE_BUILD_EXAMPLES=ON >/dev/null
cmake --build "$build" -j2
mkdir -p "$build/results"
"$build/benchmark/Rigid_incidence/benchmark_incidence_tree" "$build/results/incidence_tree" "${1:-40}" "${2:-5}"
echo
cat "$build/results/incidence_tree.md"
"$build/benchmark/Rigid_incidence/benchmark_well_formed_selection" "$build/results/well_formed_selection" 10000 3
echo
cat "$build/results/well_formed_selection.md"
# Reduced systems against the papers' naive formulations (scenes of up to 30 bodies, 3 seeds
# each; a system that takes more than 20 s to build is skipped); also writes reduced_system.svg.
"$build/benchmark/Rigid_incidence/benchmark_reduced_system" "$build/results/reduced_system" 30 3
echo
cat "$build/results/reduced_system.md"
# The subdivision solver on the paper scenes and stewart_gough40: time, boxes and achieved
# accuracy against the tolerance (double, Gmpfi 113/256 bits against a 512-bit reference), fast
# against certified, the naive formulations under the same solver, and PHCpack (phc -b) when
# installed (3 repeats, 20 s per cell, 60 s for stewart_gough40; about 8 to 10 minutes); also
# writes solver.svg.
"$build/benchmark/Rigid_incidence/benchmark_solver" "$build/results/solver" 3 20 60
echo
cat "$build/results/solver.md"
# Solving along a solution plan against the whole system, with and without inequalities: the
# paper's parallelogram and random block-triangular systems of 4 to 30 variables (2 seeds, the
# whole-system solve capped at 10 s); also writes plan.svg.
"$build/benchmark/Rigid_incidence/benchmark_plan" "$build/results/plan" 2 10 30
echo
cat "$build/results/plan.md"
# Issue 28's scene families (chains, rings, trees of bodies, molecular rings, stacked platforms,
# braced strips; planted, scripts/make_scene_family.py) at growing sizes until a solve is not
# complete within 60 s; the tool of this build, and side by side the one RI_BASELINE_TOOL names
# (another build, e.g. of an older commit); also writes scene_families.svg. Up to about 15 minutes.
baseline=()
[ -n "${RI_BASELINE_TOOL:-}" ] && baseline=(--tool "before=$RI_BASELINE_TOOL")
python3 "$root/benchmark/Rigid_incidence/scene_families.py" "${baseline[@]}" \
        --tool "now=$build/examples/Rigid_incidence/rigid_incidence" --out "$build/results/scene_families"
echo
cat "$build/results/scene_families.md"
