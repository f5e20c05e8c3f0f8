"""Error near the crack against wall time: coupled solves and all-peridynamic.

usage: run.py [--ltn build/ltn] [--out DIR]
              [--scenes plate_2d plate_2d_side_4 bar_3d]
              [--csv FILE] [--png FILE] [--png-all FILE] [--reuse]
              [--only RUN ...] [--plot-only]

For each scene, runs a sequence of resolutions (the particle spacing halves,
the horizon stays two spacings) with every solver of the coupled problem and
with LPS on the whole body ("all peridynamic", `Geometry/Models = nonlocal
only`) at the same spacing. The error is that of the maximum crack opening,
relative to a reference: the Richardson extrapolation of the openings of
the three finest resolutions of the scene's reference solver, an
all-peridynamic one to a tight tolerance (the observed order is printed and
written to the CSV). For each coupled run it prints the time the
all-peridynamic solve would take at the same error, along the line through
the two finest points of the scene's equal-error line, the all-peridynamic
CG to a tolerance sized to the error. Writes results.csv (one row per run),
error_vs_time.png (error against wall time of the whole run, one panel per
scene, the best coupled and the best all-peridynamic curve in each) and
error_vs_time_all.png (every curve). --plot-only redraws both charts from
results.csv and runs nothing.
"""
import csv
import json
import math
import os
import re
import sys
import textwrap

here = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.dirname(here))
from ltn_benchmark import (REPOSITORY_ROOT, ltn_argument_parser,  # noqa: E402
                           run_ltn, write_csv)
from plate_scene import centred_plate  # noqa: E402
parser = ltn_argument_parser(default_out=os.path.join(here, "runs"))
parser.add_argument("--scenes", nargs="+",
                    default=["plate_2d", "plate_2d_side_4", "bar_3d"])
parser.add_argument("--csv", default=os.path.join(here, "results.csv"))
parser.add_argument("--png", default=os.path.join(here, "error_vs_time.png"),
                    help="the chart of each scene's best two curves")
parser.add_argument("--png-all",
                    default=os.path.join(here, "error_vs_time_all.png"),
                    help="the chart of every curve")
parser.add_argument("--reuse", action="store_true",
                    help="keep the runs whose summary.json exists (resume)")
parser.add_argument("--only", nargs="+", metavar="RUN",
                    help="run only these curves (their names as in the CSV; "
                    "each scene run needs its reference and its "
                    "equal-error line)")
parser.add_argument("--plot-only", action="store_true",
                    help="redraw the charts from the CSV, run nothing")
options = parser.parse_args()

all_peridynamic = ["Geometry/Models=nonlocal only"]
direct = ["Coupling/Model solvers=direct"]
scalable = ["Coupling/Model solvers=preconditioned gmres",
            "Nonlocal model/Operator=matrix-free",
            "Coupling/Relative tolerance=1e-10",
            "Coupling/Model solver tolerance=1e-12"]
# The same with CG on the particle model's free block
# (doc/discretization.md, 'Iterative model solvers').
# The finite element model factorized: one local solve per local coarse
# column and two per outer iteration, on a coarse mesh.
scalable_cg = scalable + ["Coupling/Model solvers=preconditioned cg",
                          "Coupling/Local model solver=direct"]
# The same to tolerances sized to the openings' errors (above 1e-4
# relative): they move by at most 7.3e-7 relative on the plate (HISTORY.md,
# eighth session) and 3.1e-6 on the bar at 1/64 (ninth session).
scalable_cg_loose = scalable_cg + ["Coupling/Relative tolerance=1e-6",
                                   "Coupling/Model solver tolerance=1e-8"]
# The all-peridynamic solve is one CG, whose tolerance is the model solver's
# alone (`Relative tolerance` is the coupled CG's): to 1e-8, and to 1e-6,
# sized to the openings' errors as the coupled CG's 1e-6 is (HISTORY.md, ninth
# session).
all_peridynamic_cg_to = {
    tolerance: all_peridynamic + scalable_cg +
    ["Coupling/Model solver tolerance=%g" % tolerance]
    for tolerance in (1e-8, 1e-6)}
