#!/usr/bin/env bash
# Regenerates docs/comparison.md: brute, rah and crsh compared on the three built-in scenes at
# 512x512 with render --compare (one process per scene, images checked identical), the reports
# kept in OUTDIR, the markdown printed on stdout; with SCREENSHOT, a headless-Chromium picture
# of the cornell report (posterized to stay small, tests/report/shrink_png.py).
# Brute force takes tens of seconds per scene (office is ~17G tests): this is not a test.
# Usage: make_performance.sh RENDER OUTDIR [SCREENSHOT.png] > docs/comparison.md
set -eu

RENDER=${1:?usage: make_performance.sh RENDER OUTDIR [SCREENSHOT.png]}
OUT=${2:?usage: make_performance.sh RENDER OUTDIR [SCREENSHOT.png]}
SHOT=${3:-}
HERE=$(cd "$(dirname "$0")" && pwd)
SCENES=(cornell office colonnade)
mkdir -p "$OUT"
OUT=$(cd "$OUT" && pwd)

for scene in "${SCENES[@]}"; do
    echo "render --compare brute,rah,crsh builtin:$scene -W 512 -H 512 ..." >&2
    "$RENDER" --compare brute,rah,crsh "builtin:$scene" -W 512 -H 512 -q \
        --report "$OUT/$scene" >"$OUT/$scene.txt"
done

if [ -n "$SHOT" ]; then
    browser=$(command -v chromium || command -v chromium-browser || true)
    if [ -z "$browser" ]; then
        echo "no chromium: no screenshot" >&2
    else
        mkdir -p "$(dirname "$SHOT")"
        timeout 60 "$browser" --headless --no-sandbox --disable-gpu --hide-scrollbars \
            --no-first-run --user-data-dir="$OUT/profile" --screenshot="$OUT/report-full.png" \
            --window-size=1000,1700 "file://$OUT/cornell/report.html" >/dev/null 2>&1
        python3 "$HERE/shrink_png.py" "$OUT/report-full.png" "$SHOT" 1 48 >&2
        echo "wrote $SHOT ($(wc -c <"$SHOT") bytes)" >&2
    fi
fi

python3 "$HERE/comparison_markdown.py" "$OUT" "${SCENES[@]}"
