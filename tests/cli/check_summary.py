#!/usr/bin/env python3
"""Check the public interface of a run's output directory: summary.json has
every documented key with values of the right type, and the VTU, PVD and
used_parameters.prm files are there."""
import json
import os
import re
import sys

directory = sys.argv[1]
levels = int(sys.argv[2])
with open(os.path.join(directory, "summary.json")) as f:
    s = json.load(f)

def need(obj, key, kind):
    assert key in obj, f"missing key {key!r}"
    assert isinstance(obj[key], kind), f"{key!r} is {type(obj[key])}"
    return obj[key]

def check_level(entry):
    for key in ("n_nonlocal_dofs", "n_local_dofs", "n_controls"):
        assert need(entry, key, int) > 0
    solver = need(entry, "solver", dict)
    need(solver, "method", str)
    need(solver, "iterations", int)
    need(solver, "residual", float)
    need(entry, "mismatch_J", float)
    errors = need(entry, "errors", dict)
    for part in ("nonlocal", "local", "coupled"):
        for norm in ("l2", "linf"):
            need(need(errors, part, dict), norm, float)

need(s, "scene", str)
assert need(s, "dim", int) == 1
assert need(s, "model", str) == "diffusion"
check_level(s)
timings = need(s, "timings", dict)
assert need(timings, "total", float) > 0
assert need(s, "memory_mb", float) > 0
if levels > 1:
    convergence = need(s, "convergence", list)
    assert len(convergence) == levels
    for l, entry in enumerate(convergence):
        check_level(entry)
        need(entry, "h", float)
        if l > 0:
            for part in ("nonlocal", "local", "coupled"):
                need(need(entry["rates"], part, dict), "l2", float)
for name in ("used_parameters.prm", "nonlocal_field.pvd", "local_field.pvd"):
    assert os.path.isfile(os.path.join(directory, name)), name
for l in range(levels):
    for field in ("nonlocal", "local"):
        name = f"{field}_field_level-{l:02d}.pvtu"
        path = os.path.join(directory, name)
        assert os.path.isfile(path), name
        # Every piece the record lists, one per rank, is there.
        pieces = re.findall(r'<Piece Source="([^"]+)"', open(path).read())
        assert pieces, f"{name} lists no pieces"
        for piece in pieces:
            assert os.path.isfile(os.path.join(directory, piece)), piece
print("summary.json and output files OK")
