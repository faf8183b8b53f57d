#!/usr/bin/env python3
"""Writes the malformed glTF corpus and its README table (run from anywhere: python3 make_corpus.py).

Each case is one small file, broken in one way, and the text its error line must contain. The
test `gltf_io::tests::malformed_corpus_gives_the_expected_errors` reads the README's table.
"""
import base64
import copy
import json
import os
import struct

HERE = os.path.dirname(os.path.abspath(__file__))

# Eight corners of a cube and two triangles that use them (u16 indices).
POSITIONS = [(x, y, z) for x in (0.0, 1.0) for y in (0.0, 1.0) for z in (0.0, 1.0)]
INDICES = [0, 1, 3, 0, 3, 2]


def f32s(values):
    return b"".join(struct.pack("<f", v) for v in values)


def base_parts(positions=POSITIONS, indices=INDICES):
    pos = f32s([c for p in positions for c in p])
    idx = struct.pack(f"<{len(indices)}H", *indices)
    bin_ = pos + idx + b"\0" * (-len(idx) % 4)
    doc = {
        "asset": {"version": "2.0"},
        "scene": 0,
        "scenes": [{"nodes": [0]}],
        "nodes": [{"mesh": 0}],
        "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "indices": 1}]}],
        "accessors": [
            {"bufferView": 0, "componentType": 5126, "count": len(positions), "type": "VEC3",
             "min": [0, 0, 0], "max": [1, 1, 1]},
            {"bufferView": 1, "componentType": 5123, "count": len(indices), "type": "SCALAR"},
        ],
        "bufferViews": [
            {"buffer": 0, "byteOffset": 0, "byteLength": len(pos)},
            {"buffer": 0, "byteOffset": len(pos), "byteLength": len(idx)},
        ],
    }
    return doc, bin_


def embed(doc, bin_, byte_length=None):
    doc = copy.deepcopy(doc)
    doc["buffers"] = [{
        "byteLength": len(bin_) if byte_length is None else byte_length,
        "uri": "data:application/octet-stream;base64," + base64.b64encode(bin_).decode(),
    }]
    return json.dumps(doc, indent=1).encode()


def glb(doc, bin_):
    doc = copy.deepcopy(doc)
    doc["buffers"] = [{"byteLength": len(bin_)}]
    j = json.dumps(doc).encode()
    j += b" " * (-len(j) % 4)
    b = bin_ + b"\0" * (-len(bin_) % 4)
    total = 12 + 8 + len(j) + 8 + len(b)
    return (b"glTF" + struct.pack("<II", 2, total) + struct.pack("<I", len(j)) + b"JSON" + j
            + struct.pack("<I", len(b)) + b"BIN\0" + b)


def edited(fn, positions=POSITIONS, indices=INDICES):
    doc, bin_ = base_parts(positions, indices)
    fn(doc)
    return embed(doc, bin_)


CASES = []


def case(name, what, expected, data):
    CASES.append((name, what, expected, data))


valid_glb = glb(*base_parts())
case("truncated.glb", "a valid GLB cut after 100 bytes", "truncated GLB: the header says", valid_glb[:100])
case("truncated.gltf", "a valid .gltf cut in the middle of its JSON", "invalid glTF JSON: EOF while parsing",
     embed(*base_parts())[:300])
case("wrong-magic.glb", "a GLB whose magic is `glTX`", "not a glTF file: it starts with \"glTX\"",
     b"glTX" + valid_glb[4:])
case("glb-version-1.glb", "a GLB header of version 1", "GLB version 1 (only 2 is read)",
     valid_glb[:4] + struct.pack("<I", 1) + valid_glb[8:])
case("glb-length-below-header.glb", "GLB header length 4 (below its own 12 bytes; gltf 1.4.1 subtracts unchecked)",
     "GLB without a JSON chunk", valid_glb[:8] + struct.pack("<I", 4) + valid_glb[12:])
case("glb-json-chunk-too-long.glb", "the JSON chunk claims more bytes than the file has",
     "truncated GLB: a JSON chunk of 1000000", valid_glb[:12] + struct.pack("<I", 1000000) + valid_glb[16:])
case("empty.gltf", "an empty file", "empty file", b"")
case("invalid-json.gltf", "JSON with a syntax error", "invalid glTF JSON: key must be a string at line 1 column 30",
     b'{"asset": {"version": "2.0"},, "nodes": []}')
