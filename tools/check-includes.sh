#!/usr/bin/env bash
# Checks that every project include follows the rules of docs/ARCHITECTURE.md ("What may include
# what"): the `include-rules` block there is read as the source of truth, so the layout and its
# description cannot drift apart. For each source file the longest matching folder prefix gives
# what its `#include "a/b.hpp"` lines may name besides its own folder (a prefix, or `dir/*.hpp` for
# the files directly in dir and not in its sub-folders); includes without a folder
# (same-folder headers) and <system> includes are not checked. Prints every violation; exit 1 if any.
set -euo pipefail
cd "$(dirname "$0")/.."

rules_file=docs/ARCHITECTURE.md
declare -A allowed=()
in_block=0
while IFS= read -r line; do
  if [[ $line == '```include-rules' ]]; then in_block=1; continue; fi
  if ((in_block)) && [[ $line == '```' ]]; then break; fi
  ((in_block)) || continue
  folder=${line%%:*}
  folder=${folder// /}
  allowed[$folder]=${line#*:}
done <"$rules_file"
((${#allowed[@]})) || { echo "check-includes: no include-rules block in $rules_file" >&2; exit 2; }

rule_for() {  # the longest folder prefix of $1 that has a rule
  local best=""
  for folder in "${!allowed[@]}"; do
    [[ $1 == "$folder"* && ${#folder} -gt ${#best} ]] && best=$folder
  done
  printf '%s' "$best"
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
  ok+=("$folder")
  while IFS= read -r hit; do
    lineno=${hit%%:*}
    target=${hit#*\"}
    target=${target%%\"*}
    [[ $target == */* ]] || continue
    fine=0
    for prefix in "${ok[@]}"; do
      if [[ $prefix == *'*'* ]]; then  # "dir/*.hpp": files directly in dir, not in its sub-folders
        dir=${prefix%%\**}
        rest=${target#"$dir"}
        [[ $target == "$dir"* && $rest != */* && $target == $prefix ]] && { fine=1; break; }
      elif [[ $target == "$prefix"* || "tools/$target" == "$prefix"* ]]; then
        fine=1
        break
      fi
    done
    if ((!fine)); then
      echo "$file:$lineno: includes \"$target\", which $folder may not (allowed: ${ok[*]})"
      violations=$((violations + 1))
    fi
  done < <(grep -n '^[[:space:]]*#[[:space:]]*include[[:space:]]*"' "$file" || true)
done < <(git ls-files '*.cpp' '*.hpp' '*.h')

if ((violations)); then
  echo "check-includes: $violations include(s) break the rules of $rules_file"
  exit 1
fi
echo "check-includes: every include follows $rules_file"
