"""The generated part of the glTF fuzz seeds (tests/fuzz/corpus/gltf/,
written by scripts/make_feature_gltf.py): the project's own box
(scripts/gltf_models.py) made hostile in one way each, and the box with the
node names the loader reads as a mirror and a lens. The other seeds of that
folder (bad-uri-*, external-*) are written by hand; the fuzzer also starts
from every file of tests/data/gltf-models/ (scripts/fuzz.sh).
"""
import json

import gltf_models


def _box():
    return gltf_models.box()


def _json(g):
    return json.loads(g.text())


def _text(j):
    return json.dumps(j, separators=(",", ":"), sort_keys=True) + "\n"


def accessor_over_read():
    # POSITION claims 48 vertices where its bufferView holds 24.
    j = _json(_box())
    position = j["meshes"][0]["primitives"][0]["attributes"]["POSITION"]
    j["accessors"][position]["count"] = 48
    return _text(j)


def node_cycle():
    # The box node lists its parent as its child.
    j = _json(_box())
    j["nodes"][1]["children"] = [0]
    return _text(j)


def deep_nesting():
    # "extras" nested 110 arrays deep, past the loader's JSON depth limit.
    j = _json(_box())
    text = _text(j)
    return text.replace("{", '{"extras":' + "[" * 110 + "]" * 110 + ",", 1)


def glb_truncated():
    # The box as a .glb cut to half its length: the header's total length
    # and the BIN chunk run past the end of the file.
    whole = _box().binary()
    return whole[:len(whole) // 2]


def meshopt_garbage():
    # bufferView 1 (NORMAL, POSITION) claims to be EXT_meshopt_compression
    # data held in the index bytes: no meshopt vertex stream (header 0xA0).
    j = _json(_box())
    j["bufferViews"][1]["extensions"] = {"EXT_meshopt_compression": {
        "buffer": 0, "byteOffset": 576, "byteLength": 72, "byteStride": 12, "count": 48, "mode": "ATTRIBUTES"}}
    j["extensionsUsed"] = j["extensionsRequired"] = ["EXT_meshopt_compression"]
    return _text(j)


def draco_garbage():
    # The box's primitive claims KHR_draco_mesh_compression data in its
    # index bufferView: no Draco stream (magic "DRACO").
    j = _json(_box())
    j["meshes"][0]["primitives"][0]["extensions"] = {"KHR_draco_mesh_compression": {
        "bufferView": 0, "attributes": {"NORMAL": 1, "POSITION": 0}}}
    j["extensionsUsed"] = j["extensionsRequired"] = ["KHR_draco_mesh_compression"]
    return _text(j)


def mirror_lens():
    # The box drawn twice, by nodes named "mirror" and "lens".
    j = _json(_box())
    mesh = j["nodes"][1]["mesh"]
    j["nodes"][1]["name"] = "mirror"
    j["nodes"].append({"name": "lens", "mesh": mesh, "translation": [0, 0, 1], "scale": [0.5, 0.5, 0.5]})
    j["scenes"][0]["nodes"].append(len(j["nodes"]) - 1)
    return _text(j)


# name -> bytes or text
SEEDS = {
    "bad-accessor-over-read.gltf": accessor_over_read,
    "bad-deep-nesting.gltf": deep_nesting,
    "bad-draco-garbage.gltf": draco_garbage,
    "bad-glb-truncated.glb": glb_truncated,
    "bad-meshopt-garbage.gltf": meshopt_garbage,
    "bad-node-cycle.gltf": node_cycle,
    "mirror-lens.gltf": mirror_lens,
}
