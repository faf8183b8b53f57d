#!/usr/bin/env python3
"""The Cornell box in shadelab's path-traced reference and in Mitsuba 3 (docs/reference.md,
"Checks against another renderer").

Builds in Mitsuba the scene shadelab's built-in `cornell` is (crates/shadelab-model/src/scene/
cornell.rs: the same boxes, light, albedos and camera), renders it there with the `path`
integrator on the CPU (`scalar_rgb`) and in shadelab with `render --reference --bounces`, and
prints how far they agree, for the direct light alone and with light between surfaces.

    python3 -m venv /tmp/mi && /tmp/mi/bin/pip install mitsuba numpy
    cargo build --release
    /tmp/mi/bin/python studies/mitsuba/cornell.py --shadelab target/release/shadelab

Both renderers' time at the same paths and at equal noise, in one run:

    /tmp/mi/bin/python studies/mitsuba/cornell.py --shadelab target/release/shadelab --timing --size 128 --spp 256 --bounces 4

The images the test `reference::cornell_tests` holds shadelab to were written by

    /tmp/mi/bin/python studies/mitsuba/cornell.py --write assets/mitsuba --size 96 --spp 4096 --bounces 1 4

Units: the chapter's light has no 1/pi and its point lights fall off as 1/(1 + alpha d^2), so the
scene's light is given intensity alpha*A*L/pi with alpha = 1e4; shadelab's pixels are then the
physical radiance Mitsuba computes (see the scene file). In shadelab's path tracer a bounce that
meets the light ends there (its front emits, its back is black); in Mitsuba the light is given a
black diffuse BSDF, which does the same (`--light-bsdf null` lets light through it instead, as
shadelab's path tracer did before its lights were surfaces). The light's own pixels (which the
test `the_light_the_camera_sees_is_mitsubas` compares), and pixels whose corners see different
faces (edges, where Mitsuba averages over the pixel and shadelab takes its centre), are left out.
"""

import argparse
import math
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import mitsuba as mi
import numpy as np

mi.set_variant("scalar_rgb")
T = mi.ScalarTransform4f

# The values of crates/shadelab-model/src/scene/cornell.rs.
ROOM = (0.556, 0.5488, 0.5592)
WALL = 0.01
LIGHT_SIZE = (0.130, 0.105)
LIGHT_CENTER = (0.278, 0.5487, 0.2795)
RADIANCE = (17.0, 12.0, 4.0)
WHITE, RED, GREEN = (0.73, 0.73, 0.73), (0.65, 0.05, 0.05), (0.12, 0.45, 0.15)
EYE, TARGET, FOV_Y = (0.278, 0.273, -0.8), (0.278, 0.273, 0.0), 39.3


def box(lo, hi, turn_deg, albedo):
    centre = [(a + b) / 2 for a, b in zip(lo, hi)]
    half = [(b - a) / 2 for a, b in zip(lo, hi)]
    return {
        "type": "cube",
        "to_world": T().translate(centre).rotate([0, 1, 0], turn_deg).scale(half),
        "bsdf": {"type": "diffuse", "reflectance": {"type": "rgb", "value": list(albedo)}},
    }


LIGHT_BSDF = {"black": {"type": "diffuse", "reflectance": {"type": "rgb", "value": [0.0, 0.0, 0.0]}},
              "null": {"type": "null"}}


def scene(size, spp, bounces, seed, light_bsdf="black"):
    w, h, d = ROOM
    t = WALL
    shapes = {
        "floor": box((-t, -t, -t), (w + t, 0, d + t), 0, WHITE),
        "ceiling": box((-t, h, -t), (w + t, h + t, d + t), 0, WHITE),
        "back": box((-t, -t, d), (w + t, h + t, d + t), 0, WHITE),
        "left": box((w, -t, -t), (w + t, h + t, d + t), 0, RED),
        "right": box((-t, -t, -t), (0, h + t, d + t), 0, GREEN),
        "short": box((0.1025, 0, 0.0860), (0.2685, 0.165, 0.2520), -16.6, WHITE),
        "tall": box((0.2855, 0, 0.2683), (0.4515, 0.330, 0.4343), 17.2, WHITE),
        "light": {
            "type": "rectangle",
            # The unit square's normal +z turned to -y; its x along x, its y along z.
            "to_world": T().translate(LIGHT_CENTER).rotate([1, 0, 0], 90).scale([LIGHT_SIZE[0] / 2, LIGHT_SIZE[1] / 2, 1]),
            # A surface that emits from its front and absorbs (black), as shadelab's path tracer's.
            "bsdf": LIGHT_BSDF[light_bsdf],
            "emitter": {"type": "area", "radiance": {"type": "rgb", "value": list(RADIANCE)}},
        },
    }
    return mi.load_dict({
        "type": "scene",
        # Mitsuba's depth counts the segment to the light: N surface vertices are depth N + 1.
        "integrator": {"type": "path", "max_depth": bounces + 1},
        "sensor": {
            "type": "perspective",
            "fov": FOV_Y,
            "fov_axis": "y",
            "to_world": T().look_at(origin=EYE, target=TARGET, up=[0, 1, 0]),
            "film": {"type": "hdrfilm", "width": size, "height": size, "rfilter": {"type": "box"}},
            "sampler": {"type": "independent", "sample_count": spp, "seed": seed},
        },
        **shapes,
    })


