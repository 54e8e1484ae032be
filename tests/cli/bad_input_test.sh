#!/usr/bin/env bash
# Bad input to the command line: one clear line on stderr, a non-zero exit, no crash, and no
# output file. Usage: bad_input_test.sh GLOBE WORKDIR
set -uo pipefail
GLOBE="$1"
WORK="$2"
rm -rf "$WORK" && mkdir -p "$WORK"
failures=0

# expect CODE PATTERN OUTFILE -- ARGS...: exit code CODE, stderr one line matching PATTERN, OUTFILE absent.
expect() {
  local code="$1" pattern="$2" outfile="$3"
  shift 4
  local err="$WORK/stderr"
  "$@" >"$WORK/stdout" 2>"$err"
  local got=$?
  local lines
  lines=$(wc -l <"$err")
  if [[ $got -ne $code ]]; then
    echo "FAIL: '$*' exited $got, expected $code"; cat "$err"; failures=$((failures + 1)); return
  fi
  if [[ $lines -ne 1 ]] || ! grep -qE "^globe: error: .*$pattern" "$err"; then
    echo "FAIL: '$*' stderr is not one line matching '$pattern':"; cat "$err"; failures=$((failures + 1)); return
  fi
  if [[ -n "$outfile" && -e "$outfile" ]]; then
    echo "FAIL: '$*' left $outfile behind"; failures=$((failures + 1)); return
  fi
  if ls -A "$WORK" | grep -q '\.tmp'; then
    echo "FAIL: '$*' left a temporary file"; failures=$((failures + 1)); return
  fi
  echo "ok: $* -> $(cat "$err")"
}

