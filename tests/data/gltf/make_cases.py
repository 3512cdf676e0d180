#!/usr/bin/env python3
"""Writes the glTF loader's edge-case files next to this script (stdlib only, deterministic).

    python3 tests/data/gltf/make_cases.py

Every case is a one- or two-triangle scene unless README.md says otherwise. After writing, the
script reads every file back with scenes/gltf_check.py: the valid cases must load (triangle
counts, hierarchy sidecars) as the C++ loader loads them by default, those in STRICT_ERRORS must
fail strict loading, each malformed case must fail for the reason it was made for.
cases.json records the outcome the C++ loader should reproduce.
"""

import json
import math
import os
import sys

sys.dont_write_bytecode = True  # keep scenes/__pycache__ out of the tree
HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "..", "..", "scenes"))
from gltf_check import read_scene  # noqa: E402
from gltf_io import GltfError, data_uri, f32_json, glb_bytes, gltf_text, pack  # noqa: E402
from png_encoder import checkerboard_png  # noqa: E402

GENERATOR = "Pathway tests/data/gltf/make_cases.py"
FLOAT, UBYTE, USHORT, UINT = 5126, 5121, 5123, 5125
ARRAY_BUFFER, ELEMENT_ARRAY_BUFFER = 34962, 34963
INDEX_CODE = {UBYTE: "B", USHORT: "H", UINT: "I"}

# The shared geometry: a unit quad in the z = 0 plane facing +z, and a right triangle.
QUAD = [(0.0, 0.0, 0.0), (1.0, 0.0, 0.0), (1.0, 1.0, 0.0), (0.0, 1.0, 0.0)]
QUAD_INDICES = [0, 1, 2, 0, 2, 3]
TRIANGLE = [(0.0, 0.0, 0.0), (1.0, 0.0, 0.0), (0.0, 1.0, 0.0)]


class Doc:
    """A hand-assembled glTF document with one binary buffer."""

    def __init__(self):
        self.blob = bytearray()
        self.doc = {"asset": {"version": "2.0", "generator": GENERATOR}, "scene": 0,
                    "scenes": [{"nodes": [0]}], "nodes": [], "meshes": [],
                    "materials": [grey()], "accessors": [], "bufferViews": []}

    def view(self, payload, target=None, stride=None):
        while len(self.blob) % 4:
            self.blob.append(0)
        v = {"buffer": 0, "byteOffset": len(self.blob), "byteLength": len(payload)}
        if stride is not None:
            v["byteStride"] = stride
        if target is not None:
            v["target"] = target
        self.blob.extend(payload)
        self.doc["bufferViews"].append(v)
        return len(self.doc["bufferViews"]) - 1

    def accessor(self, **fields):
        self.doc["accessors"].append(fields)
        return len(self.doc["accessors"]) - 1

    def positions(self, points, count=None):
        """A tightly packed float32 POSITION accessor with min/max (NaN components ignored)."""
        flat = [c for p in points for c in p]
        return self.accessor(
            bufferView=self.view(pack("f", flat), ARRAY_BUFFER), componentType=FLOAT,
            count=len(points) if count is None else count, type="VEC3",
            min=[f32_json(min(p[i] for p in points if not math.isnan(p[i]))) for i in range(3)],
            max=[f32_json(max(p[i] for p in points if not math.isnan(p[i]))) for i in range(3)])

    def indices(self, values, component_type=UINT):
        payload = pack(INDEX_CODE[component_type], values)
        return self.accessor(bufferView=self.view(payload, ELEMENT_ARRAY_BUFFER),
                             componentType=component_type, count=len(values), type="SCALAR")

    def mesh_node(self, name, primitives, **node_fields):
        self.doc["meshes"].append({"name": name, "primitives": primitives})
        node = dict(name=name, mesh=len(self.doc["meshes"]) - 1, **node_fields)
        self.doc["nodes"].append(node)
        return len(self.doc["nodes"]) - 1

    def finish(self, uri="embedded"):
        """uri: 'embedded' (base64 data URI), a file name, or None (GLB BIN chunk)."""
        buf = {"byteLength": len(self.blob)}
        if uri == "embedded":
            buf["uri"] = data_uri("application/octet-stream", bytes(self.blob))
        elif uri is not None:
            buf["uri"] = uri
        self.doc["buffers"] = [buf]
        return self.doc


