#!/usr/bin/env bash
# Regenerates docs/convergence.md and its charts: for every scene in scenes/, penumbra at
# several sample counts (K seeds each) and POV-Ray at its quality settings, against the
# scene's POV-Ray reference (tests/references/NAME.exr, or one rendered here if missing).
# Needs the installed povray. Usage: docs/convergence/regenerate.sh
# Environment: SPP (default 1,4,16,64,256), SEEDS (default 4), THREADS (default: all cores).
set -euo pipefail
cd "$(dirname "$0")/../.."
SPP=${SPP:-1,4,16,64,256}
SEEDS=${SEEDS:-4}
THREADS=${THREADS:-$(nproc)}
cargo build --release --quiet
bin=./target/release/penumbra
out=docs/convergence
refs=target/convergence-references
mkdir -p "$out" "$refs"

for scene in scenes/*.pov; do
  name=$(basename "$scene" .pov)
  reference="tests/references/$name.exr"
  if [ ! -f "$reference" ]; then
    reference="$refs/$name.exr"
    [ -f "$reference" ] || "$bin" reference "$scene" --output "$reference" \
      --width 160 --height 120 --supersample 16
  fi
  "$bin" converge "$scene" --reference "$reference" --spp "$SPP" --seeds "$SEEDS" \
    --threads "$THREADS" --povray --output-dir "$out/$name" > /dev/null
done

# The 640x480 section is written by hand around docs/convergence/640/table.md (made by
# bench640.sh, which takes an hour): kept as it is.
at640=$(awk '/^## At 640x480/ { keep = 1 } /^\*\*Machine:\*\*/ { keep = 0 } keep' docs/convergence.md)
cpu=$(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2- | sed 's/^ *//' || true)
povray_version=$(povray --version 2>&1 | grep -m1 -o 'POV-Ray [0-9.]*[0-9]' || echo 'POV-Ray')
{
  cat <<HEADER
# Convergence: penumbra against POV-Ray, accuracy against speed

Regenerate everything on this page (charts, tables, numbers) with

    docs/convergence/regenerate.sh

It runs \`penumbra converge SCENE --reference REF.exr --spp $SPP --seeds $SEEDS --povray\`
for every scene in \`scenes/\`, at 160x120 against the scene's POV-Ray reference
(\`tests/references/\`: POV-Ray rendered 16 times larger without anti-aliasing and
block-averaged; the 8x render beside it bounds the reference's own error).

HEADER
  echo "$at640"
  cat <<HEADER

**Machine:** ${cpu:-unknown CPU}, $(nproc) cores (shared with other jobs while measured, so
single timings are noisy), $THREADS threads for penumbra and for POV-Ray (\`+WT$THREADS\`);
$povray_version.
**Times:** penumbra's are wall-clock scene load (parse included) plus render, median of
$SEEDS seeds; POV-Ray's are its own reported parse + bounding + trace times: its process
also spends a fixed ~0.6 s starting and stopping, which at this size would dominate and is
left out (the CSVs keep the process time too, as \`process_seconds\`).

**How to read the charts:** error is RMSE over all pixels and channels against the
reference, on log-log axes. The blue line is penumbra (median of the seeds, bars from the
lowest to the highest seed), the green line its noise sqrt(V) from replicate differences
alone, the dashed lines the reference slopes -1/2 (independent samples) and -1 (stratified,
smooth regions), the dashed floors penumbra's bias against POV-Ray sqrt(B) (4x4 block
means, the reference's own error subtracted; drawn only when above zero) and the per-pixel
floor sqrt(MSE - V), and the red crosses POV-Ray at \`-A\`, \`+A0.3\`, \`+A0.3 +AM2 +R3\` and
\`+A0.3 +AM2 +R4\`. "Time to reach" interpolates each method's lower envelope linearly on
the log-log curve; the speed-up is POV-Ray's time over penumbra's, a lower bound (">") when
POV-Ray never reaches the target. At 160x120 every render here takes well under a second,
so on a shared machine these speed-ups move by up to 2-3x between runs: read them as orders
of magnitude, and the errors (which do not depend on the machine) as exact.

## Time to reach RMSE 0.01 and 0.005

| scene | penumbra 0.01 | POV-Ray 0.01 | speed-up | penumbra 0.005 | POV-Ray 0.005 | speed-up |
| --- | ---: | ---: | ---: | ---: | ---: | ---: |
HEADER
  for scene in scenes/*.pov; do
    name=$(basename "$scene" .pov)
    printf '| %s |%s' "$name" "$(cat "$out/$name/speedup_row.md")"
    echo
  done
  for scene in scenes/*.pov; do
    name=$(basename "$scene" .pov)
    echo
    echo "## $name"
    echo
    head -n 2 "$scene" | sed -n 's|^// *||p' | tr '\n' ' '
    echo
    echo
    echo "![$name: error against time](convergence/$name/error_vs_time.svg)"
    echo "![$name: error against samples per pixel](convergence/$name/error_vs_spp.svg)"
    echo
    cat "$out/$name/summary.md"
    echo
    echo "Data: [converge.csv](convergence/$name/converge.csv); charts also as PNG."
  done
} > docs/convergence.md
echo "wrote docs/convergence.md"
