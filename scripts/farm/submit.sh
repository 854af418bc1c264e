#!/usr/bin/env bash
# Submits a penumbra render split into shards to Slurm: a job array of K shard tasks
# (F x K with FRAMES) (penumbra-shards.sbatch) and a merge job (penumbra-merge.sbatch) that waits for the whole
# array with --dependency=afterok:<array job id>. Prints the two job ids:
#   array_job=<id>
#   merge_job=<id>
# If any shard fails, the merge's dependency can never be met and Slurm cancels the merge
# (--kill-on-invalid-dep=yes) instead of leaving it pending.
#
# Usage: scripts/farm/submit.sh [NAME=VALUE ...]    (or the same names in the environment)
#   SCENE OUT_DIR SHARDS WIDTH HEIGHT SPP SEED FRAMES RENDER_ARGS PENUMBRA THREADS
#               as in penumbra-shards.sbatch (SCENE, OUT_DIR, SHARDS required)
#   IMAGE       the merged image's name in OUT_DIR                 [image.png]
#   MERGE_ARGS  more `penumbra merge` options, e.g. "--bit-depth 16" (penumbra-merge.sbatch)
#   CPUS_PER_TASK  CPUs for each shard task                        [1]
#   ARRAY_LIMIT    at most this many shard tasks at once (--array=0-(K-1)%LIMIT) [no limit]
#   PARTITION   the Slurm partition                                [the cluster's default]
#   SBATCH_ARGS more sbatch options for both jobs (split on blanks), e.g. "--time=00:10:00"
# Paths are made absolute here, so they must be on a filesystem all nodes share.
# The logs go to OUT_DIR/logs/shard-<task>.out and OUT_DIR/logs/merge.out.
set -euo pipefail

HERE=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
die() { echo "submit: $*" >&2; exit 1; }

for arg in "$@"; do
  case "$arg" in
    SCENE=* | OUT_DIR=* | SHARDS=* | WIDTH=* | HEIGHT=* | SPP=* | SEED=* | FRAMES=* | \
      RENDER_ARGS=* | PENUMBRA=* | THREADS=* | IMAGE=* | MERGE_ARGS=* | CPUS_PER_TASK=* | ARRAY_LIMIT=* | \
      PARTITION=* | SBATCH_ARGS=*) export "${arg?}" ;;
    -h | --help) sed -n '2,/^set -euo/p' "${BASH_SOURCE[0]}" | sed '$d; s/^# \{0,1\}//'; exit 0 ;;
    *) die "unknown argument '$arg' (expected NAME=VALUE; --help lists them)" ;;
  esac
done

: "${SCENE:?submit: SCENE is not set}"
: "${OUT_DIR:?submit: OUT_DIR is not set}"
: "${SHARDS:?submit: SHARDS is not set}"
export WIDTH=${WIDTH:-320} HEIGHT=${HEIGHT:-240} SPP=${SPP:-16} SEED=${SEED:-0}
export FRAMES=${FRAMES:-} RENDER_ARGS=${RENDER_ARGS:-} IMAGE=${IMAGE:-image.png} MERGE_ARGS=${MERGE_ARGS:-}
export PENUMBRA=${PENUMBRA:-penumbra}
CPUS_PER_TASK=${CPUS_PER_TASK:-1}
[[ $SHARDS =~ ^[1-9][0-9]*$ ]] || die "SHARDS must be a positive whole number, got '$SHARDS'"
[[ $SPP =~ ^[1-9][0-9]*$ ]] || die "SPP must be a positive whole number, got '$SPP'"
[ "$SHARDS" -le "$SPP" ] || die "SHARDS ($SHARDS) is more than SPP ($SPP): a shard would have no samples"
[ -r "$SCENE" ] || die "cannot read the scene $SCENE"
command -v sbatch >/dev/null || die "sbatch not found: is this a Slurm submit host?"

# Absolute paths: the jobs run in other folders, on other nodes.
SCENE=$(cd "$(dirname "$SCENE")" && pwd)/$(basename "$SCENE")
mkdir -p "$OUT_DIR/logs" "$OUT_DIR/shards"
OUT_DIR=$(cd "$OUT_DIR" && pwd)
case "$PENUMBRA" in
  */*) PENUMBRA=$(cd "$(dirname "$PENUMBRA")" && pwd)/$(basename "$PENUMBRA") ;;
esac
export SCENE OUT_DIR SHARDS PENUMBRA

common=(--parsable --chdir="$OUT_DIR" --export=ALL)
[ -z "${PARTITION:-}" ] || common+=(--partition="$PARTITION")
# SBATCH_ARGS is a list of options, split on blanks on purpose.
# shellcheck disable=SC2206
[ -z "${SBATCH_ARGS:-}" ] || common+=($SBATCH_ARGS)

# One task per shard, or with FRAMES=A..B one per (frame, shard): F * K tasks.
TASKS=$SHARDS
if [ -n "$FRAMES" ]; then
  [[ $FRAMES =~ ^([0-9]+)\.\.([0-9]+)$ ]] || die "FRAMES must be A..B, got '$FRAMES'"
  [ "${BASH_REMATCH[2]}" -ge "${BASH_REMATCH[1]}" ] || die "FRAMES $FRAMES is empty"
  TASKS=$(((BASH_REMATCH[2] - BASH_REMATCH[1] + 1) * SHARDS))
fi
array="0-$((TASKS - 1))"
[ -z "${ARRAY_LIMIT:-}" ] || array="$array%$ARRAY_LIMIT"

array_job=$(sbatch "${common[@]}" --array="$array" --cpus-per-task="$CPUS_PER_TASK" \
  --job-name=penumbra-shards --output="$OUT_DIR/logs/shard-%a.out" \
  "$HERE/penumbra-shards.sbatch") || die "sbatch of the shard array failed"
array_job=${array_job%%;*} # --parsable prints id[;cluster]
[[ $array_job =~ ^[0-9]+$ ]] || die "unexpected job id from sbatch: '$array_job'"

merge_job=$(sbatch "${common[@]}" --dependency="afterok:$array_job" --kill-on-invalid-dep=yes \
  --job-name=penumbra-merge --output="$OUT_DIR/logs/merge.out" \
  "$HERE/penumbra-merge.sbatch") || {
  scancel "$array_job" 2>/dev/null || true
  die "sbatch of the merge job failed (shard array $array_job cancelled)"
}
merge_job=${merge_job%%;*}

echo "array_job=$array_job"
echo "merge_job=$merge_job"