def grey(name="grey", **extra):
    mat = {"name": name, "pbrMetallicRoughness": {"baseColorFactor": [0.5, 0.5, 0.5, 1.0],
                                                  "metallicFactor": 0.0, "roughnessFactor": 1.0}}
    mat.update(extra)
    return mat


def quad_doc(index_type=UINT, points=QUAD, indices=QUAD_INDICES, position_count=None):
    d = Doc()
    pos = d.positions(points, position_count)
    idx = d.indices(indices, index_type)
    d.mesh_node("quad", [{"attributes": {"POSITION": pos}, "indices": idx, "material": 0}])
    return d


def add_checker_texture(doc):
    doc["images"] = [{"name": "checkerboard", "uri": data_uri("image/png", checkerboard_png())}]
    doc["samplers"] = [{"wrapS": 10497, "wrapT": 10497}]
    doc["textures"] = [{"sampler": 0, "source": 0}]


# --------------------------------------------------------------------------------------------
# Valid cases
# --------------------------------------------------------------------------------------------

def external_buffer():
    d = quad_doc()
    return d.finish("external_buffer.bin"), {"external_buffer.bin": bytes(d.blob)}


def embedded_buffer():
    return quad_doc().finish(), {}


def indices(component_type):
    return quad_doc(component_type).finish(), {}


def non_indexed():
    d = Doc()
    pos = d.positions([QUAD[i] for i in QUAD_INDICES])  # consecutive triples
    d.mesh_node("quad", [{"attributes": {"POSITION": pos}, "material": 0}])
    return d.finish(), {}


def interleaved():
    """POSITION (12 bytes) and TEXCOORD_0 (8 bytes) interleaved, byteStride 20; uv = (x, 1 - y)."""
    d = Doc()
    uvs = [(x, 1.0 - y) for x, y, _ in QUAD]
    payload = b"".join(pack("f", list(p) + list(uv)) for p, uv in zip(QUAD, uvs))
    view = d.view(payload, ARRAY_BUFFER, stride=20)
    pos = d.accessor(bufferView=view, byteOffset=0, componentType=FLOAT, count=4, type="VEC3",
                     min=[0.0, 0.0, 0.0], max=[1.0, 1.0, 0.0])
    uv = d.accessor(bufferView=view, byteOffset=12, componentType=FLOAT, count=4, type="VEC2")
    idx = d.indices(QUAD_INDICES)
    d.doc["materials"] = [grey("checker", pbrMetallicRoughness={
        "baseColorFactor": [1.0, 1.0, 1.0, 1.0], "baseColorTexture": {"index": 0},
        "metallicFactor": 0.0, "roughnessFactor": 1.0})]
    add_checker_texture(d.doc)
    d.mesh_node("quad", [{"attributes": {"POSITION": pos, "TEXCOORD_0": uv}, "indices": idx,
                          "material": 0}])
    return d.finish(), {}


# parent: translation (1, 2, 3), rotation 90 degrees about +Y, uniform scale 2;
# child: translation (1, 0, 0), holding the triangle (0,0,0) (1,0,0) (0,1,0).
# world = T(1,2,3) R_y(90) S(2) T(1,0,0) p, with R_y(90): (x, y, z) -> (z, y, -x):
#   (0,0,0) -> (1,0,0) -> (2,0,0) -> (0,0,-2) -> (1,2,1)
#   (1,0,0) -> (2,0,0) -> (4,0,0) -> (0,0,-4) -> (1,2,-1)
#   (0,1,0) -> (1,1,0) -> (2,2,0) -> (0,2,-2) -> (1,4,1)
HIERARCHY_EXPECTED = [(1.0, 2.0, 1.0), (1.0, 2.0, -1.0), (1.0, 4.0, 1.0)]
PARENT_MATRIX = [0.0, 0.0, -2.0, 0.0,  # column-major: R_y(90) * 2 in the upper 3x3 ...
                 0.0, 2.0, 0.0, 0.0,
                 2.0, 0.0, 0.0, 0.0,
                 1.0, 2.0, 3.0, 1.0]   # ... and the translation in the last column
CHILD_MATRIX = [1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 1.0, 0.0, 0.0, 1.0]


