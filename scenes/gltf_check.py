"""Reads a glTF 2.0 file back the way a loader would and checks it (Python 3 stdlib only).

Used by scenes/generate.py and tests/data/gltf/make_cases.py to validate what they write:
buffers decode (data URI, external file or GLB BIN chunk), every bufferView and accessor stays
inside its data, POSITION min/max match the float32 data, indices are in range, positions are
finite, the scene has triangles. read_scene() flattens the node hierarchy into world-space
triangles; check_gltf() also traces a grid of primary rays through the first camera
(ray_cast.py), to see what the camera looks at.

    python3 scenes/gltf_check.py FILE...
"""

import math
import os
import sys

from gltf_io import (EMISSIVE_STRENGTH, GltfError, default_scene, f32, load_gltf,
                     read_accessor, walk_nodes)
from ray_cast import camera_coverage
from vectors import transform_point


def read_scene(path, strict=True):
    """Flattens the default scene: returns a dict with world-space triangles per mesh instance,
    the first camera (depth-first), the background and the features a Lambertian renderer
    would have to skip. Raises GltfError for anything malformed. strict: as for load_gltf."""
    doc, buffers = load_gltf(path, strict)
    scene = default_scene(doc)[0]
    out = {"doc": doc, "parts": [], "camera": None, "skipped": set(),
           "background": scene.get("extras", {}).get("pathway_background", [0.0, 0.0, 0.0])}
    for node, world in walk_nodes(doc):
        if "camera" in node and out["camera"] is None:
            cam = doc["cameras"][node["camera"]]
            if cam["type"] == "perspective":
                out["camera"] = (world, cam["perspective"])
        if "mesh" in node:
            mesh = doc["meshes"][node["mesh"]]
            for prim in mesh["primitives"]:
                if prim.get("mode", 4) != 4:
                    out["skipped"].add("primitive mode %d" % prim.get("mode"))
                    continue
                acc_index = prim["attributes"]["POSITION"]
                positions = read_accessor(doc, buffers, acc_index)
                for attribute, other in sorted(prim["attributes"].items()):
                    if len(read_accessor(doc, buffers, other)) != len(positions):
                        raise GltfError("%s and POSITION counts differ" % attribute)
                for p in positions:
                    if not all(math.isfinite(c) for c in p):
                        raise GltfError("non-finite POSITION in mesh %s" % mesh.get("name"))
                acc = doc["accessors"][acc_index]
                for i in range(3):
                    lo = min(p[i] for p in positions)
                    hi = max(p[i] for p in positions)
                    if "min" not in acc or f32(acc["min"][i]) != lo or f32(acc["max"][i]) != hi:
                        raise GltfError("POSITION min/max do not match the data in mesh %s"
                                        % mesh.get("name"))
                if "indices" in prim:
                    idx = [i[0] for i in read_accessor(doc, buffers, prim["indices"])]
                else:
                    idx = list(range(len(positions)))
                if len(idx) % 3:
                    raise GltfError("index count not a multiple of 3")
                if idx and max(idx) >= len(positions):
                    raise GltfError("index %d out of range (%d vertices) in mesh %s"
                                    % (max(idx), len(positions), mesh.get("name")))
                tris = None  # world-space triangles, kept for small meshes only
                if len(idx) <= 3 * 100000:
                    world_pos = [transform_point(world, p) for p in positions]
                    tris = [tuple(world_pos[i] for i in idx[k:k + 3])
                            for k in range(0, len(idx), 3)]
                out["parts"].append({"name": mesh.get("name", "mesh%d" % node["mesh"]),
                                     "material": prim.get("material"), "count": len(idx) // 3,
                                     "triangles": tris})
    if not any(part["count"] for part in out["parts"]):
        raise GltfError("the scene has no triangles")
    return out


def check_gltf(path, coverage=True, generator=None, need_camera=True):
    """Re-reads `path`, checks it (materials too: rgba baseColorFactor, metallic 0, roughness 1,
    emissiveFactor in [0, 1], the emissive-strength extension listed when used; a perspective
    camera unless need_camera is False), prints a summary line and returns the flattened scene.
    With `coverage`, small scenes also get a 9 x 9 grid of camera rays traced."""
    scene = read_scene(path)
    doc = scene["doc"]
    if generator is not None and doc["asset"].get("generator") != generator:
        raise GltfError("asset.generator is not %r" % generator)
    for mat in doc.get("materials", []):
        pbr = mat.get("pbrMetallicRoughness", {})
        if len(pbr.get("baseColorFactor", [])) != 4 or pbr.get("metallicFactor") != 0.0 \
                or pbr.get("roughnessFactor") != 1.0:
            raise GltfError("material %s: expected rgba baseColorFactor, metallic 0, roughness 1"
                            % mat.get("name"))
        if not all(0.0 <= c <= 1.0 for c in mat.get("emissiveFactor", [0.0])):
            raise GltfError("material %s: emissiveFactor outside [0, 1]" % mat.get("name"))
        if EMISSIVE_STRENGTH in mat.get("extensions", {}) \
                and EMISSIVE_STRENGTH not in doc.get("extensionsUsed", []):
            raise GltfError("%s used but not listed in extensionsUsed" % EMISSIVE_STRENGTH)
    if scene["camera"] is None and need_camera:
        raise GltfError("no perspective camera")
    total = sum(p["count"] for p in scene["parts"])
    line = "%-34s %8d triangles" % (os.path.basename(path), total)
    if coverage and total <= 5000 and scene["camera"] is not None:
        counts, back = camera_coverage(scene)
        scene["coverage"], scene["back_hits"] = counts, back
        line += "  camera 9x9: " + ", ".join("%s %d" % kv for kv in sorted(counts.items()))
        if back:
            line += ", BACK FACES %d" % back
    print(line)
    return scene


if __name__ == "__main__":
    status = 0
    for file in sys.argv[1:]:
        try:
            check_gltf(file, need_camera=False)
        except GltfError as e:
            print("%s: error: %s" % (file, e))
            status = 1
    sys.exit(status)
