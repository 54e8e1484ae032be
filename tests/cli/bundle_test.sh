#!/usr/bin/env bash
# The portable GPU bundle (scripts/gpu-bundle.sh, issue 41): the archive stays under the 64 MiB a
# device machine may carry; unpacked elsewhere, the program resolves every library inside the bundle;
# run from an empty environment (`env -i`, only the bundle's own paths) on lavapipe, the bench script's
# validated run passes and writes its report; the build without FFmpeg refuses an MP4 in one line and
# lists no viewer. Usage: bundle_test.sh SOURCE_DIR WORKDIR
set -uo pipefail
SOURCE="$1"
WORK="$2"
rm -rf "$WORK" && mkdir -p "$WORK"
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }

# scripts/test.sh packs it before ctest; here it is only checked to be up to date.
archive="$SOURCE/build/bundle/globe-bundle.tar.xz"
"$SOURCE/scripts/gpu-bundle.sh" >"$WORK/pack.log" 2>&1 || { cat "$WORK/pack.log"; echo "FAIL: gpu-bundle.sh"; exit 1; }
tail -1 "$WORK/pack.log"
size=$(stat -c %s "$archive")
((size < 64 * 1024 * 1024)) || fail "the archive is $size bytes, over 64 MiB"

tar -C "$WORK" -xJf "$archive" || { echo "FAIL: unpacking $archive"; exit 1; }
B="$WORK/globe-bundle"
outside=$(env -i "$B/lib/ld-linux-x86-64.so.2" --library-path "$B/lib" --list "$B/bin/globe" |
  awk '$1 != "linux-vdso.so.1" && $3 !~ "^'"$B"'/" && $1 !~ "ld-linux"')
[[ -z "$outside" ]] || fail "libraries resolved outside the bundle: $outside"

# The bench script's short validated run, from nothing but the bundle.
cd "$WORK" || exit 1
env -i "$B/gpu-bench.sh" --quick --steps validate --out "$WORK/gb" >"$WORK/gb.log" 2>&1 ||
  { fail "gpu-bench.sh --quick --steps validate under env -i"; cat "$WORK/gb.log"; }
grep -q '^   device: llvmpipe' "$WORK/gb/summary.txt" || fail "summary names no lavapipe device: $(cat "$WORK/gb/summary.txt")"
grep -q '^   bench: 101 frames' "$WORK/gb/summary.txt" || fail "summary has no bench line: $(cat "$WORK/gb/summary.txt")"
for f in summary.json frames.csv report.html; do [[ -s "$WORK/gb/validate/$f" ]] || fail "validate/$f missing"; done

# No FFmpeg in this build: an MP4 is refused by name, before any work, and writes nothing.
env -i "$B/globe" movie --path "$B/share/globe/assets/paths/still.path" --out "$WORK/m.mp4" >"$WORK/m.out" 2>"$WORK/m.err"
code=$?
if [[ $code -ne 2 || $(wc -l <"$WORK/m.err") -ne 1 ]] || ! grep -q "^globe: error: --out: .*without FFmpeg" "$WORK/m.err" ||
  [[ -e "$WORK/m.mp4" ]]; then
  fail "movie to .mp4 in the bundle: exit $code, $(cat "$WORK/m.err")"
fi
env -i "$B/globe" --help >"$WORK/help.txt" 2>&1
grep -qE '^  view ' "$WORK/help.txt" && fail "the headless bundle lists 'view'"
grep -qE '^  bench ' "$WORK/help.txt" || fail "the bundle lists no 'bench': $(cat "$WORK/help.txt")"

[[ $failures -eq 0 ]] && echo "bundle: $((size / 1048576)) MiB, self-contained, validated bench under env -i"
exit $((failures > 0))
