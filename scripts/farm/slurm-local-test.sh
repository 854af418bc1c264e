#!/usr/bin/env bash
# shellcheck disable=SC2317 # (the cleanup functions below are called from the EXIT trap)
# Local end-to-end test of the Slurm farm scripts: a one-node Slurm cluster on this machine
# (loopback only), a penumbra render split into 8 shards by scripts/farm/submit.sh, merged
# by the merge job, and the merged image compared byte for byte (cmp) with the same render
# done on one machine. Then the cluster is shut down and no process may be left behind.
#
# What it does:
#   1. installs Debian's slurm-wlm and munge if missing (apt-get; root only);
#   2. writes a munge key, slurm.conf and cgroup.conf into a temporary folder and starts
#      munged, slurmctld and slurmd there (own socket, ports, state and spool folders;
#      proctrack/linuxproc and task/none: no systemd or cgroups needed);
#   3. case "image": scenes/soft_shadow.pov at 96x72, 16 spp, seed 7, 8 shards: submit.sh,
#      wait for the merge (with a timeout), cmp against `penumbra render` of the whole;
#   4. case "frames": scenes/clock_animation.pov, frames 1..3, 4 shards: each merged frame
#      cmp'd against the one-machine frame (FRAMES_CASE=0 leaves it out);
#   5. case "failing shard": shards given a bad option must fail, and the merge must then be
#      cancelled by Slurm (afterok can never be met), not left pending;
#   6. `penumbra merge` refuses an incomplete shard set (7 of 8), a doubled shard, and a
#      set with one shard of another seed;
#   7. stops everything (trap on EXIT, so on failure too) and checks with pgrep that no
#      daemon, job step or penumbra process of the test remains.
#
# Exit status: 0 passed; 1 failed (with a message saying what); 77 skipped: Slurm or munge
# could not be installed or started here (the message says why). Never waits long: every
# wait has a timeout.
#
# Environment:
#   PENUMBRA      the penumbra binary      [<repo>/target/release/penumbra]
#   KEEP_TMP=1    keep the temporary folder (configs, daemon logs, shards, images)
#   FRAMES_CASE=0 skip the animation case
#   STANDIN=1     use a shell stand-in for penumbra (tests the Slurm plumbing only; the
#                 stand-in writes text "shards" and checks coverage like merge does)
#   JOB_TIMEOUT   seconds to wait for each submitted render to finish [120]
set -uo pipefail

T0=$(date +%s)
HERE=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
ROOT=$(cd "$HERE/../.." && pwd)
PENUMBRA=${PENUMBRA:-$ROOT/target/release/penumbra}
KEEP_TMP=${KEEP_TMP:-0}
FRAMES_CASE=${FRAMES_CASE:-1}
STANDIN=${STANDIN:-0}
JOB_TIMEOUT=${JOB_TIMEOUT:-120}
SKIP=77

say() { echo "slurm-local-test: $*"; }
elapsed() { echo "$(($(date +%s) - T0)) s"; }
# Failures of the farm scripts or of penumbra.
fail() {
  echo "slurm-local-test: FAILED: $*" >&2
  exit 1
}
# Slurm itself cannot be had or run on this machine: not a failure of the scripts.
skip() {
  echo "slurm-local-test: SKIPPED (exit $SKIP): $*" >&2
  exit $SKIP
}

# ---------------------------------------------------------------- penumbra (or a stand-in)
TMP=$(mktemp -d /tmp/penumbra-slurm.XXXXXX) || fail "mktemp failed"
chmod 700 "$TMP"

