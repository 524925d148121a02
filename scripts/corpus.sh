#!/usr/bin/env bash
# A generated corpus measured end to end in one command (docs/corpus.md): `testbed corpus`
# samples the scenes from a seed, one `testbed sweep` (spec: scripts/corpus_sweep.json,
# scenes axis = the corpus folder) runs every technique on every scene at 640x360 for each
# shadow-map size, then scripts/corpus_stats.py (statistics across scenes at one map size),
# scripts/corpus_cost.py (equal-cost view over the sizes) and scripts/corpus_page.py (adds
# both to the sweep's index.html).
# Writes, replacing it whole at the end:
#   OUT/scenes/    the scene files and manifest.json (what was sampled)
#   OUT/           the sweep's files: index.html, records.json, corpus.md/.json, spec.json,
#                  sweep.json, the close-up figure; command.txt (command, time, commit)
#   OUT/stats/     stats.md, stats.json, one box plot per metric (map size --stats-map)
#   OUT/stats-all-maps/  the same over every technique @ map size, against sm at the largest
#   OUT/cost/      cost.md, cost.json, cost-<cost>.png, scenes/<scene>.png
# An interrupted run leaves OUT.partial/; the same command again resumes it (the sweep
# skips the cells whose records exist, docs/paper-runs.md "Resuming").
#   OUT/cost-<metric>/   the same for each soft metric (against the area-light reference)
# --reference (the sweep spec's settings.reference, docs/paper-runs.md "Reference"): both
# (the default: every technique judged against the hard ground truth and the area-light
# reference, so that sm is a baseline for the soft metrics too), hard, soft or by_output;
# --area-samples and --light-radius: the area-light reference's samples (default 64) and
# a light radius replacing every scene's (default: each scene's own).
# Usage: scripts/corpus.sh [--kind standard|outdoor] [--seed S] [--count N] [--out DIR] [--techniques all|LIST]
#                          [--shadow-maps 512,1024,2048] [--stats-map 1024]
#                          [--reference both|hard|soft|by_output] [--area-samples 64] [--light-radius R]
#                          [-- extra sweep options, e.g. --repeat 3]
set -euo pipefail
repo="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
testbed="${TESTBED:-${TESTBED_BUILD_DIR:-$repo/build}/testbed/app/testbed}"  # $TESTBED: the binary itself
python=/usr/bin/python3
[ -x "$python" ] || python=python3
seed=2026 count=40 out="$repo/results/corpus" techniques=all maps=512,1024,2048 stats_map=1024 kind=standard
reference=both area_samples="" light_radius=""
extra=()
while [ $# -gt 0 ]; do
  case "$1" in
    --seed) seed="$2"; shift 2 ;;
    --count) count="$2"; shift 2 ;;
    --kind) kind="$2"; shift 2 ;;
    --out) out="$2"; shift 2 ;;
    --techniques) techniques="$2"; shift 2 ;;
    --shadow-maps) maps="$2"; shift 2 ;;
    --stats-map) stats_map="$2"; shift 2 ;;
    --reference) reference="$2"; shift 2 ;;
    --area-samples) area_samples="$2"; shift 2 ;;
    --light-radius) light_radius="$2"; shift 2 ;;
    --) shift; extra=("$@"); break ;;
    *) echo "corpus.sh: unknown option '$1' (see the header of $0)" >&2; exit 2 ;;
  esac
done
[ -x "$testbed" ] || { echo "corpus.sh: $testbed not built (run scripts/setup.sh)" >&2; exit 2; }
testbed="$(cd "$(dirname "$testbed")" && pwd)/$(basename "$testbed")"  # the sweep runs in the work folder
export TESTBED="$testbed"  # scripts/metric_table.py asks this binary for the metric table
case ",$maps," in *",$stats_map,"*) ;; *) echo "corpus.sh: --stats-map $stats_map is not one of --shadow-maps $maps" >&2; exit 2 ;; esac
# The reference's options are checked here, before the corpus is generated (the sweep
# would check them too, but only after that).
case "$reference" in hard|soft|both|by_output) ;; *) echo "corpus.sh: --reference: expected hard, soft, both or by_output, got '$reference'" >&2; exit 2 ;; esac
if [ -n "$area_samples$light_radius" ] && [ "$reference" = hard ]; then
  echo "corpus.sh: --area-samples/--light-radius: --reference hard renders no area-light reference" >&2; exit 2
fi
if [ -n "$area_samples" ] && ! { [[ "$area_samples" =~ ^[0-9]{1,4}$ ]] && [ "$area_samples" -ge 1 ] && [ "$area_samples" -le 4096 ]; }; then
  echo "corpus.sh: --area-samples: expected an integer in 1..4096, got '$area_samples'" >&2; exit 2
fi
if [ -n "$light_radius" ] && ! "$python" -c 'import math,sys; v=float(sys.argv[1]); sys.exit(0 if math.isfinite(v) and 0 < v <= 1e6 else 1)' "$light_radius" 2>/dev/null; then
  echo "corpus.sh: --light-radius: expected a number in (0, 1e6], got '$light_radius'" >&2; exit 2
fi
[ "$techniques" = all ] && techniques="$("$testbed" list --json | "$python" -c 'import json,sys; print(",".join(t["id"] for t in json.load(sys.stdin)))')"

