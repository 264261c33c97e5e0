"""The project's own stand-ins for the models a glTF loader is usually tested
on (tests/data/gltf-models/, written by scripts/make_feature_gltf.py): one
small 3D model per loader feature, without a file camera unless the feature
is the camera, so that every effect frames it as a user's model. Every
loader feature the Khronos samples exercised is here: node matrices and TRS,
rotations as quaternions and as matrices, UNSIGNED_BYTE / SHORT / INT
indices, the seven primitive modes, non-indexed draws, several scenes with a
non-zero default, perspective and orthographic cameras, a skin with inverse
bind matrices and an animation, morph targets on POSITION and NORMAL with
weights, a sparse accessor, vertex colours, an interleaved bufferView, a
PNG texture whose orientation a wrong flip shows, a mesh of a few thousand
triangles and a .glb. What each holds is in tests/data/gltf-models/README.md.
"""
import math
import struct

from gltf_writer import (ARRAY_BUFFER, BYTE, ELEMENT_ARRAY_BUFFER, FLOAT, SHORT, UBYTE, UINT, USHORT, LINE_LOOP, LINE_STRIP, LINES, POINTS, TRIANGLE_FAN,
                         TRIANGLE_STRIP, TRIANGLES, Gltf, png_rgba)

GENERATOR = "scripts/make_feature_gltf.py (gltf_models)"

# The orientation texture: 4 x 4 texels, four 2 x 2 quadrants. glTF's uv
# (0, 0) is the image's top left: red there, green top right, blue bottom
# left, white bottom right. A loader or sampler that flips v shows blue on
# top; one that flips u shows green on the left.
RED, GREEN, BLUE, WHITE = (255, 0, 0, 255), (0, 255, 0, 255), (0, 0, 255, 255), (255, 255, 255, 255)
QUADRANTS_PNG = png_rgba(4, 4, [[RED, RED, GREEN, GREEN]] * 2 + [[BLUE, BLUE, WHITE, WHITE]] * 2)


def box_arrays(half=0.5):
    """A cube of side 2 * half: 24 vertices (4 per face, each face its own
    normal and uv square), 36 indices, counter-clockwise seen from outside.
    On every face uv (0, 0) is the corner at the face's top left as seen
    from outside with +Y up (the top and bottom faces: -Z up)."""
    faces = [  # (normal, right, up)
        ((0, 0, 1), (1, 0, 0), (0, 1, 0)), ((0, 0, -1), (-1, 0, 0), (0, 1, 0)),
        ((1, 0, 0), (0, 0, -1), (0, 1, 0)), ((-1, 0, 0), (0, 0, 1), (0, 1, 0)),
        ((0, 1, 0), (1, 0, 0), (0, 0, -1)), ((0, -1, 0), (1, 0, 0), (0, 0, 1))]
    pos, nrm, uv, idx = [], [], [], []
    for n, r, u in faces:
        base = len(pos) // 3
        for su, sv in ((-1, -1), (1, -1), (1, 1), (-1, 1)):  # bottom-left, bottom-right, top-right, top-left
            pos += [half * (n[i] + su * r[i] + sv * u[i]) for i in range(3)]
            nrm += list(n)
            uv += [(su + 1) / 2, (1 - sv) / 2]
        idx += [base, base + 1, base + 2, base, base + 2, base + 3]
    return pos, nrm, uv, idx


def box_primitive(g, material, half=0.5, index_type=USHORT, colors=None, texcoords=True):
    pos, nrm, uv, idx = box_arrays(half)
    attributes = {"POSITION": g.accessor(pos, "VEC3"), "NORMAL": g.accessor(nrm, "VEC3")}
    if texcoords:
        attributes["TEXCOORD_0"] = g.accessor(uv, "VEC2")
    if colors is not None:
        attributes["COLOR_0"] = g.accessor(colors, "VEC4")
    return {"attributes": attributes, "indices": g.indices(idx, index_type), "material": material}