def mitsuba(size, spp, bounces, seed, light_bsdf="black"):
    return np.array(mi.render(scene(size, spp, bounces, seed, light_bsdf)))[:, :, :3]


def shadelab(binary, size, spp, bounces, out):
    cmd = [binary, "render", "--scene", "cornell", "--reference", "--bounces", str(bounces), "--spp", str(spp),
           "--width", str(size), "--height", str(size), "--output", str(out)]
    subprocess.run(cmd, check=True, stdout=subprocess.DEVNULL)
    return np.array(mi.Bitmap(str(out)))[:, :, :3]


def interior(size):
    """Pixels whose four corners see the same face of the same shape: there Mitsuba's average over
    the pixel and shadelab's ray through its centre see the same smooth surface."""
    sc = scene(size, 1, 1, 0)
    sensor = sc.sensors()[0]

    def face(u, v):
        ray, _ = sensor.sample_ray(0.0, 0.5, mi.ScalarPoint2f(u, v), mi.ScalarPoint2f(0.5, 0.5))
        si = sc.ray_intersect(ray)
        if not si.is_valid():
            return None
        n = si.n
        return (si.shape.id(), round(n[0], 3), round(n[1], 3), round(n[2], 3))

    corners = [[face(x / size, y / size) for x in range(size + 1)] for y in range(size + 1)]
    keep = np.zeros((size, size), dtype=bool)
    for y in range(size):
        for x in range(size):
            c = corners[y][x]
            keep[y, x] = c is not None and c == corners[y][x + 1] == corners[y + 1][x] == corners[y + 1][x + 1]
    return keep


