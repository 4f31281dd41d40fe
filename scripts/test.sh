#!/usr/bin/env bash
# Runs the test suite: install what is missing, build, ctest; then the core tests (label
# 'core': the reader, standardize, placements, solver, random planted scenes and the CLI)
# built with AddressSanitizer and UndefinedBehaviorSanitizer. About 20 minutes on 2 cores.
# Usage: scripts/test.sh [--no-sanitize] [--sanitize-only] [--sanitize-all] [extra ctest arguments]
#   --sanitize-all: every test under the sanitizers (about 30 minutes more; run it once per change)
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
plain=1; sanitize=1; sanitize_all=0; ctest_args=()
for a in "$@"; do
  case "$a" in
    --no-sanitize) sanitize=0 ;;
    --sanitize-only) plain=0 ;;
    --sanitize-all) sanitize_all=1 ;;
    *) ctest_args+=("$a") ;;
  esac
done
"$root/scripts/install_deps.sh"
run() { # build dir, target ('all' or ri_core_tests), extra cmake args
  local build="$1" target="$2"; shift 2
  local label=()
  [ "$target" = all ] || label=(-L core)
  cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release -DRIGID_INCIDENCE_BUILD_TESTS=ON "$@" >/dev/null
  cmake --build "$build" -j2 --target "$target"
  (cd "$build" && ctest --output-on-failure -j2 "${label[@]}" "${ctest_args[@]}")
}
if [ $plain -eq 1 ]; then
  echo "== tests =="
  run "${BUILD_DIR:-$root/build}" all
fi
if [ $sanitize -eq 1 ]; then
  target=ri_core_tests
  [ $sanitize_all -eq 1 ] && target=all
  echo "== tests under AddressSanitizer + UndefinedBehaviorSanitizer ($target) =="
  # -O1 -g1: quicker to compile than -O2 -g, still fast enough to run, with line numbers in reports
  run "${SANITIZE_BUILD_DIR:-$root/build-sanitize}" "$target" -DRIGID_INCIDENCE_SANITIZE=ON -DCMAKE_BUILD_TYPE=Debug \
      "-DCMAKE_CXX_FLAGS_DEBUG=-O1 -g1" -DCGAL_DO_NOT_WARN_ABOUT_CMAKE_BUILD_TYPE=TRUE
fi
