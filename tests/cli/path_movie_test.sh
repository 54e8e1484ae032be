#!/usr/bin/env bash
# globe path import|export and globe movie end to end: KML and CZML in, .path and .kml out, a tiny
# movie as PNGs and MP4, and bad input (one line on stderr, exit 2, nothing written).
# Usage: path_movie_test.sh GLOBE SOURCE_DIR WORKDIR
set -uo pipefail
GLOBE="$1"
SRC="$2"
WORK="$3"
rm -rf "$WORK" && mkdir -p "$WORK"
DATA="$SRC/tests/data"
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }

# expect CODE PATTERN OUTPUT -- ARGS...: exit code CODE, stderr one line matching PATTERN, OUTPUT absent.
expect() {
  local code="$1" pattern="$2" output="$3"
  shift 4
  "$@" >"$WORK/stdout" 2>"$WORK/stderr"
  local got=$?
  if [[ $got -ne $code ]]; then fail "'$*' exited $got, expected $code"; cat "$WORK/stderr"; return; fi
  if [[ $(wc -l <"$WORK/stderr") -ne 1 ]] || ! grep -qE "^globe: error: .*$pattern" "$WORK/stderr"; then
    fail "'$*' stderr is not one line matching '$pattern':"; cat "$WORK/stderr"; return
  fi
  if [[ -n "$output" && -e "$output" ]]; then fail "'$*' left $output behind"; return; fi
  echo "ok: $* -> $(cat "$WORK/stderr")"
}

# Import, export, import again: the same keyframes.
"$GLOBE" path import "$DATA/tour.kml" --out "$WORK/tour.path" || fail "import tour.kml"
grep -q '^t_s lat_deg lon_deg height_m heading_deg pitch_deg roll_deg height_ref stop$' "$WORK/tour.path" ||
  fail "tour.path lacks the height_ref/stop header"
"$GLOBE" path import "$DATA/track.czml" --out "$WORK/track.path" || fail "import track.czml"
"$GLOBE" path export "$WORK/tour.path" --out "$WORK/tour.kml" || fail "export"
grep -q '<gx:Tour>' "$WORK/tour.kml" && grep -q '<gx:flyToMode>smooth</gx:flyToMode>' "$WORK/tour.kml" ||
  fail "export is not a smooth gx:Tour"
"$GLOBE" path import "$WORK/tour.kml" --out "$WORK/tour2.path" || fail "re-import"
[[ $(grep -vc '^#' "$WORK/tour.path") -eq $(grep -vc '^#' "$WORK/tour2.path") ]] || fail "round trip changed the keyframe count"

# Bad input.
expect 2 "tests/data/bad_paths/tilt.kml:7:12: tilt: 'abc' is not a finite number" "$WORK/bad.path" -- \
  "$GLOBE" path import "$DATA/bad_paths/tilt.kml" --out "$WORK/bad.path"
expect 2 "bad_paths/syntax.czml:3:73: invalid JSON" "$WORK/bad.path" -- \
  "$GLOBE" path import "$DATA/bad_paths/syntax.czml" --out "$WORK/bad.path"
expect 2 "FILE: import reads .kml" "$WORK/bad.path" -- "$GLOBE" path import "$DATA/short.path" --out "$WORK/bad.path"
expect 2 "--out: must name a .path file" "$WORK/bad.txt" -- "$GLOBE" path import "$DATA/tour.kml" --out "$WORK/bad.txt"
expect 2 "--out: must name a .kml file" "$WORK/bad.path" -- "$GLOBE" path export "$DATA/short.path" --out "$WORK/bad.path"
expect 2 "--fps: an MP4 takes 24, 25, 30, 50 or 60, got 29" "$WORK/m.mp4" -- \
  "$GLOBE" movie --path "$DATA/short.path" --fps 29 --out "$WORK/m.mp4"
expect 2 "--fps: must be within \[1, 1000\], got 0" "$WORK/m" -- \
  "$GLOBE" movie --path "$DATA/short.path" --fps 0 --out "$WORK/m"
expect 2 "--size: H.264 needs an even width and height, got 65x48" "$WORK/m.mp4" -- \
  "$GLOBE" movie --path "$DATA/short.path" --size 65x48 --out "$WORK/m.mp4"
expect 2 "--out: must be a directory .* or a .mp4 file" "$WORK/m.avi" -- \
  "$GLOBE" movie --path "$DATA/short.path" --out "$WORK/m.avi"
expect 2 "--format: must be png or exr" "$WORK/m" -- "$GLOBE" movie --path "$DATA/short.path" --format jpg --out "$WORK/m"
expect 2 "bad_paths/no_tour.kml:1: gx:Tour: no tour" "$WORK/m" -- \
  "$GLOBE" movie --path "$DATA/bad_paths/no_tour.kml" --out "$WORK/m"
