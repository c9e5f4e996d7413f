#!/usr/bin/env python3
"""POV-Ray 3.7 against Sheaf's `render`, as whole processes, on the same scene files.

    tests/bench/pov_race.py build/plugin/render/render [--runs 5] [--size 512] [--threads 2]
                            [--scene examples/advanced/chess2.pov ...] [--quick]

For each scene (the built-in scenes as .pov files from scenes/, and POV-Ray's example scenes
with many objects or triangles), both programs run alternately `--runs` times, each from a
writable copy of the scene's folder, at SIZE x SIZE with THREADS threads and no anti-aliasing,
writing a PNG. Printed per scene, medians over the runs:
  - the whole-process wall time of each and Sheaf's over POV-Ray's (below 1: Sheaf is faster);
  - POV-Ray's parse and trace times (its own statistics) beside Sheaf's scene and frame times
    (`render`'s "wrote" line: reading and committing the scene, rendering the frame);
  - each process's peak resident memory (wait4's ru_maxrss) and Sheaf's over POV-Ray's.
A benchmark, not a test: it asserts nothing and exits 0 unless a program fails on a scene.
"""
import argparse
import os
import re
import shutil
import statistics
import subprocess
import sys
import tempfile
import time

REPO = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
EXAMPLES = "/usr/share/povray-3.7/scenes"

# (scene, what it stresses). "repo/" is the project's scenes/, "examples/" POV-Ray's.
SCENES = [
    ("repo/cornell.pov", "built-in cornell: 790 triangles, mirrors"),
    ("repo/office.pov", "built-in office: meshes, two lights"),
    ("repo/colonnade.pov", "built-in colonnade: many mesh objects"),
    ("examples/advanced/benchmark/benchmark.pov", "POV-Ray's benchmark scene"),
    ("examples/advanced/chess2.pov", "many CSG pieces"),
    ("examples/advanced/teapot/teapot.pov", "bicubic patches"),
    ("examples/advanced/pawns.pov", "many objects"),
    ("examples/advanced/blocks/stackerday.pov", "many boxes"),
]
QUICK = {"repo/cornell.pov", "repo/office.pov", "examples/advanced/chess2.pov"}


def pov_seconds(text, label):
    m = re.search(label + r" Time:.*?\(([\d.]+) seconds\)", text)
    return float(m.group(1)) if m else float("nan")


def run(cmd, cwd, timeout):
    """(wall seconds, peak KiB, return code, stdout+stderr) of one process."""
    out = tempfile.TemporaryFile(mode="w+")
    start = time.perf_counter()
    p = subprocess.Popen(cmd, cwd=cwd, stdout=out, stderr=subprocess.STDOUT)
    deadline = start + timeout
    while True:
        pid, status, usage = os.wait4(p.pid, os.WNOHANG)
        if pid:
            break
        if time.perf_counter() > deadline:
            p.kill()
            pid, status, usage = os.wait4(p.pid, 0)
            break
        time.sleep(0.002)
    wall = time.perf_counter() - start
    p.returncode = os.waitstatus_to_exitcode(status)
    out.seek(0)
    return wall, usage.ru_maxrss, p.returncode, out.read()


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("render")
    ap.add_argument("--runs", type=int, default=5)
    ap.add_argument("--size", type=int, default=512)
    ap.add_argument("--threads", type=int, default=2)
    ap.add_argument("--scene", action="append", help="repo/NAME.pov or examples/PATH.pov")
    ap.add_argument("--quick", action="store_true", help="three scenes only")
    ap.add_argument("--timeout", type=float, default=600)
    ap.add_argument("--examples", default=EXAMPLES)
    a = ap.parse_args()
    render = os.path.abspath(a.render)
    if not shutil.which("povray"):
        print("povray is not installed (apt-get install povray povray-includes povray-examples)")
        return 0
    scenes = [(s, "") for s in a.scene] if a.scene else [
        s for s in SCENES if not a.quick or s[0] in QUICK]
    work = tempfile.mkdtemp(prefix="pov_race_")
    n = a.size
    print(f"{n}x{n}, {a.threads} threads, no anti-aliasing, median of {a.runs} alternating runs")
    head = (f"{'scene':44s} {'povray s':>8s} {'sheaf s':>8s} {'ratio':>6s} | {'pov parse':>9s} "
            f"{'pov trace':>9s} {'sh scene':>9s} {'sh frame':>9s} | {'pov MiB':>7s} "
            f"{'sh MiB':>7s} {'ratio':>5s}")
    print(head)
    print("-" * len(head))
    failed = 0
    for scene, _ in scenes:
        kind, rel = scene.split("/", 1)
        src = os.path.join(REPO, "scenes", rel) if kind == "repo" else os.path.join(a.examples, rel)
        if not os.path.isfile(src):
            print(f"{scene:44s} not found ({src})")
            continue
        folder = os.path.join(work, scene.replace("/", "_"))
        shutil.copytree(os.path.dirname(src), folder)
        name = os.path.basename(src)
        pov_cmd = ["povray", f"+I{name}", f"+W{n}", f"+H{n}", "-A", "-D", "-P",
                   f"+WT{a.threads}", "+Opov.png"]
        sheaf_cmd = [render, name, "-W", str(n), "-H", str(n), "--set", f"threads={a.threads}",
                     "-o", "sheaf.png"]
        runs = {"pov": [], "sheaf": []}
        error = ""
        for _ in range(a.runs):
            for who, cmd in (("pov", pov_cmd), ("sheaf", sheaf_cmd)):
                wall, kib, rc, text = run(cmd, folder, a.timeout)
                if rc != 0:
                    last = text.strip().splitlines()[-1] if text.strip() else ""
                    error = f"{who} exit {rc}: {last}"
                    break
                if who == "pov":
                    extra = (pov_seconds(text, "Parse"), pov_seconds(text, "Trace"))
                else:
                    m = re.search(r"scene ([\d.]+) ms, frame ([\d.]+) ms", text)
                    extra = (float(m.group(1)) / 1e3, float(m.group(2)) / 1e3) if m else (
                        float("nan"), float("nan"))
                runs[who].append((wall, kib / 1024, *extra))
            if error:
                break
        if error:
            print(f"{scene:44s} FAILED: {error}")
            failed += 1
            continue
        med = {w: [statistics.median(r[i] for r in runs[w]) for i in range(4)] for w in runs}
        p, s = med["pov"], med["sheaf"]
        print(f"{scene:44s} {p[0]:8.3f} {s[0]:8.3f} {s[0] / p[0]:6.2f} | {p[2]:9.3f} {p[3]:9.3f} "
              f"{s[2]:9.3f} {s[3]:9.3f} | {p[1]:7.1f} {s[1]:7.1f} {s[1] / p[1]:5.2f}")
        sys.stdout.flush()
    shutil.rmtree(work, ignore_errors=True)
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
