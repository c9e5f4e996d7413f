#!/usr/bin/env bash
# End-to-end tests of the render command line tool: outputs, statistics, presets, exit codes,
# POV-Ray switches, --threads, -q and the progress bar.
# Usage: cli_test.sh PATH/TO/render OUTPUT_DIR
set -u

RENDER=${1:?usage: cli_test.sh RENDER OUTDIR}
OUT=${2:?usage: cli_test.sh RENDER OUTDIR}
rm -rf "$OUT"
mkdir -p "$OUT"

. "$(cd "$(dirname "$0")/.." && pwd)/lib/checks.sh"




S=(-W 32 -H 32)

# PNG output and the one line on success.
expect_rc png 0 builtin:cornell "${S[@]}" -o "$OUT/cornell.png"
if [ -s "$OUT/cornell.png" ] && head -c 8 "$OUT/cornell.png" | grep -q PNG; then
    pass "png written"
else
    fail "png not written"
fi
expect_in "$OUT/png.out" "wrote $OUT/cornell.png (32x32, scene " "success line"

# Without the image module (OpenImageIO, loaded at the first image that needs it), a scene is
# still checked and a PNG still written (through libpng), and writing an EXR fails with the
# reason and exit code 3.
SHEAF_IMAGE_MODULE=/nonexistent/libsheaf_image.so.0 expect_rc no_image_module_check 0 --check builtin:cornell
SHEAF_IMAGE_MODULE=/nonexistent/libsheaf_image.so.0 expect_rc no_image_module_png 0 builtin:cornell "${S[@]}" -o "$OUT/none.png"
SHEAF_IMAGE_MODULE=/nonexistent/libsheaf_image.so.0 expect_rc no_image_module 3 builtin:cornell "${S[@]}" -o "$OUT/none.exr"
expect_in "$OUT/no_image_module.err" "the image module libsheaf_image.so.0 was not found" "a missing image module is named"

# EXR output (magic number 76 2f 31 01).
expect_rc exr 0 builtin:cornell "${S[@]}" -o "$OUT/cornell.exr"
if [ "$(head -c 4 "$OUT/cornell.exr" 2>/dev/null | od -An -tx1 | tr -d ' \n')" = "762f3101" ]; then
    pass "exr written"
else
    fail "exr not written"
fi

# Statistics as a table and as JSON.
expect_rc stats 0 builtin:cornell "${S[@]}" -o "$OUT/stats.png" --stats
expect_in "$OUT/stats.out" "tests" "--stats prints a table with tests"
expect_rc stats_json 0 builtin:cornell "${S[@]}" -o "$OUT/json.png" --stats-json "$OUT/stats.json"
if [ -s "$OUT/stats.json" ]; then
    for key in rays.shadow tests.total tests.brute_force memory.peak_bytes time_ms.frame; do
        expect_in "$OUT/stats.json" "\"$key\"" "stats.json has $key"
    done
    if command -v python3 >/dev/null; then
        if python3 -c 'import json,sys; json.load(open(sys.argv[1]))' "$OUT/stats.json"; then
            pass "stats.json parses as JSON"
        else
            fail "stats.json does not parse as JSON"
        fi
    fi
else
    fail "stats.json not written"
fi

# Presets, and the default scene.
expect_rc preset_rah 0 builtin:cornell "${S[@]}" -o "$OUT/rah.png" --preset rah
expect_rc preset_crsh 0 builtin:cornell "${S[@]}" -o "$OUT/crsh.png" --preset crsh --set accel=brute
expect_rc default_scene 0 "${S[@]}" -o "$OUT/default.png"
expect_rc version 0 --version
expect_in "$OUT/version.out" "render (Sheaf) " "--version prints the version"
expect_rc list_settings 0 --list-settings
expect_in "$OUT/list_settings.out" "hierarchy.arity" "--list-settings lists hierarchy.arity"
expect_rc help 0 --help
expect_in "$OUT/help.out" "Examples" "--help has examples"

