#!/usr/bin/env bash
# Offline checks of scripts/farm/penumbra-shards.k8s.yaml (no cluster needed):
#   1. it parses as YAML (PyYAML) and has the fields an Indexed Job needs:
#      completionMode Indexed, completions = the ConfigMap's SHARDS, parallelism,
#      restartPolicy Never/OnFailure, the claim mounted by both Jobs, labels for k8s-run.sh;
#   2. kubernetes-validate (PyPI; it ships the Kubernetes OpenAPI schemas) validates every
#      document against the schema, strictly (unknown fields are errors), when installed
#      (`pip install kubernetes-validate`; INSTALL=1 lets this script install it);
#   3. the pods' shell scripts, run here by /bin/sh with JOB_COMPLETION_INDEX = 0..K-1 and a
#      small render (RUN=1, needs PENUMBRA with `merge`), write shards that the merge Job's
#      script merges into an image equal (cmp) to the one-machine render.
# Exit status: 0 all checks that could run passed; 1 a check failed.
set -euo pipefail

HERE=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
ROOT=$(cd "$HERE/../.." && pwd)
MANIFEST=${MANIFEST:-$HERE/penumbra-shards.k8s.yaml}
PYTHON=${PYTHON:-python3}
die() { echo "k8s-check: FAILED: $*" >&2; exit 1; }

"$PYTHON" -c 'import yaml' 2>/dev/null || {
  [ "${INSTALL:-0}" = 1 ] && "$PYTHON" -m pip install -q pyyaml
} || die "PyYAML is missing (pip install pyyaml)"

"$PYTHON" - "$MANIFEST" <<'EOF' || die "structure check"
import sys, yaml
docs = [d for d in yaml.safe_load_all(open(sys.argv[1])) if d]
by = {(d["kind"], d["metadata"]["name"]): d for d in docs}
def need(cond, what):
    if not cond:
        sys.exit(f"k8s-check: {what}")
cm = by.get(("ConfigMap", "penumbra-render"))
need(cm, "no ConfigMap penumbra-render")
need(("PersistentVolumeClaim", "penumbra-farm") in by, "no PersistentVolumeClaim penumbra-farm")
data = cm["data"]
for key in ["SCENE", "OUT_DIR", "WIDTH", "HEIGHT", "SPP", "SEED", "SHARDS", "FRAMES", "RENDER_ARGS", "IMAGE", "MERGE_ARGS"]:
    need(key in data and isinstance(data[key], str), f"ConfigMap data.{key} missing or not a string")
shards = by.get(("Job", "penumbra-shards"))
merge = by.get(("Job", "penumbra-merge"))
need(shards and merge, "the Jobs penumbra-shards and penumbra-merge are not both there")
s = shards["spec"]
need(s.get("completionMode") == "Indexed", "penumbra-shards: completionMode is not Indexed")
need(isinstance(s.get("completions"), int) and s["completions"] >= 1, "penumbra-shards: completions")
need(s["completions"] == int(data["SHARDS"]), f"completions {s['completions']} != SHARDS {data['SHARDS']}")
need(isinstance(s.get("parallelism"), int) and 1 <= s["parallelism"] <= s["completions"], "penumbra-shards: parallelism")
need(int(data["SHARDS"]) <= int(data["SPP"]), "SHARDS > SPP")
for job in (shards, merge):
    name = job["metadata"]["name"]
    pod = job["spec"]["template"]["spec"]
    need(pod.get("restartPolicy") in ("Never", "OnFailure"), f"{name}: restartPolicy must be Never or OnFailure")
    vols = {v["name"]: v for v in pod["volumes"]}
    c = pod["containers"][0]
    for m in c["volumeMounts"]:
        need(vols[m["name"]]["persistentVolumeClaim"]["claimName"] == "penumbra-farm", f"{name}: not the claim")
    need(any(e.get("configMapRef", {}).get("name") == "penumbra-render" for e in c["envFrom"]), f"{name}: envFrom")
    need(data["OUT_DIR"].startswith(c["volumeMounts"][0]["mountPath"] + "/"), f"{name}: OUT_DIR is not on the claim")
