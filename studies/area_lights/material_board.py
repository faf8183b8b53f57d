"""The material board's area-light highlights against the exact integral (docs/area-lights.md,
"Specular by linearly transformed cosines"): the GPU's image with each area light's specular at
its representative point and by LTC, and the f64 reference, which integrates the lights exactly.

    /tmp/mi/bin/python studies/area_lights/material_board.py --shadelab target/release/shadelab

(after `python3 -m venv /tmp/mi && /tmp/mi/bin/pip install mitsuba numpy`: Mitsuba's Bitmap reads
the EXR files; lavapipe as the tests pick it, VK_ICD_FILENAMES and SHADELAB_ADAPTER=lavapipe).
The file's two lights become 1 m rectangles (`--light rect --light-size 1`), Cook-Torrance, the
file's own camera at 1280x720. Each sphere but the two glass ones is measured inside 0.85 of its
radius on the image, where no edge and no ground is: the light on it (Rec. 709 luminance summed)
and its brightest pixel, each over the reference's, and the pixels' RMS difference from the
reference over the reference's mean there.
"""

import argparse
import subprocess
import tempfile
from pathlib import Path

import mitsuba as mi
import numpy as np

# Each sphere's name (its material), centre and radius in pixels in the 1280x720 image.
SPHERES = [
    ("gold", 348, 205, 58), ("silver", 494, 205, 58), ("copper", 640, 205, 58),
    ("aluminium", 786, 205, 58), ("iron", 932, 205, 58), ("plastic (m = 0.15)", 813, 322, 68),
    ("plastic m=0.05", 212, 495, 85), ("plastic m=0.1", 426, 495, 85), ("plastic m=0.2", 640, 495, 85),
    ("plastic m=0.35", 853, 495, 85), ("plastic m=0.6", 1067, 495, 85),
]
SCENE = ["--scene", "assets/material-board.gltf", "--model", "cook-torrance", "--light", "rect",
         "--light-size", "1", "--width", "1280", "--height", "720"]


def render(binary, extra, out):
    subprocess.run([binary, "render", *SCENE, *extra, "--output", str(out)], check=True, stdout=subprocess.DEVNULL)
    return np.array(mi.Bitmap(str(out)))[:, :, :3].astype(np.float64) @ np.array([0.2126, 0.7152, 0.0722])


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--shadelab", required=True, help="the shadelab binary")
    args = ap.parse_args()
    mi.set_variant("scalar_rgb")
    with tempfile.TemporaryDirectory() as tmp:
        ref = render(args.shadelab, ["--reference"], Path(tmp) / "ref.exr")
        gpu = {s: render(args.shadelab, ["--area-specular", s], Path(tmp) / f"{s}.exr") for s in ["representative", "ltc"]}
    yy, xx = np.mgrid[0:ref.shape[0], 0:ref.shape[1]]
    print("| sphere | light / exact: representative point | LTC | brightest pixel / exact: representative point | LTC "
          "| pixel RMS / mean: representative point | LTC |")
    print("|---|---:|---:|---:|---:|---:|---:|")
    for name, cx, cy, r in SPHERES:
        inside = (xx - cx) ** 2 + (yy - cy) ** 2 < (0.85 * r) ** 2
        exact = ref[inside]
        light = [gpu[s][inside].sum() / exact.sum() for s in gpu]
        peak = [gpu[s][inside].max() / exact.max() for s in gpu]
        rms = [np.sqrt(((gpu[s][inside] - exact) ** 2).mean()) / exact.mean() for s in gpu]
        print(f"| {name} | {light[0]:.3f} | {light[1]:.3f} | {peak[0]:.2f} | {peak[1]:.2f} | {rms[0]:.3f} | {rms[1]:.3f} |")


if __name__ == "__main__":
    main()
