#!/usr/bin/env bash
# Installs every Debian package that the build, the tests, the main job and CI's sanitizer and
# fuzzing job (clang, its ASan/UBSan/libFuzzer runtimes, llvm-symbolizer) need, then
# configures and builds: the targets given as arguments (the main job builds needle-sim alone),
# everything when none are. Non-interactive and idempotent: when everything is installed it
# touches no package list and only runs the (incremental, ccache-backed) build.
set -euo pipefail
cd "$(dirname "$0")/.."

packages=(
  cmake ninja-build g++ pkg-config ccache
  libvulkan-dev mesa-vulkan-drivers vulkan-validationlayers glslang-tools
  libglfw3-dev libx11-dev libxext-dev libxrandr-dev libglm-dev libeigen3-dev libtinygltf-dev libimgui-dev libstb-dev
  libusb-1.0-0-dev libgtest-dev nlohmann-json3-dev liburdfdom-dev libsqlite3-dev sqlite3 libcli11-dev
  libmeshoptimizer-dev
  postgresql libpq-dev
  xvfb xauth xdotool
  clang libclang-rt-14-dev llvm-14 clang-format
)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if ((${#missing[@]})); then
  echo "setup: installing ${missing[*]}"
  sudo_cmd=()
  [ "$(id -u)" -eq 0 ] || sudo_cmd=(sudo)
  "${sudo_cmd[@]}" apt-get update -qq
  DEBIAN_FRONTEND=noninteractive "${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi

# ccache keys on paths relative to the checkout, so a fresh clone (CI) reuses earlier builds.
export CCACHE_BASEDIR="$PWD" CCACHE_NOHASHDIR=1
# Room for both builds CI makes (build/ and the sanitizers' build-asan/, about 2 GB each), so
# neither evicts the other (ccache's default is 5 GB).
ccache --max-size=12G >/dev/null
build_dir=${BUILD_DIR:-build}
cmake -S . -B "$build_dir" -G Ninja -DCMAKE_BUILD_TYPE="${BUILD_TYPE:-RelWithDebInfo}" >/dev/null
targets=()
for t in "$@"; do targets+=(--target "$t"); done
cmake --build "$build_dir" --parallel "$(nproc)" "${targets[@]}"
