#!/usr/bin/env bash
# The windowed viewer under a virtual X server: `globe view` runs 300 frames of scripted input with
# Vulkan validation on (any message fails the command), exits 0, and its screenshots show the
# planet; Esc quits early; without a display it refuses with one line; bad values exit 2.
# Needs xvfb-run (Debian package xvfb, which uses xauth); works with no display in the environment.
# Usage: viewer_test.sh GLOBE SCREENSHOT_CHECK SCRIPT WORKDIR
set -uo pipefail
GLOBE="$1"
CHECK="$2"
SCRIPT="$3"
WORK="$4"
rm -rf "$WORK" && mkdir -p "$WORK"
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }

if ! command -v xvfb-run >/dev/null; then
  echo "FAIL: xvfb-run not found (scripts/install-deps.sh installs the xvfb package)"
  exit 1
fi
# -a: the first free display number from a random start (-n), so concurrent runs (other build
# trees, other checkouts) rarely race for the same one. 24-bit like a desktop.
XVFB=(xvfb-run -a -n $((100 + RANDOM % 800)) -e "$WORK/xvfb.log" -s "-screen 0 1024x768x24 -nolisten tcp")

# 1. The scripted flight.
"${XVFB[@]}" "$GLOBE" view --validate --frames 300 --script "$SCRIPT" --size 320x240 \
  --screenshot "$WORK/shot.png" --screenshot-dir "$WORK" >"$WORK/stdout" 2>"$WORK/stderr"
code=$?
cat "$WORK/stdout"
if [[ $code -ne 0 ]]; then
  fail "globe view exited $code"; cat "$WORK/stderr"; cat "$WORK/xvfb.log" 2>/dev/null
fi
if grep -qi "validation" "$WORK/stderr"; then fail "validation messages:"; cat "$WORK/stderr"; fi
grep -q "viewed 300 frames" "$WORK/stdout" || fail "did not report 300 frames"
# The exit screenshot is at the size the script resized the window to; the planet fills part of it.
"$CHECK" "$WORK/shot.png" 400 300 0.05 0.99 || fail "exit screenshot"
# F12 at frame 150 (grid on, before the resize) and P at frame 290.
"$CHECK" "$WORK/globe-frame000150.png" 320 240 0.05 0.99 0.01 || fail "F12 screenshot with the grid"
"$CHECK" "$WORK/globe-frame000290.png" 400 300 0.05 0.99 || fail "P screenshot"

# 2. Esc quits at once, cleanly.
printf '5 KEY ESCAPE down\n' >"$WORK/esc.txt"
"${XVFB[@]}" "$GLOBE" view --validate --frames 100 --script "$WORK/esc.txt" --size 64x64 >"$WORK/esc.out" 2>&1 ||
  { fail "Esc run failed"; cat "$WORK/esc.out"; }
grep -q "viewed 5 frames" "$WORK/esc.out" || { fail "Esc did not quit at frame 5"; cat "$WORK/esc.out"; }

# 3. No display: one line, exit 1, before any window or device is made.
env -u DISPLAY -u WAYLAND_DISPLAY "$GLOBE" view --frames 1 >"$WORK/nodisp.out" 2>"$WORK/nodisp.err"
code=$?
if [[ $code -ne 1 || $(wc -l <"$WORK/nodisp.err") -ne 1 ]] || ! grep -q "^globe: error: no display" "$WORK/nodisp.err"; then
  fail "no display: exit $code, stderr:"; cat "$WORK/nodisp.err"
fi

# 4. Bad values: one line, exit 2 (checked before the display, so no X server needed).
printf '3 KEY NOSUCHKEY down\n' >"$WORK/bad_script.txt"
expect_usage() {  # expect_usage PATTERN ARGS...
  local pattern="$1"
  shift
  env -u DISPLAY "$GLOBE" view "$@" >/dev/null 2>"$WORK/usage.err"
  local got=$?
  if [[ $got -ne 2 || $(wc -l <"$WORK/usage.err") -ne 1 ]] || ! grep -qE "^globe: error: .*$pattern" "$WORK/usage.err"; then
    fail "view $*: exit $got, expected 2 with '$pattern':"; cat "$WORK/usage.err"
  else
    echo "ok: view $* -> $(cat "$WORK/usage.err")"
  fi
}
expect_usage "--frames: must be 0" --frames -3
expect_usage "--size: expected WxH" --size big
expect_usage "--at: latitude must be within" --at 95,0,100
expect_usage "--script: cannot read script" --script "$WORK/missing.txt"
expect_usage "bad_script.txt:1: unknown key 'NOSUCHKEY'" --script "$WORK/bad_script.txt"
expect_usage "--screenshot: '.*shot.jpg' must end in .png or .exr" --screenshot "$WORK/shot.jpg"
expect_usage "--screenshot-dir: '/nonexistent' is not a directory" --screenshot-dir /nonexistent

echo "viewer: $failures failure(s)"
exit $((failures > 0))
