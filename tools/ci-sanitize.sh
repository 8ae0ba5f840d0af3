#!/usr/bin/env bash
# CI's sanitizer and fuzzing job (.ci/run calls it after tools/run-tests.sh): everything built with
# clang under AddressSanitizer and UndefinedBehaviorSanitizer (Ninja, RelWithDebInfo, build-asan/,
# ccache), the code instrumented for libFuzzer too; the test suites run under the sanitizers (a
# finding fails the test that met it), then each fuzz target for FUZZ_SECONDS (default 20) from its
# seed corpus, two at a time. Tests matching SANITIZE_SKIP (a ctest -E pattern; the default is
# below, tests/README.md says why) run only unsanitized, in tools/run-tests.sh. Tests labelled
# vulkan run without the leak check (tests/README.md). Each phase prints its wall time.
set -euo pipefail
cd "$(dirname "$0")/.."
export CCACHE_BASEDIR="$PWD" CCACHE_NOHASHDIR=1
build_dir=${SANITIZE_BUILD_DIR:-build-asan}
fuzz_seconds=${FUZZ_SECONDS:-20}
# The closed-loop simulations and the sessions run end to end: the sanitized tick is 50 to 300
# times slower (Eigen's small matrices, no longer inlined), a session of minutes.
suites='BenchPrecision|BenchStability|PenaltyOnRobot|ControllerLoop|DeviceSim|RealtimeLoop|RealtimeTaskSpace'
suites+='|SimHolonomic|SimNonholonomic|SimFeel|SimHandPassivity|PassivityClosedLoop|TissueInsertion|TissueSnapshot|RealtimeNoAlloc'
suites+='|SessionLimits|SessionReviewTest|SessionStoreFailure|SessionsThatCount|ShippedTasks/ScriptedSessions|LayeredSessions|EpiduralTasks/SyringeSessions|ReviewPanels|ReviewPanelsLayered'
suites+='|CliBench[A-Za-z]*|CliHapticsBench|CliHapticsSimulate|CliRecordings|CliReport|CliReviewWindow|CliReportLayered|CliRunDevices|CliRunTask|CliWrites|Tasks/RunReplay'
suites+='|CliPostgres|CliHostileFiles|CliVerify|CliFirstAttempt'
# Generating a patient samples about ten million nodes of analytic shapes (Eigen's small vectors):
# under a second unsanitized, a minute or more sanitized, for each patient a test makes.
suites+='|PatientGeneration|ShippedPatients/PatientSessions|PatientSessionsRandom|PatientScenes|CliPatient'
tests='BenchTickAllocations\.(NonholonomicContact|LayeredTissue|PatientTissue)TickAllocatesNothing|RecordingReplay\.(ControllerReplayIsBitForBit|ATickTheDeviceHeldAtItsForceLimitIsMarkedInTheRecording)'
tests+='|LayeredDimple\.TheScriptedHandsDimpleIsThePhysicsDeflection|SimComponents\.DeviceEnergyBalancesTheWorkDoneOnIt|CliStartScreen\.(ATraineeStarts|ATraineeDoes|TheKeyboards|TheScorePanels|WithoutADisplayItSaysSoAndRunStill)[A-Za-z]*'
skip=${SANITIZE_SKIP-"^((ShaderBuild|Layout|$suites)\\.|($tests)\$)"}

phase_start=$SECONDS
phase() { echo "$1: $((SECONDS - phase_start)) s"; phase_start=$SECONDS; }

mkdir -p "$build_dir"
cmake -S . -B "$build_dir" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_COMPILER=clang++ \
      -DNEEDLE_SANITIZE=address,undefined -DNEEDLE_FUZZ=ON >/dev/null
cmake --build "$build_dir" --parallel "$(nproc)" >"$build_dir/build.log" 2>&1 || { tail -n 40 "$build_dir/build.log"; exit 1; }
phase "sanitizer build ($build_dir)"

(
  source tools/sanitizers/environment.sh
  run_ctest() { ctest --test-dir "$build_dir" --output-on-failure --parallel "$(nproc)" --timeout 900 ${skip:+-E "$skip"} "$@"; }
  run_ctest -LE vulkan
  # The Vulkan loader unloads lavapipe before the leak check, so its allocations are reported from
  # an unknown module that no suppression can name: no leak check where Vulkan runs.
  LSAN_OPTIONS="$LSAN_OPTIONS:detect_leaks=0" run_ctest -L vulkan
)
phase "tests under ASan and UBSan"

tools/fuzz.sh --build "$build_dir" --seconds "$fuzz_seconds"
phase "fuzzing (${fuzz_seconds} s a target)"
