#!/usr/bin/env python3
"""Asserts that an rviz screenshot shows the predicted path: enough pixels in the sliding (magenta) and rolling
(cyan) colours of the trajectory markers (src/ros/trajectory_markers.cpp, phaseColour). With --upright, the path's
pixels must also run up the picture (a box at least three times as tall as wide): the cockpit's test turns the cue to
+y, which the top-down view shows upright, where the demo's shot before it ran across.

Usage: check_screenshot.py IMAGE.png [min_pixels] [--upright]. Exit 0 when the checks pass, 1 otherwise.
"""
import sys

from PIL import Image

COLOURS = {"sliding (magenta)": (255, 0, 255), "rolling (cyan)": (0, 255, 255)}
TOLERANCE = 40  # per channel: antialiasing blends the line's edges with the cloth


def matches(pixel, target):
    return all(abs(p - t) <= TOLERANCE for p, t in zip(pixel[:3], target))


def main():
    arguments = [a for a in sys.argv[1:] if not a.startswith("--")]
    upright = "--upright" in sys.argv[1:]
    path = arguments[0]
    minimum = int(arguments[1]) if len(arguments) > 1 else 200
    image = Image.open(path).convert("RGB")
    width = image.size[0]
    ok = True
    path_pixels = []
    for name, colour in COLOURS.items():
        found = [i for i, pixel in enumerate(image.getdata()) if matches(pixel, colour)]
        print(f"{name}: {len(found)} pixels (need {minimum})")
        ok = ok and len(found) >= minimum
        path_pixels += found
    if upright and path_pixels:
        xs = [i % width for i in path_pixels]
        ys = [i // width for i in path_pixels]
        box_width, box_height = max(xs) - min(xs) + 1, max(ys) - min(ys) + 1
        print(f"the path's box: {box_width} x {box_height} pixels (upright: at least 3 times as tall as wide)")
        ok = ok and box_height >= 3 * box_width
    print("visual check:", "passed" if ok else "FAILED")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
