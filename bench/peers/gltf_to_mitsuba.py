"""The scene Pathway renders from a glTF 2.0 file, as a Mitsuba 3 scene built in memory.

Pathway's model is small: triangles in world space, a Lambertian albedo (baseColorFactor), an
emission (emissiveFactor x KHR_materials_emissive_strength) that is one-sided unless the material
is doubleSided, a pinhole camera and a constant background. This module reads exactly that from
a .gltf (external .bin or data-URI buffers) or .glb file with scenes/gltf_io.py, the project's
glTF reader, into numpy arrays (`read_gltf`), and turns
it into a Mitsuba scene dict (`mitsuba_scene`) whose meshes are `mi.Mesh` objects filled from
numpy buffers. Whatever Mitsuba could not render the way Pathway does (textures, double-sided
emitters, sparse accessors, required extensions) is refused with a message naming it; what
Pathway itself ignores (lamps, non-triangle primitives, metallic factors, vertex colours) is
ignored here too, with a warning, so that both renderers see the same scene.

    python gltf_to_mitsuba.py scene.gltf   # prints what was read (needs numpy only)
"""
import math
import pathlib
import sys
from dataclasses import dataclass, field

import numpy as np

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parents[2] / "scenes"))
from gltf_io import (EMISSIVE_STRENGTH, FLOAT, LAMPS, GltfError, accessor_array,  # noqa: E402
                     default_scene, load_gltf, walk_nodes)


class SceneError(Exception):
    """The file cannot be read, or holds something this converter cannot represent."""


@dataclass
class Material:
    name: str
    albedo: tuple  # linear RGB, baseColorFactor
    emission: tuple  # linear RGB radiance, emissiveFactor x emissiveStrength
    double_sided: bool

    @property
    def emissive(self):
        return max(self.emission) > 0.0


@dataclass
class Primitive:
    name: str
    positions: np.ndarray  # (n, 3) float32, world space
    faces: np.ndarray  # (m, 3) uint32
    material: Material


@dataclass
class Camera:
    position: np.ndarray
    forward: np.ndarray  # unit
    up: np.ndarray  # unit, orthogonal to forward
    yfov: float  # radians


@dataclass
class GltfScene:
    path: str
    primitives: list
    camera: Camera
    background: tuple
    warnings: list = field(default_factory=list)


# -------------------------------------------------------------------------------- file reading

def _accessor(document, buffers, index, what):
    """Accessor `index` as a (count, width) numpy array (byteStride honoured by gltf_io)."""
    try:
        values, width = accessor_array(document, buffers, index)
    except GltfError as error:
        raise SceneError(f"{what}: {error}") from error
    return np.frombuffer(values, dtype=values.typecode).reshape(-1, width)


def _material(document, index, warn):
    if index is None:  # glTF's default material: white, not emissive, one-sided
        return Material("default", (1.0, 1.0, 1.0), (0.0, 0.0, 0.0), False)
    m = document["materials"][index]
    name = m.get("name", f"material {index}")
    pbr = m.get("pbrMetallicRoughness", {})
    for texture in ("baseColorTexture",):
        if texture in pbr:
            raise SceneError(f"material {name!r} has a {texture}: Mitsuba's scene here is built "
                             "from factors only (textures are not converted)")
    if "emissiveTexture" in m:
        raise SceneError(f"material {name!r} has an emissiveTexture, which cannot be converted")
    if pbr.get("metallicFactor", 1.0) != 0.0:
        warn("metallicFactor", "ignoring metallicFactor (Pathway's materials are Lambertian)")
    albedo = tuple(float(v) for v in pbr.get("baseColorFactor", [1, 1, 1, 1])[:3])
    strength = m.get("extensions", {}).get(EMISSIVE_STRENGTH, {})
    scale = float(strength.get("emissiveStrength", 1.0))
    emission = tuple(float(v) * scale for v in m.get("emissiveFactor", [0, 0, 0]))
    material = Material(name, albedo, emission, bool(m.get("doubleSided", False)))
    if material.emissive and material.double_sided:
        # Mitsuba's area emitter emits from the front side only; Pathway's doubleSided emitter
        # emits from both, and a flipped copy of the triangles would overlap the original.
        raise SceneError(f"material {name!r} is emissive and doubleSided: Mitsuba's area emitter "
                         "is one-sided")
    return material