O="$WORK/out.png"
# Device problems: a forced device that does not exist (also how a device without fp64 is refused).
expect 1 "no Vulkan device matches 'no-such-gpu'" "$O" -- "$GLOBE" render --device no-such-gpu --out "$O" --size 64x64
expect 1 "no Vulkan device matches 'no-such-gpu'" "$O" -- env GLOBE_DEVICE=no-such-gpu "$GLOBE" render --out "$O" --size 64x64
# Missing shader files.
expect 1 "shader file '/nonexistent/.*\.spv' not found" "$O" -- env GLOBE_SHADER_DIR=/nonexistent "$GLOBE" render --out "$O" --size 64x64
# Unwritable or unsupported output paths.
expect 2 "--out: '/dev/null' is not a directory" "" -- "$GLOBE" render --out /dev/null/sub/x.png --size 64x64
expect 2 "--out: '.*out.jpg' must end in .png or .exr" "$WORK/out.jpg" -- "$GLOBE" render --out "$WORK/out.jpg" --size 64x64
expect 2 "--out: '.*' is a directory" "" -- "$GLOBE" render --out "$WORK/" --size 64x64
# Bad values.
expect 2 "--size: expected WxH" "$O" -- "$GLOBE" render --size abc --out "$O"
expect 2 "--size: width and height must be within" "$O" -- "$GLOBE" render --size 8x8 --out "$O"
expect 2 "--size: expected WxH" "$O" -- "$GLOBE" render --size 64x-64 --out "$O"
expect 2 "--at: latitude must be within \[-90, 90\] degrees" "$O" -- "$GLOBE" render --at 91,0,100 --out "$O" --size 64x64
expect 2 "--at: height must be within" "$O" -- "$GLOBE" render --at 0,0,-1 --out "$O" --size 64x64
expect 2 "--at: latitude must be finite" "$O" -- "$GLOBE" render --at nan,0,10 --out "$O" --size 64x64
expect 2 "--at: longitude must be finite" "$O" -- "$GLOBE" render --at 0,inf,10 --out "$O" --size 64x64
expect 2 "--at: expected LAT,LON,HEIGHT" "$O" -- "$GLOBE" render --at 1,2 --out "$O" --size 64x64
expect 2 "--height-ref: must be 'ground', 'sphere' or 'ellipsoid', got 'sea'" "$O" -- "$GLOBE" render --at 0,0,10 --height-ref sea --out "$O" --size 64x64
# 100 m above the reference surface is under earthlike's plateau (ground at ~7 km there).
expect 2 "--at: height 100 m above the reference surface is under the ground there" "$O" -- "$GLOBE" render --at 22,-98.4,100 --height-ref ellipsoid --out "$O" --size 64x64
# Zero or empty values are errors, not a silent "the default" (leave the option out for that).
expect 2 "--grid: .*0" "$O" -- "$GLOBE" render --grid 0 --out "$O" --size 64x64
expect 2 "--quality: .*must not be empty" "$O" -- "$GLOBE" render --quality "" --out "$O" --size 64x64
expect 2 "--quality: .*must not be empty" "" -- "$GLOBE" bench --quality "" --out "$WORK/bench"
expect 2 "--aa: unknown anti-aliasing 'msaa8' \(none, fxaa, msaa4\)" "$O" -- "$GLOBE" render --aa msaa8 --out "$O" --size 64x64
expect 2 "--aa: unknown anti-aliasing 'smaa'" "" -- "$GLOBE" bench --aa smaa --out "$WORK/bench"
expect 2 "--atmosphere: unknown atmosphere detail 'haze' \(off, sky, full\)" "$O" -- "$GLOBE" render --atmosphere haze --out "$O" --size 64x64
expect 2 "--atmosphere: unknown atmosphere detail ''" "" -- "$GLOBE" view --atmosphere "" --frames 1
expect 2 "--roughness: maybe not in \{on,off\}" "$O" -- "$GLOBE" render --roughness maybe --out "$O" --size 64x64
expect 2 "--detail-textures: yes not in \{on,near,off\}" "$O" -- "$GLOBE" render --detail-textures yes --out "$O" --size 64x64
expect 2 "--imagery: maybe not in \{on,off\}" "$O" -- "$GLOBE" render --imagery maybe --out "$O" --size 64x64
expect 2 "--stride: .*0" "" -- "$GLOBE" trade --quick --stride 0 --out "$WORK/trade"
expect 2 "--png-width: .*0" "$WORK/p.png" -- "$GLOBE" planet export --width 64 --out "$WORK/m.exr" --png "$WORK/p.png" --png-width 0
# Sizes that wrap modulo 2^32 or need more memory than the limit.
expect 2 "--size: width and height must be within" "$O" -- "$GLOBE" render --size 4294967312x16 --out "$O"
expect 2 "--size: expected WxH" "$O" -- "$GLOBE" render --size 99999999999999999999999x16 --out "$O"
expect 2 "--size: 16384x16384 would need about 15360 MiB" "$O" -- "$GLOBE" render --size 16384x16384 --out "$O"
# The estimate follows the anti-aliasing and the encoder (issue 40: an 8192x8192 movie peaked at 4.6 GB).
expect 2 "--size: 8192x8192 with --aa fxaa would need about 4352 MiB of image memory, more than the limit of 4096 MiB" \
  "$O" -- "$GLOBE" render --quality exact --size 8192x8192 --out "$O"
expect 2 "--size: 8192x8192 with --aa msaa4 would need about 5888 MiB" "" -- \
  "$GLOBE" bench --aa msaa4 --size 8192x8192 --out "$WORK/bench_msaa"
[[ -e "$WORK/bench_msaa" ]] && { echo "FAIL: bench --size 8192x8192 --aa msaa4 made its directory"; failures=$((failures + 1)); }
PATHS="$(dirname "$GLOBE")/../share/globe/assets/paths"
expect 2 "--size: 7000x7000 with --aa none into an MP4 would need about 4673 MiB" "$WORK/big.mp4" -- \
  "$GLOBE" movie --path "$PATHS/still.path" --size 7000x7000 --out "$WORK/big.mp4"
# Input files that are not regular files: refused at once (timeout: a FIFO used to block forever).
mkfifo "$WORK/fifo.toml" "$WORK/fifo.path"
expect 2 "fifo.toml: cannot read planet file: it is a FIFO" "$O" -- timeout 60 "$GLOBE" render --planet "$WORK/fifo.toml" --out "$O" --size 64x64
expect 2 "fifo.path: cannot read camera path file: it is a FIFO" "" -- timeout 60 "$GLOBE" bench --path "$WORK/fifo.path" --out "$WORK/bench"
expect 2 "/dev/zero: cannot read planet file: it is a device" "$O" -- timeout 60 "$GLOBE" render --planet /dev/zero --out "$O" --size 64x64
expect 2 "cannot read planet file: it is a directory" "$O" -- timeout 60 "$GLOBE" render --planet "$WORK" --out "$O" --size 64x64
if ! timeout 60 "$GLOBE" planet check "$WORK/fifo.toml" 2>"$WORK/stderr" && grep -q "it is a FIFO" "$WORK/stderr"; then
  echo "ok: planet check FIFO -> $(head -1 "$WORK/stderr")"
