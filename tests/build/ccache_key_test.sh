#!/bin/sh
# ccache_key_test.sh CMAKE_MODULE_DIR: the compiler cache as the build sets it up never hands back a
# wrong object, and a second clone reuses the first one's. A one-file project (ccache_project/, with
# a precompiled header) is built from scratch in a fresh cache with VALUE=1, then 2, then 1 again:
# each binary must print its own value, the change must compile anew and the return to 1 come from
# the cache. A copy of the project in another folder then builds from the cache. Last, every file in
# the cache is corrupted and VALUE=1 built again: it must still print 1. Exit 77 (skipped) without
# ccache.
set -eu
modules="$1"
command -v ccache >/dev/null 2>&1 || { echo "ccache not installed: nothing to check"; exit 77; }
here="$(cd "$(dirname "$0")" && pwd)"
work="$(mktemp -d "${TMPDIR:-/tmp}/mocap-ccache-key.XXXXXX")"
trap 'rm -rf "$work"' EXIT
export CCACHE_DIR="$work/cache"
stats="$work/ccache-stats.log"

cp -r "$here/ccache_project" "$work/clone1"
cp -r "$here/ccache_project" "$work/clone2"

# build VALUE [CLONE]: configures and builds from scratch in CLONE/build (default clone1);
# prints what the binary prints.
build() {
  src="$work/${2:-clone1}"
  rm -rf "$src/build"
  cmake -S "$src" -B "$src/build" -DMOCAP_CMAKE_DIR="$modules" -DVALUE="$1" \
    -DMOCAP_CCACHE=ON -DMOCAP_CCACHE_STATS_LOG="$stats" >/dev/null
  cmake --build "$src/build" >/dev/null
  "$src/build/value"
}
hits() { CCACHE_STATSLOG="$stats" ccache --show-log-stats | awk '/^ *Hits:/ { print $2; exit }'; }
expect() {
  if [ "$1" != "$2" ]; then
    echo "FAIL: $3: got '$1', expected '$2'"
    exit 1
  fi
  echo "ok: $3"
}

expect "$(build 1)" 1 "VALUE=1 built"
expect "$(hits)" 0 "first build compiled from scratch"
: >"$stats"
expect "$(build 2)" 2 "VALUE=2 rebuilt with the new definition"
expect "$(hits)" 0 "the changed definition missed the cache"
: >"$stats"
expect "$(build 1)" 1 "VALUE=1 again"
[ "$(hits)" -ge 1 ] || { echo "FAIL: the return to VALUE=1 did not come from the cache"; exit 1; }
echo "ok: the return to VALUE=1 came from the cache"
: >"$stats"
expect "$(build 1 clone2)" 1 "VALUE=1 in another clone"
expect "$(hits)" 2 "the other clone compiled both the precompiled header and the file from the cache"

# Corrupt every stored result: ccache checks what it reads and compiles anew.
find "$CCACHE_DIR" -type f ! -name '*.conf' ! -name stats | while read -r f; do
  printf 'corrupt' | dd of="$f" bs=1 seek=16 conv=notrunc 2>/dev/null
done
: >"$stats"
expect "$(build 1)" 1 "VALUE=1 from a corrupted cache"
expect "$(hits)" 0 "nothing corrupted was taken from the cache"
