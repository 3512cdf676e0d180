#!/usr/bin/env python3
"""The committed scenes, checked by the Khronos glTF validator and by the project's own checks.
Fails, naming what is wrong, unless:
  - the validator (npm package gltf-validator) reports no error and no warning in any .gltf of
    the folder;
  - every scene passes the checks scenes/generate.py runs after writing it
    (scenes/scene_checks.py): it reads back as Pathway's loader reads it, generate.py wrote it,
    its walls and emitters face the way the scene needs, its camera sees what the scene is about;
  - the generator is deterministic and the files are what it writes: the scenes written afresh
    into OUT_DIR are byte for byte those in the folder.
Usage: tests/scenes_test.py OUT_DIR [SCENES_DIR]   (SCENES_DIR: the committed scenes/ unless
given, e.g. a copy with a scene broken on purpose)
The validator is fetched once through the npm client (`npm pack`) into build/gltf-validator/,
checked against the registry's published SHA-512 (Debian has no package for it), and run by
Node.js (tests/gltf_validator.js).
"""
import base64
import glob
import hashlib
import json
import os
import shutil
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.join(ROOT, "scenes"))
sys.dont_write_bytecode = True  # keep scenes/__pycache__ out of the tree
from generate import write_scenes  # noqa: E402
from gltf_io import GltfError  # noqa: E402
from scene_catalog import SCENES  # noqa: E402
from scene_checks import check_scene_file  # noqa: E402

VALIDATOR = "gltf-validator@2.0.0-dev.3.10"
VALIDATOR_SHA512 = ("sha512-odJ4k0tRkGXiDGn78yDBg+fBbAIvBnXxh3RwAta0emSxGtyagFE8B4xELB1oYe3S5RD8"
                    "Ci3uZAsZaascH2LAEQ==")
VALIDATOR_DIR = os.path.join(ROOT, "build", "gltf-validator")
failures = []


def fail(message):
    failures.append(message)
    print("FAIL:", message)


def install_validator():
    """build/gltf-validator/, once: `npm pack` and its checksum, as scripts/slides gets
    reveal.js."""
    if os.path.isfile(os.path.join(VALIDATOR_DIR, "index.js")):
        return
    os.makedirs(os.path.dirname(VALIDATOR_DIR), exist_ok=True)
    staging = tempfile.mkdtemp(prefix="gltf-validator.partial.", dir=os.path.dirname(VALIDATOR_DIR))
    try:
        packed = subprocess.run(["npm", "pack", "--silent", VALIDATOR], cwd=staging, text=True,
                                capture_output=True)
        if packed.returncode != 0:
            sys.exit("scenes_test: npm could not fetch %s:\n%s" % (VALIDATOR, packed.stderr))
        tarball = os.path.join(staging, packed.stdout.strip().splitlines()[-1])
        with open(tarball, "rb") as f:
            integrity = "sha512-" + base64.b64encode(hashlib.sha512(f.read()).digest()).decode()
        if integrity != VALIDATOR_SHA512:
            sys.exit("scenes_test: %s does not match %s's published checksum"
                     % (os.path.basename(tarball), VALIDATOR))
        # GNU tar keeps every entry inside the folder (no absolute paths, no "..").
        subprocess.run(["tar", "-xzf", tarball, "-C", staging, "--no-same-owner"], check=True)
        os.replace(os.path.join(staging, "package"), VALIDATOR_DIR)
    finally:
        shutil.rmtree(staging, ignore_errors=True)


def validate(files):
    """The Khronos validator's verdict on each file. Errors and warnings fail: the committed
    scenes have none, and a warning here (an unexpected property, a yfov of pi or more, an
    emissive strength with a zero factor, an image it cannot read) is a generator bug all the
    same. Infos and hints (an unused object, a degenerate triangle, an extension it cannot
    check) are advice about the asset, not defects: they are printed, and pass."""
    done = subprocess.run(["node", os.path.join(ROOT, "tests", "gltf_validator.js"),
                           VALIDATOR_DIR] + files, capture_output=True, text=True)
    if done.returncode != 0:
        fail("the glTF validator did not run: %s" % done.stderr.strip())
        return
    for line in done.stdout.splitlines():
        report = json.loads(line)
        name = os.path.basename(report["file"])
        print("validator %s: %-26s %d errors, %d warnings, %d infos, %d hints"
              % (report["version"], name, report["errors"], report["warnings"], report["infos"],
                 report["hints"]))
        for m in report["messages"]:
            print("    %s %s at %s: %s" % (("error", "warning", "info", "hint")[m["severity"]],
                                          m["code"], m["pointer"], m["message"]))
        if report["errors"] or report["warnings"]:
            fail("%s: the glTF validator reports %d errors and %d warnings"
                 % (name, report["errors"], report["warnings"]))


def check(files):
    """The project's own checks, as generate.py runs them on what it writes."""
    for file in files:
        name = os.path.basename(file)
        try:
            check_scene_file(file)
        except (GltfError, LookupError, OSError, TypeError, ValueError) as e:
            fail(str(e) if str(e).startswith(name) else "%s: %s" % (name, e))


def check_determinism(scenes_dir, out_dir):
    """Every scene of the catalogue written afresh: the same bytes as in scenes_dir."""
    fresh = os.path.join(out_dir, "generated")
    os.makedirs(fresh, exist_ok=True)
    write_scenes(fresh)
    for name in SCENES:
        kept = os.path.join(scenes_dir, name)
        if not os.path.isfile(kept):
            fail("%s is missing from %s" % (name, scenes_dir))
            continue
        with open(kept, "rb") as a, open(os.path.join(fresh, name), "rb") as b:
            if a.read() != b.read():
                fail("%s differs from what scenes/generate.py writes (run it and commit)" % name)
    print("generator: %d scenes written into %s and compared" % (len(SCENES), fresh))


def main():
    if len(sys.argv) not in (2, 3):
        sys.exit(__doc__)
    out_dir = os.path.abspath(sys.argv[1])
    scenes_dir = os.path.abspath(sys.argv[2] if len(sys.argv) == 3
                                 else os.path.join(ROOT, "scenes"))
    for tool in ("node", "npm"):
        if shutil.which(tool) is None:
            sys.exit("scenes_test: %s is missing (scripts/install-deps installs it)" % tool)
    files = sorted(glob.glob(os.path.join(scenes_dir, "*.gltf")))
    if not files:
        sys.exit("scenes_test: no .gltf files in %s" % scenes_dir)
    os.makedirs(out_dir, exist_ok=True)
    install_validator()
    validate(files)
    check(files)
    check_determinism(scenes_dir, out_dir)
    if failures:
        print("%d problem(s) in %s" % (len(failures), scenes_dir))
        sys.exit(1)
    print("all %d scenes valid and checked" % len(files))


if __name__ == "__main__":
    main()
