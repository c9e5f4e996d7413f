#!/usr/bin/env bash
# Renders every scenes/*.xml (and the OBJ files there as whole scenes) at a small size through
# the render CLI: each must exit 0 and give a picture that is not one flat colour. A broken XML
# scene must exit 2 naming its file, line and column.
# Usage: scenes_test.sh PATH/TO/render SCENES_DIR OUTPUT_DIR PNG_TOOL
set -u

RENDER=${1:?usage: scenes_test.sh RENDER SCENES_DIR OUTDIR PNG_TOOL}
SCENES=${2:?usage: scenes_test.sh RENDER SCENES_DIR OUTDIR PNG_TOOL}
OUT=${3:?usage: scenes_test.sh RENDER SCENES_DIR OUTDIR PNG_TOOL}
PNG_TOOL=${4:?usage: scenes_test.sh RENDER SCENES_DIR OUTDIR PNG_TOOL}
rm -rf "$OUT"
mkdir -p "$OUT"

. "$(cd "$(dirname "$0")/.." && pwd)/lib/checks.sh"

# renders FILE to OUT/NAME.png and checks the exit code and that the picture is not flat.
check_scene() {
    local file=$1 name
    name=$(basename "$file")
    "$RENDER" "$file" -W 64 -H 48 -q -o "$OUT/$name.png" >"$OUT/$name.out" 2>"$OUT/$name.err"
    local rc=$?
    if [ "$rc" -ne 0 ]; then
        fail "$name exits $rc: $(head -c 600 "$OUT/$name.err")"
        return
    fi
    # png_tool prints: FILE W H CHANNELS MEAN STDDEV NONBLACK
    local stats stddev
    stats=$(python3 "$PNG_TOOL" "$OUT/$name.png") || { fail "$name: unreadable PNG"; return; }
    stddev=$(echo "$stats" | awk '{print $6}')
    if awk -v s="$stddev" 'BEGIN { exit !(s > 2.0) }'; then
        pass "$name renders (luminance spread $stddev)"
    else
        fail "$name renders a flat picture: $stats"
    fi
}

count=0
for scene in "$SCENES"/*.xml; do
    [ -e "$scene" ] || continue
    count=$((count + 1))
    check_scene "$scene"
done
[ "$count" -gt 0 ] && pass "$count XML scenes found" || fail "no XML scenes in $SCENES"
for model in "$SCENES"/*.obj; do
    [ -e "$model" ] && check_scene "$model"
done

# expect_scene_error NAME TEXT WHERE: a broken scene exits 2 and names FILE:LINE:COL.
expect_scene_error() {
    local name=$1 text=$2 where=$3
    printf '%s' "$text" >"$OUT/$name.xml"
    "$RENDER" "$OUT/$name.xml" -W 16 -H 16 -q -o "$OUT/$name.png" >"$OUT/$name.out" 2>"$OUT/$name.err"
    local rc=$?
    if [ "$rc" -ne 2 ]; then
        fail "$name exits $rc, expected 2: $(head -c 400 "$OUT/$name.err")"
    elif ! grep -qF "$OUT/$name.xml:$where: error:" "$OUT/$name.err"; then
        fail "$name: no '$name.xml:$where: error:' in: $(head -c 400 "$OUT/$name.err")"
    else
        pass "$name exits 2 naming $where"
    fi
}
expect_scene_error unknown_element $'<scene>\n  <sphere/>\n  <cube/>\n</scene>\n' "3:3"
expect_scene_error syntax $'<scene>\n  <sphere radius="1">\n</scene>\n' "3:3"
expect_scene_error bad_number $'<scene>\n  <sphere radius="one"/>\n</scene>\n' "2:19"

finish