def triangle():
    # One triangle, UNSIGNED_SHORT indices, no normals (flat-shaded).
    g = Gltf(camera=False, generator=GENERATOR)
    m = g.material((0.8, 0.3, 0.2, 1.0))
    indices = g.indices([0, 1, 2])  # accessor 0, POSITION accessor 1
    prim = {"attributes": {"POSITION": g.accessor([0, 0, 0, 1, 0, 0, 0, 1, 0], "VEC3")},
            "indices": indices, "material": m}
    g.node({"mesh": g.mesh([prim])})  # unnamed, as converters often leave them
    return g


def triangle_without_indices():
    # The same triangle drawn without an index accessor: indices 0..n-1.
    g = Gltf(camera=False, generator=GENERATOR)
    m = g.material((0.2, 0.6, 0.3, 1.0))
    prim = {"attributes": {"POSITION": g.accessor([0, 0, 0, 1, 0, 0, 0, 1, 0], "VEC3")}, "material": m}
    g.node({"name": "triangle", "mesh": g.mesh([prim], name="triangle")})
    return g


def box():
    # A unit cube (24 vertices with normals, 36 UNSIGNED_SHORT indices, base
    # colour factor 0.8) under a root node whose `matrix` turns it -90
    # degrees about X (+Y to -Z; column-major as glTF stores it). Its buffer
    # is laid out as converters often write one, and as the scene suite's
    # hostile variants (tests/scene/bad_inputs_test.cpp) count on: one
    # bufferView of NORMAL then POSITION with byteStride 12 (bytes 0..575),
    # then the indices (576..647).
    g = Gltf(camera=False, generator=GENERATOR)
    m = g.material((0.8, 0.0, 0.0, 1.0))
    pos, nrm, _, idx = box_arrays()
    g.data += struct.pack("<%df" % (len(nrm) + len(pos)), *(nrm + pos))
    g.data += struct.pack("<%dH" % len(idx), *idx)
    indices, attributes = 0, 1  # the indices' view listed first
    g.j["bufferViews"] = [
        {"buffer": 0, "byteOffset": 4 * (len(nrm) + len(pos)), "byteLength": 2 * len(idx), "target": ELEMENT_ARRAY_BUFFER},
        {"buffer": 0, "byteOffset": 0, "byteLength": 4 * (len(nrm) + len(pos)), "byteStride": 12, "target": ARRAY_BUFFER}]
    g.j["accessors"] = [
        {"bufferView": indices, "byteOffset": 0, "componentType": USHORT, "count": len(idx), "type": "SCALAR",
         "min": [0], "max": [max(idx)]},
        {"bufferView": attributes, "byteOffset": 0, "componentType": FLOAT, "count": 24, "type": "VEC3",
         "min": [min(nrm[i::3]) for i in range(3)], "max": [max(nrm[i::3]) for i in range(3)]},
        {"bufferView": attributes, "byteOffset": 4 * len(nrm), "componentType": FLOAT, "count": 24, "type": "VEC3",
         "min": [min(pos[i::3]) for i in range(3)], "max": [max(pos[i::3]) for i in range(3)]}]
    prim = {"attributes": {"NORMAL": 1, "POSITION": 2}, "indices": 0, "mode": TRIANGLES, "material": m}
    g.node({"children": [1], "matrix": [1, 0, 0, 0, 0, 0, -1, 0, 0, 1, 0, 0, 0, 0, 0, 1]})  # unnamed, as
    g.node({"mesh": g.mesh([prim])}, root=False)  # converters often leave them
    return g


def box_textured():
    # A unit cube with the orientation texture on every face (data uri).
    g = Gltf(camera=False, generator=GENERATOR)
    m = g.material((1, 1, 1, 1))
    g.j["materials"][m]["pbrMetallicRoughness"]["baseColorTexture"] = {"index": g.texture(QUADRANTS_PNG)}
    g.j["samplers"] = [{"magFilter": 9728, "minFilter": 9728}]  # NEAREST: the quadrants stay sharp
    g.j["textures"][0]["sampler"] = 0
    g.node({"name": "box", "mesh": g.mesh([box_primitive(g, m)], name="box")})
    return g


