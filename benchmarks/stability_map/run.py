#!/usr/bin/env python3
"""Stability maps of the couplings (issue 53): LtN's optimization-based
coupling and the baselines (alternating Schwarz, plain and with Aitken's
relaxation; force- and energy-based blending, in 2D on the particle lattice
of the whole body), on the same diffusion scenes (1D, or 2D on particles),
over the
overlap width in horizons and the horizon in mesh sizes. Per cell and method:
the quadratic patch test's error (FE_Q(2) on both sides, u = x^2), the L2
error on the sine scene and its rate over one halving of h at fixed eps/h
(eps -> 0), the iterations (LtN: reduced-space CG iterations; Schwarz:
sweeps; blending: 1, a direct solve), the 1D blendings' matrix asymmetry,
and whether the run failed (its one-line message). Writes
results.csv and maps.png (2D: results_2d.csv, maps_2d.png) next to this
script.

usage: python3 run.py [--ltn PATH] [--out DIR] [--dimension 1|2]
                      [--plot-only]
"""
import math
import os
import subprocess
import sys

here = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.dirname(here))
from ltn_benchmark import (REPOSITORY_ROOT, ltn_argument_parser,  # noqa: E402
                           pyplot_or_exit, results_rows, run_ltn)
from couplings import COUPLINGS, failure_line  # noqa: E402

parser = ltn_argument_parser(os.path.join(here, "runs"))
parser.add_argument("--dimension", type=int, choices=(1, 2), default=1,
                    help="1: the 1D scenes (results.csv, maps.png); 2: the "
                    "2D scenes on particles (results_2d.csv, maps_2d.png)")
parser.add_argument("--plot-only", action="store_true",
                    help="redraw the maps from the results, run nothing")
args = parser.parse_args()

METHODS = COUPLINGS
HORIZON_IN_MESH_SIZES = [1, 2, 4, 8]
OVERLAP_IN_HORIZONS = [0.5, 1, 2, 4, 8]
# The mesh size of the first level: in 1D the widest overlap (8 horizons
# of 8 mesh sizes) must still leave part of the nonlocal region [0, 1]; in
# 2D (particles at the mesh size's spacing) the cells with an overlap of
# half the region or more are not scenes.
MESH_SIZE = 1 / 128 if args.dimension == 1 else 1 / 32
if args.dimension == 1:
    PATCH = ["Nonlocal model/Finite element degree=2",
             "Local model/Finite element degree=2",
             "Diffusion data/Exact solution=x^2",
             "Diffusion data/Nonlocal right-hand side=-2",
             "Diffusion data/Local right-hand side=-2"]
else:
    # FE_Q(2) needs a particle per nodal spacing h/2.
    PATCH = ["Local model/Finite element degree=2",
             "Nonlocal model/Particle spacing to mesh size ratio=0.5",
             "Diffusion data/Exact solution=x^2 + x*y - 0.5*y^2 + x",
             "Diffusion data/Nonlocal right-hand side=-1",
             "Diffusion data/Local right-hand side=-1"]
PATCH.append("Discretization/Number of levels=1")
# max |u| of the patch test's solution over the body: the error's scale.
PATCH_MAX = 1.75**2 if args.dimension == 1 else 7.5
SMOOTH = ["Discretization/Number of levels=2"]
SCENES = {"patch": f"diffusion_{args.dimension}d_patch",
          "smooth": f"diffusion_{args.dimension}d_convergence"}
SUFFIX = "" if args.dimension == 1 else "_2d"


def cell_settings(method, eps_over_h, overlap_over_eps):
    """The --set arguments of one cell: the method, the level's mesh size,
    eps = m h at every level, the overlap width w = r eps of the first
    level (fixed as h halves), a tight tolerance and room for sweeps."""
    return [f"Coupling/Method={method}",
            f"Discretization/Mesh size={MESH_SIZE}",
            f"Nonlocal model/Horizon to mesh size ratio={eps_over_h}",
            "Geometry/Overlap width="
            f"{overlap_over_eps * eps_over_h * MESH_SIZE}",
            "Coupling/Relative tolerance=1e-12",
            "Coupling/Maximum iterations=2000"]


def run_cell(method, eps_over_h, overlap_over_eps):
    """One map cell of one method: a dict of its metrics."""
    row = {"method": method, "eps_over_h": eps_over_h,
           "overlap_over_eps": overlap_over_eps}
    for name, scene in SCENES.items():
        out = os.path.join(args.out, f"{args.dimension}d_{method}_{eps_over_h}_"
                           f"{overlap_over_eps}_{name}".replace(" ", "_"))
        settings = cell_settings(METHODS[method], eps_over_h,
                                 overlap_over_eps)
        settings += PATCH if name == "patch" else SMOOTH
        prm = os.path.join(REPOSITORY_ROOT, "parameter_files",
                           scene + ".prm")
        try:
            summary = run_ltn(args.ltn, prm, out, settings)
            # A one-level run's summary is that level's record.
            levels = summary.get("convergence", [summary])
        except subprocess.CalledProcessError as error:
            # Exit status 2: the cell is not a valid scene (an overlap
            # thinner than the mesh); 1: the method failed on it.
            kind = "invalid" if error.returncode == 2 else "failed"
            row["status"] = f"{kind} ({name}): " + failure_line(error)
            return row
        if name == "patch":
            row["patch_error"] = (levels[-1]["errors"]["coupled"]["linf"]
                                  / PATCH_MAX)
        else:
            coarse, fine = (level["errors"]["coupled"]["l2"]
                            for level in levels)
            row["l2_error"] = fine
            row["l2_rate"] = math.log2(coarse / fine)
            row["iterations"] = max(level["solver"]["iterations"]
                                    for level in levels)
            # Blending's |K - K^T|_F / |K|_F on the finer level.
            row["asymmetry"] = levels[-1]["solver"].get("asymmetry", "")
    row["status"] = "ok"
    return row


