#!/usr/bin/env bash
# Submits a sweep to Slurm: a job array of N shards (sweep.sbatch) and a merge job
# (merge.sbatch) that starts once every shard has succeeded. Prints the two job ids.
#   scripts/slurm/submit.sh SPEC OUT N [testbed sweep options...]
# e.g. scripts/slurm/submit.sh paper/gi2016-table2.json results/paper/gi2016-table2 8 --backend egl
# Submitting the same SPEC, OUT and N again (after a shard failed or was cancelled, which
# cancels the merge) resumes each shard where it stopped: finished cells are kept
# (docs/paper-runs.md "Resuming").
# Logs: OUT/logs/shard-K.log and OUT/logs/merge.log. Extra sbatch options (partition,
# account, GPUs) go in $SBATCH_OPTIONS, e.g. SBATCH_OPTIONS="--partition=gpu --gres=gpu:1".
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
repo="$(cd "$here/../.." && pwd)"
spec="$(realpath "${1:?usage: submit.sh SPEC OUT N [options...]}")"
mkdir -p "${2:?usage: submit.sh SPEC OUT N [options...]}/logs"
out="$(realpath "$2")"
n="${3:?usage: submit.sh SPEC OUT N [options...]}"
shift 3
[[ "$n" =~ ^[1-9][0-9]*$ ]] || { echo "submit.sh: N must be a positive integer, got '$n'" >&2; exit 2; }
export TESTBED_BINARY="${TESTBED_BINARY:-${TESTBED_BUILD_DIR:-$repo/build}/testbed/app/testbed}"
# shellcheck disable=SC2086  # SBATCH_OPTIONS is a list of options
array=$(sbatch --parsable ${SBATCH_OPTIONS:-} --array="1-$n" --output="$out/logs/shard-%a.log" \
  "$here/sweep.sbatch" "$spec" "$out" "$@")
array="${array%%;*}"
# The merge reads the spec again, so it loads the shards' plugins (a plugin's techniques).
plugins=()
options=("$@")
for ((i = 0; i < ${#options[@]}; i++)); do
  case "${options[i]}" in
    --plugin) plugins+=("--plugin=${options[i + 1]:-}"); i=$((i + 1)) ;;
    --plugin=*) plugins+=("${options[i]}") ;;
  esac
done
# shellcheck disable=SC2086
merge=$(sbatch --parsable ${SBATCH_OPTIONS:-} --dependency="afterok:$array" --kill-on-invalid-dep=yes \
  --output="$out/logs/merge.log" "$here/merge.sbatch" "$out" "$n" ${plugins[@]+"${plugins[@]}"})
echo "$array ${merge%%;*}"
