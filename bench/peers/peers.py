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
import csv
import datetime
import json
import math
import os
import pathlib
import platform
import re
import resource
import shutil
import subprocess
import sys
import tempfile
import time

import numpy as np

HERE = pathlib.Path(__file__).resolve().parent
ROOT = HERE.parent.parent
LLVM, SCALAR = "llvm_ad_rgb", "scalar_rgb"


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


# ------------------------------------------------------------------------------------ helpers

class Report:
    """Prints markdown tables and keeps them for summary.md; writes CSV files."""

    def __init__(self, out):
        self.out, self.lines = pathlib.Path(out), []
        self.out.mkdir(parents=True, exist_ok=True)

    def say(self, text=""):
        print(text, flush=True)
        self.lines.append(text)

    def table(self, name, header, rows, note=None):
        self.say(f"| {' | '.join(header)} |")
        self.say(f"|{'---|' * len(header)}")
        for row in rows:
            self.say(f"| {' | '.join(str(c) for c in row)} |")
        if note:
            self.say(note)
        self.say()
        with open(self.out / f"{name}.csv", "w", newline="") as f:
            csv.writer(f).writerows([header] + [list(r) for r in rows])

    def close(self):
        (self.out / "summary.md").write_text("\n".join(self.lines) + "\n")


def children_cpu():
    """CPU seconds (user + system) of the children waited for so far: one child's is the
    difference around it. CPU time barely depends on how busy the machine is; wall time does."""
    usage = resource.getrusage(resource.RUSAGE_CHILDREN)
    return usage.ru_utime + usage.ru_stime


def load_average():
    return os.getloadavg()[0]


def read_exr(path):
    """RGB of a Pathway EXR (its other channels are variance and weight), read by Mitsuba."""
    import mitsuba as mi
    if mi.variant() is None:
        mi.set_variant(SCALAR)
    return np.array(mi.Bitmap(str(path)), dtype=np.float64)[..., :3]


def rel_mse(image, reference):
    """The course's relMSE: per pixel (x - ref)^2 / (ref^2 + 0.01), mean over pixels, channels."""
    return float(np.mean((image - reference) ** 2 / (reference ** 2 + 0.01)))