def box_vertex_colors():
    # A unit cube whose COLOR_0 (RGBA float) is the vertex position mapped
    # to [0, 1] per axis, alpha 1.
    g = Gltf(camera=False, generator=GENERATOR)
    m = g.material((1, 1, 1, 1))
    pos, _, _, _ = box_arrays()
    colors = []
    for i in range(0, len(pos), 3):
        colors += [pos[i] + 0.5, pos[i + 1] + 0.5, pos[i + 2] + 0.5, 1.0]
    g.node({"name": "box", "mesh": g.mesh([box_primitive(g, m, colors=colors, texcoords=False)], name="box")})
    return g


def nodes():
    # A node tree: "base" (identity) with two children, "trs" (translation
    # (2, 0, 0), a quaternion of 30 degrees about -X, scale (1, 0.5, 0.5))
    # and "matrix" (translation (-2, 0, 0) and 5 degrees about +X, as a
    # column-major matrix), whose child "leaf" is moved (0, 0, 1) in its
    # parent's frame; the box mesh is drawn by all four (one mesh, four
    # instances).
    g = Gltf(camera=False, generator=GENERATOR)
    m = g.material((0.6, 0.6, 0.7, 1))
    mesh = g.mesh([box_primitive(g, m, half=0.4, texcoords=False)], name="box")
    half = math.radians(30) / 2
    trs = g.node({"name": "trs", "mesh": mesh, "translation": [2, 0, 0],
                  "rotation": [-math.sin(half), 0, 0, math.cos(half)], "scale": [1, 0.5, 0.5]}, root=False)
    leaf = g.node({"name": "leaf", "mesh": mesh, "translation": [0, 0, 1]}, root=False)
    c, s = math.cos(math.radians(5)), math.sin(math.radians(5))
    matrix = g.node({"name": "matrix", "mesh": mesh, "children": [leaf],
                     "matrix": [1, 0, 0, 0, 0, c, s, 0, 0, -s, c, 0, -2, 0, 0, 1]}, root=False)
    g.node({"name": "base", "mesh": mesh, "children": [trs, matrix]})
    return g


def index_types():
    # Three cubes in a row, indexed with UNSIGNED_BYTE, UNSIGNED_SHORT and
    # UNSIGNED_INT: each draws the same 12 triangles.
    g = Gltf(camera=False, generator=GENERATOR)
    m = g.material((0.3, 0.5, 0.9, 1))
    for x, (name, kind) in zip((-1.5, 0.0, 1.5), (("ubyte", UBYTE), ("ushort", USHORT), ("uint", UINT))):
        g.node({"name": name, "translation": [x, 0, 0],
                "mesh": g.mesh([box_primitive(g, m, index_type=kind, texcoords=False)], name=name)})
    return g