# The full-space GMRES solves each model loosely inside its preconditioner,
# the finite element model factorized (with GMRES on it the plate at 1/160
# did not converge).
full_space_gmres = (["Coupling/Method=full space gmres"] + scalable +
                    ["Coupling/Model solver tolerance=1e-1",
                     "Coupling/Local model solver=direct"])
# The plate's nonlocal region sized to its crack: the local model's hole is
# the crack with one cell of the coarsest FEM mesh (1/20) beyond its tips and
# on either side, the overlap one such cell wide; the file's region leaves
# five cells on every side. The same openings to 1e-7 at 1/160 and 1/320
# (HISTORY.md, "The plate's nonlocal region sized to its crack").
sized_overlap = 0.05


def plate_region_sized_to_crack(side=2):
    """The sized region in the plate of side `side` (centred_plate())."""
    c = side / 2
    return ["Geometry/Nonlocal region lower corner=%g, %g" % (c - 0.35,
                                                               c - 0.1),
            "Geometry/Nonlocal region upper corner=%g, %g" % (c + 0.35,
                                                               c + 0.1),
            "Geometry/Overlap width=%g" % sized_overlap]


plate_prm = os.path.join(REPOSITORY_ROOT, "parameter_files",
                         "lps_plate_2d_crack.prm")
# Spacings 1/80 to 1/2560, halving, and one between the last two, 1/1920
# (level 5; a lattice that still fits the crack and the region): there the
# weighted coupled plate's error is the all-peridynamic plate's at 1/2560,
# its finest, so the two are compared at equal error, both measured.
plate_mesh_sizes = (0.05, 0.025, 0.0125, 0.00625, 0.003125, 0.003125 / 1.5,
                    0.0015625)
plate_halving_levels = [0, 1, 2, 3, 4, 6]
# The peak memory of the runs that need most of a 24 GB machine, measured
# (one rank): each is skipped, with a message, where less is available.
# The all-peridynamic plate at 1/2560 holds 79M unknowns.
peak_memory_gb = {
    ("plate_2d", "all peridynamic, cg matrix-free, tolerance 1e-6", 6): 22.2}


def available_memory_gb():
    """MemAvailable of /proc/meminfo, in GB (infinite where unknown)."""
    try:
        for line in open("/proc/meminfo"):
            if line.startswith("MemAvailable:"):
                return int(line.split()[1]) * 1024 / 1e9
    except OSError:
        pass
    return float("inf")


def prm_value(path, name):
    """The number a parameter file sets `name` to."""
    for line in open(path):
        match = re.match(r"\s*set\s+%s\s*=\s*(\S+)" % re.escape(name), line)
        if match:
            return float(match.group(1))
    raise KeyError(name + " in " + path)


def lattice_on_mesh(mesh_size, spacing, horizon):
    """The settings that put particles of `spacing` and `horizon` on FEM
    cells of `mesh_size` near the nonlocal region (the file's ratios are to
    the mesh size)."""
    return ["Discretization/Mesh size=%.12g" % mesh_size,
            "Nonlocal model/Particle spacing to mesh size ratio=%.12g" %
            (spacing / mesh_size),
            "Nonlocal model/Horizon to mesh size ratio=%.12g" %
            (horizon / mesh_size)]


def plate_fem_mesh_no_finer_than(coarsest):
    """A level's settings that keep the plate's particles (spacing and
    horizon the file's ratios to the level's mesh size) on an FEM mesh no
    finer than `coarsest`: the FEM model's error then stays far below the
    particles' (HISTORY.md, eighth session)."""
    spacing, horizon = [prm_value(plate_prm, name) for name in
                        ("Particle spacing to mesh size ratio",
                         "Horizon to mesh size ratio")]

    def settings(level):
        h = plate_mesh_sizes[level]
        if h >= coarsest:
            return []
        return lattice_on_mesh(coarsest, spacing * h, horizon * h)
    return settings


