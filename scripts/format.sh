#!/usr/bin/env bash
# SPDX-License-Identifier: Zlib
# clang-format over the project's own C++ files: `format.sh fix` rewrites, `format.sh check` fails on drift.
set -euo pipefail
cd "$(dirname "$0")/.."
mode=${1:-check}
# Tracked and new (untracked, not ignored) files, so that a file is checked before it is added.
mapfile -t files < <(git ls-files --cached --others --exclude-standard '*.h' '*.cpp')
[ ${#files[@]} -gt 0 ] || exit 0
if [ "$mode" = fix ]; then
  clang-format -i "${files[@]}"
else
  clang-format --dry-run --Werror "${files[@]}"
fi
