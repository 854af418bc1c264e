#!/bin/sh
# Regenerates docs/corpus.md and its gallery (docs/corpus/*.png): every POV-Ray example scene
# parsed, the parsed ones rendered by penumbra (K = 4 seeds, 64 spp, 160x120) and by POV-Ray
# (k = 16 and 8, cached in ~/.cache/penumbra/corpus, so a rerun costs only penumbra's
# renders), judged pixel by pixel or in distribution (src/study/corpus). Extra options go to
# `penumbra corpus` (e.g. --only 'textures/*', --reference-timeout 600). Long: run it in the
# background; the report is rewritten after every scene.
set -eu
cd "$(dirname "$0")/../.."
cargo build --release --quiet
# A copy, so that a rebuild during the sweep cannot pull the binary from under it.
mkdir -p target/corpus-bin
cp target/release/penumbra target/corpus-bin/penumbra
rm -f docs/corpus/*.png
exec nice -n 10 target/corpus-bin/penumbra corpus --out docs/corpus.md "$@"
