#!/usr/bin/env python3
"""Plot the model-error indicator of a 2D LtN run (Postprocess/Model error
estimate) from its VTU output: each point's term of the estimate on a log
scale, the strip along Dirichlet faces (left out of the estimate) greyed,
and the outline of the nonlocal region's particles.

usage: python3 scripts/plot_model_error_2d.py OUTPUT_DIR [LEVEL] [PNG]

Needs Debian's python3-vtk9 and python3-matplotlib.
"""
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from run_output import level_file, level_plot_arguments, run_name  # noqa: E402
from vtu_fields import read_vtu  # noqa: E402

directory, level, png = level_plot_arguments("model_error")
x, fields = read_vtu(level_file(directory, "model_error", level))
term = fields["model_error_indicator"]
strip = fields["boundary_layer"] > 0.5
particles = level_file(directory, "particles", level)
if not os.path.exists(particles):
    particles = level_file(directory, "nonlocal_field", level)
xn, n = read_vtu(particles)
inside = n["region"] == 0

fig, ax = plt.subplots(figsize=(7, 6))
floor = max(term[~strip].max() * 1e-6, 1e-300)
shown = ax.scatter(x[~strip, 0], x[~strip, 1],
                   c=np.log10(np.maximum(term[~strip], floor)), s=3,
                   cmap="viridis")
ax.scatter(x[strip, 0], x[strip, 1], c="lightgrey", s=3,
           label="strip along Dirichlet faces (reported apart)")
ax.scatter(xn[inside, 0], xn[inside, 1], c="white", s=1,
           label="nonlocal region (no terms)")
fig.colorbar(shown, ax=ax,
             label="log10 of the point's term V |r|^2 / chi / c_G")
ax.set_aspect("equal")
ax.set_title(f"{run_name(directory)}: "
             f"model-error indicator, level {level}", fontsize=10)
ax.legend(loc="lower left", fontsize=7, markerscale=4)
fig.tight_layout()
fig.savefig(png, dpi=90)
print(f"wrote {png}")
