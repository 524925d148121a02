#!/usr/bin/env bash
# A generated corpus measured end to end (docs/corpus.md): `testbed corpus` samples the
# scenes from a seed, `testbed compare` runs every technique on each at 640x360 with a
# 1024² shadow map, and scripts/corpus_stats.py writes the statistics across scenes.
# Writes, replacing it whole at the end:
#   OUT/scenes/   the scene files and manifest.json (what was sampled)
#   OUT/runs/S/   per scene: metrics.json and report.md of compare
#   OUT/          stats.md, stats.json, one box plot per metric, command.txt
# Usage: scripts/corpus.sh [--seed S] [--count N] [--out DIR] [--techniques LIST]
#                          [--area-samples N]   (extra compare options after --)
set -euo pipefail
repo="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
testbed="${TESTBED_BUILD_DIR:-$repo/build}/testbed/app/testbed"
python=/usr/bin/python3
[ -x "$python" ] || python=python3
seed=2026 count=40 out="$repo/results/corpus" techniques=all area_samples=0
extra=()
while [ $# -gt 0 ]; do
  case "$1" in
    --seed) seed="$2"; shift 2 ;;
    --count) count="$2"; shift 2 ;;
    --out) out="$2"; shift 2 ;;
    --techniques) techniques="$2"; shift 2 ;;
    --area-samples) area_samples="$2"; shift 2 ;;
    --) shift; extra=("$@"); break ;;
    *) echo "corpus.sh: unknown option '$1' (see the header of $0)" >&2; exit 2 ;;
  esac
done
[ -x "$testbed" ] || { echo "corpus.sh: $testbed not built (run scripts/setup.sh)" >&2; exit 2; }

work="$(mktemp -d "${TMPDIR:-/tmp}/corpus.XXXXXX")"
trap 'rm -rf "$work"' EXIT
"$testbed" corpus --seed "$seed" --count "$count" --out "$work/new/scenes"
start=$(date +%s)
for scene in "$work"/new/scenes/*.json; do
  name="$(basename "$scene" .json)"
  [ "$name" = manifest ] && continue
  echo "== $name" >&2
  "$testbed" compare --scene "$scene" --size 640x360 --shadow-map 1024 --techniques "$techniques" \
    --area-samples "$area_samples" --out "$work/full/$name" "${extra[@]}"
  mkdir -p "$work/new/runs/$name"
  cp "$work/full/$name/"{metrics.json,report.md} "$work/new/runs/$name/"
  rm -rf "$work/full/$name"
done
seconds=$(( $(date +%s) - start ))
"$python" "$repo/scripts/corpus_stats.py" "$work/new/runs" --out "$work/new"
{
  echo "scripts/corpus.sh --seed $seed --count $count --techniques $techniques --area-samples $area_samples ${extra[*]}"
  echo "compare: 640x360, shadow map 1024, $count scenes in ${seconds} s on $(nproc) cores, $(date -u +%Y-%m-%d)"
  echo "testbed: $(git -C "$repo" rev-parse --short HEAD 2>/dev/null || echo unknown)"
} > "$work/new/command.txt"

# Replace OUT whole: the new tree in place, then the old one removed.
mkdir -p "$(dirname "$out")"
if [ -e "$out" ]; then mv "$out" "$work/old"; fi
mv "$work/new" "$out"
echo "corpus.sh: wrote $out (stats.md: the tables)" >&2
