#!/usr/bin/env bash
# Sets up, builds and runs the main job (README command 1). Extra arguments go to
# `needle-sim run`.
set -euo pipefail
cd "$(dirname "$0")/.."
tools/setup.sh needle-sim  # the main job's own target: the tests are built by run-tests.sh
exec "${BUILD_DIR:-build}/tools/needle-sim" run "$@"
