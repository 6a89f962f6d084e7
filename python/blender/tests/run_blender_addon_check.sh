#!/bin/sh
# ctest `blender_addon`: the Mocap Studio add-on zip installed in Debian's Blender imports the
# sample take as empties, once through the mocap Python module (which must import inside Blender)
# and once through the mocap command line (the fallback for Blender builds with their own Python);
# then keys the bundled rig's shape keys (its GLB imported) from `mocap solve`'s weight CSV and,
# through the arkit_to_ict map, its Live Link Face CSV. Exits 77 (skipped) when Blender is missing.
#   run_blender_addon_check.sh BLENDER MOCAP ZIP PYTHON_DIR TAKE RIG BINDING
set -eu
blender="$1" mocap="$2" zip="$3" module_dir="$4" take="$5" rig="$6" binding="$7"
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
weights() {
  BLENDER_USER_SCRIPTS="$out/scripts-weights" BLENDER_USER_CONFIG="$out/config-weights" \
    "$blender" -b --factory-startup --python-exit-code 1 --python "$here/check_weights.py" -- \
    "$zip" "$rig" "$out/weights.csv" "$out/livelink.csv" "$take" "$binding"
}
MOCAP_PYTHON_PATH="$module_dir" MOCAP_CLI= check module
MOCAP_PYTHON_PATH= MOCAP_CLI="$mocap" check cli
solve() { "$mocap" solve --mesh "$rig" --binding "$binding" --take "$take" --leave-out 0 "$@" >/dev/null; }
solve -o "$out/weights.csv"
solve -o "$out/livelink.csv" --format livelink
MOCAP_PYTHON_PATH="$module_dir" MOCAP_CLI= weights
