#!/usr/bin/env python3
"""Plot the cycles of a 2D LtN run with `Geometry/Nonlocal regions = auto`:
per model cycle, each block's indicator eta_K^2 (relative to the cycle's
eta^2, log scale), the region's boxes outlined, and the cycle's estimate
against the tolerance (and its true error, if the run has one).

usage: python3 scripts/plot_model_cycles_2d.py OUTPUT_DIR [PNG]

Needs Debian's python3-vtk9 and python3-matplotlib.
"""
import json
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.patches as patches
import matplotlib.pyplot as plt
import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from run_output import level_file  # noqa: E402
from vtu_fields import read_vtu  # noqa: E402

directory = sys.argv[1]
png = sys.argv[2] if len(sys.argv) > 2 else os.path.join(
    directory, "model_cycles.png")
with open(os.path.join(directory, "summary.json")) as f:
    summary = json.load(f)
loop = summary["model_adaptivity"]
cycles = loop["cycles"]
size = loop["block_size"]

fig, axes = plt.subplots(1, len(cycles), figsize=(4.6 * len(cycles), 4.6),
                         squeeze=False)
for ax, cycle in zip(axes[0], cycles):
    x, fields = read_vtu(
        level_file(directory, "model_error", cycle["level_entry"]))
    # One value per block: every point of a block carries its eta_K^2.
    blocks = {}
    for p, value in zip(x, fields["block_indicator"]):
        blocks[(int(p[0] // size), int(p[1] // size))] = value
    total = sum(blocks.values())
    shown = None
    for (i, j), value in blocks.items():
        if value <= 0:
            continue
        shade = np.clip(np.log10(value / total), -5, 0)
        shown = ax.add_patch(patches.Rectangle(
            (i * size, j * size), size, size,
            color=plt.cm.viridis((shade + 5) / 5)))
    for box in cycle["boxes"]:
        ax.add_patch(patches.Rectangle(
            (box[0], box[1]), box[2] - box[0], box[3] - box[1],
            fill=False, edgecolor="red", linewidth=1))
    ax.autoscale_view()
    ax.set_aspect("equal")
    true = cycle["true_error"]
    ax.set_title(
        f"cycle {cycle['cycle']}: {cycle['blocks']} blocks, "
        f"{cycle['particles']} particles\nestimate {cycle['estimate']:.2e} "
        f"(tol {loop['tolerance']:.0e})"
        + (f", true {true:.2e}" if true is not None else ""), fontsize=8)
mappable = plt.cm.ScalarMappable(cmap="viridis",
                                 norm=matplotlib.colors.Normalize(-5, 0))
fig.colorbar(mappable, ax=axes[0].tolist(), shrink=0.8,
             label="log10 of the block's share of eta^2")
fig.suptitle(f"{summary['scene']}: Nonlocal regions = auto "
             "(region outlined in red)", fontsize=10)
fig.savefig(png, dpi=90)
print(f"wrote {png}")
