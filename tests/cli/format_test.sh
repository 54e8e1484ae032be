#!/usr/bin/env bash
# Every C++ file git knows is formatted as .clang-format says (clang-format --dry-run --Werror).
set -euo pipefail
cd "$1"
files=$(git ls-files -co --exclude-standard -- '*.h' '*.cpp')
if ! clang-format --dry-run --Werror $files 2>"$2"; then
  grep -m 20 'warning:' "$2" >&2 || true
  echo "FAIL: run: git ls-files -co --exclude-standard -- '*.h' '*.cpp' | xargs clang-format -i" >&2
  exit 1
fi
echo "format: $(echo "$files" | wc -l) files formatted"