# Usage errors: exit 1, the message on stderr.
expect_rc bad_option 1 builtin:cornell "${S[@]}" --no-such-option
expect_in "$OUT/bad_option.err" "render: error: " "bad option: prefixed message"
expect_rc arity 1 builtin:cornell "${S[@]}" -o "$OUT/x.png" --set hierarchy.arity=1
expect_in "$OUT/arity.err" "hierarchy.arity" "arity: stderr names hierarchy.arity"
expect_in "$OUT/arity.err" "2..64" "arity: stderr names the range"
expect_rc hash_mode 1 builtin:cornell "${S[@]}" -o "$OUT/x.png" --set hash.mode=bogus
expect_in "$OUT/hash_mode.err" "none, crsh, hash32, hash192" "hash.mode: stderr lists the choices"
expect_rc nokey 1 builtin:cornell "${S[@]}" -o "$OUT/x.png" --set nokey=1
expect_in "$OUT/nokey.err" "nokey" "nokey: stderr names the key"
expect_rc noequals 1 builtin:cornell "${S[@]}" -o "$OUT/x.png" --set noequals
expect_in "$OUT/noequals.err" "noequals" "noequals: stderr names the argument"
expect_rc no_preset 1 builtin:cornell "${S[@]}" -o "$OUT/x.png" --preset nosuch
expect_in "$OUT/no_preset.err" "nosuch" "no preset: stderr names it"
expect_rc zero_width 1 builtin:cornell -W 0 -H 32 -o "$OUT/x.png"
if [ -e "$OUT/x.png" ]; then
    fail "a failed run wrote an image"
else
    pass "failed runs write no image"
fi

# Scene errors: exit 2.
expect_rc missing_scene 2 "$OUT/no/such/scene.pov" "${S[@]}" -o "$OUT/y.png"
expect_in "$OUT/missing_scene.err" "render: error: " "missing scene: prefixed message"
expect_rc builtin_nosuch 2 builtin:nosuch "${S[@]}" -o "$OUT/y.png"
expect_in "$OUT/builtin_nosuch.err" "nosuch" "builtin:nosuch: stderr names it"

# Render and image errors: exit 3.
expect_rc bad_ext 3 builtin:cornell "${S[@]}" -o "$OUT/out.bogusext"
expect_in "$OUT/bad_ext.err" "out.bogusext" "bad extension: stderr names the file"
# A frame larger than the machine's memory (about 1 TB): refused at once, with the numbers.
expect_rc too_large 3 builtin:cornell -q -W 16384 -H 16384 --set aa.samples=8 --set backend=cpu -o "$OUT/big.png"
expect_in "$OUT/too_large.err" "samples per pixel needs at least" "too large a frame: stderr says what it needs"


