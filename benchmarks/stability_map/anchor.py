#!/usr/bin/env python3
"""The 1D anchor of Diehl and Prudhomme (issue 53): their bar (nonlocal on
[1, 2] of [0, 3], eps = 2h, a quartic with both right-hand sides -u'') run
by every coupling LtN has, at h = 1/16 ... 1/128 with the overlap one mesh
size wide. Their measure: the max over the nodes of the difference to the
classical solution, which 1D FE_Q(1) reproduces at the nodes (so: the
nodal error against the exact quartic). Their matching-displacement
coupling gave 1.54e-3, 3.73e-4, 9.19e-5, 2.28e-5. Then, at h = 1/64, the
overlap widened to 1/16, 1/8 and 1/4, where the methods part. Writes
anchor.csv next to this script and prints both tables.

usage: python3 anchor.py [--ltn PATH] [--out DIR]
"""
import math
import os
import subprocess
import sys

here = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.dirname(here))
sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(here)),
                                "scripts"))
from ltn_benchmark import ltn_argument_parser, write_csv  # noqa: E402
from vtu_fields import read_vtu  # noqa: E402
from couplings import COUPLINGS  # noqa: E402

parser = ltn_argument_parser(os.path.join(here, "runs"))
args = parser.parse_args()

# LtN by its full-space solver: one direct solve, like blending's.
METHODS = dict(COUPLINGS, LtN="full space direct")
MESH_SIZES = [1 / 16, 1 / 32, 1 / 64, 1 / 128]
THEIRS = [1.54e-3, 3.73e-4, 9.19e-5, 2.28e-5]


def nodal_error(out):
    """max |u_h - u| over the local model's nodes and the nonlocal model's
    nodes in [1, 2] (its collar holds controls, not its solution)."""
    worst = 0.0
    for kind, keep in (("local_field", lambda x: True),
                       ("nonlocal_field", lambda x: 1 - 1e-9 <= x <= 2 + 1e-9)):
        points, fields = read_vtu(os.path.join(out,
                                               f"{kind}_level-00.pvtu"))
        for x, e in zip(points[:, 0], fields["error"]):
            if keep(x):
                worst = max(worst, abs(e))
    return worst


def run(method, h, overlap):
    """The anchor's row of `method` at mesh size `h` and overlap width
    `overlap`."""
    out = os.path.join(args.out, f"anchor_{method}_{round(1 / h)}_"
                       f"{round(overlap / h)}".replace(" ", "_"))
    command = [args.ltn, os.path.join(here, "diehl_prudhomme_1d.prm"),
               "--output-dir", out,
               "--set", f"Coupling/Method={METHODS[method]}",
               "--set", f"Discretization/Mesh size={h}",
               "--set", f"Geometry/Overlap width={overlap}",
               "--set", "Coupling/Relative tolerance=1e-12",
               "--set", "Coupling/Maximum iterations=20000"]
    subprocess.run(command, check=True, capture_output=True)
    return {"method": method, "h": h, "overlap": overlap,
            "nodal_error": nodal_error(out)}


WIDE_H = 1 / 64
OVERLAPS = [1 / 64, 1 / 16, 1 / 8, 1 / 4]
rows = [run(method, h, h) for method in METHODS for h in MESH_SIZES]
rows += [run(method, WIDE_H, w) for method in METHODS for w in OVERLAPS[1:]]

write_csv(os.path.join(here, "anchor.csv"), rows)
narrow = [r for r in rows if r["overlap"] == r["h"]]
print("| h | " + " | ".join(METHODS) + " | Diehl & Prudhomme (MDCM) |")
print("|---" * (len(METHODS) + 2) + "|")
for i, h in enumerate(MESH_SIZES):
    errors = [r["nodal_error"] for r in narrow if r["h"] == h]
    print(f"| 1/{round(1 / h)} | " + " | ".join(f"{e:.3g}" for e in errors)
          + f" | {THEIRS[i]:.3g} |")
for method in METHODS:
    errors = [r["nodal_error"] for r in narrow if r["method"] == method]
    rates = [math.log2(a / b) for a, b in zip(errors, errors[1:])]
    print(f"{method}: rates " + ", ".join(f"{r:.2f}" for r in rates))

print(f"\nh = 1/{round(1 / WIDE_H)}, nodal error by overlap width:")
print("| overlap | " + " | ".join(METHODS) + " |")
print("|---" * (len(METHODS) + 1) + "|")
for w in OVERLAPS:
    errors = [r["nodal_error"] for r in rows
              if r["h"] == WIDE_H and r["overlap"] == w]
    print(f"| 1/{round(1 / w)} | " + " | ".join(f"{e:.3g}" for e in errors)
          + " |")
