#!/usr/bin/env python3
"""Generate the project's own glTF test files, deterministically (Python 3,
standard library only; the `scene` suite checks them byte for byte):

- tests/data/gltf-features/*.gltf: one small file per loader feature
  (KHR_materials_unlit, texCoord sets, KHR_texture_transform,
  EXT_mesh_gpu_instancing, morph-target weights, alphaMode, orthographic
  aspect, texture orientation, a required extension that is not supported).
  Every file has an orthographic camera "main" at (0, 0, 5) looking down -Z
  with xmag = ymag = 1, so world x, y in [-1, 1] fill a square image
  (tests/data/gltf-features/README.md).
- tests/data/gltf-models/*: 3D models without a file camera, one per loader
  feature a sample model would exercise (scripts/gltf_models.py,
  tests/data/gltf-models/README.md).
- tests/fuzz/corpus/gltf/: the generated fuzz seeds (scripts/gltf_seeds.py).

    python3 scripts/make_feature_gltf.py [OUT_ROOT]   # default: the repository
    python3 scripts/make_feature_gltf.py --quantized DIR   # only the KHR_mesh_quantization
        # variants of the torus (gltf_models.QUANTIZED_MODELS), into DIR; not committed
"""
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import gltf_models  # noqa: E402
import gltf_seeds  # noqa: E402
from gltf_writer import Gltf, png_rgba  # noqa: E402

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


def orientation_file():
    # A square with the orientation texture (scripts/gltf_models.py): red
    # top left, green top right, blue bottom left, white bottom right in the
    # picture; a flipped v puts blue on top, a flipped u green on the left.
    g = Gltf()
    m = g.material((1, 1, 1, 1), **UNLIT)
    g.j["materials"][m]["pbrMetallicRoughness"]["baseColorTexture"] = {"index": g.texture(gltf_models.QUADRANTS_PNG)}
    g.j["samplers"] = [{"magFilter": 9728, "minFilter": 9728}]  # NEAREST
    g.j["textures"][0]["sampler"] = 0
    g.node({"name": "square", "mesh": g.mesh([g.quad(-0.8, -0.8, 0.8, 0.8, 0, m, uv0="quad")])})
    g.j["extensionsUsed"] = ["KHR_materials_unlit"]
    return g


def unsupported_required_file():
    # Valid, but requires an extension the loader does not implement.
    g = orthographic_file()
    g.j["extensionsUsed"] = ["KHR_materials_unlit", "KHR_materials_variants"]
    g.j["extensionsRequired"] = ["KHR_materials_variants"]
    return g


FILES = {
    "unlit.gltf": unlit_file,
    "texcoord1.gltf": texcoord1_file,
    "texture_transform.gltf": texture_transform_file,
    "instancing.gltf": instancing_file,
    "morph.gltf": morph_file,
    "alpha.gltf": alpha_file,
    "orthographic.gltf": orthographic_file,
    "orientation.gltf": orientation_file,
    "unsupported_required.gltf": unsupported_required_file,
}


def write(path, content):
    with open(path, "wb") as f:
        f.write(content if isinstance(content, bytes) else content.encode("utf-8"))


def main():
    if len(sys.argv) == 3 and sys.argv[1] == "--quantized":
        for name, make in gltf_models.QUANTIZED_MODELS.items():
            write(os.path.join(sys.argv[2], name), make().text())
        return
    here = os.path.dirname(os.path.abspath(__file__))
    root = sys.argv[1] if len(sys.argv) > 1 else os.path.join(here, "..")
    folders = {"features": os.path.join(root, "tests", "data", "gltf-features"),
               "models": os.path.join(root, "tests", "data", "gltf-models"),
               "seeds": os.path.join(root, "tests", "fuzz", "corpus", "gltf")}
    for folder in folders.values():
        os.makedirs(folder, exist_ok=True)
    for name, make in FILES.items():
        write(os.path.join(folders["features"], name), make().text())
    for name, make in gltf_models.MODELS.items():
        g = make()
        write(os.path.join(folders["models"], name), g.binary() if name.endswith(".glb") else g.text())
    for name, make in gltf_seeds.SEEDS.items():
        write(os.path.join(folders["seeds"], name), make())


if __name__ == "__main__":
    main()
