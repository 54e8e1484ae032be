#!/usr/bin/env bash
# globe bench end to end: outputs exist and parse, two replays are identical except for timings,
# and malformed inputs write nothing. Usage: bench_test.sh GLOBE SOURCE_DIR WORKDIR
set -uo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/cli_common.sh"

run() {  # run DIR: a short replay at a small size
  "$GLOBE" bench --path "$SRC/tests/data/short.path" --out "$1" --size 96x64 --keyframes 0,0.25 --rate 20 \
    --validate >"$WORK/stdout" 2>"$WORK/stderr"
}

run "$WORK/a" || { fail "bench run a"; cat "$WORK/stderr"; }
run "$WORK/b" || { fail "bench run b"; cat "$WORK/stderr"; }
# The terminal's last line sums the run up: median, p95, frames over budget, where the report is.
tail -1 "$WORK/stdout" | grep -qE '^bench: [0-9]+ frames of .*: frame median [0-9.]+ ms, p95 [0-9.]+ ms, [0-9]+ over 33.3 ms; GPU median [0-9.]+ ms; report .*/b/report.html$' ||
  fail "no one-line summary last: $(tail -1 "$WORK/stdout")"
for f in frames.csv summary.json timeline.svg report.html keyframe_00.00s.png keyframe_00.25s.png; do
  [[ -s "$WORK/a/$f" ]] || fail "missing $f"
done
header=$(head -1 "$WORK/a/frames.csv")
expected="frame,t,altitude_m,frame_ms,select_ms,gpu_ms,nodes_selected,nodes_partial,triangles,draw_calls,gen_dispatched,gen_in_flight,gen_completed,evicted,resident_mib,ground_speed_mps,gpu_terrain_ms,gpu_skirts_ms,gpu_sky_ms,gpu_generation_ms,gpu_shadows_ms"
[[ "$header" == "$expected" ]] || fail "frames.csv header: $header"
rows=$(($(wc -l <"$WORK/a/frames.csv") - 1))
[[ $rows -eq 11 ]] || fail "frames.csv has $rows rows, expected 11 (0.5 s at 20 Hz)"
for key in '"frame_ms"' '"jank_ms"' '"p99"' '"median"' '"nodes_selected"'; do
  grep -q "$key" "$WORK/a/summary.json" || fail "summary.json lacks $key"
done
grep -q '<svg' "$WORK/a/timeline.svg" || fail "timeline.svg is not SVG"
grep -q '</html>' "$WORK/a/report.html" || fail "report.html is incomplete"
# The run environment is recorded; frame 0 already draws the planet (the terrain's warm-up).
for key in '"driver"' '"shader_cache"' '"load_average_start"' '"load_average_end"' '"commit"' '"date_utc"' \
  '"generation_latency_frames"' '"phases"'; do
  grep -q "$key" "$WORK/a/summary.json" || fail "summary.json lacks $key"
done
# The commit is the one the binary was built from (cmake/GlobeCommit.cmake runs at every build):
# HEAD, when the binary is newer than HEAD's commit (a commit made after building is not in it).
if command -v git >/dev/null && [[ -e "$SRC/.git" ]] &&
  (($(stat -c %Y "$GLOBE") >= $(git -C "$SRC" log -1 --format=%ct 2>/dev/null || echo 0))); then
  head=$(git -C "$SRC" rev-parse --short=12 HEAD 2>/dev/null)
  grep -Eq "\"commit\": \"$head(-dirty)?\"" "$WORK/a/summary.json" ||
    fail "summary.json names another commit than HEAD $head (binary not rebuilt since?)"
fi
nodes0=$(sed -n 2p "$WORK/a/frames.csv" | cut -d, -f7)
[[ $nodes0 -ge 1 ]] || fail "frame 0 draws $nodes0 nodes"
# Determinism: everything but the timing columns (*_ms) is identical.
cut -d, -f1-3,7-16 "$WORK/a/frames.csv" >"$WORK/a.cols"
cut -d, -f1-3,7-16 "$WORK/b/frames.csv" >"$WORK/b.cols"
cmp -s "$WORK/a.cols" "$WORK/b.cols" || { fail "replays differ"; diff "$WORK/a.cols" "$WORK/b.cols" | head; }
for f in keyframe_00.00s.png keyframe_00.25s.png; do cmp -s "$WORK/a/$f" "$WORK/b/$f" || fail "$f differs between replays"; done

