#!/usr/bin/env bash
# Runaway planets and injected faults (issue 21, docs/reliability.md "Frame budgets", "Faults"):
# every frame stays within its budgets with ONE warning; a failed generation draws coarser and
# recovers; generation that keeps failing, a lost device and a failing fsync end with one error
# line, exit 1 and no output (also ENOSPC in the bench's row spool); nothing hangs (every command runs under a timeout).
# Usage: faults_test.sh GLOBE SOURCE_DIR WORKDIR
set -uo pipefail
GLOBE="$1"
SRC="$2"
WORK="$3"
rm -rf "$WORK" && mkdir -p "$WORK"
export MESA_SHADER_CACHE_DISABLE=true
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }
run() { timeout 300 "$@" >"$WORK/stdout" 2>"$WORK/stderr"; }
count() { grep -c -- "$1" "$WORK/stderr"; }
RUNAWAY="$SRC/tests/data/runaway.toml"
SHORT="$SRC/tests/data/short.path"

# 1. A planet that refines everywhere, at the default camera: the frame within the caps, one warning.
run "$GLOBE" render --planet "$RUNAWAY" --size 160x90 --max-nodes 400 --max-triangles 150000 --out "$WORK/runaway.png"
code=$?
read -r nodes triangles < <(sed -nE 's/^([0-9]+) nodes .*, ([0-9]+) triangles.*/\1 \2/p' "$WORK/stdout")
if [[ $code -ne 0 || ! -s "$WORK/runaway.png" ]]; then fail "runaway render exited $code"; cat "$WORK/stderr"
elif [[ ${nodes:-0} -gt 400 || ${nodes:-0} -lt 30 || ${triangles:-0} -gt 150000 ]]; then fail "runaway render drew $nodes nodes, $triangles triangles"
elif [[ $(count "globe: warning: frame budget reached") -ne 1 || $(wc -l <"$WORK/stderr") -ne 1 ]]; then fail "runaway render warnings:"; cat "$WORK/stderr"
else echo "ok: runaway render: $nodes nodes, $triangles triangles, $(cat "$WORK/stderr")"; fi

# The same planet flown (budgeted): every frame within the caps, the warning once.
run "$GLOBE" bench --planet "$RUNAWAY" --path "$SHORT" --size 64x64 --keyframes 0 --max-nodes 300 --out "$WORK/bench"
code=$?
max=$(awk -F, 'NR == 1 { for (i = 1; i <= NF; ++i) c[$i] = i; next } { if ($c["nodes_selected"] > m) m = $c["nodes_selected"] } END { print m + 0 }' "$WORK/bench/frames.csv" 2>/dev/null)
if [[ $code -ne 0 ]]; then fail "runaway bench exited $code"; cat "$WORK/stderr"
elif [[ ${max:-0} -gt 300 ]]; then fail "runaway bench drew $max nodes in a frame (budget 300)"
elif [[ $(count "globe: warning: frame budget reached") -ne 1 ]]; then fail "runaway bench warnings:"; cat "$WORK/stderr"
else echo "ok: runaway bench: at most $max nodes a frame, one warning"; fi

# 2. Pool exhaustion: a 1 MiB payload pool at 300 m draws what fits, with one warning.
run "$GLOBE" render --at 20,10,300 --size 64x64 --vram-mib 1 --out "$WORK/small_pool.png"
if [[ $? -ne 0 || $(count "globe: warning: payload pool exhausted") -ne 1 ]]; then fail "small pool:"; cat "$WORK/stderr"
else echo "ok: small pool: $(cat "$WORK/stderr")"; fi
# Too small for the 30 roots: a usage error naming the option.
run "$GLOBE" render --size 64x64 --grid 64 --vram-mib 1 --out "$WORK/tiny_pool.png"
if [[ $? -ne 2 || ! -s "$WORK/stderr" ]] || ! grep -q "^globe: error: --vram-mib: too small" "$WORK/stderr" || [[ -e "$WORK/tiny_pool.png" ]]; then
  fail "tiny pool:"; cat "$WORK/stderr"; else echo "ok: tiny pool: $(cat "$WORK/stderr")"; fi
# The imagery tiles' own pool: too small for their 30 roots names its own option.
run "$GLOBE" render --size 64x64 --imagery on --imagery-mib 1 --out "$WORK/tiny_imagery.png"
if [[ $? -ne 2 || ! -s "$WORK/stderr" ]] || ! grep -q "^globe: error: --imagery-mib: too small" "$WORK/stderr" || [[ -e "$WORK/tiny_imagery.png" ]]; then
  fail "tiny imagery pool:"; cat "$WORK/stderr"; else echo "ok: tiny imagery pool: $(cat "$WORK/stderr")"; fi

# 3. A failed generation dispatch: coarser meanwhile, asked for again, the frame completes.
run env GLOBE_FAULT=generation@3 "$GLOBE" render --size 64x64 --out "$WORK/gen_fail.png"
if [[ $? -ne 0 || ! -s "$WORK/gen_fail.png" || $(count "globe: warning: payload generation failed (vkQueueSubmit failed: VK_ERROR_OUT_OF_DEVICE_MEMORY)") -ne 1 ]]; then
  fail "one failed generation:"; cat "$WORK/stderr"; else echo "ok: one failed generation: $(cat "$WORK/stderr")"; fi
