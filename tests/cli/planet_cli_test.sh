#!/usr/bin/env bash
# globe planet check/stats/sample/export from the command line: happy paths on every preset, every
# problem of a bad file at once, bad inputs (one line, exit 2, nothing written) and an interrupted
# export (kill -9 and SIGINT mid-way) that leaves no output file. The exported pixel values are
# checked against the CPU reference in tests/engine/elevation_export_test.cpp.
# Usage: planet_cli_test.sh GLOBE SOURCE_DIR WORKDIR
set -uo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/cli_common.sh"

# -- check: every preset is valid; the default planet is found from any directory.
for p in "$SRC"/assets/planets/*.toml; do
  out=$("$GLOBE" planet check "$p" 2>&1) || fail "check $p: $out"
  # Planets with [[sources]] add one line per source after the verdict.
  [[ "$(head -1 <<<"$out")" == "$p: ok" ]] || fail "check $p printed '$out'"
done

# -- sources (docs/elevation-data.md): check reports them, sample draws the mosaic.
out=$("$GLOBE" planet check "$SRC/assets/planets/earth-dem.toml")
grep -q "source 0 (rank 0): .*jacksboro.vrt: 403 x 344 px, CRS 'WGS 84'" <<<"$out" || fail "check of earth-dem: '$out'"
grep -q "source 1 (rank 1): .*topobathy.vrt: 120 x 91 px" <<<"$out" || fail "check of earth-dem: '$out'"
h=$("$GLOBE" planet sample "$SRC/assets/planets/earth-dem.toml" --at 36.59,-84.25 | cut -d' ' -f2)
awk -v h="$h" 'BEGIN { exit !(h > 500 && h < 600) }' || fail "earth-dem at Jacksboro: $h m (the DEM says 552 m)"
sed 's#path = "dem/jacksboro.vrt"#path = "dem/missing.tif"#' "$SRC/assets/planets/earth-dem.toml" >"$WORK/nodem.toml"
"$GLOBE" planet check "$WORK/nodem.toml" 2>"$WORK/stderr" && fail "a missing source was accepted"
grep -q "nodem.toml:16:8: sources\[0\].path: no such file" "$WORK/stderr" || fail "missing source: $(cat "$WORK/stderr")"
(cd / && "$GLOBE" planet check >/dev/null 2>&1) || fail "check of the default planet from /"
GLOBE_ASSET_DIR=/nonexistent "$GLOBE" planet check >/dev/null 2>&1 && fail "GLOBE_ASSET_DIR is not honoured"

# -- check: every problem at once, as file:line:column: key: message, exit 2.
cat >"$WORK/bad.toml" <<'TOML'
radius = 6371000
seed = "one"
[[layers]]
octaves = 30
wavelength_m = 1e6
gain = nan
amplitude_m = 1000
[snow]
elevation_m = 1
colour = [0.5, 2, 0.5]
TOML
"$GLOBE" planet check "$WORK/bad.toml" >"$WORK/stdout" 2>"$WORK/stderr"
code=$?
[[ $code -eq 2 ]] || fail "check of a bad file exited $code"
for want in "bad.toml:1:1: radius: unknown key (did you mean 'radius_m'?)" \
            "bad.toml:2:8: seed: expected an integer, got a string" \
            "bad.toml:4:11: layers\[0\].octaves: must be in \[1, 24\]" \
            "bad.toml:6:8: layers\[0\].gain: must be finite" \
            "bad.toml:10:10: snow.colour: each component must be within \[0, 1\]" \
            "bad.toml: 6 problems"; do
  grep -q "$want" "$WORK/stderr" || fail "check output lacks '$want'"
done
[[ -s "$WORK/stdout" ]] && fail "check of a bad file printed to stdout"

# -- stats and sample.
"$GLOBE" planet stats "$SRC/assets/planets/moonlike.toml" --samples 20000 --bins 8 >"$WORK/stats" 2>"$WORK/stderr" \
  || fail "stats: $(cat "$WORK/stderr")"
[[ -s "$WORK/stderr" ]] && fail "stats wrote to stderr (no progress bar without a terminal): $(cat "$WORK/stderr")"
for want in "elevation: min -[0-9.]* m, max [0-9.]* m, mean" "below sea level: [0-9.]* %" "hypsometry"; do
  grep -q "$want" "$WORK/stats" || fail "stats output lacks '$want'"
done
[[ $(grep -c ' m .* % .* %' "$WORK/stats") -eq 8 ]] || fail "stats: expected 8 hypsometry bands"
# Land cover shares: one line per class, percent of the planet's area, summing to 100.
[[ $(grep -c '^land_cover ' "$WORK/stats") -eq 3 ]] || fail "stats: expected 3 land_cover lines: $(cat "$WORK/stats")"
grep -qE '^land_cover highland [0-9]+\.[0-9]$' "$WORK/stats" || fail "stats: no 'land_cover highland PERCENT' line"
awk '/^land_cover / { s += $3 } END { exit !(s > 99.8 && s < 100.2) }' "$WORK/stats" || fail "stats: land cover shares do not sum to 100"
"$GLOBE" planet stats "$SRC/assets/planets/earthlike.toml" --samples 20000 >"$WORK/stats" 2>&1 || fail "earthlike stats"
grep -qE '^land_cover sea [0-9.]+$' "$WORK/stats" || fail "stats: a planet with [water] has no land_cover sea line"
a=$("$GLOBE" planet sample "$SRC/assets/planets/asteroid.toml" --at 10,20 --threads 1 2>/dev/null)
[[ -z "$a" ]] || fail "sample accepted --threads"
a=$("$GLOBE" planet sample "$SRC/assets/planets/asteroid.toml" --at 10,20 --at=-45,170)
[[ $(echo "$a" | wc -l) -eq 2 && "$a" == "10,20 "* ]] || fail "sample printed '$a'"

# -- export: EXR + preview, exactly the two files.
"$GLOBE" planet export "$SRC/assets/planets/marslike.toml" --width 128 --out "$WORK/mars.exr" --png "$WORK/mars.png" \
  >"$WORK/stdout" 2>"$WORK/stderr" || fail "export: $(cat "$WORK/stderr")"
[[ -s "$WORK/mars.exr" && -s "$WORK/mars.png" ]] || fail "export did not write both files"
[[ $(head -c 4 "$WORK/mars.exr" | od -An -tx1 | tr -d ' ') == "762f3101" ]] || fail "mars.exr is not OpenEXR"
ls -A "$WORK" | grep -q '\.tmp' && fail "export left a temporary file"
# -- export of the map alone (a planet with land cover, no PNG asked for).
"$GLOBE" planet export "$SRC/assets/planets/earthlike.toml" --width 64 --out "$WORK/plain.exr" >/dev/null 2>"$WORK/stderr" \
  && [[ -s "$WORK/plain.exr" ]] || fail "export without previews: $(cat "$WORK/stderr")"
# -- export with land cover: the map and the preview at --png-width, PNGs of the right size.
png_size() { od -An -tu1 -j16 -N8 "$1" | awk '{ printf "%dx%d", $3 * 256 + $4, $7 * 256 + $8 }'; }
"$GLOBE" planet export "$SRC/assets/planets/earthlike.toml" --width 128 --out "$WORK/earth.exr" --png "$WORK/earth.png" \
  --land-cover "$WORK/earth-land.png" --png-width 96 >"$WORK/stdout" 2>"$WORK/stderr" || fail "land cover export: $(cat "$WORK/stderr")"
for f in earth.png earth-land.png; do
  [[ "$(png_size "$WORK/$f")" == "96x48" ]] || fail "$f is $(png_size "$WORK/$f"), expected 96x48"
done
grep -q "wrote .*earth-land.png (96x48 land cover map)" "$WORK/stdout" || fail "land cover export printed '$(cat "$WORK/stdout")'"
ls -A "$WORK" | grep -q '\.tmp' && fail "land cover export left a temporary file"

# -- bad inputs: one line, exit 2, nothing written.
expect_usage() {
  local pattern="$1" outfile="$2"
  shift 2
  "$@" >"$WORK/stdout" 2>"$WORK/stderr"
  local got=$?
  if [[ $got -ne 2 ]]; then fail "'$*' exited $got, expected 2: $(cat "$WORK/stderr")"; return; fi
  if [[ $(wc -l <"$WORK/stderr") -ne 1 ]] || ! grep -qE "^globe: error: .*$pattern" "$WORK/stderr"; then
    fail "'$*' stderr is not one line matching '$pattern': $(cat "$WORK/stderr")"; return
  fi
  if [[ -e "$outfile" ]]; then fail "'$*' left $outfile"; return; fi
  echo "ok: $(cat "$WORK/stderr")"
}
O="$WORK/o.exr"
expect_usage "--width: must be even and within \[2, 65536\]" "$O" "$GLOBE" planet export --width 1 --out "$O"
expect_usage "--width: must be even" "$O" "$GLOBE" planet export --width 65537 --out "$O"
expect_usage "--width: must be even" "$O" "$GLOBE" planet export --width 101 --out "$O"
expect_usage "width" "$O" "$GLOBE" planet export --width abc --out "$O"
expect_usage "--out: '.*o.png' must end in .exr" "$WORK/o.png" "$GLOBE" planet export --width 64 --out "$WORK/o.png"
expect_usage "--out: '/dev/null' is not a directory" "" "$GLOBE" planet export --width 64 --out /dev/null/o.exr
expect_usage "--png: '.*p.jpg' must end in .png" "$O" "$GLOBE" planet export --width 64 --out "$O" --png "$WORK/p.jpg"
expect_usage "bad.toml:1:1: radius: unknown key .*and 5 more" "$O" "$GLOBE" planet export "$WORK/bad.toml" --width 64 --out "$O"
expect_usage "cannot open planet file" "$O" "$GLOBE" planet export "$WORK/none.toml" --width 64 --out "$O"
expect_usage "--at: latitude must be within" "" "$GLOBE" planet sample --at 91,0
expect_usage "--at: expected LAT,LON" "" "$GLOBE" planet sample --at 1,2,3
expect_usage "--samples" "" "$GLOBE" planet stats --samples 0
ls -A "$WORK" | grep -q '\.tmp' && fail "a refused export left a temporary file"

# -- interrupted exports: the target never appears. The temporary is .NAME.tmpPID beside it.
interrupt() {
  local signal="$1" target="$WORK/big_$1.exr"
  "$GLOBE" planet export --width 16384 --out "$target" --threads 1 >/dev/null 2>&1 &
  local pid=$!
  # Wait until the export is under way (its temporary exists), then interrupt it mid-way.
  for _ in $(seq 1 100); do [[ -e "$WORK/.big_$1.exr.tmp$pid" ]] && break; sleep 0.1; done
  sleep 0.5
  kill "-$signal" "$pid"
  wait "$pid" 2>/dev/null
  [[ -e "$target" ]] && fail "export killed with SIG$signal left $target"
  local temp="$WORK/.big_$1.exr.tmp$pid"
  if [[ "$signal" == "INT" && -e "$temp" ]]; then fail "SIGINT left the temporary $temp"; fi
  rm -f "$temp"  # SIGKILL cannot be caught: the hidden temporary may remain, never the target
  echo "ok: SIG$signal mid-export left no $target"
}
interrupt KILL
interrupt INT

echo "planet cli: $failures failure(s)"
exit $((failures > 0))
