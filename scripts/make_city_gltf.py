#!/usr/bin/env python3
"""A large scene for the poster benchmark (scripts/poster-bench.sh, issue
36): a city of BLOCKS x BLOCKS blocks seen from above at an angle, written
at bench time into the build folder, never committed.

    scripts/make_city_gltf.py OUT.glb [--blocks N]

Each block is one mesh (one primitive, vertex colours, 32-bit indices) of
3 x 3 buildings on a pavement slab; each building's four facades are a
grid of floors x bays quads alternating wall and window colours, so the
triangle count follows the heights (the default 14 x 14 blocks: 399 318
triangles, a 37 MB .glb) and every tile of a poster draws many small triangles
with MSAA edges. Heights, footprints and colours come from a fixed
pseudo-random sequence: the file is the same on every run. A ground slab
under the city and a perspective camera named "aerial" at 160 m looking
down 35 degrees over the whole grid; no mirror or lens (frustum-demo
derives them, docs/any-scene.md). Prints the triangle count on stdout.
Python 3, standard library only (scripts/gltf_writer.py).
"""
import argparse
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from gltf_models import look  # noqa: E402
from gltf_writer import ARRAY_BUFFER, UINT, Gltf  # noqa: E402

GENERATOR = "scripts/make_city_gltf.py"
BLOCK_M = 60.0      # block pitch: 48 m of buildings and a 12 m street
PAVEMENT_M = 48.0
FLOOR_M = 3.2
BAY_M = 3.0


class Lcg:
    """A fixed 32-bit linear congruential sequence (same file on every run)."""

    def __init__(self, seed):
        self.state = seed & 0xFFFFFFFF

    def unit(self):
        self.state = (1664525 * self.state + 1013904223) & 0xFFFFFFFF
        return self.state / 2.0**32

    def between(self, lo, hi):
        return lo + (hi - lo) * self.unit()


class MeshData:
    def __init__(self):
        self.pos, self.nrm, self.col, self.idx = [], [], [], []

    def quad(self, corners, normal, color):
        """corners counter-clockwise seen from the side `normal` points to."""
        base = len(self.pos) // 3
        for c in corners:
            self.pos += c
            self.nrm += normal
            self.col += color
        self.idx += [base, base + 1, base + 2, base, base + 2, base + 3]

    def triangles(self):
        return len(self.idx) // 3


def building(mesh, x0, z0, w, d, h, wall, window):
    """A box [x0, x0 + w] x [0, h] x [z0, z0 + d]: facades as floors x bays
    quads, windows on every other bay above the ground floor, a flat roof."""
    floors = max(1, int(round(h / FLOOR_M)))
    x1, z1 = x0 + w, z0 + d
    # (origin, along, normal, length) of each facade, counter-clockwise from outside.
    facades = [((x0, z1), (1, 0), (0, 0, 1), w), ((x1, z1), (0, -1), (1, 0, 0), d),
               ((x1, z0), (-1, 0), (0, 0, -1), w), ((x0, z0), (0, 1), (-1, 0, 0), d)]
    for (ox, oz), (ax, az), normal, length in facades:
        bays = max(1, int(round(length / BAY_M)))
        for f in range(floors):
            y0, y1 = h * f / floors, h * (f + 1) / floors
            for b in range(bays):
                s0, s1 = length * b / bays, length * (b + 1) / bays
                p0 = (ox + ax * s0, oz + az * s0)
                p1 = (ox + ax * s1, oz + az * s1)
                color = window if (f > 0 and b % 2 == 1) else wall
                mesh.quad([[p0[0], y0, p0[1]], [p1[0], y0, p1[1]], [p1[0], y1, p1[1]], [p0[0], y1, p0[1]]],
                          list(normal), color)
    mesh.quad([[x0, h, z1], [x1, h, z1], [x1, h, z0], [x0, h, z0]], [0, 1, 0], [c * 0.8 for c in wall[:3]] + [1])


