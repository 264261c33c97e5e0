#!/usr/bin/env python3
"""Generate assets/showcase.gltf: the demo scene for mirrors and lenses.

Python 3 standard library only. The output is deterministic (same bytes on
every run) so it can be committed and regenerated. Units: metres, +Y up,
glTF's right-handed frame; cameras look down their local -Z.

Usage: scripts/make_showcase.py [--out PATH]   (default: assets/showcase.gltf)
"""

import argparse
import base64
import json
import math
import os
import struct

FLOAT = 5126
UNSIGNED_BYTE = 5121
UNSIGNED_SHORT = 5123
ARRAY_BUFFER = 34962
ELEMENT_ARRAY_BUFFER = 34963


# ---------------------------------------------------------------- geometry
# Each mesh builder returns (positions, normals, indices); all lists of tuples.

def quad_xy():
    """Unit quad [-0.5, 0.5]^2 in the XY plane facing +Z (the mirror)."""
    positions = [(-0.5, -0.5, 0.0), (0.5, -0.5, 0.0), (0.5, 0.5, 0.0), (-0.5, 0.5, 0.0)]
    normals = [(0.0, 0.0, 1.0)] * 4
    return positions, normals, [0, 1, 2, 0, 2, 3]


def disc_xy(segments=32):
    """Disc of diameter 1 in the XY plane facing +Z (the lens)."""
    positions = [(0.0, 0.0, 0.0)]
    for i in range(segments):
        angle = 2.0 * math.pi * i / segments
        positions.append((0.5 * math.cos(angle), 0.5 * math.sin(angle), 0.0))
    normals = [(0.0, 0.0, 1.0)] * len(positions)
    indices = []
    for i in range(segments):
        indices += [0, 1 + i, 1 + (i + 1) % segments]
    return positions, normals, indices


def box(size_x, size_y, size_z):
    """Axis-aligned box centred on the origin, flat normals (24 vertices)."""
    hx, hy, hz = size_x / 2.0, size_y / 2.0, size_z / 2.0
    faces = [  # normal, then four corners counter-clockwise seen from outside
        ((1, 0, 0), [(hx, -hy, hz), (hx, -hy, -hz), (hx, hy, -hz), (hx, hy, hz)]),
        ((-1, 0, 0), [(-hx, -hy, -hz), (-hx, -hy, hz), (-hx, hy, hz), (-hx, hy, -hz)]),
        ((0, 1, 0), [(-hx, hy, hz), (hx, hy, hz), (hx, hy, -hz), (-hx, hy, -hz)]),
        ((0, -1, 0), [(-hx, -hy, -hz), (hx, -hy, -hz), (hx, -hy, hz), (-hx, -hy, hz)]),
        ((0, 0, 1), [(-hx, -hy, hz), (hx, -hy, hz), (hx, hy, hz), (-hx, hy, hz)]),
        ((0, 0, -1), [(hx, -hy, -hz), (-hx, -hy, -hz), (-hx, hy, -hz), (hx, hy, -hz)]),
    ]
    positions, normals, indices = [], [], []
    for normal, corners in faces:
        base = len(positions)
        positions += corners
        normals += [normal] * 4
        indices += [base, base + 1, base + 2, base, base + 2, base + 3]
    return positions, normals, indices


def triangle_normal(a, b, c):
    u = [b[i] - a[i] for i in range(3)]
    v = [c[i] - a[i] for i in range(3)]
    n = (u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0])
    length = math.sqrt(sum(x * x for x in n))
    return tuple(x / length for x in n)


def pyramid(base, height):
    """Square pyramid standing on y = 0, apex at (0, height, 0), flat normals."""
    h = base / 2.0
    corners = [(-h, 0.0, h), (h, 0.0, h), (h, 0.0, -h), (-h, 0.0, -h)]
    apex = (0.0, height, 0.0)
    positions, normals, indices = [], [], []
    for i in range(4):
        a, b = corners[i], corners[(i + 1) % 4]
        n = triangle_normal(a, b, apex)
        base_index = len(positions)
        positions += [a, b, apex]
        normals += [n] * 3
        indices += [base_index, base_index + 1, base_index + 2]
    base_index = len(positions)
    positions += [corners[3], corners[2], corners[1], corners[0]]
    normals += [(0.0, -1.0, 0.0)] * 4
    indices += [base_index, base_index + 1, base_index + 2, base_index, base_index + 2, base_index + 3]
    return positions, normals, indices


