"""3-vectors, quaternions and 4x4 matrices as plain tuples and lists (Python 3 stdlib only).

Vectors are (x, y, z) tuples; quaternions are (x, y, z, w) as in glTF; matrices are row-major
nested lists, applied to column vectors.
"""

import math


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


def tidy(x):
    """Flushes rounding dust (cos(pi/2) = 6e-17) to zero so the JSON stays readable."""
    return 0.0 if abs(x) < 1e-12 else x


def rotate_y(v, angle):
    """v turned by `angle` radians about +Y (right-handed: +Z goes towards +X)."""
    c, s = math.cos(angle), math.sin(angle)
    return (c * v[0] + s * v[2], v[1], -s * v[0] + c * v[2])


def rotate_z(v, angle):
    """v turned by `angle` radians about +Z (+X goes towards +Y)."""
    c, s = math.cos(angle), math.sin(angle)
    return (c * v[0] - s * v[1], s * v[0] + c * v[1], v[2])


def quat_axis_angle(axis, angle):
    s = math.sin(0.5 * angle)
    return (axis[0] * s, axis[1] * s, axis[2] * s, math.cos(0.5 * angle))


def quat_mul(a, b):
    ax, ay, az, aw = a
    bx, by, bz, bw = b
    return (aw * bx + ax * bw + ay * bz - az * by,
            aw * by - ax * bz + ay * bw + az * bx,
            aw * bz + ax * by - ay * bx + az * bw,
            aw * bw - ax * bx - ay * by - az * bz)


def quat_matrix(q):
    """The 3x3 rotation of the unit quaternion q."""
    qx, qy, qz, qw = q
    return [[1 - 2 * (qy * qy + qz * qz), 2 * (qx * qy - qz * qw), 2 * (qx * qz + qy * qw)],
            [2 * (qx * qy + qz * qw), 1 - 2 * (qx * qx + qz * qz), 2 * (qy * qz - qx * qw)],
            [2 * (qx * qz - qy * qw), 2 * (qy * qz + qx * qw), 1 - 2 * (qx * qx + qy * qy)]]


def look_rotation(direction):
    """Quaternion turning the camera's local -Z onto `direction`, keeping the horizon level
    (a yaw about world Y applied after a pitch about local X)."""
    dx, dy, dz = normalize(direction)
    yaw = math.atan2(-dx + 0.0, -dz)  # + 0.0 turns -0.0 into 0.0: straight +z is +180 deg
    pitch = math.atan2(dy, math.hypot(dx, dz))
    q = quat_mul(quat_axis_angle((0.0, 1.0, 0.0), yaw), quat_axis_angle((1.0, 0.0, 0.0), pitch))
    return tuple(tidy(c) for c in q)


IDENTITY = [[1.0 if r == c else 0.0 for c in range(4)] for r in range(4)]


def mat_mul(a, b):
    return [[sum(a[r][k] * b[k][c] for k in range(4)) for c in range(4)] for r in range(4)]


def transform_point(m, p):
    return tuple(m[r][0] * p[0] + m[r][1] * p[1] + m[r][2] * p[2] + m[r][3] for r in range(3))


def transform_vector(m, v):
    return tuple(m[r][0] * v[0] + m[r][1] * v[1] + m[r][2] * v[2] for r in range(3))
