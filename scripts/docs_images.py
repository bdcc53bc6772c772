#!/usr/bin/python3
"""Makes every picture in README.md and docs/ from docs/images/recipes.txt.

Usage:
  docs_images.py PROGRAM [--out DIR] [--only NAME ...]   run the recipes (default: into docs/images)
  docs_images.py --check                                  every picture the documents show has a
                                                          recipe, and every recipe's picture is shown
Each picture is made in a scratch folder and moved into place when it is complete, so a failed
recipe leaves the old picture as it was. The exit status is 1 if any recipe failed.
"""
import argparse
import os
import re
import shlex
import shutil
import subprocess
import sys
import tempfile
from dataclasses import dataclass
from pathlib import Path

SOURCE = Path(__file__).resolve().parent.parent
RECIPES = SOURCE / "docs" / "images" / "recipes.txt"
HELP_RESOURCES = SOURCE / "resources" / "help" / "chaplygin_help.qrc"
DOCUMENTS = [SOURCE / "README.md", *sorted((SOURCE / "docs").glob("*.md"))]


@dataclass
class Recipe:
    output: str
    how: str
    options: list
    line: int


def read_recipes(path=RECIPES):
    recipes = []
    for number, text in enumerate(path.read_text(encoding="utf-8").splitlines(), start=1):
        if not text.strip() or text.lstrip().startswith("#"):
            continue
        words = shlex.split(text)
        if len(words) < 2:
            raise SystemExit(f"{path.name}:{number}: a recipe needs an output and a kind")
        how = words[1]
        if not (how == "screenshot" or re.fullmatch(r"plot:\w+|frame:\d+", how)):
            raise SystemExit(f"{path.name}:{number}: unknown kind '{how}' "
                             "(screenshot, plot:NAME or frame:N)")
        recipes.append(Recipe(words[0], how, words[2:], number))
    return recipes


def pictures_shown():
    """{picture name: [documents showing it]} for every docs/images picture a document embeds."""
    shown = {}
    for document in DOCUMENTS:
        text = document.read_text(encoding="utf-8")
        for name in re.findall(r"\]\((?:docs/)?images/([\w.-]+\.png)\)", text):
            shown.setdefault(name, []).append(document.relative_to(SOURCE).as_posix())
    return shown


def check():
    recipes = read_recipes()
    made = {r.output for r in recipes}
    shown = pictures_shown()
    problems = []
    for name, where in sorted(shown.items()):
        if name not in made:
            problems.append(f"{name} (shown in {', '.join(where)}) has no recipe in recipes.txt")
    for recipe in recipes:
        if recipe.output not in shown:
            problems.append(f"recipes.txt:{recipe.line}: {recipe.output} is shown by no document")
    for recipe in recipes:
        for option, value in zip(recipe.options, recipe.options[1:]):
            if option == "--scene" and not (SOURCE / value).is_file():
                problems.append(f"recipes.txt:{recipe.line}: scene file {value} does not exist")
    # the help window shows docs/*.md with their pictures compiled in
    compiled = set(re.findall(r'alias="images/([\w.-]+\.png)"', HELP_RESOURCES.read_text()))
    for name, where in sorted(shown.items()):
        if name not in compiled and any(w.startswith("docs/") for w in where):
            problems.append(f"{name} (shown in {', '.join(where)}) is not in {HELP_RESOURCES.name}")
    for name in sorted(compiled - set(shown)):
        problems.append(f"{HELP_RESOURCES.name} compiles in {name}, which no document shows")
    unused = {p.name for p in (SOURCE / "docs" / "images").glob("*.png")} - made
    for name in sorted(unused):
        problems.append(f"docs/images/{name} is made by no recipe")
    for problem in problems:
        print(problem, file=sys.stderr)
    print(f"{len(recipes)} recipes, {len(shown)} pictures shown, {len(problems)} problems")
    return 1 if problems else 0


def make(program, recipe, out_dir):
    with tempfile.TemporaryDirectory(prefix="docs-images-") as scratch:
        scratch = Path(scratch)
        if recipe.how == "screenshot":
            made = scratch / recipe.output
            command = [program, "--screenshot", str(made), *recipe.options]
        elif recipe.how.startswith("plot:"):
            made = scratch / "plots" / (recipe.how.split(":")[1] + ".png")
            command = [program, "--headless", "--plots", str(scratch / "plots"), *recipe.options]
        else:
            made = scratch / "frames" / f"frame_{int(recipe.how.split(':')[1]):05d}.png"
            command = [program, "--headless", "--animation", str(scratch / "frames") + "/",
                       *recipe.options]
        run = subprocess.run(command, cwd=SOURCE, stdout=subprocess.DEVNULL,
                             stderr=subprocess.PIPE, text=True)
        if run.returncode != 0 or not made.is_file():
            print(f"{recipe.output}: failed ({' '.join(map(shlex.quote, command[1:]))}):\n"
                  f"{run.stderr.strip()}", file=sys.stderr)
            return False
        staged = out_dir / f".{recipe.output}.part"
        shutil.copyfile(made, staged)
        os.replace(staged, out_dir / recipe.output)
        print(f"{recipe.output}")
        return True


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("program", nargs="?", help="the chaplygin-lab executable")
    parser.add_argument("--out", type=Path, default=SOURCE / "docs" / "images")
    parser.add_argument("--only", nargs="+", default=None, help="only these pictures")
    parser.add_argument("--check", action="store_true")
    args = parser.parse_args()
    if args.check:
        return check()
    if not args.program:
        parser.error("the chaplygin-lab executable is needed to make the pictures")
    recipes = read_recipes()
    if args.only:
        unknown = set(args.only) - {r.output for r in recipes}
        if unknown:
            parser.error(f"no recipe for {', '.join(sorted(unknown))}")
        recipes = [r for r in recipes if r.output in args.only]
    args.out.mkdir(parents=True, exist_ok=True)
    environment_program = str(Path(args.program).resolve())
    failed = [r.output for r in recipes if not make(environment_program, r, args.out)]
    if failed:
        print(f"failed: {', '.join(failed)}", file=sys.stderr)
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
