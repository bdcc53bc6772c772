#!/usr/bin/env python3
"""Every reference to a section of the documentation names a section that exists.

Usage: docs_section_references.py SOURCE_DIR. Scans the text files under core/, ui/, app/ (with app/python/), tests/,
resources/ and scripts/ (.cpp .h .md .txt .json .ts .py .sh .cmake .in, CMakeLists.txt), the top
CMakeLists.txt, README.md and docs/*.md for references such as "docs/physics.md §2",
"numerics.md §3, §5", "(physics.md sec. 1 and 4)" or "(docs/robustness.md, Tests)", and checks them
against the headings of the cited document: "## 2. The control law" is §2, "### 2.3 Title" or
"### 2.3. Title" is §2.3 ("## §2 Title" is §2 too), and a name after a comma must be a heading's
title. A document named without a section must exist, in docs/ or (README.md) at the top.
Inside a document of docs/ a bare § or "section N" cites that document itself, unless it follows
a capitalised word (another work's section: Green and Silverman §2.3.3); elsewhere a bare § or
"sec. N" is the paper's. A reference may run over a line break of a comment, and in C++ and Python
over adjacent string literals and the escape for § ("docs/physics.md \\u00a7" "3").
Prints each broken reference as "file:line: cites docs/<doc>.md §<n>, which has no such section"
and exits 1, or exits 0.
"""
import os
import re
import sys

SCAN_DIRS = ("core", "ui", "app", "tests", "resources", "scripts")
EXTENSIONS = (".cpp", ".h", ".md", ".txt", ".json", ".ts", ".py", ".sh", ".cmake", ".in")
# tests/ui/shell/test_help.cpp asks the help window for a document that does not exist
DELIBERATELY_MISSING = {"no-such.md"}

HEADING = re.compile(r"^(#{1,6})[ \t]+(.*?)[ \t]*#*[ \t]*$")
NUMBERED = re.compile(r"^§?[ \t]*(\d+(?:\.\d+)*)\.?(?:[ \t]+(.*))?$")
FENCE = re.compile(r"^[ \t]*(```|~~~)")

# What joins the pieces of one logical text: a line break with the next line's comment leader
# (///<, ///, //, #, a single *, --); in C++ and Python also a string literal's end and the next
# one's start, and the escape \u00a7 written for §.
LINE_BREAK = r"\r?\n[ \t]*(?:///?<?|#+(?=[ \t])|\*(?!\*)|--)?[ \t]*"
JOIN = re.compile(LINE_BREAK)
JOIN_CODE = re.compile(r'\\u00[aA]7|"[ \t]*(?:\r?\n[ \t]*)?"|' + LINE_BREAK)
CODE = (".cpp", ".h", ".py")
NUMBER = r"\d+(?:\.\d+)*"
DOC = r"(?<![\w/.\-])(?P<doc>(?:docs/)?[A-Za-z][\w\-]*\.md)(?![\w\-])"
# the sections after a document's name: "§2", ", sec. 2.7", " section 6", "§3, §5", "sec. 1 and 4"
SECTIONS = (r"(?P<secs>[ \t]*,?[ \t]*(?:§[ \t]*|sec\.[ \t]*|section[ \t]+)" + NUMBER +
            r"(?:[ \t]*,[ \t]*§[ \t]*" + NUMBER + r"|[ \t]+(?:and|or|&)[ \t]+§?[ \t]*" + NUMBER + r")*)")
# a heading's title after a comma, closing the parentheses: "(docs/robustness.md, Writing files)"
TITLE = r"(?P<title>,[ \t]+[^()§\d,;:\n]*[^()§\d,;:\s])\)"
REFERENCE = re.compile(DOC + "(?:" + SECTIONS + "|" + TITLE + ")?")
BARE = re.compile(r"(?P<before>[\w']*)[ \t(]*(?:§[ \t]*|(?<![\w-])section[ \t]+)(?P<num>" + NUMBER + ")")
NUMBERS = re.compile(NUMBER)


def headings(path):
    """The numbered sections and the titles of a Markdown document's headings (not in code)."""
    numbers, titles = set(), set()
    fenced = False
    with open(path, encoding="utf-8", errors="replace") as f:
        for line in f:
            if FENCE.match(line):
                fenced = not fenced
                continue
            m = HEADING.match(line.rstrip("\n")) if not fenced else None
            if not m:
                continue
            text = m.group(2)
            n = NUMBERED.match(text)
            if n:
                numbers.add(n.group(1))
                text = n.group(2) or ""
            titles.add(text.strip().lower())
    return numbers, titles


