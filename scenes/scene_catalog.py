"""The committed scenes (SCENES: file name -> function returning the glTF dict) and the grid of
the memory benchmark. Each function's docstring says what the scene tests and, where there is
one, the closed-form answer."""

import math
import sys
from array import array

from gltf_builder import GltfBuilder
from gltf_io import f32_json
from png_encoder import checkerboard_png
from shapes import block, floor_quad, icosphere, merge, other_diagonal, panel, quad
from vectors import add, centroid, cross, dot, rotate_y, rotate_z, scale, sub, tidy


# Cornell Box data, Cornell University Program of Computer Graphics
# (http://www.graphics.cornell.edu/online/box/data.html), millimetres, vertex order as published.
# Cross-checked against two public copies: a mirror of that page
# (https://www.graphicon.ru/oldgr/courses/cg_el99/c_box/data.htm) and the same vertices scaled
# by 0.1 in GaborDrescher/pathTracer, meshes/{floor,ceil,back,left,right,smallbox,largebox,
# light}.h. The measured room is not a perfect box (e.g. the floor is 552.8 mm wide at the front
# but 549.6 mm at the back, the red wall is slightly tilted): the coordinates are kept as they are.
# The published order already winds every wall so its front face looks into the box, every block
# face outward and the light downward; cornell_box() re-checks that and stops if it ever is not.
CORNELL_MM = {
    "floor": [[(552.8, 0.0, 0.0), (0.0, 0.0, 0.0), (0.0, 0.0, 559.2), (549.6, 0.0, 559.2)]],
    "ceiling": [[(556.0, 548.8, 0.0), (556.0, 548.8, 559.2), (0.0, 548.8, 559.2),
                 (0.0, 548.8, 0.0)]],
    "back_wall": [[(549.6, 0.0, 559.2), (0.0, 0.0, 559.2), (0.0, 548.8, 559.2),
                   (556.0, 548.8, 559.2)]],
    "right_wall_green": [[(0.0, 0.0, 559.2), (0.0, 0.0, 0.0), (0.0, 548.8, 0.0),
                          (0.0, 548.8, 559.2)]],
    "left_wall_red": [[(552.8, 0.0, 0.0), (549.6, 0.0, 559.2), (556.0, 548.8, 559.2),
                       (556.0, 548.8, 0.0)]],
    "short_block": [
        [(130, 165, 65), (82, 165, 225), (240, 165, 272), (290, 165, 114)],
        [(290, 0, 114), (290, 165, 114), (240, 165, 272), (240, 0, 272)],
        [(130, 0, 65), (130, 165, 65), (290, 165, 114), (290, 0, 114)],
        [(82, 0, 225), (82, 165, 225), (130, 165, 65), (130, 0, 65)],
        [(240, 0, 272), (240, 165, 272), (82, 165, 225), (82, 0, 225)]],
    "tall_block": [
        [(423, 330, 247), (265, 330, 296), (314, 330, 456), (472, 330, 406)],
        [(423, 0, 247), (423, 330, 247), (472, 330, 406), (472, 0, 406)],
        [(472, 0, 406), (472, 330, 406), (314, 330, 456), (314, 0, 456)],
        [(314, 0, 456), (314, 330, 456), (265, 330, 296), (265, 0, 296)],
        [(265, 0, 296), (265, 330, 296), (423, 330, 247), (423, 0, 247)]],
    # The light sits in the ceiling plane (y = 548.8) in the data; it is lowered by 0.5 mm below.
    "light": [[(343.0, 548.8, 227.0), (343.0, 548.8, 332.0), (213.0, 548.8, 332.0),
               (213.0, 548.8, 227.0)]],
}
CORNELL_LIGHT_DROP_MM = 0.5
CORNELL_BOX_CENTER_MM = (278.0, 274.4, 279.6)  # middle of the room, used for facing checks


def quad_normal(q):
    return cross(sub(q[1], q[0]), sub(q[2], q[0]))


def cornell_facing_ok(name, quads):
    """True when every quad of the part faces the way the scene needs."""
    if name == "light":
        return all(quad_normal(q)[1] < 0.0 for q in quads)
    if name.endswith("_block"):  # outward: away from the block's centre
        c = centroid([p for q in quads for p in q])
        return all(dot(quad_normal(q), sub(centroid(q), c)) > 0.0 for q in quads)
    return all(dot(quad_normal(q), sub(CORNELL_BOX_CENTER_MM, centroid(q))) > 0.0 for q in quads)