write_standin() {
  # A stand-in with penumbra's command lines: `render ... [--sample-range A..B] [--frames
  # A..B] -o FILE` writes a text file listing the samples; `merge SHARD... -o FILE` checks
  # that the shards have one header and cover 0..N once, and writes what a whole render
  # writes. Deterministic, so cmp works as with the real images.
  cat >"$1" <<'EOF'
#!/usr/bin/env bash
set -euo pipefail
cmd=$1; shift
case "$cmd" in
  render)
    scene=$1; shift; range=""; frames=""; out=""; w=320; h=240; spp=16; seed=0
    while [ $# -gt 0 ]; do
      case "$1" in
        --width) w=$2; shift 2 ;; --height) h=$2; shift 2 ;; --spp) spp=$2; shift 2 ;;
        --seed) seed=$2; shift 2 ;; --sample-range) range=$2; shift 2 ;;
        --frames) frames=$2; shift 2 ;; -o) out=$2; shift 2 ;; --threads) shift 2 ;;
        -q) shift ;; *) echo "standin: unknown option $1" >&2; exit 2 ;;
      esac
    done
    a=${range%%..*}; b=${range##*..}; [ -n "$range" ] || { a=0; b=$spp; }
    emit() { # $1 output, $2 frame
      { echo "standin $(basename "$scene") ${w}x$h spp=$spp seed=$seed frame=$2"
        if [ -n "$range" ]; then seq "$a" $((b - 1)) | sed 's/^/sample /'; else echo "samples 0..$spp"; fi
      } >"$1"
    }
    if [ -z "$frames" ]; then emit "$out" -; else
      f0=${frames%%..*}; f1=${frames##*..}
      for ((f = f0; f <= f1; f++)); do
        printf -v num "%0${#f1}d" "$f"; emit "${out%.*}$num.${out##*.}" "$f"
      done
    fi ;;
  merge)
    [ "${1:-}" != --help ] || { echo "standin merge"; exit 0; }
    files=(); out=""
    while [ $# -gt 0 ]; do case "$1" in -o) out=$2; shift 2 ;; *) files+=("$1"); shift ;; esac; done
    header=$(head -n1 "${files[0]}")
    for f in "${files[@]}"; do
      [ "$(head -n1 "$f")" = "$header" ] || { echo "standin merge: $f is from another render" >&2; exit 1; }
    done
    spp=$(echo "$header" | sed 's/.*spp=\([0-9]*\).*/\1/')
    got=$(for f in "${files[@]}"; do tail -n +2 "$f"; done | sort -k2n | tr '\n' ' ')
    want=$(seq 0 $((spp - 1)) | sed 's/^/sample /' | tr '\n' ' ')
    [ "$got" = "$want" ] || { echo "standin merge: the shards do not cover samples 0..$spp exactly once" >&2; exit 1; }
    { echo "$header"; echo "samples 0..$spp"; } >"$out" ;;
  *) echo "standin: unknown command $cmd" >&2; exit 2 ;;
esac
EOF
  chmod +x "$1"
}

if [ "$STANDIN" = 1 ]; then
  PENUMBRA=$TMP/penumbra-standin
  write_standin "$PENUMBRA"
  say "STANDIN=1: a shell stand-in replaces penumbra (Slurm plumbing only)"
