#!/usr/bin/env python3
"""Sheaf against POV-Ray on a set of scenes: both render each scene at 160x120 without
anti-aliasing, and OpenImageIO's idiff compares the 8-bit pictures (RGB, values 0..1): the mean
absolute error, and the share of pixels where some channel differs by more than 0.1.

Each scene has a class, and the class its tolerance:
  exact   mean <= 0.01,  share <= 2%:  nothing Sheaf approximates; what remains is rounding at
          silhouettes, shadow edges and far checkers (a pixel centre that falls on the other
          side of an edge flips that pixel: a checker plane to the horizon aliases).
  area    mean <= 0.02,  share <= 5%:  area lights; both jitter their samples, differently.
  legacy  mean <= 0.015, share <= 2%: a #version 3.6 scene without assumed_gamma, whose
          picture Sheaf draws two or three 8-bit levels darker all over (docs/pov.md).
  media, photons  mean <= 0.02, share <= 5%: media whose beams are narrower than the steps
          read them; caustics, whose photons both shoot in rings (the estimates agree, the
          grain does not pixel for pixel).
  radiosity  mean <= 0.03, share <= 5%: radiosity; Sheaf gathers at every pixel, with the
          noise of its count of rays, where POV-Ray interpolates a cache of gathered samples.
A scene also fails when POV-Ray's picture is constant (nothing to compare) or either renderer
fails. Exits 77 (skipped) when povray or idiff is missing.

Usage: agreement_check.py RENDER WORKDIR [--examples DIR] [--repo DIR]
"""
import argparse
import os
import re
import shutil
import subprocess
import sys

TOLERANCE = {"exact": (0.01, 2.0), "area": (0.02, 5.0), "media": (0.02, 5.0),
             "photons": (0.02, 5.0),
             "legacy": (0.015, 2.0), "radiosity": (0.03, 5.0)}

# (scene, class): examples/... are POV-Ray's example scenes, scenes/... the project's own.
SCENES = [
    ("examples/camera/orthographic.pov", "exact"),
    ("examples/advanced/bwstripe.pov", "exact"),
    ("examples/advanced/lamppost.pov", "exact"),
    ("examples/lights/parallel_lights.pov", "exact"),
    ("examples/incdemo/sundial.pov", "exact"),
    ("examples/objects/chesmsh.pov", "exact"),
    ("examples/templates/Basic_Scenes/Checkered_plane.pov", "exact"),
    ("examples/objects/quartic/torus.pov", "exact"),
    ("examples/objects/quartic/piriform.pov", "exact"),
    ("examples/objects/superel3.pov", "exact"),
    ("scenes/surfaces.pov", "exact"),
    ("scenes/text.pov", "exact"),
    ("scenes/turned.pov", "exact"),
    ("scenes/sweeps.pov", "exact"),
    ("scenes/functions.pov", "exact"),
    ("scenes/beams.pov", "exact"),
    ("examples/objects/polygon.pov", "exact"),
    ("scenes/caustics.pov", "exact"),
    ("examples/objects/prism2.pov", "exact"),
    ("examples/objects/lathe2.pov", "exact"),
    ("examples/objects/blob1a.pov", "exact"),
    ("examples/objects/blob1b.pov", "exact"),
    ("examples/objects/isosurfaces.pov", "exact"),
    ("examples/textures/patterns/mandel.pov", "exact"),
    ("examples/objects/bezier.pov", "exact"),
    ("examples/objects/fractal1.pov", "exact"),
    ("examples/objects/fractal3.pov", "exact"),
    ("examples/objects/fractal4.pov", "exact"),
    ("examples/camera/fisheye.pov", "exact"),
    ("examples/camera/cylinder3.pov", "exact"),
    ("examples/camera/panoramic.pov", "exact"),
    ("examples/camera/spherical.pov", "exact"),
    ("examples/camera/omnimax.pov", "exact"),
    ("scenes/mesh_camera.pov", "exact"),
    ("examples/interior/media/media4.pov", "exact"),
    ("examples/interior/media/media5.pov", "exact"),
    ("examples/interior/media/media1.pov", "exact"),
    ("examples/interior/media/media2.pov", "media"),
    ("examples/interior/media/galaxy.pov", "media"),
    ("examples/textures/patterns/densfile.pov", "exact"),
    ("scenes/nebula.pov", "exact"),
    ("examples/interior/rainbow1.pov", "exact"),
    ("examples/lights/phot_met_glass.pov", "photons"),
    ("scenes/photons.pov", "photons"),
    ("examples/lights/soft.pov", "area"),
    ("examples/interior/atten1.pov", "exact"),
    ("examples/interior/iortest.pov", "exact"),
    ("examples/incdemo/stones/pinkmarb.pov", "exact"),
    ("examples/incdemo/woods/teak.pov", "legacy"),
    ("examples/incdemo/func_gradient.pov", "exact"),
    ("examples/textures/pigments/skies/stars.pov", "exact"),
    ("examples/textures/normals/normavg.pov", "exact"),  # number_of_waves 1
    ("examples/textures/patterns/quilted.pov", "exact"),
    ("examples/textures/pigments/blkhole.pov", "exact"),  # black holes' jitter
    ("examples/textures/patterns/radial.pov", "exact"),
    ("examples/radiosity/cornell.pov", "radiosity"),
    ("scenes/radiosity.pov", "radiosity"),
]


