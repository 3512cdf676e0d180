#!/usr/bin/env python3
"""Writes Pathway's test scenes as glTF 2.0 files.

Python 3 standard library only; the output is deterministic (same bytes on every run), so
re-running the script leaves `git diff` empty.

    python3 scenes/generate.py                     # every committed scene, then checks them
    python3 scenes/generate.py --open-plane SCALE OFFSET OUT.gltf
    python3 scenes/generate.py --small-light SIDE OUT.gltf
    python3 scenes/generate.py --grid N OUT.gltf   # 2*N*N triangles, external OUT.bin
    python3 scenes/generate.py --check FILE...     # re-read and check glTF files

Conventions (shared with framework/scene/gltf_loader.h): metres; a triangle's front face is the
one its vertices wind counter-clockwise around (normal = cross(p1 - p0, p2 - p0)); walls of closed
rooms face into the room; emitters emit from their front face unless the material is
doubleSided; the glTF camera looks down its local -Z with +Y up; the constant background
radiance lives in scenes[0].extras.pathway_background.

The pieces, one concern each (all importable): scene_catalog.py holds the scenes (functions
returning glTF dicts), built with gltf_builder.py from shapes.py, vectors.py and png_encoder.py;
gltf_io.py reads and writes the files; gltf_check.py, ray_cast.py and scene_checks.py check them.
"""

import argparse
import math
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
from gltf_builder import GENERATOR  # noqa: E402
from gltf_check import check_gltf  # noqa: E402
from gltf_io import GltfError, write_gltf  # noqa: E402
from scene_catalog import SCENES, grid, open_plane, small_light, \
    small_light_expected_radiance  # noqa: E402
from scene_checks import check_scene_file  # noqa: E402


def write_scenes(directory):
    """Writes every committed scene into `directory` (the same bytes on every run)."""
    for file, make in SCENES.items():
        write_gltf(os.path.join(directory, file), make())


def generate_all(directory=HERE):
    write_scenes(directory)
    print("wrote %d scenes to %s" % (len(SCENES), directory))
    for file in SCENES:
        check_scene_file(os.path.join(directory, file))
    print("small_light expected floor radiance below the light: s = 0.1: %.6f, s -> 0: %.6f"
          % (small_light_expected_radiance(0.1), 0.5 / math.pi ** 2))


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    group = parser.add_mutually_exclusive_group()
    group.add_argument("--open-plane", nargs=3, metavar=("SCALE", "OFFSET", "OUT"),
                       help="write open_plane(SCALE, OFFSET) to OUT")
    group.add_argument("--small-light", nargs=2, metavar=("SIDE", "OUT"),
                       help="write small_light(SIDE) (power fixed at 1) to OUT")
    group.add_argument("--grid", nargs=2, metavar=("N", "OUT"),
                       help="write a 2*N*N-triangle grid to OUT with an external OUT.bin")
    group.add_argument("--check", nargs="+", metavar="FILE", help="re-read and check files")
    args = parser.parse_args(argv)
    try:
        if args.open_plane:
            s, o, out = args.open_plane
            write_gltf(out, open_plane(float(s), float(o)))
            check_gltf(out, generator=GENERATOR)
        elif args.small_light:
            side, out = args.small_light
            write_gltf(out, small_light(float(side)))
            check_gltf(out, generator=GENERATOR)
        elif args.grid:
            n, out = int(args.grid[0]), args.grid[1]
            bin_path = os.path.splitext(out)[0] + ".bin"
            doc, blob = grid(n, os.path.basename(bin_path))
            with open(bin_path, "wb") as f:
                f.write(blob)
            write_gltf(out, doc)
            check_gltf(out, coverage=False, generator=GENERATOR)
        elif args.check:
            for path in args.check:
                check_gltf(path)
        else:
            generate_all()
    except GltfError as e:
        print("error: %s" % e, file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
