#!/usr/bin/env python3
"""Plot the fields of a 2D LtN run from its VTU output: the particles (dots)
and the local mesh's nodes (squares) coloured by u, by the pointwise error,
and by region tag.

usage: python3 scripts/plot_fields_2d.py OUTPUT_DIR [LEVEL] [PNG]

Needs Debian's python3-vtk9 and python3-matplotlib.
"""
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from run_output import level_file, level_plot_arguments, run_name  # noqa: E402
from vtu_fields import read_vtu  # noqa: E402


directory, level, png = level_plot_arguments("fields")
xn, n = read_vtu(level_file(directory, "nonlocal_field", level))
xl, l = read_vtu(level_file(directory, "local_field", level))

keys = [k for k in ("u", "error") if k in n]
figure, axes = plt.subplots(1, len(keys) + 1, figsize=(5 * (len(keys) + 1), 4.2))
for axis, key in zip(axes, keys):
    low = min(n[key].min(), l[key].min())
    high = max(n[key].max(), l[key].max())
    axis.scatter(xl[:, 0], xl[:, 1], c=l[key], s=6, marker="s",
                 vmin=low, vmax=high)
    dots = axis.scatter(xn[:, 0], xn[:, 1], c=n[key], s=4, vmin=low, vmax=high)
    figure.colorbar(dots, ax=axis)
    axis.set_title(key + " (particles: dots, mesh nodes: squares)", fontsize=9)
    axis.set_aspect("equal")
axis = axes[-1]
axis.scatter(xn[:, 0], xn[:, 1], c=n["region"], s=5, cmap="tab10", vmin=0, vmax=9)
axis.scatter(xl[:, 0], xl[:, 1], c=l["region"], s=2, marker="s", cmap="tab10",
             vmin=0, vmax=9, alpha=0.3)
axis.set_title("region: 0 nonlocal (blue), 1 physical collar (orange),\n"
               "2 control collar (green), 3 overlap (red), 4 local (purple)",
               fontsize=8)
axis.set_aspect("equal")
figure.suptitle(f"{run_name(directory)}, level {level}")
figure.tight_layout()
figure.savefig(png, dpi=90)
print(f"wrote {png}")
