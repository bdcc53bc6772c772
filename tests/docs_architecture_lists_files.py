#!/usr/bin/env python3
"""docs/architecture.md names every source file of core/, ui/ and app/ (with app/python/).

Usage: docs_architecture_lists_files.py SOURCE_DIR. A .cpp or .h file counts as named when the
document has its path below its top folder or below the source dir, with or without the
extension, e.g. `paths/path_table.h`, `ui/shell/main_window.cpp`, `canvas/vector_layer` (a name
without an extension names the .h and the .cpp), `shell/playback.{h,cpp}` or
`shell/playback.h/.cpp`. On a line that starts with a folder (a table row such as
"| `paths/` | ... | `curve`, `path_table` |", or "app/  ...: main.cpp, headless_options"), a bare
name is a file of that folder. Prints each file the document does not name and exits 1, or
exits 0.
"""
import os
import re
import sys

TOPS = ("core", "ui", "app")
SOURCE = (".cpp", ".h")

# a path-like name: folders, a name and an optional extension or pair of extensions
NAME = re.compile(r"(?<![\w./{}\-])((?:[\w\-]+/)*[\w\-]+)"
                  r"(\.\{h,\s*cpp\}|\.\{cpp,\s*h\}|\.h/\.cpp|\.cpp/\.h|\.cpp|\.h)?(?![\w{}/\-])")
# what may stand before a line's first word: table pipes, list bullets, the tree's box drawing
LEAD = re.compile(r"^[\s|*`\-\u2500-\u257f]*")
FOLDER = re.compile(r"([\w\-]+(?:/[\w\-]+)*)/(?![\w\-])")
PAIRS = {".{h,cpp}", ".{cpp,h}", ".h/.cpp", ".cpp/.h"}


def named(text):
    """Every name the text gives a file by, as paths without and with their extensions."""
    names = set()
    for line in text.splitlines():
        lead = LEAD.match(line).end()
        folder = FOLDER.match(line, lead)
        context = folder.group(1) + "/" if folder else None
        for m in NAME.finditer(line):
            stem, ext = m.group(1), re.sub(r"\s", "", m.group(2) or "")
            stems = [stem]
            if "/" not in stem:
                if not context:
                    continue
                stems = [context + stem]
            for s in stems:
                if ext in PAIRS:
                    names.update({s + ".h", s + ".cpp"})
                else:
                    names.add(s + ext)  # a name without an extension names both
    return names


def main():
    if len(sys.argv) != 2:
        sys.exit("usage: docs_architecture_lists_files.py SOURCE_DIR")
    root = sys.argv[1]
    with open(os.path.join(root, "docs", "architecture.md"), encoding="utf-8") as f:
        names = named(f.read())
    missing, count = [], 0
    for top in TOPS:
        for base, dirs, files in os.walk(os.path.join(root, top)):
            dirs.sort()
            for name in sorted(files):
                if not name.endswith(SOURCE):
                    continue
                count += 1
                rel = os.path.relpath(os.path.join(base, name), os.path.join(root, top))
                rel = rel.replace(os.sep, "/")
                stem = os.path.splitext(rel)[0]
                forms = {rel, top + "/" + rel, stem, top + "/" + stem}
                if not forms & names:
                    missing.append(f"{top}/{rel}")
    for m in missing:
        print(f"docs/architecture.md does not name {m}")
    if missing:
        print(f"{len(missing)} of {count} source files are not named in docs/architecture.md")
        return 1
    print(f"docs/architecture.md names all {count} source files of {', '.join(TOPS)}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