else
  echo "FAIL: planet check of a FIFO"; cat "$WORK/stderr"; failures=$((failures + 1))
fi
rm -f "$WORK/fifo.toml" "$WORK/fifo.path"
# A planet file with many unknown keys: the first 20 problems, then a count of the rest.
cp "$(dirname "$0")/../../assets/planets/earthlike.toml" "$WORK/many.toml"
for i in $(seq 1 30); do echo "unknown_key_$i = 1" >>"$WORK/many.toml"; done
"$GLOBE" planet check "$WORK/many.toml" 2>"$WORK/stderr"
if [[ $(wc -l <"$WORK/stderr") -eq 22 ]] && grep -q "and 10 more" "$WORK/stderr"; then
  echo "ok: planet check caps its error list"
else
  echo "FAIL: planet check error list not capped:"; head -30 "$WORK/stderr"; failures=$((failures + 1))
fi
rm -f "$WORK/many.toml"
# Bad land cover ([climate], [[land_cover]]): the first problem on one line, file:line:column and
# field, exit 2 and nothing written.
LAND='radius_m = 5e6
[[layers]]
octaves = 2
wavelength_m = 1e6
amplitude_m = 100
'
CLASS='[[land_cover]]
name = "grass"
colour = [0.1, 0.3, 0.05]
'
printf '%s%smoisture = [0.8, 0.2]\n' "$LAND" "$CLASS" >"$WORK/lc_moisture.toml"
expect 2 "lc_moisture.toml:9:12: land_cover\[0\].moisture: the first value must be below the second" "$WORK/lc.exr" -- "$GLOBE" planet export "$WORK/lc_moisture.toml" --width 64 --out "$WORK/lc.exr"
printf '%s%scolor = [1, 1, 1]\n' "$LAND" "$CLASS" >"$WORK/lc_key.toml"
expect 2 "lc_key.toml:9:1: land_cover\[0\].color: unknown key \(did you mean 'colour'\?\)" "$WORK/lc.exr" -- "$GLOBE" planet export "$WORK/lc_key.toml" --width 64 --out "$WORK/lc.exr"
{ printf '%s' "$LAND"; for i in 0 1 2 3 4 5 6 7 8; do printf '[[land_cover]]\nname = "c%s"\ncolour = [0, 0, 0]\n' "$i"; done; } >"$WORK/lc_nine.toml"
expect 2 "lc_nine.toml:30:1: land_cover: at most 8 classes" "" -- "$GLOBE" planet stats "$WORK/lc_nine.toml" --samples 10
printf '%s[climate]\nmoisture_base = 0.5\n' "$LAND" >"$WORK/lc_climate.toml"
expect 2 "lc_climate.toml:6:1: climate: \[climate\] needs at least one \[\[land_cover\]\] class" "" -- "$GLOBE" planet stats "$WORK/lc_climate.toml" --samples 10
printf '%s' "$LAND" >"$WORK/lc_none.toml"
expect 2 "--land-cover: the planet has no \[\[land_cover\]\] classes" "$WORK/lc.png" -- "$GLOBE" planet export "$WORK/lc_none.toml" --width 64 --out "$WORK/lc.exr" --land-cover "$WORK/lc.png"
expect 2 "--land-cover: '.*lc.jpg' must end in .png" "$WORK/lc.exr" -- "$GLOBE" planet export --width 64 --out "$WORK/lc.exr" --land-cover "$WORK/lc.jpg"
[[ -e "$WORK/lc.exr" ]] && { echo "FAIL: a refused land cover export left lc.exr"; failures=$((failures + 1)); }
rm -f "$WORK"/lc_*.toml
# A write that fails keeps the earlier file: a file size limit (EFBIG, SIGXFSZ ignored) stands in
# for a full disk (ENOSPC); both go through the same checked writer.
limited() { bash -c 'trap "" XFSZ; ulimit -f "$0"; exec "$@"' "$@"; }
"$GLOBE" render --size 64x48 --out "$WORK/keep.png" >/dev/null 2>&1 && cp "$WORK/keep.png" "$WORK/keep.orig"
expect 1 "keep.png: cannot write: File too large" "" -- limited 16 "$GLOBE" render --size 1024x768 --out "$WORK/keep.png"
cmp -s "$WORK/keep.png" "$WORK/keep.orig" || { echo "FAIL: a failed render write changed keep.png"; failures=$((failures + 1)); }
"$GLOBE" planet export --width 64 --out "$WORK/map.exr" --png "$WORK/keep.png" >/dev/null 2>&1
cp "$WORK/keep.png" "$WORK/keep.orig"
expect 1 "keep.png: cannot write: File too large" "" -- limited 16 "$GLOBE" planet export --width 64 --out "$WORK/map.exr" --png "$WORK/keep.png" --png-width 2048
cmp -s "$WORK/keep.png" "$WORK/keep.orig" || { echo "FAIL: a failed export write changed keep.png"; failures=$((failures + 1)); }
rm -f "$WORK/keep.png" "$WORK/keep.orig" "$WORK/map.exr"
expect 1 "cannot write: File too large" "" -- limited 8 "$GLOBE" bench --path "$(dirname "$0")/../data/short.path" --size 64x64 --keyframes 99 --out "$WORK/small_bench"
rm -rf "$WORK/small_bench"
# A bench whose report cannot be written leaves the earlier run whole: its key frames too.
SHORT="$(dirname "$0")/../data/short.path"
"$GLOBE" bench --path "$SHORT" --size 64x64 --keyframes 0.25 --out "$WORK/keep_bench" >/dev/null 2>&1
cp "$WORK/keep_bench/keyframe_00.25s.png" "$WORK/keyframe.orig"
expect 1 "cannot write: File too large" "" -- limited 8 "$GLOBE" bench --path "$SHORT" --size 48x32 --keyframes 0.25 --out "$WORK/keep_bench"
cmp -s "$WORK/keep_bench/keyframe_00.25s.png" "$WORK/keyframe.orig" ||
  { echo "FAIL: a failed bench replaced the earlier run's key frame"; failures=$((failures + 1)); }
