#!/usr/bin/env bash
# Checks that every C++ source of the project is as clang-format leaves it (.clang-format: Google
# style, 120 columns). Prints each file that differs; exit 1 if any. To format a file:
# `clang-format -i FILE` (every file: `git ls-files '*.cpp' '*.hpp' | xargs clang-format -i`).
set -euo pipefail
cd "$(dirname "$0")/.."
command -v clang-format >/dev/null || { echo "check-format: clang-format is not installed (tools/setup.sh installs it)" >&2; exit 2; }
mapfile -t files < <(git ls-files '*.cpp' '*.hpp' '*.h')
unformatted=()
for f in "${files[@]}"; do
  clang-format --dry-run --Werror "$f" >/dev/null 2>&1 || unformatted+=("$f")
done
if ((${#unformatted[@]})); then
  printf '%s\n' "${unformatted[@]}"
  echo "check-format: ${#unformatted[@]} of ${#files[@]} file(s) differ from clang-format's output (clang-format -i FILE)"
  exit 1
fi
echo "check-format: all ${#files[@]} C++ files as clang-format leaves them"
