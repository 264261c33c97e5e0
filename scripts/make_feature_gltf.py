#!/usr/bin/env python3
"""Generate tests/data/gltf-features/*.gltf: one small glTF 2.0 file per
loader feature (KHR_materials_unlit, texCoord sets, KHR_texture_transform,
EXT_mesh_gpu_instancing, morph-target weights, alphaMode, orthographic
aspect, a required extension that is not supported).

Python 3, standard library only; deterministic. Every file has an
orthographic camera "main" at (0, 0, 5) looking down -Z with xmag = ymag = 1,
so world x, y in [-1, 1] fill a square image (tests/data/gltf-features/README.md).

    python3 scripts/make_feature_gltf.py [OUT_DIR]   # default tests/data/gltf-features
"""
import base64
import json
import math
import os
import struct
import sys
import zlib

FLOAT, UBYTE = 5126, 5121


def png_rgba(width, height, pixels):
    """pixels: rows top to bottom of (r, g, b, a) bytes."""
    raw = b"".join(b"\x00" + bytes(c for p in row for c in p) for row in pixels)

    def chunk(kind, data):
        return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data) & 0xFFFFFFFF)

    header = struct.pack(">IIBBBBB", width, height, 8, 6, 0, 0, 0)
    return (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", header) + chunk(b"IDAT", zlib.compress(raw, 9)) +
            chunk(b"IEND", b""))