# POV-Ray scene files: render, --check, --strict, include paths, a syntax error.
mkdir -p "$OUT/inc"
echo '#declare Col = rgb <0.9, 0.3, 0.2>;' >"$OUT/inc/cli_colors.inc"
cat >"$OUT/scene.pov" <<'POV'
#include "cli_colors.inc"
camera { location <0, 1, -4> look_at 0 }
light_source { <2, 4, -3> rgb 1 }
sphere { 0, 1 pigment { Col } }
plane { y, -1 pigment { rgb 1 } }
global_settings { subsurface { } }
POV
expect_rc pov_file 0 "$OUT/scene.pov" --include-path "$OUT/inc" "${S[@]}" -o "$OUT/scene.png"
expect_in "$OUT/pov_file.err" "scene.pov:6:" "a POV scene's warning names file and line"
expect_in "$OUT/pov_file.err" "warning: unsupported" "the warning says unsupported"
expect_rc pov_plus_l 0 "$OUT/scene.pov" "+L$OUT/inc" "${S[@]}" -o "$OUT/scene.png"
expect_rc pov_no_include 2 "$OUT/scene.pov" "${S[@]}" -o "$OUT/scene.png"
expect_in "$OUT/pov_no_include.err" "cli_colors.inc" "a missing include is named"
expect_rc check 0 --check "$OUT/scene.pov" --include-path "$OUT/inc"
expect_in "$OUT/check.out" "usable, 1 warning" "--check: the verdict with the warning count"
expect_in "$OUT/check.out" "limits used: parse_steps " "--check: what the scene used of the reader's limits"
expect_in "$OUT/check.out" "objects 3 of 200000 (" "--check: the objects parsed of the limit"
expect_rc check_limit 2 --check --limit objects=2 "$OUT/scene.pov" --include-path "$OUT/inc"
expect_in "$OUT/check_limit.err" "scene.pov:5:1: error: more than 2 objects parsed" "--limit: a scene past it fails where it went past"
expect_in "$OUT/check_limit.err" "render --limit objects=N" "--limit: the error says how to raise it"
expect_rc check_limit_raised 0 --check --limit objects=3 --limit parse_steps=1000 "$OUT/scene.pov" --include-path "$OUT/inc"
expect_in "$OUT/check_limit_raised.out" "objects 3 of 3 (" "--limit: the limit set is the one reported"
expect_rc bad_limit_name 1 --check --limit tokens=5 "$OUT/scene.pov"
expect_in "$OUT/bad_limit_name.err" "--limit tokens=5: unknown load option 'limit.tokens'" "--limit: an unknown limit is named"
expect_rc bad_limit_value 1 --check --limit objects "$OUT/scene.pov"
expect_in "$OUT/bad_limit_value.err" "expected NAME=N" "--limit: the form is shown"
expect_rc check_strict 2 --check --strict "$OUT/scene.pov" --include-path "$OUT/inc"
expect_in "$OUT/check_strict.err" "error: unsupported" "--strict: the unsupported feature is an error"
printf 'sphere { <0, 0, 0>, 1\n  pigment { rgb <1, 0, 0> }\n  translate <1, 2\n}\n' >"$OUT/bad.pov"
expect_rc pov_syntax 2 "$OUT/bad.pov" "${S[@]}" -o "$OUT/bad.png"
expect_in "$OUT/pov_syntax.err" "bad.pov:4:1: error: found '}'" "a syntax error: file, line, column, token"
expect_rc pov_unknown_ext 2 "$OUT/inc" "${S[@]}" -o "$OUT/bad.png"
echo 'x' >"$OUT/scene.txt"
expect_rc pov_txt 2 "$OUT/scene.txt" "${S[@]}" -o "$OUT/bad.png"
expect_in "$OUT/pov_txt.err" "no reader for '.txt'" "an unknown extension is named"

# json_value FILE KEY: a number from a flat stats JSON file.
json_value() { sed -n "s/^ *\"$2\": *\([0-9.e+-]*\).*/\1/p" "$1"; }

# POV-Ray switches: +W +H +O, +I, +A/-A (aa.samples 3 and 1), +L, -D/+D.
expect_rc pov_size 0 builtin:cornell +W32 +H24 "+O$OUT/pov.png"
expect_in "$OUT/pov_size.out" "wrote $OUT/pov.png (32x24, " "+W +H +O: size and file"
expect_rc pov_input 0 +Ibuiltin:cornell -W 16 -H 16 -o "$OUT/pov_in.png" \
    --stats-json "$OUT/pov_in.json"
expect_in "$OUT/pov_in.json" '"scene.primitives": 790' "+I: the cornell scene"
expect_rc pov_aa 0 builtin:cornell -W 16 -H 16 +A -o "$OUT/aa.png" --stats-json "$OUT/aa.json"
[ "$(json_value "$OUT/aa.json" frame.samples_per_pixel)" = 9 ] && pass "+A: 3x3 samples" ||
    fail "+A: samples per pixel $(json_value "$OUT/aa.json" frame.samples_per_pixel), expected 9"
expect_rc pov_aa_threshold 0 builtin:cornell -W 16 -H 16 +A0.3 -o "$OUT/aa.png" \
    --stats-json "$OUT/aa3.json"
