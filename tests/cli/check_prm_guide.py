#!/usr/bin/env python3
"""The parameter table of doc/prm_guide.md, between its two marker lines, is
exactly what scripts/parameter_table.py makes of
`ltn --print-parameters --json`:
every parameter that ltn declares, under its subsection's heading row, with
its default, allowed values and documentation, and no other. When it is
stale this prints a short diff and the command that regenerates it
(`python3 scripts/parameter_table.py LTN GUIDE`), and fails.

usage: check_prm_guide.py LTN GUIDE
"""
import pathlib
import sys

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parents[2]
                       / "scripts"))
import parameter_table  # noqa: E402

if len(sys.argv) != 3:
    sys.exit(__doc__)
sys.exit(parameter_table.check(sys.argv[1], sys.argv[2]))