fi
case "$PENUMBRA" in */*) PENUMBRA=$(cd "$(dirname "$PENUMBRA")" 2>/dev/null && pwd)/$(basename "$PENUMBRA") ;; esac
[ -x "$PENUMBRA" ] || fail "no penumbra binary at $PENUMBRA (build it: cargo build --release; or set PENUMBRA)"
timeout 20 "$PENUMBRA" merge --help >/dev/null 2>&1 ||
  fail "$PENUMBRA has no working 'merge' subcommand (penumbra merge --help failed); STANDIN=1 tests the Slurm side alone"

# ---------------------------------------------------------------- cleanup, on any exit
PIDS_TO_STOP=() # daemons we started, in the order to stop them
DAEMONS=(slurmctld slurmd slurmstepd munged)
daemon_pids() { local d; for d in "${DAEMONS[@]}"; do pgrep -x "$d"; done; }
PREEXISTING=$(daemon_pids | tr '\n' ' ')
SLURM_UP=0
stop_pid() { # pid name
  local pid=$1 name=$2 i
  kill -0 "$pid" 2>/dev/null || return 0
  kill -TERM "$pid" 2>/dev/null
  for ((i = 0; i < 100; i++)); do
    kill -0 "$pid" 2>/dev/null || return 0
    sleep 0.1
  done
  say "$name ($pid) did not stop on TERM in 10 s; KILL"
  kill -KILL "$pid" 2>/dev/null
  sleep 0.5
}
leftovers() { # processes of this test: argv naming the temp folder, our daemons, job steps
  local p out=""
  for p in $(pgrep -f -- "$TMP" 2>/dev/null); do
    [ "$p" = $$ ] || out+="$p "
  done
  for p in "${PIDS_TO_STOP[@]}"; do
    p=${p%%:*}
    kill -0 "$p" 2>/dev/null && out+="$p "
  done
  if [ -z "$PREEXISTING" ]; then
    for p in $(daemon_pids); do out+="$p "; done
  fi
  # A zombie (state Z: ended, waiting for init to reap it) is no process left running.
  for p in $(echo "$out" | tr ' ' '\n' | sort -u); do
    [ "$(ps -o stat= -p "$p" 2>/dev/null | cut -c1)" = Z ] || echo "$p"
  done | tr '\n' ' ' | sed 's/ *$//'
}
cleanup() {
  local rc=$? i entry rest jobs
  trap - EXIT INT TERM
  set +e
  if [ "$SLURM_UP" = 1 ]; then
    # Every job of this private controller is this test's.
    jobs=$(timeout 10 squeue -h -o %A 2>/dev/null | sort -u | tr '\n' ' ')
    # shellcheck disable=SC2086 # a list of job ids
    [ -z "${jobs// /}" ] || timeout 10 scancel --quiet --full $jobs >/dev/null 2>&1
    for ((i = 0; i < 50; i++)); do
      [ -z "$(timeout 5 squeue -h -o %A 2>/dev/null)" ] && break
      sleep 0.2
    done
  fi
  # slurmd first (it ends its job steps), then slurmctld, then munged.
  for ((i = ${#PIDS_TO_STOP[@]} - 1; i >= 0; i--)); do
    entry=${PIDS_TO_STOP[$i]}
    stop_pid "${entry%%:*}" "${entry#*:}"
  done
  # Job steps and daemons may take a moment to go: look again for up to 5 s.
  for ((i = 0; i < 10; i++)); do
    rest=$(leftovers)
    [ -z "$rest" ] && break
    sleep 0.5
  done
  if [ -n "$rest" ]; then
    echo "slurm-local-test: processes left behind:" >&2
    ps -o pid,ppid,args -p "${rest// /,}" >&2
    for i in $rest; do kill -KILL "$i" 2>/dev/null; done
    [ "$rc" = 0 ] && rc=1
    echo "slurm-local-test: FAILED: processes were left behind (now killed)" >&2
  else
    say "no process left behind (pgrep)"
  fi
  if [ "$KEEP_TMP" = 1 ]; then
    say "kept $TMP"
  else
    rm -rf "$TMP"
  fi
  case $rc in
    0) say "PASSED in $(elapsed)" ;;
    "$SKIP") say "skipped after $(elapsed)" ;;
    *) say "exit $rc after $(elapsed)" ;;
  esac
  exit "$rc"
}
trap cleanup EXIT
trap 'echo "slurm-local-test: interrupted" >&2; exit 130' INT TERM

# ---------------------------------------------------------------- install Slurm and munge
have_slurm() {
  command -v slurmctld && command -v slurmd && command -v sbatch && command -v munged && command -v munge
} >/dev/null 2>&1
if ! have_slurm; then
  [ "$(id -u)" = 0 ] || skip "Slurm/munge are not installed and installing them needs root"
  command -v apt-get >/dev/null || skip "Slurm/munge are not installed and there is no apt-get"
  say "installing slurm-wlm and munge (apt-get)"
  export DEBIAN_FRONTEND=noninteractive
  timeout 180 apt-get update -qq >"$TMP/apt.log" 2>&1 || {
    tail -5 "$TMP/apt.log" >&2
    skip "apt-get update failed or timed out"
  }
  timeout 300 apt-get install -y -qq slurm-wlm munge >>"$TMP/apt.log" 2>&1 || {
    tail -5 "$TMP/apt.log" >&2
    skip "apt-get install slurm-wlm munge failed or timed out"
  }
  have_slurm || skip "slurm-wlm and munge installed, but slurmctld/slurmd/sbatch/munged are still missing"
fi
say "$(slurmctld -V 2>&1), $(munged -V 2>&1 | head -n1)"

# ---------------------------------------------------------------- munge
mkdir -p "$TMP/munge" "$TMP/log" "$TMP/state" "$TMP/spool" "$TMP/run"
chmod 700 "$TMP/munge"
KEY=$TMP/munge/munge.key
if [ ! -f "$KEY" ]; then
  if command -v mungekey >/dev/null; then
    mungekey --create --keyfile="$KEY" >/dev/null 2>&1 || dd if=/dev/urandom of="$KEY" bs=1024 count=1 2>/dev/null
  else
    dd if=/dev/urandom of="$KEY" bs=1024 count=1 2>/dev/null
  fi
  chmod 600 "$KEY"
fi
SOCK=$TMP/munge/munge.socket
munged --foreground --force --socket="$SOCK" --key-file="$KEY" --pid-file="$TMP/munge/munged.pid" \
  --log-file="$TMP/log/munged.log" --seed-file="$TMP/munge/munged.seed" >"$TMP/log/munged.out" 2>&1 &
PIDS_TO_STOP+=("$!:munged")
MUNGED_PID=$!
# wait_for SECONDS PID COMMAND...: until COMMAND succeeds (0), the daemon PID dies or the
# time is up (1).
wait_for() {
  local deadline=$((SECONDS + $1)) pid=$2
  shift 2
  while ((SECONDS < deadline)); do
    "$@" && return 0
    kill -0 "$pid" 2>/dev/null || return 1
    sleep 0.2
  done
  return 1
}
munge_round_trip() { timeout 5 munge -n -S "$SOCK" 2>/dev/null | timeout 5 unmunge -S "$SOCK" >/dev/null 2>&1; }
if ! wait_for 20 "$MUNGED_PID" munge_round_trip; then
  cat "$TMP/log/munged.out" "$TMP/log/munged.log" 2>/dev/null | tail -5 >&2
  skip "munged did not start (a credential round trip failed)"
fi
say "munged is up ($SOCK)"

# ---------------------------------------------------------------- slurm.conf
NODE=$(hostname -s 2>/dev/null || hostname)
[ -n "$NODE" ] || NODE=localhost
CPUS=$(nproc)
USER_NAME=$(id -un)
port_free() { ! (exec 3<>"/dev/tcp/127.0.0.1/$1") 2>/dev/null; }
pick_port() {
  local p i
  for ((i = 0; i < 50; i++)); do
    p=$((20000 + RANDOM % 30000))
    if port_free "$p" && port_free $((p + 1)); then
      echo "$p"
      return 0
    fi
  done
  return 1
}
PORT=$(pick_port) || skip "no free pair of TCP ports on 127.0.0.1"
export SLURM_CONF=$TMP/slurm.conf
cat >"$SLURM_CONF" <<EOF
# A one-node test cluster, loopback only (written by scripts/farm/slurm-local-test.sh).
ClusterName=penumbra-test
SlurmctldHost=$NODE(127.0.0.1)
SlurmctldPort=$PORT
SlurmdPort=$((PORT + 1))
SlurmUser=$USER_NAME
SlurmdUser=root
AuthType=auth/munge
AuthInfo=socket=$SOCK
CredType=cred/munge
StateSaveLocation=$TMP/state
SlurmdSpoolDir=$TMP/spool
SlurmctldPidFile=$TMP/run/slurmctld.pid
SlurmdPidFile=$TMP/run/slurmd.pid
SlurmctldLogFile=$TMP/log/slurmctld.log
SlurmdLogFile=$TMP/log/slurmd.log
SlurmctldDebug=info
SlurmdDebug=info
# No systemd, no cgroups: plain process tracking, no task binding, no accounting.
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
JobCompType=jobcomp/filetxt
JobCompLoc=$TMP/log/jobcomp.txt
SwitchType=switch/none
MpiDefault=none
SchedulerType=sched/backfill
SchedulerParameters=batch_sched_delay=0,sched_min_interval=0
SelectType=select/cons_tres
SelectTypeParameters=CR_CPU
SlurmdParameters=config_overrides
ReturnToService=2
MailProg=/bin/true
SlurmctldTimeout=30
SlurmdTimeout=30
MessageTimeout=10
KillWait=5
InactiveLimit=0
MinJobAge=600
NodeName=$NODE NodeHostname=$NODE NodeAddr=127.0.0.1 CPUs=$CPUS State=UNKNOWN
PartitionName=test Nodes=$NODE Default=YES MaxTime=10 State=UP
EOF
cat >"$TMP/cgroup.conf" <<EOF
# Not used (proctrack/linuxproc, task/none); present so nothing looks for /etc/slurm.
CgroupPlugin=autodetect
IgnoreSystemd=yes
EOF

# ---------------------------------------------------------------- slurmctld, slurmd
slurmctld -D -i -f "$SLURM_CONF" >"$TMP/log/slurmctld.out" 2>&1 &
PIDS_TO_STOP+=("$!:slurmctld")
CTLD_PID=$!
SLURM_UP=1
controller_up() { timeout 5 scontrol ping 2>/dev/null | grep -q 'is UP'; }
if ! wait_for 40 "$CTLD_PID" controller_up; then
  tail -n 8 "$TMP/log/slurmctld.out" "$TMP/log/slurmctld.log" >&2 2>/dev/null
  skip "slurmctld did not come up (logs above)"
fi
say "slurmctld is up (port $PORT)"

slurmd -D -N "$NODE" -f "$SLURM_CONF" >"$TMP/log/slurmd.out" 2>&1 &
PIDS_TO_STOP+=("$!:slurmd")
SLURMD_PID=$!
state=""
# idle, not idle* (not responding); a drained node fails here with its reason shown below.
node_ready() {
  state=$(timeout 5 sinfo -h -n "$NODE" -o %T 2>/dev/null | head -n1)
  case "$state" in idle | mixed | allocated) return 0 ;; esac
  return 1
}
if ! wait_for 40 "$SLURMD_PID" node_ready; then
  tail -n 8 "$TMP/log/slurmd.out" "$TMP/log/slurmd.log" >&2 2>/dev/null
  timeout 5 scontrol show node "$NODE" 2>/dev/null | grep -E 'State|Reason' >&2
  skip "slurmd did not register (node state '${state:-none}'; logs above)"
fi
say "slurmd is up: node $NODE, $CPUS CPUs, state $state ($(elapsed) so far)"

# ---------------------------------------------------------------- helpers for the cases
# wait_jobs TIMEOUT ID...: until none of the jobs is pending or running. A job whose
# dependency can never be met counts as finished (Slurm cancels it: --kill-on-invalid-dep).
wait_jobs() {
  local limit=$1 start ids left
  shift
  ids=$(IFS=,; echo "$*")
  start=$(date +%s)
  while :; do
    left=$(timeout 10 squeue -h -j "$ids" -o '%i %T %r' 2>/dev/null)
    [ -z "$left" ] && return 0
    if (($(date +%s) - start > limit)); then
      echo "$left" >&2
      return 1
    fi
    sleep 0.5
  done
}
# job_states ID: the final state of a job, or of every task of an array ("COMPLETED" x8 ...)
job_states() {
  timeout 10 scontrol -o show job "$1" 2>/dev/null | grep -o 'JobState=[A-Z_]*' | sed 's/JobState=//' | sort | uniq -c | tr -s ' ' | sed 's/^ //'
}
show_logs() { # run folder
  local f
  for f in "$1"/logs/*.out; do
    [ -f "$f" ] || continue
    echo "--- $f" >&2
    tail -n 5 "$f" >&2
  done
}
# submit_case NAME VAR=VALUE...: submit.sh with the settings; sets ARRAY_JOB, MERGE_JOB
submit_case() {
  local name=$1 out
  shift
  out=$(timeout 60 bash "$HERE/submit.sh" "$@" PENUMBRA="$PENUMBRA" SBATCH_ARGS="--time=5") ||
    fail "$name: submit.sh failed: $out"
  ARRAY_JOB=$(echo "$out" | sed -n 's/^array_job=//p')
  MERGE_JOB=$(echo "$out" | sed -n 's/^merge_job=//p')
  if [ -z "$ARRAY_JOB" ] || [ -z "$MERGE_JOB" ]; then
    fail "$name: submit.sh printed no job ids: $out"
  fi
  say "$name: submitted shard array $ARRAY_JOB and merge $MERGE_JOB"
}
# render_ok NAME RUN: waits for ARRAY_JOB and MERGE_JOB and checks that all completed
render_ok() {
  local name=$1 run=$2 s m
  wait_jobs "$JOB_TIMEOUT" "$ARRAY_JOB" "$MERGE_JOB" || {
    show_logs "$run"
    fail "$name: the jobs did not finish in $JOB_TIMEOUT s"
  }
  s=$(job_states "$ARRAY_JOB")
  m=$(job_states "$MERGE_JOB")
  say "$name: shard tasks: $s; merge: $m"
  [[ $s =~ ^[0-9]+\ COMPLETED$ ]] || {
    show_logs "$run"
    fail "$name: not every shard task completed ($s)"
  }
  [ "$m" = "1 COMPLETED" ] || {
    show_logs "$run"
    fail "$name: the merge job did not complete ($m)"
  }
}

SOFT=$ROOT/scenes/soft_shadow.pov
ANIM=$ROOT/scenes/clock_animation.pov
[ -r "$SOFT" ] || fail "no scene $SOFT"

# ---------------------------------------------------------------- case 1: one image, 8 shards
RUN=$TMP/image
mkdir -p "$RUN"
t=$(date +%s)
timeout 120 "$PENUMBRA" render "$SOFT" --width 96 --height 72 --spp 16 --seed 7 -o "$RUN/single.png" -q ||
  fail "image: the one-machine render failed"
submit_case image SCENE="$SOFT" OUT_DIR="$RUN" WIDTH=96 HEIGHT=72 SPP=16 SEED=7 SHARDS=8 IMAGE=merged.png
render_ok image "$RUN"
n=$(find "$RUN/shards" -name 'shard-*.pshard' | wc -l)
[ "$n" = 8 ] || fail "image: expected 8 shard files, found $n"
[ -f "$RUN/merged.png" ] || fail "image: the merge job wrote no $RUN/merged.png"
cmp "$RUN/single.png" "$RUN/merged.png" || fail "image: the merged image differs from the one-machine render"
say "image: 8 shards merged == one-machine render (cmp), soft_shadow 96x72 16 spp seed 7 ($(($(date +%s) - t)) s)"

# ---------------------------------------------------------------- merge refuses a bad set
files=("$RUN"/shards/shard-*.pshard)
# refuse NAME SHARD...: penumbra merge must exit non-zero and say why
refuse() {
  local name=$1
  shift
  if timeout 60 "$PENUMBRA" merge "$@" -o "$TMP/bad.png" >"$TMP/bad.log" 2>&1; then
    fail "penumbra merge accepted $name"
  fi
  [ -s "$TMP/bad.log" ] || fail "penumbra merge refused $name but said nothing"
  say "merge refuses $name: $(head -n1 "$TMP/bad.log")"
}
refuse "7 of 8 shards" "${files[@]:0:7}"
refuse "a shard given twice" "${files[@]}" "${files[3]}"
timeout 60 "$PENUMBRA" render "$SOFT" --width 96 --height 72 --spp 16 --seed 8 --sample-range 0..2 \
  -o "$TMP/other-seed.pshard" -q || fail "rendering a shard with another seed failed"
refuse "shard 0 of another seed" "$TMP/other-seed.pshard" "${files[@]:1}"

# ---------------------------------------------------------------- case 2: frames x shards
if [ "$FRAMES_CASE" = 1 ]; then
  [ -r "$ANIM" ] || fail "no scene $ANIM"
  RUN=$TMP/frames
  mkdir -p "$RUN"
  t=$(date +%s)
  timeout 120 "$PENUMBRA" render "$ANIM" --width 48 --height 36 --spp 8 --seed 3 --frames 1..3 \
    -o "$RUN/single.png" -q || fail "frames: the one-machine render of frames 1..3 failed"
  submit_case frames SCENE="$ANIM" OUT_DIR="$RUN" WIDTH=48 HEIGHT=36 SPP=8 SEED=3 SHARDS=4 \
    FRAMES=1..3 IMAGE=merged.png
  render_ok frames "$RUN"
  count=0
  for single in "$RUN"/single*.png; do
    number=${single#"$RUN"/single}
    number=${number%.png}
    [ -f "$RUN/merged$number.png" ] || fail "frames: no merged frame $RUN/merged$number.png"
    cmp "$single" "$RUN/merged$number.png" || fail "frames: merged frame $number differs from the one-machine frame"
    count=$((count + 1))
  done
  [ "$count" = 3 ] || fail "frames: expected 3 frames, the one-machine render wrote $count"
  say "frames: 3 frames x 4 shards merged == one-machine frames (cmp) ($(($(date +%s) - t)) s)"
fi

# ---------------------------------------------------------------- case 3: a failing shard
RUN=$TMP/failing
mkdir -p "$RUN"
submit_case failing SCENE="$SOFT" OUT_DIR="$RUN" WIDTH=32 HEIGHT=24 SPP=4 SEED=1 SHARDS=2 \
  RENDER_ARGS=--no-such-option IMAGE=merged.png
wait_jobs 60 "$ARRAY_JOB" "$MERGE_JOB" || fail "failing: the jobs were still queued after 60 s (merge left pending?)"
s=$(job_states "$ARRAY_JOB")
m=$(job_states "$MERGE_JOB")
say "failing: shard tasks: $s; merge: $m"
[[ $s =~ FAILED ]] || fail "failing: the shard tasks with a bad option did not fail ($s)"
[[ $m =~ CANCELLED ]] || fail "failing: the merge was not cancelled after the shards failed ($m)"
[ ! -e "$RUN/merged.png" ] || fail "failing: a merged image exists although the shards failed"
say "failing: shards failed, the merge was cancelled (afterok), no image"

say "all cases passed; run time $(elapsed) (shutting down)"
exit 0
