"""Reads and writes glTF 2.0 files (Python 3 stdlib only): the one implementation of the file
format behind Pathway's Python tools (scenes/generate.py, scenes/gltf_check.py,
tests/data/gltf/make_cases.py, bench/peers/gltf_to_mitsuba.py).

Reading: load_gltf() gives the JSON document and its buffers (GLB BIN chunk, base64 data URI or
external file); read_accessor() decodes an accessor, honouring byteStride and checking every
range; walk_nodes() visits the default scene's nodes with their world matrices.
Writing: write_gltf() (indented JSON, the committed scenes' form) and glb_bytes().
"""

import base64
import json
import math
import os
import struct
import sys
from array import array
from urllib.parse import unquote

from vectors import IDENTITY, mat_mul, quat_matrix

# glTF enums
FLOAT, UNSIGNED_INT = 5126, 5125
ARRAY_BUFFER, ELEMENT_ARRAY_BUFFER = 34962, 34963
REPEAT = 10497
GLB_JSON, GLB_BIN = 0x4E4F534A, 0x004E4942

EMISSIVE_STRENGTH = "KHR_materials_emissive_strength"
# A required extension Pathway's loader ignores unless strict: Blender requires it for any lamp.
LAMPS = "KHR_lights_punctual"
SUPPORTED_REQUIRED = {EMISSIVE_STRENGTH}

# componentType -> (array typecode, bytes); accessor type -> components per element
COMPONENTS = {5120: ("b", 1), 5121: ("B", 1), 5122: ("h", 2), 5123: ("H", 2), 5125: ("I", 4),
              5126: ("f", 4)}
TYPE_SIZES = {"SCALAR": 1, "VEC2": 2, "VEC3": 3, "VEC4": 4, "MAT2": 4, "MAT3": 9, "MAT4": 16}


class GltfError(Exception):
    pass


def f32(x):
    return struct.unpack("<f", struct.pack("<f", x))[0]


def f32_json(x):
    """The shortest decimal that reads back as the same float32 (0.5528 rather than
    0.5527999997138977), so min/max match the packed data exactly and stay readable."""
    v = f32(x)
    for digits in range(1, 10):
        s = float("%.*g" % (digits, v))
        if f32(s) == v:
            return s
    return v


def pack(typecode, values):
    """Packs numbers little-endian: 'f' float32, 'I' uint32, 'H' uint16, 'B' uint8."""
    a = array(typecode, values)
    if typecode == "I":
        assert a.itemsize == 4, "array('I') is not 32-bit on this platform"
    if sys.byteorder == "big":
        a.byteswap()
    return a.tobytes()


def data_uri(mime, payload):
    return "data:%s;base64,%s" % (mime, base64.b64encode(payload).decode("ascii"))


# --------------------------------------------------------------------------------------------
# Reading
# --------------------------------------------------------------------------------------------

def split_glb(raw):
    """(JSON text, BIN chunk or None) of a GLB container, checking its header and chunks."""
    _, version, length = struct.unpack_from("<4sII", raw, 0)
    if version != 2 or length != len(raw):
        raise GltfError("bad GLB header")
    json_len, json_type = struct.unpack_from("<II", raw, 12)
    if json_type != GLB_JSON or json_len % 4:
        raise GltfError("bad GLB JSON chunk")
    text = raw[20:20 + json_len]
    offset = 20 + json_len
    if offset == len(raw):
        return text, None
    bin_len, bin_type = struct.unpack_from("<II", raw, offset)
    if bin_type != GLB_BIN or bin_len % 4 or offset + 8 + bin_len != len(raw):
        raise GltfError("bad GLB BIN chunk")
    return text, raw[offset + 8:offset + 8 + bin_len]


def load_gltf(path, strict=True):
    """Returns (doc, [buffer bytes]) for a .gltf or .glb file. strict=False accepts a required
    KHR_lights_punctual, as Pathway's loader does by default."""
    with open(path, "rb") as f:
        raw = f.read()
    text, bin_chunk = split_glb(raw) if raw[:4] == b"glTF" else (raw, None)
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
            file = os.path.join(os.path.dirname(path), unquote(uri))  # URIs are %-encoded
            if not os.path.isfile(file):
                raise GltfError("missing buffer file %s" % uri)
            with open(file, "rb") as f:
                data = f.read()
        if len(data) < buf["byteLength"]:
            raise GltfError("buffer %d holds %d bytes, byteLength says %d"
                            % (i, len(data), buf["byteLength"]))
        buffers.append(data)
    return doc, buffers