FIELDS = ["method", "eps_over_h", "overlap_over_eps", "patch_error",
          "l2_error", "l2_rate", "iterations", "asymmetry", "status"]


def run_map():
    """Every cell of every method: the CSV's rows."""
    rows = []
    for method in METHODS:
        for m in HORIZON_IN_MESH_SIZES:
            for r in OVERLAP_IN_HORIZONS:
                row = run_cell(method, m, r)
                print(f"{method:17s} eps/h {m}  w/eps {r:4}: "
                      + ", ".join(f"{k} {row[k]:.3g}" for k in
                                  ("patch_error", "l2_error", "l2_rate",
                                   "iterations") if k in row)
                      + f" [{row['status']}]", flush=True)
                rows.append({k: row.get(k, "") for k in FIELDS})
    return rows


rows = results_rows(os.path.join(here, f"results{SUFFIX}.csv"),
                    args.plot_only, run_map)

plt = pyplot_or_exit()
import numpy as np  # noqa: E402 (matplotlib's dependency)

# Per metric: its title, and the floor of its logarithmic colour scale
# (None: linear).
METRICS = [("patch_error", "quadratic patch test, max error / max |u|",
            1e-17),
           ("l2_error", f"L2 error, sine scene (h = 1/{round(2 / MESH_SIZE)})",
            1e-17),
           ("l2_rate", f"L2 rate, h 1/{round(1 / MESH_SIZE)} -> "
            f"1/{round(2 / MESH_SIZE)} (eps/h fixed)", None),
           ("iterations", "iterations (CG) / sweeps", 1)]
figure, axes = plt.subplots(len(METRICS), len(METHODS),
                            figsize=(4.2 * len(METHODS), 3.3 * len(METRICS)),
                            constrained_layout=True)
for i, (metric, title, floor) in enumerate(METRICS):
    grids = {}
    for method in METHODS:
        grid = np.full((len(HORIZON_IN_MESH_SIZES),
                        len(OVERLAP_IN_HORIZONS)), np.nan)
        for row in rows:
            if row["method"] != method or row[metric] in ("", None):
                continue
            a = HORIZON_IN_MESH_SIZES.index(int(float(row["eps_over_h"])))
            b = OVERLAP_IN_HORIZONS.index(float(row["overlap_over_eps"]))
            grid[a, b] = float(row[metric])
        grids[method] = grid
    shown = {m: (np.log10(np.maximum(g, floor)) if floor else g)
             for m, g in grids.items()}
    low = min(np.nanmin(s) for s in shown.values())
    high = max(np.nanmax(s) for s in shown.values())
    for j, method in enumerate(METHODS):
        axis = axes[i, j]
        image = axis.imshow(shown[method], origin="lower", cmap="YlGnBu",
                            vmin=low, vmax=high, aspect="auto")
        for a in range(len(HORIZON_IN_MESH_SIZES)):
            for b in range(len(OVERLAP_IN_HORIZONS)):
                value = grids[method][a, b]
                status = next((row["status"] for row in rows
                               if row["method"] == method
                               and int(float(row["eps_over_h"]))
                               == HORIZON_IN_MESH_SIZES[a]
                               and float(row["overlap_over_eps"])
                               == OVERLAP_IN_HORIZONS[b]), "")
                text = (status.split(" ")[0] if not np.isfinite(value)
                        else f"{value:.2g}" if metric != "iterations"
                        else f"{value:.0f}")
                axis.text(b, a, text, ha="center", va="center", fontsize=7,
                          color="black" if np.isfinite(value) else "red")
        axis.set_xticks(range(len(OVERLAP_IN_HORIZONS)),
                        [f"{r:g}" for r in OVERLAP_IN_HORIZONS])
        axis.set_yticks(range(len(HORIZON_IN_MESH_SIZES)),
                        [str(m) for m in HORIZON_IN_MESH_SIZES])
        axis.set_xlabel("overlap width / horizon")
        axis.set_ylabel("horizon / mesh size")
        axis.set_title(f"{method}: {title}", fontsize=8)
    figure.colorbar(image, ax=axes[i, :],
                    label=("log10 " if floor else "") + metric)
figure.savefig(os.path.join(here, f"maps{SUFFIX}.png"), dpi=110)