# Generation failing on and on: one error line, exit 1, no image.
run env GLOBE_FAULT=generation@1+ "$GLOBE" render --size 64x64 --out "$WORK/gen_dead.png"
code=$?
if [[ $code -ne 1 || -e "$WORK/gen_dead.png" ]] || ! grep -q "^globe: error: payload generation failed 256 times in a row" "$WORK/stderr"; then
  fail "generation always failing (exit $code):"; cat "$WORK/stderr"; else echo "ok: generation always failing: $(tail -1 "$WORK/stderr")"; fi

# The same planet as a movie (converged frames): within the caps, the warning once.
run "$GLOBE" movie --planet "$RUNAWAY" --path "$SHORT" --size 64x64 --fps 24 --max-nodes 300 --out "$WORK/movie"
code=$?
if [[ $code -ne 0 || $(count "globe: warning: frame budget reached (300 nodes") -ne 1 ]]; then
  fail "runaway movie exited $code:"; cat "$WORK/stderr"
else echo "ok: runaway movie: one warning"; fi

# 4. Device lost at a frame's submit (bench) and at the first submit (render): one line, exit 1,
# no report, no image, no temporaries.
run env GLOBE_FAULT=device-lost@40 "$GLOBE" bench --path "$SHORT" --size 64x64 --out "$WORK/lost_bench"
code=$?
if [[ $code -ne 1 || -e "$WORK/lost_bench/summary.json" || $(wc -l <"$WORK/stderr") -ne 1 ]] ||
  ! grep -q "^globe: error: the Vulkan device was lost (vkQueueSubmit failed: VK_ERROR_DEVICE_LOST)" "$WORK/stderr"; then
  fail "device lost in bench (exit $code):"; cat "$WORK/stderr"; else echo "ok: device lost in bench: $(cat "$WORK/stderr")"; fi
run env GLOBE_FAULT=device-lost@1 "$GLOBE" render --size 64x64 --out "$WORK/lost.png"
code=$?
if [[ $code -ne 1 || -e "$WORK/lost.png" ]] || ! grep -q "device was lost" "$WORK/stderr"; then
  fail "device lost in render (exit $code):"; cat "$WORK/stderr"; else echo "ok: device lost in render"; fi
# A malformed fault list is an error, not ignored.
run env GLOBE_FAULT=gpu-on-fire@1 "$GLOBE" render --size 64x64 --out "$WORK/bad_fault.png"
if [[ $? -ne 1 ]] || ! grep -q "GLOBE_FAULT: unknown fault 'gpu-on-fire@1'" "$WORK/stderr"; then fail "bad GLOBE_FAULT:"; cat "$WORK/stderr"
else echo "ok: bad GLOBE_FAULT"; fi

# 5. A failing fsync (EIO) fails every image write and keeps the earlier file: PNG and EXR renders,
# the elevation EXR export.
for out in keep.png keep.exr; do
  "$GLOBE" render --size 64x48 --out "$WORK/$out" >/dev/null 2>&1 && cp "$WORK/$out" "$WORK/$out.orig"
  run env GLOBE_FAULT=fsync@1 "$GLOBE" render --size 96x48 --out "$WORK/$out"
  if [[ $? -ne 1 ]] || ! grep -q "^globe: error: .*$out: cannot write: Input/output error" "$WORK/stderr" ||
    ! cmp -s "$WORK/$out" "$WORK/$out.orig" || ls -A "$WORK" | grep -q '\.tmp'; then
    fail "fsync failure writing $out:"; cat "$WORK/stderr"; else echo "ok: fsync failure writing $out: $(cat "$WORK/stderr")"; fi
done
"$GLOBE" planet export --width 64 --out "$WORK/map.exr" >/dev/null 2>&1 && cp "$WORK/map.exr" "$WORK/map.orig"
run env GLOBE_FAULT=fsync@1 "$GLOBE" planet export --width 128 --out "$WORK/map.exr"
if [[ $? -eq 0 ]] || ! grep -q "map.exr: cannot write: Input/output error" "$WORK/stderr" || ! cmp -s "$WORK/map.exr" "$WORK/map.orig"; then
  fail "fsync failure in planet export:"; cat "$WORK/stderr"; else echo "ok: fsync failure in planet export: $(cat "$WORK/stderr")"; fi

# 6. A full disk while the bench spools its rows (ENOSPC at the row file's first write): one line
# naming the directory, exit 1, the earlier report untouched, no temporary left.
"$GLOBE" bench --path "$SHORT" --size 64x64 --keyframes 0 --out "$WORK/spool" >/dev/null 2>&1 &&
  cp "$WORK/spool/summary.json" "$WORK/spool.summary.orig"
run env GLOBE_FAULT=write@1 "$GLOBE" bench --path "$SHORT" --size 64x64 --keyframes 0 --out "$WORK/spool"
if [[ $? -ne 1 || $(wc -l <"$WORK/stderr") -ne 1 ]] ||
  ! grep -q "^globe: error: .*spool: cannot write the benchmark's rows: No space left on device" "$WORK/stderr" ||
  ! cmp -s "$WORK/spool/summary.json" "$WORK/spool.summary.orig" || ls -A "$WORK/spool" | grep -q '^\.'; then
  fail "full disk in the bench's rows:"; cat "$WORK/stderr"; ls -A "$WORK/spool"
else echo "ok: full disk in the bench's rows: $(cat "$WORK/stderr")"; fi

if [[ $failures -ne 0 ]]; then echo "$failures failure(s)"; exit 1; fi
echo "all fault checks passed"
