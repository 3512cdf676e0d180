"""Shapes as (positions, triangles) pairs: vertices as (x, y, z) tuples, triangles as index
triples wound counter-clockwise seen from the front face."""

import math

from vectors import add, normalize, rotate_y, scale, tidy


def quad(p0, p1, p2, p3):
    """A planar-ish quad as (positions, triangles), front face counter-clockwise p0->p1->p2."""
    return [p0, p1, p2, p3], [(0, 1, 2), (0, 2, 3)]


def floor_quad(x0, x1, z0, z1, y=0.0, up=True):
    """Horizontal rectangle at height y, facing +y (up) or -y."""
    a, b, c, d = (x0, y, z0), (x0, y, z1), (x1, y, z1), (x1, y, z0)
    return quad(a, b, c, d) if up else quad(a, d, c, b)


def other_diagonal(part):
    """The same quad split along its other diagonal (vertex order rotated, winding kept)."""
    positions, triangles = part
    return positions[1:] + positions[:1], triangles


def merge(*parts):
    """Concatenates (positions, triangles) pairs into one mesh."""
    positions, triangles = [], []
    for pos, tris in parts:
        base = len(positions)
        positions.extend(pos)
        triangles.extend((a + base, b + base, c + base) for a, b, c in tris)
    return positions, triangles


def icosphere(subdivisions, radius=1.0, center=(0.0, 0.0, 0.0)):
    """Icosahedron subdivided `subdivisions` times (20 * 4^n triangles), faces outward."""
    t = (1.0 + math.sqrt(5.0)) / 2.0
    verts = [normalize(v) for v in [
        (-1, t, 0), (1, t, 0), (-1, -t, 0), (1, -t, 0), (0, -1, t), (0, 1, t),
        (0, -1, -t), (0, 1, -t), (t, 0, -1), (t, 0, 1), (-t, 0, -1), (-t, 0, 1)]]
    faces = [(0, 11, 5), (0, 5, 1), (0, 1, 7), (0, 7, 10), (0, 10, 11), (1, 5, 9), (5, 11, 4),
             (11, 10, 2), (10, 7, 6), (7, 1, 8), (3, 9, 4), (3, 4, 2), (3, 2, 6), (3, 6, 8),
             (3, 8, 9), (4, 9, 5), (2, 4, 11), (6, 2, 10), (8, 6, 7), (9, 8, 1)]
    for _ in range(subdivisions):
        midpoints = {}

        def midpoint(i, j):
            key = (min(i, j), max(i, j))
            if key not in midpoints:
                verts.append(normalize(scale(add(verts[i], verts[j]), 0.5)))
                midpoints[key] = len(verts) - 1
            return midpoints[key]

        new_faces = []
        for a, b, c in faces:
            ab, bc, ca = midpoint(a, b), midpoint(b, c), midpoint(c, a)
            new_faces += [(a, ab, ca), (b, bc, ab), (c, ca, bc), (ab, bc, ca)]
        faces = new_faces
    return [add(center, scale(v, radius)) for v in verts], faces


def panel(center, u, v, s0, s1, t0, t1):
    """The rectangle center + s u + t v, s in [s0, s1], t in [t0, t1], facing along u x v."""
    def at(s, t):
        return tuple(tidy(c) for c in add(center, add(scale(u, s), scale(v, t))))
    return quad(at(s0, t0), at(s1, t0), at(s1, t1), at(s0, t1))


def block(cx, cz, half_x, half_z, height, yaw):
    """An upright box on the floor (y in [0, height]) turned by `yaw` about +Y: its top and four
    sides, facing outward (no bottom: it stands on the floor)."""
    u, w = rotate_y((1.0, 0.0, 0.0), yaw), rotate_y((0.0, 0.0, 1.0), yaw)
    up = (0.0, 1.0, 0.0)
    centre = (cx, 0.0, cz)
    return merge(
        panel(add(centre, (0.0, height, 0.0)), w, u, -half_z, half_z, -half_x, half_x),  # top
        panel(add(centre, scale(w, half_z)), u, up, -half_x, half_x, 0.0, height),        # +w
        panel(add(centre, scale(w, -half_z)), up, u, 0.0, height, -half_x, half_x),       # -w
        panel(add(centre, scale(u, half_x)), up, w, 0.0, height, -half_z, half_z),        # +u
        panel(add(centre, scale(u, -half_x)), w, up, -half_z, half_z, 0.0, height))       # -u
