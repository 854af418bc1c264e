#!/usr/bin/env bash
# Regenerates the POV-Ray references for every scene in scenes/: 160x120, k = 16 (and the
# k = 8 render inside the same file). Needs the installed povray.
set -euo pipefail
cd "$(dirname "$0")/../.."
cargo build --release --quiet
for scene in scenes/*.pov; do
  name=$(basename "$scene" .pov)
  case "$name" in media_* | camera_mesh) continue ;; esac
  ./target/release/penumbra reference "$scene" --output "tests/references/$name.exr" \
    --width 160 --height 120 --supersample 16
done
# Media scenes: POV-Ray's quadrature at 10 intervals of 10 samples (its defaults overshoot
# the integral: docs/differences.md), k = 8 (and 4) to keep each under a few minutes.
for scene in scenes/media_*.pov; do
  name=$(basename "$scene" .pov)
  ./target/release/penumbra reference "$scene" --output "tests/references/$name.exr" \
    --width 160 --height 120 --supersample 8 \
    --declare MediaIntervals=10 --declare MediaSamples=10
done
# The mesh camera of distribution 0 shoots its rays from face centroids, whatever the pixel's
# size: POV-Ray's one ray per pixel at the image's own size is its converged image (k = 1).
./target/release/penumbra reference scenes/camera_mesh.pov --output tests/references/camera_mesh.exr \
  --width 160 --height 120 --supersample 1
# The continuous-light references: a fine grid (slow: about 7 minutes) and the corners only.
./target/release/penumbra reference scenes/area_continuous.pov \
  --output tests/references/area_continuous_n33.exr --declare AreaN=33
./target/release/penumbra reference scenes/area_continuous.pov \
  --output tests/references/area_continuous_n2.exr --declare AreaN=2
# Frame 4 of scenes/clock_animation.pov rendered as +KFI1 +KFF5 (clock 0.75), for
# tests/animation.rs.
./target/release/penumbra reference scenes/clock_animation.pov --clock 0.75 \
  --output tests/references/clock_animation_frame4.exr
# POV-Ray's own example scenes used by tests/povray_examples.rs and tests/corpus_sample.rs
# (the lists there), with their folder on the include path; named after their path with /
# turned into _.
P=/usr/share/povray-3.7/scenes
cat tests/povray_examples.rs tests/corpus_sample.rs | grep -o '"[a-z_/0-9]*\.pov"' |
  tr -d '"' | sed 's/\.pov$//' | sort -u |
while read -r f; do
  ./target/release/penumbra reference "$P/$f.pov" -L "$P/$(dirname "$f")" \
    --output "tests/references/examples/$(echo "$f" | tr / _).exr"
done
