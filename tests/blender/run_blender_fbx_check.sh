#!/bin/sh
# ctest `blender_fbx_import`: writes the sample take's markers as FBX (`mocap convert`, Y-up in cm,
# and Z-up in mm) and the sample's solve on the bundled ICT FaceKit rig as FBX beside its weight
# CSV (`mocap solve`), opens them in Blender's FBX importer with check_fbx.py (one empty per marker
# at the marker positions within 0.01 mm, one shape key per rig shape equal to the weight CSV within
# 1e-4 at every frame), the same with key reduction (within the tolerance), and has `assimp info`
# read each file as a second reader. Exits 77 (reported
# as skipped) when Blender is missing; without assimp (Debian's assimp-utils) it says so and checks
# with Blender alone.
#   run_blender_fbx_check.sh MOCAP BLENDER SAMPLE_DIR
set -eu
mocap="$1" blender="$2" sample="$3"
if ! command -v "$blender" >/dev/null 2>&1; then
  echo "SKIPPED: blender not found (Debian package 'blender')"
  exit 77
fi
here="$(cd "$(dirname "$0")" && pwd)"
out="$(mktemp -d "${TMPDIR:-/tmp}/mocap-blender-fbx.XXXXXX")"
trap 'rm -rf "$out"' EXIT
take="$sample/Facial-Sing.c3d"

"$mocap" convert "$take" "$out/take.csv" >/dev/null
"$mocap" convert "$take" "$out/take_y_cm.fbx" --up y --units cm >/dev/null 2>&1
"$mocap" convert "$take" "$out/take_z_mm.fbx" --up z >/dev/null 2>&1
solve() {
  "$mocap" solve --mesh "$sample/ict_face_rig.glb" --binding "$sample/Facial-Sing.ict_face_rig.binding.json" \
    --take "$take" --leave-out 0 "$@" >/dev/null
}
solve -o "$out/rig.fbx"
solve -o "$out/weights.csv"
# Key reduction: each curve keyed within 0.1 mm (markers) or 0.01 (weights) of every frame.
"$mocap" convert "$take" "$out/take_reduced.fbx" --reduce 0.1 >/dev/null 2>&1
solve -o "$out/rig_reduced.fbx" --reduce 0.01

status=0
if command -v assimp >/dev/null 2>&1; then
  for file in take_y_cm.fbx take_z_mm.fbx rig.fbx take_reduced.fbx rig_reduced.fbx; do
    if assimp info "$out/$file" >"$out/assimp.txt" 2>&1; then
      echo "PASS: assimp info $file: $(grep -E '^(Nodes|Meshes|Animations|Animation Channels): +[0-9]' "$out/assimp.txt" | tr -s ' \n' ' ')"
    else
      echo "FAIL: assimp info $file:"; cat "$out/assimp.txt"; status=1
    fi
  done
else
  echo "NOTE: assimp not found (Debian package 'assimp-utils'): the second reader is not run"
fi

"$blender" -b --factory-startup --python-exit-code 1 --python "$here/check_fbx.py" -- \
  --markers "$out/take_y_cm.fbx" "$out/take.csv" y \
  --markers "$out/take_z_mm.fbx" "$out/take.csv" z \
  --rig "$out/rig.fbx" "$out/weights.csv" \
  --tolerance 0.1 --markers "$out/take_reduced.fbx" "$out/take.csv" z \
  --tolerance 0.01 --rig "$out/rig_reduced.fbx" "$out/weights.csv" || status=$?
exit "$status"
