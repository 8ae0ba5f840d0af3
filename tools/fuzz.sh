#!/usr/bin/env bash
# Runs the libFuzzer targets of tests/fuzz (scene, task, scenario, urdf, recording, gltf) under
# ASan and UBSan, each for SECONDS (default 600) from its seed corpus (assets/, tests/fuzz/seeds/)
# plus what earlier runs found (BUILD/fuzz/corpus/TARGET/), with its dictionary
# (tests/fuzz/dictionaries/) and its structured mutations (tests/fuzz/structure.hpp), JOBS targets
# at a time (default: the cores). A crash, a hang (10 s an input) or a runaway allocation (over
# 2 GB) is saved to BUILD/fuzz/artifacts/TARGET/ and ends the run with exit 1; make it a
# regression by copying the file into tests/fuzz/regressions/TARGET/ (every build then runs it,
# tests/README.md) and adding a test of the fixed reader.
#
#   tools/fuzz.sh [--build DIR] [--seconds N] [--jobs N] [TARGET...]
#
# DIR (default build-asan) is configured like tools/ci-sanitize.sh does, if it is not yet, and
# the targets are built.
set -euo pipefail
cd "$(dirname "$0")/.."
build_dir=build-asan
seconds=600
jobs=$(nproc)
targets=()
while (($#)); do
  case $1 in
    --build) build_dir=$2; shift 2 ;;
    --seconds) seconds=$2; shift 2 ;;
    --jobs) jobs=$2; shift 2 ;;
    -h|--help) sed -n '2,15p' "$0"; exit 0 ;;
    -*) echo "fuzz.sh: unknown option $1 (see --help)" >&2; exit 2 ;;
    *) targets+=("$1"); shift ;;
  esac
done
((${#targets[@]})) || targets=(scene task scenario urdf recording gltf)

export CCACHE_BASEDIR="$PWD" CCACHE_NOHASHDIR=1
if [[ ! -f $build_dir/CMakeCache.txt ]]; then
  cmake -S . -B "$build_dir" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_COMPILER=clang++ \
        -DNEEDLE_SANITIZE=address,undefined -DNEEDLE_FUZZ=ON >/dev/null
fi
mkdir -p "$build_dir/fuzz"
cmake --build "$build_dir" --parallel "$(nproc)" $(printf -- '--target fuzz_%s ' "${targets[@]}") \
  >"$build_dir/fuzz/build.log" 2>&1 || { tail -n 40 "$build_dir/fuzz/build.log"; exit 1; }
grep -q '^NEEDLE_FUZZ:BOOL=ON' "$build_dir/CMakeCache.txt" ||
  { echo "fuzz.sh: $build_dir is not configured with -DNEEDLE_FUZZ=ON (clang)" >&2; exit 2; }
source tools/sanitizers/environment.sh

# One target: its log in BUILD/fuzz/TARGET.log, exit 1 when it found a fault.
fuzz_one() {
  local t=$1 corpus=$build_dir/fuzz/corpus/$1 artifacts=$build_dir/fuzz/artifacts/$1 log=$build_dir/fuzz/$1.log
  local seeds options
  mkdir -p "$corpus" "$artifacts"
  mapfile -t seeds <"$build_dir/tests/fuzz/fuzz_$t.seeds"
  mapfile -t options <"$build_dir/tests/fuzz/fuzz_$t.options"  # its dictionary (tests/fuzz/CMakeLists.txt)
  "$build_dir/tests/fuzz/fuzz_$t" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 -print_final_stats=1 \
    "${options[@]}" -artifact_prefix="$artifacts/" "$corpus" "${seeds[@]}" >"$log" 2>&1
}

echo "fuzzing ${targets[*]}: ${seconds} s each, $jobs at a time"
declare -A pid_of
for t in "${targets[@]}"; do
  while (($(jobs -rp | wc -l) >= jobs)); do wait -n || true; done
  fuzz_one "$t" &
  pid_of[$t]=$!
done
failed=()
for t in "${targets[@]}"; do
  log=$build_dir/fuzz/$t.log
  if wait "${pid_of[$t]}"; then
    printf 'fuzz_%-10s %s\n' "$t" "$(grep -E '^stat::(number_of_executed_units|new_units_added)' "$log" | tr -s ' \n' ' ')"
  else
    failed+=("$t")
    grep -E 'ERROR|SUMMARY|Test unit written|INFO: Seed' "$log" | head -n 6 || true
    echo "fuzz_$t found a fault: $log, the input in $build_dir/fuzz/artifacts/$t/"
  fi
done
if ((${#failed[@]})); then
  echo "fuzzing found faults in: ${failed[*]}"
  exit 1
fi