def cylinder(radius, height, segments=20):
    """Cylinder standing on y = 0: smooth sides, flat caps."""
    positions, normals, indices = [], [], []
    for i in range(segments + 1):  # side, seam duplicated
        angle = 2.0 * math.pi * i / segments
        x, z = math.cos(angle), -math.sin(angle)
        positions += [(radius * x, 0.0, radius * z), (radius * x, height, radius * z)]
        normals += [(x, 0.0, z), (x, 0.0, z)]
    for i in range(segments):
        b = 2 * i
        indices += [b, b + 2, b + 3, b, b + 3, b + 1]
    for y, ny in ((height, 1.0), (0.0, -1.0)):  # caps
        centre = len(positions)
        positions.append((0.0, y, 0.0))
        normals.append((0.0, ny, 0.0))
        for i in range(segments):
            angle = 2.0 * math.pi * i / segments
            positions.append((radius * math.cos(angle), y, -radius * math.sin(angle)))
            normals.append((0.0, ny, 0.0))
        for i in range(segments):
            a, b = centre + 1 + i, centre + 1 + (i + 1) % segments
            indices += [centre, a, b] if ny > 0 else [centre, b, a]
    return positions, normals, indices


def uv_sphere(radius, rings=8, sectors=12):
    """Low-poly UV sphere centred on the origin, smooth normals."""
    positions, normals, indices = [], [], []
    for r in range(rings + 1):
        theta = math.pi * r / rings
        for s in range(sectors + 1):
            phi = 2.0 * math.pi * s / sectors
            n = (math.sin(theta) * math.cos(phi), math.cos(theta), -math.sin(theta) * math.sin(phi))
            normals.append(n)
            positions.append(tuple(radius * x for x in n))
    for r in range(rings):
        for s in range(sectors):
            a = r * (sectors + 1) + s
            b = a + sectors + 1
            if r != 0:
                indices += [a, b, a + 1]
            if r != rings - 1:
                indices += [a + 1, b, b + 1]
    return positions, normals, indices


def checkered_floor(size_m=10.0, cells=10):
    """Floor in the XZ plane at y = 0, one quad per cell, vertex colours."""
    light, dark = (225, 225, 225, 255), (60, 60, 70, 255)
    cell = size_m / cells
    positions, normals, colors, indices = [], [], [], []
    for row in range(cells):
        for col in range(cells):
            x0, z0 = -size_m / 2 + col * cell, -size_m / 2 + row * cell
            base = len(positions)
            positions += [(x0, 0.0, z0 + cell), (x0 + cell, 0.0, z0 + cell),
                          (x0 + cell, 0.0, z0), (x0, 0.0, z0)]
            normals += [(0.0, 1.0, 0.0)] * 4
            colors += [light if (row + col) % 2 == 0 else dark] * 4
            indices += [base, base + 1, base + 2, base, base + 2, base + 3]
    return positions, normals, colors, indices


# ---------------------------------------------------------------- transforms

def quat_axis_angle(axis, angle_rad):
    """glTF quaternion (x, y, z, w) for a rotation about a unit axis."""
    s = math.sin(angle_rad / 2.0)
    return [axis[0] * s, axis[1] * s, axis[2] * s, math.cos(angle_rad / 2.0)]


def quat_from_columns(x, y, z):
    """glTF quaternion of the rotation matrix with columns x, y, z."""
    m00, m11, m22 = x[0], y[1], z[2]
    trace = m00 + m11 + m22
    if trace > 0:
        s = math.sqrt(trace + 1.0) * 2
        return [(y[2] - z[1]) / s, (z[0] - x[2]) / s, (x[1] - y[0]) / s, 0.25 * s]
    if m00 > m11 and m00 > m22:
        s = math.sqrt(1.0 + m00 - m11 - m22) * 2
        return [0.25 * s, (y[0] + x[1]) / s, (z[0] + x[2]) / s, (y[2] - z[1]) / s]
    if m11 > m22:
        s = math.sqrt(1.0 + m11 - m00 - m22) * 2
        return [(y[0] + x[1]) / s, 0.25 * s, (z[1] + y[2]) / s, (z[0] - x[2]) / s]
    s = math.sqrt(1.0 + m22 - m00 - m11) * 2
    return [(z[0] + x[2]) / s, (z[1] + y[2]) / s, 0.25 * s, (x[1] - y[0]) / s]


def normalize(v):
    length = math.sqrt(sum(c * c for c in v))
    return [c / length for c in v]


def cross(a, b):
    return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]


def look_at_rotation(eye, target, up=(0.0, 1.0, 0.0)):
    """Rotation for a glTF camera at `eye` looking at `target` (camera -Z)."""
    back = normalize([eye[i] - target[i] for i in range(3)])
    right = normalize(cross(up, back))
    true_up = cross(back, right)
    return quat_from_columns(right, true_up, back)


def rounded(values, digits=6):
    return [round(v, digits) + 0.0 for v in values]