def blocks(img, k=8):
    h, w, c = img.shape
    return img[: h // k * k, : w // k * k].reshape(h // k, k, w // k, k, c).mean(axis=(1, 3))


def timing(binary, size, spp, bounces, variants):
    """Each renderer's time and noise on the box at the same paths, in one run: Mitsuba's scalar_rgb
    and llvm_ad_rgb (after a warm-up render that compiles its kernels), shadelab's path tracer.
    The noise is two seeds' RMS difference over sqrt(2), on the compared pixels; the time to
    shadelab's noise scales each time by (its noise / shadelab's)^2, as noise falls as 1/sqrt(paths)."""
    keep = interior(size)
    rows = []
    for variant in variants:
        try:
            mi.set_variant(variant)
        except Exception as e:  # a variant this build of Mitsuba lacks
            print(f"({variant}: {e})")
            continue
        if variant != "scalar_rgb":
            mi.render(scene(size, 1, bounces, 3))
        t = time.perf_counter()
        a = np.array(mi.render(scene(size, spp, bounces, 1)))[:, :, :3]
        seconds = time.perf_counter() - t
        b = np.array(mi.render(scene(size, spp, bounces, 2)))[:, :, :3]
        rows.append((f"Mitsuba {variant}", seconds, math.sqrt(((a - b)[keep] ** 2).mean() / 2)))
    mi.set_variant("scalar_rgb")
    with tempfile.TemporaryDirectory() as tmp:
        imgs, seconds = [], None
        for seed in [1, 2]:
            out = Path(tmp) / f"s{seed}.exr"
            cmd = [binary, "render", "--scene", "cornell", "--reference", "--bounces", str(bounces), "--spp", str(spp),
                   "--seed", str(seed), "--width", str(size), "--height", str(size), "--output", str(out)]
            t = time.perf_counter()
            subprocess.run(cmd, check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
            seconds = seconds or time.perf_counter() - t
            imgs.append(np.array(mi.Bitmap(str(out)))[:, :, :3])
        rows.append(("shadelab (the whole process)", seconds, math.sqrt(((imgs[0] - imgs[1])[keep] ** 2).mean() / 2)))
    ours = rows[-1][2]
    print(f"# Cornell box, {size}x{size}, {bounces} surface vertices, {spp} paths a pixel in each")
    print("| renderer | time, s | noise (one image, RMS) | time to shadelab's noise, s |")
    print("|---|---:|---:|---:|")
    for name, seconds, noise in rows:
        print(f"| {name} | {seconds:.2f} | {noise:.3e} | {seconds * (noise / ours) ** 2:.2f} |")


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--shadelab", help="the shadelab binary")
    ap.add_argument("--size", type=int, default=256)
    ap.add_argument("--spp", type=int, default=256, help="paths a pixel in each renderer")
    ap.add_argument("--bounces", type=int, nargs="+", default=[1, 6])
    ap.add_argument("--light-bsdf", choices=sorted(LIGHT_BSDF), default="black",
                    help="the light's surface in Mitsuba: black (absorbs, as shadelab's) or null (passes light)")
    ap.add_argument("--timing", action="store_true",
                    help="time both renderers at the same paths (--size, --spp, the first --bounces) and at equal noise")
    ap.add_argument("--variants", nargs="+", default=["scalar_rgb", "llvm_ad_rgb"],
                    help="Mitsuba's variants --timing runs (an LLVM that cannot compile for this CPU aborts the process)")
    ap.add_argument("--write", metavar="DIR", help="only write Mitsuba's images, mitsuba-cornell-N.exr, N per --bounces")
    args = ap.parse_args()
    if args.timing:
        timing(args.shadelab, args.size, args.spp, args.bounces[0], args.variants)
        return 0
    if args.write:
        for bounces in args.bounces:
            out = Path(args.write) / f"mitsuba-cornell-{bounces}.exr"
            mi.Bitmap(mitsuba(args.size, args.spp, bounces, 1, args.light_bsdf).astype(np.float32)).write(str(out))
            print(f"wrote {out}: {args.size}x{args.size}, {args.spp} paths a pixel, {bounces} surface vertices")
        return 0
    print(f"# Cornell box, {args.size}x{args.size}, {args.spp} paths a pixel; Mitsuba {mi.__version__} scalar_rgb, "
          f"light BSDF {args.light_bsdf}")
    print("| surface vertices | mean, shadelab / Mitsuba (R, G, B) | pixel RMSE | the mean's noise (both) | 8x8 blocks: 95th percentile of |diff|/mean |")
    print("|---:|---|---:|---:|---:|")
    inside = interior(args.size)
    print(f"({inside.mean() * 100:.1f} % of the pixels are compared: those whose corners see one face of one shape)")
    with tempfile.TemporaryDirectory() as tmp:
        for bounces in args.bounces:
            a = mitsuba(args.size, args.spp, bounces, 1, args.light_bsdf)
            b = mitsuba(args.size, args.spp, bounces, 2, args.light_bsdf)
            s = shadelab(args.shadelab, args.size, args.spp, bounces, Path(tmp) / f"shadelab-{bounces}.exr")
            # The light's own pixels, and their neighbours, are left out.
            light = (a.max(axis=2) > 3.0) | (b.max(axis=2) > 3.0)
            light = light | np.roll(light, 1, 0) | np.roll(light, -1, 0) | np.roll(light, 1, 1) | np.roll(light, -1, 1)
            keep = ~light & inside
            m = (a + b) / 2
            ratio = [s[keep][:, c].mean() / m[keep][:, c].mean() for c in range(3)]
            rmse = math.sqrt(((s - m)[keep] ** 2).mean())
            # Two Mitsuba images differ by sqrt(2) times one's noise; their mean has half its variance.
            noise = math.sqrt(((a - b)[keep] ** 2).mean() / 2) / math.sqrt(2)
            kb = blocks(keep[:, :, None].astype(float))[:, :, 0] > 0.99
            bs, bm = blocks(s)[kb], blocks(m)[kb]
            rel = np.abs(bs - bm).mean(axis=1) / np.maximum(bm.mean(axis=1), 1e-6)
            print(f"| {bounces} | {ratio[0]:.4f}, {ratio[1]:.4f}, {ratio[2]:.4f} | {rmse:.3e} | {noise:.3e} | {np.percentile(rel, 95):.4f} |")
    return 0


if __name__ == "__main__":
    sys.exit(main())