rm -rf "$WORK/keep_bench" "$WORK/keyframe.orig"
# Paths and benches beyond the limits of docs/reliability.md ("Input limits"), refused up front.
printf '%s\n' "t_s lat_deg lon_deg height_m heading_deg pitch_deg roll_deg" "0 0 0 100 0 0 0" "3000 0 0.01 100 0 0 0" >"$WORK/long.path"
expect 2 "--rate: 3000 s of path at 100 Hz is 300001 frames, more than the limit of 216001" "" -- "$GLOBE" bench --path "$WORK/long.path" --rate 100 --out "$WORK/bench"
printf '%s\n' "t_s lat_deg lon_deg height_m heading_deg pitch_deg roll_deg" "0 0 1e308 100 0 0 0" "1 0 0 100 0 0 0" >"$WORK/far.path"
expect 2 "far.path:2: lon_deg must be within \[-360, 360\]" "" -- "$GLOBE" bench --path "$WORK/far.path" --out "$WORK/bench"
rm -f "$WORK/long.path" "$WORK/far.path"
# A planet name with terminal escape sequences is printed escaped (\xNN), never raw.
sed 's/^name = "earthlike"/name = "x\\u001b]0;pwned\\u0007"/' "$(dirname "$0")/../../assets/planets/earthlike.toml" >"$WORK/name.toml"
if "$GLOBE" planet stats "$WORK/name.toml" --samples 1000 2>&1 | grep -q $'\x1b'; then
  echo "FAIL: planet stats printed a raw ESC of the planet name"; failures=$((failures + 1))
else
  echo "ok: planet stats escapes the planet name"
fi
rm -f "$WORK/name.toml"
# Unknown options and subcommands.
expect 2 "bogus" "" -- "$GLOBE" render --bogus
expect 2 "frobnicate" "" -- "$GLOBE" frobnicate

# And the good case works, leaving exactly the output.
if ! "$GLOBE" render --size 64x48 --out "$WORK/good.exr" >/dev/null 2>"$WORK/stderr" || [[ ! -s "$WORK/good.exr" ]]; then
  echo "FAIL: good render"; cat "$WORK/stderr"; failures=$((failures + 1))
fi

echo "bad input: $failures failure(s)"
exit $((failures > 0))
