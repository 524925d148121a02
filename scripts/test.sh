#!/usr/bin/env bash
# The test suite: set up (packages, assets, build) if needed, then run every test with
# CTest. Extra arguments go to ctest (e.g. -R Scene).
set -euo pipefail
repo="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
"$repo/scripts/setup.sh"
build_dir="${TESTBED_BUILD_DIR:-$repo/build}"
ctest --test-dir "$build_dir" --output-on-failure -j"$(nproc)" "$@"
