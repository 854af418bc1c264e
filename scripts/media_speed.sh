#!/usr/bin/env bash
# Equal-error time against POV-Ray for every media scene in scenes/, at the scenes' own
# media settings (1 interval of 4 samples) and at high ones (10 x 10, as the references),
# both renderers given the same settings. Writes docs/media-speed.md. Needs povray and the
# references in tests/references/ (tests/references/regenerate.sh). About 5 minutes.
set -euo pipefail
cd "$(dirname "$0")/.."
cargo build --release --quiet
out=docs/media-speed.md
tmp=$(mktemp -d)
{
  echo "# Media scenes: time to a given error, penumbra against POV-Ray"
  echo
  echo "Written by scripts/media_speed.sh on $(nproc) cores, $(date -u +%Y-%m-%d)."
  echo "Each scene at 160x120 against its reference (POV-Ray, 10 x 10 media samples,"
  echo "8x supersampled). POV-Ray's times are its own parse + render seconds (its process"
  echo "start-up, about 0.6 s, apart); penumbra's are render seconds for 2 seeds' median."
  echo "At the scenes' own settings POV-Ray's quadrature is biased, so its error stops at"
  echo "that bias (docs/differences.md); penumbra's estimator is unbiased at any setting."
  echo
} > "$out"
for scene in scenes/media_*.pov; do
  name=$(basename "$scene" .pov)
  rate=$(./target/release/penumbra render "$scene" --width 640 --height 480 --spp 16 \
    --output "$tmp/$name.exr" 2>&1 | grep -o '[0-9.]* M rays/s ([0-9]* rays)' || true)
  echo "**$name**: at 640x480, 16 spp, own settings: $rate (camera, shadow and secondary rays; the shadow rays from media points included)." >> "$out"
  echo >> "$out"
  for setting in own high; do
    args=()
    if [ "$setting" = high ]; then
      args=(--declare MediaIntervals=10 --declare MediaSamples=10)
    fi
    ./target/release/penumbra converge "$scene" --reference "tests/references/$name.exr" \
      --spp 1,4,16,64,256 --seeds 2 --povray --targets 0.01,0.005,0.002 --quiet \
      --output-dir "$tmp/$name-$setting" "${args[@]}" > /dev/null
    {
      echo "## $name, media settings: $setting"
      echo
      sed -n '/^| spp/,$p' "$tmp/$name-$setting/summary.md" | grep -v '^wrote'
      echo
    } >> "$out"
  done
done
rm -rf "$tmp"
echo "wrote $out"
