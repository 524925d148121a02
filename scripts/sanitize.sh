#!/usr/bin/env bash
# The GoogleTest suite built with AddressSanitizer + UBSan (-DTESTBED_SANITIZE=ON) in a build
# folder of its own, then run through CTest (docs/input-limits.md "Sanitizers"). Not part of
# scripts/test.sh: a sanitized build and run take several times as long as the plain one.
#
#   scripts/sanitize.sh                  # build build-sanitize/, run every GoogleTest test
#   scripts/sanitize.sh -R 'Scene|Mesh'  # extra arguments go to ctest
#
# Environment: TESTBED_SANITIZE_BUILD_DIR (default build-sanitize), JOBS (default nproc).
# Needs what scripts/setup.sh installs and the assets it extracts; installs nothing.
set -euo pipefail
repo="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build_dir="${TESTBED_SANITIZE_BUILD_DIR:-$repo/build-sanitize}"
jobs="${JOBS:-$(nproc)}"

launcher=()
command -v ccache >/dev/null && launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache -DCMAKE_C_COMPILER_LAUNCHER=ccache)
# -O1: the optimisation the sanitizers' authors recommend (usable stack traces, tolerable
# speed); asserts stay on. Batched (unity) sources: every file is compiled fresh here, since
# the plain build's objects carry no sanitizer, and batching parses the heavy headers once a
# batch (docs/performance.md "Build time").
cmake -S "$repo" -B "$build_dir" -G Ninja -DTESTBED_SANITIZE=ON -DTESTBED_UNITY_BUILD=ON \
  -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g1" \
  -DCMAKE_C_FLAGS_RELWITHDEBINFO="-O1 -g1" \
  -DTESTBED_WITH_BENCHMARKS=OFF -DTESTBED_WITH_FUZZERS=OFF "${launcher[@]}" >/dev/null
# testbed_tests pulls in what it runs: the testbed binary and the plugin fixtures.
cmake --build "$build_dir" --target testbed_tests -- -j"$jobs"

# Leaks that are not ours, reported by LeakSanitizer at exit (docs/input-limits.md "Sanitizers" says why):
suppressions="$build_dir/lsan.supp"
cat >"$suppressions" <<'SUPP'
# Mesa's llvmpipe (OSMesa, EGL) and the LLVM it JIT-compiles shaders with keep
# process-lifetime allocations (screen, shader cache, LLVM's target registry) that they
# free only when the library is unloaded, which never happens before exit.
leak:libOSMesa.so
leak:libgallium
leak:libLLVM
leak:libEGL_mesa.so
leak:libglapi.so
leak:swrast_dri.so
SUPP

export ASAN_OPTIONS="detect_leaks=1:abort_on_error=0:strict_string_checks=1:detect_stack_use_after_return=1:check_initialization_order=1${ASAN_OPTIONS:+:$ASAN_OPTIONS}"
export LSAN_OPTIONS="suppressions=$suppressions:print_suppressions=0${LSAN_OPTIONS:+:$LSAN_OPTIONS}"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1${UBSAN_OPTIONS:+:$UBSAN_OPTIONS}"
# Only the GoogleTest tests (named Suite.Test, or Prefix/Suite.Test/Case followed by
# "  # GetParam() = ..."): the Python and browser tests run no sanitized code.
ctest --test-dir "$build_dir" --output-on-failure -j"$jobs" \
  -R '^[A-Za-z0-9_/]+\.[A-Za-z0-9_/]+( |$)' -E '^Docs\.|^Plugin\.ShaderMissing' "$@"
