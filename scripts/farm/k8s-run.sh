#!/usr/bin/env bash
# Runs scripts/farm/penumbra-shards.k8s.yaml in the current kubectl context, in order:
# the claim and settings, the Indexed Job of shards, then (only once every shard completed)
# the merge Job. Kubernetes has no afterok dependency, so this script is the sequencing:
# `kubectl wait --for=condition=complete` on the shard Job, stopping early if it fails.
#
# Usage: scripts/farm/k8s-run.sh [MANIFEST]     (default: penumbra-shards.k8s.yaml beside it)
#   NAMESPACE       kubectl namespace                      [the context's]
#   SHARDS_TIMEOUT  how long to wait for the shards         [1h]
#   MERGE_TIMEOUT   how long to wait for the merge          [10m]
#   RESTART=1       delete the two Jobs of an earlier run first (Jobs are immutable)
# Exit status: 0 when the merge Job completed; 1 otherwise (a failed or timed-out Job).
set -euo pipefail

HERE=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
MANIFEST=${1:-$HERE/penumbra-shards.k8s.yaml}
SHARDS_TIMEOUT=${SHARDS_TIMEOUT:-1h}
MERGE_TIMEOUT=${MERGE_TIMEOUT:-10m}
kc=(kubectl)
[ -z "${NAMESPACE:-}" ] || kc+=(--namespace "$NAMESPACE")
C=app.kubernetes.io/component

die() { echo "k8s-run: $*" >&2; exit 1; }
command -v kubectl >/dev/null || die "kubectl not found"
[ -r "$MANIFEST" ] || die "cannot read $MANIFEST"

# wait_job NAME TIMEOUT: 0 when the Job completed, 1 when it failed or timed out.
wait_job() {
  local job=$1 limit=$2 ok fail
  "${kc[@]}" wait --for=condition=complete "job/$job" --timeout="$limit" >/dev/null 2>&1 &
  ok=$!
  "${kc[@]}" wait --for=condition=failed "job/$job" --timeout="$limit" >/dev/null 2>&1 &
  fail=$!
  # Whichever wait ends first decides.
  while kill -0 "$ok" 2>/dev/null && kill -0 "$fail" 2>/dev/null; do sleep 2; done
  if ! kill -0 "$ok" 2>/dev/null && wait "$ok"; then
    kill "$fail" 2>/dev/null || true
    wait "$fail" 2>/dev/null || true
    return 0
  fi
  kill "$ok" "$fail" 2>/dev/null || true
  wait "$ok" "$fail" 2>/dev/null || true
  return 1
}

if [ "${RESTART:-0}" = 1 ]; then
  "${kc[@]}" delete job penumbra-shards penumbra-merge --ignore-not-found --wait=true
fi
"${kc[@]}" apply -f "$MANIFEST" -l "$C=storage"
"${kc[@]}" apply -f "$MANIFEST" -l "$C=shards"
echo "k8s-run: waiting for job/penumbra-shards (at most $SHARDS_TIMEOUT)"
if ! wait_job penumbra-shards "$SHARDS_TIMEOUT"; then
  "${kc[@]}" get pods -l "job-name=penumbra-shards" -o wide || true
  die "job/penumbra-shards failed or timed out: the merge is not started (logs: kubectl logs -l job-name=penumbra-shards)"
fi
"${kc[@]}" apply -f "$MANIFEST" -l "$C=merge"
echo "k8s-run: waiting for job/penumbra-merge (at most $MERGE_TIMEOUT)"
if ! wait_job penumbra-merge "$MERGE_TIMEOUT"; then
  "${kc[@]}" logs -l "job-name=penumbra-merge" --tail=20 || true
  die "job/penumbra-merge failed or timed out"
fi
"${kc[@]}" logs -l "job-name=penumbra-merge" --tail=20 || true
echo "k8s-run: done; the image is on the claim penumbra-farm (OUT_DIR in the ConfigMap penumbra-render)"
