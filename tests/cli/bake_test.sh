#!/usr/bin/env bash
# globe bake end to end (issue 19): bad options fail on one line with nothing written; shards run by
# GNU parallel give byte-identical tiles to one run; a killed bake leaves no half-written tile and
# resumes to the same result; COG tiles are valid Cloud-Optimized GeoTIFFs (gdalinfo); a baked tileset
# reads back as a planet source (planet check, planet sample, a bad tileset); a planet with DEM
# sources bakes.
# Usage: bake_test.sh GLOBE SOURCE_DIR WORK_DIR
set -uo pipefail
GLOBE="$1"
SRC="$2"
WORK="$3"
PLANET="$SRC/assets/planets/earthlike.toml"
rm -rf "$WORK"
mkdir -p "$WORK"
failures=0
fail() {
  echo "FAIL: $*"
  failures=$((failures + 1))
}

# ---- bad input: one line on stderr, exit 2, no output directory ----
bad() {  # bad EXPECTED_TEXT ARGS...
  local expected="$1" out="$WORK/bad_out"
  shift
  rm -rf "$out"
  "$GLOBE" bake --planet "${BAD_PLANET:-$PLANET}" --out "$out" "$@" >"$WORK/bad.stdout" 2>"$WORK/bad.stderr"
  local code=$?
  local lines
  lines=$(wc -l <"$WORK/bad.stderr")
  if [[ $code -ne 2 || $lines -ne 1 ]] || ! grep -q -- "$expected" "$WORK/bad.stderr" || [[ -e "$out" ]]; then
    fail "bake $* -> exit $code, $lines stderr lines, out exists: $([[ -e $out ]] && echo yes || echo no): $(cat "$WORK/bad.stderr")"
  else
    echo "ok: bake $*: $(cat "$WORK/bad.stderr")"
  fi
}
bad "unknown format 'png'" --format png --levels 0..2
bad "levels must satisfy" --format cog --levels 5..2
bad "levels must satisfy" --format cog --levels 0..30
bad "expected A..B" --format cog --levels two
bad "expected W,S,E,N" --format cog --levels 0..2 --region 1,2,3
bad "longitudes must satisfy" --format cog --levels 0..2 --region 10,0,5,5
bad "latitudes must satisfy" --format cog --levels 0..2 --region 0,40,5,95
bad "shard must satisfy" --format cog --levels 0..2 --shard 3/3
bad "shard must satisfy" --format cog --levels 0..2 --shard 0/0
bad "expected K/N" --format cog --levels 0..2 --shard 1of2
BAD_PLANET="$WORK/missing.toml" bad "missing.toml" --format cog --levels 0..2

# ---- shards with GNU parallel == one run, byte for byte ----
ARGS=(--planet "$PLANET" --format quantized-mesh --levels 0..6 --region 5,40,12,47)
"$GLOBE" bake "${ARGS[@]}" --out "$WORK/one" >"$WORK/one.log" || fail "single bake failed: $(cat "$WORK/one.log")"
parallel --halt now,fail=1 "$GLOBE" bake "${ARGS[@]}" --shard {}/3 --out "$WORK/sharded" ::: 0 1 2 >"$WORK/sharded.log" 2>&1 ||
  fail "sharded bake failed: $(cat "$WORK/sharded.log")"
if diff -r "$WORK/one" "$WORK/sharded" >/dev/null; then
  echo "ok: 3 shards under GNU parallel == one run ($(find "$WORK/one" -name '*.terrain' | wc -l) tiles)"
else
  fail "sharded tiles differ from the single run"
fi
"$GLOBE" bake "${ARGS[@]}" --out "$WORK/one" >"$WORK/again.log" || fail "rerun failed"
grep -q " 0 of .* tiles written" "$WORK/again.log" && echo "ok: a rerun skips every finished tile" ||
  fail "a rerun rewrote tiles: $(cat "$WORK/again.log")"
"$GLOBE" bake --planet "$SRC/assets/planets/marslike.toml" --format quantized-mesh --levels 0..6 --region 5,40,12,47 \
  --out "$WORK/one" >/dev/null 2>"$WORK/mixed.err"