case("missing-count.gltf", "an accessor without its required count", "invalid glTF JSON: missing field",
     edited(lambda d: d["accessors"][0].pop("count")))
case("accessor-past-buffer-view.gltf", "POSITION accessor of 9 vertices over a view of 8",
     "accessor 0: 9 elements of 12 bytes from offset 0 need 108 bytes, buffer view 0 has 96",
     edited(lambda d: d["accessors"][0].update(count=9)))
case("buffer-view-past-buffer.gltf", "a buffer view that ends past its buffer",
     "buffer view 0: bytes 0..1000 are past the end of buffer 0",
     edited(lambda d: d["bufferViews"][0].update(byteLength=1000)))
case("index-past-vertex-count.gltf", "index 17 in a mesh of 8 vertices",
     "mesh 0 primitive 0: index 17 is past the vertex count 8",
     embed(*base_parts(indices=[0, 1, 17, 0, 3, 2])))
case("nan-position.gltf", "a NaN vertex position", "mesh 0 primitive 0: POSITION 1 is not finite",
     embed(*base_parts(positions=[POSITIONS[0], (float("nan"), 0.0, 0.0)] + POSITIONS[2:])))
case("inf-position.gltf", "an infinite vertex position", "mesh 0 primitive 0: POSITION 7 is not finite",
     embed(*base_parts(positions=POSITIONS[:7] + [(0.0, float("inf"), 0.0)])))
case("huge-count.gltf", "an accessor declaring 10^9 vertices over 96 bytes",
     "1000000000 elements of 12 bytes from offset 0 need 12000000000 bytes",
     edited(lambda d: d["accessors"][0].update(count=1000000000)))
case("huge-buffer.gltf", "a buffer declaring 10^8 bytes with 108 bytes of data",
     "buffer 0: byteLength 100000000 but its data: URI holds 108 bytes",
     embed(*base_parts(), byte_length=10**8))
case("buffer-over-limit.gltf", "a buffer declaring 10^12 bytes, more than any scene can use",
     "buffer 0: byteLength 1000000000000 is more than the limit of 2147483648 (MAX_FILE_BYTES)",
     embed(*base_parts(), byte_length=10**12))


doc, bin_ = base_parts()
doc["buffers"] = [{"byteLength": len(bin_), "uri": "missing.bin"}]
case("missing-external-buffer.gltf", "an external buffer file that does not exist",
     "buffer 0: cannot read 'missing.bin'", json.dumps(doc, indent=1).encode())
doc["buffers"] = [{"byteLength": len(bin_), "uri": "data:application/octet-stream;base64,@@@@"}]
case("bad-base64.gltf", "a data: URI that is not base64", "buffer 0: bad base64 data",
     json.dumps(doc, indent=1).encode())


def external(uri, extra_buffer=None):
    """The base cube with its buffer at `uri` (and a second buffer nothing uses, if given)."""
    doc, bin_ = base_parts()
    doc["buffers"] = [{"byteLength": len(bin_), "uri": uri}]
    if extra_buffer:
        doc["buffers"].append({"byteLength": 16, "uri": extra_buffer})
    return json.dumps(doc, indent=1).encode()


# A scene reads only what lies in its own folder (gltf_io/confine.rs).
case("uri-absolute-path.gltf", "a buffer at /etc/passwd",
     "buffer 0: '/etc/passwd' is an absolute path, outside the scene's folder", external("/etc/passwd"))
case("uri-traversal.gltf", "a buffer at ../../../../etc/hostname",
     "buffer 0: '../../../../etc/hostname' leaves the scene's folder through '..'",
     external("../../../../etc/hostname"))
case("uri-link-outside.gltf", "a buffer through outside-link.bin, a link to the repository's Cargo.toml",
     "buffer 0: 'outside-link.bin' is a link to", external("outside-link.bin"))
case("uri-remote.gltf", "a buffer at http://example.com/cube.bin",
     "buffer 0: 'http://example.com/cube.bin' is a remote URI; shadelab never opens a network connection",
     external("http://example.com/cube.bin"))
case("unused-outside-buffer.gltf", "a second buffer at /etc/passwd that no view uses: not read",
     "warning: buffer 1: no accessor or image uses it: skipped, not read",
     external("data:application/octet-stream;base64," + base64.b64encode(base_parts()[1]).decode(), "/etc/passwd"))