[ "$(json_value "$OUT/aa3.json" frame.samples_per_pixel)" = 9 ] && pass "+A0.3: 3x3 samples" ||
    fail "+A0.3: samples per pixel $(json_value "$OUT/aa3.json" frame.samples_per_pixel)"
expect_rc pov_aa_off 0 builtin:cornell -W 16 -H 16 +A -A -o "$OUT/aa.png" \
    --stats-json "$OUT/aa0.json"
[ "$(json_value "$OUT/aa0.json" frame.samples_per_pixel)" = 1 ] && pass "+A -A: one sample" ||
    fail "+A -A: samples per pixel $(json_value "$OUT/aa0.json" frame.samples_per_pixel)"
expect_rc pov_include 0 builtin:cornell "${S[@]}" +L/usr/share -D +D -o "$OUT/l.png"
expect_rc pov_unknown 1 builtin:cornell "${S[@]}" +Q9 -o "$OUT/q.png"
expect_in "$OUT/pov_unknown.err" "+Q9" "unknown POV-Ray switch: stderr names it"
expect_rc pov_bad_width 1 builtin:cornell +Wide -o "$OUT/q.png"
expect_in "$OUT/pov_bad_width.err" "+Wide" "+W without a number: stderr names it"
expect_rc pov_two_scenes 1 builtin:cornell +Ibuiltin:office "${S[@]}"

# POV-Ray animation: +KFI +KFF +KI +KF +KC +SF +EF +K, numbered images, .ini files, Declare=.
mkdir -p "$OUT/anim"
cat >"$OUT/anim/clock.pov" <<'POV'
camera { location <0, 1, -9> look_at 0 }
light_source { <3, 5, -4> rgb 1 }
#ifndef (Extra) #declare Extra = 0; #end
#for (I, 1, frame_number + Extra) sphere { <I - 3, 0, 0>, 0.4 pigment { rgb 1 } } #end
#if (clock > 0.5) box { -2, -1.5 pigment { rgb 1 } } #end
POV
A=(-W 8 -H 8)
expect_rc anim 0 "$OUT/anim/clock.pov" "${A[@]}" +KFI1 +KFF10 "+O$OUT/anim/f.png" \
    --stats-json "$OUT/anim/f.json"
expect_in "$OUT/anim.out" "wrote $OUT/anim/f01.png" "a sequence numbers its images to the last frame's digits"
expect_in "$OUT/anim.out" "wrote $OUT/anim/f10.png" "the last frame is written"
# Frame 6 of 1..10 has clock 5/9 > 0.5: six spheres and the box; frame 5 (4/9) only spheres.
[ "$(json_value "$OUT/anim/f06.json" scene.primitives)" = 7 ] && pass "frame 6: clock 5/9" ||
    fail "frame 6: $(json_value "$OUT/anim/f06.json" scene.primitives) primitives, expected 7"
[ "$(json_value "$OUT/anim/f05.json" scene.primitives)" = 5 ] && pass "frame 5: clock 4/9" ||
    fail "frame 5: $(json_value "$OUT/anim/f05.json" scene.primitives) primitives, expected 5"
expect_rc anim_subset 0 "$OUT/anim/clock.pov" "${A[@]}" +KFI1 +KFF4 +SF2 +EF3 +KI0 +KF2 +KC \
    -o "$OUT/anim/s.png" --stats-json "$OUT/anim/s.json"
[ -f "$OUT/anim/s2.png" ] && [ -f "$OUT/anim/s3.png" ] && [ ! -f "$OUT/anim/s1.png" ] &&
    [ ! -f "$OUT/anim/s4.png" ] && pass "+SF +EF: only frames 2 and 3" || fail "+SF +EF: $(ls "$OUT/anim")"
[ "$(json_value "$OUT/anim/s3.json" scene.primitives)" = 4 ] && pass "+KC +KF2: frame 3 has clock 1" ||
    fail "+KC: $(json_value "$OUT/anim/s3.json" scene.primitives) primitives, expected 4"
