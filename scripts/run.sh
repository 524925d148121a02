#!/usr/bin/env bash
# The main job: set up (packages, assets, build) if needed, then render every bundled
# scene with every registered technique into out/<scene>/ (PNG, EXR, JSON per technique).
# Extra arguments go to each `testbed render` call (e.g. --shadow-map 512 --backend egl).
set -euo pipefail
repo="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
"$repo/scripts/setup.sh"
testbed="${TESTBED_BUILD_DIR:-$repo/build}/testbed/app/testbed"
out="${TESTBED_OUT:-$repo/out}"
mapfile -t techniques < <("$testbed" list --json | python3 -c 'import json,sys; print("\n".join(t["id"] for t in json.load(sys.stdin)))')
scenes=("$repo"/scenes/*.json)
total=$(( ${#scenes[@]} * ${#techniques[@]} )); n=0
for scene in "${scenes[@]}"; do
  name="$(basename "$scene" .json)"
  for technique in "${techniques[@]}"; do
    n=$((n + 1))
    echo "[$n/$total] $technique on $name" >&2
    "$testbed" render --scene "$scene" --technique "$technique" --out "$out/$name" "$@"
  done
done
echo "results in $out" >&2