# The sized region on FEM cells no smaller than 1/80 near the overlap: at
# 1/640 the opening moves by 1.8e-6 relative (0.2 % of the error) and the
# FEM model has half the unknowns.
def plate_sized_fem_to_1_80(side=2):
    """The sized region, in the plate of side `side`, on FEM cells no
    smaller than 1/80."""
    return (["Coupling/Method=reduced space cg"] +
            plate_region_sized_to_crack(side) +
            [plate_fem_mesh_no_finer_than(0.0125)])


# `Coupling/Collar layer weight` and `Coupling/Crack opening coarse fields`:
# every run starts from 0 and `false`, the defaults until the thirteenth
# session, so that the curves measure what they measured before; the
# weighted curves take the weight `auto`, the default since (for LPS,
# 1.5 log2(w / (8 eps)) where the overlap w is more than 8 horizons eps
# wide: on the sized region from 1/640 on, 1.5, 3, 3.9 and 4.5 at 1/640,
# 1/1280, 1/1920 and 1/2560), and the last curves the crack opening field
# too (the default in 2D since the fourteenth session;
# doc/discretization.md, 'A coarse level for the controls').
baseline = ["Coupling/Collar layer weight=0",
            "Coupling/Crack opening coarse fields=false"]
collar_layer_weighted = ["Coupling/Collar layer weight=auto"]
with_crack_opening_field = collar_layer_weighted + [
    "Coupling/Crack opening coarse fields=true"]


bar_prm = os.path.join(here, "cracked_bar_3d.prm")
bar_mesh_size = prm_value(bar_prm, "Mesh size")
# Spacing 1/8 leaves the collar (two horizons deep) no room inside the bar.
bar_spacings = (1 / 16, 1 / 32, 1 / 64, 1 / 128)


def bar_particles_on(mesh_size, fe_degree=None, graded_layers=None):
    """A level's settings that put the bar's particles (the level's spacing,
    the horizon two spacings) on FEM cells of `mesh_size` near the nonlocal
    region, optionally of another degree and graded."""
    def settings(level):
        spacing = bar_spacings[level]
        local = []
        if fe_degree is not None:
            local.append("Local model/Finite element degree=%d" % fe_degree)
        if graded_layers is not None:
            local.append("Local model/Graded mesh layers=%d" % graded_layers)
        return lattice_on_mesh(mesh_size, spacing, 2 * spacing) + local
    return settings