# A FIFO where the movie manifest belongs is refused at once (it used to block forever).
mkdir -p "$WORK/fifo_movie" && mkfifo "$WORK/fifo_movie/movie.txt"
expect 2 "movie.txt: --out: cannot read movie manifest: it is a FIFO" "" -- \
  timeout 60 "$GLOBE" movie --path "$DATA/short.path" --size 64x48 --out "$WORK/fifo_movie"
rm -rf "$WORK/fifo_movie"

# A tiny movie from a KML tour given straight to --path (the tour's first 0.2 s is too short to
# be interesting, so use short.path's 0.5 s descent at 24 fps: 13 frames) as PNGs and as MP4.
"$GLOBE" movie --path "$DATA/short.path" --size 64x48 --fps 24 --quality fast --out "$WORK/frames" >"$WORK/movie.out" ||
  fail "movie (PNG)"
cat "$WORK/movie.out"
[[ $(ls "$WORK/frames" | grep -c '^frame_[0-9]\{6\}\.png$') -eq 13 ]] || fail "expected 13 PNG frames"
"$GLOBE" movie --path "$DATA/short.path" --size 64x48 --fps 24 --quality fast --out "$WORK/frames" >"$WORK/movie.out" ||
  fail "movie (resume)"
grep -q "0 rendered, 13 kept" "$WORK/movie.out" || fail "a complete sequence was rendered again: $(cat "$WORK/movie.out")"
expect 2 "frames/movie.txt: --out: this directory holds frames of another movie" "" -- \
  "$GLOBE" movie --path "$DATA/short.path" --size 64x48 --fps 25 --quality fast --out "$WORK/frames"
[[ $(ls "$WORK/frames" | grep -c '^frame_') -eq 13 ]] || fail "a refused resume changed the frames"
# Any rate for an image sequence: a 2 fps preview of the 0.5 s descent is 2 frames.
"$GLOBE" movie --path "$DATA/short.path" --size 64x48 --fps 2 --quality fast --out "$WORK/preview" >"$WORK/preview.out" ||
  fail "movie --fps 2 (PNG preview)"
[[ $(ls "$WORK/preview" | grep -c '^frame_[0-9]\{6\}\.png$') -eq 2 ]] || fail "expected 2 preview frames"
"$GLOBE" movie --path "$DATA/short.path" --size 64x48 --fps 24 --quality fast --out "$WORK/short.mp4" >"$WORK/mp4.out" ||
  fail "movie (MP4)"
cat "$WORK/mp4.out"
grep -q "^encoder: libx264" "$WORK/mp4.out" || fail "the MP4 was not encoded by libx264"
[[ -s "$WORK/short.mp4" ]] || fail "no MP4"
ls "$WORK" | grep -q '\.tmp' && fail "a temporary file was left behind"
# The same MP4 twice is the same file (issue 40 item 10: x264's AVX-512 code read uninitialised memory).
"$GLOBE" movie --path "$DATA/short.path" --size 160x90 --fps 24 --quality balanced --out "$WORK/a.mp4" >/dev/null &&
  "$GLOBE" movie --path "$DATA/short.path" --size 160x90 --fps 24 --quality balanced --out "$WORK/b.mp4" >/dev/null ||
  fail "movie (MP4 twice)"
cmp -s "$WORK/a.mp4" "$WORK/b.mp4" || fail "two runs of one MP4 gave different files"

# Resumed sequences are bit-identical to an uninterrupted one (issue 40 item 9): the whole plateau
# tour at 4 fps, where the LOD ranges learn all the way to the exit at 25 000 km. Resumed once from
# the LOD log, once without it (the frames before each gap are replayed unwritten: 0-19, 22-54, 60-69).
tour=(movie --path "$SRC/assets/paths/plateau-tour.kml" --size 160x90 --fps 4)
"$GLOBE" "${tour[@]}" --out "$WORK/tour" >/dev/null || fail "movie (tour)"
for variant in log nolog; do
  rm -rf "$WORK/resumed" && cp -r "$WORK/tour" "$WORK/resumed"
  rm -f "$WORK/resumed"/frame_00002[01].png "$WORK/resumed"/frame_00005[5-9].png "$WORK/resumed"/frame_00007*.png
  [[ $variant == nolog ]] && rm "$WORK/resumed/lod-log.txt"
  "$GLOBE" "${tour[@]}" --out "$WORK/resumed" >"$WORK/resumed.out" || fail "movie (tour resumed, $variant)"
  grep -q "^wrote .* 17 rendered, 64 kept" "$WORK/resumed.out" || fail "resumed ($variant): $(cat "$WORK/resumed.out")"
  if [[ $variant == nolog ]]; then
    grep -q "^replayed 63 earlier frames" "$WORK/resumed.out" || fail "no replay: $(cat "$WORK/resumed.out")"
  fi
  for f in "$WORK/tour"/frame_*.png; do
    cmp -s "$f" "$WORK/resumed/${f##*/}" || { fail "resumed ($variant) ${f##*/} differs"; break; }
  done
done

if ((failures)); then echo "$failures failure(s)"; exit 1; fi
echo "all path and movie checks passed"