def accessor_array(doc, buffers, index):
    """The accessor's elements as one flat array (native byte order) and the number of
    components per element, checking every range."""
    acc = doc["accessors"][index]
    if "sparse" in acc:
        raise GltfError("accessor %d is sparse (not supported)" % index)
    if "bufferView" not in acc:
        raise GltfError("accessor %d has no bufferView" % index)
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
        return values, n
    values = array(code)
    fmt = "<%d%s" % (n, code)
    for k in range(count):
        values.extend(struct.unpack_from(fmt, buf, begin + stride * k))
    return values, n


def read_accessor(doc, buffers, index):
    """The accessor's elements as a list of tuples, checking every range."""
    values, n = accessor_array(doc, buffers, index)
    return [tuple(values[k:k + n]) for k in range(0, len(values), n)]


def node_matrix(node):
    """The node's local 4x4 matrix: its column-major `matrix`, or translation * rotation * scale
    with the rotation normalized, as Pathway's loader does (exporters round unit quaternions)."""
    if "matrix" in node:
        m = node["matrix"]
        return [[m[c * 4 + r] for c in range(4)] for r in range(4)]
    t = node.get("translation", (0.0, 0.0, 0.0))
    q = node.get("rotation", (0.0, 0.0, 0.0, 1.0))
    sx, sy, sz = node.get("scale", (1.0, 1.0, 1.0))
    length = math.sqrt(sum(c * c for c in q))
    if not length > 0.0:
        raise GltfError("node %r: rotation is not a rotation" % node.get("name", ""))
    rot = quat_matrix([c / length for c in q])
    return [[rot[r][0] * sx, rot[r][1] * sy, rot[r][2] * sz, t[r]] for r in range(3)] + [
        [0.0, 0.0, 0.0, 1.0]]


def default_scene(doc):
    """The scene to show and its root nodes; with no scenes, every node that is nobody's child."""
    if doc.get("scenes"):
        scene = doc["scenes"][doc.get("scene", 0)]
        return scene, scene.get("nodes", [])
    nodes = doc.get("nodes", [])
    children = {c for node in nodes for c in node.get("children", [])}
    return {}, [i for i in range(len(nodes)) if i not in children]


def walk_nodes(doc):
    """Yields (node, world matrix) for the default scene, depth first, parents before their
    children: the order Pathway's loader walks, which decides the first camera."""
    def visit(index, parent):
        node = doc["nodes"][index]
        world = mat_mul(parent, node_matrix(node))
        yield node, world
        for child in node.get("children", []):
            yield from visit(child, world)

    for root in default_scene(doc)[1]:
        yield from visit(root, IDENTITY)


# --------------------------------------------------------------------------------------------
# Writing
# --------------------------------------------------------------------------------------------

def gltf_text(doc):
    """The .gltf JSON as committed: indented, no NaN or Infinity, one final newline."""
    return json.dumps(doc, indent=2, allow_nan=False) + "\n"


def write_gltf(path, doc):
    with open(path, "w", encoding="ascii", newline="\n") as f:
        f.write(gltf_text(doc))


def glb_bytes(doc, blob):
    """GLB container: 12-byte header, compact JSON chunk padded with spaces, BIN chunk padded
    with zeros (buffer 0 is the BIN chunk: give it no uri)."""
    text = json.dumps(doc, separators=(",", ":"), allow_nan=False).encode("ascii")
    text += b" " * (-len(text) % 4)
    binary = bytes(blob) + b"\0" * (-len(blob) % 4)
    chunks = (struct.pack("<II", len(text), GLB_JSON) + text
              + struct.pack("<II", len(binary), GLB_BIN) + binary)
    return struct.pack("<4sII", b"glTF", 2, 12 + len(chunks)) + chunks