# ---------------------------------------------------------------- glTF writer

class GltfBuilder:
    def __init__(self):
        self.binary = bytearray()
        self.doc = {
            "asset": {"version": "2.0", "generator": "scripts/make_showcase.py",
                      "copyright": "CC0-1.0 (public domain), frustum project"},
            "scene": 0,
            "scenes": [{"name": "showcase", "nodes": []}],
            "nodes": [], "meshes": [], "materials": [], "cameras": [],
            "accessors": [], "bufferViews": [], "buffers": [],
        }

    def _view(self, data, target):
        while len(self.binary) % 4:
            self.binary.append(0)
        self.doc["bufferViews"].append({"buffer": 0, "byteOffset": len(self.binary),
                                        "byteLength": len(data), "target": target})
        self.binary += data
        return len(self.doc["bufferViews"]) - 1

    def _accessor(self, data, target, component_type, count, type_name, **extra):
        view = self._view(data, target)
        accessor = {"bufferView": view, "componentType": component_type, "count": count,
                    "type": type_name}
        accessor.update(extra)
        self.doc["accessors"].append(accessor)
        return len(self.doc["accessors"]) - 1

    def vec3s(self, values, with_bounds=False):
        data = b"".join(struct.pack("<3f", *v) for v in values)
        extra = {}
        if with_bounds:  # glTF requires min/max on POSITION
            extra["min"] = [min(struct.unpack("<f", struct.pack("<f", v[i]))[0] for v in values)
                            for i in range(3)]
            extra["max"] = [max(struct.unpack("<f", struct.pack("<f", v[i]))[0] for v in values)
                            for i in range(3)]
        return self._accessor(data, ARRAY_BUFFER, FLOAT, len(values), "VEC3", **extra)

    def colors_u8(self, values):
        data = b"".join(struct.pack("<4B", *c) for c in values)
        return self._accessor(data, ARRAY_BUFFER, UNSIGNED_BYTE, len(values), "VEC4",
                              normalized=True)

    def indices_u16(self, values):
        data = struct.pack("<%dH" % len(values), *values)
        return self._accessor(data, ELEMENT_ARRAY_BUFFER, UNSIGNED_SHORT, len(values), "SCALAR")

    def material(self, name, rgba, double_sided=False, blend=False):
        material = {"name": name,
                    "pbrMetallicRoughness": {"baseColorFactor": rounded(rgba),
                                             "metallicFactor": 0.0, "roughnessFactor": 0.8}}
        if double_sided:
            material["doubleSided"] = True
        if blend:
            material["alphaMode"] = "BLEND"
        self.doc["materials"].append(material)
        return len(self.doc["materials"]) - 1

    def mesh(self, name, geometry, material, colors=None):
        positions, normals, indices = geometry
        attributes = {"POSITION": self.vec3s(positions, with_bounds=True),
                      "NORMAL": self.vec3s(normals)}
        if colors is not None:
            attributes["COLOR_0"] = self.colors_u8(colors)
        primitive = {"attributes": attributes, "indices": self.indices_u16(indices),
                     "material": material, "mode": 4}
        self.doc["meshes"].append({"name": name, "primitives": [primitive]})
        return len(self.doc["meshes"]) - 1

    def node(self, name, root=True, **fields):
        node = {"name": name}
        for key, value in fields.items():
            node[key] = rounded(value) if key in ("translation", "rotation", "scale") else value
        self.doc["nodes"].append(node)
        index = len(self.doc["nodes"]) - 1
        if root:
            self.doc["scenes"][0]["nodes"].append(index)
        return index

    def perspective_camera(self, name, yfov_rad, aspect, eye, target):
        self.doc["cameras"].append({"name": name, "type": "perspective", "perspective": {
            "yfov": round(yfov_rad, 6), "aspectRatio": round(aspect, 6),
            "znear": 0.1, "zfar": 100.0}})
        camera = len(self.doc["cameras"]) - 1
        return self.node(name, camera=camera, translation=list(eye),
                         rotation=look_at_rotation(eye, target))

    def to_json(self):
        while len(self.binary) % 4:
            self.binary.append(0)
        self.doc["buffers"] = [{
            "byteLength": len(self.binary),
            "uri": "data:application/octet-stream;base64," +
                   base64.b64encode(bytes(self.binary)).decode("ascii")}]
        return json.dumps(self.doc, indent=1) + "\n"


# ---------------------------------------------------------------- the scene

MIRROR_CENTER = (0.0, 1.05, -2.0)    # bottom edge 5 cm above the floor
MIRROR_SIZE = (3.0, 2.0, 1.0)        # width, height (m); local quad is 1 x 1
MIRROR_YAW_RAD = math.radians(12.0)  # turned slightly toward +X
MAIN_EYE = (0.8, 1.7, 6.5)           # the "main" camera
LENS_CENTER = (-0.5, 1.3, 3.6)       # between the main camera and the objects


