#!/usr/bin/env python3
"""Checks a report's results.json and results.csv: one entry per preset or grid point, in
order, each with the totals (tests.total, tests.brute_force, share, time_ms.frame), its settings
and every statistic; share = tests.total / tests.brute_force.

Usage: results_check.py DIR MODE NAME...   (MODE: compare or sweep; NAME: the entries' names)
"""
import csv
import json
import os
import sys

TOTALS = ["tests.total", "tests.brute_force", "share", "time_ms.frame"]


def fail(message):
    print(f"results_check: {message}")
    sys.exit(1)


def main():
    directory, mode, names = sys.argv[1], sys.argv[2], sys.argv[3:]
    doc = json.load(open(os.path.join(directory, "results.json")))
    if doc.get("mode") != mode:
        fail(f"mode is {doc.get('mode')!r}, expected {mode!r}")
    entries = doc.get("entries", [])
    if [e.get("name") for e in entries] != names:
        fail(f"entries {[e.get('name') for e in entries]}, expected {names}")
    for e in entries:
        totals, stats = e.get("totals", {}), e.get("stats", {})
        for key in TOTALS:
            if not isinstance(totals.get(key), (int, float)):
                fail(f"{e['name']}: totals lack {key}")
        if totals["tests.brute_force"] <= 0 or totals["tests.total"] <= 0:
            fail(f"{e['name']}: empty totals {totals}")
        if abs(totals["share"] - totals["tests.total"] / totals["tests.brute_force"]) > 1e-6:
            fail(f"{e['name']}: share {totals['share']} is not tests.total / tests.brute_force")
        for key in ("tests.total", "tests.brute_force", "time_ms.frame", "rays.shadow"):
            if key not in stats:
                fail(f"{e['name']}: stats lack {key}")
        if stats["tests.total"] != totals["tests.total"]:
            fail(f"{e['name']}: totals and stats disagree on tests.total")
        if "accel" not in e.get("settings", {}):
            fail(f"{e['name']}: settings lack accel")
        if mode == "sweep" and not e.get("grid"):
            fail(f"{e['name']}: a sweep entry without its grid")
    if mode == "compare" and doc.get("images_identical") is not True:
        fail("images_identical is not true")
    if mode == "sweep":
        best = doc.get("best", {})
        if best.get("fewest_tests") not in names or best.get("fastest") not in names:
            fail(f"best {best} does not name grid points")
        fewest = min(entries, key=lambda e: e["totals"]["tests.total"])
        if fewest["totals"]["tests.total"] != next(
                e for e in entries if e["name"] == best["fewest_tests"])["totals"]["tests.total"]:
            fail("best.fewest_tests is not the fewest")

    with open(os.path.join(directory, "results.csv"), newline="") as f:
        rows = list(csv.DictReader(f))
    if [r["name"] for r in rows] != names:
        fail(f"CSV rows {[r['name'] for r in rows]}, expected {names}")
    for r, e in zip(rows, entries):
        for key in TOTALS:
            if key not in r or r[key] == "":
                fail(f"CSV {r['name']}: no {key}")
        if float(r["tests.total"]) != e["totals"]["tests.total"]:
            fail(f"CSV {r['name']}: tests.total differs from the JSON")
        if "rays.shadow" not in r:
            fail("CSV lacks the statistics columns")
        for key in e.get("grid", {}):
            if r.get(key) != e["grid"][key]:
                fail(f"CSV {r['name']}: grid column {key} is {r.get(key)!r}")
    print(f"results_check: {len(entries)} {mode} entries in JSON and CSV")


if __name__ == "__main__":
    main()
