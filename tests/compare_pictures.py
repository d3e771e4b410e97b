#!/usr/bin/env python3
"""Compares a picture with the expected one within a tolerance: the same
size, and few pixels that differ visibly (renderers and fonts move edges by
a pixel; a missing hole, a wrong colour or a moved path changes far more).
Usage: compare_pictures.py ACTUAL.png EXPECTED.png [--max-changed FRACTION]
Writes ACTUAL.diff.png (the changed pixels in red) when they differ."""
import argparse
import sys

from PIL import Image, ImageChops


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("actual")
    parser.add_argument("expected")
    parser.add_argument("--max-changed", type=float, default=0.0002,
                        help="the fraction of pixels that may differ")
    parser.add_argument("--threshold", type=int, default=48,
                        help="a channel difference that counts as a change")
    args = parser.parse_args()
    actual = Image.open(args.actual).convert("RGB")
    expected = Image.open(args.expected).convert("RGB")
    if actual.size != expected.size:
        print(f"{args.actual}: {actual.size} pixels, expected {expected.size}")
        return 1
    diff = ImageChops.difference(actual, expected).convert("L")
    changed = diff.point(lambda v: 255 if v > args.threshold else 0)
    count = sum(1 for v in changed.getdata() if v)
    fraction = count / (actual.size[0] * actual.size[1])
    print(f"{args.actual}: {count} pixels changed ({fraction:.4%}), "
          f"at most {args.max_changed:.4%}")
    if fraction > args.max_changed:
        red = Image.new("RGB", actual.size, (255, 0, 0))
        Image.composite(red, actual, changed).save(
            args.actual.removesuffix(".png") + ".diff.png")
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