# The work folder is kept when the run fails, so the same command resumes it; other
# arguments start it afresh.
out="$(mkdir -p "$(dirname "$out")" && cd "$(dirname "$out")" && pwd)/$(basename "$out")"
work="$out.partial"
arguments="$seed $count $techniques $maps $stats_map $reference $area_samples $light_radius ${extra[*]}"
if [ -e "$work" ] && [ "$(cat "$work/arguments" 2>/dev/null)" != "$arguments" ]; then rm -rf "$work"; fi
mkdir -p "$work"
echo "$arguments" > "$work/arguments"
if [ ! -f "$work/scenes/manifest.json" ]; then
  "$testbed" corpus --kind "$kind" --seed "$seed" --count "$count" --out "$work/scenes" || { status=$?; rm -rf "$work"; exit $status; }
fi
"$python" - "$repo/scripts/corpus_sweep.json" "$work/corpus.json" "$techniques" "$maps" "$reference" \
  "$area_samples" "$light_radius" <<'PY'
import json, sys
template, target, techniques, maps, reference, samples, radius = sys.argv[1:]
spec = json.load(open(template))
spec["techniques"] = techniques.split(",")
spec["axes"]["shadow_map"] = [int(m) for m in maps.split(",")]
spec["settings"]["reference"] = reference
if samples:
    spec["settings"]["area_samples"] = int(samples)
if radius:
    spec["settings"]["light_radius"] = float(radius)
json.dump(spec, open(target, "w"), indent=1)
PY

start=$(date +%s)
# Relative paths: the sweep's command line and tables name no machine's folder.
(cd "$work" && "$testbed" sweep --spec corpus.json --no-plot --out sweep "${extra[@]}")
seconds=$(( $(date +%s) - start ))
"$python" "$repo/scripts/corpus_stats.py" "$work/sweep/records.json" --out "$work/sweep/stats" \
  --shadow-map "$stats_map" --baseline sm
# Every configuration (technique @ map size) against sm at the largest map: is smsr at 1024²
# better than sm at 2048²?
largest="$(tr ',' '\n' <<< "$maps" | sort -n | tail -1)"
if [ "$maps" != "$stats_map" ]; then
  "$python" "$repo/scripts/corpus_stats.py" "$work/sweep/records.json" --out "$work/sweep/stats-all-maps" \
    --baseline "sm @$largest"
fi
"$python" "$repo/scripts/corpus_cost.py" "$work/sweep/records.json" --out "$work/sweep/cost"
# The equal-cost view of each soft metric the records hold (ids from `testbed metrics --json`).
for metric in $("$python" "$repo/scripts/corpus_cost.py" "$work/sweep/records.json" --list-soft); do
  "$python" "$repo/scripts/corpus_cost.py" "$work/sweep/records.json" --error "$metric" --out "$work/sweep/cost-$metric"
done
mv "$work/scenes" "$work/sweep/scenes"
# spec.json lists each scene's absolute path (the shards' identity); the committed folder
# names them relative to itself.
"$python" - "$work/sweep/spec.json" "$work/sweep" <<'PY'
import json, os, sys
path, folder = sys.argv[1:]
spec = json.load(open(path))
scenes = spec.get("scenes")
if isinstance(scenes, dict):
    spec["scenes"] = {k: "scenes/" + os.path.basename(v) for k, v in scenes.items()}
json.dump(spec, open(path, "w"), indent=1, sort_keys=True)
open(path, "a").write("\n")
PY
# The command as bash reads it back (each word quoted with %q): pasted at the repository's
# root, it runs this again; an --out inside the repository is named relative to it, so the
# committed file names no machine's folder.
recorded_out="$out"
case "$out" in "$repo"/*) recorded_out="${out#"$repo"/}" ;; esac
printf -v recorded ' %q' --kind "$kind" --seed "$seed" --count "$count" --techniques "$techniques" --shadow-maps "$maps" \
  --stats-map "$stats_map" --reference "$reference" --out "$recorded_out"
[ -z "$area_samples" ] || recorded+=" --area-samples $area_samples"
[ -z "$light_radius" ] || { printf -v more ' %q' --light-radius "$light_radius"; recorded+="$more"; }
if [ ${#extra[@]} -gt 0 ]; then printf -v more ' %q' -- "${extra[@]}"; recorded+="$more"; fi
{
  echo "scripts/corpus.sh$recorded"
  echo "sweep: 640x360, shadow maps $maps, $count scenes in ${seconds} s on $(nproc) cores, $(date -u +%Y-%m-%d)"
  echo "reference: $reference (area-light reference: ${area_samples:-64} samples, light radius ${light_radius:-of each scene})"
  echo "testbed: $(git -C "$repo" rev-parse --short HEAD 2>/dev/null || echo unknown)"
} > "$work/sweep/command.txt"
"$python" "$repo/scripts/corpus_page.py" "$work/sweep"

# Replace OUT whole: the new tree in place, then the old one and the work folder removed.
if [ -e "$out" ]; then mv "$out" "$work/old"; fi
mv "$work/sweep" "$out"
rm -rf "$work"
echo "corpus.sh: wrote $out (index.html; stats/stats.md and cost/cost.md: the tables)" >&2