[[ $? -ne 0 ]] && grep -q "another bake" "$WORK/mixed.err" && echo "ok: another planet into the same directory is refused" ||
  fail "mixing bakes was not refused: $(cat "$WORK/mixed.err")"

# ---- two bakes of different regions started together into one empty directory: one is refused ----
for trial in 1 2 3 4; do
  race="$WORK/race_$trial"
  "$GLOBE" bake --planet "$PLANET" --format quantized-mesh --levels 0..4 --region 5,40,12,47 --out "$race" \
    >/dev/null 2>"$race.a.err" &
  a=$!
  "$GLOBE" bake --planet "$PLANET" --format quantized-mesh --levels 0..4 --region 20,10,30,20 --out "$race" \
    >/dev/null 2>"$race.b.err" &
  b=$!
  wait $a; ca=$?
  wait $b; cb=$?
  if (((ca == 0) + (cb == 0) == 1)) && cat "$race.a.err" "$race.b.err" | grep -q "another bake"; then
    echo "ok: race $trial: one bake refused"
  else
    fail "race $trial: exits $ca and $cb: $(cat "$race.a.err" "$race.b.err")"
  fi
done

# ---- a killed bake: no half-written tile, resumes to the same tiles ----
BIG=(--planet "$PLANET" --format quantized-mesh --levels 0..8 --region 0,40,5,45)
"$GLOBE" bake "${BIG[@]}" --out "$WORK/clean" >/dev/null || fail "clean bake failed"
total=$(find "$WORK/clean" -name '*.terrain' | wc -l)
for sig in KILL TERM; do
  out="$WORK/killed_$sig"
  "$GLOBE" bake "${BIG[@]}" --out "$out" >/dev/null 2>&1 &
  pid=$!
  for _ in $(seq 100); do  # wait until some tiles are there, then stop it midway
    (($(find "$out" -name '*.terrain' 2>/dev/null | wc -l) > 20)) && break
    sleep 0.1
  done
  kill -"$sig" "$pid"
  wait "$pid" 2>/dev/null
  done_tiles=$(find "$out" -name '*.terrain' | wc -l)
  ((done_tiles < total)) || echo "note: the $sig bake finished before it was stopped"
  temps=$(find "$out" -name '.*.tmp*' | wc -l)
  [[ $sig == TERM && $temps -ne 0 ]] && fail "SIGTERM left $temps temporaries"
  # Every finished tile is whole: byte-identical to the clean bake's.
  partial=0
  while read -r f; do cmp -s "$f" "$WORK/clean/${f#"$out"/}" || partial=$((partial + 1)); done < <(find "$out" -name '*.terrain')
  ((partial == 0)) || fail "$partial tiles of the SIG$sig bake differ from the clean bake's"
  "$GLOBE" bake "${BIG[@]}" --out "$out" >"$WORK/resume.log" || fail "resume after SIG$sig failed"
  if diff -r "$WORK/clean" "$out" >/dev/null; then
    echo "ok: SIG$sig after $done_tiles of $total tiles ($temps temporaries), resumed: $(cat "$WORK/resume.log")"
  else
    fail "the resumed SIG$sig bake differs from the clean bake"
  fi
done

# ---- COG through GDAL ----
"$GLOBE" bake --planet "$PLANET" --format cog --levels 0..2 --region 5,40,12,47 --out "$WORK/cog" >"$WORK/cog.log" ||
  fail "COG bake failed: $(cat "$WORK/cog.log")"
for f in $(find "$WORK/cog" -name '*.tif' | sort); do
  info=$(gdalinfo "$f" 2>&1)
  if ! grep -q "LAYOUT=COG" <<<"$info" || ! grep -q "Size is 256, 256" <<<"$info" ||
    ! grep -q 'ELLIPSOID\["sphere",6371000,0' <<<"$info" || ! grep -q "Overviews: 128x128" <<<"$info"; then
    fail "$f is not the expected COG: $info"
  fi
done
echo "ok: $(find "$WORK/cog" -name '*.tif' | wc -l) COG tiles pass gdalinfo (LAYOUT=COG, 256x256, sphere CRS, overview)"

