#!/usr/bin/env python3
"""POV-Ray 3.7's example scenes through `render --check`.

Copies the examples (Debian's povray-examples) to a writable folder, checks every scene from
its own folder (scenes #write files and #include their neighbours; a scene with an .ini that
names it is checked through the .ini, every frame), and prints the counts:
scenes, parsed, usable with no unsupported feature; then the unsupported features by the
number of scenes they keep from being clean, every scene that fails with its error, and the
most any scene uses of each of the reader's limits (parse steps, objects, data, loop runs).

Exits 77 (skipped) when the examples are not installed, 1 when fewer than --min-parsed of
the scenes parse or fewer than --min-clean are clean, or a scene uses more than
--max-limit-share of one of the reader's limits (the limits are meant to stop runaway scenes,
far above what real ones use), 0 otherwise.

Usage: corpus_check.py RENDER WORKDIR [--examples DIR] [--jobs N] [--timeout S]
"""
import argparse
import collections
import concurrent.futures
import os
import re
import shutil
import subprocess
import sys


def ini_for(folder, scene):
    """The .ini beside the scene that names it as its Input_File_Name (how POV-Ray's animations
    and portfolio scenes are meant to be rendered: they need its frames), or the scene itself."""
    ini = os.path.splitext(scene)[0] + ".ini"
    try:
        with open(os.path.join(folder, ini), errors="replace") as f:
            for line in f:
                key, _, value = line.split(";", 1)[0].partition("=")
                if key.strip().lower() == "input_file_name" and \
                        value.strip().strip('"').lower() == scene.lower():
                    return ini
    except OSError:
        pass
    return scene


LIMITS = re.compile(r"(\w+) ([0-9.e+-]+) of ([0-9.e+-]+) \(")


def limits_used(stdout):
    """{limit: (used, limit)} from render --check's 'limits used:' lines, the most of each."""
    used = {}
    for line in stdout.splitlines():
        if line.strip().startswith("limits used:"):
            for name, u, lim in LIMITS.findall(line):
                if float(u) >= used.get(name, (-1, 0))[0]:
                    used[name] = (float(u), float(lim))
    return used


def copy_corpus(examples, workdir):
    """A fresh writable copy of the examples under WORKDIR/scenes, and its .pov scenes (paths
    relative to it, sorted)."""
    root = os.path.join(os.path.abspath(workdir), "scenes")
    shutil.rmtree(root, ignore_errors=True)
    shutil.copytree(examples, root, symlinks=False)
    return root, sorted(os.path.relpath(os.path.join(d, f), root)
                        for d, _, files in os.walk(root) for f in files if f.endswith(".pov"))


def check(render, root, scene, timeout):
    """(scene, 'ok'|'error'|'timeout', unsupported-feature warnings, message, limits used,
    every warning)."""
    folder = os.path.join(root, os.path.dirname(scene))
    try:
        p = subprocess.run([render, "--check", ini_for(folder, os.path.basename(scene))],
                           cwd=folder,
                           capture_output=True, text=True, timeout=timeout)
    except subprocess.TimeoutExpired:
        return scene, "timeout", [], f"no answer in {timeout} s", {}, []
    every = [l for l in p.stderr.splitlines() if ": warning: " in l]
    warnings = [l for l in every if ": warning: unsupported " in l]
    used = limits_used(p.stdout)
    if p.returncode == 0 and "usable" in p.stdout:
        return scene, "ok", warnings, "", used, every
    errors = [l for l in p.stderr.splitlines() if "error" in l]
    if p.returncode not in (1, 2):  # a crash, never acceptable
        return scene, "crash", warnings, f"exit code {p.returncode}: {p.stderr[-300:]}", used, \
            every
    return scene, "error", warnings, errors[-1] if errors else p.stderr.strip()[-300:], used, \
        every


def feature(warning):
    """The unsupported feature a warning names, without the position and the remark."""
    text = warning.split(": warning: unsupported ", 1)[1]
    text = re.sub(r"\s*\(.*", "", text)
    return re.sub(r"layered texture '.*", "layered texture", text)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("render")
    ap.add_argument("workdir")
    ap.add_argument("--examples", default="/usr/share/povray-3.7/scenes")
    ap.add_argument("--jobs", type=int, default=os.cpu_count() or 2)
    ap.add_argument("--timeout", type=float, default=300)
    ap.add_argument("--min-parsed", type=float, default=0.90)
    ap.add_argument("--min-clean", type=float, default=0.25)
    ap.add_argument("--max-limit-share", type=float, default=0.25)
    a = ap.parse_args()
    a.render = os.path.abspath(a.render)
    if not os.path.isdir(a.examples):
        print(f"skipped: {a.examples} is not installed (apt-get install povray-examples)")
        return 77
    root, scenes = copy_corpus(a.examples, a.workdir)
    with concurrent.futures.ThreadPoolExecutor(a.jobs) as pool:
        results = list(pool.map(lambda s: check(a.render, root, s, a.timeout), scenes))

    parsed = [r for r in results if r[1] == "ok"]
    clean = [r for r in parsed if not r[2]]
    blockers = collections.Counter()
    for _, _, warnings, _, _, _ in parsed:
        for f in {feature(w) for w in warnings}:
            blockers[f] += 1
    n = len(scenes)
    print(f"POV-Ray 3.7 examples: {n} scenes, {len(parsed)} parsed ({len(parsed) / n:.1%}), "
          f"{len(clean)} usable with no unsupported feature ({len(clean) / n:.1%})")
    print("\nUnsupported features, by the number of parsed scenes that use them:")
    for f, count in blockers.most_common():
        print(f"  {count:4d}  {f}")
    print("\nScenes that do not parse:")
    for scene, status, _, message, _, _ in results:
        if status != "ok":
            print(f"  {scene}: {status}: {message}")
    print("\nThe reader's limits: the most a scene uses of each, and the next four above 1%:")
    near = []
    for name in sorted({k for r in results for k in r[4]}):
        users = sorted(((r[4][name][0], r[4][name][1], r[0]) for r in results if name in r[4]),
                       reverse=True)
        used, limit, scene = users[0]
        print(f"  {name}: {used:.15g} of {limit:.15g} ({used / limit:.2%}) in {scene}")
        for u, lim, s in users[1:5]:
            if u < 0.01 * lim:
                break
            print(f"      {u:.15g} ({u / lim:.2%}) in {s}")
        near += [(name, s) for u, lim, s in users if u > a.max_limit_share * lim]
    crashes = [r for r in results if r[1] in ("crash", "timeout")]
    ok = len(parsed) >= a.min_parsed * n and len(clean) >= a.min_clean * n and not crashes \
        and not near
    if not ok:
        print(f"\nFAILED: need {a.min_parsed:.0%} parsed, {a.min_clean:.0%} clean, "
              f"no crash or timeout ({len(crashes)}), no scene above {a.max_limit_share:.0%} "
              f"of a limit ({', '.join(f'{s}: {name}' for name, s in near) or 'none'})")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
