#!/usr/bin/env python3
"""Scene links through the command line (docs/user-guide.md, Sharing a scene as a link).

scene_link_test.py EXE SOURCE_DIR. For every preset and gallery scene file: `--link` prints a
link under 2,000 characters that Python's own base64 and zlib decode to a scene, and the scene
read back through the link (`--scene LINK`) has the same summary as the file, or the same
refusal; a link that Python encodes from the file itself reads the same. Then the screenshot mode
opens a link, the window's argument takes one (and a file: URL), and a decompression bomb is refused within a second and without inflating it
(the peak memory of the run beside that of a plain one).
"""
import base64
import json
import pathlib
import subprocess
import sys
import tempfile
import time
import zlib

exe, source = sys.argv[1], pathlib.Path(sys.argv[2])
failures = []


def run(*args):
    """The program's exit status, stdout, stderr, wall time and peak resident memory [kB], the
    last measured by GNU time (a fork of this Python would count Python's own memory)."""
    with tempfile.NamedTemporaryFile() as memory:
        start = time.monotonic()
        done = subprocess.run(["/usr/bin/time", "-f", "%M", "-o", memory.name, exe, *args],
                              capture_output=True, text=True)
        seconds = time.monotonic() - start
        return (done.returncode, done.stdout, done.stderr, seconds,
                int(pathlib.Path(memory.name).read_text().split()[-1]))


def decode(link):
    assert link.startswith("chaplygin-lab:"), link[:40]
    payload = link[len("chaplygin-lab:"):]
    return zlib.decompress(base64.urlsafe_b64decode(payload + "=" * (-len(payload) % 4)))


def encode(data):
    return "chaplygin-lab:" + base64.urlsafe_b64encode(zlib.compress(data, 9)).decode().rstrip("=")


def comparable(summary):
    """The summary without the path table's certified bounds, which vary in their last digits
    from run to run of the same file."""
    try:
        parsed = json.loads(summary)
    except json.JSONDecodeError:
        return summary
    path = parsed.get("models", {}).get("path")
    if isinstance(path, str) and "bounds:" in path:
        parsed["models"]["path"] = path[:path.index("bounds:")]
    return parsed


def check(condition, message):
    if not condition:
        failures.append(message)


files = sorted((source / "resources" / "scenes").glob("*/*.json"))
check(len(files) >= 18, f"only {len(files)} scene files")
longest = 0
for path in files:
    name = path.relative_to(source / "resources" / "scenes")
    status, link, err, _, _ = run("--headless", "--scene", str(path), "--link")
    link = link.strip()
    check(status == 0, f"{name}: --link exited {status}: {err}")
    if status != 0:
        continue
    longest = max(longest, len(link))
    check(len(link) < 2000, f"{name}: the link has {len(link)} characters")
    check(set(link[len("chaplygin-lab:"):]) <= set(
        "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789-_"),
          f"{name}: the link is not URL-safe")
    held = json.loads(decode(link))
    check(held.get("format") == "chaplygin-lab-scene", f"{name}: the link holds {held}")
    from_file = run("--headless", "--scene", str(path), "--summary", "-")
    for how, given in (("--link", link), ("Python's encoding", encode(path.read_bytes()))):
        from_link = run("--headless", "--scene", given, "--summary", "-")
        check(from_link[0] == from_file[0], f"{name} via {how}: exit {from_link[0]}, "
              f"the file's {from_file[0]}")
        check(comparable(from_link[1]) == comparable(from_file[1]),
              f"{name} via {how}: another summary")
        if from_file[0] != 0:  # a gallery scene the core refuses: the same words
            check(from_link[2] == from_file[2], f"{name} via {how}: {from_link[2]!r} "
                  f"instead of {from_file[2]!r}")
print(f"{len(files)} scenes round-trip; the longest link has {longest} characters")

# the screenshot mode takes a link where it takes a file, and refuses a bad one
with tempfile.TemporaryDirectory() as work:
    circle = run("--headless", "--preset", "circle", "--link")[1].strip()
    picture = pathlib.Path(work) / "circle.png"
    status, _, err, _, _ = run("--screenshot", str(picture), "--size", "640x400", "--scene", circle)
    check(status == 0 and picture.stat().st_size > 1000, f"screenshot of a link: {status} {err}")
    status, _, err, _, _ = run("--screenshot", str(picture) + "2", "--scene", circle[:100])
    check(status == 2 and "scene link: truncated" in err, f"screenshot of a bad link: {status} {err}")
    check(not pathlib.Path(str(picture) + "2").exists(), "a bad link wrote a screenshot")

# the window's argument, from a terminal (where a bad one exits 2 instead of a dialog): a bad
# link is refused naming what is wrong, and a file: URL (the desktop entry's %u) is a file
def window(argument):
    done = subprocess.run(["script", "-qec", f"{exe} '{argument}'", "/dev/null"],
                          capture_output=True, text=True, timeout=60)
    return done.returncode, done.stdout


status, said = window(circle[:150])
check(status == 2 and "scene link: truncated" in said, f"the window's bad link: {status} {said}")
status, said = window("mailto:someone@example.org")
check(status == 2 and "'mailto:' is another scheme" in said, f"the window's mailto: {status} {said}")
status, said = window("file:///nonexistent/my%20lesson.json")
check(status == 2 and "cannot open '/nonexistent/my lesson.json'" in said,
      f"the window's file: URL: {status} {said}")

# a bomb: 256 MB of spaces in a 340 kB zlib stream would be too long an argument; 96 MB in
# about 130,000 characters is not, and must cost no more memory than reading a small link
bomb = encode(b" " * (96 << 20))
check(len(bomb) < 131072, f"the bomb has {len(bomb)} characters")
line = run("--headless", "--preset", "line", "--link")[1].strip()
status, _, _, _, plain_memory = run("--headless", "--scene", line, "--link")
check(status == 0, "the line's link does not read")
status, _, err, seconds, bomb_memory = run("--headless", "--scene", bomb, "--link")
check(status == 2 and "inflates to more than 1048576 bytes" in err, f"the bomb: {status} {err}")
check(seconds < 1.0, f"the bomb took {seconds:.2f} s")
check(bomb_memory < plain_memory + 8 * 1024,
      f"the bomb's run peaked at {bomb_memory} kB, a plain one at {plain_memory} kB")
print(f"bomb: refused in {seconds:.3f} s, peak {bomb_memory} kB (a plain link {plain_memory} kB)")

for failure in failures:
    print("FAIL:", failure)
sys.exit(1 if failures else 0)
