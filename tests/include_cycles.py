#!/usr/bin/env python3
"""The layering rule inside core/ and inside ui/: each tree's folders include each other without a
cycle.

Usage: include_cycles.py SOURCE_DIR. For each tree, an edge a -> b is a file of a/ that includes
"b/..." where b is another folder of the same tree (ui/'s includes of core/ folders are the layer
rule's business, not this one's). Prints every folder edge that lies on a cycle and exits 1, or
prints each tree's folder order (lowest first) and exits 0. docs/architecture.md gives the intended
orders.
"""
import os
import re
import sys

TREES = ("core", "ui")
INCLUDE = re.compile(r'#include\s+"([a-z_]+)/')


def folder_graph(root, tree):
    """The folders of root/tree, the folders each includes, and a file for each edge."""
    top = os.path.join(root, tree)
    folders = sorted(d for d in os.listdir(top) if os.path.isdir(os.path.join(top, d)))
    edges = {d: set() for d in folders}
    where = {}
    for d in folders:
        for base, _, files in os.walk(os.path.join(top, d)):
            for f in sorted(files):
                path = os.path.join(base, f)
                with open(path, errors="replace") as text:
                    for m in INCLUDE.finditer(text.read()):
                        target = m.group(1)
                        if target != d and target in edges:
                            edges[d].add(target)
                            where.setdefault((d, target), os.path.relpath(path, root))
    return folders, edges, where


def reaches(edges, a, b):
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


def check(root, tree):
    """Prints the tree's cycles or its order; True when it has no cycle."""
    folders, edges, where = folder_graph(root, tree)
    cycles = sorted((a, b) for a in folders for b in edges[a] if reaches(edges, b, a))
    for a, b in cycles:
        print(f"cycle in {tree}/: {a}/ includes {b}/ (e.g. {where[(a, b)]}), "
              f"and {b}/ leads back to {a}/")
    if cycles:
        return False
    order = []
    remaining = set(folders)
    while remaining:
        level = sorted(d for d in remaining if edges[d] <= set(order))
        order += level
        remaining -= set(level)
    print(f"ok: no include cycle between {tree} folders; bottom to top:", " ".join(order))
    return True


def main():
    if len(sys.argv) != 2:
        sys.exit("usage: include_cycles.py SOURCE_DIR")
    results = [check(sys.argv[1], tree) for tree in TREES]
    return 0 if all(results) else 1


if __name__ == "__main__":
    sys.exit(main())
