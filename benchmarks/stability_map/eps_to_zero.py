#!/usr/bin/env python3
"""The eps -> 0 axis of the stability maps (issue 53): the 1D sine scene
with eps = 2h and the overlap one mesh size wide, h = 1/16 ... 1/512, every
coupling at Coupling/Maximum iterations' default (1000) and a relative
tolerance of 1e-10. doc/baseline_couplings.md ('A nonlocal model and an
overlap thinner than the horizon') predicts plain Schwarz's sweeps to grow
like 1/h there and pass the limit near h = 1/128. Per mesh size and method:
the iterations (CG, sweeps, or one solve), the L2 error, and failure.
Writes eps_to_zero.csv next to this script and prints the table.

usage: python3 eps_to_zero.py [--ltn PATH] [--out DIR]
"""
import os
import subprocess
import sys

here = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.dirname(here))
from ltn_benchmark import (REPOSITORY_ROOT, ltn_argument_parser,  # noqa: E402
                           run_ltn, write_csv)
from couplings import COUPLINGS, failure_line  # noqa: E402

parser = ltn_argument_parser(os.path.join(here, "runs"))
args = parser.parse_args()

METHODS = COUPLINGS
MESH_SIZES = [1 / 16, 1 / 32, 1 / 64, 1 / 128, 1 / 256, 1 / 512]

rows = []
for method, name in METHODS.items():
    for h in MESH_SIZES:
        row = {"method": method, "h": h}
        out = os.path.join(args.out, f"eps0_{method}_{round(1 / h)}"
                           .replace(" ", "_"))
        try:
            summary = run_ltn(
                args.ltn,
                os.path.join(REPOSITORY_ROOT, "parameter_files",
                             "diffusion_1d_convergence.prm"),
                out,
                [f"Coupling/Method={name}",
                 f"Discretization/Mesh size={h}",
                 "Discretization/Number of levels=1",
                 "Nonlocal model/Horizon to mesh size ratio=2",
                 f"Geometry/Overlap width={h}",
                 "Coupling/Relative tolerance=1e-10"])
            row["iterations"] = summary["solver"]["iterations"]
            row["l2_error"] = summary["errors"]["coupled"]["l2"]
            row["status"] = "ok"
        except subprocess.CalledProcessError as error:
            row["status"] = failure_line(error)
        rows.append({k: row.get(k, "") for k in
                     ("method", "h", "iterations", "l2_error", "status")})
        print(f"{method:17s} h 1/{round(1 / h)}: "
              + ", ".join(f"{k} {row[k]}" for k in ("iterations", "l2_error")
                          if k in row)
              + f" [{row['status'][:100]}]", flush=True)
write_csv(os.path.join(here, "eps_to_zero.csv"), rows)