def regions(image, grid):
    """Means of a grid x grid partition of the image, per channel: (grid, grid, 3)."""
    h, w, c = image.shape
    return image.reshape(grid, h // grid, grid, w // grid, c).mean(axis=(1, 3))


def mean_and_se(images):
    """Mean over independent renders and its standard error (from their spread)."""
    stack = np.stack(images)
    return stack.mean(axis=0), stack.std(axis=0, ddof=1) / math.sqrt(len(stack))


def rel_diff(a, se_a, b, se_b):
    """(a - b) / b and its standard error (first order)."""
    with np.errstate(divide="ignore", invalid="ignore"):
        d = a / b - 1.0
        se = np.abs(a / b) * np.sqrt((se_a / a) ** 2 + (se_b / b) ** 2)
    black = (a == 0) & (b == 0)  # e.g. an empty background: nothing to compare
    return np.where(black, 0.0, d), np.where(black, 0.0, se)


def pct(x, digits=2):
    return f"{100 * x:+.{digits}f} %"


def fmt_s(x):
    return f"{x:.3f}" if x < 10 else f"{x:.2f}"


# ------------------------------------------------------------------------------------ renderers

class Renderers:
    def __init__(self, args, work):
        self.args, self.work = args, pathlib.Path(work)
        self.counter = 0

    def _file(self, suffix):
        self.counter += 1
        return self.work / f"{self.counter:04d}{suffix}"

    def pathway(self, spp, seed, width, max_depth=None, read=True):
        """One `pathway render` process: wall time from launch to exit, its --timings, image."""
        a = self.args
        exr = self._file(".exr")
        depth = a.max_depth if max_depth is None else max_depth
        cmd = [a.pathway, "render", a.scene, "-i", a.integrator, "--spp", str(spp),
               "--width", str(width), "--height", str(width), "--filter", "box",
               "--filter-radius", "0.5", "--sampler", a.sampler, "--seed", str(seed),
               "--threads", "0", "-p", f"max-depth={depth}", "-p", f"rr-depth={a.rr_depth}",
               "-p", "nee=on", "-p", "light-pick=power", "-q", "--timings", "-o", str(exr)]
        env = dict(os.environ)
        cpu = children_cpu()
        launch = time.monotonic_ns()
        env["PATHWAY_LAUNCH_NS"] = str(launch)  # --timings then counts from the launch
        done = subprocess.run(cmd, env=env, capture_output=True, text=True)
        wall = (time.monotonic_ns() - launch) * 1e-9
        cpu = children_cpu() - cpu
        if done.returncode != 0:
            sys.exit(f"peers: pathway failed ({' '.join(cmd)}):\n{done.stderr.strip()}")
        line = next(l for l in done.stdout.splitlines() if l.startswith("timings"))
        t = {k.strip(): float(v) * 1e-3 for k, v in re.findall(r"([a-z ]+?) ([\d.]+)",
                                                                 line.split(":", 1)[1])}
        result = {"wall": wall, "cpu": cpu, "first_ray": t["first ray"], "written": t["images written"],
                  "render": t["last ray"] - t["first ray"],
                  "write": t["images written"] - t["last ray"]}
        if read:
            result["image"] = read_exr(exr)
        exr.unlink()
        return result

    def mitsuba(self, variant, renders, width, max_depth=None, home=None):
        """One Mitsuba process (mitsuba_worker.py): its report, and the saved images by name."""
        a = self.args
        names = {}
        for r in renders:
            if "save" in r:
                names.setdefault(r["save"], str(self._file(".npy")))
                r["save"] = names[r["save"]]
        job = {"variant": variant, "scene": a.scene, "width": width, "height": width,
               "max_depth": (a.max_depth + 1) if max_depth is None else max_depth,
               "rr_depth": a.rr_depth, "renders": renders}
        env = dict(os.environ)
        if home:  # Dr.Jit keeps its kernel cache in $HOME/.drjit: a new HOME is a cold cache
            env["HOME"] = str(home)
        launch = time.monotonic_ns()
        env["PEERS_LAUNCH_NS"] = str(launch)
        cpu = children_cpu()
        done = subprocess.run([sys.executable, str(HERE / "mitsuba_worker.py"), json.dumps(job)],
                              env=env, capture_output=True, text=True)
        exit_ns = time.monotonic_ns()
        cpu = children_cpu() - cpu
        if done.returncode != 0:
            sys.exit(f"peers: Mitsuba {variant} failed (status {done.returncode}):\n"
                     f"{done.stderr.strip()[-3000:]}")
        report = json.loads(done.stdout.strip().splitlines()[-1])
        report["process"] = (exit_ns - launch) * 1e-9
        report["process_cpu"] = cpu
        report["to_first_image"] = (report["renders"][0]["done_ns"] - launch) * 1e-9
        report["to_scene"] = (report["scene_ns"] - launch) * 1e-9
        report["images"] = {}
        for key, path in names.items():
            report["images"][key] = np.load(path).astype(np.float64)
            os.unlink(path)
        return report


# ------------------------------------------------------------------------------------ sections

def traversal_floor(a):
    """`pathway_bench floor`'s seconds for the timed image, or None where it does not apply."""
    bench = pathlib.Path(a.pathway).with_name("pathway_bench")
    defaults = (a.max_depth, a.rr_depth, a.sampler) == (5, 3, "sobol")
    if a.integrator != "stage5@fast" or not defaults or not os.access(bench, os.X_OK):
        return None
    done = subprocess.run([str(bench), "floor", a.scene, "--width", str(a.width), "--spp",
                           str(a.spp), "--repeats", str(a.repeats)], capture_output=True, text=True)
    line = next((l for l in done.stdout.splitlines() if l.startswith("floor: render=")), None)
    if done.returncode != 0 or line is None:  # the timings stand without it: say so, go on
        print(f"peers: pathway_bench floor failed, the floor rows are left out:\n"
              f"{done.stderr.strip()}", file=sys.stderr)
        return None
    return {k: float(v) for k, v in re.findall(r"([a-z-]+)=([\d.]+)", line)}


def section_time(rep, run, args):
    a = args
    rep.say(f"## 1. Time: {a.width}x{a.width}, {a.spp} spp, Pathway max-depth {a.max_depth} = "
            f"Mitsuba max_depth {a.max_depth + 1}, rr-depth {a.rr_depth}, box filter, all threads")
    rep.say()
    runs = [run.pathway(a.spp, 0, a.width) for _ in range(a.repeats)]
    pw = min(runs, key=lambda r: r["wall"])
    later = [{"spp": a.spp, "seed": s} for s in range(1, max(a.repeats, 2) + 1)]
    scalar = run.mitsuba(SCALAR, [{"spp": a.spp, "seed": 0, "save": "img"}] + later[:2], a.width)
    cache = pathlib.Path(tempfile.mkdtemp(prefix="peers-home-", dir=run.work))
    cold = run.mitsuba(LLVM, [{"spp": a.spp, "seed": 0, "save": "img"}] + later, a.width,
                       home=cache)
    warm = run.mitsuba(LLVM, [{"spp": a.spp, "seed": 0}], a.width, home=cache)

    def best(report):
        return min(r["seconds"] for r in report["renders"][1:])

    llvm_render = best(cold)
    rows = [
        [f"Pathway {a.integrator}", fmt_s(pw["wall"]), fmt_s(pw["first_ray"]), fmt_s(pw["render"]),
         fmt_s(pw["render"]), fmt_s(pw["write"] + pw["wall"] - pw["written"]), "1.00"],
        ["Mitsuba scalar_rgb", fmt_s(scalar["to_first_image"]), fmt_s(scalar["to_scene"]),
         fmt_s(scalar["renders"][0]["seconds"]), fmt_s(best(scalar)), "—",
         f"{pw['wall'] / best(scalar):.2f}"],
        ["Mitsuba llvm_ad_rgb, cold kernel cache", fmt_s(cold["to_first_image"]),
         fmt_s(cold["to_scene"]), fmt_s(cold["renders"][0]["seconds"]), fmt_s(llvm_render), "—",
         f"{pw['wall'] / llvm_render:.2f}"],
        ["Mitsuba llvm_ad_rgb, kernels cached on disk", fmt_s(warm["to_first_image"]),
         fmt_s(warm["to_scene"]), fmt_s(warm["renders"][0]["seconds"]), "—", "—",
         f"{pw['wall'] / warm['renders'][0]['seconds']:.2f}"],
    ]
    rep.table("time", ["renderer", "launch → image s", "launch → ready s", "first render s",
                       "render s (warm)", "after render s", "Pathway process ÷ this render"],
              rows,
              f"Pathway: fastest of {a.repeats} processes; 'launch → image' is its whole process "
              "(launch to exit, EXR written), 'launch → ready' its first ray, 'after render' "
              "the EXR write and exit. Mitsuba: 'launch → image' from the process's launch to "
              "its first image in memory (python start, import, scene, first render), 'launch → "
              "ready' to the scene loaded, 'render s (warm)' the fastest later render in the same "
              "process (llvm: its kernel compiled). Last column: Pathway's whole process over "
              "that renderer's warm render.")
    ratios = [
        ["Pathway whole process / Mitsuba llvm render (goal ≤ 0.6)",
         f"{pw['wall'] / llvm_render:.2f}"],
        ["Pathway render / Mitsuba llvm render", f"{pw['render'] / llvm_render:.2f}"],
        ["Pathway whole process / Mitsuba llvm process to first image (cold cache)",
         f"{pw['wall'] / cold['to_first_image']:.2f}"],
        ["Pathway whole process / Mitsuba llvm process to first image (cached kernels)",
         f"{pw['wall'] / warm['to_first_image']:.2f}"],
        ["Pathway whole process / Mitsuba scalar render", f"{pw['wall'] / best(scalar):.2f}"],
        ["Mitsuba llvm JIT: first render − warm render (cold cache) s",
         fmt_s(cold["renders"][0]["seconds"] - llvm_render)],
        ["Pathway outside the render: whole process − render s",
         f"{fmt_s(pw['wall'] - pw['render'])} ({100 * (1 - pw['render'] / pw['wall']):.0f} %)"],
    ]
    floor = traversal_floor(a)
    if floor:
        ratios += [
            ["Embree's traversal of stage5@fast's rays alone (robust BVH) / Mitsuba llvm render",
             f"{floor['robust'] / llvm_render:.2f}"],
            ["the same, non-robust BVH / Mitsuba llvm render",
             f"{floor['non-robust'] / llvm_render:.2f}"],
        ]
    rep.table("time_ratios", ["ratio", "value"], ratios,
              "The last two rows (when the settings are stage 5's defaults): `pathway_bench "
              "floor` replays every ray stage5@fast traces for this image through raw Embree in "
              "its 16-ray packets, on all threads, with nothing else: what these rays cost "
              "before any shading, sampling or film." if floor else None)

    def best_cpu(report):
        return min(r["cpu"] for r in report["renders"][1:])

    def first_image_cpu(report):  # the process less its later renders
        return report["process_cpu"] - sum(r["cpu"] for r in report["renders"][1:])

    pw_cpu = min(r["cpu"] for r in runs)
    cpu_rows = [
        [f"Pathway {a.integrator}", f"{pw_cpu:.2f}", "—", "1.00"],
        ["Mitsuba scalar_rgb", f"{first_image_cpu(scalar):.2f}", f"{best_cpu(scalar):.2f}",
         f"{pw_cpu / best_cpu(scalar):.2f}"],
        ["Mitsuba llvm_ad_rgb, cold kernel cache", f"{first_image_cpu(cold):.2f}",
         f"{best_cpu(cold):.2f}", f"{pw_cpu / best_cpu(cold):.2f}"],
        ["Mitsuba llvm_ad_rgb, kernels cached on disk", f"{warm['process_cpu']:.2f}", "—",
         f"{pw_cpu / warm['process_cpu']:.2f}"],
    ]
    rep.table("time_cpu", ["renderer", "process CPU s (to first image)", "render CPU s (warm)",
                           "Pathway process CPU ÷ this"], cpu_rows,
              "CPU seconds, user + system, all threads: what the work costs whatever else runs "
              "on the machine (wall times above stretch when the cores are shared). Pathway's is "
              "its whole process, the least of its runs; Mitsuba's warm render from "
              "time.process_time() around mi.render; the last column divides by the warm render "
              "where there is one, else by the whole process.")
    images = {"Pathway": pw["image"], "Mitsuba scalar_rgb": scalar["images"]["img"],
              "Mitsuba llvm_ad_rgb": cold["images"]["img"]}
    return images, {"pathway": pw, "llvm_render": llvm_render, "scalar": scalar, "cold": cold,
                    "warm": warm}


def section_depth(rep, run, args):
    a = args
    depths = sorted({0, 1, 2, a.max_depth})
    w, seeds = a.agree_width, range(8)
    rep.say(f"## 2. Depth mapping: Pathway max-depth d against Mitsuba max_depth d + 1 and d "
            f"({w}x{w}, 8 x {a.depth_spp} spp each)")
    rep.say()
    mitsuba_depths = sorted({m for d in depths for m in (d, d + 1) if m >= 1})
    renders = [{"spp": a.depth_spp, "seed": s, "max_depth": m, "save": f"{m}/{s}"}
               for m in mitsuba_depths for s in seeds]
    mts = run.mitsuba(LLVM, renders, w, max_depth=mitsuba_depths[0])["images"]
    rows, ok = [], True
    for d in depths:
        p_mean, p_se = mean_and_se([run.pathway(a.depth_spp, 100 + s, w, d)["image"]
                                    .mean(axis=(0, 1)) for s in seeds])
        row = [d, " ".join(f"{v:.4f}" for v in p_mean)]
        for m in (d + 1, d):
            if m < 1:
                row.append("— (black)")
                continue
            m_mean, m_se = mean_and_se([mts[f"{m}/{s}"].mean(axis=(0, 1)) for s in seeds])
            diff, se = rel_diff(p_mean, p_se, m_mean, m_se)
            worst = int(np.argmax(np.abs(diff)))
            row.append(f"{pct(diff[worst])} ± {100 * se[worst]:.2f} %")
            if m == d + 1:
                ok &= bool(np.all(np.abs(diff) <= 0.01))
        rows.append(row)
    rep.table("depth", ["Pathway max-depth", "Pathway channel means", "vs Mitsuba d + 1",
                        "vs Mitsuba d"], rows,
              "Largest relative difference of the channel means (Pathway / Mitsuba − 1), with "
              f"its standard error from the spread of 8 independent renders each. Mapping d → "
              f"d + 1 {'holds' if ok else 'FAILS'} (every channel within 1 %).")
    return ok


def section_agreement(rep, run, args, timed_images):
    a = args
    w, k, spp = a.agree_width, a.agree_seeds, a.agree_spp
    rep.say(f"## 3. Image agreement: {k} independent renders of {w}x{w} at {spp} spp per "
            f"renderer ({k * spp} spp in all)")
    rep.say()
    pws = [run.pathway(spp, 200 + s, w)["image"] for s in range(k)]
    mts = run.mitsuba(LLVM, [{"spp": spp, "seed": 200 + s, "save": str(s)} for s in range(k)],
                      w)["images"]
    mts = [mts[str(s)] for s in range(k)]
    rows, ok = [], True
    # Global channel means, and a 4 x 4 grid of regions, each a sixteenth of the image.
    for name, grid, limit in (("global channel means", 1, 0.01), ("4x4 regions", 4, 0.03)):
        p, p_se = mean_and_se([regions(x, grid) for x in pws])
        m, m_se = mean_and_se([regions(x, grid) for x in mts])
        diff, se = rel_diff(p, p_se, m, m_se)
        worst = np.unravel_index(np.argmax(np.abs(diff)), diff.shape)
        passed = bool(np.max(np.abs(diff)) <= limit)
        ok &= passed
        rows.append([name, f"{diff.size}", pct(diff[worst]), f"{100 * se[worst]:.2f} %",
                     f"{100 * se.max():.2f} %", f"{100 * limit:.0f} %",
                     "pass" if passed else "FAIL"])
    # Finer: 4x4-pixel blocks, for information: too noisy for a 3 % bound, so judged by t.
    fine = w // 4
    p, p_se = mean_and_se([regions(x, fine) for x in pws])
    m, m_se = mean_and_se([regions(x, fine) for x in mts])
    noisy = (p_se > 0) | (m_se > 0)  # a block black in every render has no t
    p, p_se, m, m_se = p[noisy], p_se[noisy], m[noisy], m_se[noisy]
    t = (p - m) / np.sqrt(p_se ** 2 + m_se ** 2)
    # Welch-Satterthwaite degrees of freedom, per block and channel.
    dof = (p_se ** 2 + m_se ** 2) ** 2 / ((p_se ** 4 + m_se ** 4) / (k - 1))
    family_p = 1.0 - (1.0 - np.min(t_two_sided_p(t, dof))) ** t.size  # Sidak: any of them
    diff, se = rel_diff(p, p_se, m, m_se)
    worst = np.unravel_index(np.argmax(np.abs(diff)), diff.shape)
    rows.append([f"4x4-pixel blocks ({fine}x{fine})", f"{diff.size}", pct(diff[worst]),
                 f"{100 * se[worst]:.2f} %", f"{100 * se.max():.2f} %", "—",
                 f"max abs t {np.max(np.abs(t)):.2f}, p {family_p:.2f}"])
    rep.table("agreement", ["comparison (Pathway / Mitsuba llvm − 1)", "values",
                            "worst difference", "its std. error", "largest std. error", "limit",
                            "result"], rows,
              "Standard errors from the spread of the independent renders (relative, first "
              "order, both renderers' added). A limit is only meaningful where the largest "
              "standard error is far below it. The 4x4-pixel blocks are too noisy for a 3 % "
              "bound; they are reported by their largest |t| (Welch) and the chance p of a "
              f"|t| that large among all {diff.size} blocks and channels (Šidák) when both "
              "renderers have the same expected image: a small p (< 0.001) would show a "
              "local difference.")
    if not timed_images:
        return ok
    # The timed images too: same settings, so their global means must agree as well.
    ref = timed_images["Pathway"].mean(axis=(0, 1))
    timed = []
    for name, image in timed_images.items():
        means = image.mean(axis=(0, 1))
        d = means / ref - 1
        timed.append([name, " ".join(f"{v:.4f}" for v in means),
                      pct(d[np.argmax(np.abs(d))])])
        ok &= bool(np.all(np.abs(d) <= 0.01))
    rep.table("agreement_timed", [f"timed image ({a.width}², {a.spp} spp)", "channel means",
                                  "worst vs Pathway"], timed)
    return ok


def t_two_sided_p(t, dof):
    """P(|T| > |t|) for Student's t with `dof` degrees of freedom (arrays), by integrating the
    density numerically (numpy only: no scipy in the venv)."""
    t, dof = np.abs(np.ravel(t))[:, None], np.ravel(dof)[:, None]
    x = t + np.linspace(0.0, 1.0, 4001)[None, :] ** 3 * 400.0  # dense near |t|, far into the tail
    log_c = (np.vectorize(math.lgamma)((dof + 1) / 2) - np.vectorize(math.lgamma)(dof / 2)
             - 0.5 * np.log(dof * math.pi))
    density = np.exp(log_c - (dof + 1) / 2 * np.log1p(x ** 2 / dof))
    tail = np.sum(0.5 * (density[:, 1:] + density[:, :-1]) * np.diff(x, axis=1), axis=1)
    return np.clip(2.0 * tail, 0.0, 1.0)


def loglog_at(times, errors, t):
    """relMSE at time t, linear in log-log between the measured points (None outside them)."""
    lt, le = np.log(times), np.log(errors)
    order = np.argsort(lt)
    lt, le = lt[order], le[order]
    if not lt[0] <= math.log(t) <= lt[-1]:
        return None
    return float(np.exp(np.interp(math.log(t), lt, le)))


def curve_seed(spp, r):
    """Seeds of the curve's renders: apart from every other section's and the reference's."""
    return 10000 + 10 * spp + r


def section_equal_time(rep, run, args):
    a = args
    w = a.width
    rep.say(f"## 4. Equal time: relMSE against a reference ({w}x{w}; the reference averages "
            f"Pathway and Mitsuba llvm at {a.ref_spp} spp each)")
    rep.say()
    pw_ref = run.pathway(a.ref_spp, 1000, w)["image"]
    chunk = min(a.spp, a.ref_spp)
    renders = [{"spp": a.curve_spp[0], "seed": 999}]  # warm-up: compiles the kernel
    # One more spp at each end, so that Pathway's times fall within Mitsuba's measured ones.
    mt_spp = sorted({max(1, a.curve_spp[0] // 2), *a.curve_spp, 2 * a.curve_spp[-1]})
    for spp in mt_spp:
        renders += [{"spp": spp, "seed": curve_seed(spp, r), "save": f"{spp}/{r}"}
                    for r in range(2)]
    renders += [{"spp": chunk, "seed": 1000 + i, "save": "ref"}
                for i in range(a.ref_spp // chunk)]
    saves = [r.get("save") for r in renders]  # run.mitsuba renames them to files
    m = run.mitsuba(LLVM, renders, w)
    reference = 0.5 * (pw_ref + m["images"]["ref"])
    # The reference's own noise adds to every measured relMSE; with no bias between the two
    # halves, (P - M)^2 / 4 estimates it per pixel, and it is subtracted.
    ref_noise = rel_mse(pw_ref, m["images"]["ref"]) / 4.0
    def mitsuba_runs(spp):  # the curve's own renders at spp: not the warm-up, not the reference
        return [r for r, save in zip(m["renders"], saves) if save in (f"{spp}/0", f"{spp}/1")]

    pw_points, mt_points = {}, {}
    for spp in a.curve_spp:
        runs = [run.pathway(spp, curve_seed(spp, r), w) for r in range(2)]
        pw_points[spp] = {"wall": min(r["wall"] for r in runs),
                          "render": min(r["render"] for r in runs),
                          "cpu": min(r["cpu"] for r in runs),
                          "error": np.mean([rel_mse(r["image"], reference) for r in runs])
                          - ref_noise}
    for spp in mt_spp:
        mt_points[spp] = {"wall": min(r["seconds"] for r in mitsuba_runs(spp)),
                          "cpu": min(r["cpu"] for r in mitsuba_runs(spp)),
                          "error": np.mean([rel_mse(m["images"][f"{spp}/{r}"], reference)
                                            for r in range(2)]) - ref_noise}
    mt_e = np.array([p["error"] for p in mt_points.values()])

    def ratio_at(pw, pw_key, mt_key):
        """Pathway's relMSE over Mitsuba's at Pathway's time (None outside Mitsuba's times)."""
        at = loglog_at(np.array([p[mt_key] for p in mt_points.values()]), mt_e, pw[pw_key])
        return pw["error"] / at if at else None

    def show(x):
        return f"{x:.2f}" if x else "—"

    rows, ratios = [], {"wall": [], "render": [], "cpu": []}
    for spp in mt_spp:
        mt = mt_points[spp]
        if spp not in pw_points:
            rows.append([spp, "—", "—", "—", fmt_s(mt["wall"]), fmt_s(mt["cpu"]),
                         f"{mt['error']:.3e}", "—", "—"])
            continue
        pw = pw_points[spp]
        by = {"wall": ratio_at(pw, "wall", "wall"), "render": ratio_at(pw, "render", "wall"),
              "cpu": ratio_at(pw, "cpu", "cpu")}
        for key, value in by.items():
            if value:
                ratios[key].append(value)
        rows.append([spp, fmt_s(pw["wall"]), fmt_s(pw["cpu"]), f"{pw['error']:.3e}",
                     fmt_s(mt["wall"]), fmt_s(mt["cpu"]), f"{mt['error']:.3e}",
                     show(by["wall"]), show(by["cpu"])])
    rep.table("equal_time", ["spp", "Pathway process s", "Pathway CPU s", "Pathway relMSE",
                             "Mitsuba llvm render s", "Mitsuba CPU s", "Mitsuba relMSE",
                             "ratio at equal wall time", "ratio at equal CPU time"], rows,
              f"relMSE = mean over pixels and channels of (x − ref)² / (ref² + 0.01), mean of 2 "
              f"renders, less the reference's own noise ({ref_noise:.2e}). Pathway: its whole "
              "process (wall and CPU), the least of 2; Mitsuba llvm: its render in a process "
              "whose kernel is compiled, the least of 2. Ratio = Pathway's relMSE over "
              "Mitsuba's at the same time, Mitsuba's interpolated linearly in log-log "
              "('—': outside Mitsuba's measured times).")

    def geo(values):
        return float(np.exp(np.mean(np.log(values)))) if values else float("nan")

    rep.table("equal_time_summary", ["equal-time relMSE ratio, Pathway / Mitsuba llvm",
                                     "geometric mean over spp"],
              [["Pathway whole process vs Mitsuba render, wall time (goal ≤ 0.5)",
                f"{geo(ratios['wall']):.2f}"],
               ["Pathway render only vs Mitsuba render, wall time",
                f"{geo(ratios['render']):.2f}"],
               ["Pathway whole process vs Mitsuba render, CPU time", f"{geo(ratios['cpu']):.2f}"]])
    return geo(ratios["wall"])


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