# Per scene: its parameter file, its reference solver (the error's), its
# equal-error line (the fastest all-peridynamic solver at the errors in
# question), the settings of each resolution, and the runs: name ->
# (settings, the resolutions it runs at, by index).
scenes = {
    "plate_2d": {
        "prm": plate_prm,
        "reference": "all peridynamic, cg matrix-free, tolerance 1e-8",
        "equal-error line": "all peridynamic, cg matrix-free, tolerance 1e-6",
        "levels": [["Discretization/Mesh size=%.12g" % h]
                   for h in plate_mesh_sizes],
        "runs": {
            "all peridynamic, gmres matrix-free":
                (all_peridynamic + scalable, [0, 1, 2]),
            "all peridynamic, cg matrix-free":
                (all_peridynamic + scalable_cg, [0, 1, 2, 3]),
            # At 1/1280: 19.8M unknowns and 5.4 GB on one rank.
            "all peridynamic, cg matrix-free, tolerance 1e-8":
                (all_peridynamic_cg_to[1e-8], [0, 1, 2, 3, 4]),
            # At 1/2560: 79M unknowns, about 2 minutes and 22 GB.
            "all peridynamic, cg matrix-free, tolerance 1e-6":
                (all_peridynamic_cg_to[1e-6], plate_halving_levels),
            # The sparse LU of 1.2M particle dofs does not fit: two levels.
            "all peridynamic, direct": (all_peridynamic + direct, [0, 1]),
            # The saddle-point LU: 3.7 s and 30 s at the first two levels
            # (one rank, a 2-core Xeon); the third does not fit.
            "coupled, full space direct":
                (["Coupling/Method=full space direct"], [0, 1]),
            "coupled, reduced space cg, direct":
                (["Coupling/Method=reduced space cg"] + direct, [0, 1, 2]),
            # Level 1 took 43 s (one rank, a 2-core Xeon, 2026-12-06), four
            # times level 0; level 2 would take minutes more.
            "coupled, reduced space cg, gmres matrix-free":
                (["Coupling/Method=reduced space cg"] + scalable, [0, 1]),
            "coupled, reduced space cg, cg matrix-free":
                (["Coupling/Method=reduced space cg"] + scalable_cg,
                 [0, 1, 2, 3]),
            "coupled, reduced space cg, cg matrix-free, region sized to the "
            "crack": (["Coupling/Method=reduced space cg"] + scalable_cg +
                      plate_region_sized_to_crack(), [0, 1, 2, 3]),
            "coupled, reduced space cg, cg matrix-free, region sized to the "
            "crack, FEM cells at least 0.0125":
                (scalable_cg + plate_sized_fem_to_1_80(), [0, 1, 2, 3]),
            "coupled, reduced space cg, cg matrix-free, region sized to the "
            "crack, FEM cells at least 0.0125, tolerance 1e-6":
                (scalable_cg_loose + plate_sized_fem_to_1_80(),
                 plate_halving_levels),
            # The same with the collar layer weighted (doc/discretization.md,
            # 'A coarse level for the controls'), also at 1/1920.
            "coupled, reduced space cg, cg matrix-free, region sized to the "
            "crack, FEM cells at least 0.0125, tolerance 1e-6, collar layer "
            "weighted":
                (scalable_cg_loose + plate_sized_fem_to_1_80() +
                 collar_layer_weighted, [0, 1, 2, 3, 4, 5, 6]),
            "coupled, reduced space cg, cg matrix-free, region sized to the "
            "crack, FEM cells at least 0.0125, tolerance 1e-6, collar layer "
            "weighted, crack opening field":
                (scalable_cg_loose + plate_sized_fem_to_1_80() +
                 with_crack_opening_field, [0, 1, 2, 3, 4, 5, 6]),
            # 4.8 s and 23 s (one rank, a 2-core Xeon, 2026-12-06).
            "coupled, full space gmres, matrix-free":
                (full_space_gmres, [0, 1]),
        },
    },
    # The same crack in a plate twice as wide: the all-peridynamic solve
    # covers four times the area, the coupled one the same particles.
    "plate_2d_side_4": {
        "prm": plate_prm,
        "reference": "all peridynamic, cg matrix-free, tolerance 1e-8",
        "equal-error line": "all peridynamic, cg matrix-free, tolerance 1e-6",
        "levels": [["Discretization/Mesh size=%.12g" % h] + centred_plate(4)
                   for h in plate_mesh_sizes],
        "runs": {
            # At 1/640: 19.8M unknowns, as the plate of side 2 at 1/1280.
            "all peridynamic, cg matrix-free, tolerance 1e-8":
                (all_peridynamic_cg_to[1e-8], [0, 1, 2, 3]),
            "all peridynamic, cg matrix-free, tolerance 1e-6":
                (all_peridynamic_cg_to[1e-6], [0, 1, 2, 3]),
            "coupled, reduced space cg, cg matrix-free, region sized to the "
            "crack, FEM cells at least 0.0125, tolerance 1e-6":
                (scalable_cg_loose + plate_sized_fem_to_1_80(4),
                 [0, 1, 2, 3, 4]),
            "coupled, reduced space cg, cg matrix-free, region sized to the "
            "crack, FEM cells at least 0.0125, tolerance 1e-6, collar layer "
            "weighted":
                (scalable_cg_loose + plate_sized_fem_to_1_80(4) +
                 collar_layer_weighted, [0, 1, 2, 3, 4]),
            "coupled, reduced space cg, cg matrix-free, region sized to the "
            "crack, FEM cells at least 0.0125, tolerance 1e-6, collar layer "
            "weighted, crack opening field":
                (scalable_cg_loose + plate_sized_fem_to_1_80(4) +
                 with_crack_opening_field, [0, 1, 2, 3, 4]),
        },
    },
    "bar_3d": {
        "prm": bar_prm,
        "reference": "all peridynamic, cg matrix-free",
        "equal-error line": "all peridynamic, cg matrix-free, tolerance 1e-6",
        "levels": [bar_particles_on(bar_mesh_size)(level)
                   for level in range(len(bar_spacings))],
        "runs": {
            "all peridynamic, gmres matrix-free":
                (all_peridynamic + scalable, [0, 1, 2]),
            # Spacing 1/128 (7.2 million particles with the collar, 6.9 GB
            # on one rank) for the CG curves only.
            "all peridynamic, cg matrix-free":
                (all_peridynamic + scalable_cg, [0, 1, 2, 3]),
            "all peridynamic, cg matrix-free, tolerance 1e-6":
                (all_peridynamic_cg_to[1e-6], [0, 1, 2, 3]),
            # The 3D LU of the finest level's LPS matrix fills in.
            "coupled, reduced space cg, direct":
                (["Coupling/Method=reduced space cg"] + direct, [0, 1]),
            "coupled, reduced space cg, gmres matrix-free":
                (["Coupling/Method=reduced space cg"] + scalable, [0, 1, 2]),
            "coupled, reduced space cg, cg matrix-free":
                (["Coupling/Method=reduced space cg"] + scalable_cg,
                 [0, 1, 2, 3]),
            # FEM cells small enough that the FEM model's error does not
            # cancel the particles' (HISTORY.md, ninth session); FE_Q(2) needs
            # spacings of at most half its cells: from 1/32 on.
            "coupled, reduced space cg, cg matrix-free, FE_Q(2) on cells "
            "of 0.0625, tolerance 1e-6":
                (["Coupling/Method=reduced space cg"] + scalable_cg_loose +
                 [bar_particles_on(1 / 16, fe_degree=2, graded_layers=2)],
                 [1, 2, 3]),
            "coupled, full space gmres, matrix-free":
                (full_space_gmres, [0, 1]),
        },
    },
}


