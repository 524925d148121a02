#!/usr/bin/env bash
# The main job: set up (packages, assets, build) if needed, then compare every registered
# technique with the ground truth on every bundled scene (OSMesa by default) into
# out/<scene>/: report.md, grid.png, speed_vs_error.svg, metrics.json and each technique's
# PNG/EXR/JSON. Extra arguments go to each `testbed compare` call
# (e.g. --shadow-map 512 --techniques sm,pcf --backend egl).
set -euo pipefail
repo="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
"$repo/scripts/setup.sh"
testbed="${TESTBED_BUILD_DIR:-$repo/build}/testbed/app/testbed"
out="${TESTBED_OUT:-$repo/out}"
scenes=("$repo"/scenes/*.json)
n=0
for scene in "${scenes[@]}"; do
  n=$((n + 1))
  name="$(basename "$scene" .json)"
  echo "== scene $n/${#scenes[@]}: $name" >&2
  "$testbed" compare --scene "$scene" --out "$out/$name" "$@"
done
echo "reports: $out/*/report.md" >&2
