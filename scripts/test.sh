#!/usr/bin/env bash
# Command 2 of the README: the same set-up, then the whole test suite through ctest.
#  1. build/        RelWithDebInfo, every test (GUI tests under xvfb-run);
#  2. build-asan/   clang with AddressSanitizer + UBSan: core and CLI tests again, plus a short
#                   libFuzzer run of the C3D and TRC readers. Skip with MOCAP_SKIP_SANITIZERS=1.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
jobs="$(nproc 2>/dev/null || echo 2)"
"$root/scripts/setup.sh" -DMOCAP_WERROR=ON

run_ctest() {
  local dir="$1"; shift
  if command -v xvfb-run >/dev/null; then
    (cd "$dir" && xvfb-run -a -s "-screen 0 1280x1024x24" ctest --output-on-failure -j "$jobs" "$@")
  else
    (cd "$dir" && ctest --output-on-failure -j "$jobs" "$@")
  fi
}

run_ctest "$root/build"

if [ "${MOCAP_SKIP_SANITIZERS:-0}" != 1 ] && command -v clang++ >/dev/null; then
  echo "== AddressSanitizer/UBSan build with libFuzzer targets (build-asan/)"
  # Debug keeps assertions (Eigen's bounds checks among them); -O1 makes Eigen-heavy tests several
  # times faster than -O0 without hiding what the sanitizers see.
  cmake -S "$root" -B "$root/build-asan" -DCMAKE_BUILD_TYPE=Debug \
    -DCMAKE_C_COMPILER=clang -DCMAKE_CXX_COMPILER=clang++ \
    -DCMAKE_C_FLAGS_DEBUG="-g -O1" -DCMAKE_CXX_FLAGS_DEBUG="-g -O1" \
    -DMOCAP_SANITIZE=ON -DMOCAP_BUILD_FUZZ=ON -DMOCAP_BUILD_BENCH=OFF -DMOCAP_WERROR=ON >/dev/null
  cmake --build "$root/build-asan" -j "$jobs"
  (cd "$root/build-asan" && ASAN_OPTIONS=detect_leaks=1 ctest --output-on-failure -j "$jobs" -L 'core|cli|fuzz')
fi
echo "All tests passed."
