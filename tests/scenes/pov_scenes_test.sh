#!/usr/bin/env bash
# Renders every scenes/*.pov at a small size through the render CLI: each must exit 0 and give
# a picture that is not one flat colour. The sample scenes must load with no unsupported-feature
# warning (--strict); the built-in scenes as .pov files (cornell, office, colonnade) may warn,
# but must have the built-in scene's primitives and objects (--stats-json) and nearly its image.
# Usage: pov_scenes_test.sh PATH/TO/render SCENES_DIR OUTPUT_DIR PNG_TOOL
set -u

RENDER=${1:?usage: pov_scenes_test.sh RENDER SCENES_DIR OUTDIR PNG_TOOL}
SCENES=${2:?usage: pov_scenes_test.sh RENDER SCENES_DIR OUTDIR PNG_TOOL}
OUT=${3:?usage: pov_scenes_test.sh RENDER SCENES_DIR OUTDIR PNG_TOOL}
PNG_TOOL=${4:?usage: pov_scenes_test.sh RENDER SCENES_DIR OUTDIR PNG_TOOL}
rm -rf "$OUT"
mkdir -p "$OUT"

W=96
H=72
BUILTINS="cornell office colonnade"
# Sample scenes that show a feature Sheaf approximates (radiosity.pov: radiosity gathered at
# every pixel): they render without --strict, and every warning must name an approximation.
APPROXIMATE="radiosity"

. "$(cd "$(dirname "$0")/.." && pwd)/lib/checks.sh"

is_builtin() {
    case " $BUILTINS " in *" $1 "*) return 0 ;; esac
    return 1
}

is_approximate() {
    case " $APPROXIMATE " in *" $1 "*) return 0 ;; esac
    return 1
}

# json_value FILE KEY: a value of the flat --stats-json object.
json_value() {
    python3 -c 'import json, sys; print(json.load(open(sys.argv[1]))[sys.argv[2]])' "$1" "$2"
}

# mean_difference A.png B.png: the mean absolute difference of the RGB channels, 0..255.
mean_difference() {
    python3 - "$PNG_TOOL" "$1" "$2" <<'EOF'
import importlib.util, sys
spec = importlib.util.spec_from_file_location("png_tool", sys.argv[1])
png = importlib.util.module_from_spec(spec)
spec.loader.exec_module(png)
(wa, ha, ca, ra), (wb, hb, cb, rb) = png.decode(sys.argv[2]), png.decode(sys.argv[3])
if (wa, ha) != (wb, hb):
    print("inf")
    sys.exit()
total = 0
for la, lb in zip(ra, rb):
    for x in range(wa):
        for c in range(3):
            total += abs(la[x * ca + c] - lb[x * cb + c])
print(total / (wa * ha * 3))
EOF
}

# check_scene FILE: renders FILE to OUT/NAME.png (with its statistics in OUT/NAME.json) and
# checks the exit code, warnings and that the picture is not flat.
check_scene() {
    local file=$1 name strict=--strict
    name=$(basename "$file" .pov)
    is_builtin "$name" && strict=
    is_approximate "$name" && strict=
    # From the scene's own folder, as a user would render it; its includes are found there.
    (cd "$(dirname "$file")" &&
        "$RENDER" "$(basename "$file")" -W $W -H $H -q $strict -o "$OUT/$name.png" \
            --stats-json "$OUT/$name.json" >"$OUT/$name.out" 2>"$OUT/$name.err")
    local rc=$?
    if [ "$rc" -ne 0 ]; then
        fail "$name.pov exits $rc: $(head -c 600 "$OUT/$name.err")"
        return
    fi
    if [ -n "$strict" ] && grep -q "warning:" "$OUT/$name.err"; then
        fail "$name.pov warns: $(grep -m 3 "warning:" "$OUT/$name.err")"
        return
    fi
    if is_approximate "$name" && grep "warning:" "$OUT/$name.err" | grep -qv "warning: approximated "; then
        fail "$name.pov warns of more than approximations: $(grep -m 3 "warning:" "$OUT/$name.err")"
        return
    fi
    # png_tool prints: FILE W H CHANNELS MEAN STDDEV NONBLACK
    local stats stddev
    stats=$(python3 "$PNG_TOOL" "$OUT/$name.png") || { fail "$name.pov: unreadable PNG"; return; }
    stddev=$(echo "$stats" | awk '{print $6}')
    if awk -v s="$stddev" 'BEGIN { exit !(s > 2.0) }'; then
        pass "$name.pov renders${strict:+ with no warning} (luminance spread $stddev)"
    else
        fail "$name.pov renders a flat picture: $stats"
    fi
}

# check_builtin NAME: scenes/NAME.pov against builtin:NAME, both rendered at the same size.
check_builtin() {
    local name=$1
    [ -e "$OUT/$name.json" ] || { fail "$name.pov was not rendered"; return; }
    "$RENDER" "builtin:$name" -W $W -H $H -q -o "$OUT/builtin_$name.png" \
        --stats-json "$OUT/builtin_$name.json" >"$OUT/builtin_$name.out" 2>&1 ||
        { fail "builtin:$name does not render"; return; }
    local key a b
    for key in scene.primitives scene.objects scene.lights; do
        a=$(json_value "$OUT/builtin_$name.json" $key)
        b=$(json_value "$OUT/$name.json" $key)
        if [ "$a" = "$b" ]; then
            pass "$name.pov has the $key of builtin:$name ($b)"
        else
            fail "$name.pov has $key $b, builtin:$name $a"
        fi
    done
    local diff
    diff=$(mean_difference "$OUT/builtin_$name.png" "$OUT/$name.png")
    if awk -v d="$diff" 'BEGIN { exit !(d < 0.1) }'; then
        pass "$name.pov looks like builtin:$name (mean difference $diff of 255)"
    else
        fail "$name.pov differs from builtin:$name by $diff of 255 on average"
    fi
}

count=0
samples=0
for scene in "$SCENES"/*.pov; do
    [ -e "$scene" ] || continue
    count=$((count + 1))
    is_builtin "$(basename "$scene" .pov)" || samples=$((samples + 1))
    check_scene "$scene"
done
[ "$count" -gt 0 ] && pass "$count POV scenes found" || fail "no POV scenes in $SCENES"
[ "$samples" -ge 6 ] && pass "$samples sample scenes besides the built-ins" ||
    fail "only $samples sample scenes besides the built-ins (6 or more expected)"
for name in $BUILTINS; do
    if [ -e "$SCENES/$name.pov" ]; then
        check_builtin "$name"
    else
        fail "no $name.pov in $SCENES"
    fi
done

finish