def cornell_box():
    """Cornell box (measured geometry, RGB approximations of the measured reflectances).

    Tests: the whole pipeline on the standard reference scene; compare against a converged
    reference render (no closed form). Looking from the camera, the red wall (x ~ 0.55 m) is
    on the LEFT and the green wall (x = 0) on the RIGHT: the camera's 180-degree turn about Y
    maps its local +X (image right) onto world -X. check_cornell() verifies this by projection:
    the red wall's centre lands at image x = -0.715, the green wall's at +0.721 (x in [-1, 1],
    -1 = left edge).
    Light: radiance (17, 12, 4), albedo 0.78, lowered 0.5 mm below the (hole-less) ceiling.
    """
    b = GltfBuilder()
    white = b.material("white", (0.725, 0.71, 0.68))
    red = b.material("red", (0.63, 0.065, 0.05))
    green = b.material("green", (0.14, 0.45, 0.091))
    light = b.material("light", (0.78, 0.78, 0.78), emission=(17.0, 12.0, 4.0))
    materials = {"left_wall_red": red, "right_wall_green": green, "light": light}
    for name, quads_mm in CORNELL_MM.items():
        if not cornell_facing_ok(name, quads_mm):
            raise SystemExit("cornell_box: %s does not face the expected way" % name)
        drop = CORNELL_LIGHT_DROP_MM if name == "light" else 0.0
        quads_m = [[(x * 0.001, (y - drop) * 0.001, z * 0.001) for x, y, z in q] for q in quads_mm]
        positions, triangles = merge(*(quad(*q) for q in quads_m))
        b.mesh(name, positions, triangles, materials.get(name, white))
    # 35 mm lens on 25 mm x 25 mm film: yfov = 2 atan(12.5 / 35) = 0.68605 rad (39.31 degrees).
    b.camera((0.278, 0.273, -0.8), (0.0, 0.0, 1.0), 2.0 * math.atan(0.0125 / 0.035))
    return b.build()


def furnace_closed(albedo=0.5, emission=1.0):
    """Closed furnace: camera at the centre of a 2 m cube whose inward-facing walls all have
    albedo a = 0.5 and emit Le = 1 (one-sided, into the room).

    Expected radiance at every pixel: Le / (1 - a) = 2 with unlimited bounces; with at most D
    bounces the geometric series stops after D + 1 terms: Le (1 - a^(D+1)) / (1 - a)
    (D = 0: 1, D = 1: 1.5, D = 2: 1.75, ...).
    """
    b = GltfBuilder()
    wall = b.material("furnace_wall", (albedo,) * 3, emission=(emission,) * 3)
    lo, hi = -1.0, 1.0
    positions, triangles = merge(
        floor_quad(lo, hi, lo, hi, y=lo, up=True),                         # floor, faces +y
        floor_quad(lo, hi, lo, hi, y=hi, up=False),                        # ceiling, faces -y
        quad((lo, lo, lo), (hi, lo, lo), (hi, hi, lo), (lo, hi, lo)),      # z = -1, faces +z
        quad((lo, lo, hi), (lo, hi, hi), (hi, hi, hi), (hi, lo, hi)),      # z = +1, faces -z
        quad((lo, lo, lo), (lo, hi, lo), (lo, hi, hi), (lo, lo, hi)),      # x = -1, faces +x
        quad((hi, lo, lo), (hi, lo, hi), (hi, hi, hi), (hi, hi, lo)))      # x = +1, faces -x
    b.mesh("furnace_walls", positions, triangles, wall)
    b.camera((0.0, 0.0, 0.0), (0.3, -0.2, -1.0), 1.2)
    return b.build()


def white_furnace():
    """White furnace: a Lambertian icosphere (3 subdivisions, 1280 triangles, radius 1 m,
    outward faces) of albedo 1, no emitters, constant background radiance (1, 1, 1).

    Expected: every pixel is exactly 1, whether it sees the sphere or the background. The
    polyhedron is convex, so a bounced ray never meets it again: any depth >= 1 gives 1.
    """
    b = GltfBuilder()
    white = b.material("albedo_one", (1.0, 1.0, 1.0))
    positions, triangles = icosphere(3)
    b.mesh("sphere", positions, triangles, white)
    b.camera((0.0, 0.0, 4.0), (0.0, 0.0, -1.0), 0.7)
    return b.build(background=(1.0, 1.0, 1.0))


def open_plane(scale_factor=1.0, offset=0.0):
    """Open plane: a 200 m x 200 m square (two triangles) of albedo 1 facing +y, the camera
    1 m above and 1 m back, looking 45 degrees down. Nothing is above the plane, so ambient
    occlusion is 1 at every pixel, for every AO distance.

    Robustness variants: every coordinate (vertices and the camera position, and znear) is
    multiplied by `scale_factor`, then (offset, offset, offset) is added to every vertex and to
    the camera position. The offset is baked into the vertex data (not a node translation), so
    the float32 positions really sit far from the origin. The expected AO stays 1.
    """
    s, o = float(scale_factor), float(offset)

    def place(p):
        return (p[0] * s + o, p[1] * s + o, p[2] * s + o)

    b = GltfBuilder()
    white = b.material("albedo_one", (1.0, 1.0, 1.0))
    # Off-centre in z so that the diagonal both triangles share (z = x - 50) stays out of view.
    positions, triangles = floor_quad(-100.0, 100.0, -150.0, 50.0)
    b.mesh("plane", [place(p) for p in positions], triangles, white)
    b.camera(place((0.0, 1.0, 1.0)), (0.0, -1.0, -1.0), 0.6, znear=0.01 * s)
    return b.build()


