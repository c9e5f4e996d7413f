#!/usr/bin/env python3
"""The verdicts of the corpus agreement check (corpus_verdicts.py), without povray: classes,
tolerances, the record, the departures table of docs/pov.md and the warnings it names."""
import os
import sys
import tempfile
import unittest

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import corpus_verdicts as v  # noqa: E402

DOC = """# POV-Ray scenes

### Scenes beyond their tolerance

| scene | class | SSIM | mean error | warning | why |
|---|---|---:|---:|---|---|
| `radiosity/r.pov` | radiosity | 0.7 | 0.03 | `approximated radiosity` | gathered per pixel |
| `advanced/odd.pov` | exact | 0.5 | 0.1 | - | not found yet |

## Next section

| `other/not_a_departure.pov` | exact | 0.1 | 0.1 | `x` | outside the table's section |
"""


class Verdicts(unittest.TestCase):
    def setUp(self):
        f = tempfile.NamedTemporaryFile("w", suffix=".md", delete=False)
        f.write(DOC)
        f.close()
        self.addCleanup(os.unlink, f.name)
        self.departures = v.read_departures(f.name)

    def test_the_table_is_read_from_its_section_only(self):
        self.assertEqual(self.departures, {"radiosity/r.pov": "approximated radiosity",
                                           "advanced/odd.pov": None})

    def test_within_the_tolerance_is_ok(self):
        self.assertEqual(v.verdict("a.pov", 0.95, 0.01, "exact", None, {}, [])[0], "ok")
        self.assertEqual(v.verdict("a.pov", 0.90, 0.03, "exact", None, {}, [])[0], "ok")

    def test_beyond_the_tolerance_and_not_listed_fails(self):
        verdict, why = v.verdict("a.pov", 0.85, 0.01, "exact", None, self.departures, [])
        self.assertEqual(verdict, "FAILED")
        self.assertIn("not listed", why)
        # The mean error alone takes a scene beyond its tolerance.
        self.assertEqual(v.verdict("a.pov", 0.99, 0.05, "exact", None, {}, [])[0], "FAILED")
        # A looser class lets it through.
        self.assertEqual(v.verdict("a.pov", 0.85, 0.01, "area", None, {}, [])[0], "ok")

    def test_a_listed_scene_passes_only_while_it_is_warned(self):
        warned = ["r.pov:3:19: warning: approximated radiosity: gathered anew ..."]
        self.assertEqual(v.verdict("radiosity/r.pov", 0.7, 0.03, "radiosity", None,
                                   self.departures, warned)[0], "warned")
        verdict, why = v.verdict("radiosity/r.pov", 0.7, 0.03, "radiosity", None,
                                 self.departures, [])
        self.assertEqual(verdict, "FAILED")
        self.assertIn("no longer warns", why)

    def test_a_known_defect_is_reported_not_failed(self):
        self.assertEqual(v.verdict("advanced/odd.pov", 0.5, 0.1, "exact", None,
                                   self.departures, [])[0], "defect")

    def test_a_regression_from_the_record_fails_within_the_tolerance_too(self):
        verdict, why = v.verdict("a.pov", 0.95, 0.01, "exact", (0.99, 0.005), {}, [])
        self.assertEqual(verdict, "FAILED")
        self.assertIn("regressed", why)
        self.assertEqual(v.verdict("a.pov", 0.98, 0.01, "exact", (0.99, 0.005), {}, [])[0],
                         "ok")
        # Worse mean error beyond the margin: a regression as well.
        self.assertEqual(v.verdict("a.pov", 0.99, 0.02, "exact", (0.99, 0.005), {}, [])[0],
                         "FAILED")

    def test_the_project_files_read(self):
        classes = v.read_classes()
        self.assertTrue(set(classes.values()) <= set(v.CLASSES))
        self.assertEqual(classes.get("radiosity/cornell.pov"), "radiosity")
        here = os.path.dirname(os.path.abspath(__file__))
        departures = v.read_departures(os.path.join(here, "..", "..", "docs", "pov.md"))
        self.assertIn("approximated radiosity", departures.values())
        scores = v.read_scores()
        self.assertGreater(len(scores), 300)
        for scene in departures:
            self.assertIn(scene, scores, f"{scene} is listed but has no recorded score")


if __name__ == "__main__":
    unittest.main()
