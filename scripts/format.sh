#!/usr/bin/env bash
# Apply deal.II's .clang-format (clang-format 16) to every C++ file of LtN,
# or, with --check, only report files that are not formatted.
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
cd "$here"
# Tracked and new (untracked, not ignored) files alike.
mapfile -t files < <(git ls-files --cached --others --exclude-standard '*.h' '*.cc')
if [ "${1:-}" = "--check" ]; then
  clang-format-16 --dry-run --Werror "${files[@]}"
  echo "formatting OK (${#files[@]} files)"
else
  clang-format-16 -i "${files[@]}"
fi
