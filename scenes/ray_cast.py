"""A tiny ray caster over a flattened scene (gltf_check.read_scene), to see what the camera
looks at: which mesh each primary ray hits first, and on which side."""

import math

from vectors import add, centroid, cross, dot, normalize, scale, sub, transform_point, \
    transform_vector


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


def grid_hits(scene, n=9):
    """(name or None, front) of the first hit of each ray of an n x n grid over the film."""
    for j in range(n):
        for i in range(n):
            sx, sy = -1.0 + (2 * i + 1.0) / n, 1.0 - (2 * j + 1.0) / n
            yield trace(scene, *camera_ray(scene["camera"], sx, sy))


def camera_coverage(scene, n=9):
    """Traces an n x n grid of primary rays; returns {mesh name or 'background': count} and the
    number of back-face hits."""
    counts, back = {}, 0
    for name, front in grid_hits(scene, n):
        counts[name or "background"] = counts.get(name or "background", 0) + 1
        back += (front is False)
    return counts, back


def back_face_parts(scene, n=9):
    """Names of the parts whose back faces the n x n grid of camera rays hits."""
    return {name for name, front in grid_hits(scene, n) if front is False}


def trace_to_part(scene, part_name):
    """(name, front) of the first hit along the ray from the camera to a part's centroid."""
    eye = transform_point(scene["camera"][0], (0.0, 0.0, 0.0))
    part = next(p for p in scene["parts"] if p["name"] == part_name)
    target = centroid([p for t in part["triangles"] for p in t])
    return trace(scene, eye, normalize(sub(target, eye)))