case("unsupported-required-extension.gltf", "requires KHR_draco_mesh_compression",
     "requires unsupported extension(s): KHR_draco_mesh_compression",
     edited(lambda d: d.update(extensionsUsed=["KHR_draco_mesh_compression"],
                               extensionsRequired=["KHR_draco_mesh_compression"])))
case("accessor-index-out-of-range.gltf", "POSITION names accessor 5 of 2 (gltf 1.4.1's validate() panics here)",
     "mesh 0 primitive 0: POSITION: accessor 5 does not exist (the file has 2)",
     edited(lambda d: d["meshes"][0]["primitives"][0]["attributes"].update(POSITION=5)))
case("node-cycle.gltf", "node 0 and node 1 are each other's child", "node 0 is reached twice",
     edited(lambda d: d.update(nodes=[{"mesh": 0, "children": [1]}, {"children": [0]}])))


def deep(d):
    d["nodes"] = [{"children": [i + 1]} for i in range(299)] + [{"mesh": 0}]


case("node-depth-300.gltf", "a chain of 300 nested nodes", "the hierarchy is deeper than 256 (MAX_NODE_DEPTH)",
     edited(deep))
case("child-out-of-range.gltf", "a node whose child does not exist", "node 0: child node 9 does not exist",
     edited(lambda d: d["nodes"][0].update(children=[9])))
case("stride-below-element.gltf", "byteStride 4 for 12-byte positions",
     "buffer view 0: byteStride 4 is less than the 12-byte elements",
     edited(lambda d: d["bufferViews"][0].update(byteStride=4)))
case("sparse-accessor.gltf", "a sparse POSITION accessor whose 6 UNSIGNED_INT indices need more bytes than their view",
     "accessor 0: sparse indices: 6 elements need 24 bytes from offset 0, buffer view 1 has 12",
     edited(lambda d: d["accessors"][0].update(sparse={
         "count": 6, "indices": {"bufferView": 1, "componentType": 5125}, "values": {"bufferView": 0}})))
case("indices-not-multiple-of-3.gltf", "5 indices for a triangle list", "5 indices is not a multiple of 3",
     embed(*base_parts(indices=[0, 1, 3, 0, 3])))
case("normal-count-mismatch.gltf", "3 normals for 8 positions", "3 NORMALs for 8 POSITIONs",
     edited(lambda d: (d["accessors"].append(
         {"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3"}),
         d["meshes"][0]["primitives"][0]["attributes"].update(NORMAL=2))))
case("zero-quaternion.gltf", "a node rotation of (0, 0, 0, 0)", "node 0: rotation",
     edited(lambda d: d["nodes"][0].update(rotation=[0, 0, 0, 0])))
case("infinite-translation.gltf", "a translation of 1e39 (beyond f32)", "invalid glTF JSON: number out of range",
     edited(lambda d: d["nodes"][0].update(translation=[1e39, 0, 0])))


def png_header(width, height):
    """A PNG (valid CRCs) declaring width × height RGBA8: whole pixel data for a small image; for a
    large one an IDAT with one row's start only, as a hostile file would declare more than it holds."""
    import zlib

    def chunk(kind, data):
        return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data))
    ihdr = struct.pack(">IIBBBBB", width, height, 8, 6, 0, 0, 0)
    rows = b"".join(b"\0" + b"\xff" * (4 * width) for _ in range(height)) if width * height <= 64 else b"\0" * 16
    return (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", ihdr) + chunk(b"IDAT", zlib.compress(rows))
            + chunk(b"IEND", b""))


def textured(image, sampler=None, texture_index=0):
    """The base cube with a material whose base colour texture is `image` (a glTF image object)."""
    def fn(d):
        d["materials"] = [{"pbrMetallicRoughness": {"baseColorTexture": {"index": texture_index}}}]
        d["meshes"][0]["primitives"][0]["material"] = 0
        d["textures"] = [{"source": 0} if sampler is None else {"source": 0, "sampler": sampler}]
        d["images"] = [image]
    return fn


case("texture-index-out-of-range.gltf", "a base colour texture index past the textures",
     "material 0: baseColorTexture: texture 3 does not exist",
     edited(textured({"uri": "data:image/png;base64," + base64.b64encode(png_header(1, 1)).decode()},
                     texture_index=3)))
case("image-huge-declared.gltf", "a PNG whose header declares 100000 × 100000 pixels",
     "image 0: 100000×100000 pixels, outside 1..=8192 per side (MAX_TEXTURE_SIDE)",
     edited(textured({"uri": "data:image/png;base64," + base64.b64encode(png_header(100000, 100000)).decode()})))
