#!/usr/bin/env python3
"""Writes the small seed inputs of the texture_image, env_image and extras targets into seeds/
(run from anywhere). The load_scene target is seeded with ../tests/gltf-corpus and ../assets
instead, and env_image with ../assets/mitsuba's OpenEXR files too."""
import json
import math
import os
import struct
import zlib

HERE = os.path.join(os.path.dirname(os.path.abspath(__file__)), "seeds")


def png(width, height, color_type, depth, pixel):
    """A whole PNG of width × height, every pixel the bytes `pixel`."""
    def chunk(kind, data):
        return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data))
    ihdr = struct.pack(">IIBBBBB", width, height, depth, color_type, 0, 0, 0)
    rows = b"".join(b"\0" + pixel * width for _ in range(height))
    return b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", ihdr) + chunk(b"IDAT", zlib.compress(rows)) + chunk(b"IEND", b"")


def hdr_header(width, height):
    return b"#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n" + f"-Y {height} +X {width}\n".encode()


def rgbe(r, g, b):
    """One texel as Radiance's shared-exponent bytes."""
    v = max(r, g, b)
    if v < 1e-32:
        return bytes(4)
    m, e = math.frexp(v)
    return bytes([int(r * m * 256 / v), int(g * m * 256 / v), int(b * m * 256 / v), e + 128])


def hdr_flat(width, height):
    """A Radiance HDR of uncompressed texels, a sky-like gradient."""
    texels = (rgbe(0.2 + x / width, 0.4, 1.0 - y / height) for y in range(height) for x in range(width))
    return hdr_header(width, height) + b"".join(texels)


def hdr_rle(width, height):
    """A Radiance HDR of run-length scanlines, each channel one literal run (8 ≤ width < 128)."""
    out = hdr_header(width, height)
    for y in range(height):
        px = [rgbe(1.0 + x, 0.5, 0.25 * y) for x in range(width)]
        out += bytes([2, 2, width >> 8, width & 255])
        for c in range(4):
            out += bytes([width]) + bytes(p[c] for p in px)
    return out


SEEDS = {
    "texture_image": {
        "rgba-1x1.png": png(1, 1, 6, 8, b"\xff\x80\x00\xff"),
        "rgb-4x4.png": png(4, 4, 2, 8, b"\x20\x40\x60"),
        "grey-3x2.png": png(3, 2, 0, 8, b"\x7f"),
        "grey-alpha-2x2.png": png(2, 2, 4, 8, b"\x7f\xff"),
        "rgba16-2x2.png": png(2, 2, 6, 16, b"\xff\xff\x00\x00\x80\x00\xff\xff"),
        # A JPEG's start of image, a frame header of 8×8 and its end: the decoder's header path.
        "jpeg-header.jpg": b"\xff\xd8\xff\xc0\x00\x11\x08\x00\x08\x00\x08\x03\x01\x11\x00\x02\x11\x01\x03\x11\x01\xff\xd9",
    },
    "env_image": {
        "sky-4x2.hdr": hdr_flat(4, 2),
        "rle-16x8.hdr": hdr_rle(16, 8),
        "square-3x3.hdr": hdr_flat(3, 3),
        # Declares 8192 × 4096 texels and holds none: refused, never allocated in full.
        "declared-huge.hdr": hdr_header(8192, 4096),
    },
    "extras": {
        "material.json": json.dumps({"m": 0.3, "h": 40, "mu": [0.9, 0.6, 0.2], "r_s": 1.0, "r_d": 0.8}).encode(),
        "mirror.json": json.dumps({"h": "mirror"}).encode(),
        "light.json": json.dumps({"I_L": 2.0, "alpha": 0.1, "falloff_form": "linear", "d0": 0.5,
                                  "casts_shadows": True, "shadow_resolution": 1024, "shadow_filter": "pcss",
                                  "pcss_taps": 16, "shadow_cascades": False}).encode(),
        "scene.json": json.dumps({"shading": "gouraud", "specular": "cook-torrance", "ambient": [0.1, 0.1, 0.1]}).encode(),
        "empty.json": b"{}",
    },
}


def main():
    for target, files in SEEDS.items():
        os.makedirs(os.path.join(HERE, target), exist_ok=True)
        for name, data in files.items():
            with open(os.path.join(HERE, target, name), "wb") as f:
                f.write(data)
    print("wrote", sum(len(f) for f in SEEDS.values()), "seeds")


if __name__ == "__main__":
    main()
