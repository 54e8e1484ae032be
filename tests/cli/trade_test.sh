#!/usr/bin/env bash
# globe trade end to end (quick, one configuration, tiny image): outputs exist, the CSV header, the
# SVG is complete; bad input is one line, exit 2, nothing written. Usage: trade_test.sh GLOBE WORKDIR
set -uo pipefail
GLOBE="$1"
WORK="$2"
rm -rf "$WORK" && mkdir -p "$WORK"
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }

"$GLOBE" trade --quick --size 96x64 --configs 1 --frames 1 --stride 2 --out "$WORK/t" --validate \
  >"$WORK/stdout" 2>"$WORK/stderr" || { fail "trade run"; cat "$WORK/stderr"; }
for f in trade.csv pareto.svg pareto-image.svg; do [[ -s "$WORK/t/$f" ]] || fail "missing $f"; done
header=$(head -1 "$WORK/t/trade.csv")
expected="config,camera,grid_cells,distance_multiplier,max_depth,morph_fraction,generation,positions,lod,tolerance_px,width,height,converged,frame_median_ms,frame_p95_ms,select_ms,triangles,nodes,resident_mib,gen_ms_per_node,err_p50_px,err_p95_px,err_max_px,err_p50_m,err_p95_m,err_max_m,silhouette_mismatches,silhouette_max_px,samples,samples_both_hit,truth_unresolved,ssim,colour_de2000"
[[ "$header" == "$expected" ]] || fail "trade.csv header: $header"
rows=$(($(wc -l <"$WORK/t/trade.csv") - 1))
[[ $rows -eq 3 ]] || fail "trade.csv has $rows rows, expected 3 (two cameras and the worst)"
grep -q ',worst,' "$WORK/t/trade.csv" || fail "no worst row"
# Every row compares its picture with the exact image: an SSIM in (0, 1] and a colour difference.
awk -F, 'NR > 1 && !($(NF-1) > 0 && $(NF-1) <= 1 && $NF >= 0 && $NF != "") { bad = 1 } END { exit bad }' \
  "$WORK/t/trade.csv" || fail "image columns: $(cut -d, -f1,2,32,33 "$WORK/t/trade.csv")"
grep -q '<svg' "$WORK/t/pareto.svg" || fail "pareto.svg has no <svg"
grep -q '</svg>' "$WORK/t/pareto.svg" || fail "pareto.svg has no </svg>"
ls -a "$WORK/t" | grep -q '\.tmp' && fail "temporary files left"

bad() {  # bad NAME ARGS...: exit 2, one line on stderr, nothing written
  local name="$1"; shift
  "$GLOBE" trade --out "$WORK/bad_$name" "$@" >"$WORK/bad.out" 2>"$WORK/bad.err"
  local code=$?
  [[ $code -eq 2 ]] || fail "$name: exit $code, expected 2"
  [[ $(wc -l <"$WORK/bad.err") -eq 1 ]] || { fail "$name: stderr is not one line"; cat "$WORK/bad.err"; }
  grep -q '^globe: error: ' "$WORK/bad.err" || fail "$name: stderr: $(cat "$WORK/bad.err")"
  [[ -e "$WORK/bad_$name" ]] && fail "$name: output written"
}
bad quality --quality best
bad size --size 3x3
bad planet --planet "$WORK/missing.toml"
bad frames --frames 5000
bad unknown --frobnicate
"$GLOBE" trade --out /dev/null/x --quick >"$WORK/bad.out" 2>"$WORK/bad.err"
[[ $? -eq 2 ]] || fail "parent directory a device: not exit 2"
# --quality on the rendering commands.
"$GLOBE" render --quality best --out "$WORK/r.png" >"$WORK/bad.out" 2>"$WORK/bad.err"
[[ $? -eq 2 ]] || fail "render --quality best: not exit 2"
grep -q "unknown quality 'best'" "$WORK/bad.err" || fail "render --quality: $(cat "$WORK/bad.err")"
[[ -e "$WORK/r.png" ]] && fail "render wrote a file"
"$GLOBE" render --quality fast --size 64x48 --out "$WORK/fast.png" >"$WORK/r.out" 2>"$WORK/r.err" || fail "render --quality fast"
[[ -s "$WORK/fast.png" ]] || fail "render --quality fast wrote nothing"

# --tolerance on the rendering commands: bad values are one line naming the option, exit 2.
badTolerance() {  # badTolerance COMMAND VALUE [OPTION]
  local option=${3:---tolerance}
  (cd "$WORK" && "$GLOBE" "$1" "$option" "$2" >"$WORK/bad.out" 2>"$WORK/bad.err")
  local code=$?
  [[ $code -eq 2 ]] || fail "$1 $option $2: exit $code, expected 2"
  [[ $(wc -l <"$WORK/bad.err") -eq 1 ]] || fail "$1 $option $2: stderr is not one line"
  grep -q -- "$option" "$WORK/bad.err" || fail "$1 $option $2: $(cat "$WORK/bad.err")"
}
for value in 0 -1 nan 5000; do badTolerance render "$value"; done
for command in bench movie view trade; do badTolerance "$command" abc; done
# --texel-px likewise (0 is valid: the texel rule off).
for value in 0.1 -1 nan 5000 abc; do badTolerance render "$value" --texel-px; done
"$GLOBE" render --texel-px 8 --size 64x48 --out "$WORK/texel.png" >"$WORK/r.out" 2>"$WORK/r.err" || fail "render --texel-px 8"
# A tolerance-driven trade row says so in the lod column.
"$GLOBE" trade --quick --size 96x64 --configs 1 --frames 1 --stride 4 --cameras 1km --tolerance 2 \
  --out "$WORK/tt" >"$WORK/tt.out" 2>"$WORK/tt.err" || { fail "trade --tolerance"; cat "$WORK/tt.err"; }
lod=$(awk -F, 'NR == 2 { print $9 "," $10 }' "$WORK/tt/trade.csv")
[[ "$lod" == "tolerance,2.000" ]] || fail "trade --tolerance 2: lod,tolerance_px = $lod"
# balanced is an 8 px tolerance (docs/tradeoffs.md, "Presets").
lod=$(awk -F, 'NR == 2 { print $9 "," $10 }' "$WORK/t/trade.csv")
[[ "$lod" == "tolerance,8.000" ]] || fail "trade (balanced): lod,tolerance_px = $lod"

if [[ $failures -ne 0 ]]; then echo "$failures failure(s)"; exit 1; fi
echo "trade: all checks passed"