case("image-absolute-path.gltf", "a base colour texture at /etc/passwd",
     "image 0: '/etc/passwd' is an absolute path, outside the scene's folder",
     edited(textured({"uri": "/etc/passwd"})))
case("image-truncated-png.gltf", "a base colour texture whose PNG is cut after its header: not used",
     "warning: image 0:",
     edited(textured({"uri": "data:image/png;base64," + base64.b64encode(png_header(4, 4)[:60]).decode()})))
case("image-view-past-buffer.gltf", "an image in a buffer view that ends past its buffer",
     "buffer view 2: bytes 0..4000 are past the end of buffer 0",
     edited(lambda d: (textured({"bufferView": 2, "mimeType": "image/png"})(d),
                       d["bufferViews"].append({"buffer": 0, "byteOffset": 0, "byteLength": 4000}))))
case("sampler-out-of-range.gltf", "a texture whose sampler does not exist",
     "texture 0: sampler 5 does not exist",
     edited(textured({"uri": "data:image/png;base64," + base64.b64encode(png_header(1, 1)).decode()}, sampler=5)))
case("normal-texture-out-of-range.gltf", "a normal texture index past the textures",
     "material 0: normalTexture: texture 2 does not exist",
     edited(lambda d: (textured({"uri": "data:image/png;base64," + base64.b64encode(png_header(1, 1)).decode()})(d),
                       d["materials"][0].update(normalTexture={"index": 2}))))
case("metal-roughness-texture-out-of-range.gltf", "a metallic–roughness texture index past the textures",
     "material 0: metallicRoughnessTexture: texture 7 does not exist",
     edited(lambda d: (textured({"uri": "data:image/png;base64," + base64.b64encode(png_header(1, 1)).decode()})(d),
                       d["materials"][0]["pbrMetallicRoughness"].update(metallicRoughnessTexture={"index": 7}))))
case("tangent-wrong-type.gltf", "a TANGENT accessor of VEC3 (glTF's is VEC4)",
     "mesh 0 primitive 0: TANGENT: accessor 0 is Vec3 of F32; Vec4 of FLOAT",
     edited(lambda d: d["meshes"][0]["primitives"][0]["attributes"].update(TANGENT=0)))
case("sparse-indices-not-increasing.gltf", "a sparse accessor whose indices go back",
     "is not increasing or not below the count 8",
     edited(lambda d: d["accessors"][0].update(sparse={
         "count": 2, "indices": {"bufferView": 1, "componentType": 5123}, "values": {"bufferView": 0}}),
         indices=[3, 1, 3, 0, 3, 2]))


def overflow(d):
    d["nodes"] = [{"scale": [1e38, 1e38, 1e38], "children": [i + 1]} for i in range(9)] + [{"mesh": 0}]


case("overflowing-hierarchy.gltf", "nine nested scales of 1e38: the world transform overflows f64",
     "node 8: its world transform is not finite", edited(overflow))
case("material-out-of-range.gltf", "a primitive naming material 4 of none",
     "mesh 0 primitive 0: material 4 does not exist (the file has 0)",
     edited(lambda d: d["meshes"][0]["primitives"][0].update(material=4)))
case("light-out-of-range.gltf", "a node naming KHR_lights_punctual light 3 of 1", "node 0: light 3 does not exist",
     edited(lambda d: (d.update(extensionsUsed=["KHR_lights_punctual"],
                                extensions={"KHR_lights_punctual": {"lights": [{"type": "point"}]}}),
                       d["nodes"][0].update(extensions={"KHR_lights_punctual": {"light": 3}}))))
def with_light(light):
    def edit(d):
        d.update(extensionsUsed=["KHR_lights_punctual"], extensions={"KHR_lights_punctual": {"lights": [light]}})
        d["nodes"].append({"translation": [0, 2, 0], "extensions": {"KHR_lights_punctual": {"light": 0}}})
        d["scenes"][0]["nodes"].append(1)
    return edited(edit)


case("spot-cone-inverted.gltf", "a spot light whose inner cone is wider than its outer cone",
     "light 0: spot cone angles inner 0.8, outer 0.3 must be 0 ≤ inner < outer ≤ π/2",
     with_light({"type": "spot", "spot": {"innerConeAngle": 0.8, "outerConeAngle": 0.3}}))
