#!/usr/bin/env bash
# The test suite: set up (packages, assets, builds) if needed, then run every test with
# CTest, the fuzz harnesses' smoke run included. Extra arguments go to ctest (e.g. -R Scene).
set -euo pipefail
repo="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
"$repo/scripts/setup.sh"
build_dir="${TESTBED_BUILD_DIR:-$repo/build}"
fuzz_dir="${TESTBED_FUZZ_BUILD_DIR:-$repo/build-fuzz}"
ctest --test-dir "$build_dir" --output-on-failure -j"$(nproc)" "$@"
# The fuzz harnesses' smoke run on their kept corpora (docs/input-limits.md "Fuzzing").
ctest --test-dir "$fuzz_dir" --output-on-failure -j"$(nproc)" "$@"
