#!/usr/bin/env bash
# Sets up, builds and runs every test (README command 2; .ci/run calls exactly this).
set -euo pipefail
cd "$(dirname "$0")/.."
tools/setup.sh
ctest --test-dir "${BUILD_DIR:-build}" --output-on-failure --parallel "$(nproc)" --timeout 900
