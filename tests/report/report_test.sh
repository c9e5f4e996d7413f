#!/usr/bin/env bash
# End-to-end tests of render --compare and --sweep: the tables, the exit codes, the report
# directory (report.html self-contained, images, results.json and results.csv), the presets of
# the papers, and the errors for unknown presets and keys. Small renders (cornell, 64x64).
# Usage: report_test.sh PATH/TO/render OUTPUT_DIR
set -u

RENDER=${1:?usage: report_test.sh RENDER OUTDIR}
OUT=${2:?usage: report_test.sh RENDER OUTDIR}
HERE=$(cd "$(dirname "$0")" && pwd)
rm -rf "$OUT"
mkdir -p "$OUT"

. "$(cd "$(dirname "$0")/.." && pwd)/lib/checks.sh"




# png_field FILE N: field N of png_tool.py's line (4 channels, 5 mean, 6 stddev, 7 non-black).
png_field() { python3 "$HERE/png_tool.py" "$1" | awk -v n="$2" '{print $n}'; }
is_zero() { awk -v v="$1" 'BEGIN { exit !(v == 0) }'; }
is_above() { awk -v v="$1" -v t="$2" 'BEGIN { exit !(v > t) }'; }

S=(builtin:cornell -W 64 -H 64 -q)

# --- Comparison: tables, identical images, the report. ---
CMP="$OUT/cmp"
expect_rc compare 0 --compare crsh,rah,brute "${S[@]}" --report "$CMP"
for text in "Intersection tests: shadow" "Intersection tests: reflection" "level 2" "level 1" \
    "final" "brute force" "share" "Totals" "vs crsh" "Time per phase" "traversal" \
    "images: all 3 identical to crsh's"; do
    expect_in "$OUT/compare.out" "$text" "compare prints '$text'"
done
if grep -q "wrote" "$OUT/compare.out"; then
    fail "-q still prints 'wrote'"
else
    pass "-q: no 'wrote' line"
fi
if [ -s "$OUT/compare.err" ]; then
    fail "compare wrote to stderr: $(cat "$OUT/compare.err")"
else
    pass "compare: stderr empty"
fi
check "compare results.json and results.csv" \
    python3 "$HERE/results_check.py" "$CMP" compare crsh rah brute
check "compare report.html is self-contained" python3 "$HERE/html_check.py" "$CMP/report.html" 8 3
for text in "crsh" "rah" "brute" "tests per pixel" "difference from crsh" "Time per phase" \
    "Settings" "hierarchy.arity" "accel" "identical"; do
    expect_in "$CMP/report.html" "$text" "report.html has '$text'"
done
for name in 0-crsh 1-rah 2-brute; do
    img="$CMP/images/$name.png"
    if [ -s "$img" ] && is_above "$(png_field "$img" 6)" 5; then
        pass "$name.png is an image"
    else
        fail "$name.png missing or flat"
    fi
    heat="$CMP/images/$name-tests.png"
    if [ -s "$heat" ] && is_above "$(png_field "$heat" 6)" 1; then
        pass "$name heat map varies"
    else
        fail "$name heat map missing or flat"
    fi
done
for name in 1-rah 2-brute; do
    diff="$CMP/images/$name-difference.png"
    if [ -s "$diff" ] && is_zero "$(png_field "$diff" 7)"; then
        pass "$name difference image is black"
    else
        fail "$name difference image missing or not black"
    fi
done
# The rendered images decode to the same pixels (the files differ in their metadata).
check "crsh and brute PNGs have the same pixels" \
    python3 "$HERE/png_tool.py" --same "$CMP/images/0-crsh.png" "$CMP/images/2-brute.png"

# --- Differing images: exit 3, the pixels named, the report still written. ---
cat >"$OUT/ao4.xml" <<'XML'
<?xml version="1.0"?>
<preset name="ao4" description="crsh with ambient occlusion: a different image on purpose.">
  <set key="ao.samples" value="4"/>
</preset>
XML
DIFF="$OUT/diff"
expect_rc differ 3 --compare crsh,"$OUT/ao4.xml" "${S[@]}" --report "$DIFF"
expect_in "$OUT/differ.err" "images differ" "differ: stderr says images differ"
expect_in "$OUT/differ.err" "pixels differ from crsh" "differ: stderr counts the pixels"
expect_in "$OUT/differ.err" "max difference" "differ: stderr gives the max difference"
expect_in "$OUT/differ.err" ") (" "differ: stderr gives coordinates"
expect_in "$DIFF/report.html" "Images differ" "differ: the report says so"
d="$DIFF/images/1-ao4-difference.png"
if [ -s "$d" ] && is_above "$(png_field "$d" 7)" 0; then
    pass "differ: the difference image shows the pixels"
