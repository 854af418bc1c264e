#!/usr/bin/env bash
# Cost per ray against POV-Ray's, scene by scene: every fourth example scene that passes its
# comparison in docs/corpus.md, rendered once by POV-Ray 3.7 with -A (one ray per pixel) and
# once by penumbra at one sample per pixel (--uniform), both at 640x480 on one thread, side
# by side in one run, RUNS times each in turn (default 2), keeping each one's fastest. POV-Ray's
# time is its trace time (parse and start-up apart, as it reports them); penumbra's is its
# render time (its summary line: parse and preparation apart). Writes docs/cost/per_ray.csv
# and prints the table (docs/cost/per_ray_table.py). Takes about 15 minutes a run; run it
# with nothing else on the machine.
# Environment: BIN (a built penumbra; default: build one), BASE (an earlier penumbra to time
# beside it, e.g. a build of the commit before a change), OUT (default docs/cost/per_ray.csv),
# WIDTH/HEIGHT (default 640x480), RUNS (default 2).
set -euo pipefail
cd "$(dirname "$0")/../.."
bin=${BIN:-./target/release/penumbra}
[ -n "${BIN:-}" ] || cargo build --release --quiet
bin=$(realpath "$bin")
out=$(realpath -m "${OUT:-docs/cost/per_ray.csv}")
w=${WIDTH:-640}
h=${HEIGHT:-480}
runs=${RUNS:-2}
scenes=/usr/share/povray-3.7/scenes
include=/usr/share/povray-3.7/include
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
grep -E '^\| [a-zA-Z_/0-9.-]+\.pov \| yes \| (pixel|distribution)' docs/corpus.md \
  | grep -E '\| pass' | awk -F'|' '{gsub(/ /,"",$2); print $2}' | awk 'NR % 4 == 1' > "$tmp/list"
base=${BASE:+$(realpath "$BASE")}
echo "scene,povray_parse_s,povray_trace_s,penumbra_render_s,base_render_s" > "$out"
while read -r s; do
  (
    cd "$scenes/$(dirname "$s")"
    f=$(basename "$s")
    # The render time from a penumbra's summary line.
    time_of() {
      timeout 300 "$1" render "$f" --width "$w" --height "$h" --spp 1 --uniform --threads 1 \
        -L "$include" --output "$tmp/q.png" 2>&1 | sed -nE 's/.* spp, ([0-9.]+) s,.*/\1/p' | tail -1
    }
    # The fastest of `runs`, each renderer in turn: disturbance only ever adds time.
    least() {
      if [ -z "$1" ] || { [ -n "$2" ] && awk "BEGIN { exit !($2 < $1) }"; }; then
        echo "$2"
      else
        echo "$1"
      fi
    }
    parse="" trace="" render="" before=""
    for _ in $(seq "$runs"); do
      pov=$(timeout 300 povray "+I$f" "+O$tmp/p.png" "+W$w" "+H$h" -A +WT1 -D "+L$include" 2>&1 || true)
      parse=$(least "$parse" "$(echo "$pov" | sed -nE 's/.*Parse Time.*\(([0-9.]+) seconds\).*/\1/p')")
      trace=$(least "$trace" "$(echo "$pov" | sed -nE 's/.*Trace Time.*\(([0-9.]+) seconds\).*/\1/p')")
      render=$(least "$render" "$(time_of "$bin" || true)")
      if [ -n "$base" ]; then before=$(least "$before" "$(time_of "$base" || true)"); fi
    done
    if [ -n "$parse" ] && [ -n "$trace" ] && [ -n "$render" ]; then
      echo "$s,$parse,$trace,$render,$before" >> "$out"
    fi
  )
done < "$tmp/list"
python3 docs/cost/per_ray_table.py "$out"