need("JOB_COMPLETION_INDEX" in shards["spec"]["template"]["spec"]["containers"][0]["args"][0], "shard pods do not read JOB_COMPLETION_INDEX")
components = {d["metadata"]["labels"]["app.kubernetes.io/component"] for d in docs}
need(components == {"storage", "shards", "merge"}, f"component labels {components}")
need(merge["metadata"]["labels"]["app.kubernetes.io/component"] == "merge", "merge label")
print(f"k8s-check: {len(docs)} documents parse; Indexed Job: completions {s['completions']} = SHARDS, parallelism {s['parallelism']}; both Jobs mount penumbra-farm")
EOF

if ! command -v kubernetes-validate >/dev/null && [ "${INSTALL:-0}" = 1 ]; then
  "$PYTHON" -m pip install -q kubernetes-validate || true
fi
if command -v kubernetes-validate >/dev/null; then
  # The oldest schemas it ships (1.25) and its default, the newest.
  for v in 1.25.0 ""; do
    kubernetes-validate --strict --quiet ${v:+-k "$v"} "$MANIFEST" || die "kubernetes-validate --strict ${v:+-k $v}"
  done
  echo "k8s-check: kubernetes-validate $(kubernetes-validate --version 2>&1 | tail -n1) --strict: every document valid against the Kubernetes 1.25 and newest bundled schemas"
else
  echo "k8s-check: kubernetes-validate not installed: schema validation not done (INSTALL=1 installs it)"
fi

if [ "${RUN:-0}" = 1 ]; then
  PENUMBRA=${PENUMBRA:-$ROOT/target/release/penumbra}
  "$PENUMBRA" merge --help >/dev/null 2>&1 || die "RUN=1 needs a penumbra with merge ($PENUMBRA)"
  tmp=$(mktemp -d)
  trap 'rm -rf "$tmp"' EXIT
  mkdir -p "$tmp/bin"
  ln -s "$PENUMBRA" "$tmp/bin/penumbra"
  "$PYTHON" - "$MANIFEST" "$tmp" <<'EOF'
import sys, yaml
docs = [d for d in yaml.safe_load_all(open(sys.argv[1])) if d]
for d in docs:
    if d["kind"] == "Job":
        c = d["spec"]["template"]["spec"]["containers"][0]
        open(f"{sys.argv[2]}/{d['metadata']['name']}.sh", "w").write(c["args"][0])
EOF
  run_case() { # frames
    local out=$tmp/run$1 k
    export SCENE=$ROOT/scenes/soft_shadow.pov OUT_DIR=$out WIDTH=64 HEIGHT=48 SPP=12 SEED=5 SHARDS=5
    export FRAMES=$1 RENDER_ARGS="" MERGE_ARGS="" IMAGE=image.png PATH="$tmp/bin:$PATH"
    [ -z "$FRAMES" ] || SCENE=$ROOT/scenes/clock_animation.pov
    for ((k = 0; k < SHARDS; k++)); do
      JOB_COMPLETION_INDEX=$k /bin/sh "$tmp/penumbra-shards.sh" >/dev/null || die "shard pod script, index $k"
    done
    /bin/sh "$tmp/penumbra-merge.sh" >/dev/null || die "merge pod script"
    local fr=()
    [ -z "$FRAMES" ] || fr=(--frames "$FRAMES")
    penumbra render "$SCENE" --width "$WIDTH" --height "$HEIGHT" --spp "$SPP" --seed "$SEED" "${fr[@]}" -o "$out/single.png" -q
    local n=0 f
    for f in "$out"/single*.png; do
      cmp "$f" "$out/image${f#"$out"/single}" || die "pod scripts: merged ${f#"$out"/} differs"
      n=$((n + 1))
    done
    echo "k8s-check: pod scripts under /bin/sh (indexes 0..4${FRAMES:+, frames $FRAMES}): $n merged image(s) == one-machine render (cmp)"
  }
  run_case ""
  run_case "1..2"
fi
echo "k8s-check: passed"