def build():
    g = GltfBuilder()
    up = (0.0, 1.0, 0.0)

    floor_positions, floor_normals, floor_colors, floor_indices = checkered_floor()
    white = g.material("floor_vertex_colors", (1.0, 1.0, 1.0, 1.0))
    g.node("floor", mesh=g.mesh("floor", (floor_positions, floor_normals, floor_indices), white,
                                colors=floor_colors))

    # The mirror: a unit quad facing local +Z, scaled to 3 x 2 m, with a dark
    # backing board as its child (1 cm behind the surface, 4 % larger, clear
    # of the floor).
    mirror_surface = g.material("mirror_surface", (0.82, 0.86, 0.9, 1.0))
    backing_material = g.material("mirror_backing", (0.12, 0.1, 0.08, 1.0))
    backing = g.node("mirror_backing", root=False,
                     mesh=g.mesh("mirror_backing", box(1.0, 1.0, 1.0), backing_material),
                     translation=[0.0, 0.0, -0.03], scale=[1.04, 1.04, 0.04])
    g.node("mirror", mesh=g.mesh("mirror", quad_xy(), mirror_surface),
           translation=list(MIRROR_CENTER), rotation=quat_axis_angle(up, MIRROR_YAW_RAD),
           scale=list(MIRROR_SIZE), children=[backing])

    # Behind the mirror: must never show up in the reflection.
    red = g.material("marker_red", (1.0, 0.0, 0.0, 1.0))
    g.node("marker_behind_mirror", mesh=g.mesh("marker_box", box(0.6, 0.6, 0.6), red),
           translation=[0.0, 0.8, -3.2])

    # Coloured objects in front of the mirror.
    blue = g.material("blue", (0.15, 0.3, 0.9, 1.0))
    green = g.material("green", (0.15, 0.75, 0.25, 1.0))
    yellow = g.material("yellow", (0.95, 0.8, 0.1, 1.0))
    purple = g.material("purple", (0.6, 0.2, 0.75, 1.0))
    orange = g.material("orange", (1.0, 0.5, 0.1, 1.0))
    g.node("box_blue", mesh=g.mesh("box_blue", box(0.8, 0.8, 0.8), blue),
           translation=[-0.9, 0.4, 0.4], rotation=quat_axis_angle(up, math.radians(20.0)))
    g.node("box_green", mesh=g.mesh("box_green", box(0.6, 0.6, 0.6), green),
           translation=[1.9, 0.3, 0.6], rotation=quat_axis_angle(up, math.radians(-30.0)))
    g.node("pyramid_yellow", mesh=g.mesh("pyramid_yellow", pyramid(0.9, 1.1), yellow),
           translation=[-0.7, 0.0, 2.2])
    g.node("cylinder_purple", mesh=g.mesh("cylinder_purple", cylinder(0.3, 1.4), purple),
           translation=[1.2, 0.0, 2.4])
    g.node("sphere_orange", mesh=g.mesh("sphere_orange", uv_sphere(0.35), orange),
           translation=[0.2, 0.35, 0.8])

    # The lens: a disc of diameter 1 scaled to 0.8 m (radius 0.4 m), between
    # the main camera and the objects, facing the camera.
    # (The rotation that points a camera's -Z from MAIN_EYE at the lens points
    # the lens's +Z back at MAIN_EYE.)
    glass = g.material("lens_glass", (0.7, 0.9, 1.0, 0.35), double_sided=True, blend=True)
    g.node("lens", mesh=g.mesh("lens_disc", disc_xy(), glass), translation=list(LENS_CENTER),
           rotation=look_at_rotation(MAIN_EYE, LENS_CENTER), scale=[0.8, 0.8, 0.8])

    g.perspective_camera("main", math.radians(50.0), 16.0 / 9.0,
                         eye=MAIN_EYE, target=MIRROR_CENTER)
    g.perspective_camera("overview", math.radians(70.0), 16.0 / 9.0,
                         eye=(6.0, 6.5, 8.0), target=(0.0, 0.5, -0.5))
    return g.to_json()


def main():
    repo = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--out", default=os.path.join(repo, "assets", "showcase.gltf"))
    args = parser.parse_args()
    text = build()
    os.makedirs(os.path.dirname(os.path.abspath(args.out)), exist_ok=True)
    with open(args.out, "w", encoding="utf-8", newline="\n") as out:
        out.write(text)
    print("wrote %s (%d bytes)" % (args.out, len(text.encode("utf-8"))))


if __name__ == "__main__":
    main()
