#!/bin/sh
# Runs every `mocap` command on the bundled sample and writes its --json output (and, for the
# commands that write files, those files' report) into OUTDIR, one file per command, with the
# timing fields removed. Two snapshots are compared with `diff -r` to show that a restructuring
# changed no CLI output. Usage: scripts/cli_json_snapshot.sh OUTDIR [BUILD_DIR] (default build).
set -eu
root=$(cd "$(dirname "$0")/.." && pwd)
out=$1
mocap="${2:-$root/build}/bin/mocap"
sample="$root/resources/sample/Facial-Sing.c3d"
mesh="$root/resources/sample/canonical_face_model.obj"
binding="$root/resources/sample/Facial-Sing.binding.json"
heads="root-1,root-2,root-3,root-4,root-5,root-6"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
mkdir -p "$out"

# Removes timing fields and history timestamps (they differ run to run), names the scratch folder
# WORK, and pretty-prints with sorted keys.
normalise() {
  python3 -c '
import json, sys
TIMING = {"seconds", "setup_seconds", "frame_seconds_mean", "frame_seconds_p95", "time"}
def strip(v):
    if isinstance(v, dict):
        return {k: strip(x) for k, x in v.items() if k not in TIMING}
    if isinstance(v, list):
        return [strip(x) for x in v]
    return v
print(json.dumps(strip(json.load(sys.stdin)), indent=1, sort_keys=True))
' | sed "s|$work|WORK|g" >"$out/$1.json"
}

"$mocap" info "$sample" --json | normalise info
"$mocap" convert "$sample" "$work/sample.trc" >/dev/null
"$mocap" info "$work/sample.trc" --json | normalise convert-trc-info
"$mocap" clean "$sample" -o "$work/clean.c3d" --stabilize "$heads" --report "$work/clean.json" >/dev/null
normalise clean-report <"$work/clean.json"
"$mocap" info "$work/clean.c3d" --json | normalise clean-info
"$mocap" eval-fill "$sample" --copies 2 --lengths 10,60 --json | normalise eval-fill
"$mocap" eval-spikes "$sample" --json | normalise eval-spikes
"$mocap" eval-smooth "$sample" --json | normalise eval-smooth
"$mocap" smooth-table "$sample" --json | normalise smooth-table
"$mocap" pfa "$sample" --stabilize "$heads" --restarts 50 --k 5:12 --json | normalise pfa
"$mocap" pfa "$sample" --method greedy --k 5:8 --json | normalise pfa-greedy
"$mocap" track "$work/sample.trc" -o "$work/tracked.c3d" --template "$sample" --json | normalise track
"$mocap" fix-swaps "$sample" -o "$work/fixed.c3d" --json | normalise fix-swaps
"$mocap" eval-track "$sample" --swaps 3 --json | normalise eval-track
"$mocap" bind --mesh "$mesh" --take "$sample" --stabilize "$heads" -o "$work/bind.json" --json |
  normalise bind
"$mocap" deform --mesh "$mesh" --binding "$binding" --take "$sample" --stabilize "$heads" \
  --frames 1:100 --leave-out 0.2 -o "$work/out.pc2" --json | normalise deform-rbf
"$mocap" deform --mesh "$mesh" --binding "$binding" --take "$sample" --stabilize "$heads" \
  --method laplacian --frames 1:100 -o "$work/out2.pc2" --json | normalise deform-laplacian
echo "wrote $(ls "$out" | wc -l) snapshots into $out"
