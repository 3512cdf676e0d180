"""GltfBuilder: assembles a glTF document from meshes, materials, textures and a camera, with
float32 positions / texcoords and uint32 indices packed into ONE buffer (embedded as a base64
data URI unless an external .bin is asked for). Deterministic: the same calls give the same
bytes."""

from gltf_io import (ARRAY_BUFFER, ELEMENT_ARRAY_BUFFER, EMISSIVE_STRENGTH, FLOAT, REPEAT,
                     UNSIGNED_INT, data_uri, f32_json, pack)
from vectors import look_rotation

GENERATOR = "Pathway scenes/generate.py"


def emission_to_gltf(radiance):
    """emissiveFactor must stay in [0, 1]; anything brighter moves into the emissive strength."""
    peak = max(radiance)
    if peak <= 1.0:
        return [float(c) for c in radiance], None
    return [c / peak for c in radiance], float(peak)


class GltfBuilder:
    def __init__(self):
        self.blob = bytearray()
        self.lists = {k: [] for k in ("nodes", "cameras", "meshes", "materials", "textures",
                                      "images", "samplers", "accessors", "bufferViews")}
        self.scene_nodes = []
        self.extensions_used = set()

    def _append(self, kind, item):
        self.lists[kind].append(item)
        return len(self.lists[kind]) - 1

    def _buffer_view(self, payload, target):
        while len(self.blob) % 4:  # float32 / uint32 data must be 4-byte aligned
            self.blob.append(0)
        view = {"buffer": 0, "byteOffset": len(self.blob), "byteLength": len(payload),
                "target": target}
        self.blob.extend(payload)
        return self._append("bufferViews", view)

    def _accessor(self, payload, target, component_type, count, kind, bounds=None):
        accessor = {"bufferView": self._buffer_view(payload, target),
                    "componentType": component_type, "count": count, "type": kind}
        if bounds is not None:
            accessor["min"], accessor["max"] = bounds
        return self._append("accessors", accessor)

    def material(self, name, base_color, emission=(0.0, 0.0, 0.0), double_sided=False,
                 texture=None):
        pbr = {"baseColorFactor": [float(c) for c in base_color] + [1.0],
               "metallicFactor": 0.0, "roughnessFactor": 1.0}
        if texture is not None:
            pbr["baseColorTexture"] = {"index": texture}
        mat = {"name": name, "pbrMetallicRoughness": pbr}
        if max(emission) > 0.0:
            factor, strength = emission_to_gltf(emission)
            mat["emissiveFactor"] = factor
            if strength is not None:
                mat["extensions"] = {EMISSIVE_STRENGTH: {"emissiveStrength": strength}}
                self.extensions_used.add(EMISSIVE_STRENGTH)
        if double_sided:
            mat["doubleSided"] = True
        return self._append("materials", mat)

    def png_texture(self, name, png):
        image = self._append("images", {"name": name, "uri": data_uri("image/png", png)})
        sampler = self._append("samplers", {"wrapS": REPEAT, "wrapT": REPEAT})
        return self._append("textures", {"sampler": sampler, "source": image})

    def mesh(self, name, positions, triangles, material, texcoords=None):
        """positions: [(x, y, z)], triangles: [(i, j, k)] counter-clockwise from the front,
        texcoords: [(u, v)] or None."""
        bounds = ([f32_json(min(p[i] for p in positions)) for i in range(3)],
                  [f32_json(max(p[i] for p in positions)) for i in range(3)])
        uv = None if texcoords is None else pack("f", [c for t in texcoords for c in t])
        return self.packed_mesh(name, pack("f", [c for p in positions for c in p]), bounds,
                                pack("I", [i for t in triangles for i in t]), material, uv)

    def packed_mesh(self, name, position_bytes, bounds, index_bytes, material,
                    texcoord_bytes=None):
        """A mesh (and its node) from packed little-endian float32 xyz positions, their
        ([min], [max]) bounds, uint32 triangle indices and optional float32 uv pairs."""
        count = len(position_bytes) // 12
        attributes = {"POSITION": self._accessor(position_bytes, ARRAY_BUFFER, FLOAT, count,
                                                 "VEC3", bounds)}
        if texcoord_bytes is not None:
            attributes["TEXCOORD_0"] = self._accessor(texcoord_bytes, ARRAY_BUFFER, FLOAT, count,
                                                      "VEC2")
        indices = self._accessor(index_bytes, ELEMENT_ARRAY_BUFFER, UNSIGNED_INT,
                                 len(index_bytes) // 4, "SCALAR")
        mesh = self._append("meshes", {"name": name, "primitives": [
            {"attributes": attributes, "indices": indices, "material": material}]})
        node = self._append("nodes", {"name": name, "mesh": mesh})
        self.scene_nodes.append(node)
        return node

    def camera(self, position, direction, yfov, aspect_ratio=1.0, znear=0.01):
        cam = self._append("cameras", {"name": "camera", "type": "perspective", "perspective": {
            "yfov": yfov, "aspectRatio": aspect_ratio, "znear": znear}})
        node = self._append("nodes", {"name": "camera", "camera": cam,
                                      "translation": [float(c) for c in position],
                                      "rotation": list(look_rotation(direction))})
        self.scene_nodes.append(node)
        return node

    def build(self, background=None, buffer_uri=None):
        """The glTF dict; the buffer is embedded unless buffer_uri names an external file
        (whose bytes are then self.blob)."""
        doc = {"asset": {"version": "2.0", "generator": GENERATOR}}
        if self.extensions_used:
            doc["extensionsUsed"] = sorted(self.extensions_used)
        scene = {"nodes": list(self.scene_nodes)}
        if background is not None:
            scene["extras"] = {"pathway_background": [float(c) for c in background]}
        doc["scene"] = 0
        doc["scenes"] = [scene]
        for kind, items in self.lists.items():
            if items:
                doc[kind] = items
        uri = buffer_uri or data_uri("application/octet-stream", bytes(self.blob))
        doc["buffers"] = [{"byteLength": len(self.blob), "uri": uri}]
        return doc
