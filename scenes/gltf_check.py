"""Reads a glTF 2.0 file back the way a loader would and checks it (Python 3 stdlib only).

Used by scenes/generate.py and tests/data/gltf/make_cases.py to validate what they write:
buffers decode (data URI, external file or GLB BIN chunk), every bufferView and accessor stays
inside its data, POSITION min/max match the float32 data, indices are in range, positions are
finite, the scene has triangles. read_scene() flattens the node hierarchy into world-space
triangles; camera_coverage() traces a grid of primary rays through the first camera with a
tiny ray caster, to see what the camera looks at.

    python3 scenes/gltf_check.py FILE...
"""

import base64
import json
import math
import os
import struct
import sys
from array import array

EMISSIVE_STRENGTH = "KHR_materials_emissive_strength"


def sub(a, b):
    return (a[0] - b[0], a[1] - b[1], a[2] - b[2])


def add(a, b):
    return (a[0] + b[0], a[1] + b[1], a[2] + b[2])


def scale(a, s):
    return (a[0] * s, a[1] * s, a[2] * s)


def dot(a, b):
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]


def cross(a, b):
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def normalize(a):
    return scale(a, 1.0 / math.sqrt(dot(a, a)))


def centroid(points):
    n = float(len(points))
    return (sum(p[0] for p in points) / n, sum(p[1] for p in points) / n,
            sum(p[2] for p in points) / n)


def f32(x):
    return struct.unpack("<f", struct.pack("<f", x))[0]


class GltfError(Exception):
    pass


COMPONENTS = {5120: ("b", 1), 5121: ("B", 1), 5122: ("h", 2), 5123: ("H", 2), 5125: ("I", 4),
              5126: ("f", 4)}
TYPE_SIZES = {"SCALAR": 1, "VEC2": 2, "VEC3": 3, "VEC4": 4, "MAT2": 4, "MAT3": 9, "MAT4": 16}
SUPPORTED_REQUIRED = {EMISSIVE_STRENGTH}
# A required extension the C++ loader ignores unless strict: Blender requires it for any lamp.
LAMPS = "KHR_lights_punctual"


def load_gltf(path, strict=True):
    """Returns (doc, [buffer bytes]) for a .gltf or .glb file. strict=False accepts a required
    KHR_lights_punctual, as the C++ loader does by default."""
    with open(path, "rb") as f:
        raw = f.read()
    bin_chunk = None
    if raw[:4] == b"glTF":
        _, version, length = struct.unpack_from("<4sII", raw, 0)
        if version != 2 or length != len(raw):
            raise GltfError("bad GLB header")
        json_len, json_type = struct.unpack_from("<II", raw, 12)
        if json_type != 0x4E4F534A or json_len % 4:
            raise GltfError("bad GLB JSON chunk")
        text = raw[20:20 + json_len]
        offset = 20 + json_len
        if offset < len(raw):
            bin_len, bin_type = struct.unpack_from("<II", raw, offset)
            if bin_type != 0x004E4942 or bin_len % 4 or offset + 8 + bin_len != len(raw):
                raise GltfError("bad GLB BIN chunk")
            bin_chunk = raw[offset + 8:offset + 8 + bin_len]
    else:
        text = raw
    try:
        doc = json.loads(text.decode("utf-8"))
    except ValueError as e:
        raise GltfError("bad JSON: %s" % e)
    if doc.get("asset", {}).get("version") != "2.0":
        raise GltfError("asset.version is not 2.0")
    lacking = set(doc.get("extensionsRequired", [])) - SUPPORTED_REQUIRED
    if not strict:
        lacking.discard(LAMPS)
    if lacking:
        raise GltfError("required extension not supported: %s" % ", ".join(sorted(lacking)))
    buffers = []
    for i, buf in enumerate(doc.get("buffers", [])):
        uri = buf.get("uri")
        if uri is None:
            if bin_chunk is None or i != 0:
                raise GltfError("buffer %d has no uri and no GLB BIN chunk" % i)
            data = bin_chunk
        elif uri.startswith("data:"):
            data = base64.b64decode(uri.split(",", 1)[1], validate=True)
        else:
            file = os.path.join(os.path.dirname(path), uri)
            if not os.path.isfile(file):
                raise GltfError("missing buffer file %s" % uri)
            with open(file, "rb") as f:
                data = f.read()
        if len(data) < buf["byteLength"]:
            raise GltfError("buffer %d holds %d bytes, byteLength says %d"
                            % (i, len(data), buf["byteLength"]))
        buffers.append(data)
    return doc, buffers


def read_accessor(doc, buffers, index):
    """Returns the accessor's elements as a list of tuples, checking every range."""
    acc = doc["accessors"][index]
    if "sparse" in acc:
        raise GltfError("accessor %d is sparse (not supported)" % index)
    code, size = COMPONENTS[acc["componentType"]]
    n = TYPE_SIZES[acc["type"]]
    count = acc["count"]
    view = doc["bufferViews"][acc["bufferView"]]
    buf = buffers[view["buffer"]]
    view_start = view.get("byteOffset", 0)
    if view_start + view["byteLength"] > len(buf):
        raise GltfError("bufferView %d runs past its buffer" % acc["bufferView"])
    stride = view.get("byteStride", size * n)
    start = acc.get("byteOffset", 0)
    if stride < size * n or (start + (view_start % size)) % size:
        raise GltfError("accessor %d has a bad stride or alignment" % index)
    if count and start + stride * (count - 1) + size * n > view["byteLength"]:
        raise GltfError("accessor %d (count %d) runs past its bufferView" % (index, count))
    begin = view_start + start
    if stride == size * n:  # tightly packed: decode in one go
        values = array(code, buf[begin:begin + stride * count])
        assert values.itemsize == size
        if sys.byteorder == "big":
            values.byteswap()
        return [tuple(values[k:k + n]) for k in range(0, n * count, n)]
    fmt = "<%d%s" % (n, code)
    return [struct.unpack_from(fmt, buf, begin + stride * k) for k in range(count)]


