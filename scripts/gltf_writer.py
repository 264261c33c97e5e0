"""A small glTF 2.0 writer for the project's generated test models
(scripts/make_feature_gltf.py): accessors, materials, meshes, nodes,
textures, PNG images and GLB packing. Python 3, standard library only;
the output is deterministic (sorted keys, fixed float formatting by json).
"""
import base64
import json
import struct
import zlib

BYTE, UBYTE, SHORT, USHORT, UINT, FLOAT = 5120, 5121, 5122, 5123, 5125, 5126
ARRAY_BUFFER, ELEMENT_ARRAY_BUFFER = 34962, 34963
POINTS, LINES, LINE_LOOP, LINE_STRIP, TRIANGLES, TRIANGLE_STRIP, TRIANGLE_FAN = range(7)

_FORMAT = {BYTE: "b", UBYTE: "B", SHORT: "h", USHORT: "H", UINT: "I", FLOAT: "f"}
_SIZE = {"SCALAR": 1, "VEC2": 2, "VEC3": 3, "VEC4": 4, "MAT4": 16}


def _with_given(fields, **optional):
    """`fields` with each optional field that is not None added, in order."""
    fields.update((key, value) for key, value in optional.items() if value is not None)
    return fields


def _bound(acc, values, size):
    """Adds the per-component min and max of `values` (`size` components an element)."""
    acc["min"] = [min(values[i::size]) for i in range(size)]
    acc["max"] = [max(values[i::size]) for i in range(size)]


def png_rgba(width, height, pixels):
    """pixels: rows top to bottom of (r, g, b, a) bytes."""
    raw = b"".join(b"\x00" + bytes(c for p in row for c in p) for row in pixels)

    def chunk(kind, data):
        return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data) & 0xFFFFFFFF)

    header = struct.pack(">IIBBBBB", width, height, 8, 6, 0, 0, 0)
    return (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", header) + chunk(b"IDAT", zlib.compress(raw, 9)) +
            chunk(b"IEND", b""))


def glb(json_text, binary):
    """A .glb: 12-byte header, JSON chunk (space-padded), BIN chunk (zero-padded)."""
    js = json_text.encode("utf-8")
    js += b" " * (-len(js) % 4)
    binary = bytes(binary) + b"\x00" * (-len(binary) % 4)
    total = 12 + 8 + len(js) + (8 + len(binary) if binary else 0)
    out = struct.pack("<4sII", b"glTF", 2, total) + struct.pack("<II", len(js), 0x4E4F534A) + js
    if binary:
        out += struct.pack("<II", len(binary), 0x004E4942) + binary
    return out