def block(rng, cx, cz):
    """3 x 3 buildings on a pavement slab centred at (cx, cz)."""
    mesh = MeshData()
    half = PAVEMENT_M / 2
    mesh.quad([[cx - half, 0.05, cz + half], [cx + half, 0.05, cz + half], [cx + half, 0.05, cz - half],
               [cx - half, 0.05, cz - half]], [0, 1, 0], [0.55, 0.55, 0.52, 1])
    # Taller towards the centre of the city, with a random spread.
    centre = math.hypot(cx, cz)
    cell = PAVEMENT_M / 3
    palette = [(0.72, 0.45, 0.35), (0.78, 0.75, 0.68), (0.55, 0.6, 0.65), (0.82, 0.7, 0.5), (0.5, 0.52, 0.48)]
    for i in range(3):
        for j in range(3):
            w = rng.between(0.6, 0.9) * cell
            d = rng.between(0.6, 0.9) * cell
            h = rng.between(6.0, 24.0) + 60.0 * math.exp(-centre / 200.0) * rng.unit()
            x0 = cx - half + i * cell + (cell - w) / 2
            z0 = cz - half + j * cell + (cell - d) / 2
            wall = list(palette[int(rng.unit() * len(palette)) % len(palette)]) + [1]
            window = [0.15, 0.22, 0.3 + 0.2 * rng.unit(), 1]
            building(mesh, x0, z0, w, d, h, wall, window)
    return mesh


def city(blocks):
    g = Gltf(camera=False, generator=GENERATOR)
    white = g.material((1, 1, 1, 1), name="city")
    rng = Lcg(36)
    extent = blocks * BLOCK_M
    ground = MeshData()
    ground.quad([[-extent / 2 - 20, 0, extent / 2 + 20], [extent / 2 + 20, 0, extent / 2 + 20],
                 [extent / 2 + 20, 0, -extent / 2 - 20], [-extent / 2 - 20, 0, -extent / 2 - 20]],
                [0, 1, 0], [0.32, 0.33, 0.35, 1])
    meshes = [("ground", ground)]
    for i in range(blocks):
        for j in range(blocks):
            cx = (i - (blocks - 1) / 2) * BLOCK_M
            cz = (j - (blocks - 1) / 2) * BLOCK_M
            meshes.append(("block_%d_%d" % (i, j), block(rng, cx, cz)))
    triangles = 0
    for name, m in meshes:
        attributes = {"POSITION": g.accessor(m.pos, "VEC3", target=ARRAY_BUFFER),
                      "NORMAL": g.accessor(m.nrm, "VEC3", target=ARRAY_BUFFER),
                      "COLOR_0": g.accessor(m.col, "VEC4", target=ARRAY_BUFFER)}
        prim = {"attributes": attributes, "indices": g.indices(m.idx, component=UINT), "material": white}
        g.node({"name": name, "mesh": g.mesh([prim], name=name)})
        triangles += m.triangles()
    # Over one corner of the city, looking across it to the far corner.
    distance = 0.75 * extent
    g.j["cameras"] = [{"type": "perspective", "name": "aerial",
                       "perspective": {"yfov": 0.9, "aspectRatio": 1.0, "znear": 1.0, "zfar": 4.0 * extent}}]
    g.node({"name": "eye", "camera": 0,
            "translation": [-distance * math.sin(math.radians(45)), 160.0, distance * math.cos(math.radians(45))],
            "rotation": look(math.radians(-45), math.radians(-35))})
    return g, triangles


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("out", help="the .glb to write")
    parser.add_argument("--blocks", type=int, default=14, help="blocks per side (default 14)")
    args = parser.parse_args()
    if args.blocks < 1 or args.blocks > 64:
        parser.error("--blocks must be 1 to 64, got %d" % args.blocks)
    g, triangles = city(args.blocks)
    tmp = args.out + ".tmp"
    with open(tmp, "wb") as f:
        f.write(g.binary())
    os.replace(tmp, args.out)
    print(triangles)


if __name__ == "__main__":
    main()
