#!/usr/bin/python3
"""The drawn path is the exact path: renders the circle, catenary and sinusoid presets with
--screenshot, --body marker and --view-report, maps 400 points of each exact path (the preset's
closed form, resources/scenes/presets/*.json) through the reported metres-to-pixels map and
checks that each has a pixel of the path's band within 1.5 px. Standard library only; the PNG is
read as a PPM from ImageMagick's convert."""
import json
import math
import os
import subprocess
import sys
import tempfile

from rendered_image import read_ppm

EXACT = {
    "circle": lambda u: (2 * math.cos(u), 2 * math.sin(u)),
    "catenary": lambda u: (math.sqrt(u * u + 1), math.asinh(u)),
    "sinusoid": lambda x: (x, -math.sin(x)),
}
RANGE = {"circle": (0, 2 * math.pi), "catenary": (0, 5), "sinusoid": (0, 4 * math.pi)}


def band_colours():
    # the band's colours (ui/canvas/scene_canvas_background.cpp): halfway to white from grey
    # towards the left-turn blue or the right-turn red
    flat = (150, 150, 150)
    out = []
    for turn in ((40, 90, 230), (220, 60, 40)):
        for i in range(101):
            w = i / 100
            c = [f + w * (t - f) for f, t in zip(flat, turn)]
            out.append(tuple(0.5 * 255 + 0.5 * v for v in c))
    return out


def main():
    exe = sys.argv[1]
    colours = band_colours()
    failed = False
    with tempfile.TemporaryDirectory() as tmp:
        for preset, exact in EXACT.items():
            png, report = os.path.join(tmp, preset + ".png"), os.path.join(tmp, preset + ".json")
            subprocess.run([exe, "--screenshot", png, "--preset", preset, "--size", "1280x800",
                            "--body", "marker", "--view-report", report], check=True)
            view = json.load(open(report))
            scale, (ox, oy) = view["scale"], view["origin"]
            canvas = view["canvas"]
            width, height, pixels = read_ppm(png)
            band = {}

            def is_band(px, py):
                if (px, py) not in band:
                    i = 3 * (py * width + px)
                    rgb = pixels[i:i + 3]
                    band[(px, py)] = any(
                        sum((a - b) ** 2 for a, b in zip(rgb, c)) <= 12 ** 2 for c in colours)
                return band[(px, py)]

            def to_pixel(p):
                return ox + scale * p[0], oy - scale * p[1]

            lo, hi = RANGE[preset]
            # the start and end markers and the bodies (markers, at the start) cover the band
            ends = [to_pixel(exact(lo)), to_pixel(exact(hi))]
            missed, checked = [], 0
            for k in range(400):
                x, y = to_pixel(exact(lo + (hi - lo) * k / 399))
                if min(math.hypot(x - ex, y - ey) for ex, ey in ends) < 24:
                    continue
                inside = (canvas["x"] <= x < canvas["x"] + canvas["width"] and
                          canvas["y"] <= y < canvas["y"] + canvas["height"])
                if not inside:
                    missed.append((k, "outside the canvas"))
                    continue
                checked += 1
                # a pixel's centre within 1.5 px of the point
                near = any(is_band(px, py)
                           for px in range(int(math.floor(x - 2)), int(math.ceil(x + 2)) + 1)
                           for py in range(int(math.floor(y - 2)), int(math.ceil(y + 2)) + 1)
                           if 0 <= px < width and 0 <= py < height and
                           math.hypot(px + 0.5 - x, py + 0.5 - y) <= 1.5)
                if not near:
                    missed.append((k, (round(x, 1), round(y, 1))))
            print(f"{preset}: scale {scale:.4g} px/m, {checked} points checked, "
                  f"{len(missed)} without a band pixel within 1.5 px")
            if missed or checked < 300:
                print(f"  missed: {missed[:10]}")
                failed = True
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
