"""One Mitsuba 3 process of the peers benchmark: loads a glTF scene, renders a list of images.

Run by peers.py as a child so that each variant starts fresh (its own process time, its own
kernel cache) exactly as a user's script would. The job is one JSON argument:

    {"variant": "llvm_ad_rgb", "scene": "scenes/cornell_box.gltf", "width": 256, "height": 256,
     "max_depth": 6, "rr_depth": 3,
     "renders": [{"spp": 64, "seed": 0, "save": "a.npy"}, {"spp": 64, "seed": 1}, ...]}

A render may name its own "max_depth" (one scene is built per depth, on first use).

Renders that name the same `save` file are averaged (weighted by spp) into it, so a reference
of many passes costs one file. Prints one JSON object: monotonic times (ns) of the import, the
scene load and each render's end, and each render's own seconds and CPU seconds. PEERS_LAUNCH_NS, when set,
is the monotonic time at which the parent started this process.
"""
import json
import os
import pathlib
import sys
import time

launch_ns = int(os.environ.get("PEERS_LAUNCH_NS", time.monotonic_ns()))
job = json.loads(sys.argv[1])

import numpy as np  # noqa: E402  (imported after the clock started: their cost is measured)
import mitsuba as mi  # noqa: E402

mi.set_variant(job["variant"])
sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))
import gltf_to_mitsuba  # noqa: E402

report = {"launch_ns": launch_ns, "imported_ns": time.monotonic_ns(), "renders": []}
gltf = gltf_to_mitsuba.read_gltf(job["scene"])
scenes = {}


def scene_for(max_depth):
    if max_depth not in scenes:
        scenes[max_depth] = mi.load_dict(gltf_to_mitsuba.mitsuba_scene(
            mi, gltf, job["width"], job["height"], job["renders"][0]["spp"], max_depth,
            job["rr_depth"]))
    return scenes[max_depth]


scene_for(job["max_depth"])
report["scene_ns"] = time.monotonic_ns()

sums = {}  # save path -> [sum of spp-weighted images, total spp]
for r in job["renders"]:
    scene = scene_for(r.get("max_depth", job["max_depth"]))
    start, cpu = time.perf_counter(), time.process_time()
    # np.array forces the evaluation: in JIT variants mi.render only records the computation.
    image = np.array(mi.render(scene, spp=r["spp"], seed=r["seed"]), dtype=np.float64)
    seconds = time.perf_counter() - start
    report["renders"].append({"spp": r["spp"], "seed": r["seed"], "seconds": seconds,
                              "cpu": time.process_time() - cpu,  # all threads
                              "done_ns": time.monotonic_ns()})
    if "save" in r:
        entry = sums.setdefault(r["save"], [0.0, 0])
        entry[0] = entry[0] + image[..., :3] * r["spp"]
        entry[1] += r["spp"]
for path, (total, spp) in sums.items():
    np.save(path, (total / spp).astype(np.float32))
print(json.dumps(report))