def hierarchy(use_matrix):
    d = Doc()
    pos = d.positions(TRIANGLE)
    idx = d.indices([0, 1, 2])
    d.doc["nodes"].append({"name": "parent", "children": [1]})
    if use_matrix:
        d.doc["nodes"][0]["matrix"] = PARENT_MATRIX
        child = {"matrix": CHILD_MATRIX}
    else:
        d.doc["nodes"][0].update(translation=[1.0, 2.0, 3.0],
                                 rotation=[0.0, math.sqrt(0.5), 0.0, math.sqrt(0.5)],
                                 scale=[2.0, 2.0, 2.0])
        child = {"translation": [1.0, 0.0, 0.0]}
    d.mesh_node("triangle", [{"attributes": {"POSITION": pos}, "indices": idx, "material": 0}],
                **child)
    expected = {"description": "world-space positions of the triangle's vertices, in vertex "
                               "order, after the parent and child transforms",
                "positions": [list(p) for p in HIERARCHY_EXPECTED], "tolerance": 1e-5}
    return d.finish(), {"": expected}


def camera():
    d = quad_doc()
    d.doc["scenes"][0]["nodes"] = [0, 1]
    d.doc["cameras"] = [{"name": "camera", "type": "perspective",
                         "perspective": {"yfov": 0.8, "aspectRatio": 1.5, "znear": 0.1}}]
    d.doc["nodes"].append({"name": "camera", "camera": 0, "translation": [0.0, 1.0, 5.0]})
    return d.finish(), {}


def emissive_strength():
    """Two triangles of the quad as two meshes: 'emitter' uses emissiveFactor (1, 0.5, 0.25) x
    KHR_materials_emissive_strength 4 = (4, 2, 1) and is doubleSided; 'plain' has the same
    emissiveFactor without the extension, (1, 0.5, 0.25), one-sided."""
    d = Doc()
    pos = d.positions(QUAD)
    first, second = d.indices([0, 1, 2]), d.indices([0, 2, 3])
    factor = [1.0, 0.5, 0.25]
    d.doc["extensionsUsed"] = ["KHR_materials_emissive_strength"]
    d.doc["materials"] = [
        grey("emitter", emissiveFactor=factor, doubleSided=True,
             extensions={"KHR_materials_emissive_strength": {"emissiveStrength": 4.0}}),
        grey("plain", emissiveFactor=factor)]
    d.doc["scenes"][0]["nodes"] = [0, 1]
    d.mesh_node("emitter", [{"attributes": {"POSITION": pos}, "indices": first, "material": 0}])
    d.mesh_node("plain", [{"attributes": {"POSITION": pos}, "indices": second, "material": 1}])
    return d.finish(), {}


def unsupported_features():
    """The quad (2 triangles, loaded) plus: a normalTexture, an animation, a skin, the
    KHR_lights_punctual extension and a LINES primitive (skipped). One warning each."""
    d = Doc()
    pos = d.positions(QUAD)
    idx = d.indices(QUAD_INDICES)
    lines = d.indices([0, 1, 1, 2, 2, 3, 3, 0])
    times = d.accessor(bufferView=d.view(pack("f", [0.0, 1.0])), componentType=FLOAT, count=2,
                       type="SCALAR", min=[0.0], max=[1.0])
    moves = d.accessor(bufferView=d.view(pack("f", [0.0, 0.0, 0.0, 0.0, 1.0, 0.0])),
                       componentType=FLOAT, count=2, type="VEC3")
    add_checker_texture(d.doc)
    d.doc["materials"] = [grey("bumpy", normalTexture={"index": 0})]
    d.doc["extensionsUsed"] = ["KHR_lights_punctual"]
    d.doc["extensions"] = {"KHR_lights_punctual": {"lights": [
        {"name": "bulb", "type": "point", "color": [1.0, 1.0, 1.0], "intensity": 10.0}]}}
    d.doc["scenes"][0]["nodes"] = [0, 1, 2]
    d.mesh_node("quad", [{"attributes": {"POSITION": pos}, "indices": idx, "material": 0},
                         {"attributes": {"POSITION": pos}, "indices": lines, "material": 0,
                          "mode": 1}])
    d.doc["nodes"].append({"name": "joint", "translation": [0.0, 0.0, 1.0]})
    d.doc["nodes"].append({"name": "bulb", "translation": [0.5, 0.5, 2.0],
                           "extensions": {"KHR_lights_punctual": {"light": 0}}})
    d.doc["skins"] = [{"name": "skin", "joints": [1]}]
    d.doc["animations"] = [{"name": "slide", "samplers": [
        {"input": times, "output": moves, "interpolation": "LINEAR"}],
        "channels": [{"sampler": 0, "target": {"node": 0, "path": "translation"}}]}]
    return d.finish(), {}


