# Sourced by tools/ci-sanitize.sh and tools/fuzz.sh: how the sanitizers report. A finding ends the
# program with exit code 86 (not 1, which needle-sim uses for an ordinary error, so a command-line
# test cannot mistake one for the other), with a symbolized stack. A leak in a system library (not
# ours) would be suppressed by its name in tools/sanitizers/lsan.supp; where Vulkan runs there is no
# leak check (tools/ci-sanitize.sh says why).
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
export ASAN_OPTIONS="exitcode=86:abort_on_error=0:detect_leaks=1:strict_string_checks=1:detect_stack_use_after_return=0:check_initialization_order=1"
export UBSAN_OPTIONS="exitcode=86:print_stacktrace=1:halt_on_error=1"
export LSAN_OPTIONS="exitcode=86:suppressions=$here/lsan.supp:print_suppressions=0"
if command -v llvm-symbolizer-14 >/dev/null; then export ASAN_SYMBOLIZER_PATH=$(command -v llvm-symbolizer-14); fi
