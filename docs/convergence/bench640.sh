#!/usr/bin/env bash
# The equal-error benchmark where users render: 640x480, penumbra at several sample counts
# beside POV-Ray at -A, +A0.3, +AM2 +R3 and +AM2 +R4, measured side by side in one run
# against a POV-Ray reference at k = 8 (cached under target/bench640: they take minutes to
# hours each). Writes docs/convergence/640/NAME/ and prints each scene's summary.
# Usage: docs/convergence/bench640.sh [SCENE.pov...]   (default: the scenes listed below)
# Environment: SPP (default 1,2,3,4,6,8,16,32, and with --adaptive the averages 1.0625,
# 1.125, 1.25, 1.5 and 1.75 too, where one whole step doubles the time and POV-Ray's -A,
# +AM2 +R3 and +R4 errors fall), SEEDS (default 2), THREADS (default 1: penumbra
# and POV-Ray alike, so a loaded 2-core machine disturbs both the same way), OPTIONS (extra
# penumbra render options, e.g. "--adaptive"), OUT (default docs/convergence/640), BIN (a
# built penumbra, instead of building one). Run it once as it is and once with
# OPTIONS=--adaptive OUT=docs/convergence/640-adaptive (two at a time on two cores, one
# thread each); it then writes the equal-error table of both, docs/convergence/640/table.md.
set -euo pipefail
cd "$(dirname "$0")/../.."
if [[ "${OPTIONS:-}" == *--adaptive* ]]; then
  SPP=${SPP:-1,1.0625,1.125,1.25,1.5,1.75,2,3,4,6,8,16,32}
else
  SPP=${SPP:-1,2,3,4,6,8,16,32}
fi
OUT=${OUT:-docs/convergence/640}
SEEDS=${SEEDS:-2}
THREADS=${THREADS:-1}
scenes=("$@")
[ ${#scenes[@]} -gt 0 ] || scenes=(scenes/area_circular_9x9.pov scenes/soft_shadow.pov
  scenes/area_grid_6x2.pov scenes/area_illumination.pov scenes/glass.pov
  scenes/reflection.pov scenes/checker.pov scenes/shape_quadrics.pov scenes/focal_blur.pov
  scenes/csg_operations.pov scenes/pattern_gradient.pov scenes/area_adaptive.pov)
bin=${BIN:-./target/release/penumbra}
[ -n "${BIN:-}" ] || cargo build --release --quiet
refs=target/bench640
mkdir -p "$refs" "$OUT"
for scene in "${scenes[@]}"; do
  name=$(basename "$scene" .pov)
  [ -f "$refs/$name.exr" ] || "$bin" reference "$scene" --output "$refs/$name.exr" \
    --width 640 --height 480 --supersample 8
  # shellcheck disable=SC2086
  "$bin" converge "$scene" --reference "$refs/$name.exr" --spp "$SPP" --seeds "$SEEDS" \
    --threads "$THREADS" --povray --quiet --targets 0.01,0.005,0.0025 ${OPTIONS:-} \
    --output-dir "$OUT/$name"
done
if [ -d docs/convergence/640 ] && [ -d docs/convergence/640-adaptive ]; then
  python3 docs/convergence/bench640_table.py uniform=docs/convergence/640 \
    adaptive=docs/convergence/640-adaptive > docs/convergence/640/table.md
fi
