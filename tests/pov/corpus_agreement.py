#!/usr/bin/env python3
"""Sheaf against POV-Ray over POV-Ray's whole clean example corpus: every example scene that
`render --check` calls clean (no unsupported feature; scenes rendered through an .ini, the
animations, are left out) is rendered by both at 160x120 without anti-aliasing, and scored by
SSIM on luminance (Rec. 709 weights of the 8-bit values, 7x7 windows, the usual constants)
and the mean absolute error of RGB in 0..1. Prints the distribution and the worst scenes.

Usage: corpus_agreement.py RENDER WORKDIR [--examples DIR] [--jobs N] [--timeout S]
                           [--share K/N] [--worst 20] [--csv FILE] [--check] [--record]
                           [--doc docs/pov.md]
--share K/N scores the K-th of N fixed slices of the corpus (every N-th scene from the K-th):
a run that does not fit takes a share. POV-Ray failing or passing --timeout leaves the scene
out of the scores (listed); so does Sheaf, but that fails --check.
--check gives each scene a verdict by its class and tolerance (corpus_verdicts.py) and exits 1
when one fails; --record writes the scores of this run to corpus_scores.csv.
Exits 77 when povray, oiiotool or the examples are missing, else 0 (without --check).
"""
import argparse
import concurrent.futures
import os
import shutil
import statistics
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import corpus_check  # noqa: E402  (its copy of the corpus and its --check)
import corpus_verdicts  # noqa: E402

W, H = 160, 120


def read_ppm(path):
    """(width, height, bytes) of a binary PPM (P6, 8 bits)."""
    with open(path, "rb") as f:
        data = f.read()
    fields, pos = [], 2
    while len(fields) < 3:
        while data[pos:pos + 1].isspace():
            pos += 1
        if data[pos:pos + 1] == b"#":
            pos = data.index(b"\n", pos)
            continue
        end = pos
        while not data[end:end + 1].isspace():
            end += 1
        fields.append(int(data[pos:end]))
        pos = end
    w, h, _ = fields
    return w, h, data[pos + 1:pos + 1 + w * h * 3]


def to_ppm(src, dst):
    subprocess.run(["oiiotool", src, "--ch", "R,G,B", "-d", "uint8", "-o", dst], check=True,
                   capture_output=True)


def luminance(rgb, n):
    return [0.2126 * rgb[3 * i] + 0.7152 * rgb[3 * i + 1] + 0.0722 * rgb[3 * i + 2]
            for i in range(n)]


def integral(v, w, h):
    s = [[0.0] * (w + 1) for _ in range(h + 1)]
    for y in range(h):
        row, acc = s[y + 1], 0.0
        above = s[y]
        for x in range(w):
            acc += v[y * w + x]
            row[x + 1] = above[x + 1] + acc
    return s


def ssim(a, b, w, h, win=7):
    """Mean SSIM over every win x win window (uniform weights)."""
    c1, c2 = (0.01 * 255) ** 2, (0.03 * 255) ** 2
    sa, sb = integral(a, w, h), integral(b, w, h)
    saa = integral([x * x for x in a], w, h)
    sbb = integral([x * x for x in b], w, h)
    sab = integral([x * y for x, y in zip(a, b)], w, h)
    n = win * win
    total, count = 0.0, 0
    for y in range(h - win + 1):
        for x in range(w - win + 1):
            def box(s):
                return s[y + win][x + win] - s[y][x + win] - s[y + win][x] + s[y][x]
            ma, mb = box(sa) / n, box(sb) / n
            va = box(saa) / n - ma * ma
            vb = box(sbb) / n - mb * mb
            cov = box(sab) / n - ma * mb
            total += ((2 * ma * mb + c1) * (2 * cov + c2)) / \
                     ((ma * ma + mb * mb + c1) * (va + vb + c2))
            count += 1
    return total / count