class Gltf:
    def __init__(self):
        self.data = bytearray()
        self.j = {"asset": {"version": "2.0", "generator": "scripts/make_feature_gltf.py"},
                  "scene": 0, "scenes": [{"nodes": []}], "nodes": [], "meshes": [], "materials": [],
                  "accessors": [], "bufferViews": [], "buffers": []}
        self.node({"name": "main", "camera": 0, "translation": [0, 0, 5]})
        self.j["cameras"] = [{"name": "main", "type": "orthographic",
                              "orthographic": {"xmag": 1.0, "ymag": 1.0, "znear": 0.1, "zfar": 10.0}}]

    def accessor(self, values, kind, component=FLOAT, normalized=False):
        size = {"SCALAR": 1, "VEC2": 2, "VEC3": 3, "VEC4": 4}[kind]
        fmt = "<%d%s" % (len(values), "f" if component == FLOAT else "B")
        while len(self.data) % 4:
            self.data.append(0)
        offset = len(self.data)
        self.data += struct.pack(fmt, *values)
        self.j["bufferViews"].append({"buffer": 0, "byteOffset": offset, "byteLength": len(self.data) - offset})
        acc = {"bufferView": len(self.j["bufferViews"]) - 1, "componentType": component,
               "count": len(values) // size, "type": kind}
        if normalized:
            acc["normalized"] = True
        if kind == "VEC3" and component == FLOAT:
            acc["min"] = [min(values[i::3]) for i in range(3)]
            acc["max"] = [max(values[i::3]) for i in range(3)]
        self.j["accessors"].append(acc)
        return len(self.j["accessors"]) - 1

    def material(self, color, **extra):
        m = {"pbrMetallicRoughness": {"baseColorFactor": list(color), "metallicFactor": 0.0}}
        m.update(extra)
        self.j["materials"].append(m)
        return len(self.j["materials"]) - 1

    def mesh(self, primitives, weights=None):
        m = {"primitives": primitives}
        if weights is not None:
            m["weights"] = weights
        self.j["meshes"].append(m)
        return len(self.j["meshes"]) - 1

    def node(self, fields):
        self.j["nodes"].append(fields)
        self.j["scenes"][0]["nodes"].append(len(self.j["nodes"]) - 1)
        return len(self.j["nodes"]) - 1

    def quad(self, x0, y0, x1, y1, z, material, colors=None, uv0=None, uv1=None, targets=None):
        """Axis-aligned quad facing +Z, two triangles, uv (0, 0) at the top left."""
        pos = [x0, y0, z, x1, y0, z, x1, y1, z, x0, y0, z, x1, y1, z, x0, y1, z]
        uv = [0, 1, 1, 1, 1, 0, 0, 1, 1, 0, 0, 0]
        attributes = {"POSITION": self.accessor(pos, "VEC3"), "NORMAL": self.accessor([0, 0, 1] * 6, "VEC3")}
        if uv0 is not None:
            attributes["TEXCOORD_0"] = self.accessor(uv0 if uv0 != "quad" else uv, "VEC2")
        if uv1 is not None:
            attributes["TEXCOORD_1"] = self.accessor(uv1 if uv1 != "quad" else uv, "VEC2")
        if colors is not None:  # per corner: bottom-left, bottom-right, top-right, top-left
            bl, br, tr, tl = colors
            attributes["COLOR_0"] = self.accessor(bl + br + tr + bl + tr + tl, "VEC4")
        p = {"attributes": attributes, "material": material}
        if targets is not None:
            p["targets"] = [{"POSITION": self.accessor(delta * 6, "VEC3")} for delta in targets]
        return p

    def texture(self, png):
        self.j.setdefault("images", []).append(
            {"uri": "data:image/png;base64," + base64.b64encode(png).decode("ascii")})
        self.j.setdefault("textures", []).append({"source": len(self.j["images"]) - 1})
        return len(self.j["textures"]) - 1

    def text(self):
        self.j["buffers"] = [{"byteLength": len(self.data),
                              "uri": "data:application/octet-stream;base64," +
                                     base64.b64encode(bytes(self.data)).decode("ascii")}]
        for key in [k for k, v in self.j.items() if v == []]:
            del self.j[key]
        return json.dumps(self.j, indent=1, sort_keys=True) + "\n"


UNLIT = {"extensions": {"KHR_materials_unlit": {}}}


def unlit_file():
    # Left: lit; right: the same colour unlit (lighting must not change it).
    g = Gltf()
    lit = g.material((0.8, 0.2, 0.2, 1.0))
    flat = g.material((0.8, 0.2, 0.2, 1.0), **UNLIT)
    g.node({"name": "lit", "mesh": g.mesh([g.quad(-0.9, -0.8, -0.1, 0.8, 0, lit)])})
    g.node({"name": "unlit", "mesh": g.mesh([g.quad(0.1, -0.8, 0.9, 0.8, 0, flat)])})
    g.j["extensionsUsed"] = g.j["extensionsRequired"] = ["KHR_materials_unlit"]
    return g


def red_green(g):
    # 2 x 1 texels: red on the left (u < 0.5), green on the right.
    return g.texture(png_rgba(2, 1, [[(255, 0, 0, 255), (0, 255, 0, 255)]]))


def texcoord1_file():
    # TEXCOORD_0 is constant (0.9, 0.5): read through it the quad would be
    # all green. The material reads TEXCOORD_1: red left, green right.
    g = Gltf()
    m = g.material((1, 1, 1, 1), **UNLIT)
    g.j["materials"][m]["pbrMetallicRoughness"]["baseColorTexture"] = {"index": red_green(g), "texCoord": 1}
    g.node({"name": "quad", "mesh": g.mesh([g.quad(-0.8, -0.8, 0.8, 0.8, 0, m, uv0=[0.9, 0.5] * 6, uv1="quad")])})
    g.j["extensionsUsed"] = ["KHR_materials_unlit"]
    return g


def texture_transform_file():
    # As texcoord1, but KHR_texture_transform moves the texture by half its
    # width (offset 0.5, repeat): green left, red right; its texCoord (1)
    # overrides the textureInfo's (0). A second quad, out of view, carries
    # rotation and scale for the loader test.
    g = Gltf()
    texture = red_green(g)
    moved = g.material((1, 1, 1, 1), **UNLIT)
    g.j["materials"][moved]["pbrMetallicRoughness"]["baseColorTexture"] = {
        "index": texture, "texCoord": 0,
        "extensions": {"KHR_texture_transform": {"offset": [0.5, 0.0], "texCoord": 1}}}
    turned = g.material((1, 1, 1, 1), **UNLIT)
    g.j["materials"][turned]["pbrMetallicRoughness"]["baseColorTexture"] = {
        "index": texture,
        "extensions": {"KHR_texture_transform": {"offset": [0.25, 0.5], "rotation": math.pi / 2, "scale": [2.0, 3.0]}}}
    g.node({"name": "quad", "mesh": g.mesh([g.quad(-0.8, -0.8, 0.8, 0.8, 0, moved, uv0=[0.9, 0.5] * 6, uv1="quad")])})
    g.node({"name": "turned", "translation": [5, 0, 0], "mesh": g.mesh([g.quad(-0.5, -0.5, 0.5, 0.5, 0, turned, uv0="quad")])})
    g.j["extensionsUsed"] = ["KHR_materials_unlit", "KHR_texture_transform"]
    g.j["extensionsRequired"] = ["KHR_texture_transform"]
    return g


def instancing_file():
    # One 0.3 m quad drawn three times along x; the middle one twice as tall.
    g = Gltf()
    m = g.material((0.1, 0.3, 0.9, 1), **UNLIT)
    mesh = g.mesh([g.quad(-0.15, -0.15, 0.15, 0.15, 0, m)])
    g.node({"name": "row", "mesh": mesh, "extensions": {"EXT_mesh_gpu_instancing": {"attributes": {
        "TRANSLATION": g.accessor([-0.6, 0, 0, 0, 0, 0, 0.6, 0, 0], "VEC3"),
        "ROTATION": g.accessor([0, 0, 0, 1] * 3, "VEC4"),
        "SCALE": g.accessor([1, 1, 1, 1, 2, 1, 1, 1, 1], "VEC3")}}}})
    g.j["extensionsUsed"] = ["EXT_mesh_gpu_instancing", "KHR_materials_unlit"]
    return g


def morph_file():
    # A 0.4 m quad at the origin with one target moving it +0.5 m along x.
    # mesh.weights [1]: node "moved" (y = +0.5) shows it at x = 0.5; node
    # "kept" (y = -0.5) has node.weights [0]: at x = 0.
    g = Gltf()
    m = g.material((0.9, 0.6, 0.1, 1), **UNLIT)
    mesh = g.mesh([g.quad(-0.2, -0.2, 0.2, 0.2, 0, m, targets=[[0.5, 0, 0]])], weights=[1.0])
    g.node({"name": "moved", "mesh": mesh, "translation": [0, 0.5, 0]})
    g.node({"name": "kept", "mesh": mesh, "translation": [0, -0.5, 0], "weights": [0.0]})
    g.j["extensionsUsed"] = ["KHR_materials_unlit"]
    return g


def alpha_file():
    # Top: a BLEND quad (white, alpha 0.5, listed FIRST and nearest) over
    # x in [-0.9, 0]; behind it an opaque dark red quad over x in [-0.5, 0.9]:
    # x < -0.5 shows the sky through the glass, -0.5 < x < 0 the red.
    # Bottom: a MASK quad (green) whose COLOR_0 alpha goes 0 -> 1 from left
    # to right, cutoff 0.5 (the default): its left half is cut away.
    g = Gltf()
    glass = g.material((1, 1, 1, 0.5), alphaMode="BLEND", **UNLIT)
    red = g.material((0.5, 0, 0, 1), **UNLIT)
    leaf = g.material((0, 0.5, 0, 1), alphaMode="MASK", **UNLIT)
    g.node({"name": "glass", "mesh": g.mesh([g.quad(-0.9, 0.1, 0.0, 0.9, 0.5, glass)])})
    g.node({"name": "red", "mesh": g.mesh([g.quad(-0.5, 0.1, 0.9, 0.9, 0.0, red)])})
    clear, solid = [1, 1, 1, 0], [1, 1, 1, 1]
    g.node({"name": "leaf", "mesh": g.mesh([g.quad(-0.9, -0.9, 0.9, -0.1, 0.0, leaf,
                                                   colors=[clear, solid, solid, clear])])})
    g.j["extensionsUsed"] = ["KHR_materials_unlit"]
    return g


def orthographic_file():
    # A 1 m square in front of the square orthographic camera.
    g = Gltf()
    m = g.material((0.9, 0.9, 0.9, 1), **UNLIT)
    g.node({"name": "square", "mesh": g.mesh([g.quad(-0.5, -0.5, 0.5, 0.5, 0, m)])})
    g.j["extensionsUsed"] = ["KHR_materials_unlit"]
    return g


def draco_file():
    # Valid, but requires an extension the loader does not implement.
    g = orthographic_file()
    g.j["extensionsUsed"] = ["KHR_draco_mesh_compression", "KHR_materials_unlit"]
    g.j["extensionsRequired"] = ["KHR_draco_mesh_compression"]
    return g


FILES = {
    "unlit.gltf": unlit_file,
    "texcoord1.gltf": texcoord1_file,
    "texture_transform.gltf": texture_transform_file,
    "instancing.gltf": instancing_file,
    "morph.gltf": morph_file,
    "alpha.gltf": alpha_file,
    "orthographic.gltf": orthographic_file,
    "draco_required.gltf": draco_file,
}


def main():
    here = os.path.dirname(os.path.abspath(__file__))
    out = sys.argv[1] if len(sys.argv) > 1 else os.path.join(here, "..", "tests", "data", "gltf-features")
    os.makedirs(out, exist_ok=True)
    for name, make in FILES.items():
        with open(os.path.join(out, name), "w", newline="\n") as f:
            f.write(make().text())


if __name__ == "__main__":
    main()
