#!/usr/bin/env python3
"""Fireflies in images (docs/reference.md, "Fireflies"): the pixels whose luminance is above 10 times
the median of their 3x3 neighbourhood (itself included; at the border, the neighbours inside),
as `shadelab render --reference --bounces` prints it (`reference::outlier_pixels`). It reads any
renderer's EXR alike, so an older shadelab's image and Mitsuba's are counted the same way.

    /tmp/mi/bin/python studies/mitsuba/fireflies.py IMAGE.exr...
"""

import sys

import mitsuba as mi
import numpy as np

mi.set_variant("scalar_rgb")
FACTOR = 10.0


def outliers(img):
    lum = 0.2126 * img[:, :, 0] + 0.7152 * img[:, :, 1] + 0.0722 * img[:, :, 2]
    h, w = lum.shape
    count = 0
    for y in range(h):
        for x in range(w):
            around = np.sort(lum[max(y - 1, 0):y + 2, max(x - 1, 0):x + 2].ravel())
            if lum[y, x] > FACTOR * around[len(around) // 2]:
                count += 1
    return count


def main():
    for path in sys.argv[1:]:
        img = np.array(mi.Bitmap(path)).astype(np.float64)[:, :, :3]
        n = outliers(img)
        print(f"{path}: {n} of {img.shape[0] * img.shape[1]} pixels above {FACTOR:g}x their 3x3 median "
              f"({100 * n / (img.shape[0] * img.shape[1]):.2f} %)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