def run(scene, name, level, sets):
    out = os.path.join(options.out, scene,
                       name.replace(", ", "_").replace(" ", "_"),
                       "level_%d" % level)
    summary = os.path.join(out, "summary.json")
    if options.reuse and os.path.exists(summary):
        return json.load(open(summary))
    # A run's setting is a string, or a function of the level giving a list.
    settings = [setting
                for s in baseline + scenes[scene]["levels"][level] + sets
                for setting in (s(level) if callable(s) else [s])]
    return run_ltn(options.ltn, scenes[scene]["prm"], out, settings)


def extrapolate(values):
    """Richardson limit and observed order of three values at h, h/2, h/4."""
    a, b, c = values
    if (a - b) * (b - c) <= 0 or a == b:
        return c, float("nan")
    ratio = (a - b) / (b - c)
    return c - (b - c) / (ratio - 1), math.log2(ratio)


# Every curve of each scene, in order, for the chart: --only runs some of
# them, the CSV keeps the others.
curves = {name: list(scene["runs"]) for name, scene in scenes.items()}
if options.only:
    for name in options.scenes:
        scene = scenes[name]
        scene["runs"] = {run_name: run
                         for run_name, run in scene["runs"].items()
                         if run_name in options.only}
        missing = [scene[key] for key in ("reference", "equal-error line")
                   if scene["runs"] and scene[key] not in scene["runs"]]
        if missing:
            raise SystemExit("--only: the errors and ratios of %s need %s" %
                             (name, ", ".join('"%s"' % m for m in missing)))