expect_rc anim_still 0 "$OUT/anim/clock.pov" "${A[@]}" +K0.9 -o "$OUT/anim/k.png" \
    --stats-json "$OUT/anim/k.json"
[ "$(json_value "$OUT/anim/k.json" scene.primitives)" = 1 ] && pass "+K0.9: a still with its clock" ||
    fail "+K0.9: $(json_value "$OUT/anim/k.json" scene.primitives) primitives, expected 1"
expect_rc anim_backwards 1 "$OUT/anim/clock.pov" "${A[@]}" +KFI5 +KFF2 -o "$OUT/anim/b.png"
expect_in "$OUT/anim_backwards.err" "--final-frame 2 is below --initial-frame 5" "a backwards sequence is refused"
expect_rc anim_bad_switch 1 "$OUT/anim/clock.pov" "${A[@]}" +KFIx -o "$OUT/anim/b.png"
expect_in "$OUT/anim_bad_switch.err" "+KFIx" "a bad +KFI names itself"
expect_rc anim_compare 1 --compare crsh,brute "$OUT/anim/clock.pov" "${A[@]}" +KFF3
expect_in "$OUT/anim_compare.err" "--compare renders one frame" "--compare refuses a sequence"
# An .ini in place of the scene: its scene (found beside it), size, frames, Declare, image name.
cat >"$OUT/anim/clock.ini" <<'INI'
; a POV-Ray ini file
Input_File_Name=clock.pov
Width=12
+h10
Antialias=Off
Initial_Frame=1
Final_Frame=3
Declare=Extra=2
Pause_When_Done=off   ; accepted, nothing to do
Jitter=On
INI
(cd "$OUT" && "$RENDER" anim/clock.ini --stats-json anim/i.json >ini.out 2>ini.err)
rc=$?
[ "$rc" -eq 0 ] && pass "an .ini renders" || fail "an .ini: exit $rc: $(cat "$OUT/ini.err")"
expect_in "$OUT/ini.out" "wrote clock1.png (12x10," "the .ini's size, frames and image name"
[ "$(json_value "$OUT/anim/i3.json" scene.primitives)" = 6 ] && pass "Declare=Extra=2 in the .ini" ||
    fail "Declare in the .ini: $(json_value "$OUT/anim/i3.json" scene.primitives) primitives, expected 6"
rm -f "$OUT"/clock?.png
expect_rc ini_override 0 "$OUT/anim/clock.ini" -o "$OUT/anim/o.png" Final_Frame=1 Width=8
expect_in "$OUT/ini_override.out" "wrote $OUT/anim/o.png (8x10," "-o and Key=Value after the .ini win"
expect_rc ini_check 0 --check "$OUT/anim/clock.ini"
expect_in "$OUT/ini_check.out" "(frame 3): usable" "--check reads every frame of the .ini"
printf 'Width=wide\n' >"$OUT/anim/bad.ini"
expect_rc ini_bad 1 "$OUT/anim/bad.ini"
expect_in "$OUT/ini_bad.err" "bad.ini:1: Width=wide: expected a whole number" "a bad .ini line: file, line, value"
expect_rc ini_missing 1 "$OUT/anim/none.ini"
expect_in "$OUT/ini_missing.err" "cannot read the .ini file" "a missing .ini is named"

# --threads, -q, and no progress bar when stderr is not a terminal.
expect_rc threads 0 builtin:cornell "${S[@]}" --threads 1 -o "$OUT/t.png"
expect_rc threads_bad 1 builtin:cornell "${S[@]}" --threads -1 -o "$OUT/t.png"
expect_in "$OUT/threads_bad.err" "threads" "--threads -1: stderr names threads"
expect_rc quiet 0 builtin:cornell "${S[@]}" -q -o "$OUT/quiet.png"
if [ -s "$OUT/quiet.out" ] || [ -s "$OUT/quiet.err" ] || [ ! -s "$OUT/quiet.png" ]; then
    fail "-q: output printed or no image"
