#!/bin/sh
# ctest `blender_addon`: the Mocap Studio add-on zip installed in Debian's Blender imports the
# sample take as empties, once through the mocap Python module (which must import inside Blender)
# and once through the mocap command line (the fallback for Blender builds with their own Python).
# Exits 77 (reported as skipped) when Blender is missing.
#   run_blender_addon_check.sh BLENDER MOCAP ZIP PYTHON_DIR TAKE
set -eu
blender="$1" mocap="$2" zip="$3" module_dir="$4" take="$5"
if ! command -v "$blender" >/dev/null 2>&1; then
  echo "SKIPPED: blender not found (Debian package 'blender')"
  exit 77
fi
here="$(cd "$(dirname "$0")" && pwd)"
out="$(mktemp -d "${TMPDIR:-/tmp}/mocap-blender-addon.XXXXXX")"
trap 'rm -rf "$out"' EXIT
"$mocap" convert "$take" "$out/take.csv" >/dev/null
check() {
  # A user scripts folder of its own, so installing the add-on leaves the user's Blender alone.
  BLENDER_USER_SCRIPTS="$out/scripts-$1" BLENDER_USER_CONFIG="$out/config-$1" \
    "$blender" -b --factory-startup --python-exit-code 1 --python "$here/check_addon.py" -- \
    "$zip" "$take" "$out/take.csv" "$1"
}
MOCAP_PYTHON_PATH="$module_dir" MOCAP_CLI= check module
MOCAP_PYTHON_PATH= MOCAP_CLI="$mocap" check cli