def stats(path):
    out = subprocess.run(["oiiotool", "--stats", path], capture_output=True, text=True).stdout
    dev = re.search(r"Stats StdDev:\s*([\d.e+-]+)", out)
    return float(dev.group(1)) if dev else 0.0


def compare(a, b):
    out = subprocess.run(["idiff", "-fail", "0.1", "-failpercent", "100", a, b],
                         capture_output=True, text=True).stdout
    mean = re.search(r"Mean error = ([\d.e+-]+)", out)
    share = re.search(r"\(([\d.e+-]+)%\) over 0.1", out)
    return (float(mean.group(1)) if mean else 0.0, float(share.group(1)) if share else 0.0)


def rgb(src, dst):
    subprocess.run(["oiiotool", src, "--ch", "R,G,B", "-o", dst], check=True)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("render")
    ap.add_argument("workdir")
    ap.add_argument("--examples", default="/usr/share/povray-3.7/scenes")
    ap.add_argument("--repo", default=os.path.join(os.path.dirname(__file__), "..", ".."))
    a = ap.parse_args()
    render = os.path.abspath(a.render)
    for tool in ("povray", "idiff", "oiiotool"):
        if not shutil.which(tool):
            print(f"skipped: {tool} is not installed")
            return 77
    if not os.path.isdir(a.examples):
        print(f"skipped: {a.examples} is not installed")
        return 77
    work = os.path.abspath(a.workdir)
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    failures = 0
    print(f"{'scene':55s} {'class':9s} {'mean':>8s} {'>0.1':>7s}  verdict")
    for scene, cls in SCENES:
        kind, rel = scene.split("/", 1)
        src = os.path.join(a.examples if kind == "examples" else os.path.join(a.repo, "scenes"),
                           rel)
        # Each scene from a writable copy of its own folder (scenes write and include files).
        folder = os.path.join(work, os.path.dirname(scene).replace("/", "_"))
        if not os.path.isdir(folder):
            shutil.copytree(os.path.dirname(src), folder)
        name = os.path.splitext(os.path.basename(rel))[0]
        pov_png, sheaf_png = os.path.join(folder, name + ".povray.png"), os.path.join(
            folder, name + ".sheaf.png")
        p = subprocess.run(["povray", f"+I{name}.pov", "+W160", "+H120", "-A", "-D", "-GA",
                            f"+O{pov_png}"], cwd=folder, capture_output=True, text=True,
                           timeout=300)
        s = subprocess.run([render, f"{name}.pov", "-W", "160", "-H", "120", "-q", "-o",
                            sheaf_png], cwd=folder, capture_output=True, text=True, timeout=300)
        if p.returncode != 0 or s.returncode != 0 or not os.path.exists(pov_png):
            print(f"{scene:55s} {cls:9s} {'-':>8s} {'-':>7s}  FAILED: povray {p.returncode}, "
                  f"render {s.returncode}: {s.stderr.strip()[-200:]}")
            failures += 1
            continue
        rgb(pov_png, pov_png + ".tif")
        rgb(sheaf_png, sheaf_png + ".tif")
        mean, share = compare(pov_png + ".tif", sheaf_png + ".tif")
        max_mean, max_share = TOLERANCE[cls]
        ok = mean <= max_mean and share <= max_share and stats(pov_png + ".tif") > 0.01
        failures += not ok
        print(f"{scene:55s} {cls:9s} {mean:8.5f} {share:6.2f}%  {'ok' if ok else 'FAILED'}")
    print(f"{len(SCENES) - failures} of {len(SCENES)} scenes within tolerance")
    return 0 if failures == 0 else 1


if __name__ == "__main__":
    sys.exit(main())