def required_lamp():
    """The quad and a point lamp as Blender exports them: extensionsUsed and extensionsRequired
    both list KHR_lights_punctual, and node "Lamp" holds light "Light". Loads without the lamp,
    with one warning naming it; strict loading refuses the file."""
    d = quad_doc()
    d.doc["extensionsUsed"] = ["KHR_lights_punctual"]
    d.doc["extensionsRequired"] = ["KHR_lights_punctual"]
    d.doc["extensions"] = {"KHR_lights_punctual": {"lights": [
        {"name": "Light", "type": "point", "color": [1.0, 1.0, 1.0], "intensity": 1000.0}]}}
    d.doc["scenes"][0]["nodes"] = [0, 1]
    d.doc["nodes"].append({"name": "Lamp", "translation": [0.5, 0.5, 2.0],
                           "extensions": {"KHR_lights_punctual": {"light": 0}}})
    return d.finish(), {}


# --------------------------------------------------------------------------------------------
# Malformed cases (each must make the loader throw one PathwayError)
# --------------------------------------------------------------------------------------------

def accessor_out_of_range():
    """POSITION claims 5 vertices (60 bytes) in a 48-byte bufferView (the buffer itself is long
    enough: the indices follow)."""
    return quad_doc(position_count=5).finish(), {}


def index_out_of_range():
    return quad_doc(indices=[0, 1, 2, 0, 2, 4]).finish(), {}  # 4 vertices: index 4 is past them


def nan_positions():
    points = list(QUAD)
    points[2] = (1.0, float("nan"), 0.0)
    return quad_doc(points=points).finish(), {}


def no_triangles():
    doc = {"asset": {"version": "2.0", "generator": GENERATOR}, "scene": 0,
           "scenes": [{"nodes": [0]}], "nodes": [{"name": "empty", "translation": [0.0, 1.0, 0.0]}]}
    return doc, {}


def missing_buffer():
    return quad_doc().finish("missing_buffer.bin"), {}


def sparse_accessor():
    """POSITION is a sparse accessor (vertex 2 replaced by (1, 2, 0)): not supported."""
    d = quad_doc()
    acc = d.doc["accessors"][0]
    acc["sparse"] = {"count": 1,
                     "indices": {"bufferView": d.view(pack("I", [2])), "componentType": UINT},
                     "values": {"bufferView": d.view(pack("f", [1.0, 2.0, 0.0]))}}
    acc["max"] = [1.0, 2.0, 0.0]
    return d.finish(), {}


def required_extension():
    d = quad_doc()
    d.doc["extensionsUsed"] = ["KHR_draco_mesh_compression"]
    d.doc["extensionsRequired"] = ["KHR_draco_mesh_compression"]
    return d.finish(), {}


# --------------------------------------------------------------------------------------------
# Writing
# --------------------------------------------------------------------------------------------

def binary():
    """One triangle, uint16 indices: 36 + 6 = 42 bytes of BIN data, padded to 44."""
    d = Doc()
    pos = d.positions(TRIANGLE)
    idx = d.indices([0, 1, 2], USHORT)
    d.mesh_node("triangle", [{"attributes": {"POSITION": pos}, "indices": idx, "material": 0}])
    doc = d.finish(None)
    doc["buffers"][0]["name"] = "bin"  # makes the compact JSON 745 bytes: 3 spaces of padding
    return doc, bytes(d.blob)


def write(name, data):
    mode = "wb" if isinstance(data, bytes) else "w"
    with open(os.path.join(HERE, name), mode, **({} if mode == "wb" else {"newline": "\n"})) as f:
        f.write(data)


