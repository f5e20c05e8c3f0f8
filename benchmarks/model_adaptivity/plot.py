"""Draw results.csv of run.py: per scene, the estimate and the true error of
`auto`'s final region against its particles (effectivity: their ratio),
and the wall time of each run.

usage: plot.py [--csv FILE] [--png FILE]

Needs Debian's python3-matplotlib.
"""
import argparse
import csv
import os

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt

here = os.path.dirname(os.path.abspath(__file__))
parser = argparse.ArgumentParser()
parser.add_argument("--csv", default=os.path.join(here, "results.csv"))
parser.add_argument("--png", default=os.path.join(here, "results.png"))
options = parser.parse_args()

with open(options.csv) as f:
    rows = list(csv.DictReader(f))
scenes = list(dict.fromkeys(r["scene"] for r in rows))

fig, (errors, times) = plt.subplots(1, 2, figsize=(12, 4.8))
for k, scene in enumerate(scenes):
    colour = f"C{k}"
    auto = [r for r in rows if r["scene"] == scene and r["run"] == "auto"]
    particles = [int(r["particles"]) for r in auto]
    errors.plot(particles, [float(r["true_error"]) for r in auto], "o-",
                color=colour, label=f"{scene}: true error")
    errors.plot(particles, [float(r["estimate"]) for r in auto], "x--",
                color=colour, label=f"{scene}: estimate")
    for r in auto:
        errors.annotate(f"tol {r['tolerance']}",
                        (int(r["particles"]), float(r["true_error"])),
                        fontsize=6, xytext=(3, 3), textcoords="offset points")
errors.set_xscale("log")
errors.set_yscale("log")
errors.set_xlabel("particles of the final region")
errors.set_ylabel("modeling error, relative to the energy norm")
errors.set_title("auto: estimate and true error (against the largest "
                 "admissible region)", fontsize=9)
errors.legend(fontsize=6)

labels, values, colours = [], [], []
for k, scene in enumerate(scenes):
    for r in rows:
        if r["scene"] == scene:
            name = r["run"] if r["run"] != "auto" else \
                f"auto {r['tolerance']}"
            labels.append(f"{scene}: {name}")
            values.append(float(r["total_s"]))
            colours.append(f"C{k}")
times.barh(range(len(values)), values, color=colours)
times.set_yticks(range(len(values)))
times.set_yticklabels(labels, fontsize=6)
times.invert_yaxis()
times.set_xscale("log")
times.set_xlabel("wall time of the whole run, s (one run each, 2-core "
                 "machine)")
times.set_title("time per run", fontsize=9)
fig.tight_layout()
fig.savefig(options.png, dpi=90)
print(f"wrote {options.png}")
