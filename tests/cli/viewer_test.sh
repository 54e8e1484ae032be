#!/usr/bin/env bash
# The windowed viewer under a virtual X server: `globe view` flies the terrain with scripted input
# and Vulkan validation on (any message fails the command), exits 0, and its screenshots show
# terrain; a recorded path replays the same view in `globe render`; the sphere mode draws its grid;
# a camera path flies in real time with --frame-times; Esc quits early; without a display it refuses with one line; bad values exit 2.
# Needs xvfb-run (Debian package xvfb, which uses xauth); works with no display in the environment.
# Usage: viewer_test.sh GLOBE SCREENSHOT_CHECK SCRIPT RECORD_SCRIPT WORKDIR
set -uo pipefail
GLOBE="$1"
CHECK="$2"
SCRIPT="$3"
RECORD_SCRIPT="$4"
WORK="$5"
rm -rf "$WORK" && mkdir -p "$WORK"
source "$(dirname "$0")/xvfb_common.sh"

# 1. The scripted flight over the terrain: debug views, a resize, a recorded path. Screenshots are
# EXR so the check can tell terrain (finite depth) from sky and space (+inf).
"${XVFB[@]}" "$GLOBE" view --validate --frames 150 --script "$SCRIPT" --size 320x240 \
  --screenshot "$WORK/shot.exr" --screenshot-dir "$WORK" --screenshot-format exr --record-dir "$WORK" \
  >"$WORK/stdout" 2>"$WORK/stderr"
code=$?
cat "$WORK/stdout"
if [[ $code -ne 0 ]]; then
  fail "globe view exited $code"; cat "$WORK/stderr"; cat "$WORK/xvfb.log" 2>/dev/null
