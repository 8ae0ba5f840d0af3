#!/usr/bin/env bash
# The shader rule under GENERATOR ("Ninja" or "Unix Makefiles"), from clean folders:
#  - a good shader builds and its header is there;
#  - a broken shader fails the build with glslang's own message, and leaves no header;
#  - an output glslang cannot write (glslang then exits 0) fails the build too.
set -euo pipefail
source_dir=$1 generator=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

build() {  # build SHADER_FILE -> builds in $work/b, output in $work/log
  rm -rf "$work/b"
  cmake -S "$source_dir/tests/build/shader_project" -B "$work/b" -G "$generator" \
    -DNEEDLE_SOURCE_DIR="$source_dir" -DSHADER="$1" >"$work/log" 2>&1
  cmake --build "$work/b" --target check_shaders_spirv -j2 >>"$work/log" 2>&1
}
fail() { echo "FAIL ($generator): $1"; cat "$work/log"; exit 1; }

printf '#version 450\nlayout(local_size_x = 1) in;\nvoid main() {}\n' >"$work/good.comp"
build "$work/good.comp" || fail "a good shader did not build"
[ -s "$work/b/spirv/good_comp.h" ] || fail "a good shader built but its header is missing"
grep -q good_comp_spv "$work/b/spirv/good_comp.h" || fail "the header does not hold good_comp_spv"

printf '#version 450\nlayout(local_size_x = 1) in;\nvoid main() { undeclared_thing = 1; }\n' >"$work/broken.comp"
if build "$work/broken.comp"; then fail "a broken shader built"; fi
grep -q "undeclared_thing" "$work/log" || fail "the build failed without glslang's message"
[ ! -e "$work/b/spirv/broken_comp.h" ] || fail "a broken shader left a header"

# glslang exits 0 when it cannot open its output: the rule must notice that nothing was written.
rm -rf "$work/b"
cmake -S "$source_dir/tests/build/shader_project" -B "$work/b" -G "$generator" \
  -DNEEDLE_SOURCE_DIR="$source_dir" -DSHADER="$work/good.comp" >"$work/log" 2>&1
mkdir -p "$work/b/spirv/good_comp.h.tmp/in_the_way"
if cmake --build "$work/b" --target check_shaders_spirv >>"$work/log" 2>&1; then
  fail "an output glslang could not write passed the build"
fi
grep -q "wrote no output" "$work/log" || fail "the build failed without saying the output was not written"
echo "ok ($generator)"