# ---- read back: the baked tileset as the source of a planet with earthlike's layers ----
RB="$WORK/readback"
mkdir -p "$RB"
if ! "$GLOBE" bake --planet "$PLANET" --format quantized-mesh --levels 12 --region -99.05,38.95,-99.0,39.0 \
  --out "$RB/qm" >"$RB/bake.log" 2>&1; then
  fail "read-back bake failed: $(cat "$RB/bake.log")"
fi
{ cat "$PLANET"; printf '\n[[sources]]\npath = "qm"\n'; } >"$RB/baked.toml"
if ! "$GLOBE" planet check "$RB/baked.toml" >"$RB/check.log" 2>&1 || ! grep -q "source 0 (rank 0): .*/qm:" "$RB/check.log"; then
  fail "planet check of the baked planet: $(cat "$RB/check.log")"
fi
# Level 12's error is 18.8 m; these points lie inside the region, away from its tiles' borders.
at=(--at 38.97,-99.03 --at 38.985,-99.012 --at 38.96,-99.04)
baked=$("$GLOBE" planet sample "$RB/baked.toml" "${at[@]}" | awk '{print $2}')
original=$("$GLOBE" planet sample "$PLANET" "${at[@]}" | awk '{print $2}')
if ! paste <(echo "$baked") <(echo "$original") | awk '{d = $1 - $2; if (d < 0) d = -d; if (d > 18.8 || NF != 2) bad = 1} END {exit bad}'; then
  fail "baked vs original samples differ by more than the level's error: $baked / $original"
else
  echo "ok: planet sample over the baked source = the original within level 12's error ($(echo $baked) vs $(echo $original))"
fi
# A planet with [[sources]] bakes its DEM mosaic (earth-dem's Jacksboro grid).
if ! "$GLOBE" bake --planet "$SRC/assets/planets/earth-dem.toml" --format cog --levels 11 \
  --region -84.28,36.57,-84.25,36.6 --out "$RB/dem" >"$RB/dem.log" 2>&1; then
  fail "earth-dem bake failed: $(cat "$RB/dem.log")"
else
  echo "ok: earth-dem bakes: $(head -1 "$RB/dem.log")"
fi
# A bad tileset: one error line naming the file (then planet check's count), exit 2.
rm "$RB/qm/layer.json"
"$GLOBE" planet check "$RB/baked.toml" >"$RB/bad.stdout" 2>"$RB/bad.stderr"
code=$?
if [[ $code -ne 2 ]] || [[ $(grep -c "sources\[0\]" "$RB/bad.stderr") -ne 1 ]] ||
  ! grep -q "baked.toml:[0-9]*:[0-9]*: sources\[0\].path: .*qm/layer.json: no such file" "$RB/bad.stderr"; then
  fail "missing layer.json -> exit $code: $(cat "$RB/bad.stderr")"
else
  echo "ok: $(cat "$RB/bad.stderr")"
fi

# A plan of 2^49 tiles is never listed (issue 40 item 7: the last of a million shards spun with no
# tile, levels 0..14 took 3 GB first): within 10 s the shard has written tiles, in little memory.
huge="$WORK/huge"
"$GLOBE" bake --planet "$PLANET" --format quantized-mesh --levels 0..24 --shard 999999/1000000 --out "$huge" \
  >/dev/null 2>&1 &
pid=$!
sleep 10
rss_kb=$(awk '/^VmHWM:/ { print $2 }' "/proc/$pid/status" 2>/dev/null)
kill -INT "$pid" 2>/dev/null
wait "$pid"
tiles=$(find "$huge" -name '*.terrain' | wc -l)
rss_kb=${rss_kb:-0}
if ((tiles > 0 && rss_kb < 1000000)); then echo "ok: huge plan: $tiles tiles in 10 s, $rss_kb KB"
else fail "huge plan: $tiles tiles in 10 s, $rss_kb KB resident"; fi
find "$huge" -name '.*.tmp*' | grep -q . && fail "huge plan: an interrupted tile left its temporary"

if ((failures > 0)); then
  echo "$failures failures"
  exit 1
fi
echo "all bake checks passed"