def _default_camera(primitives):
    """Pathway's framing without a camera: 45 degrees, from +Z, the bounding sphere fits."""
    points = np.concatenate([p.positions for p in primitives])
    lo, hi = points.min(axis=0), points.max(axis=0)
    center, radius = (lo + hi) / 2, max(0.5 * float(np.linalg.norm(hi - lo)), 1e-6)
    yfov = math.radians(45.0)
    position = center + np.array([0.0, 0.0, radius / math.sin(0.5 * yfov)])
    return Camera(position, np.array([0.0, 0.0, -1.0]), np.array([0.0, 1.0, 0.0]), yfov)


def read_gltf(path):
    """Pathway's view of a glTF file: world-space triangles, materials, camera, background."""
    path = pathlib.Path(path)
    try:
        return _read_gltf(path)
    except SceneError as error:  # every message names the file
        if str(error).startswith(str(path)):
            raise
        raise SceneError(f"{path}: {error}") from error
    except (KeyError, IndexError, TypeError, ValueError) as error:
        raise SceneError(f"{path}: malformed glTF ({type(error).__name__}: {error})") from error


def _read_gltf(path):
    try:
        document, buffers = load_gltf(str(path), strict=False)  # lamps: warned about below
    except (OSError, GltfError) as error:
        raise SceneError(f"{path}: cannot read: {error}") from error
    warnings = {}

    def warn(key, message):
        warnings.setdefault(key, f"{path}: {message}")

    if LAMPS in document.get("extensionsRequired", []) or LAMPS in document.get("extensions", {}):
        warn(LAMPS, "ignoring KHR_lights_punctual lamps, as Pathway does (emissive meshes only)")

    materials, primitives, camera = {}, [], None
    for node, world in walk_nodes(document):  # the order Pathway's loader walks
        to_world = np.array(world)
        if "mesh" in node:
            mesh = document["meshes"][node["mesh"]]
            for p, primitive in enumerate(mesh.get("primitives", [])):
                where = f"mesh {mesh.get('name', node['mesh'])!r} primitive {p}"
                if primitive.get("mode", 4) != 4:
                    warn(f"mode {primitive.get('mode')}", f"ignoring {where}: not TRIANGLES")
                    continue
                if primitive.get("targets"):
                    warn("targets", "ignoring morph targets (not supported)")
                if "POSITION" not in primitive.get("attributes", {}):
                    raise SceneError(f"{path}: {where} has no POSITION")
                position = primitive["attributes"]["POSITION"]
                if document["accessors"][position].get("componentType") != FLOAT:
                    raise SceneError(f"{where}: POSITION must be floats")
                local = _accessor(document, buffers, position, where)
                if "indices" in primitive:
                    faces = _accessor(document, buffers, primitive["indices"], where)
                    faces = faces.astype(np.uint32).reshape(-1, 3)
                else:
                    faces = np.arange(len(local) // 3 * 3, dtype=np.uint32).reshape(-1, 3)
                if faces.size and faces.max() >= len(local):
                    raise SceneError(f"{path}: {where} has an index out of range")
                if not len(faces):
                    continue
                # World space as Pathway computes it (double precision, then float). The file's
                # winding is kept even under a mirroring transform, as Pathway keeps it.
                world = local.astype(np.float64) @ to_world[:3, :3].T + to_world[:3, 3]
                if not np.all(np.isfinite(world)):
                    raise SceneError(f"{where} has a non-finite position")
                key = primitive.get("material")
                if key not in materials:
                    materials[key] = _material(document, key, warn)
                primitives.append(Primitive(where, world.astype(np.float32), faces,
                                            materials[key]))
        if "camera" in node and camera is None:
            spec = document["cameras"][node["camera"]]
            if spec.get("type") == "perspective":
                # Pathway keeps the position, -Z as forward and +Y (made orthogonal) as up.
                back = to_world[:3, 2] / np.linalg.norm(to_world[:3, 2])
                up = to_world[:3, 1] - np.dot(to_world[:3, 1], back) * back
                camera = Camera(to_world[:3, 3].copy(), -back, up / np.linalg.norm(up),
                                float(spec["perspective"]["yfov"]))
            else:
                warn("orthographic", "ignoring orthographic cameras (not supported)")

    if not primitives:
        raise SceneError(f"{path}: the scene has no triangles")
    background = tuple(float(v) for v in default_scene(document)[0].get("extras", {}).get(
        "pathway_background", [0.0, 0.0, 0.0]))
    if len(background) != 3 or not all(math.isfinite(v) and v >= 0 for v in background):
        raise SceneError(f"{path}: pathway_background must be 3 finite non-negative numbers")
    return GltfScene(str(path), primitives, camera or _default_camera(primitives), background,
                     list(warnings.values()))


# -------------------------------------------------------------------------------- Mitsuba scene

def _mesh(mi, primitive, index):
    """An mi.Mesh filled from the primitive's numpy buffers, with its BSDF and emitter."""
    m = primitive.material
    props = mi.Properties()
    # Pathway's Lambertian shades both sides (the normal is turned to face the ray); Mitsuba's
    # `diffuse` is black from behind, so it is wrapped in `twosided`.
    props["bsdf"] = mi.load_dict({"type": "twosided", "bsdf": {
        "type": "diffuse", "reflectance": {"type": "rgb", "value": list(m.albedo)}}})
    if m.emissive:
        # One-sided: Mitsuba emits towards the face normal cross(p1 - p0, p2 - p0), the side
        # Pathway calls the front face. sampling_weight = power, as Pathway's light-pick=power.
        p = primitive.positions[primitive.faces.astype(np.int64)]
        area = 0.5 * np.linalg.norm(np.cross(p[:, 1] - p[:, 0], p[:, 2] - p[:, 0]), axis=1).sum()
        props["emitter"] = mi.load_dict({
            "type": "area", "radiance": {"type": "rgb", "value": list(m.emission)},
            "sampling_weight": float(area * sum(m.emission) / 3.0)})
    mesh = mi.Mesh(f"mesh{index}", len(primitive.positions), len(primitive.faces), props=props)
    params = mi.traverse(mesh)
    # The buffers' own array types (dynamic arrays in scalar variants, JIT arrays in llvm ones).
    for key, values in (("vertex_positions", primitive.positions), ("faces", primitive.faces)):
        params[key] = type(params[key])(values.ravel())
    params.update()
    return mesh


def mitsuba_scene(mi, scene, width, height, spp, max_depth, rr_depth):
    """The Mitsuba scene dict for `scene` (from read_gltf), for the variant already set on `mi`.

    `max_depth` and `rr_depth` are Mitsuba's (path integrator) values.
    """
    c = scene.camera
    sensor = {
        "type": "perspective",
        "fov": math.degrees(c.yfov), "fov_axis": "y",  # aspect ratio from the film, as Pathway
        "near_clip": 1e-4,  # Pathway's camera rays start at the eye
        "to_world": mi.ScalarTransform4f().look_at(origin=c.position.tolist(),
                                                 target=(c.position + c.forward).tolist(),
                                                 up=c.up.tolist()),
        "sampler": {"type": "independent", "sample_count": spp},
        "film": {"type": "hdrfilm", "width": width, "height": height, "pixel_format": "rgb",
                 "component_format": "float32", "rfilter": {"type": "box"}},  # radius 0.5 px
    }
    result = {
        "type": "scene",
        "integrator": {"type": "path", "max_depth": max_depth, "rr_depth": rr_depth},
        "sensor": sensor,
    }
    for i, primitive in enumerate(scene.primitives):
        result[f"mesh{i}"] = _mesh(mi, primitive, i)
    if max(scene.background) > 0.0:
        result["background"] = {"type": "constant",
                                "radiance": {"type": "rgb", "value": list(scene.background)}}
    return result


if __name__ == "__main__":
    try:
        s = read_gltf(sys.argv[1] if len(sys.argv) > 1 else "scenes/cornell_box.gltf")
    except SceneError as error:
        sys.exit(f"gltf_to_mitsuba: {error}")
    for w in s.warnings:
        print("warning:", w)
    for p in s.primitives:
        print(f"{p.name}: {len(p.faces)} triangles, albedo {p.material.albedo}, "
              f"emission {p.material.emission}")
    print(f"camera at {s.camera.position}, forward {s.camera.forward}, up {s.camera.up}, "
          f"yfov {math.degrees(s.camera.yfov):.3f} deg; background {s.background}")
