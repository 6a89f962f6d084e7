#!/usr/bin/env bash
# Shared set-up for scripts/studio.sh and scripts/test.sh: installs the Debian/Ubuntu packages
# that are missing (with sudo when not root), then configures and builds in build/.
# Usage: scripts/setup.sh [--target TARGET]... [extra cmake -D options...]
#   --target  build only TARGET (repeatable; default: everything). scripts/studio.sh builds the studio.
# Prints how long each step took (seconds) and, when ccache is in use, the build's cache hit rate.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
# shellcheck source=scripts/build_report.sh
. "$root/scripts/build_report.sh"

targets=()
cmake_options=()
while [ $# -gt 0 ]; do
  case "$1" in
    --target) targets+=(--target "$2"); shift 2 ;;
    *) cmake_options+=("$1"); shift ;;
  esac
done

# Never libvtk9-qt-dev: it drags in the Qt 5 stack. ccache, lld and ninja only make builds faster: the
# build goes on without them (and says so) where they cannot be installed.
packages=(
  cmake make ninja-build g++ clang pkg-config ccache lld
  qt6-base-dev qt6-tools-dev qt6-l10n-tools
  qt6-translations-l10n  # Qt's own texts (OK, Cancel, file dialogs) in the studio's languages
  libvtk9-dev libeigen3-dev libcli11-dev
  libgtest-dev libgmock-dev libbenchmark-dev
  nlohmann-json3-dev libtinygltf-dev
  libopencv-videoio-dev libopencv-imgproc-dev
  xvfb xauth libgl1-mesa-dri
  parallel chromium  # GNU parallel runs `mocap clean --index` in a cli test; Chromium renders the archive report (gui)
  pybind11-dev python3-dev python3-numpy python3-pytest  # the `mocap` Python module and its tests (label python)
  liblo-tools  # oscdump reads `mocap stream --protocol vmc` in a cli test
)

install_missing_packages() {
  command -v dpkg-query >/dev/null || { echo "setup: not a Debian/Ubuntu system; install the packages by hand: ${packages[*]}" >&2; return 0; }
  local missing=()
  for p in "${packages[@]}"; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
  done
  [ ${#missing[@]} -eq 0 ] && return 0
  echo "setup: installing ${missing[*]}"
  local sudo=()
  [ "$(id -u)" -ne 0 ] && sudo=(sudo)
  "${sudo[@]}" apt-get update -qq
  DEBIAN_FRONTEND=noninteractive "${sudo[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
}

phase_start
install_missing_packages
phase_end "packages"

jobs="$(nproc 2>/dev/null || echo 2)"
phase_start
configure_quietly "$root/build" -DCMAKE_BUILD_TYPE=RelWithDebInfo "${cmake_options[@]}"
phase_end "configure"

phase_start
reset_ccache_log "$root/build"
cmake --build "$root/build" -j "$jobs" "${targets[@]}"
phase_end "build"
report_ccache "$root/build"