else
    pass "-q: silent, image written"
fi
# Off a terminal stderr carries the one backend line and nothing else (no progress bar).
if grep -v -q '^backend: ' "$OUT/png.err"; then
    fail "progress drawn when stderr is not a terminal"
elif [ "$(grep -c '^backend: ' "$OUT/png.err")" != 1 ]; then
    fail "one backend line on stderr"
else
    pass "no progress off a terminal, one backend line"
fi
# Parts of a frame: --tile I/N and +SR/+ER/+SC/+EC render a part; --merge puts OpenEXR parts
# (output.exr=float) back together, equal to the whole frame pixel for pixel (idiff).
mkdir -p "$OUT/tiles"
T=(builtin:office -W 40 -H 30 +A --set output.exr=float -q)
expect_rc tile_whole 0 "${T[@]}" -o "$OUT/tiles/whole.exr"
expect_rc tile_whole_png 0 "${T[@]}" -o "$OUT/tiles/whole.png"
tiles_ok=1
for i in 1 2 3 4 5 6 7 8 9; do
    "$RENDER" "${T[@]}" --tile "$i/9" -o "$OUT/tiles/t$i.exr" >/dev/null 2>&1 || tiles_ok=0
done
[ $tiles_ok = 1 ] && pass "--tile 1/9 ... 9/9" || fail "--tile: a tile failed"
expect_rc tile_merge 0 --merge "$OUT"/tiles/t*.exr -o "$OUT/tiles/merged.png"
expect_in "$OUT/tile_merge.out" "(40x30, 9 parts)" "--merge writes the whole frame"
expect_rc tile_merge_exr 0 --merge "$OUT"/tiles/t*.exr -o "$OUT/tiles/merged.exr"
if command -v idiff >/dev/null; then
    idiff -a "$OUT/tiles/whole.png" "$OUT/tiles/merged.png" >"$OUT/tiles/idiff_png.out" 2>&1 &&
        pass "9 tiles merged equal the whole frame (PNG)" ||
        fail "9 tiles merged differ: $(tail -3 "$OUT/tiles/idiff_png.out")"
    idiff -a "$OUT/tiles/whole.exr" "$OUT/tiles/merged.exr" >"$OUT/tiles/idiff_exr.out" 2>&1 &&
        pass "9 tiles merged equal the whole frame (every pass of the EXR)" ||
        fail "9 tiles merged differ (EXR): $(tail -3 "$OUT/tiles/idiff_exr.out")"
fi
# POV-Ray's rows and columns: fractions and pixel numbers (from 1, the end included).
expect_rc rows_top 0 "${T[@]}" +SR0.0 +ER0.5 -o "$OUT/tiles/top.exr"
expect_rc rows_bottom 0 "${T[@]}" +SR16 +ER30 +SC1 +EC1.0 -o "$OUT/tiles/bottom.exr"
expect_rc rows_merge 0 --merge "$OUT/tiles/bottom.exr" "$OUT/tiles/top.exr" -o "$OUT/tiles/rows.exr"
if command -v idiff >/dev/null; then
    idiff -a "$OUT/tiles/whole.exr" "$OUT/tiles/rows.exr" >/dev/null 2>&1 &&
        pass "+SR0.0 +ER0.5 and +SR16 +ER30 make the whole frame" ||
        fail "+SR/+ER halves differ from the whole frame"
fi
expect_rc rows_png 0 builtin:office -W 40 -H 30 +SR0.5 -o "$OUT/tiles/half.png"
expect_in "$OUT/rows_png.out" "wrote $OUT/tiles/half.png (40x15" "+SR0.5: the image holds the lower half"
# As povray 3.7 reads them on an 8x8 image: +SR0.3 +ER0.6 rows 3-4 (from 1), +SR2 +ER3 rows
# 2-3, +SR1 +ER1 every row, +SR0.9 the last row.
for case in "+SR0.3 +ER0.6:8x2" "+SR2 +ER3:8x2" "+SR1 +ER1:8x8" "+SR0.9:8x1" "+SC0.1 +EC0.3:2x8"; do
    args=${case%%:*}
    # shellcheck disable=SC2086
    "$RENDER" builtin:cornell -W 8 -H 8 $args -o "$OUT/tiles/pov.png" >"$OUT/pov_rows.out" 2>&1
    expect_in "$OUT/pov_rows.out" "(${case##*:}," "$args on 8x8 is ${case##*:}, as POV-Ray's"
