"""The verdicts of corpus_agreement.py --check: each scene's class and tolerance, the scores it
had when they were last recorded, and the departures docs/pov.md lists with their reasons.

A scene's class (tests/pov/corpus_classes.txt; `exact` when not listed) gives its tolerance:
the lowest SSIM and the highest mean error it may have. A scene beyond its tolerance fails
unless docs/pov.md lists it in the table under "Scenes beyond their tolerance":
  - with a warning (the text `render --check` prints for it, such as `approximated radiosity`):
    it passes while --check prints that warning, and fails when the warning is gone;
  - with `-` for the warning: a known defect whose cause is not found or not fixed yet. It is
    reported, and does not fail the check (issue 43 keeps them open).
A scene also fails when it scores lower than tests/pov/corpus_scores.csv recorded for it by
more than its class's margin (a regression that stays within the tolerance), or when Sheaf
fails to render it. `--record` rewrites the recorded scores from a run.
"""
import csv
import os
import re

# class: (lowest SSIM, highest mean error, margin of SSIM and of mean error below the record).
# Why each class may differ from POV-Ray at all:
#   exact      nothing approximated: pixel centres on the other side of an edge at 160x120
#              without anti-aliasing (silhouettes, shadow edges, fine patterns, far checkers)
#   area       area lights: both jitter their samples, differently
#   blur       focal blur: both sample the lens, differently
#   media      media: Sheaf takes fixed steps, POV-Ray refines its samples where they differ
#   photons    caustics: the estimates agree, their grain not pixel for pixel
#   radiosity  Sheaf gathers at every pixel, POV-Ray interpolates a cache (warned); POV-Ray's
#              own picture changes from run to run with its threads
CLASSES = {
    "exact": (0.90, 0.03, 0.02, 0.01),
    "area": (0.85, 0.03, 0.03, 0.01),
    "blur": (0.80, 0.05, 0.05, 0.02),
    "media": (0.85, 0.03, 0.03, 0.01),
    "photons": (0.80, 0.04, 0.05, 0.02),
    "radiosity": (0.80, 0.05, 0.05, 0.02),
}

HERE = os.path.dirname(os.path.abspath(__file__))
CLASSES_FILE = os.path.join(HERE, "corpus_classes.txt")
SCORES_FILE = os.path.join(HERE, "corpus_scores.csv")
DEPARTURES_HEADING = "Scenes beyond their tolerance"


def read_classes(path=CLASSES_FILE):
    """{scene: class} from lines `SCENE CLASS` (# starts a comment)."""
    classes = {}
    with open(path) as f:
        for n, line in enumerate(f, 1):
            line = line.split("#", 1)[0].strip()
            if not line:
                continue
            scene, cls = line.split()
            if cls not in CLASSES:
                raise ValueError(f"{path}:{n}: unknown class '{cls}'")
            classes[scene] = cls
    return classes


def read_scores(path=SCORES_FILE):
    """{scene: (ssim, mean error)} as last recorded; empty when there is no record."""
    if not os.path.exists(path):
        return {}
    with open(path) as f:
        return {r["scene"]: (float(r["ssim"]), float(r["mean_error"]))
                for r in csv.DictReader(f)}


def write_scores(scored, path=SCORES_FILE):
    with open(path, "w") as f:
        f.write("scene,ssim,mean_error\n")
        for r in sorted(scored):
            f.write(f"{r[0]},{r[1]:.4f},{r[2]:.5f}\n")


def read_departures(doc):
    """{scene: warning or None} from the table under DEPARTURES_HEADING in docs/pov.md: rows
    `| `SCENE` | CLASS | SSIM | MEAN ERROR | WARNING | WHY |`, the warning in backquotes or
    `-` (none)."""
    departures, inside = {}, False
    with open(doc) as f:
        for line in f:
            if line.startswith("#"):
                inside = DEPARTURES_HEADING in line
                continue
            if not inside or not line.startswith("| `"):
                continue
            cells = [c.strip() for c in line.strip().strip("|").split("|")]
            scene = cells[0].strip("`")
            warned = re.fullmatch(r"`([^`]+)`", cells[4]) if len(cells) > 4 else None
            departures[scene] = warned.group(1) if warned else None
    return departures


def verdict(scene, ssim, err, cls, recorded, departures, warnings):
    """('ok' | 'warned' | 'defect' | 'FAILED', why) for one scored scene."""
    low, high, ssim_margin, err_margin = CLASSES[cls]
    if recorded and (ssim < recorded[0] - ssim_margin or err > recorded[1] + err_margin):
        return "FAILED", (f"regressed: SSIM {ssim:.3f}, mean error {err:.4f}; recorded "
                          f"{recorded[0]:.3f}, {recorded[1]:.4f}")
    if ssim >= low and err <= high:
        return "ok", ""
    beyond = f"SSIM {ssim:.3f}, mean error {err:.4f} beyond {cls} ({low}, {high})"
    if scene not in departures:
        return "FAILED", beyond + "; not listed in docs/pov.md"
    warning = departures[scene]
    if warning is None:
        return "defect", beyond + "; listed in docs/pov.md as a known defect"
    if not any(warning in w for w in warnings):
        return "FAILED", beyond + f"; --check no longer warns '{warning}'"
    return "warned", beyond + f"; warned: {warning}"
