#!/usr/bin/env bash
# Regenerates the benchmark gate's baselines (tests/benchmark_gate_test.cpp): `compare` on
# every bundled scene with the settings in tests/baselines/settings, keeping each run's
# metrics.json as tests/baselines/<scene>/metrics.json. Run it after an intended change of
# output (and commit the baselines with that change):
#   scripts/baselines.sh [TESTBED_BINARY]   (default: build/testbed/app/testbed)
set -euo pipefail
repo="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
binary="${1:-${TESTBED_BUILD_DIR:-$repo/build}/testbed/app/testbed}"
read -r -a settings < "$repo/tests/baselines/settings"
work=$(mktemp -d); trap 'rm -rf "$work"' EXIT
for scene in "$repo"/scenes/*.json; do
  name=$(basename "$scene" .json)
  "$binary" compare --scene "$scene" "${settings[@]}" --out "$work/$name" > /dev/null
  mkdir -p "$repo/tests/baselines/$name"
  cp "$work/$name/metrics.json" "$repo/tests/baselines/$name/metrics.json"
  echo "baseline: tests/baselines/$name/metrics.json"
done
