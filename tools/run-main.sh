#!/usr/bin/env bash
# Sets up, builds and runs the main job (README command 1). Extra arguments go to
# `needle-sim run`.
set -euo pipefail
cd "$(dirname "$0")/.."
tools/setup.sh
exec "${BUILD_DIR:-build}/tools/needle-sim" run "$@"