fi
if grep -qi "validation" "$WORK/stderr"; then fail "validation messages:"; cat "$WORK/stderr"; fi
grep -q "viewed 150 frames" "$WORK/stdout" || fail "did not report 150 frames"
# The exit screenshot is at the size the script resized the window to; terrain fills part of it.
"$CHECK" coverage "$WORK/shot.exr" 400 300 0.05 0.99 || fail "exit screenshot"
# F12 at frame 65 (LOD colours, before the resize) and P at frame 145.
"$CHECK" coverage "$WORK/globe-frame000065.exr" 320 240 0.05 0.99 || fail "F12 screenshot with LOD colours"
"$CHECK" coverage "$WORK/globe-frame000145.exr" 400 300 0.05 0.99 || fail "P screenshot"
# R at frames 72 and 138: a timestamped path file that parses.
paths=("$WORK"/globe-path-*.path)
if [[ ${#paths[@]} -ne 1 || ! -f ${paths[0]} ]]; then
  fail "expected one recorded globe-path-*.path in $WORK"
else
  "$CHECK" pose "${paths[0]}" >/dev/null || fail "recorded path does not parse"
  grep -qE "^path .*globe-path-.*\.path \([0-9]+ keyframes, 1.0[0-9] s\)" "$WORK/stdout" || fail "path not reported"
fi

# 2. Record a path, then render its last pose headless: the same view (depth per pixel within 0.1%).
"${XVFB[@]}" "$GLOBE" view --validate --at 30,20,20000,45,-20,0 --frames 130 --script "$RECORD_SCRIPT" --size 160x120 \
  --screenshot-dir "$WORK" --screenshot-format exr --record "$WORK/rec.path" >"$WORK/rec.out" 2>&1
code=$?
cat "$WORK/rec.out"
[[ $code -eq 0 ]] || fail "recording run exited $code"
grep -qi "validation" "$WORK/rec.out" && fail "validation messages in the recording run"
grep -q "^screenshot .*globe-frame000128.exr (converged)" "$WORK/rec.out" || fail "recording run did not converge"
if pose=$("$CHECK" pose "$WORK/rec.path"); then
  "$GLOBE" render --validate --at="$pose" --size 160x120 --out "$WORK/replay.exr" >"$WORK/render.out" 2>&1 ||
    { fail "globe render of the recorded pose"; cat "$WORK/render.out"; }
  "$CHECK" depth "$WORK/globe-frame000128.exr" "$WORK/replay.exr" 0.001 || fail "the recorded pose renders another view"
else
  fail "rec.path does not parse"
fi

# 3. The analytic sphere (--mode sphere) and its latitude/longitude grid (F1/L).
printf '3 KEY L down\n4 KEY L up\n8 KEY P down\n9 KEY P up\n' >"$WORK/sphere.txt"
"${XVFB[@]}" "$GLOBE" view --validate --mode sphere --frames 12 --script "$WORK/sphere.txt" --size 320x240 \
  --screenshot-dir "$WORK" >"$WORK/sphere.out" 2>&1 || { fail "sphere run failed"; cat "$WORK/sphere.out"; }
"$CHECK" coverage "$WORK/globe-frame000008.png" 320 240 0.05 0.99 0.01 || fail "sphere screenshot with the grid"

# 4. Esc quits at once, cleanly.
printf '5 KEY ESCAPE down\n' >"$WORK/esc.txt"
"${XVFB[@]}" "$GLOBE" view --validate --frames 100 --script "$WORK/esc.txt" --size 64x64 >"$WORK/esc.out" 2>&1 ||
  { fail "Esc run failed"; cat "$WORK/esc.out"; }
grep -q "viewed 5 frames" "$WORK/esc.out" || { fail "Esc did not quit at frame 5"; cat "$WORK/esc.out"; }

# 5. Fly a camera path in real time (tests/data/short.path, 0.5 s) with --frame-times: the viewer
# quits at the path's end by itself, the CSV has its header and one line per frame ending at the
# path's end, and the exit line gives the frame count and times.
SHORT_PATH="$(dirname "$SCRIPT")/../data/short.path"
"${XVFB[@]}" "$GLOBE" view --validate --path "$SHORT_PATH" --frame-times "$WORK/times.csv" --size 160x120 \
  >"$WORK/path.out" 2>&1
code=$?
cat "$WORK/path.out"
[[ $code -eq 0 ]] || fail "path flight exited $code"
grep -qi "validation" "$WORK/path.out" && fail "validation messages in the path flight"
if ! exit_line=$(grep -E "^frames [0-9]+ median_ms [0-9.]+ p95_ms [0-9.]+$" "$WORK/path.out"); then
  fail "no 'frames N median_ms X p95_ms Y' line"
elif [[ ! -f "$WORK/times.csv" ]]; then
  fail "--frame-times wrote no file"
else
  frames=$(echo "$exit_line" | cut -d' ' -f2)
  [[ $(head -1 "$WORK/times.csv") == "frame,wall_s,path_t_s,frame_ms,nodes_selected,triangles,gpu_ms,height_m,latitude_deg,longitude_deg,heading_deg,pitch_deg" ]] ||
    fail "frame-times header: $(head -1 "$WORK/times.csv")"
  [[ $(($(wc -l <"$WORK/times.csv") - 1)) -eq $frames ]] || fail "frame-times rows differ from the $frames frames"
  [[ $frames -ge 2 ]] || fail "a path flight of $frames frame(s)"
  # The last frame shows the path's end (0.5 s); every frame draws some of the planet.
  [[ $(tail -1 "$WORK/times.csv" | cut -d, -f3) == "0.500000" ]] || fail "last frame is not at the path's end"
  awk -F, 'NR > 1 && $5 == 0 { bad = 1 } END { exit bad }' "$WORK/times.csv" || fail "a frame drew no nodes"
  grep -q "viewed $frames frames" "$WORK/path.out" || fail "exit line and viewed count differ"
fi
ls -a "$WORK" | grep -q '^\.times\.csv\.tmp' && fail "a frame-times temporary was left behind"

# 6. No display: one line, exit 1, before any window or device is made.
env -u DISPLAY -u WAYLAND_DISPLAY "$GLOBE" view --frames 1 >"$WORK/nodisp.out" 2>"$WORK/nodisp.err"
code=$?
if [[ $code -ne 1 || $(wc -l <"$WORK/nodisp.err") -ne 1 ]] || ! grep -q "^globe: error: no display" "$WORK/nodisp.err"; then
  fail "no display: exit $code, stderr:"; cat "$WORK/nodisp.err"
fi

# 7. Bad values: one line, exit 2 (checked before the display, so no X server needed).
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
expect_usage "--script: cannot open input script" --script "$WORK/missing.txt"
expect_usage "bad_script.txt:1: unknown key 'NOSUCHKEY'" --script "$WORK/bad_script.txt"
expect_usage "--screenshot: '.*shot.jpg' must end in .png or .exr" --screenshot "$WORK/shot.jpg"
expect_usage "--screenshot-dir: '/nonexistent' is not a directory" --screenshot-dir /nonexistent
expect_usage "--record-dir: '/nonexistent' is not a directory" --record-dir /nonexistent
expect_usage "--grid: must be a power of two" --grid 33
expect_usage "--frame-times: '/dev/null' is not a directory" --frame-times /dev/null/t.csv
expect_usage "missing.path: cannot open camera path file" --path "$WORK/missing.path"
expect_usage "--hold: needs --path" --hold
expect_usage "--mode: .*" --mode cube
expect_usage "--screenshot-format: .*" --screenshot-format jpg
{ cat "$(dirname "$SCRIPT")/../../assets/planets/earthlike.toml"; printf 'no_such_key = 1\n'; } >"$WORK/bad_planet.toml"
expect_usage "bad_planet.toml:[0-9]+:1: .*no_such_key" --planet "$WORK/bad_planet.toml"
expect_usage "--max-nodes: .*" --max-nodes 0.5
printf '# mine\n1,2,3 short\n' >"$WORK/bad_bookmarks.txt"
expect_usage "bad_bookmarks.txt:2: place: expected LAT,LON,HEIGHT,HEADING,PITCH,ROLL, got '1,2,3'" \
  --bookmarks "$WORK/bad_bookmarks.txt"

# A runaway planet within a frame budget: the viewer says so once (stderr and overlay), exit 0.
RUNAWAY="$(dirname "$SCRIPT")/../data/runaway.toml"
"${XVFB[@]}" "$GLOBE" view --validate --planet "$RUNAWAY" --frames 12 --size 160x90 --max-nodes 300 \
  >"$WORK/runaway.out" 2>"$WORK/runaway.err"
code=$?
if [[ $code -ne 0 || $(grep -c "globe: warning: frame budget reached (300 nodes" "$WORK/runaway.err") -ne 1 ]]; then
  fail "runaway planet in the viewer (exit $code):"; cat "$WORK/runaway.err"
else echo "ok: runaway planet in the viewer: $(cat "$WORK/runaway.err")"; fi

echo "viewer: $failures failure(s)"
exit $((failures > 0))
