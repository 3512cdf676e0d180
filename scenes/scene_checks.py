"""What each committed scene must look like from its camera, beyond gltf_check's generic
checks: the Cornell box's walls face into the room and project to the right halves of the
image, the camera sees the meshes its scene is about (and back faces only where intended), and
small emitters face the camera as designed."""

import math
import os

from gltf_builder import GENERATOR
from gltf_check import check_gltf
from gltf_io import GltfError
from ray_cast import back_face_parts, trace_to_part
from scene_catalog import CORNELL_BOX_CENTER_MM
from vectors import centroid, cross, dot, normalize, scale, sub, transform_point, \
    transform_vector


def check_cornell(scene):
    """Prints per-wall normals and checks: walls face into the box, blocks outward, light down,
    and the red wall projects to the left half of the image, the green one to the right."""
    centre = scale(CORNELL_BOX_CENTER_MM, 0.001)
    print("  cornell_box normals (unit, per triangle) and facing:")
    for part in scene["parts"]:
        name = part["name"]
        tris = part["triangles"]
        block_centre = centroid([p for t in tris for p in t])
        ok = True
        normals = []
        for t in tris:
            nrm = normalize(cross(sub(t[1], t[0]), sub(t[2], t[0])))
            normals.append(nrm)
            c = centroid(t)
            if name == "light":
                ok &= nrm[1] < -0.999
            elif name.endswith("_block"):
                ok &= dot(nrm, sub(c, block_centre)) > 0.0
            else:
                ok &= dot(nrm, sub(centre, c)) > 0.0
        facing = {"light": "down", "short_block": "outward", "tall_block": "outward"}.get(
            name, "into the box")
        shown = normals if len(normals) <= 2 else normals[::2]
        print("    %-17s %s  %s: %s" % (name, " ".join("(%+.4f %+.4f %+.4f)" % n for n in shown),
                                        facing, "ok" if ok else "WRONG"))
        if not ok:
            raise GltfError("cornell_box: %s faces the wrong way" % name)
    # Projection: image x of a point = dot(d, right) / dot(d, forward) / tan(yfov / 2).
    world, persp = scene["camera"]
    eye = transform_point(world, (0.0, 0.0, 0.0))
    right = transform_vector(world, (1.0, 0.0, 0.0))
    forward = transform_vector(world, (0.0, 0.0, -1.0))
    for name, expect in (("left_wall_red", "left"), ("right_wall_green", "right")):
        part = next(p for p in scene["parts"] if p["name"] == name)
        d = sub(centroid([p for t in part["triangles"] for p in t]), eye)
        x = dot(d, right) / dot(d, forward) / math.tan(0.5 * persp["yfov"])
        side = "left" if x < 0.0 else "right"
        print("    %-17s centre projects to image x = %+.3f (%s half)" % (name, x, side))
        if side != expect:
            raise GltfError("cornell_box: %s appears on the %s" % (name, side))


def check_expectations(name, scene):
    """Scene-specific checks on what the camera sees."""
    counts = scene.get("coverage", {})
    seen = set(counts)
    back_ok = {"grading_lights.gltf": {"back_light"},  # seen from behind
               "light_near_floor.gltf": {"light"}}.get(name, set())
    if scene.get("back_hits"):
        backs = back_face_parts(scene)
        if not backs <= back_ok:
            raise GltfError("%s: the camera sees back faces of %s" % (name, backs - back_ok))
        print("    %s: back faces seen (intended): %s" % (name, ", ".join(sorted(backs))))
    needs = {  # mesh names the 9x9 camera rays may hit; None = anything
        "furnace_closed.gltf": {"furnace_walls"},
        "open_plane.gltf": {"plane"},
        "ceiling.gltf": {"floor"},
        "wall.gltf": {"floor", "wall"},
        "corner.gltf": {"floor", "wall_x0", "wall_z0"},
        "small_light.gltf": {"floor"},
        "white_furnace.gltf": {"sphere", "background"},
        "textured_quad.gltf": {"quad", "background"},
        "grading_stripes.gltf": {"stripes_white", "stripes_dark"},
    }.get(name)
    if needs is not None and not seen <= needs:
        raise GltfError("%s: camera rays hit %s, expected only %s" % (name, seen, needs))
    must = {"wall.gltf": {"floor", "wall"}, "corner.gltf": {"floor", "wall_x0", "wall_z0"},
            "white_furnace.gltf": {"sphere", "background"}, "textured_quad.gltf": {"quad"},
            "light_touching_wall.gltf": {"light", "back_wall"},
            "light_near_floor.gltf": {"floor"},
            "grading_edges.gltf": {"background", "star_dark", "star_white", "star_red",
                                   "star_blue", "bars_white", "bars_yellow", "stripes_white",
                                   "stripes_dark", "stripes_green", "sphere"},
            "grading_lights.gltf": {"background", "floor", "back_wall", "left_wall",
                                    "green_block", "grey_block"},
            "cornell_box.gltf": {"left_wall_red", "right_wall_green", "short_block",
                                 "tall_block", "floor", "ceiling", "back_wall"}}.get(name, set())
    if not must <= seen:
        raise GltfError("%s: camera rays miss %s" % (name, must - seen))
    # Small parts the 9x9 grid may miss: the ray from the eye to the part's centroid must hit
    # that part first, on the side given (True: front, False: back).
    centroids = {
        "grading_edges.gltf": {"emitter": True, "sliver": True, "wedge": True},
        "grading_lights.gltf": {"small_light": True, "wall_light": True, "back_light": False},
        "light_near_floor.gltf": {"light": False},
    }.get(name, {})
    for part_name, front in sorted(centroids.items()):
        hit, hit_front = trace_to_part(scene, part_name)
        if hit != part_name or hit_front != front:
            raise GltfError("%s: the ray to %s's centroid hits %s (%s face)"
                            % (name, part_name, hit, "front" if hit_front else "back"))


def check_scene_file(path):
    """Every check a committed scene gets: gltf_check's, that generate.py wrote it, and what its
    camera must see. Raises GltfError naming the first problem."""
    name = os.path.basename(path)
    scene = check_gltf(path, generator=GENERATOR)
    check_expectations(name, scene)
    if name == "cornell_box.gltf":
        check_cornell(scene)
