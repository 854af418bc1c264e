#!/bin/sh
# Runs `penumbra check` over every POV-Ray 3.7 example scene and sorts the outcomes into
# parsed / unsupported feature / other error / crash / timeout. SKIP=1 adds
# --skip-unsupported (unsupported features become warnings). Usage:
#   tests/corpus/check-all.sh [PENUMBRA_BINARY] [SCENES_DIR] [OUT_DIR]
BIN=${1:-target/release/penumbra}
SCENES=${2:-/usr/share/povray-3.7/scenes}
OUT=${3:-target/corpus}
mkdir -p "$OUT"
: > "$OUT/results.tsv"
find -L "$SCENES" -name '*.pov' | sort | while read -r scene; do
    rel=${scene#"$SCENES"/}
    dir=$(dirname "$scene")
    timeout 30 "$BIN" check ${SKIP:+--skip-unsupported} -L "$dir" "$scene" >/dev/null 2>"$OUT/err.txt" </dev/null
    rc=$?
    first=$(grep -m1 -i '^error' "$OUT/err.txt")
    if [ $rc -eq 0 ]; then
        kind=parsed
    elif [ $rc -eq 124 ]; then
        kind=timeout
    elif [ $rc -gt 128 ] || grep -q 'panicked' "$OUT/err.txt"; then
        kind=crash
    elif echo "$first" | grep -q 'unsupported'; then
        kind=unsupported
    else
        kind=other
    fi
    loc=$(grep -m1 -E '^ *--> ' "$OUT/err.txt" | sed 's/^ *--> //')
    printf '%s\t%s\t%s\t%s\n' "$rel" "$kind" "$first" "$loc" >> "$OUT/results.tsv"
done
cut -f2 "$OUT/results.tsv" | sort | uniq -c