def ceiling():
    """Floor under a parallel ceiling: floor (albedo 1, facing up) at y = 0, ceiling (facing
    down) at y = h = 1, both 400 m x 400 m; camera between them looking down at the floor.

    Expected cosine-weighted AO with distance r at a floor point (the unoccluded fraction):
    a direction at angle theta from the normal meets the ceiling after h / cos(theta), so it is
    occluded iff h / cos(theta) < r, i.e. cos(theta) > h / r. With the cosine-weighted pdf
    p(theta) = cos(theta) sin(theta) / pi, P(cos(theta) > c) = 1 - c^2, hence
        AO(r) = 1               for r <= h,
        AO(r) = (h / r)^2       for r >= h     (r = 2: 0.25, r = 4: 0.0625).
    The planes' edges are at least 100 m away: they do not matter for r <= 4 (the ceiling is
    met within h tan(theta) <= 3.9 m). Off-centre in z so that the quads' diagonals stay out of
    view.
    """
    b = GltfBuilder()
    white = b.material("albedo_one", (1.0, 1.0, 1.0))
    b.mesh("floor", *floor_quad(-200.0, 200.0, -300.0, 100.0, y=0.0, up=True), white)
    b.mesh("ceiling", *floor_quad(-200.0, 200.0, -300.0, 100.0, y=1.0, up=False), white)
    b.camera((0.0, 0.5, 0.5), (0.0, -math.sqrt(3.0), -1.0), 0.5)  # 60 degrees down
    return b.build()


def wall():
    """Floor (facing up, x in [0, 200], z in [-100, 100]) meeting a vertical wall along x = 0
    (facing +x, 200 m tall); camera 1 m from the wall looking at the floor near it.

    Expected AO with infinite distance: 1/2 at every visible point. A floor point sees the
    wall in exactly the directions with a -x component, half of the cosine-weighted hemisphere
    (and a wall point, symmetrically, loses the half pointing down at the floor). The finite
    200 m extents let a few grazing directions past the far edges: AO ~ 1/2 + 0.004 d for a
    point d metres from the other plane. Numerically integrated at the visible points:
    0.5000 .. 0.5010.
    """
    b = GltfBuilder()
    white = b.material("albedo_one", (1.0, 1.0, 1.0))
    b.mesh("floor", *floor_quad(0.0, 200.0, -100.0, 100.0), white)
    b.mesh("wall", *quad((0.0, 0.0, -100.0), (0.0, 200.0, -100.0), (0.0, 200.0, 100.0),
                         (0.0, 0.0, 100.0)), white)
    b.camera((1.0, 0.5, 0.0), (-1.0, -math.tan(math.radians(30.0)), 0.0), 1.0)
    return b.build()


def corner():
    """Inside corner: floor (facing up) plus two perpendicular walls, x = 0 facing +x and
    z = 0 facing +z, all 200 m; camera looking into the corner.

    Expected AO with infinite distance: 1/4 at every visible point: only directions with both
    +x and +z components escape, a quarter of the cosine-weighted hemisphere by symmetry (the
    same holds on either wall). The finite 200 m extents add about 0.003 per metre of distance
    from the corner; numerically integrated at the visible points: 0.2500 .. 0.2515.
    """
    b = GltfBuilder()
    white = b.material("albedo_one", (1.0, 1.0, 1.0))
    b.mesh("floor", *other_diagonal(floor_quad(0.0, 200.0, 0.0, 200.0)), white)
    b.mesh("wall_x0", *other_diagonal(quad((0.0, 0.0, 0.0), (0.0, 200.0, 0.0),
                                           (0.0, 200.0, 200.0), (0.0, 0.0, 200.0))), white)
    b.mesh("wall_z0", *other_diagonal(quad((0.0, 0.0, 0.0), (200.0, 0.0, 0.0),
                                           (200.0, 200.0, 0.0), (0.0, 200.0, 0.0))), white)
    # Aimed a little off the symmetry plane x = z, so that no pixel centre lands exactly on the
    # corner line x = z = 0, where AO is ill-defined.
    b.camera((1.3, 0.9, 1.1), (-1.1, -0.75, -0.75), 1.0)
    return b.build()


def small_light_expected_radiance(side, height=1.0, albedo=0.5, power=1.0):
    """Radiance of the floor point right below the centre of small_light(side).

    Le = power / (pi side^2); E = pi Le F with F the form factor from a differential area to a
    parallel square centred above it (four corner rectangles a = b = side / 2):
    F_corner = 1/(2 pi) [A/sqrt(1+A^2) atan(B/sqrt(1+A^2)) + B/sqrt(1+B^2) atan(A/sqrt(1+B^2))],
    A = B = side / (2 height); L = albedo E / pi.
    As side -> 0, E -> power / (pi height^2) and L -> albedo power / (pi^2 height^2).
    """
    le = power / (math.pi * side * side)
    a = 0.5 * side / height
    r = math.sqrt(1.0 + a * a)
    f = 4.0 * (1.0 / (2.0 * math.pi)) * 2.0 * (a / r) * math.atan(a / r)
    return albedo * (math.pi * le * f) / math.pi


