"""Check that two runs of a scene report the same sizes and errors.

usage: compare_summaries.py REFERENCE/summary.json OTHER/summary.json TOL

Sizes must be equal, errors equal to TOL relative (used to compare runs on
different numbers of MPI ranks, or with different solvers).
"""
import json
import sys

reference, other = (json.load(open(path)) for path in sys.argv[1:3])
tolerance = float(sys.argv[3])

levels = reference["convergence"]
assert len(levels) == len(other["convergence"]), "different level counts"
worst = 0.0
for l, (a, b) in enumerate(zip(levels, other["convergence"])):
    for size in ("n_nonlocal_dofs", "n_local_dofs", "n_controls"):
        assert a[size] == b[size], f"level {l}: {size} {a[size]} != {b[size]}"
    for part, norms in a["errors"].items():
        for norm, value in norms.items():
            # A model the scene does not have reports no error (None).
            if value is None or b["errors"][part][norm] is None:
                assert value == b["errors"][part][norm], (
                    f"level {l}: {part} {norm} error {value} against "
                    f"{b['errors'][part][norm]}")
                continue
            difference = abs(value - b["errors"][part][norm]) / abs(value)
            worst = max(worst, difference)
            assert difference <= tolerance, (
                f"level {l}: {part} {norm} error {value} against "
                f"{b['errors'][part][norm]}: relative difference "
                f"{difference:.3g} > {tolerance}")
print(f"{len(levels)} levels: same sizes, errors equal to {worst:.3g} "
      f"relative (<= {tolerance})")