# --baseline: an earlier run's numbers beside this one's; a bad baseline is one line, exit 2, nothing written.
"$GLOBE" bench --path "$SRC/tests/data/short.path" --out "$WORK/c" --size 96x64 --keyframes 0 --rate 20 \
  --baseline "$WORK/a" >/dev/null 2>"$WORK/err" || { fail "bench --baseline"; cat "$WORK/err"; }
grep -q '"median_ratio"' "$WORK/c/summary.json" || fail "--baseline: no ratios in summary.json"
grep -q 'baseline median' "$WORK/c/report.html" || fail "--baseline: no baseline column in report.html"
mkdir -p "$WORK/garbled" && printf '{ nope' >"$WORK/garbled/summary.json"
for base in "$WORK/none" "$WORK/garbled"; do
  "$GLOBE" bench --path "$SRC/tests/data/short.path" --out "$WORK/out-base" --baseline "$base" >/dev/null 2>"$WORK/err"
  code=$?
  [[ $code -eq 2 ]] || fail "--baseline $base: exit $code, expected 2"
  [[ $(wc -l <"$WORK/err") -eq 1 ]] && grep -q "^globe: error: $base/summary.json: " "$WORK/err" ||
    fail "--baseline $base: $(cat "$WORK/err")"
  [[ ! -e "$WORK/out-base" ]] || fail "--baseline $base: wrote output"
done

# Malformed paths: file:line: message, non-zero exit, nothing written.
bad() {  # bad NAME CONTENT PATTERN
  printf '%b' "$2" >"$WORK/$1.path"
  "$GLOBE" bench --path "$WORK/$1.path" --out "$WORK/out-$1" --size 96x64 >/dev/null 2>"$WORK/err"
  local code=$?
  [[ $code -ne 0 ]] || fail "$1: exit 0"
  [[ $(wc -l <"$WORK/err") -eq 1 ]] && grep -qE "^globe: error: .*$3" "$WORK/err" || { fail "$1: $(cat "$WORK/err")"; }
  [[ ! -e "$WORK/out-$1" ]] || fail "$1: wrote $WORK/out-$1"
}
H='t_s lat_deg lon_deg height_m heading_deg pitch_deg roll_deg\n'
bad empty "" "empty.path:1: empty camera path"
bad badnumber "${H}0 1 2 3 4 5 6\n1 x 2 3 4 5 6\n" "badnumber.path:3: "
bad time "${H}0 1 2 3 4 5 6\n0 1 2 3 4 5 6\n" "time.path:3: "
bad lat "${H}0 1 2 3 4 5 6\n1 91 2 3 4 5 6\n" "lat.path:3: "
bad missing "${H}0 1 2 3 4 5 6\n1 1 2 3 4 5\n" "missing.path:3: "
"$GLOBE" bench --path "$WORK/nonexistent.path" --out "$WORK/out-none" >/dev/null 2>"$WORK/err" && fail "missing file: exit 0"
[[ ! -e "$WORK/out-none" ]] || fail "missing file: wrote output"

# From an empty directory, outputs at their defaults: out/ is made (and said so), from any directory.
mkdir -p "$WORK/empty" && (
  cd "$WORK/empty" &&
    "$GLOBE" render --size 64x36 >"$WORK/empty.out" 2>&1 &&
    "$GLOBE" bench --path "$SRC/tests/data/short.path" --size 96x64 --rate 20 --keyframes 0 >>"$WORK/empty.out" 2>&1
) || { fail "render/bench from an empty directory"; cat "$WORK/empty.out"; }
[[ -s "$WORK/empty/out/render.png" && -s "$WORK/empty/out/bench/report.html" ]] || fail "outputs not made under out/"
grep -q "made directory 'out/bench'" "$WORK/empty.out" || fail "the new directory was not announced"

echo "bench: $failures failure(s)"
exit $((failures > 0))
