#!/usr/bin/env bash
# Renders every technique on every bundled scene with two testbed binaries and compares
# the visibility EXRs byte for byte except the header's capDate timestamp (the writer is
# otherwise deterministic, so equal bytes mean equal visibility). Use it to show that a speed-up left a technique's output unchanged:
#   scripts/bit_identical.sh BEFORE_BINARY AFTER_BINARY [WxH] [SHADOW_MAP] [TECHNIQUES] [--set k=v ...]
# Exit 0 when every EXR is identical, 1 otherwise (the differing ones are listed).
set -euo pipefail
before=${1:?before binary}; after=${2:?after binary}
size=${3:-320x180}; map=${4:-256}; techniques=${5:-all}; shift $(( $# < 5 ? $# : 5 ))
root=$(cd "$(dirname "$0")/.." && pwd)
work=$(mktemp -d); trap 'rm -rf "$work"' EXIT
status=0
# The EXR without its capture date (the first "YYYY:MM:DD HH:MM:SS" in the header).
undated() { perl -0777 -pe 's/\d{4}:\d\d:\d\d \d\d:\d\d:\d\d/0000:00:00 00:00:00/' "$1"; }
for scene in "$root"/scenes/*.json; do
  name=$(basename "$scene" .json)
  for side in before after; do
    binary=$before; [[ $side == after ]] && binary=$after
    "$binary" compare --scene "$scene" --techniques "$techniques" --size "$size" --shadow-map "$map" \
      "$@" --out "$work/$side/$name" > "$work/log" 2>&1 ||
      { echo "compare failed: $binary on $name" >&2; tail -3 "$work/log" >&2; exit 2; }
  done
  for exr in "$work/before/$name"/*.exr; do
    file=$(basename "$exr")
    if cmp -s <(undated "$exr") <(undated "$work/after/$name/$file"); then echo "same    $name $file"
    else echo "DIFFERS $name $file"; status=1; fi
  done
done
exit $status