def logical(text, join):
    """The text with its pieces joined (see JOIN), and the line of each of its characters."""
    out, lines = [], []
    line, pos = 1, 0
    for m in join.finditer(text):
        chunk = text[pos:m.start()]
        for ch in chunk:
            out.append(ch)
            lines.append(line)
            if ch == "\n":
                line += 1
        piece = m.group(0)
        if piece.startswith("\\u"):
            joined = "§"
        elif piece.startswith('"'):
            joined = ""  # adjacent string literals are one string
        else:
            joined = " "  # a line break with the next line's comment leader
        out.append(joined)
        lines.extend([line] * len(joined))
        line += piece.count("\n")
        pos = m.end()
    for ch in text[pos:]:
        out.append(ch)
        lines.append(line)
        if ch == "\n":
            line += 1
    joined = "".join(out)
    assert len(joined) == len(lines)
    return joined, lines


def files_to_scan(root):
    for d in SCAN_DIRS:
        for base, dirs, names in os.walk(os.path.join(root, d)):
            dirs.sort()
            for name in sorted(names):
                if name.endswith(EXTENSIONS) or name == "CMakeLists.txt":
                    yield os.path.join(base, name)
    for name in ("CMakeLists.txt", "README.md"):
        if os.path.isfile(os.path.join(root, name)):
            yield os.path.join(root, name)
    docs = os.path.join(root, "docs")
    for name in sorted(os.listdir(docs)):
        if name.endswith(".md"):
            yield os.path.join(docs, name)


def main():
    if len(sys.argv) != 2:
        sys.exit("usage: docs_section_references.py SOURCE_DIR")
    root = sys.argv[1]
    cache = {}

    def resolve(doc):
        """The cited document's path relative to root, or None."""
        for rel in ([doc] if doc.startswith("docs/") else [os.path.join("docs", doc), doc]):
            if os.path.isfile(os.path.join(root, rel)):
                return rel
        return None

    def sections(rel):
        if rel not in cache:
            cache[rel] = headings(os.path.join(root, rel))
        return cache[rel]

    broken = []
    count = 0
    for path in files_to_scan(root):
        rel_path = os.path.relpath(path, root)
        with open(path, encoding="utf-8", errors="replace") as f:
            raw = f.read()
        text, line_of = logical(raw, JOIN_CODE if path.endswith(CODE) else JOIN)
        cited_spans = []
        for m in REFERENCE.finditer(text):
            doc = m.group("doc")
            if os.path.basename(doc) in DELIBERATELY_MISSING:
                continue
            count += 1
            target = resolve(doc)
            line = line_of[m.start("doc")]
            if target is None:
                broken.append(f"{rel_path}:{line}: cites {doc}, which does not exist")
                continue
            numbers, titles = sections(target)
            if m.group("secs"):
                cited_spans.append((m.start(), m.end()))
                start = m.start("secs")
                for n in NUMBERS.finditer(m.group("secs")):
                    if n.group(0) not in numbers:
                        broken.append(f"{rel_path}:{line_of[start + n.start()]}: cites {target} "
                                      f"§{n.group(0)}, which has no such section")
            elif m.group("title"):
                title = m.group("title")[1:].strip()
                if title.lower() not in titles:
                    broken.append(f"{rel_path}:{line_of[m.start('title')]}: cites {target} "
                                  f"\"{title}\", which has no such heading")
        # inside a document of docs/ a bare § or "section N" cites that document itself
        if rel_path.startswith("docs" + os.sep) and rel_path.endswith(".md"):
            numbers, _ = sections(rel_path)
            for m in BARE.finditer(text):
                if any(a <= m.start("num") < b for a, b in cited_spans):
                    continue
                if m.group("before")[:1].isupper():
                    continue  # another work's section (an author's name before it)
                count += 1
                if m.group("num") not in numbers:
                    broken.append(f"{rel_path}:{line_of[m.start('num')]}: cites {rel_path} "
                                  f"§{m.group('num')}, which has no such section")
    for b in broken:
        print(b)
    if broken:
        print(f"{len(broken)} broken of {count} references to the documentation")
        return 1
    print(f"{count} references to the documentation, every one names an existing section")
    return 0


if __name__ == "__main__":
    sys.exit(main())
