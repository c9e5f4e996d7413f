#!/usr/bin/env bash
# The comparison report opened in headless Chromium: the page loads (its DOM has the title, the
# images and the charts), logs nothing on the console, and its screenshot is not blank (the
# pixel spread of the decoded PNG). First checks on a broken page that console errors are seen.
# Exits 77 (skipped) when no Chromium is installed (Debian: apt-get install chromium).
# Usage: report_browser_test.sh PATH/TO/render OUTPUT_DIR
set -u

RENDER=${1:?usage: report_browser_test.sh RENDER OUTDIR}
OUT=${2:?usage: report_browser_test.sh RENDER OUTDIR}
HERE=$(cd "$(dirname "$0")" && pwd)
rm -rf "$OUT"
mkdir -p "$OUT"
OUT=$(cd "$OUT" && pwd)

BROWSER=""
for candidate in chromium chromium-browser google-chrome; do
    if command -v "$candidate" >/dev/null; then
        BROWSER=$(command -v "$candidate")
        break
    fi
done
if [ -z "$BROWSER" ]; then
    echo "skipped: no chromium installed (apt-get install chromium)"
    exit 77
fi

. "$(cd "$(dirname "$0")/.." && pwd)/lib/checks.sh"

# browse NAME URL ARGS...: runs the headless browser on URL with ARGS; the log in NAME.log.
# Chromium's start is not always sound on a loaded machine (its zygote process may die and the
# browser then hangs with nothing logged): a run the timeout kills is tried again, three times
# in all.
browse() {
    local name=$1 url=$2 attempt status
    shift 2
    for attempt in 1 2 3; do
        timeout 40 "$BROWSER" --headless --no-sandbox --disable-gpu --hide-scrollbars \
            --no-first-run --user-data-dir="$OUT/profile" --enable-logging=stderr --v=0 \
            "$@" "$url" >"$OUT/$name.stdout" 2>"$OUT/$name.log"
        status=$?
        [ "$status" -eq 124 ] || return "$status"
        echo "$name: the browser hung (attempt $attempt of 3): $(tail -1 "$OUT/$name.log")"
    done
    return 124
}

# Console messages: the report has no scripts, so any message at all is a fault.
console_errors() { grep -E ':CONSOLE|Uncaught|ERROR:CONSOLE' "$1"; }

# The detector sees errors: a page with a script error and a console.error.
cat >"$OUT/broken.html" <<'HTML'
<!DOCTYPE html><html><body><p>broken</p>
<script>notDefinedAnywhere();</script><script>console.error("deliberate");</script></body></html>
HTML
# The detector gets three tries too, should a browser that did not hang log nothing.
seen=""
for attempt in 1 2 3; do
    browse broken "file://$OUT/broken.html" --dump-dom
    if console_errors "$OUT/broken.log" >/dev/null; then
        seen=$attempt
        break
    fi
    echo "attempt $attempt: no console captured: $(tail -2 "$OUT/broken.log")"
done
if [ -n "$seen" ]; then
    pass "console errors of a broken page are seen (attempt $seen)"
else
    fail "the browser's console is not captured in 3 attempts: $(tail -5 "$OUT/broken.log")"
fi

# The report.
"$RENDER" --compare crsh,rah,brute builtin:cornell -W 64 -H 64 -q --report "$OUT/report" \
    >"$OUT/render.out" 2>"$OUT/render.err" || fail "render --compare: $(cat "$OUT/render.err")"
URL="file://$OUT/report/report.html"

browse dom "$URL" --dump-dom
if grep -q "Sheaf preset comparison: crsh, rah, brute" "$OUT/dom.stdout"; then
    pass "the page loads (--dump-dom has its title)"
else
    fail "--dump-dom lacks the title: $(head -c 400 "$OUT/dom.stdout")"
fi
images=$(grep -o '<img ' "$OUT/dom.stdout" | wc -l)
charts=$(grep -o '<svg ' "$OUT/dom.stdout" | wc -l)
if [ "$images" -eq 8 ] && [ "$charts" -ge 3 ]; then
    pass "the DOM has 8 images and $charts charts"
else
    fail "the DOM has $images images and $charts charts"
fi

browse shot "$URL" --screenshot="$OUT/report.png" --window-size=1200,2000
if [ -s "$OUT/report.png" ]; then
    pass "screenshot written"
    read -r _ w h _ mean std nonblack < <(python3 "$HERE/png_tool.py" "$OUT/report.png")
    echo "screenshot ${w}x${h}: mean $mean, stddev $std, non-black share $nonblack"
    if awk -v s="$std" -v n="$nonblack" 'BEGIN { exit !(s > 20 && n > 0.5) }'; then
        pass "the screenshot is not blank"
    else
        fail "the screenshot looks blank (stddev $std, non-black $nonblack)"
    fi
else
    fail "no screenshot: $(tail -5 "$OUT/shot.log")"
fi

for log in dom shot; do
    if errors=$(console_errors "$OUT/$log.log"); then
        fail "the page logged on the console ($log): $errors"
    else
        pass "no console messages ($log)"
    fi
done

finish