rows = []
for scene in [] if options.plot_only else options.scenes:
    if not scenes[scene]["runs"]:
        continue
    results = {}
    for name, (sets, levels) in scenes[scene]["runs"].items():
        for level in levels:
            needed = peak_memory_gb.get((scene, name, level), 0)
            if needed > available_memory_gb():
                print(scene, name, level, "skipped: needs about %g GB, "
                      "%.1f GB available" % (needed, available_memory_gb()),
                      flush=True)
                continue
            summary = run(scene, name, level, sets)
            results[(name, level)] = summary
            print(scene, name, level, summary["timings"]["total"],
                  summary["mechanics"]["crack_openings"][0]["max_opening"],
                  flush=True)
    # The reference opening: the reference solver's three finest levels.
    reference_run = scenes[scene]["reference"]
    reference_levels = scenes[scene]["runs"][reference_run][1][-3:]
    openings = [results[(reference_run, level)]["mechanics"]
                ["crack_openings"][0]["max_opening"]
                for level in reference_levels]
    reference, order = extrapolate(openings)
    print(scene, "reference opening", reference, "observed order", order,
          "from", reference_run, "at levels", reference_levels)

    def error(summary):
        opening = summary["mechanics"]["crack_openings"][0]["max_opening"]
        return abs(opening / reference - 1)

    # The all-peridynamic time at a coupled run's error: along the log-log
    # line through the two finest points of the equal-error line.
    line_run = scenes[scene]["equal-error line"]
    line_levels = [level for level in scenes[scene]["runs"][line_run][1]
                   if (line_run, level) in results]
    (t1, e1), (t2, e2) = [(results[(line_run, level)]["timings"]["total"],
                           error(results[(line_run, level)]))
                          for level in line_levels[-2:]]
    slope = math.log(e2 / e1) / math.log(t2 / t1)
    for (name, level), summary in results.items():
        if name.startswith("coupled"):
            t = summary["timings"]["total"]
            t_all = t2 * (error(summary) / e2) ** (1 / slope)
            print(scene, name, level, "error %.3g in %.3g s;" % (
                error(summary), t), "all peridynamic at that error "
                "%.3g s (error ~ t^%.2f, %s): %.2fx" % (
                    t_all, slope, "interpolated" if e2 <= error(summary) <=
                    e1 else "extrapolated", t_all / t))
    # The converse, with both sides measured: at each error the equal-error
    # line reached, the coupled time along the log-log line through the two
    # runs of a coupled curve that bracket it (none beyond a curve's runs).
    for name, (sets, levels) in scenes[scene]["runs"].items():
        if not name.startswith("coupled"):
            continue
        curve = [(error(results[(name, level)]),
                  results[(name, level)]["timings"]["total"], level)
                 for level in levels if (name, level) in results]
        for line_level in line_levels:
            e_all = error(results[(line_run, line_level)])
            t_all = results[(line_run, line_level)]["timings"]["total"]
            for (e_a, t_a, a), (e_b, t_b, b) in zip(curve, curve[1:]):
                if e_a >= e_all >= e_b and e_a > e_b:
                    t = t_a * (e_all / e_a) ** (math.log(t_b / t_a) /
                                                math.log(e_b / e_a))
                    print(scene, name, "at the error %.3g of the equal-error "
                          "line's level %d (%.3g s): %.3g s between its "
                          "levels %d and %d: %.2fx" % (
                              e_all, line_level, t_all, t, a, b, t_all / t))
                    break
    for (name, level), summary in results.items():
        opening = summary["mechanics"]["crack_openings"][0]["max_opening"]
        solver = summary["solver"]
        rows.append({
            "scene": scene,
            "run": name,
            "level": level,
            "particle_dofs": summary["n_nonlocal_dofs"],
            "local_dofs": summary["n_local_dofs"],
            "iterations": solver.get("iterations", 0),
            "solve_s": round(summary["timings"]["solve"], 2),
            "total_s": round(summary["timings"]["total"], 2),
            "memory_mb": round(summary["memory_mb"]),
            "max_opening": "%.7g" % opening,
            "reference_opening": "%.7g" % reference,
            "observed_order": "%.2f" % order,
            "error": "%.3g" % error(summary),
        })

