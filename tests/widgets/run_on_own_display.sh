#!/bin/sh
# run_on_own_display.sh COMMAND [ARG...]: runs one GUI test process on an X server of its own (Xvfb,
# 1280x1024x24) with a home folder of its own, so GUI tests run in parallel (ctest -j) without taking
# each other's focus or reading each other's settings and recovery files (Qt's test mode keeps them
# under $HOME/.qttest). Caches (Mesa's shaders, fontconfig) stay shared through XDG_CACHE_HOME.
# Xvfb picks a free display itself (-displayfd), so two starts never race for one as with
# `xvfb-run -a`. Without Xvfb the command runs as it is, on the current DISPLAY if any.
command -v Xvfb >/dev/null 2>&1 || exec "$@"

dir=$(mktemp -d "${TMPDIR:-/tmp}/mocap-display.XXXXXX") || exit 1
xvfb=
cleanup() {
  [ -n "$xvfb" ] && kill "$xvfb" 2>/dev/null && wait "$xvfb" 2>/dev/null
  rm -rf "$dir"
}
trap cleanup EXIT
trap 'exit 143' TERM
trap 'exit 130' INT

mkfifo "$dir/display"
Xvfb -displayfd 3 -screen 0 1280x1024x24 -nolisten tcp 3>"$dir/display" 2>"$dir/xvfb.log" &
xvfb=$!
read -r display <"$dir/display"
if [ -z "$display" ]; then
  echo "run_on_own_display: Xvfb did not start:" >&2
  cat "$dir/xvfb.log" >&2
  exit 1
fi

mkdir "$dir/home"
export XDG_CACHE_HOME="${XDG_CACHE_HOME:-${HOME:-$dir}/.cache}"
HOME="$dir/home" DISPLAY=":$display" "$@"