def score(render, root, scene, timeout):
    """(scene, ssim, mean error, seconds povray, seconds sheaf) or (scene, None, why)."""
    import time
    folder = os.path.join(root, os.path.dirname(scene))
    name = os.path.splitext(os.path.basename(scene))[0]
    pov_png = os.path.join(folder, name + ".agree.povray.png")
    sheaf_png = os.path.join(folder, name + ".agree.sheaf.png")
    try:
        t0 = time.monotonic()
        p = subprocess.run(["povray", f"+I{os.path.basename(scene)}", f"+W{W}", f"+H{H}", "-A",
                            "-D", "-GA", f"+O{pov_png}"], cwd=folder, capture_output=True,
                           timeout=timeout)
        t1 = time.monotonic()
        s = subprocess.run([render, os.path.basename(scene), "-W", str(W), "-H", str(H), "-q",
                            "-o", sheaf_png], cwd=folder, capture_output=True, timeout=timeout)
        t2 = time.monotonic()
    except subprocess.TimeoutExpired as e:
        who = "render" if e.cmd[0] == render else "povray"
        return scene, None, f"{who} over {timeout:g} s"
    if p.returncode != 0 or not os.path.exists(pov_png):
        return scene, None, f"povray failed ({p.returncode})"
    if s.returncode != 0:
        return scene, None, f"render failed ({s.returncode}): {s.stderr.decode()[-200:]}"
    pa, pb = pov_png + ".ppm", sheaf_png + ".ppm"
    to_ppm(pov_png, pa)
    to_ppm(sheaf_png, pb)
    wa, ha, ra = read_ppm(pa)
    wb, hb, rb = read_ppm(pb)
    if (wa, ha) != (wb, hb):
        return scene, None, "sizes differ"
    n = wa * ha
    err = sum(abs(x - y) for x, y in zip(ra, rb)) / (3 * n * 255.0)
    return scene, ssim(luminance(ra, n), luminance(rb, n), wa, ha), err, t1 - t0, t2 - t1


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("render")
    ap.add_argument("workdir")
    ap.add_argument("--examples", default="/usr/share/povray-3.7/scenes")
    ap.add_argument("--jobs", type=int, default=os.cpu_count() or 2)
    ap.add_argument("--timeout", type=float, default=120)
    ap.add_argument("--share", default="0/1")
    ap.add_argument("--worst", type=int, default=20)
    ap.add_argument("--csv")
    ap.add_argument("--check", action="store_true")
    ap.add_argument("--record", action="store_true")
    ap.add_argument("--doc", default=os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                                  "..", "..", "docs", "pov.md"))
    a = ap.parse_args()
    render = os.path.abspath(a.render)
    for tool in ("povray", "oiiotool"):
        if not shutil.which(tool):
            print(f"skipped: {tool} is not installed")
            return 77
    if not os.path.isdir(a.examples):
        print(f"skipped: {a.examples} is not installed")
        return 77
    k, n = (int(x) for x in a.share.split("/"))
    root, scenes = corpus_check.copy_corpus(a.examples, a.workdir)
    scenes = scenes[k::n]
    with concurrent.futures.ThreadPoolExecutor(a.jobs) as pool:
        checked = list(pool.map(lambda s: corpus_check.check(render, root, s, a.timeout), scenes))
    clean = [r[0] for r in checked if r[1] == "ok" and not r[2] and
             corpus_check.ini_for(os.path.join(root, os.path.dirname(r[0])),
                                  os.path.basename(r[0])).endswith(".pov")]
    warnings = {r[0]: r[5] for r in checked}
    with concurrent.futures.ThreadPoolExecutor(a.jobs) as pool:
        results = list(pool.map(lambda s: score(render, root, s, a.timeout), clean))
    scored = [r for r in results if r[1] is not None]
    left = [r for r in results if r[1] is None]
    print(f"{len(scenes)} scenes (share {k}/{n}), {len(clean)} clean without an .ini, "
          f"{len(scored)} compared at {W}x{H}")
    if a.csv:
        with open(a.csv, "w") as f:
            f.write("scene,ssim,mean_error,povray_s,sheaf_s\n")
            for r in scored:
                f.write(f"{r[0]},{r[1]:.4f},{r[2]:.5f},{r[3]:.2f},{r[4]:.2f}\n")
    if scored:
        v = [r[1] for r in scored]
        print(f"SSIM: mean {statistics.mean(v):.3f}, median {statistics.median(v):.3f}, "
              f">= 0.97: {sum(x >= 0.97 for x in v)}, >= 0.90: {sum(x >= 0.90 for x in v)}, "
              f"< 0.90: {sum(x < 0.90 for x in v)}")
        print(f"\nThe {min(a.worst, len(scored))} lowest:")
        for r in sorted(scored, key=lambda r: r[1])[:a.worst]:
            print(f"  {r[1]:.3f}  mean error {r[2]:.4f}  {r[0]}")
        slow = [r for r in scored if r[4] > 5 * max(r[3], 0.2)]
        if slow:
            print("\nMore than 5x POV-Ray's time (povray s, sheaf s):")
            for r in sorted(slow, key=lambda r: -r[4] / max(r[3], 0.2)):
                print(f"  {r[3]:7.2f} {r[4]:7.2f}  {r[0]}")
    if left:
        print("\nNot compared:")
        for r in left:
            print(f"  {r[0]}: {r[2]}")
    if a.record:
        recorded = corpus_verdicts.read_scores()
        recorded.update({r[0]: (r[1], r[2]) for r in scored})
        corpus_verdicts.write_scores([(s, v[0], v[1]) for s, v in recorded.items()])
        print(f"\nRecorded {len(scored)} scores in {corpus_verdicts.SCORES_FILE}")
    if not a.check:
        return 0
    return report_verdicts(scored, left, warnings, a.doc)


def report_verdicts(scored, left, warnings, doc):
    """Prints each scene's verdict that is not plainly ok; 1 when one failed."""
    classes = corpus_verdicts.read_classes()
    recorded = corpus_verdicts.read_scores()
    departures = corpus_verdicts.read_departures(doc)
    counts, failed = {}, 0
    print("\nVerdicts (class, tolerance: corpus_verdicts.py; departures: docs/pov.md):")
    for scene, ssim_v, err, _, _ in sorted(scored):
        cls = classes.get(scene, "exact")
        v, why = corpus_verdicts.verdict(scene, ssim_v, err, cls, recorded.get(scene),
                                         departures, warnings.get(scene, []))
        counts[v] = counts.get(v, 0) + 1
        failed += v == "FAILED"
        if v != "ok":
            print(f"  {v:7s} {scene}: {why}")
    for scene, _, why in left:
        if why.startswith("render"):  # Sheaf failed or took too long: always a failure
            failed += 1
            print(f"  FAILED  {scene}: {why}")
    print(", ".join(f"{c} {k}" for k, c in sorted(counts.items())))
    if failed:
        print(f"FAILED: {failed} scenes")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
