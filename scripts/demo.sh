#!/usr/bin/env bash
# The main job: install what is missing, build, analyze the shipped tetra scene and solve it:
# every real configuration, certified, drawn side by side in an SVG gallery.
# Usage: scripts/demo.sh [SCENE.json]   (default: examples/Rigid_incidence/data/tetra.json)
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
"$root/scripts/install_deps.sh"
build="${BUILD_DIR:-$root/build}"
cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release -DRIGID_INCIDENCE_BUILD_TESTS=OFF >/dev/null
cmake --build "$build" --target rigid_incidence -j2
scene="${1:-$root/examples/Rigid_incidence/data/tetra.json}"
"$build/examples/Rigid_incidence/rigid_incidence" analyze "$scene" --dot "$build/overlap_graph.dot"
if command -v dot >/dev/null; then
  dot -Tsvg "$build/overlap_graph.dot" -o "$build/overlap_graph.svg"
  echo
  echo "overlap graph with the incidence tree: $build/overlap_graph.svg"
fi
echo
"$build/examples/Rigid_incidence/rigid_incidence" solve "$scene" --svg "$build/configurations.svg"
echo
echo "the configurations side by side: $build/configurations.svg"