def mat_mul(a, b):
    return [[sum(a[r][k] * b[k][c] for k in range(4)) for c in range(4)] for r in range(4)]


def node_matrix(node):
    """The node's local 4x4 matrix (row-major nested lists)."""
    if "matrix" in node:
        m = node["matrix"]  # column-major
        return [[m[c * 4 + r] for c in range(4)] for r in range(4)]
    tx, ty, tz = node.get("translation", (0.0, 0.0, 0.0))
    qx, qy, qz, qw = node.get("rotation", (0.0, 0.0, 0.0, 1.0))
    sx, sy, sz = node.get("scale", (1.0, 1.0, 1.0))
    rot = [[1 - 2 * (qy * qy + qz * qz), 2 * (qx * qy - qz * qw), 2 * (qx * qz + qy * qw)],
           [2 * (qx * qy + qz * qw), 1 - 2 * (qx * qx + qz * qz), 2 * (qy * qz - qx * qw)],
           [2 * (qx * qz - qy * qw), 2 * (qy * qz + qx * qw), 1 - 2 * (qx * qx + qy * qy)]]
    t = (tx, ty, tz)
    return [[rot[r][0] * sx, rot[r][1] * sy, rot[r][2] * sz, t[r]] for r in range(3)] + [
        [0.0, 0.0, 0.0, 1.0]]


def transform_point(m, p):
    return tuple(m[r][0] * p[0] + m[r][1] * p[1] + m[r][2] * p[2] + m[r][3] for r in range(3))


def transform_vector(m, v):
    return tuple(m[r][0] * v[0] + m[r][1] * v[1] + m[r][2] * v[2] for r in range(3))


def read_scene(path, strict=True):
    """Flattens the default scene: returns a dict with world-space triangles per mesh instance,
    the first camera (depth-first), the background and the features a Lambertian renderer
    would have to skip. Raises GltfError for anything malformed. strict: as for load_gltf."""
    doc, buffers = load_gltf(path, strict)
    scene = doc["scenes"][doc.get("scene", 0)]
    out = {"doc": doc, "parts": [], "camera": None, "skipped": set(),
           "background": scene.get("extras", {}).get("pathway_background", [0.0, 0.0, 0.0])}

    def visit(index, parent):
        node = doc["nodes"][index]
        world = mat_mul(parent, node_matrix(node))
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
        for child in node.get("children", []):
            visit(child, world)

    identity = [[1.0 if r == c else 0.0 for c in range(4)] for r in range(4)]
    for root in scene.get("nodes", []):
        visit(root, identity)
    if not any(part["count"] for part in out["parts"]):
        raise GltfError("the scene has no triangles")
    return out


def camera_ray(camera, sx, sy):
    """Primary ray through normalized film coordinates sx, sy in [-1, 1] (+sy is up)."""
    world, persp = camera
    origin = transform_point(world, (0.0, 0.0, 0.0))
    right = normalize(transform_vector(world, (1.0, 0.0, 0.0)))
    up = normalize(transform_vector(world, (0.0, 1.0, 0.0)))
    forward = normalize(transform_vector(world, (0.0, 0.0, -1.0)))
    h = math.tan(0.5 * persp["yfov"])
    w = h * persp.get("aspectRatio", 1.0)
    return origin, normalize(add(forward, add(scale(right, sx * w), scale(up, sy * h))))


def intersect(origin, direction, tri):
    """Moller-Trumbore; returns (t, front_face) or None."""
    e1, e2 = sub(tri[1], tri[0]), sub(tri[2], tri[0])
    pv = cross(direction, e2)
    det = dot(e1, pv)
    if abs(det) < 1e-20:
        return None
    inv = 1.0 / det
    tv = sub(origin, tri[0])
    u = dot(tv, pv) * inv
    if u < 0.0 or u > 1.0:
        return None
    qv = cross(tv, e1)
    v = dot(direction, qv) * inv
    if v < 0.0 or u + v > 1.0:
        return None
    t = dot(e2, qv) * inv
    if t <= 0.0:
        return None
    return t, dot(cross(e1, e2), direction) < 0.0


def trace(scene, origin, direction):
    """Name of the closest mesh hit and whether its front face was hit; (None, None) on a miss."""
    best = (math.inf, None, None)
    for part in scene["parts"]:
        for tri in part["triangles"]:
            hit = intersect(origin, direction, tri)
            if hit and hit[0] < best[0]:
                best = (hit[0], part["name"], hit[1])
    return best[1], best[2]


def camera_coverage(scene, n=9):
    """Traces an n x n grid of primary rays; returns {mesh name or 'background': count} and the
    number of back-face hits."""
    counts, back = {}, 0
    for j in range(n):
        for i in range(n):
            sx, sy = -1.0 + (2 * i + 1.0) / n, 1.0 - (2 * j + 1.0) / n
            name, front = trace(scene, *camera_ray(scene["camera"], sx, sy))
            counts[name or "background"] = counts.get(name or "background", 0) + 1
            back += (front is False)
    return counts, back


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
