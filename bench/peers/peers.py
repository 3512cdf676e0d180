"""Peers benchmark: Pathway's stage 5 reference against Mitsuba 3 on the same glTF scene.

Run with the virtual environment's python (scripts/bench peers sets it up):

    build/peers/venv/bin/python bench/peers/peers.py [--out build/peers-results] [--quick]

One run measures, in this order (docs/benchmarks.md, "Peers: Mitsuba 3"):
  1. time: Pathway `stage5@fast` (--integrator; the wavefront reference: the same image as
     `stage5@ref`, bit for bit) (whole process and its --timings render) and Mitsuba
     `scalar_rgb` and `llvm_ad_rgb` (process to first image, first render, later renders) on the
     same image: 256x256, 64 spp, box filter of one pixel, all threads, Pathway with stage 5's
     own sampler (Owen-scrambled Sobol'; --sampler picks another) and Mitsuba with its
     independent one;
  2. depth: Pathway's max-depth d against Mitsuba's max_depth d + 1 (and d, to show the
     mapping is not off by one), by global means;
  3. agreement: global channel means within 1 % and every region of a 4x4 grid within 3 %, on
     many independent renders of a small image so that the standard errors are far below that;
  4. equal time: relMSE against a high-spp reference for several spp, Pathway's whole-process
     time against Mitsuba llvm's render time, compared at equal time (log-log interpolation).
Times are wall seconds and also CPU seconds (all threads), which a busy machine barely changes.
It prints markdown tables and writes them, with CSV files, into --out. Exit status 1 when the
images do not agree (the timings would then compare different things).
"""
import argparse
import datetime
import os
import pathlib
import platform
import shutil
import subprocess
import sys
import tempfile
import time

from renderers import Renderers
from report_tables import Report
from section_agreement import section_agreement
from section_depth import section_depth
from section_equal_time import section_equal_time
from section_time import section_time

HERE = pathlib.Path(__file__).resolve().parent
ROOT = HERE.parent.parent


def parse_args():
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("--pathway", default=str(ROOT / "build/release/pathway"))
    p.add_argument("--scene", default=str(ROOT / "scenes/cornell_box.gltf"))
    p.add_argument("--integrator", default="stage5@fast",
                   help="Pathway's stage 5: stage5@fast (wavefront) or stage5@ref (single rays)")
    p.add_argument("--out", default=str(ROOT / "build/peers-results"))
    p.add_argument("--width", type=int, default=256, help="timed image (square)")
    p.add_argument("--spp", type=int, default=64, help="timed image's samples per pixel")
    p.add_argument("--max-depth", type=int, default=5, help="Pathway's; Mitsuba gets one more")
    p.add_argument("--rr-depth", type=int, default=3, help="the same number in both")
    p.add_argument("--sampler", default="sobol",
                   help="Pathway's sampler (stage 5's default: sobol; or independent, stratified)")
    p.add_argument("--repeats", type=int, default=3, help="timed runs; the fastest is kept")
    p.add_argument("--agree-width", type=int, default=64)
    p.add_argument("--agree-spp", type=int, default=1024, help="per render, --agree-seeds renders")
    p.add_argument("--agree-seeds", type=int, default=8)
    p.add_argument("--depth-spp", type=int, default=512, help="per render, 8 renders per depth")
    p.add_argument("--curve-spp", default="4,8,16,32,64,128,256")
    p.add_argument("--ref-spp", type=int, default=4096, help="per renderer; the reference is both")
    p.add_argument("--sections", default="time,depth,agreement,equal-time",
                   help="which sections to run (comma-separated), default all")
    p.add_argument("--quick", action="store_true", help="small settings, to check the script")
    args = p.parse_args()
    if args.quick:
        args.repeats, args.agree_spp, args.agree_seeds, args.depth_spp = 1, 64, 4, 32
        args.curve_spp, args.ref_spp = "4,16,64", 256
    args.curve_spp = [int(s) for s in args.curve_spp.split(",")]
    args.sections = set(args.sections.split(","))
    unknown = args.sections - {"time", "depth", "agreement", "equal-time"}
    if unknown:
        p.error(f"unknown section(s) {sorted(unknown)}")
    return args


def load_average():
    return os.getloadavg()[0]


def machine_lines(args):
    import drjit
    import mitsuba
    cpu = next((l.split(":", 1)[1].strip() for l in open("/proc/cpuinfo")
                if l.startswith("model name")), platform.processor())
    commit = subprocess.run(["git", "-C", str(ROOT), "rev-parse", "--short", "HEAD"],
                            capture_output=True, text=True).stdout.strip()
    return [f"Date {datetime.date.today()}, {cpu}, {os.cpu_count()} cores, load average "
            f"{load_average():.2f} at the start; Pathway {commit} ({args.pathway}), Mitsuba "
            f"{mitsuba.__version__}, Dr.Jit {drjit.__version__}, LLVM "
            f"{os.environ.get('DRJIT_LIBLLVM_PATH', '(found by Dr.Jit)')}; scene {args.scene}."]


def main():
    args = parse_args()
    if not os.access(args.pathway, os.X_OK):
        sys.exit(f"peers: {args.pathway} not found: build it first (scripts/build release)")
    rep = Report(args.out)
    rep.say(f"# Peers: Pathway {args.integrator} against Mitsuba 3")
    rep.say()
    for line in machine_lines(args):
        rep.say(line)
    rep.say()
    start = time.monotonic()
    work = tempfile.mkdtemp(prefix="peers-")
    try:
        run = Renderers(args, work)
        timed_images, depth_ok, agree_ok = {}, True, True
        if "time" in args.sections:
            timed_images, _ = section_time(rep, run, args)
        if "depth" in args.sections:
            depth_ok = section_depth(rep, run, args)
        if "agreement" in args.sections:
            agree_ok = section_agreement(rep, run, args, timed_images)
        if "equal-time" in args.sections:
            section_equal_time(rep, run, args)
    finally:
        shutil.rmtree(work, ignore_errors=True)
    rep.say(f"Load average at the end {load_average():.2f}; {time.monotonic() - start:.0f} s "
            f"for the whole benchmark. Tables and CSV files: {args.out}")
    rep.close()
    if not (depth_ok and agree_ok):
        sys.exit("peers: the images do not agree (see the tables above)")


if __name__ == "__main__":
    main()
