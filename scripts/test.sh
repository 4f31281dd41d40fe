#!/usr/bin/env bash
# Runs the test suite: install what is missing, build, ctest; then the same tests built
# with AddressSanitizer and UndefinedBehaviorSanitizer.
# Usage: scripts/test.sh [--no-sanitize] [--sanitize-only] [extra ctest arguments]
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
plain=1; sanitize=1; ctest_args=()
for a in "$@"; do
  case "$a" in
    --no-sanitize) sanitize=0 ;;
    --sanitize-only) plain=0 ;;
    *) ctest_args+=("$a") ;;
  esac
done
"$root/scripts/install_deps.sh"
run() { # build dir, extra cmake args
  local build="$1"; shift
  cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release -DRIGID_INCIDENCE_BUILD_TESTS=ON "$@" >/dev/null
  cmake --build "$build" -j2
  (cd "$build" && ctest --output-on-failure -j2 "${ctest_args[@]}")
}
if [ $plain -eq 1 ]; then
  echo "== tests =="
  run "${BUILD_DIR:-$root/build}"
fi
if [ $sanitize -eq 1 ]; then
  echo "== tests under AddressSanitizer + UndefinedBehaviorSanitizer =="
  # -O1 -g1: quicker to compile than -O2 -g, still fast enough to run, with line numbers in reports
  run "${SANITIZE_BUILD_DIR:-$root/build-sanitize}" -DRIGID_INCIDENCE_SANITIZE=ON -DCMAKE_BUILD_TYPE=Debug \
      "-DCMAKE_CXX_FLAGS_DEBUG=-O1 -g1" -DCGAL_DO_NOT_WARN_ABOUT_CMAKE_BUILD_TYPE=TRUE
fi