def primitive_modes():
    # One mesh per primitive mode in a 4 x 2 grid of unit cells: POINTS,
    # LINES, LINE_LOOP, LINE_STRIP without indices, TRIANGLES, TRIANGLE_STRIP
    # and TRIANGLE_FAN with UNSIGNED_SHORT indices, and a filled backdrop quad.
    g = Gltf(camera=False, generator=GENERATOR)
    m = g.material((0.9, 0.8, 0.2, 1))
    square = [0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0]  # counter-clockwise from the bottom left
    cases = [("points", POINTS, None), ("lines", LINES, None), ("line_loop", LINE_LOOP, None),
             ("line_strip", LINE_STRIP, None), ("triangles", TRIANGLES, [0, 1, 2, 0, 2, 3]),
             ("triangle_strip", TRIANGLE_STRIP, [0, 1, 3, 2]), ("triangle_fan", TRIANGLE_FAN, [0, 1, 2, 3])]
    for k, (name, mode, idx) in enumerate(cases):
        prim = {"attributes": {"POSITION": g.accessor(square, "VEC3")}, "mode": mode, "material": m}
        if idx is not None:
            prim["indices"] = g.indices(idx)
        g.node({"name": name, "translation": [1.5 * (k % 4) - 3, 1.5 * (1 - k // 4), 0],
                "mesh": g.mesh([prim], name=name)})
    return g


def multiple_scenes():
    # Two scenes over two meshes: scene 0 draws a triangle, scene 1 (the
    # default) a cube.
    g = Gltf(camera=False, generator=GENERATOR)
    m = g.material((0.5, 0.7, 0.5, 1))
    tri = {"attributes": {"POSITION": g.accessor([0, 0, 0, 1, 0, 0, 0, 1, 0], "VEC3")}, "material": m}
    first = g.node({"name": "triangle", "mesh": g.mesh([tri], name="triangle")})
    second = g.node({"name": "box", "mesh": g.mesh([box_primitive(g, m, texcoords=False)], name="box")}, root=False)
    g.j["scenes"] = [{"name": "first", "nodes": [first]}, {"name": "second", "nodes": [second]}]
    g.j["scene"] = 1
    return g


def cameras():
    # A cube seen by two cameras on one node at (0.5, 0.5, 3) looking down
    # -Z: perspective (yfov 0.7, aspect 1.5, znear 0.01, zfar 100) first,
    # orthographic (xmag = ymag = 1, znear 0.01, zfar 100) second.
    g = Gltf(camera=False, generator=GENERATOR)
    m = g.material((0.7, 0.4, 0.6, 1))
    g.node({"name": "box", "mesh": g.mesh([box_primitive(g, m, texcoords=False)], name="box")})
    g.j["cameras"] = [
        {"name": "perspective", "type": "perspective",
         "perspective": {"yfov": 0.7, "aspectRatio": 1.5, "znear": 0.01, "zfar": 100.0}},
        {"name": "orthographic", "type": "orthographic",
         "orthographic": {"xmag": 1.0, "ymag": 1.0, "znear": 0.01, "zfar": 100.0}}]
    g.node({"name": "perspective", "camera": 0, "translation": [0.5, 0.5, 3.0]})
    g.node({"name": "orthographic", "camera": 1, "translation": [0.5, 0.5, 3.0]})
    return g


def skin():
    # A 2 m column of 5 rings (8 vertices each) along +Y, skinned to two
    # joints with inverse bind matrices, and an animation that bends the
    # upper joint. The loader draws the bind pose (skins and animations are
    # not applied), so the column stands straight at its node's place.
    g = Gltf(camera=False, generator=GENERATOR)
    m = g.material((0.4, 0.8, 0.8, 1))
    pos, nrm, joints, weights, idx = [], [], [], [], []
    rings, sides = 5, 8
    for r in range(rings):
        y = 2.0 * r / (rings - 1)
        for s in range(sides):
            a = 2 * math.pi * s / sides
            pos += [0.25 * math.cos(a), y, 0.25 * math.sin(a)]
            nrm += [math.cos(a), 0, math.sin(a)]
            w = y / 2.0
            joints += [0, 1, 0, 0]
            weights += [1 - w, w, 0, 0]
    for r in range(rings - 1):
        for s in range(sides):
            a, b = r * sides + s, r * sides + (s + 1) % sides
            idx += [a, b + sides, b, a, a + sides, b + sides]
    prim = {"attributes": {"POSITION": g.accessor(pos, "VEC3"), "NORMAL": g.accessor(nrm, "VEC3"),
                           "JOINTS_0": g.accessor(joints, "VEC4", UBYTE, bounds=False),
                           "WEIGHTS_0": g.accessor(weights, "VEC4")},
            "indices": g.indices(idx), "material": m}
    upper = g.node({"name": "upper", "translation": [0, 1, 0]}, root=False)
    lower = g.node({"name": "lower", "children": [upper]})
    inverse_bind = [1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1,
                    1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, -1, 0, 1]
    g.j["skins"] = [{"joints": [lower, upper], "skeleton": lower,
                     "inverseBindMatrices": g.accessor(inverse_bind, "MAT4", bounds=False)}]
    g.node({"name": "column", "mesh": g.mesh([prim], name="column"), "skin": 0, "translation": [0, 0, 0.5]})
    times = g.accessor([0.0, 1.0, 2.0], "SCALAR", bounds=True)
    half = math.radians(20) / 2
    turns = g.accessor([0, 0, 0, 1, 0, 0, math.sin(half), math.cos(half), 0, 0, 0, 1], "VEC4", bounds=False)
    g.j["animations"] = [{"name": "bend", "samplers": [{"input": times, "output": turns, "interpolation": "LINEAR"}],
                          "channels": [{"sampler": 0, "target": {"node": upper, "path": "rotation"}}]}]
    return g


def morph():
    # A 1 m square (4 vertices, facing +Z) with two morph targets: target 0
    # moves its top edge up 0.5 m, target 1 turns the normals towards +X
    # (NORMAL deltas). mesh.weights [0.5, 1.0]: the square is drawn 1.25 m
    # tall with normals (1, 0, 1) before normalization.
    g = Gltf(camera=False, generator=GENERATOR)
    m = g.material((0.9, 0.5, 0.3, 1))
    pos = [-0.5, 0, 0, 0.5, 0, 0, 0.5, 1, 0, -0.5, 1, 0]
    prim = {"attributes": {"POSITION": g.accessor(pos, "VEC3"), "NORMAL": g.accessor([0, 0, 1] * 4, "VEC3")},
            "indices": g.indices([0, 1, 2, 0, 2, 3]), "material": m,
            "targets": [{"POSITION": g.accessor([0, 0, 0, 0, 0, 0, 0, 0.5, 0, 0, 0.5, 0], "VEC3")},
                        {"NORMAL": g.accessor([1, 0, 0] * 4, "VEC3")}]}
    g.node({"name": "square", "mesh": g.mesh([prim], weights=[0.5, 1.0], name="square")})
    return g


def sparse():
    # Two rows of 4 vertices, y = 0 (0..3) over y = -0.5 (4..7), joined by
    # 3 quads, whose sparse accessor moves vertices 1, 3 and 6 to y = 1, 2
    # and -1 (UNSIGNED_SHORT sparse indices, FLOAT values).
    g = Gltf(camera=False, generator=GENERATOR)
    m = g.material((0.7, 0.7, 0.3, 1))
    dense = []
    for i in range(8):
        dense += [0.5 * (i % 4), 0 if i < 4 else -0.5, 0]
    position = g.accessor(dense, "VEC3", bounds=False)
    acc = g.j["accessors"][position]
    lifted = {1: 1.0, 3: 2.0, 6: -1.0}
    values = []
    for k in sorted(lifted):
        values += [dense[3 * k], lifted[k], 0]
    acc["sparse"] = {"count": len(lifted),
                     "indices": {"bufferView": g.view(struct.pack("<3H", *sorted(lifted))), "componentType": USHORT},
                     "values": {"bufferView": g.view(struct.pack("<%df" % len(values), *values))}}
    final = list(dense)
    for k, y in lifted.items():
        final[3 * k + 1] = y
    acc["min"] = [min(final[i::3]) for i in range(3)]
    acc["max"] = [max(final[i::3]) for i in range(3)]
    idx = []
    for i in range(3):
        idx += [4 + i, 4 + i + 1, i + 1, 4 + i, i + 1, i]
    prim = {"attributes": {"POSITION": position}, "indices": g.indices(idx), "material": m}
    g.node({"name": "row", "mesh": g.mesh([prim], name="row")})
    return g


def interleaved():
    # A unit cube whose POSITION, NORMAL and TEXCOORD_0 share one bufferView
    # with byteStride 32 (vertex by vertex), textured with the orientation
    # texture.
    g = Gltf(camera=False, generator=GENERATOR)
    m = g.material((1, 1, 1, 1))
    g.j["materials"][m]["pbrMetallicRoughness"]["baseColorTexture"] = {"index": g.texture(QUADRANTS_PNG)}
    pos, nrm, uv, idx = box_arrays()
    p, n, t = g.interleaved([("VEC3", pos), ("VEC3", nrm), ("VEC2", uv)])
    prim = {"attributes": {"POSITION": p, "NORMAL": n, "TEXCOORD_0": t}, "indices": g.indices(idx), "material": m}
    g.node({"name": "box", "mesh": g.mesh([prim], name="box")})
    return g


def torus_arrays(rings=48, sides=32, major=0.6, minor=0.25):
    """A torus around +Y: (rings + 1) x (sides + 1) vertices (the seams
    doubled for the uv), 2 * rings * sides triangles."""
    pos, nrm, uv, idx = [], [], [], []
    for i in range(rings + 1):
        a = 2 * math.pi * i / rings
        for j in range(sides + 1):
            b = 2 * math.pi * j / sides
            n = (math.cos(a) * math.cos(b), math.sin(b), math.sin(a) * math.cos(b))
            pos += [math.cos(a) * major + minor * n[0], minor * n[1], math.sin(a) * major + minor * n[2]]
            nrm += [round(c, 6) for c in n]
            uv += [i / rings, j / sides]
    for i in range(rings):
        for j in range(sides):
            a, b = i * (sides + 1) + j, (i + 1) * (sides + 1) + j
            idx += [a, a + 1, b + 1, a, b + 1, b]
    pos = [round(c, 6) for c in pos]
    return pos, nrm, uv, idx


def torus(in_buffer=False):
    # 3072 triangles with the orientation texture, under a parent scaled
    # 0.01 that holds a perspective camera (yfov 0.66, aspect 1.5, znear 1,
    # zfar 10000, in the parent's centimetres) looking at it from above.
    g = Gltf(camera=False, generator=GENERATOR)
    m = g.material((1, 1, 1, 1), name="torus")
    g.j["materials"][m]["pbrMetallicRoughness"]["baseColorTexture"] = {"index": g.texture(QUADRANTS_PNG, in_buffer)}
    pos, nrm, uv, idx = torus_arrays()
    prim = {"attributes": {"POSITION": g.accessor([100 * c for c in pos], "VEC3"),
                           "NORMAL": g.accessor(nrm, "VEC3"), "TEXCOORD_0": g.accessor(uv, "VEC2")},
            "indices": g.indices(idx), "material": m}
    body = g.node({"name": "torus", "mesh": g.mesh([prim], name="torus")}, root=False)
    # The camera 300 cm back and 200 cm up, pitched down by atan(2/3).
    half = math.atan2(200, 300) / 2
    eye = g.node({"camera": 0, "translation": [0, 200, 300],  # neither it nor its camera named
                  "rotation": [-math.sin(half), 0, 0, math.cos(half)]}, root=False)
    g.node({"name": "centimetres", "scale": [0.01, 0.01, 0.01], "children": [body, eye]})
    g.j["cameras"] = [{"type": "perspective",
                       "perspective": {"yfov": 0.66, "aspectRatio": 1.5, "znear": 1.0, "zfar": 10000.0}}]
    return g


def torus_glb():
    return torus(in_buffer=True)


def torus_quantized(normalized=True):
    # torus.gltf with KHR_mesh_quantization, the node "torus" carrying the
    # dequantization (its translation and uniform scale), as the extension
    # says. normalized: POSITION normalized SHORT (centre + half extent *
    # max(q / 32767, -1)), NORMAL normalized BYTE, TEXCOORD_0 normalized UNSIGNED_SHORT.
    # Else POSITION plain UNSIGNED_SHORT (min + step * q), NORMAL normalized
    # SHORT, TEXCOORD_0 plain UNSIGNED_BYTE (i, j) scaled by
    # KHR_texture_transform to (i / 48, j / 32), exactly torus.gltf's uv.
    # Not committed (tests/data is the committed set): the scene and gl
    # suites write them at test time (make_feature_gltf.py --quantized DIR).
    rings, sides = 48, 32
    g = Gltf(camera=False, generator=GENERATOR)
    m = g.material((1, 1, 1, 1), name="torus")
    texture = {"index": g.texture(QUADRANTS_PNG)}
    pos, nrm, uv, idx = torus_arrays(rings, sides)
    pos = [100 * c for c in pos]
    low = [min(pos[i::3]) for i in range(3)]
    high = [max(pos[i::3]) for i in range(3)]
    if normalized:
        centre = [(a + b) / 2 for a, b in zip(low, high)]
        half = max(b - a for a, b in zip(low, high)) / 2
        q = [round((c - centre[k % 3]) / half * 32767) for k, c in enumerate(pos)]
        position = g.accessor(q, "VEC3", SHORT, normalized=True, stride=8, bounds=True)
        normal = g.accessor([round(c * 127) for c in nrm], "VEC3", BYTE, normalized=True, stride=4)
        texcoord = g.accessor([round(c * 65535) for c in uv], "VEC2", USHORT, normalized=True)
        dequantize = {"translation": centre, "scale": [half] * 3}  # the reader maps q to q / 32767
    else:
        step = max(b - a for a, b in zip(low, high)) / 65535
        q = [round((c - low[k % 3]) / step) for k, c in enumerate(pos)]
        position = g.accessor(q, "VEC3", USHORT, stride=8, bounds=True)
        normal = g.accessor([round(c * 32767) for c in nrm], "VEC3", SHORT, normalized=True, stride=8)
        texcoord = g.accessor([round(c * (rings if k % 2 == 0 else sides)) for k, c in enumerate(uv)], "VEC2", UBYTE,
                              stride=4)
        texture["extensions"] = {"KHR_texture_transform": {"scale": [1 / rings, 1 / sides]}}
        dequantize = {"translation": low, "scale": [step] * 3}
    g.j["materials"][m]["pbrMetallicRoughness"]["baseColorTexture"] = texture
    prim = {"attributes": {"POSITION": position, "NORMAL": normal, "TEXCOORD_0": texcoord},
            "indices": g.indices(idx), "material": m}
    body = g.node(dict({"name": "torus", "mesh": g.mesh([prim], name="torus")}, **dequantize), root=False)
    g.node({"name": "centimetres", "scale": [0.01, 0.01, 0.01], "children": [body]})
    used = ["KHR_mesh_quantization"] + ([] if normalized else ["KHR_texture_transform"])
    g.j["extensionsUsed"] = used
    g.j["extensionsRequired"] = ["KHR_mesh_quantization"]
    return g


def box_meshes(g, colors):
    """One unit cube (box_arrays(0.5), counter-clockwise from outside) per
    colour, sharing its accessors: name -> mesh index."""
    pos, nrm, _, idx = box_arrays(0.5)
    attributes = {"POSITION": g.accessor(pos, "VEC3"), "NORMAL": g.accessor(nrm, "VEC3")}
    indices = g.indices(idx)
    return {name: g.mesh([{"attributes": dict(attributes), "indices": indices, "material": g.material(rgba, name=name)}],
                         name=name)
            for name, rgba in colors.items()}


def place_boxes(g, meshes, boxes):
    # boxes: (name, mesh name, centre, size); each a node scaling the unit cube.
    for name, mesh, centre, size in boxes:
        g.node({"name": name, "mesh": meshes[mesh], "translation": list(centre), "scale": list(size)})


def look(yaw_rad, pitch_rad):
    """The rotation quaternion [x, y, z, w] of a camera turned by yaw about +Y,
    then pitched about its own x (glTF cameras look down -Z)."""
    cy, sy = math.cos(yaw_rad / 2), math.sin(yaw_rad / 2)
    cp, sp = math.cos(pitch_rad / 2), math.sin(pitch_rad / 2)
    # q_yaw * q_pitch with q_yaw = (0, sy, 0, cy), q_pitch = (sp, 0, 0, cp)
    return [round(v, 9) for v in (cy * sp, sy * cp, -sy * sp, cy * cp)]


def room(zfar=50.0):
    # A closed room seen from inside (issue 33): 6 m wide (x), 3 m high, 8 m
    # deep (z), walls, floor and ceiling 0.1 m thick boxes of their own
    # colours, furniture boxes (a table, a cabinet, a sofa behind the
    # camera, a lamp column), and a perspective camera named "inside" at
    # eye height 1.6 m near the back wall looking into the room, turned 20
    # degrees left and 8 degrees down. zfar None: no far plane (infinite).
    g = Gltf(camera=False, generator=GENERATOR)
    meshes = box_meshes(g, {"floor": (0.55, 0.4, 0.3, 1), "ceiling": (0.92, 0.92, 0.9, 1),
                            "wall_front": (0.35, 0.55, 0.75, 1), "wall_back": (0.8, 0.45, 0.35, 1),
                            "wall_side": (0.85, 0.8, 0.55, 1), "furniture": (0.3, 0.6, 0.35, 1),
                            "dark": (0.2, 0.18, 0.22, 1)})
    place_boxes(g, meshes, [
        ("floor", "floor", (0, -0.05, 0), (6.2, 0.1, 8.2)),
        ("ceiling", "ceiling", (0, 3.05, 0), (6.2, 0.1, 8.2)),
        ("wall_front", "wall_front", (0, 1.5, -4.05), (6.2, 3.2, 0.1)),
        ("wall_back", "wall_back", (0, 1.5, 4.05), (6.2, 3.2, 0.1)),
        ("wall_left", "wall_side", (-3.05, 1.5, 0), (0.1, 3.2, 8.2)),
        ("wall_right", "wall_side", (3.05, 1.5, 0), (0.1, 3.2, 8.2)),
        ("table", "furniture", (0.8, 0.375, -1.5), (1.4, 0.75, 0.8)),
        ("cabinet", "dark", (-2.6, 0.9, -3.4), (0.7, 1.8, 0.5)),
        ("sofa", "furniture", (0.5, 0.4, 3.3), (2.2, 0.8, 0.9)),
        ("lamp", "dark", (2.4, 0.9, -3.2), (0.2, 1.8, 0.2)),
    ])
    perspective = {"yfov": 0.9, "aspectRatio": 16 / 9, "znear": 0.1}
    if zfar is not None:
        perspective["zfar"] = zfar
    g.j["cameras"] = [{"type": "perspective", "name": "inside", "perspective": perspective}]
    g.node({"name": "eye", "camera": 0, "translation": [0.4, 1.6, 2.6],
            "rotation": look(math.radians(20), math.radians(-8))})
    return g


def street(znear=0.05, zfar=1e6):
    # A street of blocks seen from street level (issue 33): a ground slab
    # 40 m x 120 m, two rows of building boxes either side of a 12 m street
    # running along -z, 8 to 26 m high, and a camera named "street" at eye
    # height 1.7 m 35 m into the street looking down it. The camera
    # is a CAD export's: znear 0.05 m, zfar 1e6 m (a ratio of 2e7).
    g = Gltf(camera=False, generator=GENERATOR)
    meshes = box_meshes(g, {"ground": (0.35, 0.35, 0.37, 1), "brick": (0.7, 0.4, 0.3, 1),
                            "stone": (0.75, 0.72, 0.65, 1), "glass": (0.4, 0.55, 0.7, 1)})
    boxes = [("ground", "ground", (0, -0.05, -50), (40, 0.1, 120))]
    heights = [14, 22, 9, 18, 26, 12, 16, 8, 20, 11]
    kinds = ["brick", "stone", "glass"]
    for side, x in (("left", -12.5), ("right", 12.5)):
        z = 5.0
        for i, h in enumerate(heights if side == "left" else heights[::-1]):
            depth = 9.0 + 2.0 * ((i * 7) % 3)
            boxes.append(("%s_%d" % (side, i), kinds[(i + (side == "right")) % 3],
                          (x, h / 2, z - depth / 2), (13.0, h, depth - 1.0)))
            z -= depth
    place_boxes(g, meshes, boxes)
    g.j["cameras"] = [{"type": "perspective", "name": "street",
                       "perspective": {"yfov": 0.8, "aspectRatio": 16 / 9, "znear": znear, "zfar": zfar}}]
    g.node({"name": "eye", "camera": 0, "translation": [-1.5, 1.7, -30.0], "rotation": look(math.radians(-6), 0.0)})
    return g


# Written only on request (make_feature_gltf.py --quantized DIR), by the
# tests that load them next to torus.gltf.
QUANTIZED_MODELS = {
    "torus_quantized.gltf": torus_quantized,
    "torus_quantized_int.gltf": lambda: torus_quantized(normalized=False),
}

# name -> builder; .glb files are written with Gltf.binary().
MODELS = {
    "box.gltf": box,
    "box_textured.gltf": box_textured,
    "box_vertex_colors.gltf": box_vertex_colors,
    "cameras.gltf": cameras,
    "index_types.gltf": index_types,
    "interleaved.gltf": interleaved,
    "morph.gltf": morph,
    "multiple_scenes.gltf": multiple_scenes,
    "nodes.gltf": nodes,
    "primitive_modes.gltf": primitive_modes,
    "room.gltf": room,
    "room_no_zfar.gltf": lambda: room(zfar=None),
    "skin.gltf": skin,
    "sparse.gltf": sparse,
    "street.gltf": street,
    "torus.gltf": torus,
    "torus.glb": torus_glb,
    "triangle.gltf": triangle,
    "triangle_without_indices.gltf": triangle_without_indices,
}
