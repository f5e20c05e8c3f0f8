"""What the benchmark scripts share: the repository's root, the options that
name the ltn program and the folder of its runs, one run of ltn, the
writing and reading back of results.csv and the charts' matplotlib."""
import argparse
import csv
import json
import os
import subprocess
import sys

REPOSITORY_ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def ltn_argument_parser(default_out):
    """A parser of --ltn (the program, by default the build folder's) and
    --out (the folder of the runs, by default `default_out`); a benchmark
    adds its own options after these two."""
    parser = argparse.ArgumentParser()
    parser.add_argument("--ltn",
                        default=os.path.join(REPOSITORY_ROOT, "build", "ltn"))
    parser.add_argument("--out", default=default_out)
    return parser


def run_ltn(ltn, prm, out, settings):
    """Run the program `ltn` on the parameter file `prm` into the folder
    `out`, each of `settings` a `--set`, without VTU output (a benchmark
    reads only the summary); return its summary.json. Raises
    subprocess.CalledProcessError where the run fails."""
    command = [ltn, prm, "--output-dir", out,
               "--set", "Output/Write VTU=false"]
    for setting in settings:
        command += ["--set", setting]
    subprocess.run(command, check=True, capture_output=True)
    with open(os.path.join(out, "summary.json")) as f:
        return json.load(f)


def write_csv(path, rows):
    """Write `rows`, dicts with the same keys, to the CSV file `path`, the
    first row's keys as its header."""
    with open(path, "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=list(rows[0]))
        writer.writeheader()
        writer.writerows(rows)


def results_rows(path, plot_only, run):
    """The rows of the CSV file `path`: read back when `plot_only` (a
    redraw), else the list of dicts `run()` returns, written there first."""
    if plot_only:
        with open(path) as f:
            return list(csv.DictReader(f))
    rows = run()
    write_csv(path, rows)
    return rows


def pyplot_or_exit():
    """matplotlib's pyplot, drawing to files; without matplotlib (Debian:
    python3-matplotlib) the CSV is the whole result: say so and exit 0."""
    try:
        import matplotlib
    except ImportError:
        print("matplotlib not found (Debian: python3-matplotlib): no chart")
        sys.exit(0)
    matplotlib.use("Agg")
    import matplotlib.pyplot
    return matplotlib.pyplot
