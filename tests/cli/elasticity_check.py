"""Run an elasticity scene and check what it must show.

usage: elasticity_check.py --ltn LTN [--mpiexec MPIEXEC --np N] --prm PRM
           --out DIR [--set S]... CHECK [ARGS...]

CHECK is one of
  patch MAX_U TOL        relative max error (coupled, nonlocal, local) <= TOL,
                         relative to MAX_U = max |u| over the body
  rate MIN               observed coupled L2 rates of every level >= MIN
  forces TOL             the axial force through every section plane equals
                         the applied resultant (sum over the loaded faces)
                         within TOL relative; so does the mean axial stress
  openings REFERENCE TOL the crack openings equal those of REFERENCE (a
                         summary.json of the same crack) within TOL (relative
                         L2 over the crack faces)
  classical MAX          report the relative L2 difference of the opening to
                         the scene's reference profile, and check it <= MAX
"""
import argparse
import json
import math
import os
import subprocess
import sys

parser = argparse.ArgumentParser()
parser.add_argument("--ltn", required=True)
parser.add_argument("--mpiexec")
parser.add_argument("--np", type=int, default=1)
parser.add_argument("--prm", required=True)
parser.add_argument("--out", required=True)
parser.add_argument("--set", action="append", default=[])
parser.add_argument("check")
parser.add_argument("args", nargs="*")
options = parser.parse_args()

command = [options.ltn, options.prm, "--output-dir", options.out,
           "--set", "Output/Write VTU=false"]
for assignment in options.set:
    command += ["--set", assignment]
if options.np > 1:
    command = [options.mpiexec, "-np", str(options.np)] + command
run = subprocess.run(command, capture_output=True, text=True)
print(run.stdout[-3000:])
if run.returncode != 0:
    sys.exit(f"ltn failed ({run.returncode}): {run.stderr[-3000:]}")
summary = json.load(open(os.path.join(options.out, "summary.json")))
mechanics = summary.get("mechanics", {})


def check(condition, message):
    print(("ok:     " if condition else "FAILED: ") + message)
    if not condition:
        sys.exit(1)


def openings(s):
    return [(tuple(round(c, 9) for c in p), o)
            for crack in s["mechanics"]["crack_openings"]
            for p, o in zip(crack["points"], crack["opening"])]


if options.check == "patch":
    max_u, tolerance = map(float, options.args)
    for part in ("coupled", "nonlocal", "local"):
        error = summary["errors"][part]["linf"] / max_u
        check(error <= tolerance,
              f"{part} relative max error {error:.3g} <= {tolerance}")
elif options.check == "rate":
    minimum = float(options.args[0])
    levels = summary["convergence"]
    check(len(levels) >= 3, f"{len(levels)} levels")
    for level in levels[1:]:
        rate = level["rates"]["coupled"]["l2"]
        check(rate >= minimum,
              f"h = {level['h']}: coupled L2 error "
              f"{level['errors']['coupled']['l2']:.3g}, rate {rate:.3f} "
              f">= {minimum}")
elif options.check == "forces":
    tolerance = float(options.args[0])
    applied = sum(abs(f["force"][0]) for f in mechanics["applied_forces"])
    check(applied > 0, f"applied axial resultant {applied:.6g}")
    for section in mechanics["section_forces"]:
        force = section["force"][0]
        difference = abs(force - applied) / applied
        check(difference <= tolerance,
              f"force through {section['plane']}: {force:.8g}, "
              f"relative difference {difference:.3g} <= {tolerance}")
    areas = [abs(s["force"][0] / s["mean_stress"])
             for s in mechanics["section_forces"]]
    for section, area in zip(mechanics["section_forces"], areas):
        traction = applied / area
        difference = abs(section["mean_stress"] - traction) / traction
        check(difference <= tolerance,
              f"mean axial stress at {section['plane']}: "
              f"{section['mean_stress']:.8g} against the applied traction "
              f"{traction:.8g}, relative difference {difference:.3g}")
elif options.check == "openings":
    reference = dict(openings(json.load(open(options.args[0]))))
    tolerance = float(options.args[1])
    pairs = [(o, reference[p]) for p, o in openings(summary) if p in reference]
    check(len(pairs) > 0 and len(pairs) == len(reference),
          f"{len(pairs)} points of the crack faces in both runs")
    difference = math.sqrt(sum((a - b) ** 2 for a, b in pairs) /
                           sum(b * b for _, b in pairs))
    check(difference <= tolerance,
          f"crack opening against the reference: relative L2 difference "
          f"{difference:.3g} <= {tolerance}; max opening "
          f"{max(a for a, _ in pairs):.6g} against "
          f"{max(b for _, b in pairs):.6g}")
elif options.check == "classical":
    maximum = float(options.args[0])
    for crack in mechanics["crack_openings"]:
        difference = crack["relative_l2_difference_to_reference"]
        check(difference <= maximum,
              f"crack opening against the classical profile: relative L2 "
              f"difference {difference:.3g} (<= {maximum})")
else:
    sys.exit(f"unknown check {options.check}")
