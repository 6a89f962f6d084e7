#!/usr/bin/env bash
# Command 2 of the README: the same set-up, then the whole test suite through ctest.
#  1. build/        RelWithDebInfo, every test (each GUI test on an Xvfb display of its own);
#  2. build-asan/   clang with AddressSanitizer + UBSan, only what it runs (no Qt, VTK or studio):
#                   the core and CLI tests again, then a short libFuzzer run of each file reader.
#                   Skip with MOCAP_SKIP_SANITIZERS=1.
# Prints each phase's time and the compiler cache's hit rate at the end.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
# shellcheck source=scripts/build_report.sh
. "$root/scripts/build_report.sh"
jobs="$(nproc 2>/dev/null || echo 2)"
MOCAP_PHASE_LOG="$(mktemp)"
export MOCAP_PHASE_LOG
finish() {
  local status=$?
  print_phases
  rm -f "$MOCAP_PHASE_LOG"
  exit "$status"
}
trap finish EXIT

"$root/scripts/setup.sh" -DMOCAP_WERROR=ON

run_ctest() {
  local dir="$1"; shift
  (cd "$dir" && ctest --output-on-failure -j "$jobs" "$@")
}

phase_start
command -v Xvfb >/dev/null || echo "== Xvfb not found: GUI tests run on \$DISPLAY (${DISPLAY:-none})"
run_ctest "$root/build"
phase_end "tests"

if [ "${MOCAP_SKIP_SANITIZERS:-0}" = 1 ]; then
  echo "== Sanitizer pass skipped (MOCAP_SKIP_SANITIZERS=1): core, cli and fuzz labels not run under ASan/UBSan"
elif ! command -v clang++ >/dev/null; then
  echo "== Sanitizer pass skipped: clang++ not found (apt-get install clang): core, cli and fuzz labels not run under ASan/UBSan"
else
  echo "== AddressSanitizer/UBSan build with libFuzzer targets (build-asan/)"
  phase_start
  # Debug keeps assertions (Eigen's bounds checks among them); -O1 makes Eigen-heavy tests several
  # times faster than -O0 without hiding what the sanitizers see.
  configure_quietly "$root/build-asan" -DCMAKE_BUILD_TYPE=Debug \
    -DCMAKE_C_COMPILER=clang -DCMAKE_CXX_COMPILER=clang++ \
    -DCMAKE_C_FLAGS_DEBUG="-g -O1" -DCMAKE_CXX_FLAGS_DEBUG="-g -O1" \
    -DMOCAP_SANITIZE=ON -DMOCAP_BUILD_FUZZ=ON -DMOCAP_BUILD_BENCH=OFF -DMOCAP_BUILD_GUI=OFF -DMOCAP_BUILD_PYTHON=OFF -DMOCAP_WERROR=ON
  reset_ccache_log "$root/build-asan"
  cmake --build "$root/build-asan" -j "$jobs"
  phase_end "sanitizer build"
  report_ccache "$root/build-asan"

  phase_start
  # Label realtime: a take streamed for its 30 s of wall-clock time to a Python receiver; its C++
  # (the streamer, the packets) runs under the sanitizers in stream_tests and the stream CLI tests.
  echo "== sanitizer tests: label realtime left to build/ (wall-clock streaming, no code of its own)"
  ASAN_OPTIONS=detect_leaks=1 run_ctest "$root/build-asan" -L 'core|cli' -LE realtime
  phase_end "sanitizer tests"
  phase_start
  ASAN_OPTIONS=detect_leaks=1 run_ctest "$root/build-asan" -L fuzz
  phase_end "fuzz"
fi
report_ccache "$root/build"
echo "All tests passed."
