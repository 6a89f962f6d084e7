#!/bin/sh
# ctest `blender_import`: writes the animation exports with the built `mocap` CLI (a BVH of the
# sample take, an OBJ sequence and an OBJ + PC2 cache of the deformed MediaPipe face, a solved
# blendshape rig as GLB with its weight curves as CSV) and opens
# them in Blender with check_exports.py, which also has Blender export the rig again as GLB and
# reads that with `mocap rig`. Exits 77 (reported as skipped) when Blender is missing.
#   run_blender_check.sh MOCAP BLENDER TEST_DATA_DIR SAMPLE_TAKE
set -eu
mocap="$1" blender="$2" data="$3" sample="$4"
if ! command -v "$blender" >/dev/null 2>&1; then
  echo "SKIPPED: blender not found (Debian package 'blender')"
  exit 77
fi
here="$(cd "$(dirname "$0")" && pwd)"
out="$(mktemp -d "${TMPDIR:-/tmp}/mocap-blender.XXXXXX")"
trap 'rm -rf "$out"' EXIT
mesh="$data/face_mesh/canonical_face_model.obj"
stabilize=root-1,root-2,root-3,root-4,root-5,root-6
markers=""
for section in 1 2 3 4 5 6 7 8 9 10 11 12 13 14; do
  count=2
  if [ "$section" -eq 10 ] || [ "$section" -ge 13 ]; then count=3; fi
  for k in $(seq 1 "$count"); do markers="${markers:+$markers,}section$section-$k"; done
done

"$mocap" bind --mesh "$mesh" --take "$sample" --stabilize "$stabilize" --markers "$markers" -o "$out/bind.json" >/dev/null
deform() {
  "$mocap" deform --mesh "$mesh" --binding "$out/bind.json" --take "$sample" --stabilize "$stabilize" \
    --frames 1:12 --leave-out 0 "$@" >/dev/null
}
deform -o "$out/face.pc2"
deform -o "$out/sequence"
"$mocap" convert "$sample" "$out/take.bvh" >/dev/null

# A three-shape rig of the same face (each shape lifts a band of vertices along one axis), solved
# from the same binding to a GLB and to weight curves.
mkdir "$out/shapes"
shape() {  # NAME FIRST LAST AXIS(2..4 = x..z column) OFFSET
  awk -v first="$2" -v last="$3" -v axis="$4" -v offset="$5" \
    '/^v /{n++; if (n >= first && n <= last) $axis += offset} {print}' "$mesh" >"$out/shapes/$1.obj"
}
shape jawOpen 1 40 3 -0.8
shape browInnerUp 150 190 3 0.5
shape mouthSmile_L 300 340 2 0.6
solve() {
  "$mocap" solve --mesh "$mesh" --shapes "$out/shapes" --binding "$out/bind.json" --take "$sample" \
    --stabilize "$stabilize" --leave-out 0 "$@" >/dev/null
}
solve -o "$out/rig.glb"
solve -o "$out/weights.csv"

# Blender's glTF importer needs numpy (Debian's python3-numpy, only recommended by blender).
glb=""
if "$blender" -b --factory-startup --python-exit-code 1 --python-expr "import numpy" >/dev/null 2>&1; then
  glb="--glb"
else
  echo "NOTE: Blender's Python has no numpy (python3-numpy), so the GLB import is not checked"
fi

# Frame 5 of the sequence is sample 4 of the cache: the two exports must agree.
status=0
"$blender" -b --factory-startup --python-exit-code 1 --python "$here/check_exports.py" -- \
  "$out/take.bvh" "$out/sequence/canonical_face_model_0005.obj" "$out/face.pc2" 4 \
  ${glb:+--glb "$out/rig.glb" "$out/weights.csv" --mocap "$mocap"} || status=$?
exit "$status"
