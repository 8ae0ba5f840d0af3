#!/usr/bin/env bash
# The renderer on whatever Vulkan device this machine has (a GPU where there is one, lavapipe
# otherwise; docs/RENDERING.md, "On a GPU"): builds needle-sim and the engine tests, then runs
#   - the engine tests on that device (not pinned to lavapipe, as CTest pins them), every one
#     under the validation layer;
#   - the main job headless (`needle-sim run --headless`), the epidural task with the section cut
#     and the layered target's translucent, with NEEDLE_VALIDATION=1;
#   - `bench render`, `bench frame --targets offscreen`, `bench deform` and `bench ultrasound`, with
#     NEEDLE_VALIDATION=1 and --json;
# and writes OUT (default out/gpu-check): summary.md (the device, each step's result, time and
# validation messages, the failing tests), logs/, bench/*.json, run/ (the main job's pictures)
# and pictures/ (each failing golden's actual and diff images). Exit 0 when every step passed
# with no validation message, 1 otherwise, 2 for a usage error.
#
#   tools/gpu-check.sh [OUT]       QUICK=1 tools/gpu-check.sh: the benches short (20 frames, fewer
#                                  sizes and meshes), to check the script or a device quickly
set -uo pipefail
cd "$(dirname "$0")/.."

if (($# > 1)) || [[ ${1:-} == -* ]]; then
  echo "usage: tools/gpu-check.sh [OUT]  (default out/gpu-check; QUICK=1 for short benches)" >&2
  exit 2
fi
out=${1:-out/gpu-check}
build=${BUILD_DIR:-build}
quick=${QUICK:-}
frames=${quick:+20}
rm -rf "$out"
mkdir -p "$out/logs" "$out/bench" "$out/pictures" "$out/run" || exit 1

tools/setup.sh needle-sim engine_tests >"$out/logs/build.log" 2>&1 || {
  echo "gpu-check: the build failed; $out/logs/build.log says why" >&2
  exit 1
}
sim=$build/tools/needle-sim
goldens=$build/tests/engine/output/golden
# Whatever device the loader offers: no ICD pinned.
unset VK_ICD_FILENAMES VK_DRIVER_FILES

rows=()
failed=0
# step NAME COMMAND...: runs it with a log of its own; a failure or a validation message fails it.
step() {
  local name=$1
  shift
  local log=$out/logs/$name.log start=$SECONDS
  "$@" >"$log" 2>&1
  local rc=$? seconds=$((SECONDS - start))
  local messages
  messages=$(grep -c '^Vulkan validation' "$log")
  local result=passed
  if ((rc != 0 || messages != 0)); then
    result="failed (exit $rc)"
    failed=1
  fi
  rows+=("| $name | $result | $seconds | $messages |")
}

# The device, as the engine picks it.
step device "$sim" render --scene assets/scenes/penetrable_sphere.json --out "$out/pictures/device_check.png"
device=$(grep -m1 '^Vulkan device:' "$out/logs/device.log" || echo "Vulkan device: unknown (see logs/device.log)")

rm -rf "$goldens"
step engine_tests "$build/tests/engine/engine_tests" --gtest_output="json:$out/engine_tests.json"
[[ -d $goldens ]] && cp "$goldens"/*.png "$out/pictures/" 2>/dev/null

export NEEDLE_VALIDATION=1
step run_penetrable_sphere "$sim" run --headless --db "$out/run/sessions.db" --out "$out/run/penetrable_sphere"
step run_epidural_cut "$sim" run --headless --task assets/tasks/epidural.json --section cut --db "$out/run/sessions.db" \
  --out "$out/run/epidural_cut"
step run_layered_translucent "$sim" run --headless --task assets/tasks/layered_target.json --section translucent \
  --db "$out/run/sessions.db" --out "$out/run/layered_translucent"
step bench_render "$sim" bench render ${frames:+--frames "$frames"} ${quick:+--spheres 100,400} \
  --json "$out/bench/render.json"
step bench_frame "$sim" bench frame --targets offscreen ${frames:+--frames "$frames"} ${quick:+--sizes 1280x720} \
  --contents penetrable_sphere,layered_target,epidural,tissue:400 --views translucent \
  --variants 'default;translucency=screen_door' --json "$out/bench/frame.json"
step bench_deform "$sim" bench deform ${frames:+--frames "$frames"} ${quick:+--spheres 100,400} \
  --json "$out/bench/deform.json"
step bench_ultrasound "$sim" bench ultrasound ${frames:+--frames "$frames"} --json "$out/bench/ultrasound.json"

{
  echo "# gpu-check, $(date -u +%Y-%m-%dT%H:%MZ)"
  echo
  echo "$device"
  echo
  echo "| step | result | seconds | validation messages |"
  echo "|---|---|---|---|"
  printf '%s\n' "${rows[@]}"
  echo
  echo "Engine tests: $(grep -m1 -E '^\[  PASSED  \]' "$out/logs/engine_tests.log" || echo 'none passed')"
  if grep -q '^\[  FAILED  \]' "$out/logs/engine_tests.log"; then
    echo
    echo "Failing engine tests (their pictures in pictures/):"
    echo
    grep -E '^\[  FAILED  \] [^ ]+ \(' "$out/logs/engine_tests.log" | sed 's/^\[  FAILED  \] /- /'
  fi
} >"$out/summary.md"
cat "$out/summary.md"
exit "$failed"
