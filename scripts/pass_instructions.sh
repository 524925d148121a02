#!/usr/bin/env bash
# Counts the CPU instructions each timed pass of one technique frame costs on llvmpipe, with
# callgrind: a measure of a pass's work that, unlike wall time on a shared 2-core machine,
# repeats to the instruction. Use it to see what a speed-up bought, pass by pass:
#   scripts/pass_instructions.sh BINARY SCENE TECHNIQUE [--set k=v ...]
#   (SIZE=640x360 MAP=512 by default; KEEP=1 keeps the callgrind files and prints where)
# `render` runs a warm-up frame and the timed frame; each PassTimer scope (glFinish before and
# after, so a scope holds exactly its pass's work) becomes one callgrind dump, and the timed
# frame's dumps are printed in frame order, with the pass names `render` recorded (a name may
# cover two scopes, a clear and a draw). Shaders compile in the
# warm-up frame; Mesa's shader cache is kept private so every run compiles the same way.
# Takes about a minute at the default size. valgrind is a developer tool, not in setup.sh:
# `sudo apt-get install valgrind`.
set -euo pipefail
binary=${1:?testbed binary}; scene=${2:?scene JSON}; technique=${3:?technique id}; shift 3
size=${SIZE:-640x360}; map=${MAP:-512}
command -v valgrind > /dev/null || { echo "pass_instructions: valgrind is not installed" >&2; exit 2; }
work=$(mktemp -d)
[[ ${KEEP:-0} == 1 ]] || trap 'rm -rf "$work"' EXIT
LP_NUM_THREADS=0 MESA_SHADER_CACHE_DIR="$work/shader-cache" \
  valgrind --tool=callgrind --callgrind-out-file="$work/callgrind.out.%p" \
  --dump-before='testbed::PassTimer::Scope::Scope*' --dump-after='testbed::PassTimer::Scope::~Scope*' \
  "$binary" render --scene "$scene" --technique "$technique" --size "$size" --shadow-map "$map" "$@" \
  --out "$work/out" > "$work/log" 2>&1 || { tail -5 "$work/log" >&2; exit 2; }
# Each dump file names its trigger; the dump-after ones hold one scope each, in order.
mapfile -t counts < <(for file in $(ls "$work"/callgrind.out.*.* | awk -F. '{ print $NF, $0 }' | sort -n | cut -d' ' -f2); do
  grep -q '^desc: Trigger: --dump-after' "$file" || continue
  awk '/^(summary|totals):/ { print $2; exit }' "$file"
done)
mapfile -t names < <(python3 -c '
import json, sys
record = json.load(open(sys.argv[1]))
print("\n".join(record["gpu_ms"]["passes"]))' "$work/out/$technique.json")
# The warm-up frame may open a scope more than the timed one (a first-frame pass), never fewer.
half=$(( (${#counts[@]} + 1) / 2 ))
total=0
echo "$technique on $(basename "$scene" .json), $size, map $map: instructions per pass (M)"
for (( i = half; i < ${#counts[@]}; i++ )); do
  total=$(( total + counts[i] ))
  awk -v name="scope $(( i - half + 1 ))" -v n="${counts[i]}" 'BEGIN { printf "  %-24s %8.1f\n", name, n / 1e6 }'
done
awk -v n="$total" 'BEGIN { printf "  %-24s %8.1f\n", "total", n / 1e6 }'
echo "  passes this frame recorded (alphabetical; the scopes above are in frame order): ${names[*]:-?}"
[[ ${KEEP:-0} == 1 ]] && echo "  callgrind files kept in $work"
exit 0
