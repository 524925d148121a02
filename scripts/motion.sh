#!/usr/bin/env bash
# Regenerates results/motion/<scene>/ (docs/motion.md): `testbed compare --frames all` of
# every registered technique on each bundled animated scene (scenes/motion/*.json) at
# 640x360 with a 1024² shadow map, keeping report.md, sequence.json, index.html, and per technique the
# video, the error-over-time plot and the sequence record. Extra arguments go to compare.
set -euo pipefail
repo="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
testbed="${TESTBED_BUILD_DIR:-$repo/build}/testbed/app/testbed"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
for scene in "$repo"/scenes/motion/*.json; do
  name="$(basename "$scene" .json)"
  echo "== $name" >&2
  "$testbed" compare --scene "$scene" --frames all --size 640x360 --shadow-map 1024 --out "$work/$name" "$@"
  keep="$repo/results/motion/$name"
  rm -rf "$keep"
  mkdir -p "$keep"
  cp "$work/$name/"{report.md,sequence.json,index.html} "$work/$name/"*.mp4 "$work/$name/"*_error_over_time.png \
     "$work/$name/"*_sequence.json "$keep/"
done
