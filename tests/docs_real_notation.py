#!/usr/bin/env python3
"""What the window shows about physics is written in real notation, not in ASCII spellings.

Usage: docs_real_notation.py SOURCE_DIR. Checks the notes, descriptions and titles of the scene
files (resources/scenes/*/*.json: the gallery's explanations and the presets' lines) and the prose
of the help documents compiled into the program (the .md files of resources/help/*.qrc), outside
code blocks and `code spans`, where a CSV column (`phidot`) or a typed expression (`sqrt(x)`)
keeps its ASCII name. Forbidden: Psi, phidot, psidot, chidot, sdot, sddot, phiddot, kappa,
lambda, dphi, "sqrt(" and "^2" (write Ψ, φ̇, Ψ̇, χ̇, ṡ, s̈, φ̈, κ, λ, dφ, √(…), ²). Prints each
hit with its place and exits 1, or exits 0.
"""
import glob
import json
import os
import re
import sys

ASCII = re.compile(r"\b(Psi|Psidot|phidot|psidot|chidot|sdot|sddot|phiddot|kappa|lambda|dphi)\b"
                   r"|sqrt\(|\^2\b")
FENCE = re.compile(r"^\s*(```|~~~)")
CODE_SPAN = re.compile(r"`+[^`]*`+")
LINK_TARGET = re.compile(r"\]\([^)]*\)")


def prose_lines(text):
    """(line number, the line without code spans and link targets) outside fenced code."""
    fenced = False
    for number, line in enumerate(text.splitlines(), 1):
        if FENCE.match(line):
            fenced = not fenced
            continue
        if fenced or line.startswith("    "):
            continue
        yield number, LINK_TARGET.sub("]", CODE_SPAN.sub("", line))


def main(source):
    hits = []
    for path in sorted(glob.glob(os.path.join(source, "resources", "scenes", "*", "*.json"))):
        scene = json.load(open(path, encoding="utf-8"))
        texts = {"note": scene.get("note", ""), "description": scene.get("description", ""),
                 "gallery/title": scene.get("gallery", {}).get("title", "")}
        for field, text in texts.items():
            for m in ASCII.finditer(text):
                hits.append(f"{os.path.relpath(path, source)} {field}: '{m.group(0)}' in "
                            f"...{text[max(0, m.start() - 30):m.end() + 30]}...")
    documents = set()
    for qrc in glob.glob(os.path.join(source, "resources", "help", "*.qrc")):
        for name in re.findall(r">([^<]+\.md)</file>", open(qrc, encoding="utf-8").read()):
            documents.add(os.path.normpath(os.path.join(os.path.dirname(qrc), name)))
    if not documents:
        hits.append("no help document found in resources/help/*.qrc")
    for path in sorted(documents):
        for number, line in prose_lines(open(path, encoding="utf-8").read()):
            for m in ASCII.finditer(line):
                hits.append(f"{os.path.relpath(path, source)}:{number}: '{m.group(0)}' in "
                            f"{line.strip()[:100]}")
    for hit in hits:
        print(hit)
    return 1 if hits else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1]))