# The rows of the curves not run now (other scenes, curves --only left
# out, or every curve with --plot-only) are kept from the CSV.
if os.path.exists(options.csv):
    ran = {(row["scene"], row["run"]) for row in rows}
    with open(options.csv, newline="") as f:
        kept = [row for row in csv.DictReader(f)
                if (row["scene"], row["run"]) not in ran]
    order = list(scenes)
    rows = sorted(kept + rows, key=lambda row: order.index(row["scene"]))
if not options.plot_only:
    write_csv(options.csv, rows)

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
from matplotlib.ticker import FuncFormatter

shown = [s for s in scenes if any(r["scene"] == s for r in rows)]
titles = {"plate_2d": "plate_2d: 2D plate of side 2",
          "plate_2d_side_4": "plate_2d_side_4: 2D plate of side 4",
          "bar_3d": "bar_3d: 3D bar"}
# The two sides, as the CSV's run names start, and the colour and line of
# each side's best curve in both charts; the chart of every curve draws the
# others thinner, in the colours of `others`.
sides = {"coupled": ("tab:blue", "s-"), "all peridynamic": ("tab:orange",
                                                           "o--")}
others = ["tab:green", "tab:red", "tab:purple", "tab:brown", "tab:pink",
          "tab:gray", "tab:olive", "tab:cyan", "black"]
# The chart's short names: each phrase of a CSV name and its abbreviation,
# the longer phrases first (no-break spaces keep a number on its line).
abbreviations = [
    ("all peridynamic, ", ""),
    ("coupled, ", ""),
    ("reduced space cg, cg matrix-free", "reduced-space CG, matrix-free"),
    ("reduced space cg", "reduced-space CG"),
    ("cg matrix-free", "CG, matrix-free"),
    ("gmres matrix-free", "GMRES, matrix-free"),
    ("full space gmres", "full-space GMRES"),
    ("full space direct", "full-space direct"),
    ("FEM cells at least 0.0125", "FEM cells ≥\u00a01/80"),
    ("FE_Q(2) on cells of 0.0625", "FE_Q(2) on cells of 1/16"),
    ("tolerance ", "to\u00a0"),
    ("collar layer weighted", "collar weighted"),
]


def wrap(text, width):
    """`text` in lines of at most `width`, broken at spaces only (not in
    "matrix-free" or "1e-6")."""
    return textwrap.fill(text, width, break_on_hyphens=False)


def short_name(run):
    """`run`'s side, then its abbreviated settings in parentheses."""
    side = next(s for s in sides if run.startswith(s))
    for phrase, abbreviation in abbreviations:
        run = run.replace(phrase, abbreviation)
    return "%s (%s)" % (side.replace(" ", "-"), run)


def runs_of(scene, name):
    """The CSV rows of one curve, coarsest first."""
    return sorted((r for r in rows
                   if r["scene"] == scene and r["run"] == name),
                  key=lambda r: int(r["level"]))


