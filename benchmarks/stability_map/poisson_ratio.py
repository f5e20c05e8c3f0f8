#!/usr/bin/env python3
"""The Poisson-ratio axis of the stability maps (issue 53): LPS coupled to
Navier-Cauchy on the 2D plates, LtN (reduced-space CG) against alternating
Schwarz (plain and with Aitken's relaxation), as the material nears
incompressibility. Per Poisson ratio and method: the quadratic patch test's
max error over max |u| (lps_plate_2d_quadratic_patch.prm), the iterations
(CG iterations or Schwarz updates) there and on the cracked plate
(lps_plate_2d_crack.prm), the cracked plate's crack-opening error against
its reference, and failure. Writes poisson_ratio.csv and poisson_ratio.png
next to this script.

usage: python3 poisson_ratio.py [--ltn PATH] [--out DIR] [--plot-only]
"""
import os
import subprocess
import sys

here = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.dirname(here))
from ltn_benchmark import (REPOSITORY_ROOT, ltn_argument_parser,  # noqa: E402
                           pyplot_or_exit, results_rows, run_ltn)
from couplings import COUPLINGS_LPS, failure_line  # noqa: E402

parser = ltn_argument_parser(os.path.join(here, "runs"))
parser.add_argument("--plot-only", action="store_true",
                    help="redraw poisson_ratio.png from the CSV, run nothing")
args = parser.parse_args()

METHODS = COUPLINGS_LPS
POISSON_RATIOS = [0.25, 0.45, 0.49, 0.499]
# max |u| of the patch scene's solution (1e-5 x^2, 0) on [0, 2] x [0, 1].
PATCH_MAX = 4e-5
FIELDS = ["method", "poisson_ratio", "patch_error", "patch_iterations",
          "crack_iterations", "opening_error", "status"]


def run(method, nu, scene):
    """summary.json's last level of `scene` with `method` at ratio `nu`."""
    out = os.path.join(args.out, f"lps_{scene}_{method}_{nu}".replace(" ", "_"))
    summary = run_ltn(args.ltn,
                      os.path.join(REPOSITORY_ROOT, "parameter_files",
                                   scene + ".prm"),
                      out,
                      [f"Coupling/Method={METHODS[method]}",
                       f"Material/Poisson ratio={nu}",
                       "Coupling/Maximum iterations=2000"])
    return summary.get("convergence", [summary])[-1]


def run_axis():
    """Every method at every Poisson ratio: the CSV's rows."""
    rows = []
    for method in METHODS:
        for nu in POISSON_RATIOS:
            row = {"method": method, "poisson_ratio": nu}
            scene = "patch"
            try:
                patch = run(method, nu, "lps_plate_2d_quadratic_patch")
                row["patch_error"] = (patch["errors"]["coupled"]["linf"]
                                      / PATCH_MAX)
                row["patch_iterations"] = patch["solver"]["iterations"]
                scene = "crack"
                crack = run(method, nu, "lps_plate_2d_crack")
                row["crack_iterations"] = crack["solver"]["iterations"]
                row["opening_error"] = crack["mechanics"]["crack_openings"][
                    0]["relative_l2_difference_to_reference"]
                row["status"] = "ok"
            except subprocess.CalledProcessError as error:
                row["status"] = f"failed ({scene}): " + failure_line(error)
            print(f"{method:17s} nu {nu}: "
                  + ", ".join(f"{k} {row[k]}" for k in FIELDS[2:]
                              if k in row), flush=True)
            rows.append({k: row.get(k, "") for k in FIELDS})
    return rows


rows = results_rows(os.path.join(here, "poisson_ratio.csv"), args.plot_only,
                    run_axis)

plt = pyplot_or_exit()
figure, axes = plt.subplots(1, 2, figsize=(10, 4), constrained_layout=True)
for axis, key, title in zip(axes, ("patch_iterations", "crack_iterations"),
                            ("quadratic patch plate", "cracked plate")):
    for method in METHODS:
        points = [(float(r["poisson_ratio"]), float(r[key])) for r in rows
                  if r["method"] == method and r[key] not in ("", None)]
        line, = axis.plot([1 / (0.5 - nu) for nu, _ in points],
                          [n for _, n in points], "o-", label=method)
        # A failed run: a cross at the top of the axis, in its colour.
        for r in rows:
            if (r["method"] == method and r[key] in ("", None)
                    and r["status"].startswith("failed")):
                nu = float(r["poisson_ratio"])
                axis.plot([1 / (0.5 - nu)], [1], "x", color=line.get_color(),
                          markersize=12, transform=axis.get_xaxis_transform(),
                          clip_on=False)
                axis.annotate("stalled" if "stalled" in r["status"]
                              else "failed", (1 / (0.5 - nu), 0.97),
                              xycoords=("data", "axes fraction"),
                              ha="right", va="top",
                              color=line.get_color())
    axis.set_xscale("log")
    axis.set_yscale("log")
    axis.set_xticks([1 / (0.5 - nu) for nu in POISSON_RATIOS],
                    [str(nu) for nu in POISSON_RATIOS])
    axis.set_xlabel("Poisson ratio (axis: 1 / (1/2 - nu))")
    axis.set_ylabel("iterations (CG) / Schwarz updates")
    axis.set_title(f"LPS coupled to Navier-Cauchy: {title}")
    axis.legend()
figure.savefig(os.path.join(here, "poisson_ratio.png"), dpi=110)