def small_light(side=0.1, height=1.0, power=1.0):
    """Small light: a floor (albedo 0.5, facing up, 100 m x 100 m) under a square emitter of
    side s centred 1 m above the origin, facing down, black, with fixed power Phi = 1 W:
    Le = Phi / (pi s^2) (power = radiance x pi x area for a one-sided Lambertian emitter).

    Expected radiance of the floor point below the light (the origin, at the image centre):
    small_light_expected_radiance(s) = 0.050492 for s = 0.1, tending to the point-light limit
    0.5 / pi^2 = 0.050661 as s -> 0 (0.33 % below it at s = 0.1, 0.0033 % at s = 0.01). The
    floor sees nothing but the (black) light, so the value holds for any bounce depth >= 1.
    Shrinking s at fixed power barely changes the expected image; estimators that only find
    the light by BSDF sampling get noisier without bound, light sampling does not.
    """
    b = GltfBuilder()
    floor_mat = b.material("floor", (0.5, 0.5, 0.5))
    le = power / (math.pi * side * side)
    light_mat = b.material("light", (0.0, 0.0, 0.0), emission=(le, le, le))
    h = 0.5 * side
    # Off-centre in z so that the floor's diagonal (z = x - 20) misses the point below the light.
    b.mesh("floor", *floor_quad(-50.0, 50.0, -70.0, 30.0), floor_mat)
    b.mesh("light", *floor_quad(-h, h, -h, h, y=height, up=False), light_mat)
    b.camera((0.0, 0.6, 1.5), (0.0, -0.6, -1.5), 0.7)  # aims at the origin, light out of view
    return b.build()


def light_touching_wall():
    """An emitter touching a wall: a room corner (floor y = 0, back wall z = 0 facing +z, left
    wall x = -2 facing +x; albedo 0.5) with a horizontal 1 m x 0.5 m emitter at y = 1 facing
    down (radiance 10, one-sided) whose edge z = 0 lies on the back wall.

    Tests: robustness at the contact line. Radiance there is bounded (irradiance <= pi Le), but
    the light-sampling geometry term grows without bound as the distance goes to 0, so the
    output must stay finite (no NaN / Inf, no runaway fireflies) on the wall just under the
    light. No closed-form value.
    """
    b = GltfBuilder()
    grey = b.material("grey", (0.5, 0.5, 0.5))
    light_mat = b.material("light", (0.0, 0.0, 0.0), emission=(10.0, 10.0, 10.0))
    b.mesh("floor", *floor_quad(-2.0, 2.0, 0.0, 4.0), grey)
    b.mesh("back_wall", *quad((-2.0, 0.0, 0.0), (2.0, 0.0, 0.0), (2.0, 2.0, 0.0), (-2.0, 2.0, 0.0)),
           grey)
    b.mesh("left_wall", *quad((-2.0, 0.0, 0.0), (-2.0, 2.0, 0.0), (-2.0, 2.0, 4.0),
                              (-2.0, 0.0, 4.0)), grey)
    b.mesh("light", *floor_quad(-0.5, 0.5, 0.0, 0.5, y=1.0, up=False), light_mat)
    b.camera((0.4, 0.3, 1.6), (-0.4, 0.6, -1.4), 1.0)  # looks up at the contact line
    return b.build()


def light_near_floor():
    """A light a few centimetres above a floor: a 0.8 m x 0.1 m strip emitter (radiance 2,
    one-sided, albedo 0.8) facing down at y = 0.04 over a floor (albedo 0.5, 4 m x 4 m facing
    up); no walls, a black background. The camera looks down at 35 degrees across the strip, so
    its top (its back, which emits nothing) and the glow on the floor on both sides of it are in
    view.

    Tests: the light-sampling geometry term cos cos / d^2 where d is small but never zero. Floor
    points within about 10 cm of the strip get most of their light from emitter points only a
    few centimetres away, so an estimator that clamps d^2 or otherwise tames 1/d^2 near a light
    darkens the whole glow, while the estimator's variance stays bounded (d >= 4 cm). Also light
    an emitter reflects: the strip's front sends part of the glow under it back to the floor
    (naive recursion sees it from depth 3). No closed form.
    """
    b = GltfBuilder()
    grey = b.material("grey", (0.5, 0.5, 0.5))
    light_mat = b.material("light", (0.8, 0.8, 0.8), emission=(2.0, 2.0, 2.0))
    b.mesh("floor", *floor_quad(-2.0, 2.0, -2.0, 2.0), grey)
    b.mesh("light", *floor_quad(-0.4, 0.4, -0.05, 0.05, y=0.04, up=False), light_mat)
    down = math.radians(35.0)
    b.camera((0.0, 1.3 * math.sin(down), 1.3 * math.cos(down)),
             (0.0, -math.sin(down), -math.cos(down)), 0.7)  # 1.3 m from the origin
    return b.build()