done
expect_rc rows_empty 1 "${T[@]}" +SR20 +ER10 -o "$OUT/tiles/x.exr"
expect_in "$OUT/rows_empty.err" "the rows 20 to 10 (+SR +ER) leave nothing of the image" "+SR after +ER is refused"
expect_rc rows_past 1 "${T[@]}" +EC41 -o "$OUT/tiles/x.exr"
expect_in "$OUT/rows_past.err" "past the image's 40 columns" "+EC past the image is refused"
expect_rc rows_bad 1 "${T[@]}" +SRx -o "$OUT/tiles/x.exr"
expect_in "$OUT/rows_bad.err" "+SRx" "a malformed +SR names itself"
expect_rc tile_bad 1 "${T[@]}" --tile 10/9 -o "$OUT/tiles/x.exr"
expect_in "$OUT/tile_bad.err" "there are 9 tiles" "--tile past N is refused"
expect_rc tile_and_rows 1 "${T[@]}" --tile 1/4 +SR0.5 -o "$OUT/tiles/x.exr"
expect_in "$OUT/tile_and_rows.err" "give one" "--tile with +SR is refused"
expect_rc merge_missing 3 --merge "$OUT"/tiles/t[1-8].exr -o "$OUT/tiles/hole.png"
expect_in "$OUT/merge_missing.err" "uncovered" "a missing tile is named by its pixels"
expect_rc merge_png 3 --merge "$OUT/tiles/whole.png" -o "$OUT/tiles/x.png"
expect_in "$OUT/merge_png.err" "32-bit floats" "an 8-bit part is refused"
expect_rc merge_no_output 1 --merge "$OUT/tiles/t1.exr"
expect_in "$OUT/merge_no_output.err" "--merge needs -o" "--merge without -o is refused"
# --frame-step: every Nth frame of the subset, for interleaving machines.
expect_rc frame_step 0 "$OUT/anim/clock.pov" "${A[@]}" +KFI1 +KFF10 +SF2 --frame-step 4 \
    -o "$OUT/anim/step.png"
[ -f "$OUT/anim/step02.png" ] && [ -f "$OUT/anim/step06.png" ] && [ -f "$OUT/anim/step10.png" ] &&
    [ ! -f "$OUT/anim/step03.png" ] && [ "$(ls "$OUT"/anim/step*.png | wc -l)" = 3 ] &&
    pass "+SF2 --frame-step 4: frames 2, 6 and 10" || fail "--frame-step: $(ls "$OUT/anim")"

# On a terminal (script(1) gives a pseudo-terminal): the bar with the time left.
if command -v script >/dev/null; then
    script -qec "'$RENDER' builtin:cornell -W 32 -H 32 -o '$OUT/tty.png'" /dev/null \
        >"$OUT/tty.out" 2>&1
    expect_in "$OUT/tty.out" "left" "progress bar on a terminal shows the time left"
    expect_in "$OUT/tty.out" "100%" "progress bar reaches 100%"
    script -qec "'$RENDER' builtin:cornell -W 32 -H 32 -q -o '$OUT/tty.png'" /dev/null \
        >"$OUT/ttyq.out" 2>&1
    if grep -q "left" "$OUT/ttyq.out"; then
        fail "-q still draws the progress bar"
    else
        pass "-q: no progress bar"
    fi
fi
for text in "--compare" "--sweep" "+A0.3" "+L" "--threads" "-q"; do
    expect_in "$OUT/help.out" "$text" "--help mentions $text"
done

finish
