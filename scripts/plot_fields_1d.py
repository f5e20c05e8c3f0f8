#!/usr/bin/env python3
"""Plot the fields of a 1D LtN run from its VTU output: the nonlocal and the
local solution with the exact one, the pointwise errors, and the region tags.

usage: python3 scripts/plot_fields_1d.py OUTPUT_DIR [LEVEL] [PNG]

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

REGIONS = ["nonlocal", "physical collar", "control collar", "overlap", "local"]


def read_sorted(path):
    """The x coordinates, left to right, and the fields in that order."""
    points, fields = read_vtu(path)
    order = points[:, 0].argsort()
    return points[order, 0], {k: v[order] for k, v in fields.items()}

directory, level, png = level_plot_arguments("fields")

xn, n = read_sorted(level_file(directory, "nonlocal_field", level))
xl, l = read_sorted(level_file(directory, "local_field", level))

figure, (top, middle, bottom) = plt.subplots(
    3, 1, sharex=True, figsize=(8, 7), height_ratios=[3, 2, 1])
top.plot(xn, n["u"], "o-", ms=3, label="nonlocal $u_n$")
top.plot(xl, l["u"], "s-", ms=3, label="local $u_l$")
if "u_exact" in n:
    top.plot(xn, n["u_exact"], "k:", label="exact")
    top.plot(xl, l["u_exact"], "k:")
    middle.semilogy(xn, abs(n["error"]) + 1e-300, "o-", ms=3, label="$|u_n - u|$")
    middle.semilogy(xl, abs(l["error"]) + 1e-300, "s-", ms=3, label="$|u_l - u|$")
    middle.set_ylabel("error at nodes")
    middle.legend()
top.set_ylabel("u")
top.legend()
for x, f, marker, label in ((xn, n, "o", "nonlocal mesh"),
                            (xl, l, "s", "local mesh")):
    bottom.scatter(x, f["region"], marker=marker, s=12, label=label)
bottom.set_yticks(range(len(REGIONS)), REGIONS, fontsize=7)
bottom.set_xlabel("x")
bottom.legend(fontsize=7, loc="upper right")
figure.suptitle(f"{run_name(directory)}, level {level}")
figure.tight_layout()
figure.savefig(png, dpi=110)
print(f"wrote {png}")