# file -> (maker, expected outcome); the outcome goes into cases.json
VALID = {
    "external_buffer.gltf": external_buffer,
    "embedded_buffer.gltf": embedded_buffer,
    "indices_u8.gltf": lambda: indices(UBYTE),
    "indices_u16.gltf": lambda: indices(USHORT),
    "indices_u32.gltf": lambda: indices(UINT),
    "non_indexed.gltf": non_indexed,
    "interleaved.gltf": interleaved,
    "hierarchy_trs.gltf": lambda: hierarchy(False),
    "hierarchy_matrix.gltf": lambda: hierarchy(True),
    "camera.gltf": camera,
    "emissive_strength.gltf": emissive_strength,
    "unsupported_features.gltf": unsupported_features,
    "required_lamp.gltf": required_lamp,
}
MALFORMED = {  # file -> (maker, what gltf_check must complain about, reason for cases.json)
    "accessor_out_of_range.gltf": (accessor_out_of_range, "runs past its bufferView",
                                   "accessor reads past the end of its bufferView"),
    "index_out_of_range.gltf": (index_out_of_range, "out of range",
                                "index 4 >= vertex count 4"),
    "nan_positions.gltf": (nan_positions, "non-finite POSITION", "NaN in POSITION data"),
    "no_triangles.gltf": (no_triangles, "no triangles", "the scene has no triangles"),
    "missing_buffer.gltf": (missing_buffer, "missing buffer",
                            "buffer uri missing_buffer.bin does not exist"),
    "sparse_accessor.gltf": (sparse_accessor, "sparse", "sparse accessor (unsupported)"),
    "required_extension.gltf": (required_extension, "required extension",
                                "extensionsRequired lists KHR_draco_mesh_compression"),
}
WARNINGS = {"unsupported_features.gltf": ["normalTexture", "animations", "skins",
                                          "KHR_lights_punctual", "primitive mode 1 (LINES)"],
            "required_lamp.gltf": ["KHR_lights_punctual"]}
# Valid files that strict loading refuses: file -> (what gltf_check must complain about, reason)
STRICT_ERRORS = {"required_lamp.gltf": ("required extension",
                                        "extensionsRequired lists KHR_lights_punctual")}


def main():
    outcomes = {}
    for name, make in VALID.items():
        doc, extra = make()
        write(name, gltf_text(doc))
        for suffix, content in extra.items():
            if suffix == "":  # expected-values sidecar
                write(name.replace(".gltf", ".expected.json"), json.dumps(content, indent=2) + "\n")
            else:
                write(suffix, content)
    doc, blob = binary()
    # binary.glb should exercise both paddings: the JSON chunk's spaces, the BIN chunk's zeros.
    assert len(json.dumps(doc, separators=(",", ":"))) % 4 and len(blob) % 4
    write("binary.glb", glb_bytes(doc, blob))
    for name, (make, _, _) in MALFORMED.items():
        write(name, gltf_text(make()[0]))
    good = gltf_text(quad_doc().finish())
    write("bad_json.gltf", good[:len(good) // 2])  # truncated mid-document

    # Read everything back, the way the C++ loader does by default (not strict).
    for name in list(VALID) + ["binary.glb"]:
        scene = read_scene(os.path.join(HERE, name), strict=False)
        count = sum(p["count"] for p in scene["parts"])
        outcomes[name] = {"triangles": count}
        if name in WARNINGS:
            outcomes[name]["warnings"] = WARNINGS[name]
        print("%-28s ok     %d triangle%s%s" % (name, count, "s" * (count != 1),
              "  (skipped: %s)" % ", ".join(sorted(scene["skipped"])) if scene["skipped"] else ""))
        if name.startswith("hierarchy_"):
            with open(os.path.join(HERE, name.replace(".gltf", ".expected.json"))) as f:
                expected = json.load(f)["positions"]
            got = scene["parts"][0]["triangles"][0]
            worst = max(abs(a - b) for p, q in zip(got, expected) for a, b in zip(p, q))
            print("    world positions %s (max error %.1e)" % (
                " ".join("(%g %g %g)" % p for p in got), worst))
            if worst > 1e-9:
                raise SystemExit("%s: world positions differ from the expected ones" % name)
    for name, (message, reason) in STRICT_ERRORS.items():
        try:
            read_scene(os.path.join(HERE, name), strict=True)
        except GltfError as e:
            if message not in str(e):
                raise SystemExit("%s failed strict loading for the wrong reason: %s" % (name, e))
            print("%-28s strict fails  %s" % (name, e))
            outcomes[name]["strict"] = {"error": reason}
        else:
            raise SystemExit("%s loaded strictly but should not have" % name)
    failing = [(n, m, r) for n, (_, m, r) in MALFORMED.items()]
    for name, message, reason in failing + [("bad_json.gltf", "bad JSON", "truncated JSON")]:
        try:
            read_scene(os.path.join(HERE, name), strict=False)
        except GltfError as e:
            if message not in str(e):
                raise SystemExit("%s failed for the wrong reason: %s" % (name, e))
            print("%-28s fails  %s" % (name, e))
            outcomes[name] = {"error": reason}
        else:
            raise SystemExit("%s loaded but should not have" % name)
    outcomes = {k: outcomes[k] for k in sorted(outcomes)}
    write("cases.json", json.dumps(outcomes, indent=2) + "\n")


if __name__ == "__main__":
    main()