else
    fail "differ: difference image black or missing"
fi

# --- Errors: unknown preset, conflicting options. ---
expect_rc unknown_preset 1 --compare crsh,nosuchpreset "${S[@]}" --report "$OUT/none"
expect_in "$OUT/unknown_preset.err" "nosuchpreset" "unknown preset: stderr names it"
if [ -e "$OUT/none" ]; then
    fail "a failed comparison wrote a report"
else
    pass "a failed comparison writes no report"
fi
expect_rc compare_output 1 --compare crsh,rah "${S[@]}" -o "$OUT/x.png"
expect_rc compare_preset 1 --compare crsh,rah --preset rah "${S[@]}"
expect_rc report_alone 1 "${S[@]}" --report "$OUT/alone"
expect_in "$OUT/report_alone.err" "--report" "--report alone: stderr names it"
expect_rc compare_scene 2 --compare crsh,rah builtin:nosuchscene -W 8 -H 8

# --- The papers' presets: every one loads; the exact ones agree with each other. ---
EXACT=crsh,rah,brute,crsh-d1-a8,crsh-d3-a8,crsh-d4-a8,crsh-d2-a2,crsh-d2-a4,crsh-d2-a16
expect_rc presets_exact 0 --compare "$EXACT" \
    builtin:cornell -W 24 -H 24 -q
expect_rc presets_ao 0 --compare ao-hash32-full,ao-hash192-full,ao-hash32-csd \
    builtin:cornell -W 24 -H 24 -q
expect_in "$OUT/presets_ao.out" "Intersection tests: ao" "ao presets trace AO rays"
expect_in "$OUT/presets_ao.out" "images: all 3 identical" "ao presets agree"

# --- Sweep: the grid, the best, the report. ---
SW="$OUT/sweep"
expect_rc sweep 0 --sweep hierarchy.depth=1..2 hierarchy.arity=4,8 "${S[@]}" --report "$SW"
expect_in "$OUT/sweep.out" "Sweep (4 settings)" "sweep prints the grid"
expect_in "$OUT/sweep.out" "fewest tests: hierarchy.depth=" "sweep names the fewest tests"
expect_in "$OUT/sweep.out" "fastest frame: hierarchy.depth=" "sweep names the fastest"
check "sweep results.json and results.csv" python3 "$HERE/results_check.py" "$SW" sweep \
    "hierarchy.depth=1 hierarchy.arity=4" "hierarchy.depth=1 hierarchy.arity=8" \
    "hierarchy.depth=2 hierarchy.arity=4" "hierarchy.depth=2 hierarchy.arity=8"
check "sweep report.html is self-contained" python3 "$HERE/html_check.py" "$SW/report.html" 0 2
expect_in "$SW/report.html" "<polyline" "sweep report has line charts"
expect_in "$SW/report.html" "Fewest tests: hierarchy.depth=" "sweep report names the best"
# One axis, a comma list of choices, --sweep=KEY=VALUES, and the preset as the base.
expect_rc sweep_accel 0 --preset rah --sweep=accel=brute,rah,crsh builtin:cornell -W 16 -H 16 -q
expect_in "$OUT/sweep_accel.out" "Sweep (3 settings)" "sweep over accel"

expect_rc sweep_nokey 1 --sweep nosuchkey=1..3 "${S[@]}"
expect_in "$OUT/sweep_nokey.err" "nosuchkey" "sweep unknown key: stderr names it"
expect_rc sweep_badvalue 1 --sweep hierarchy.arity=1..3 "${S[@]}"
expect_in "$OUT/sweep_badvalue.err" "hierarchy.arity" "sweep bad value: stderr names the key"
expect_rc sweep_badrange 1 --sweep hierarchy.depth=3..1 "${S[@]}"
expect_in "$OUT/sweep_badrange.err" "3..1" "sweep empty range: stderr names it"
expect_rc sweep_twice 1 --sweep hierarchy.depth=1,2 hierarchy.depth=3 "${S[@]}"
expect_in "$OUT/sweep_twice.err" "twice" "sweep repeated key: stderr says so"
expect_rc sweep_empty 1 "${S[@]}" --sweep

finish
