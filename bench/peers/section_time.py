"""Section 1, time: Pathway's process and render against Mitsuba scalar_rgb and llvm_ad_rgb
(cold and cached kernels) on the timed image, in wall and CPU seconds, with the traversal floor
where it applies."""
import os
import pathlib
import re
import subprocess
import sys
import tempfile

from renderers import LLVM, SCALAR
from report_tables import fmt_s


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
