"""The two renderers as the benchmark runs them: a `pathway render` process, or a Mitsuba process
(mitsuba_worker.py) rendering a list of images; each timed from its launch, wall and CPU."""
import json
import os
import pathlib
import re
import resource
import subprocess
import sys
import time

import numpy as np

HERE = pathlib.Path(__file__).resolve().parent
LLVM, SCALAR = "llvm_ad_rgb", "scalar_rgb"


def children_cpu():
    """CPU seconds (user + system) of the children waited for so far: one child's is the
    difference around it. CPU time barely depends on how busy the machine is; wall time does."""
    usage = resource.getrusage(resource.RUSAGE_CHILDREN)
    return usage.ru_utime + usage.ru_stime


def read_exr(path):
    """RGB of a Pathway EXR (its other channels are variance and weight), read by Mitsuba."""
    import mitsuba as mi
    if mi.variant() is None:
        mi.set_variant(SCALAR)
    return np.array(mi.Bitmap(str(path)), dtype=np.float64)[..., :3]


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
