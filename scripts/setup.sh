#!/usr/bin/env bash
# Shared set-up for scripts/studio.sh and scripts/test.sh: installs the Debian/Ubuntu packages
# that are missing (with sudo when not root), then configures and builds in build/.
# Usage: scripts/setup.sh [extra cmake -D options...]
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"

# Never libvtk9-qt-dev: it drags in the Qt 5 stack.
packages=(
  cmake make g++ clang pkg-config
  qt6-base-dev qt6-tools-dev qt6-l10n-tools
  libvtk9-dev libeigen3-dev libcli11-dev
  libgtest-dev libgmock-dev libbenchmark-dev
  nlohmann-json3-dev libtinygltf-dev
  libopencv-videoio-dev libopencv-imgproc-dev
  xvfb xauth libgl1-mesa-dri
  parallel chromium  # GNU parallel runs `mocap clean --index` in a cli test; Chromium renders the archive report (gui)
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

install_missing_packages
jobs="$(nproc 2>/dev/null || echo 2)"
cmake -S "$root" -B "$root/build" -DCMAKE_BUILD_TYPE=RelWithDebInfo "$@" >/dev/null
cmake --build "$root/build" -j "$jobs"
