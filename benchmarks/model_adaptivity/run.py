"""`Geometry/Nonlocal regions = auto` against the hand-placed region and
against LPS on the whole body: particles, time, estimate, true error and the
crack opening's difference to the all-peridynamic one.

usage: run.py [--ltn build/ltn] [--out DIR] [--scenes plate_2 ...]
              [--csv FILE]

Per scene: LPS on the whole body (`nonlocal only`, the reference of the
crack opening; not for scenes with traction-free faces, which LPS alone
cannot hold), the scene's hand-placed region, and `auto` at three
tolerances. Each `auto` point runs twice: once as a user would (its wall
time counts) and once with `Postprocess/True model error` (the region's true
error against the largest admissible region, and the effectivity). One run
each: the ratios compare runs of one session on one machine. Writes
results.csv and prints each row.
"""
import math
import os
import subprocess
import sys

here = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.dirname(here))
from ltn_benchmark import (REPOSITORY_ROOT, ltn_argument_parser,  # noqa: E402
                           run_ltn, write_csv)
from plate_scene import centred_plate  # noqa: E402

TWO_CRACKS = ["Cracks/Corners=0.4, 0.5, 0.6, 0.5; 1.4, 1.5, 1.6, 1.5",
              "Postprocess/Reference crack opening=",
              "Geometry/Nonlocal regions=0.2,0.3,0.8,0.7; 1.2,1.3,1.8,1.7"]
SCENES = {
    "plate_2": ("lps_plate_2d_crack.prm", centred_plate(2),
                [1e-4, 5e-5, 3e-5]),
    "plate_4": ("lps_plate_2d_crack.prm", centred_plate(4),
                [1e-4, 5e-5, 3e-5]),
    "two_cracks": ("lps_plate_2d_crack.prm", TWO_CRACKS, [1e-4, 5e-5, 3e-5]),
    "bar_3d": ("lps_bar_3d_crack.prm", [], [1e-4, 6e-5, 3e-5]),
}

parser = ltn_argument_parser(default_out=os.path.join(here, "runs"))
parser.add_argument("--scenes", nargs="+", default=list(SCENES))
parser.add_argument("--csv", default=os.path.join(here, "results.csv"))
options = parser.parse_args()


def run(scene, sets, name):
    return run_ltn(options.ltn,
                   os.path.join(REPOSITORY_ROOT, "parameter_files", scene),
                   os.path.join(options.out, name), sets)


def openings(summary):
    """Every crack's opening per particle pair, by position."""
    return {(k, tuple(round(c, 9) for c in p)): o
            for k, crack in enumerate(summary["mechanics"]["crack_openings"])
            for p, o in zip(crack["points"], crack["opening"])}


def difference(summary, reference):
    mine = openings(summary)
    return math.sqrt(sum((mine[p] - reference[p]) ** 2 for p in reference) /
                     sum(v * v for v in reference.values()))


rows = []
for key in options.scenes:
    scene, sets, tolerances = SCENES[key]
    try:
        whole = run(scene, sets + ["Geometry/Models=nonlocal only"],
                    f"{key}/all_peridynamic")
        reference = openings(whole)
    except subprocess.CalledProcessError:
        # LPS alone needs a volume constraint on every face: a scene with
        # traction-free faces (the bar) has no all-peridynamic reference.
        whole = None
    hand = run(scene, sets, f"{key}/hand_placed")

    def row(name, summary, tolerance="", checked=None):
        loop = summary.get("model_adaptivity")
        last = loop["cycles"][-1] if loop else None
        checked_last = checked["model_adaptivity"]["cycles"][-1] \
            if checked else None
        # Every particle (collars too) carries the displacement and the
        # dilatation.
        particles = summary["n_nonlocal_dofs"] // (summary["dim"] + 1)
        rows.append({
            "scene": key,
            "run": name,
            "tolerance": tolerance,
            "cycles": len(loop["cycles"]) if loop else "",
            "stopped": last["stopped"] if last else "",
            "particles": particles,
            "total_s": round(summary["timings"]["total"], 2),
            "speedup_vs_all_peridynamic":
                round(whole["timings"]["total"] /
                      summary["timings"]["total"], 2) if whole else "",
            "speedup_vs_hand_placed":
                round(hand["timings"]["total"] /
                      summary["timings"]["total"], 2),
            "estimate": f"{last['estimate']:.3g}" if last else "",
            "true_error": f"{checked_last['true_error']:.3g}"
                          if checked_last else "",
            "effectivity": f"{checked_last['effectivity']:.3g}"
                           if checked_last else "",
            "opening_difference_to_all_peridynamic":
                f"{difference(summary, reference):.3g}" if whole else "",
        })
        print(rows[-1], flush=True)

    if whole:
        row("all peridynamic", whole)
    row("hand-placed region", hand)
    for tolerance in tolerances:
        automatic = sets + ["Geometry/Nonlocal regions=auto",
                            f"Geometry/Model error tolerance={tolerance:g}"]
        timed = run(scene, automatic, f"{key}/auto_{tolerance:g}")
        checked = run(scene, automatic + ["Postprocess/True model error=true"],
                      f"{key}/auto_{tolerance:g}_checked")
        row("auto", timed, f"{tolerance:g}", checked)

write_csv(options.csv, rows)
print(f"wrote {options.csv}")
