#!/usr/bin/env python3
"""Two builds of `render` side by side, with POV-Ray beside them, on the same scene files.

    tests/bench/render_ab.py OLD/render NEW/render [--runs 3] [SCENE.pov:SIZE ...]

The three run alternately `--runs` times per scene (2 threads, no anti-aliasing, PNG out);
printed per scene, medians: each render's whole-process wall time and frame time (its "wrote"
line), new over old, and POV-Ray's wall time. For a change to the engine: build the commit
before it (e.g. a git worktree, -DSHEAF_ENABLE_CUDA=OFF, target render) and compare. A benchmark:
it asserts nothing.
"""
import argparse, os, re, shutil, statistics, subprocess, sys, tempfile, time

REPO = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
DEFAULT = ["scenes/office.pov:384", "scenes/cornell.pov:384", "scenes/colonnade.pov:256"]


def run(cmd, cwd):
    t = time.perf_counter()
    p = subprocess.run(cmd, cwd=cwd, capture_output=True, text=True)
    wall = time.perf_counter() - t
    if p.returncode:
        sys.exit("failed: %s\n%s" % (" ".join(cmd), p.stderr[-500:]))
    m = re.search(r"frame ([0-9.]+) ms", p.stdout)
    return wall, float(m.group(1)) if m else float("nan")


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("old")
    ap.add_argument("new")
    ap.add_argument("scenes", nargs="*", default=DEFAULT)
    ap.add_argument("--runs", type=int, default=3)
    a = ap.parse_args()
    print("%-24s %9s %9s %10s %10s %8s %9s" % ("scene", "old wall", "new wall", "old frame",
                                               "new frame", "new/old", "povray"))
    for spec in a.scenes:
        path, size = spec.rsplit(":", 1)
        path = os.path.join(REPO, path) if not os.path.isabs(path) else path
        work = tempfile.mkdtemp()
        shutil.copytree(os.path.dirname(path), work, dirs_exist_ok=True)
        scene = os.path.join(work, os.path.basename(path))
        r = {"old": [], "new": [], "pov": []}
        for _ in range(a.runs):
            for k, exe in (("old", a.old), ("new", a.new)):
                r[k].append(run([exe, scene, "-W", size, "-H", size, "--threads", "2", "-o",
                                 "o.png"], work))
            r["pov"].append(run(["povray", "-D", "-GA", "+W" + size, "+H" + size, "+WT2", "-A",
                                 "+I" + scene, "+Op.png"], work))
        med = lambda k, i: statistics.median(x[i] for x in r[k])
        print("%-24s %8.2fs %8.2fs %8.0fms %8.0fms %8.3f %8.2fs" % (
            os.path.basename(path) + " " + size, med("old", 0), med("new", 0), med("old", 1),
            med("new", 1), med("new", 1) / med("old", 1), med("pov", 0)))
        shutil.rmtree(work)


if __name__ == "__main__":
    main()
