#!/usr/bin/env bash
# Fuzzes the scene reader (and the analysis behind it) with libFuzzer, ASan and UBSan.
# Usage: scripts/fuzz.sh [SECONDS] [extra libFuzzer arguments]     (default 300 s)
# Environment: FUZZ_BUILD_DIR (default <repo>/build-fuzz), FUZZ_CORPUS (scratch corpus,
# default <build>/corpus), FUZZ_JOBS (build parallelism, default 2).
# Seeds: examples/Rigid_incidence/data/*.json and the past reproducers in
# test/Rigid_incidence/fuzz/crashes/ (read only; new inputs go to the scratch corpus), so a
# regression of a fixed finding stops the run at once.
# Findings (crash-*, timeout-*, leak-*, oom-*) are written to <build>/artifacts/.
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
seconds="${1:-300}"
if [ $# -gt 0 ]; then shift; fi
build="${FUZZ_BUILD_DIR:-$root/build-fuzz}"
corpus="${FUZZ_CORPUS:-$build/corpus}"
artifacts="$build/artifacts"

# clang and its runtime libraries (libFuzzer, sanitizers), plus the usual dependencies.
"$root/scripts/install_deps.sh" clang libclang-rt-14-dev

CXX=clang++ cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DRIGID_INCIDENCE_FUZZ=ON -DRIGID_INCIDENCE_BUILD_TESTS=OFF -DRIGID_INCIDENCE_BUILD_EXAMPLES=OFF >/dev/null
cmake --build "$build" -j"${FUZZ_JOBS:-2}" --target fuzz_read_scene

mkdir -p "$corpus" "$artifacts"
fuzzer="$(find "$build" -name fuzz_read_scene -type f -perm -u+x | head -n1)"
echo "fuzz: running $fuzzer for $seconds s (corpus $corpus, findings in $artifacts)"
# The first corpus directory receives new inputs; the others only seed.
seeds=("$root/examples/Rigid_incidence/data")
if [ -d "$root/test/Rigid_incidence/fuzz/crashes" ]; then seeds+=("$root/test/Rigid_incidence/fuzz/crashes"); fi
UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1" \
"$fuzzer" "$corpus" "${seeds[@]}" \
  -dict="$root/test/Rigid_incidence/fuzz/scene.dict" \
  -max_len=4096 -timeout=10 -rss_limit_mb=2048 -max_total_time="$seconds" \
  -print_final_stats=1 -artifact_prefix="$artifacts/" "$@"
