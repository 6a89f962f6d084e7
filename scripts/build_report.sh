# Sourced by scripts/setup.sh and scripts/test.sh: phase times, quiet configuring and ccache's hit rate.
# Each phase's time is printed when it ends and, when MOCAP_PHASE_LOG names a file, appended to it
# ("seconds<TAB>name" a line) so scripts/test.sh can print every phase's time at the end.

phase_start() { phase_started=$SECONDS; }

# phase_end NAME
phase_end() {
  local seconds=$((SECONDS - phase_started))
  printf '== %s: %d s\n' "$1" "$seconds"
  if [ -n "${MOCAP_PHASE_LOG:-}" ]; then
    printf '%d\t%s\n' "$seconds" "$1" >>"$MOCAP_PHASE_LOG"
  fi
}

# print_phases: the table of MOCAP_PHASE_LOG, minutes and seconds, with the total.
print_phases() {
  [ -n "${MOCAP_PHASE_LOG:-}" ] && [ -s "$MOCAP_PHASE_LOG" ] || return 0
  echo "== Phase times"
  awk -F '\t' '{ total += $1; printf "   %-28s %4d s  (%d:%02d)\n", $2, $1, $1 / 60, $1 % 60 }
       END { printf "   %-28s %4d s  (%d:%02d)\n", "total", total, total / 60, total % 60 }' "$MOCAP_PHASE_LOG"
}

# generator_options BUILD_DIR: "-G Ninja" for a new build folder when ninja is installed. Ninja starts
# a target's compiles before the libraries it links are built, where make waits for each target in
# turn, so both cores stay busy at the seams. A folder configured before keeps its generator (CMake
# refuses to change it).
generator_options() {
  [ -f "$1/CMakeCache.txt" ] && return 0
  if command -v ninja >/dev/null; then
    echo "-G Ninja"
  else
    echo "== ninja not found: building with make (apt-get install ninja-build)" >&2
  fi
}

# configure_quietly BUILD_DIR [cmake options...]: cmake's output only on failure, but its "mocap:"
# lines (a tool the build goes without, and why) always.
configure_quietly() {
  local dir="$1"; shift
  local log generator
  generator="$(generator_options "$dir")"
  log="$(mktemp)"
  # shellcheck disable=SC2086 # $generator is empty or two words
  if ! cmake -S "$root" -B "$dir" $generator "$@" >"$log" 2>&1; then
    cat "$log" >&2
    rm -f "$log"
    return 1
  fi
  grep -E '^-- mocap:' "$log" || true
  rm -f "$log"
}

# The ccache stats log of a build folder (set in cmake/mocap_build_tools.cmake), emptied before a build
# so that its hit rate is this build's.
ccache_log_of() { sed -n 's/^MOCAP_CCACHE_STATS_LOG:FILEPATH=//p' "$1/CMakeCache.txt" 2>/dev/null; }

reset_ccache_log() {
  local log
  log="$(ccache_log_of "$1")"
  [ -n "$log" ] && : >"$log"
  return 0
}

# report_ccache BUILD_DIR: "ccache: N of M compiles from the cache (P %)", or why there is none.
report_ccache() {
  local log
  log="$(ccache_log_of "$1")"
  if ! grep -q '^MOCAP_CCACHE:BOOL=ON' "$1/CMakeCache.txt" 2>/dev/null || ! command -v ccache >/dev/null; then
    echo "== ccache: not used for $1 (not installed, or MOCAP_CCACHE=OFF)"
    return 0
  fi
  if [ ! -s "$log" ]; then
    echo "== ccache ($1): nothing compiled"
    return 0
  fi
  CCACHE_STATSLOG="$log" ccache --show-log-stats | awk -v dir="$1" '
    /^ *Hits:/ && !seen { hits = $2; calls = $4; seen = 1 }
    END { if (calls > 0) printf "== ccache (%s): %d of %d compiles from the cache (%.1f %%)\n", dir, hits, calls, 100 * hits / calls }'
}
