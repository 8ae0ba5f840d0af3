#!/usr/bin/env bash
# Checks that every include follows the rules of docs/ARCHITECTURE.md ("What may include what"):
# its `include-rules` and `system-include-rules` blocks are read as the source of truth, so the
# layout and its description cannot drift apart.
# - `include-rules`: for each source file the longest matching folder prefix gives what its
#   `#include "a/b.hpp"` lines may name besides its own folder (a prefix, or `dir/*.hpp` for the
#   files directly in dir and not in its sub-folders). Its own folder's sub-folders that have a rule
#   of their own are floors of their own: only what the rule lists reaches them. Includes without a
#   folder (same-folder headers) are not checked.
# - `system-include-rules`: each `<name` prefix (`GLFW/`, `vulkan/`, `imgui`) may be included only
#   by the files and folders its rule lists; other `<system>` includes are not checked.
# Prints every violation; exit 1 if any.
set -euo pipefail
cd "$(dirname "$0")/.."

rules_file=docs/ARCHITECTURE.md
declare -A allowed=() system_allowed=()
block=""
while IFS= read -r line; do
  case $line in
    '```include-rules') block=project; continue ;;
    '```system-include-rules') block=system; continue ;;
    '```'*) block=""; continue ;;
  esac
  [[ -n $block ]] || continue
  key=${line%%:*}
  key=${key// /}
  if [[ $block == project ]]; then allowed[$key]=${line#*:}; else system_allowed[$key]=${line#*:}; fi
done <"$rules_file"
((${#allowed[@]})) || { echo "check-includes: no include-rules block in $rules_file" >&2; exit 2; }
((${#system_allowed[@]})) || { echo "check-includes: no system-include-rules block in $rules_file" >&2; exit 2; }

rule_for() {  # the longest folder prefix of $1 that has a rule
  local best=""
  for folder in "${!allowed[@]}"; do
    [[ $1 == "$folder"* && ${#folder} -gt ${#best} ]] && best=$folder
  done
  printf '%s' "$best"
}

# Whether path $1 is named by the rule entry $2: a prefix, or "dir/*.hpp" (files directly in dir).
names() {
  local target=$1 prefix=$2
  if [[ $prefix == *'*'* ]]; then
    local dir=${prefix%%\**}
    local rest=${target#"$dir"}
    [[ $target == "$dir"* && $rest != */* && $target == $prefix ]]
  else
    [[ $target == "$prefix"* || "tools/$target" == "$prefix"* ]]
  fi
}

violations=0
while IFS= read -r file; do
  folder=$(rule_for "$file")
  if [[ -z $folder ]]; then
    echo "$file: no include rule covers this folder ($rules_file)"
    violations=$((violations + 1))
    continue
  fi
  read -r -a ok <<<"${allowed[$folder]}"
  while IFS= read -r hit; do
    lineno=${hit%%:*}
    target=${hit#*\"}
    target=${target%%\"*}
    [[ $target == */* ]] || continue
    fine=0
    for prefix in "${ok[@]}"; do
      if names "$target" "$prefix"; then fine=1; break; fi
    done
    # Its own folder, but not a sub-folder with a rule of its own.
    path=$target
    [[ $path == "$folder"* ]] || path=tools/$target
    if ((!fine)) && [[ $path == "$folder"* && $(rule_for "$path") == "$folder" ]]; then fine=1; fi
    if ((!fine)); then
      echo "$file:$lineno: includes \"$target\", which $folder may not (allowed: ${ok[*]} and $folder itself)"
      violations=$((violations + 1))
    fi
  done < <(grep -n '^[[:space:]]*#[[:space:]]*include[[:space:]]*"' "$file" || true)
  while IFS= read -r hit; do
    lineno=${hit%%:*}
    target=${hit#*<}
    target=${target%%>*}
    for name in "${!system_allowed[@]}"; do
      [[ $target == "$name"* ]] || continue
      read -r -a ok <<<"${system_allowed[$name]}"
      fine=0
      for prefix in "${ok[@]}"; do
        if names "$file" "$prefix"; then fine=1; break; fi
      done
      if ((!fine)); then
        echo "$file:$lineno: includes <$target>, which only ${ok[*]} may"
        violations=$((violations + 1))
      fi
    done
  done < <(grep -n '^[[:space:]]*#[[:space:]]*include[[:space:]]*<' "$file" || true)
done < <(git ls-files --cached --others --exclude-standard '*.cpp' '*.hpp' '*.h')

if ((violations)); then
  echo "check-includes: $violations include(s) break the rules of $rules_file"
  exit 1
fi
echo "check-includes: every include follows $rules_file"
