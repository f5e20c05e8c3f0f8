"""Scaling of the coupled solve with the number of peridynamic particles.

usage: run.py [--ltn build/ltn] [--out DIR] [--scenes 1e4 3e4 ...]
              [--ranks 1 2] [--csv FILE] [--png FILE] [--reuse]

Runs benchmarks/scaling/lps_bar_3d_<N>.prm (the cracked tensile bar of
parameter_files/lps_bar_3d_tensile_crack.prm with finer particle lattices;
matrix-free LPS, reduced-space CG with AMG-preconditioned CG in the particle
model and the FEM model factorized)
on each number of MPI ranks. Writes per run the particle and FEM sizes, the
wall time per phase (and of the control preconditioner's setup, and of
solving each model once alone with the same solvers, from zero, after the
coupled solve (`Coupling/Time standalone solves`): the standalone cost the
coupled solve, without them, is compared with), the outer and inner iterations, the peak memory (summed
over ranks) and the bytes per particle to results.csv, and a log-log chart of
solve time against particles with the fitted slope to scaling.png. With
--reuse, runs whose summary.json exists in DIR are read, not rerun, and
missing ones are skipped (to chart a run of the 10^6 scene made apart, e.g.
`mpirun -np 2 build/ltn benchmarks/scaling/lps_bar_3d_1e6.prm --output-dir
benchmarks/scaling/runs/1e6_np2 --set "Coupling/Time standalone solves=true"`,
about two minutes on two cores, with the others).
"""
import json
import math
import os
import subprocess
import sys

here = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.dirname(here))
from ltn_benchmark import ltn_argument_parser, write_csv  # noqa: E402
parser = ltn_argument_parser(default_out=os.path.join(here, "runs"))
parser.add_argument("--scenes", nargs="+", default=["1e4", "3e4"])
parser.add_argument("--ranks", type=int, nargs="+", default=[1])
parser.add_argument("--csv", default=os.path.join(here, "results.csv"))
parser.add_argument("--png", default=os.path.join(here, "scaling.png"))
parser.add_argument("--reuse", action="store_true")
options = parser.parse_args()

environment = dict(os.environ, OMP_NUM_THREADS="1", OPENBLAS_NUM_THREADS="1",
                   OMPI_ALLOW_RUN_AS_ROOT="1",
                   OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
rows = []
for ranks in options.ranks:
    for name in options.scenes:
        scene = os.path.join(here, f"lps_bar_3d_{name}.prm")
        out = os.path.join(options.out, f"{name}_np{ranks}")
        command = [options.ltn, scene, "--output-dir", out,
                   "--set", "Output/Write VTU=false",
                   "--set", "Coupling/Time standalone solves=true"]
        if ranks > 1:
            command = ["mpirun", "-np", str(ranks), "--oversubscribe"] + \
                command
        summary = os.path.join(out, "summary.json")
        if options.reuse:
            if not os.path.exists(summary):
                continue
        else:
            subprocess.run(command, check=True, capture_output=True,
                           env=environment)
        s = json.load(open(summary))
        models = s["solver"].get("model solvers", {})
        rows.append({
            "scene": name,
            "ranks": ranks,
            "particles": round(s["n_nonlocal_dofs"] / 4),
            "particle_dofs": s["n_nonlocal_dofs"],
            "local_dofs": s["n_local_dofs"],
            "controls": s["n_controls"],
            "assemble_nonlocal_s": round(s["timings"]["assemble nonlocal"], 2),
            # The coupled solve, without the standalone solves timed after
            # it (Coupling/Time standalone solves).
            "solve_s": round(s["timings"]["solve"] - sum(
                p["seconds"] for p in s["solver"].get("phases", [])
                if p["name"] == "standalone solves"), 2),
            "preconditioner_setup_s": round(s["solver"].get(
                "control preconditioner", {}).get("setup seconds", 0), 2),
            "standalone_s": round(s["solver"].get(
                "standalone model solves seconds", 0), 2),
            "total_s": round(s["timings"]["total"], 2),
            "outer_iterations": s["solver"]["iterations"],
            "nonlocal_iterations_per_solve":
                round(models.get("nonlocal", {}).get(
                    "iterations per solve", 0), 1),
            "local_iterations_per_solve":
                round(models.get("local", {}).get(
                    "iterations per solve", 0), 1),
            "peak_memory_mb": round(s["memory_mb"]),
            "bytes_per_particle":
                round(s["memory"].get("bytes per particle", 0)),
            "max_crack_opening":
                f"{s['mechanics']['crack_openings'][0]['max_opening']:.6g}",
        })
        print(rows[-1], flush=True)

write_csv(options.csv, rows)

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt

figure, axes = plt.subplots(figsize=(6, 4.5))
for ranks in options.ranks:
    mine = [r for r in rows if r["ranks"] == ranks]
    n = [r["particles"] for r in mine]
    t = [r["solve_s"] for r in mine]
    label = f"{ranks} rank{'s' if ranks > 1 else ''}"
    if len(mine) > 1:
        # Least-squares slope of log t against log n.
        x = [math.log(v) for v in n]
        y = [math.log(v) for v in t]
        mx, my = sum(x) / len(x), sum(y) / len(y)
        slope = sum((a - mx) * (b - my) for a, b in zip(x, y)) / \
            sum((a - mx) ** 2 for a in x)
        label += f", fitted slope {slope:.2f}"
        print(f"{ranks} ranks: fitted slope of solve time {slope:.3f}")
    axes.loglog(n, t, "o-", label=label)
axes.set_xlabel("particles (with collar)")
axes.set_ylabel("solve wall time [s]")
axes.set_title("Cracked tensile bar, coupled LPS-FEM")
axes.grid(True, which="both", alpha=0.3)
axes.legend()
figure.tight_layout()
figure.savefig(options.png, dpi=120)
