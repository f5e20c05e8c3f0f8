#!/usr/bin/env python3
"""Error against wall time for the 2D diffusion coupling, one curve per solver
method: runs parameter_files/diffusion_2d_convergence.prm once per method,
reads each run's summary.json, and writes results.csv and (with matplotlib)
error_vs_time.png next to this script.

usage: python3 run.py [--ltn PATH] [--levels N] [--out DIR] [--quick]
                     [--plot-only]

--quick runs two coarse levels (a smoke test that keeps the benchmark
working; its numbers mean nothing).
"""
import argparse
import csv
import json
import os
import subprocess
import sys

here = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.dirname(here))
from ltn_benchmark import REPOSITORY_ROOT, pyplot_or_exit, write_csv  # noqa: E402

# Not ltn_argument_parser(): --out here holds results.csv and the chart too.
parser = argparse.ArgumentParser()
parser.add_argument("--ltn",
                    default=os.path.join(REPOSITORY_ROOT, "build", "ltn"))
parser.add_argument("--levels", type=int, default=3)
parser.add_argument("--out", default=here)
parser.add_argument("--quick", action="store_true")
parser.add_argument("--plot-only", action="store_true",
                    help="redraw the chart from results.csv, run nothing")
args = parser.parse_args()

# One curve per solver of the optimality system (label: its settings).
methods = {
    "full space direct": ["Coupling/Method=full space direct"],
    "full space gmres": ["Coupling/Method=full space gmres"],
    "reduced space cg": ["Coupling/Method=reduced space cg"],
    "reduced space cg, surrogate block": [
        "Coupling/Method=reduced space cg",
        "Coupling/Nonlocal control block=surrogate extension"],
}
scene = os.path.join(REPOSITORY_ROOT, "parameter_files",
                     "diffusion_2d_convergence.prm")
levels = 2 if args.quick else args.levels
rows = []
for method, settings in ({} if args.plot_only else methods).items():
    out = os.path.join(args.out, "runs",
                       method.replace(",", "").replace(" ", "_"))
    subprocess.run([args.ltn, scene]
                   + [a for setting in settings for a in ("--set", setting)]
                   + ["--set", f"Discretization/Number of levels={levels}",
                    "--set", "Output/Write VTU=false",
                    "--output-dir", out],
                   check=True, stdout=subprocess.DEVNULL)
    with open(os.path.join(out, "summary.json")) as f:
        summary = json.load(f)
    for entry in summary["convergence"]:
        t = entry["timings"]
        rows.append({
            "method": method,
            "h": entry["h"],
            "eps": entry["horizon"],
            "particles": entry["n_nonlocal_dofs"],
            "fem_dofs": entry["n_local_dofs"],
            "controls": entry["n_controls"],
            "iterations": entry["solver"]["iterations"],
            "l2_error": entry["errors"]["coupled"]["l2"],
            "max_error": entry["errors"]["coupled"]["linf"],
            "solve_s": t["solve"],
            "wall_s": sum(v for k, v in t.items() if k != "output"),
        })

csv_path = os.path.join(args.out, "results.csv")
if args.plot_only:
    with open(csv_path) as f:
        rows = [{k: (v if k == "method" else float(v)) for k, v in r.items()}
                for r in csv.DictReader(f)]
else:
    write_csv(csv_path, rows)
    print(f"wrote {csv_path}")
for r in rows:
    print(f"{r['method']:34s} h={r['h']:<9.4g} "
          f"particles={int(r['particles']):<6d} "
          f"iter={int(r['iterations']):<4d} L2={r['l2_error']:.3e} "
          f"wall={r['wall_s']:.3f}s")

plt = pyplot_or_exit()
figure, axis = plt.subplots(figsize=(6, 4.5))
for method in methods:
    mine = [r for r in rows if r["method"] == method]
    axis.loglog([r["wall_s"] for r in mine], [r["l2_error"] for r in mine],
                "o-", label=method)
    # The levels' h once, on the slowest curve (the others share them).
    if method == "full space direct":
        for r in mine:
            axis.annotate(f"h={r['h']:.3g}", (r["wall_s"], r["l2_error"]),
                          fontsize=7, textcoords="offset points",
                          xytext=(4, 4))
axis.set_xlabel("wall time per level (s)")
axis.set_ylabel("coupled L2 error")
axis.set_title("2D diffusion coupling, eps = 1/8 fixed")
axis.grid(True, which="both", alpha=0.3)
axis.legend()
figure.tight_layout()
png_path = os.path.join(args.out, "error_vs_time.png")
figure.savefig(png_path, dpi=110)
print(f"wrote {png_path}")
