#!/usr/bin/env python3
"""The layering rule inside core/: its folders include each other without a cycle.

Usage: include_cycles.py SOURCE_DIR. Prints every folder edge that lies on a cycle and exits 1,
or prints the folder order (lowest first) and exits 0. docs/architecture.md gives the intended order.
"""
import os
import re
import sys

core = os.path.join(sys.argv[1], "core")
include = re.compile(r'#include\s+"([a-z_]+)/')
folders = sorted(d for d in os.listdir(core) if os.path.isdir(os.path.join(core, d)))
edges = {d: set() for d in folders}
where = {}
for d in folders:
    for root, _, files in os.walk(os.path.join(core, d)):
        for f in files:
            path = os.path.join(root, f)
            for m in include.finditer(open(path, errors="replace").read()):
                target = m.group(1)
                if target != d and target in edges:
                    edges[d].add(target)
                    where.setdefault((d, target), os.path.relpath(path, sys.argv[1]))


def reaches(a, b):
    seen, todo = set(), [a]
    while todo:
        n = todo.pop()
        for m in edges[n]:
            if m == b:
                return True
            if m not in seen:
                seen.add(m)
                todo.append(m)
    return False


cycles = sorted((a, b) for a in folders for b in edges[a] if reaches(b, a))
if cycles:
    for a, b in cycles:
        print(f"cycle: {a}/ includes {b}/ (e.g. {where[(a, b)]}), and {b}/ leads back to {a}/")
    sys.exit(1)
order = []
remaining = set(folders)
while remaining:
    level = sorted(d for d in remaining if edges[d] <= set(order))
    order += level
    remaining -= set(level)
print("ok: no include cycle between core folders; bottom to top:", " ".join(order))
