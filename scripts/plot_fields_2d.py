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
# Each model the run has (a scene may have one only): its points, fields,
# marker and size.
parts = []
for name, marker, size in (("local_field", "s", 6), ("nonlocal_field", "o", 4)):
    path = level_file(directory, name, level)
    if os.path.exists(path):
        parts.append((*read_vtu(path), marker, size))
if not parts:
    sys.exit(f"no nonlocal_field or local_field of level {level} in "
             f"{directory}")

keys = [k for k in ("u", "error") if all(k in p[1] for p in parts)]
figure, axes = plt.subplots(1, len(keys) + 1, figsize=(5 * (len(keys) + 1), 4.2))
for axis, key in zip(axes, keys):
    low = min(f[key].min() for _, f, _, _ in parts)
    high = max(f[key].max() for _, f, _, _ in parts)
    for x, f, marker, size in parts:
        dots = axis.scatter(x[:, 0], x[:, 1], c=f[key], s=size, marker=marker,
                            vmin=low, vmax=high)
    figure.colorbar(dots, ax=axis)
    axis.set_title(key + " (particles: dots, mesh nodes: squares)", fontsize=9)
    axis.set_aspect("equal")
axis = axes[-1]
for x, f, marker, size in parts:
    axis.scatter(x[:, 0], x[:, 1], c=f["region"], s=size / 2 + 1,
                 marker=marker, cmap="tab10", vmin=0, vmax=9,
                 alpha=0.3 if marker == "s" else 1)
axis.set_title("region: 0 nonlocal (blue), 1 physical collar (orange),\n"
               "2 control collar (green), 3 overlap (red), 4 local (purple)",
               fontsize=8)
axis.set_aspect("equal")
figure.suptitle(f"{run_name(directory)}, level {level}")
figure.tight_layout()
figure.savefig(png, dpi=90)
print(f"wrote {png}")