def textured_quad():
    """A 1 m x 1 m quad (z = 0, facing +z) with a 4 x 4 checkerboard baseColorTexture (PNG data
    URI, TEXCOORD_0, repeat sampler), lit only by a constant background of radiance 1.

    Expected: nothing occludes the quad's hemisphere, so a texel of albedo rho shows radiance
    rho: the light squares 1.0, the dark squares 0.2158605 (sRGB 128 decoded to linear), at
    texel centres (bilinear filtering blends across the squares' edges).
    uv (0, 0), the light top-left texel of the PNG, sits at the quad's top-left corner
    (-0.5, 0.5, 0) as seen from the camera, so the image's top-left square is light. The
    background around the quad is 1.
    """
    b = GltfBuilder()
    tex = b.png_texture("checkerboard", checkerboard_png())
    mat = b.material("checker", (1.0, 1.0, 1.0), texture=tex)
    positions = [(-0.5, 0.5, 0.0), (-0.5, -0.5, 0.0), (0.5, -0.5, 0.0), (0.5, 0.5, 0.0)]
    texcoords = [(0.0, 0.0), (0.0, 1.0), (1.0, 1.0), (1.0, 0.0)]
    b.mesh("quad", positions, [(0, 1, 2), (0, 2, 3)], mat, texcoords=texcoords)
    b.camera((0.0, 0.0, 2.0), (0.0, 0.0, -1.0), 2.0 * math.atan(0.6 / 2.0))
    return b.build(background=(1.0, 1.0, 1.0))