class Gltf:
    def __init__(self, camera=True, generator="scripts/make_feature_gltf.py"):
        self.data = bytearray()
        self.j = {"asset": {"version": "2.0", "generator": generator},
                  "scene": 0, "scenes": [{"nodes": []}], "nodes": [], "meshes": [], "materials": [],
                  "accessors": [], "bufferViews": [], "buffers": []}
        if camera:  # the feature files' square orthographic camera at (0, 0, 5)
            self.node({"name": "main", "camera": 0, "translation": [0, 0, 5]})
            self.j["cameras"] = [{"name": "main", "type": "orthographic",
                                  "orthographic": {"xmag": 1.0, "ymag": 1.0, "znear": 0.1, "zfar": 10.0}}]

    def _align(self):
        while len(self.data) % 4:
            self.data.append(0)

    def view(self, payload, stride=None, target=None):
        """A bufferView over `payload` (bytes), 4-byte aligned in buffer 0."""
        self._align()
        offset = len(self.data)
        self.data += payload
        self.j["bufferViews"].append(_with_given({"buffer": 0, "byteOffset": offset, "byteLength": len(payload)},
                                                 byteStride=stride, target=target))
        return len(self.j["bufferViews"]) - 1

    def accessor(self, values, kind, component=FLOAT, normalized=False, target=None, bounds=None, stride=None):
        """A tightly packed accessor with its own bufferView (or, with
        `stride`, each element zero-padded to that many bytes, as vertex
        attributes of 1- and 2-byte components must be). VEC3 float
        accessors get min/max (POSITION needs them); `bounds` forces them
        on (True) or off (False)."""
        size = _SIZE[kind]
        if stride is None:
            payload = struct.pack("<%d%s" % (len(values), _FORMAT[component]), *values)
        else:
            element = struct.Struct("<%d%s" % (size, _FORMAT[component]))
            payload = b"".join(element.pack(*values[i:i + size]) + b"\x00" * (stride - element.size)
                               for i in range(0, len(values), size))
        acc = {"bufferView": self.view(payload, stride=stride, target=target), "componentType": component,
               "count": len(values) // size, "type": kind}
        if normalized:
            acc["normalized"] = True
        if bounds is None:
            bounds = kind == "VEC3" and component == FLOAT
        if bounds:
            _bound(acc, values, size)
        self.j["accessors"].append(acc)
        return len(self.j["accessors"]) - 1

    def indices(self, values, component=USHORT):
        return self.accessor(values, "SCALAR", component, target=ELEMENT_ARRAY_BUFFER)

    def interleaved(self, columns):
        """columns: [(kind, values)] of float attributes with the same count,
        written vertex by vertex into one bufferView with a byteStride.
        Returns one accessor per column, in order."""
        sizes = [_SIZE[kind] for kind, _ in columns]
        count = len(columns[0][1]) // sizes[0]
        stride = 4 * sum(sizes)
        payload = bytearray()
        for i in range(count):
            for (kind, values), size in zip(columns, sizes):
                payload += struct.pack("<%df" % size, *values[i * size:(i + 1) * size])
        view = self.view(bytes(payload), stride=stride, target=ARRAY_BUFFER)
        out, offset = [], 0
        for (kind, values), size in zip(columns, sizes):
            acc = {"bufferView": view, "byteOffset": offset, "componentType": FLOAT, "count": count, "type": kind}
            if kind == "VEC3":
                _bound(acc, values, 3)
            self.j["accessors"].append(acc)
            out.append(len(self.j["accessors"]) - 1)
            offset += 4 * size
        return out

    def material(self, color, **extra):
        m = {"pbrMetallicRoughness": {"baseColorFactor": list(color), "metallicFactor": 0.0}}
        m.update(extra)
        self.j["materials"].append(m)
        return len(self.j["materials"]) - 1

    def mesh(self, primitives, weights=None, name=None):
        self.j["meshes"].append(_with_given({"primitives": primitives}, weights=weights, name=name))
        return len(self.j["meshes"]) - 1

    def node(self, fields, root=True):
        """A node; a root node is listed in scene 0."""
        self.j["nodes"].append(fields)
        if root:
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

    def texture(self, png, in_buffer=False):
        """A texture of `png`: as a data uri, or (in_buffer) in a bufferView
        of buffer 0 with its mimeType, as .glb files carry images."""
        if in_buffer:
            image = {"bufferView": self.view(png), "mimeType": "image/png"}
        else:
            image = {"uri": "data:image/png;base64," + base64.b64encode(png).decode("ascii")}
        self.j.setdefault("images", []).append(image)
        self.j.setdefault("textures", []).append({"source": len(self.j["images"]) - 1})
        return len(self.j["textures"]) - 1

    def _pruned(self):
        for key in [k for k, v in self.j.items() if v == []]:
            del self.j[key]

    def text(self):
        """The .gltf text, buffer 0 as a base64 data uri."""
        self.j["buffers"] = [{"byteLength": len(self.data),
                              "uri": "data:application/octet-stream;base64," +
                                     base64.b64encode(bytes(self.data)).decode("ascii")}]
        self._pruned()
        return json.dumps(self.j, indent=1, sort_keys=True) + "\n"

    def binary(self):
        """The .glb bytes, buffer 0 in the BIN chunk."""
        self._align()
        self.j["buffers"] = [{"byteLength": len(self.data)}]
        self._pruned()
        return glb(json.dumps(self.j, separators=(",", ":"), sort_keys=True), self.data)
