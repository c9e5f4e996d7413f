#!/bin/sh
# The sample scenes (scenes/*.pov, *.xml, *.obj) under two or more accel modes, as whole
# `render` frames, alternating the modes run by run so that both see the same machine: the
# median frame time (render's "wrote" line) per scene and mode, and the ratio to the first mode.
# This is how the default accel was chosen (docs/settings.md).
#
# Usage: tests/bench/accel_scenes.sh RENDER [SIZE] [RUNS] [MODES]
#        e.g. tests/bench/accel_scenes.sh build/plugin/render/render 256 3 "crsh bvh"
set -eu
render=$1
size=${2:-256}
runs=${3:-3}
modes=${4:-"crsh bvh"}
here=$(cd "$(dirname "$0")/../.." && pwd)
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
first=${modes%% *}
printf '| scene |'
for m in $modes; do printf ' %s ms |' "$m"; done
for m in $modes; do [ "$m" = "$first" ] || printf ' %s / %s |' "$m" "$first"; done
printf '\n|---|'
for m in $modes; do printf -- '---:|'; done
for m in $modes; do [ "$m" = "$first" ] || printf -- '---:|'; done
printf '\n'
for scene in "$here"/scenes/*.pov "$here"/scenes/*.xml "$here"/scenes/*.obj; do
    name=$(basename "$scene")
    for m in $modes; do : > "$out/$m"; done
    r=0
    while [ "$r" -lt "$runs" ]; do
        for m in $modes; do
            line=$("$render" "$scene" -W "$size" -H "$size" --set threads=2 --set accel="$m" \
                -o "$out/x.png" 2>/dev/null | grep '^wrote' || true)
            ms=$(printf '%s\n' "$line" | sed -n 's/.*frame \([0-9.]*\) ms.*/\1/p')
            [ -n "$ms" ] && echo "$ms" >> "$out/$m"
        done
        r=$((r + 1))
    done
    printf '| %s |' "$name"
    base=
    for m in $modes; do
        med=$(sort -n "$out/$m" | awk '{a[NR]=$1} END {if (NR) print a[int((NR+1)/2)]; else print "-"}')
        eval "med_$(echo "$m" | tr -c 'a-z0-9\n' _)=\$med"
        printf ' %s |' "$med"
        [ "$m" = "$first" ] && base=$med
    done
    for m in $modes; do
        [ "$m" = "$first" ] && continue
        eval "v=\$med_$(echo "$m" | tr -c 'a-z0-9\n' _)"
        awk -v a="$v" -v b="$base" 'BEGIN { if (b > 0 && a != "-") printf " %.2f |", a / b; else printf " - |" }'
    done
    printf '\n'
done
