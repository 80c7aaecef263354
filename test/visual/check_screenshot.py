#!/usr/bin/env python3
"""Asserts that an rviz screenshot shows the predicted path: enough pixels in the sliding (magenta) and rolling
(cyan) colours of the trajectory markers (src/ros/trajectory_markers.cpp, phaseColour).

Usage: check_screenshot.py IMAGE.png [min_pixels]. Exit 0 when both colours are there, 1 otherwise.
"""
import sys

from PIL import Image

COLOURS = {"sliding (magenta)": (255, 0, 255), "rolling (cyan)": (0, 255, 255)}
TOLERANCE = 40  # per channel: antialiasing blends the line's edges with the cloth


def count(image, target):
    return sum(1 for pixel in image.getdata() if all(abs(p - t) <= TOLERANCE for p, t in zip(pixel[:3], target)))


def main():
    path = sys.argv[1]
    minimum = int(sys.argv[2]) if len(sys.argv) > 2 else 200
    image = Image.open(path).convert("RGB")
    ok = True
    for name, colour in COLOURS.items():
        n = count(image, colour)
        print(f"{name}: {n} pixels (need {minimum})")
        ok = ok and n >= minimum
    print("visual check:", "passed" if ok else "FAILED")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