def grading_edges():
    """Grading scene for stage 1 (pixel filters and the splat under eye-light shading: albedo
    |cos theta| + emission, the background where a ray misses). 4:3 camera (256 x 192 at
    --width 256) looking down -Z at a collage of flat, sharp-edged parts 2.6 .. 3.7 m away, in
    front of a constant background (0.25, 0.3, 0.4) that fills about a third of the frame and
    meets geometry along many edges and along the image border.

    Parts and what they test:
      - star (upper left): a Siemens star, 64 wedges of radius 0.8 m alternating dark
        (albedo 0.05) with white 0.9, red (0.9, 0.15, 0.1) and blue (0.1, 0.3, 0.9): edges at
        64 orientations, and towards the centre wedges narrower than a pixel, where the image
        depends on the filter's exact support and weights (aliasing vs. blur);
      - bars (upper right): axis-aligned white / yellow / green bars 0.16 m .. 0.02 m wide
        (about 14 .. 1.8 pixels at 256 wide) with background gaps of the same width, over a
        horizontal bar: vertical and horizontal edges against the background, where a
        half-pixel offset in the splat or in the filter's argument shifts every edge;
      - stripes (lower right, running off the right and bottom image borders): a panel of
        16 stripes (white 0.9 / dark 0.05 / green (0.15, 0.7, 0.2)) widening from 0.015 m
        (about one pixel at 256 wide) to 0.2 m, turned 25 degrees about Z and -40 degrees about
        Y, so they recede in perspective and their |cos theta| shading varies; the filter's
        support at the image border (footprints that leave the image);
      - emitter (lower middle): a 0.3 m square turned 30 degrees, black albedo, emission 2,
        partly over the purple wedge, partly over the background: the brightest edges, which
        show a filter's negative lobes (Mitchell) and wrong normalisation most;
      - sphere (lower left): an icosphere (2 subdivisions, 320 triangles, radius 0.3 m, albedo
        (0.8, 0.7, 0.5)): curved silhouette against the background, smooth shading;
      - wedge and sliver: a purple triangle tilted in depth (albedo (0.5, 0.1, 0.6)) over the
        star's lower edge and the background, and a thin dark sliver (albedo 0.05) lying 5
        degrees off horizontal across the bars: occlusion edges between two surfaces.
    Every part faces the camera (no back faces are seen). No closed form: compare against the
    reference stage 1 with the same filter, sampler, seed and spp.
    """
    b = GltfBuilder()
    dark = b.material("dark", (0.05, 0.05, 0.05))
    white = b.material("white", (0.9, 0.9, 0.9))
    red = b.material("red", (0.9, 0.15, 0.1))
    blue = b.material("blue", (0.1, 0.3, 0.9))
    yellow = b.material("yellow", (0.9, 0.8, 0.1))
    green = b.material("green", (0.15, 0.7, 0.2))
    purple = b.material("purple", (0.5, 0.1, 0.6))
    tan = b.material("tan", (0.8, 0.7, 0.5))
    glow = b.material("emitter", (0.0, 0.0, 0.0), emission=(2.0, 2.0, 2.0))

    # Siemens star in the plane z = 0, wedges wound counter-clockwise seen from +z.
    centre, radius, wedges, turn = (-0.68, 0.27, 0.0), 0.8, 64, 0.013
    rims = [(centre[0] + radius * math.cos(turn + 2.0 * math.pi * i / wedges),
             centre[1] + radius * math.sin(turn + 2.0 * math.pi * i / wedges), 0.0)
            for i in range(wedges)]
    star = {"star_dark": [], "star_white": [], "star_red": [], "star_blue": []}
    for i in range(wedges):
        kind = "star_dark" if i % 2 == 0 else ("star_white", "star_red", "star_white",
                                                "star_blue")[(i // 2) % 4]
        star[kind].append(([centre, rims[i], rims[(i + 1) % wedges]], [(0, 1, 2)]))
    for name, mat in (("star_dark", dark), ("star_white", white), ("star_red", red),
                      ("star_blue", blue)):
        b.mesh(name, *merge(*star[name]), mat)

    # Axis-aligned bars at z = 0.1: widths shrink, gaps (background) as wide as the bar before.
    x, bars = 0.25, {"bars_white": [], "bars_yellow": [], "bars_green": []}
    for k, width in enumerate((0.16, 0.12, 0.09, 0.06, 0.04, 0.03, 0.02)):
        kind = ("bars_white", "bars_yellow", "bars_green")[k % 3]
        bars[kind].append(quad((x, 0.55, 0.1), (x + width, 0.55, 0.1), (x + width, 1.15, 0.1),
                               (x, 1.15, 0.1)))
        x += 2.0 * width
    bars["bars_white"].append(quad((0.25, 0.38, 0.1), (x, 0.38, 0.1), (x, 0.47, 0.1),
                                   (0.25, 0.47, 0.1)))
    for name, mat in (("bars_white", white), ("bars_yellow", yellow), ("bars_green", green)):
        b.mesh(name, *merge(*bars[name]), mat)
    # A thin dark sliver in front of the bars, 5 degrees off horizontal.
    a = math.radians(5.0)
    d = (math.cos(a), math.sin(a), 0.0)
    n = (-math.sin(a), math.cos(a), 0.0)
    p0 = (0.15, 0.72, 0.3)
    b.mesh("sliver", [p0, add(p0, scale(d, 1.45)), add(add(p0, scale(d, 1.45)), scale(n, 0.035))],
           [(0, 1, 2)], dark)

    # Receding stripes, lower right, crossing the right and bottom image borders.
    u = rotate_y(rotate_z((1.0, 0.0, 0.0), math.radians(25.0)), math.radians(-40.0))
    v = rotate_y(rotate_z((0.0, 1.0, 0.0), math.radians(25.0)), math.radians(-40.0))
    origin = (0.5, -1.2, -0.1)
    s, stripes = 0.0, {"stripes_white": [], "stripes_dark": [], "stripes_green": []}
    for k in range(16):
        width = 0.2 * 0.84 ** (15 - k)
        kind = "stripes_dark" if k % 2 else ("stripes_white", "stripes_green")[(k // 2) % 2]
        stripes[kind].append(panel(origin, u, v, s, s + width, -0.2, 1.15))
        s += width
    for name, mat in (("stripes_white", white), ("stripes_dark", dark),
                      ("stripes_green", green)):
        b.mesh(name, *merge(*stripes[name]), mat)

    # Emitter: a 0.3 m square turned 30 degrees about z, in front of the star's lower rim.
    e_u, e_v = rotate_z((1.0, 0.0, 0.0), math.radians(30.0)), rotate_z((0.0, 1.0, 0.0),
                                                                       math.radians(30.0))
    b.mesh("emitter", *panel((-0.3, -0.62, 0.3), e_u, e_v, -0.15, 0.15, -0.15, 0.15), glow)

    # Sphere, lower left, and a purple triangle tilted in depth.
    b.mesh("sphere", *icosphere(2, 0.3, (-1.08, -0.72, 0.1)), tan)
    b.mesh("wedge", [(-0.75, -0.95, 0.5), (-0.05, -0.25, -0.3), (-1.15, -0.3, 0.0)],
           [(0, 1, 2)], purple)

    b.camera((0.1, 0.05, 3.2), (-0.1, -0.05, -3.2), 0.66, aspect_ratio=4.0 / 3.0)
    return b.build(background=(0.25, 0.3, 0.4))


def grading_stripes():
    """Grading scene for stage 1's filter profiles: the whole frame is stripes, so nearly every
    pixel depends on the filter's shape (a flat region depends on nothing but the mean). 4:3
    camera 3 m in front of four panels in the plane z = 0 (a 64 x 48 image puts 1 pixel at about
    0.043 m). In each panel white (0.9) and dark (0.05) stripes widen geometrically from about
    0.6 to 4.5 pixels (64 wide), so the panels sweep the frequencies where filters differ most,
    from above the pixel rate to a few pixels per period. The stripes are sheared 4 degrees so
    that along each stripe the edge crosses every sub-pixel phase. Upper left and lower right run
    vertically, the other two horizontally; the panels sit at depths 0, 0.01, ... so that where
    their sheared ends overlap, one is in front."""
    b = GltfBuilder()
    white = b.material("white", (0.9, 0.9, 0.9))
    dark = b.material("dark", (0.05, 0.05, 0.05))
    half_h = 3.0 * math.tan(0.33)  # the camera's yfov is 0.66 rad
    half_w = half_h * 4.0 / 3.0
    pixel = 2.0 * half_w / 64.0
    shear = math.tan(math.radians(4.0))
    stripes = {"white": [], "dark": []}
    # (centre x, centre y, depth, vertical?, widening towards +s?)
    for k, (cx, cy, vertical, widening) in enumerate(((-0.5, 0.5, True, True),
                                                       (0.5, 0.5, False, True),
                                                       (-0.5, -0.5, False, False),
                                                       (0.5, -0.5, True, False))):
        u, v = ((1.0, 0.0, 0.0), (0.0, 1.0, 0.0)) if vertical else ((0.0, 1.0, 0.0),
                                                                     (-1.0, 0.0, 0.0))
        across = half_w if vertical else half_h  # panel extent across and along the stripes
        along = half_h if vertical else half_w
        centre = (cx * half_w, cy * half_h, 0.01 * k)
        widths, total = [], 0.0
        while total < across + 2.0 * pixel:
            widths.append(0.6 * pixel * 1.13 ** len(widths))
            total += widths[-1]
        if not widening:
            widths.reverse()
        s = -total / 2.0
        for i, w in enumerate(widths):
            t0, t1 = -along / 2.0 - pixel, along / 2.0 + pixel

            def at(si, t):
                return tuple(tidy(c) for c in add(centre, add(scale(u, si + shear * t),
                                                               scale(v, t))))
            stripes["white" if i % 2 == 0 else "dark"].append(
                quad(at(s, t0), at(s + w, t0), at(s + w, t1), at(s, t1)))
            s += w
    b.mesh("stripes_white", *merge(*stripes["white"]), white)
    b.mesh("stripes_dark", *merge(*stripes["dark"]), dark)
    b.camera((0.0, 0.0, 3.0), (0.0, 0.0, -1.0), 0.66, aspect_ratio=4.0 / 3.0)
    return b.build(background=(0.25, 0.3, 0.4))


def grading_lights():
    """Grading scene for stages 2-5 (AO, naive recursion, path tracing with next-event
    estimation): an open room lit by a constant background (0.2, 0.25, 0.3) and three one-sided
    emitters of different size, radiance and colour. Metres; y up.

    Room (open at the front z > 1.25, at the right x > 1.25 and at the top, so rays escape to
    the background, which lights the room through the openings):
      - floor y = 0, x, z in [-1.25, 1.25], facing up, grey 0.5;
      - back wall z = -1.25, 2 m tall, facing +z, white 0.8;
      - left wall x = -1.25, 2 m tall, facing +x, red (0.7, 0.3, 0.3);
      - green block (0.3, 0.6, 0.3), 0.5 x 0.5 x 0.35 m, turned -18 degrees, near the front left;
      - grey block 0.5, 0.36 x 0.36 x 1.0 m, turned 25 degrees, at the back right.
    Emitters (black albedo, one-sided, none touching anything; power = pi x area x radiance):
      - wall_light: 0.5 m x 0.5 m, radiance (3, 2.6, 2), 1 cm in front of the left wall
        (y in [0.9, 1.4], z in [-0.6, -0.1]), facing +x into the room: the large dim source
        (2.1 W in luminance terms), soft shadows; its front is in view;
      - small_light: 0.12 m x 0.12 m, radiance 50, centred at (-0.5, 0.75, 0), facing down and
        tilted 40 degrees towards +z (the camera): the small bright source (2.3 W, about as
        much as wall_light from 1/17 of its area), 0.4 m above and just behind the green
        block, whose top it lights with a steep falloff and whose shadow it throws forward.
        The camera sees its front. Light picking by area and by power differ a lot between it
        and wall_light;
      - back_light: 0.5 m x 0.3 m, radiance (2, 3, 5), floating 0.4 m in front of the back wall
        and 0.45 m above the floor, facing -z (towards the back wall). The camera sees its BACK,
        which must stay black in every stage (no emission from behind), while its front throws
        a bluish glow on the back wall and the floor behind it, both in view around it. An
        estimator that ignores one-sidedness (the cosine at the light in NEE, or emission found
        by a bounce) wrongly lights the floor in front of it, towards the camera.
    Camera: at the open front right, (1.1, 1.0, 2.7), yfov 0.9, square, looking into the back
    left corner; the background shows above the back wall, beyond the floor's front edge and
    past its right edge. No closed form: compare against the reference stages with the same
    parameters, sampler, seed and spp.
    """
    b = GltfBuilder()
    grey = b.material("grey", (0.5, 0.5, 0.5))
    white = b.material("white", (0.8, 0.8, 0.8))
    red = b.material("red", (0.7, 0.3, 0.3))
    green = b.material("green", (0.3, 0.6, 0.3))
    wall_light_mat = b.material("wall_light", (0.0, 0.0, 0.0), emission=(3.0, 2.6, 2.0))
    small_light_mat = b.material("small_light", (0.0, 0.0, 0.0), emission=(50.0, 50.0, 50.0))
    back_light_mat = b.material("back_light", (0.0, 0.0, 0.0), emission=(2.0, 3.0, 5.0))
    lo, hi, top = -1.25, 1.25, 2.0
    b.mesh("floor", *floor_quad(lo, hi, lo, hi), grey)
    b.mesh("back_wall", *quad((lo, 0.0, lo), (hi, 0.0, lo), (hi, top, lo), (lo, top, lo)), white)
    b.mesh("left_wall", *quad((lo, 0.0, lo), (lo, top, lo), (lo, top, hi), (lo, 0.0, hi)), red)
    b.mesh("green_block", *block(-0.55, 0.35, 0.25, 0.25, 0.35, math.radians(-18.0)), green)
    b.mesh("grey_block", *block(0.7, -0.55, 0.18, 0.18, 1.0, math.radians(25.0)), grey)
    # wall_light: x = lo + 0.01, facing +x (counter-clockwise seen from +x: z decreasing with y up).
    x = lo + 0.01
    b.mesh("wall_light", *quad((x, 0.9, -0.1), (x, 0.9, -0.6), (x, 1.4, -0.6), (x, 1.4, -0.1)),
           wall_light_mat)
    # small_light: faces down, tilted 40 degrees towards +z (the camera): normal (0, -c, s).
    c, s = math.cos(math.radians(40.0)), math.sin(math.radians(40.0))
    b.mesh("small_light", *panel((-0.5, 0.75, 0.0), (1.0, 0.0, 0.0), (0.0, s, c),
                                 -0.06, 0.06, -0.06, 0.06), small_light_mat)
    # back_light: z = -0.85, facing -z (counter-clockwise seen from -z: x decreasing with y up).
    z = -0.85
    b.mesh("back_light", *quad((0.3, 0.45, z), (-0.2, 0.45, z), (-0.2, 0.75, z), (0.3, 0.75, z)),
           back_light_mat)
    b.camera((1.1, 1.0, 2.7), (-1.5, -0.4, -3.4), 0.9)
    return b.build(background=(0.2, 0.25, 0.3))


def grid(n, bin_uri):
    """Height-field grid for the memory benchmark: n x n cells over [-1, 1]^2 (2 n^2 triangles,
    (n + 1)^2 vertices; n = 708 gives 1,002,528), albedo 0.8, lit by a background of 1.
    Returns (doc, blob) with the buffer in an external file named bin_uri."""
    positions = array("f")
    for j in range(n + 1):
        z = -1.0 + 2.0 * j / n
        for i in range(n + 1):
            x = -1.0 + 2.0 * i / n
            positions.extend((x, 0.05 * math.sin(7.0 * x) * math.cos(5.0 * z), z))
    indices = array("I")
    row = n + 1
    for j in range(n):
        for i in range(n):
            v = j * row + i  # (x, z) -> (x, z + dz) -> (x + dx, z + dz) winds counter-clockwise
            indices.extend((v, v + row, v + row + 1, v, v + row + 1, v + 1))  # seen from +y
    assert positions.itemsize == 4 and indices.itemsize == 4
    ys = positions[1::3]
    y_min, y_max = f32_json(min(ys)), f32_json(max(ys))
    if sys.byteorder == "big":
        positions.byteswap()
        indices.byteswap()
    b = GltfBuilder()
    mat = b.material("grid", (0.8, 0.8, 0.8))
    bounds = ([-1.0, y_min, -1.0], [1.0, y_max, 1.0])
    b.packed_mesh("grid", positions.tobytes(), bounds, indices.tobytes(), mat)
    b.camera((0.0, 1.5, 1.5), (0.0, -1.5, -1.5), 0.9)
    return b.build(background=(1.0, 1.0, 1.0), buffer_uri=bin_uri), bytes(b.blob)


# The committed scenes: file name -> function.
SCENES = {
    "cornell_box.gltf": cornell_box,
    "furnace_closed.gltf": furnace_closed,
    "white_furnace.gltf": white_furnace,
    "open_plane.gltf": open_plane,
    "ceiling.gltf": ceiling,
    "wall.gltf": wall,
    "corner.gltf": corner,
    "small_light.gltf": small_light,
    "light_touching_wall.gltf": light_touching_wall,
    "light_near_floor.gltf": light_near_floor,
    "textured_quad.gltf": textured_quad,
    "grading_edges.gltf": grading_edges,
    "grading_stripes.gltf": grading_stripes,
    "grading_lights.gltf": grading_lights,
}
