#!/bin/sh
# Leave-markers-out quality of `mocap deform` (issue 5): for each take and mesh, bind the markers
# (ICP, no user pairs), then report the leave-20%-out error (mm) of every method and
# kernel/weighting. Usage: scripts/deform_quality.sh [BUILD_DIR] (default build). Reads the ICT
# FaceKit mesh and the AnimFace takes from ../shared/data when present.
set -eu
root=$(cd "$(dirname "$0")/.." && pwd)
mocap="${1:-$root/build}/bin/mocap"
shared="$root/../shared/data"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

sing="$root/resources/sample/Facial-Sing.c3d"
heads="root-1,root-2,root-3,root-4,root-5,root-6"
faces=""
for s in 1 2 3 4 5 6 7 8 9 10 11 12 13 14; do
  count=2; case $s in 10|13|14) count=3 ;; esac
  k=1; while [ $k -le $count ]; do faces="$faces${faces:+,}section$s-$k"; k=$((k + 1)); done
done

meshes="mediapipe=$root/tests/data/face_mesh/canonical_face_model.obj"
[ -f "$shared/face_mesh/ict_facekit/generic_neutral_mesh.obj" ] &&
  meshes="$meshes ict=$shared/face_mesh/ict_facekit/generic_neutral_mesh.obj"

# take name | file | bind/deform extra flags
takes="sing|$sing|--stabilize $heads"
for t in CheeksMoCap NoseMoCap; do
  f="$shared/facial_mocap/animface_bournemouth/derived_trc/$t.trc"
  [ -f "$f" ] && takes="$takes
$t|$f|"
done

variants="rbf-exp|--method rbf --kernel exp
rbf-exp-regions|--method rbf --kernel exp --regions
rbf-gaussian-r5|--method rbf --kernel gaussian --radius 5
rbf-biharmonic|--method rbf --kernel biharmonic
rbf-thin-plate|--method rbf --kernel thin-plate
rbf-thin-plate-regions|--method rbf --kernel thin-plate --regions
laplacian-uniform|--method laplacian --weights uniform
laplacian-cotangent|--method laplacian --weights cotangent
laplacian-mean-value|--method laplacian --weights mean-value
laplacian-mean-value-w10|--method laplacian --weights mean-value --constraint-weight 10
laplacian-mean-value-rot2|--method laplacian --weights mean-value --rotations 2"

number() { sed -n "s/.*\"$1\": \([-0-9.e]*\).*/\1/p" | head -n 1; }

printf '%-12s %-10s %-26s %9s %9s %10s %11s\n' take mesh variant error_mm rest_mm setup_s frame_ms
echo "$takes" | while IFS='|' read -r name file extra; do
  for entry in $meshes; do
    mesh=${entry%%=*}; path=${entry#*=}
    markers=""; [ "$name" = sing ] && markers="--markers $faces"
    vertices=""; [ "$mesh" = ict ] && vertices="--vertices 0:6705"
    # shellcheck disable=SC2086
    "$mocap" bind --mesh "$path" --take "$file" $extra $markers $vertices -o "$work/bind.json" >/dev/null 2>&1
    echo "$variants" | while IFS='|' read -r label flags; do
      # Rotation-aware iterations re-solve per frame: too slow over whole takes on ICT's 26 719 vertices.
      case "$mesh-$label" in ict-*-rot*) continue ;; esac
      # shellcheck disable=SC2086
      json=$("$mocap" deform --mesh "$path" --binding "$work/bind.json" --take "$file" $extra $flags \
        --frames 1:2 -o "$work/out.pc2" --json 2>"$work/err.txt") || {
        printf '%-12s %-10s %-26s failed: %s\n' "$name" "$mesh" "$label" "$(head -n 1 "$work/err.txt")"; continue; }
      printf '%-12s %-10s %-26s %9.3f %9.3f %10.4f %11.4f\n' "$name" "$mesh" "$label" \
        "$(echo "$json" | number leave_out_error_mm)" "$(echo "$json" | number rest_error_mm)" \
        "$(echo "$json" | number setup_seconds)" \
        "$(echo "$json" | number frame_seconds_mean | awk '{ print $1 * 1000 }')"
    done
  done
done
