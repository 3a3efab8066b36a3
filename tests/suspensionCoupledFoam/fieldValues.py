#!/usr/bin/python3
"""fieldValues.py FILE [COMPONENT]: the cell values of an ascii OpenFOAM
volume field (its internalField, uniform or a nonuniform List), one per
line; COMPONENT (0, 1, 2, ...) picks one component of a vector or tensor."""
import re
import sys

text = open(sys.argv[1]).read()
body = text[text.index("internalField"):]
m = re.match(r"internalField\s+uniform\s+(\([^)]*\)|\S+?);", body)
if m:
    sys.exit("fieldValues.py: uniform internalField in " + sys.argv[1])
m = re.match(r"internalField\s+nonuniform\s+List<\w+>\s*(\d+)\s*\(", body)
n = int(m.group(1))
rest = body[m.end():]
values = re.findall(r"\(([^()]*)\)", rest) if rest.lstrip().startswith("(") \
    else rest.split()[:n]
comp = int(sys.argv[2]) if len(sys.argv) > 2 else None
for v in values[:n]:
    print(v.split()[comp] if comp is not None else v)