case("spot-cone-past-90.gltf", "a spot light with an outer cone of 2 radians (past a half-space)",
     "light 0: spot cone angles inner 0, outer 2 must be 0 ≤ inner < outer ≤ π/2",
     with_light({"type": "spot", "spot": {"outerConeAngle": 2.0}}))
case("light-range-zero.gltf", "a point light with range 0", "light 0: range 0 is not in [0.000001, 1000000000]",
     with_light({"type": "point", "range": 0}))
case("shadow-resolution-too-small.gltf", "a light whose shadow map side in extras is 100 texels",
     "light 0: extras.shadelab.shadow_resolution = 100 is not an integer in [256, 4096]",
     with_light({"type": "point", "extras": {"shadelab": {"shadow_resolution": 100}}}))
case("shadow-filter-unknown.gltf", "a light whose shadow filter in extras is \"vsm\"",
     "light 0: extras.shadelab.shadow_filter = \"vsm\" is not one of hard, pcf, poisson",
     with_light({"type": "directional", "extras": {"shadelab": {"shadow_filter": "vsm"}}}))
case("camera-zero-fov.gltf", "a perspective camera with yfov 0", "camera 0: yfov 0 is not in (0, π)",
     edited(lambda d: (d.update(cameras=[{"type": "perspective", "perspective": {"yfov": 0, "znear": 0.1}}]),
                       d["nodes"].append({"camera": 0}), d["scenes"][0]["nodes"].append(1))))
case("extras-h-not-a-number.gltf", "material extras with h = \"sharp\"",
     "material 0: extras.shadelab.h = \"sharp\" is not a number in [1, 1000000000]",
     edited(lambda d: (d.update(materials=[{"extras": {"shadelab": {"h": "sharp"}}}]),
                       d["meshes"][0]["primitives"][0].update(material=0))))
case("points-only.gltf", "a mesh of points only: nothing to show", "the scene has no triangle meshes to show",
     edited(lambda d: d["meshes"][0]["primitives"][0].update(mode=0)))


def with_environment(env):
    return edited(lambda d: d["scenes"][0].update(extras={"shadelab": {"environment": env}}))


def hdr_uri(data):
    return "data:image/vnd.radiance;base64," + base64.b64encode(data).decode()


HDR_HEAD = b"#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n"
case("env-huge-declared.gltf", "an environment map whose HDR header declares 100000 × 100000 texels",
     "100000×100000 texels, outside 1..=8192 per side (MAX_ENV_SIDE)",
     with_environment({"source": "image", "uri": hdr_uri(HDR_HEAD + b"-Y 100000 +X 100000\n")}))
case("env-truncated-hdr.gltf", "an environment map whose HDR data stops after 3 of 8 texels",
     "extras.shadelab.environment: environment map (a data URI): ",
     with_environment({"source": "image", "uri": hdr_uri(HDR_HEAD + b"-Y 2 +X 4\n" + bytes([128, 64, 32, 129]) * 3)}))
case("env-not-a-map.gltf", "an environment map that is a PNG", "is not a radiance map",
     with_environment({"source": "image", "uri": "data:image/png;base64," + base64.b64encode(png_header(2, 1)).decode()}))
case("env-image-without-uri.gltf", "an image environment without its uri", "source \"image\" needs a uri",
     with_environment({"source": "image"}))
case("env-turbidity-out-of-range.gltf", "a sky of turbidity 40",
     "extras.shadelab.environment = ",
     with_environment({"source": "sky", "turbidity": 40}))


def main():
    for f in os.listdir(HERE):
        if f.endswith((".gltf", ".glb")):
            os.remove(os.path.join(HERE, f))
    # The link a case reads through: out of this folder, to a file every checkout has.
    link = os.path.join(HERE, "outside-link.bin")
    if os.path.lexists(link):
        os.remove(link)
    os.symlink("../../Cargo.toml", link)
    rows = []
    for name, what, expected, data in CASES:
        with open(os.path.join(HERE, name), "wb") as f:
            f.write(data)
        assert "|" not in what + expected and "`" not in expected, name
        rows.append(f"| `{name}` | {what} | `{expected}` |")
    readme = os.path.join(HERE, "README.md")
    text = open(readme, encoding="utf-8").read()
    head = text[: text.index("| file | case | expected error contains |")]
    table = "| file | case | expected error contains |\n|---|---|---|\n" + "\n".join(rows) + "\n"
    open(readme, "w", encoding="utf-8").write(head + table)
    print(f"wrote {len(CASES)} cases")


if __name__ == "__main__":
    main()
