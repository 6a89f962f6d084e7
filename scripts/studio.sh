#!/usr/bin/env bash
# Command 1 of the README: set up (packages, build) and start the studio on the bundled sample take.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
"$root/scripts/setup.sh"
sample="$root/resources/sample/Facial-Sing.c3d"
if [ -x "$root/build/bin/mocap-studio" ]; then
  exec "$root/build/bin/mocap-studio" "$sample" "$@"
fi
echo "The studio (mocap-studio) is not built yet; showing the sample take with 'mocap info' instead:"
exec "$root/build/bin/mocap" info "$sample"
