#!/usr/bin/env bash
# Measures what POV-Ray's anti-aliasing switches give in POV-Ray and in penumbra (which maps
# them to sample counts): RMSE against the committed converged reference (160x120, k = 16),
# and wall time, side by side in one run. Prints the markdown rows of docs/cli.md's table.
# Needs the installed povray. Figures, not a timed test: the machine is shared.
set -euo pipefail
cd "$(dirname "$0")/../.."
cargo build --release --quiet
P=$PWD/target/release/penumbra
ROOT=$PWD
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
rmse() { "$P" compare "$1" "$2" | sed -n 's/^RMSE \([0-9.]*\).*/\1/p'; }
seconds() { local t0 t1; t0=$(date +%s.%N); "$@" >/dev/null 2>&1; t1=$(date +%s.%N); echo "$t1 - $t0" | bc; }
settings=("-A" "+A0.3" "+A0.1" "+A0.3 +AM2 +R3")
echo "| scene | switches | penumbra spp | POV-Ray RMSE | penumbra RMSE | POV-Ray s | penumbra s |"
echo "| --- | --- | --- | --- | --- | --- | --- |"
for scene in "$@"; do
  name=$(basename "$scene" .pov)
  ref=tests/references/$name.exr
  for s in "${settings[@]}"; do
    # shellcheck disable=SC2086
    tp=$(cd "$out" && seconds povray "+I$ROOT/$scene" +W160 +H120 $s +FE +Opov.exr -D -P -GA +WT2)
    # shellcheck disable=SC2086
    tn=$(seconds "$P" "$scene" +W160 +H120 $s +FE "+O$out/pen.exr" +WT2 --quiet)
    # shellcheck disable=SC2086
    spp=$("$P" "$scene" +W8 +H6 $s "+O$out/probe.png" 2>&1 | sed -n 's/.*, \([0-9]*\) spp.*/\1/p')
    echo "| $name | \`$s\` | $spp | $(rmse "$out/pov.exr" "$ref") | $(rmse "$out/pen.exr" "$ref") | $(printf %.2f "$tp") | $(printf %.2f "$tn") |"
  done
done
