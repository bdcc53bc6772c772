#!/usr/bin/python3
"""Framing that shows the lesson, and bodies that never hide it: renders the circle, catenary
and sinusoid presets and the gallery's cusp with --screenshot and --view-report, at 1920x1080 in
presentation mode and at 1280x800, and checks against each exact path (the closed forms of
resources/scenes/presets/*.json and gallery/cusp.json):
- with marker bodies, the exact path lies on the canvas and covers at least 60 % of it in the
  direction that limits it; in presentation the canvas is at least 55 % of the window;
- with the bodies to scale, at several times (the cusp's at the moment it is passed), each of 400
  exact points has a pixel of the path's band or of the controlled trail on it within 1.5 px,
  except under the knife at the controlled body's P (its position from --headless's CSV).
Standard library only; the PNG is read as a PPM from ImageMagick's convert."""
import csv
import json
import math
import os
import subprocess
import sys
import tempfile

from rendered_image import read_ppm

EXACT = {
    "circle": (lambda u: (2 * math.cos(u), 2 * math.sin(u)), 0, 2 * math.pi),
    "catenary": (lambda u: (math.sqrt(u * u + 1), math.asinh(u)), 0, 5),
    "sinusoid": (lambda x: (x, -math.sin(x)), 0, 4 * math.pi),
    "cusp": (lambda u: (u * u, u ** 3), -1, 1),
}
# times [s] the bodies are looked at; the cusp is passed at t = 1.948 s
TIMES = {"circle": (1, 3, 7), "catenary": (1, 2, 3.5), "sinusoid": (1, 2, 6), "cusp": (1, 1.948, 3)}
MODES = {"presentation": ["--presentation", "--size", "1920x1080"],
         "normal": ["--size", "1280x800"]}


def scene_args(name, source):
    if name == "cusp":
        return ["--scene", os.path.join(source, "resources/scenes/gallery/cusp.json")]
    return ["--preset", name]


def hsv_darker(rgb, factor):
    # QColor::darker: the value divided by factor / 100, hue and saturation kept
    return tuple(c * 100 / factor for c in rgb)


def path_colours(presenting):
    # the band (ui/canvas/scene_canvas_background.cpp): in presentation one grey; otherwise
    # halfway to white from grey towards the left-turn blue or the right-turn red
    if presenting:
        band = [(0x8c, 0x8c, 0x8c)]
    else:
        flat, band = (150, 150, 150), []
        for turn in ((40, 90, 230), (220, 60, 40)):
            for i in range(101):
                w = i / 100
                band.append(tuple(0.5 * 255 + 0.5 * (f + w * (t - f)) for f, t in zip(flat, turn)))
    # the controlled trail on it (ui/canvas/canvas_style.cpp, darker(150))
    trail = hsv_darker((0x00, 0x1f, 0x7a) if presenting else (0x1f, 0x77, 0xb4), 150)
    return band, trail


def render(exe, args, tmp, tag):
    png, report = os.path.join(tmp, tag + ".png"), os.path.join(tmp, tag + ".json")
    subprocess.run([exe, "--screenshot", png, "--view-report", report] + args, check=True)
    view = json.load(open(report))
    return view, read_ppm(png)


def samples(name):
    f, lo, hi = EXACT[name]
    return [f(lo + (hi - lo) * k / 399) for k in range(400)]


def check_framing(exe, source, tmp):
    failed = False
    for mode, mode_args in MODES.items():
        for name in EXACT:
            view, (width, height, _) = render(
                exe, scene_args(name, source) + mode_args + ["--body", "marker"], tmp,
                f"{mode}-{name}-frame")
            c, scale, (ox, oy) = view["canvas"], view["scale"], view["origin"]
            pts = [(ox + scale * x, oy - scale * y) for x, y in samples(name)]
            xs, ys = [p[0] for p in pts], [p[1] for p in pts]
            fill = max((max(xs) - min(xs)) / c["width"], (max(ys) - min(ys)) / c["height"])
            inside = all(c["x"] <= x <= c["x"] + c["width"] and c["y"] <= y <= c["y"] + c["height"]
                         for x, y in pts)
            share = c["width"] * c["height"] / (width * height)
            print(f"{mode} {name}: the path fills {fill:.3f} of the canvas, all on it: {inside}; "
                  f"the canvas is {share:.3f} of the window")
            if fill < 0.6 or not inside or (mode == "presentation" and share < 0.55):
                failed = True
    return failed


def body_positions(exe, source, name, tmp):
    out = os.path.join(tmp, name + ".csv")
    subprocess.run([exe, "--headless", "--csv", out] + scene_args(name, source), check=True,
                   capture_output=True)
    return [(float(r["t"]), float(r["x"]), float(r["y"])) for r in csv.DictReader(open(out))]


def check_visible(exe, source, tmp):
    failed = False
    for mode, mode_args in MODES.items():
        presenting = mode == "presentation"
        band, trail = path_colours(presenting)
        knife = 12 * (1.6 if presenting else 1) + 4  # [px] half the knife drawn over P, and more
        for name in EXACT:
            rows = body_positions(exe, source, name, tmp)
            f, lo, hi = EXACT[name]
            for t in TIMES[name]:
                view, (width, height, pixels) = render(
                    exe, scene_args(name, source) + mode_args + ["--body", "scale", "--at", str(t)],
                    tmp, f"{mode}-{name}-{t}")
                scale, (ox, oy) = view["scale"], view["origin"]

                def to_pixel(p):
                    return ox + scale * p[0], oy - scale * p[1]

                _, px_, py_ = min(rows, key=lambda r: abs(r[0] - t))
                body = to_pixel((px_, py_))
                ends = [to_pixel(f(lo)), to_pixel(f(hi))]
                memo = {}

                def drawn(px, py):
                    if (px, py) not in memo:
                        i = 3 * (py * width + px)
                        rgb = pixels[i:i + 3]
                        near = lambda col, tol: sum((a - b) ** 2 for a, b in zip(rgb, col)) <= tol ** 2
                        memo[(px, py)] = near(trail, 30) or any(near(b, 12) for b in band)
                    return memo[(px, py)]

                missed, checked = [], 0
                for p in samples(name):
                    x, y = to_pixel(p)
                    if math.hypot(x - body[0], y - body[1]) < knife:
                        continue
                    if min(math.hypot(x - ex, y - ey) for ex, ey in ends) < 24:
                        continue
                    checked += 1
                    if not any(drawn(px, py)
                               for px in range(int(math.floor(x - 2)), int(math.ceil(x + 2)) + 1)
                               for py in range(int(math.floor(y - 2)), int(math.ceil(y + 2)) + 1)
                               if 0 <= px < width and 0 <= py < height and
                               math.hypot(px + 0.5 - x, py + 0.5 - y) <= 1.5):
                        missed.append((round(x, 1), round(y, 1)))
                print(f"{mode} {name} t = {t}: to scale, {checked} points checked, "
                      f"{len(missed)} hidden")
                # at the cusp the path folds back under the knife: fewer points are left
                if missed or checked < 200:
                    print(f"  hidden: {missed[:8]}")
                    failed = True
    return failed


def main():
    exe, source = sys.argv[1], sys.argv[2]
    with tempfile.TemporaryDirectory() as tmp:
        failed = check_framing(exe, source, tmp)
        failed = check_visible(exe, source, tmp) or failed
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
