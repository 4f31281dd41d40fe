#!/usr/bin/env bash
# Runs the test suite: install what is missing, build, ctest; then a smoke set (label
# 'sanitize': the random planted scenes, which reach every stage of the pipeline, and the
# reader on malformed input) built with AddressSanitizer and UndefinedBehaviorSanitizer.
# The build dominates (CI's run: 24 min at de5cb5d, 40 min at 54396c0 without the sanitizer
# pass; a clean run here 42 min at 7de07e7). Since then the whole-scene solves are
# instantiated once for all test programs (test/Rigid_incidence/solve_scene_instances.h), the
# tests build at -O1 and the sanitizer smoke set at -O0: build 20 min, tests 3 min, sanitizer
# build 7.5 min and run 3 min here.
# Usage: scripts/test.sh [--no-sanitize] [--sanitize-only] [--sanitize-core] [--sanitize-all] [extra ctest arguments]
#   --sanitize-core: the core set under the sanitizers (label 'core': reader, standardize,
#                    placements, solver, random scenes and the CLI; about 20 minutes more)
#   --sanitize-all:  every test under them (about 30 minutes more)
# Run one of these once per change (the developers' rule); CI runs the smoke set.
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
plain=1; sanitize=1; sanitize_set=smoke; ctest_args=()
for a in "$@"; do
  case "$a" in
    --no-sanitize) sanitize=0 ;;
    --sanitize-only) plain=0 ;;
    --sanitize-core) sanitize_set=core ;;
    --sanitize-all) sanitize_set=all ;;
    *) ctest_args+=("$a") ;;
  esac
done
"$root/scripts/install_deps.sh"
run() { # build dir, target ('all', ri_core_tests or ri_sanitize_tests), extra cmake args
  local build="$1" target="$2"; shift 2
  local label=()
  [ "$target" = ri_core_tests ] && label=(-L core)
  [ "$target" = ri_sanitize_tests ] && label=(-L sanitize)
  cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release -DRIGID_INCIDENCE_BUILD_TESTS=ON "$@" >/dev/null
  cmake --build "$build" -j2 --target "$target"
  (cd "$build" && ctest --output-on-failure -j2 "${label[@]}" "${ctest_args[@]}")
}
if [ $plain -eq 1 ]; then
  echo "== tests =="
  run "${BUILD_DIR:-$root/build}" all
fi
if [ $sanitize -eq 1 ]; then
  case "$sanitize_set" in
    smoke) target=ri_sanitize_tests ;;
    core) target=ri_core_tests ;;
    all) target=all ;;
  esac
  echo "== tests under AddressSanitizer + UndefinedBehaviorSanitizer ($target) =="
  # -O0: g++ with the sanitizers takes 156 s on a whole-scene solve instance at -O0, 188 s with
  # -g1 and 425 s at -O1 -g1; the tests run a few times slower, far less than that (reports name
  # the functions; for line numbers configure a build of your own with -g)
  run "${SANITIZE_BUILD_DIR:-$root/build-sanitize}" "$target" -DRIGID_INCIDENCE_SANITIZE=ON -DCMAKE_BUILD_TYPE=Debug \
      "-DCMAKE_CXX_FLAGS_DEBUG=-O0" -DCGAL_DO_NOT_WARN_ABOUT_CMAKE_BUILD_TYPE=TRUE
fi
