#!/usr/bin/env bash
# Command 1 of the README: set up (packages, then a build of the studio alone: no tests, no
# benchmarks) and start the studio on the bundled sample take.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
start=$SECONDS
"$root/scripts/setup.sh" --target mocap-studio --target mocap
echo "== The studio was set up and built in $((SECONDS - start)) s"
sample="$root/resources/sample/Facial-Sing.c3d"
exec "$root/build/bin/mocap-studio" "$sample" "$@"
