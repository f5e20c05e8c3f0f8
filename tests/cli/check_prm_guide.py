#!/usr/bin/env python3
"""Every parameter that `ltn --print-parameters` lists has a row in the
parameter table of doc/prm_guide.md (its section "## Parameters"), under
its own subsection's heading row (top-level parameters above the first
heading row), and the table names no parameter that ltn does not know.

usage: check_prm_guide.py LTN GUIDE
"""
import re
import subprocess
import sys

ltn, guide = sys.argv[1], sys.argv[2]

listing = subprocess.run([ltn, "--print-parameters"], check=True,
                         capture_output=True, text=True).stdout
declared = set()
section = ""
for line in listing.splitlines():
    line = line.split("#", 1)[0].strip()
    if line.startswith("subsection "):
        section = line[len("subsection "):].strip()
    elif line == "end":
        section = ""
    elif line.startswith("set "):
        declared.add((section, line[4:].split("=", 1)[0].strip()))

documented = set()
section = ""
in_table = False
for line in open(guide, encoding="utf-8"):
    if line.startswith("## "):
        in_table = line.strip() == "## Parameters"
        continue
    if not in_table:
        continue
    heading = re.match(r"\|\s*\*\*(.+?)\*\*\s*\|", line)
    if heading:
        section = heading.group(1)
        continue
    row = re.match(r"\|\s*(`[^|]+`)\s*\|", line)
    if row:
        for name in re.findall(r"`([^`]+)`", row.group(1)):
            documented.add((section, name))

missing = sorted(declared - documented)
unknown = sorted(documented - declared)
for section, name in missing:
    print("not in %s: %s/%s" % (guide, section or "(top level)", name))
for section, name in unknown:
    print("in %s but not a parameter of ltn: %s/%s"
          % (guide, section or "(top level)", name))
print("%d parameters, %d documented rows" % (len(declared), len(documented)))
sys.exit(1 if missing or unknown else 0)