def best(scene, side):
    """The rule for "best" (README.md, "The charts"): of the scene's curves
    of one side, the fastest (`total_s`) at the finest `level` any of them
    reached. At one level every curve has the same particle spacing, so
    they are ranked at the same discretization, not at equal error: a
    curve whose FEM model cancels part of the particles' error (the bar's
    on FE_Q(1) cells of 1/8, HISTORY.md, ninth session) does not win on
    that."""
    mine = [r for name in curves[scene] if name.startswith(side)
            for r in runs_of(scene, name)]
    finest = max(int(r["level"]) for r in mine)
    winner = min((r for r in mine if int(r["level"]) == finest),
                 key=lambda r: float(r["total_s"]))
    print(scene, "best", side, "curve:", winner["run"], "(%s s at level %d)"
          % (winner["total_s"], finest))
    return winner["run"]


def draw(axis, scene, name, label, colour, style, width):
    """One curve: the error in % against the run's wall time."""
    mine = runs_of(scene, name)
    axis.loglog([float(r["total_s"]) for r in mine],
                [100 * float(r["error"]) for r in mine], style, label=label,
                color=colour, linewidth=width, markersize=2 + 2.5 * width)


def label_axes(axis, scene, y_label=True):
    """The scene's title, the axes' names and units, ticks and grid."""
    axis.set_title(titles.get(scene, scene))
    axis.set_xlabel("wall time of the whole run (s), one rank")
    if y_label:
        axis.set_ylabel("relative error of the max crack opening (%)")
    # Plain numbers, and the 2s and 5s between the powers of ten labelled
    # too: the bar's and the wide plate's errors span about one decade.
    plain = FuncFormatter(lambda v, _: "%g" % v)
    some = FuncFormatter(lambda v, _: "%g" % v if
                         round(v / 10 ** math.floor(math.log10(v))) in (2, 5)
                         else "")
    for ax in (axis.xaxis, axis.yaxis):
        ax.set_major_formatter(plain)
        ax.set_minor_formatter(some)
    axis.grid(True, which="major", alpha=0.5)
    axis.grid(True, which="minor", alpha=0.15)


winners = {scene: {side: best(scene, side) for side in sides}
           for scene in shown}
rule = ("(best: the fastest of its side at the finest particle spacing the "
        "side ran)")

# Fonts large for the figure: the README shows it about 900 pixels wide.
plt.rcParams.update({"font.size": 13, "legend.fontsize": 12})
# The chart of the two curves that matter, each scene's panel with its
# legend below (the names wrap over up to four lines).
figure, axes = plt.subplots(1, len(shown), figsize=(4.8 * len(shown), 7),
                            squeeze=False, layout="constrained")
for i, (axis, scene) in enumerate(zip(axes[0], shown)):
    for side, (colour, style) in sides.items():
        name = winners[scene][side]
        draw(axis, scene, name, wrap(short_name(name), 36), colour,
             style, 2)
    label_axes(axis, scene, y_label=i == 0)
    axis.legend(loc="upper center", bbox_to_anchor=(0.5, -0.16))
figure.suptitle("Error against wall time: each scene's best coupled and best "
                "all-peridynamic solve\n" + rule)
figure.savefig(options.png, dpi=110, bbox_inches="tight")

# Every curve: one row per scene, the legend right of the axes.
figure, axes = plt.subplots(len(shown), 1, figsize=(14, 6.5 * len(shown)),
                            squeeze=False, layout="constrained")
for axis, scene in zip(axes[:, 0], shown):
    for side, (colour, style) in sides.items():
        palette = iter(others)
        for name in curves[scene]:
            if not name.startswith(side) or not runs_of(scene, name):
                continue
            if name == winners[scene][side]:
                draw(axis, scene, name, wrap(name + " (best)", 60),
                     colour, style, 2.5)
            else:
                draw(axis, scene, name, wrap(name, 60),
                     next(palette), style, 1.2)
    label_axes(axis, scene)
    axis.legend(loc="center left", bbox_to_anchor=(1.02, 0.5),
                fontsize=9)
figure.suptitle("Error against wall time, every curve (names as in "
                "results.csv)\n" + rule)
figure.savefig(options.png_all, dpi=100, bbox_inches="tight")
