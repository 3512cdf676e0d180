#!/usr/bin/env python3
"""Draws the tables of `pathway_bench growth --out DIR` as charts, PNG and SVG, into DIR.

    python3 scripts/draw_growth.py DIR

Reads DIR/machine.csv, stages.csv, threads.csv, spp.csv and bvh.csv (written by the benchmark)
and writes DIR/stages, threads, spp and bvh (.png and .svg). Needs matplotlib and numpy
(Debian: python3-matplotlib, which scripts/install-deps installs).
"""

import csv
import os
import sys
import textwrap

import matplotlib

matplotlib.use("Agg")  # files only, no display
import matplotlib.pyplot as plt  # noqa: E402
import matplotlib.ticker as ticker  # noqa: E402
import numpy as np  # noqa: E402

RENDERER = "#1f77b4"
RAW = "#ff7f0e"
EXTRA = ["#2ca02c", "#d62728", "#9467bd"]


def read_csv(folder, name):
    path = os.path.join(folder, name)
    try:
        with open(path, newline="") as f:
            return list(csv.DictReader(f))
    except OSError as error:
        sys.exit(f"draw_growth: {path}: {error.strerror} "
                 "(run `pathway_bench growth --out DIR` first)")


def machine_line(folder):
    info = {row["key"]: row["value"] for row in read_csv(folder, "machine.csv")}
    return (f"{info.get('cpu', '?')}, {info.get('cores', '?')} cores, "
            f"load average {float(info.get('load_average', 'nan')):.1f} at the start, "
            f"Embree {info.get('embree', '?')}, {info.get('date', '')}")


def save(fig, folder, name):
    fig.tight_layout()
    for ext in ("png", "svg"):
        fig.savefig(os.path.join(folder, f"{name}.{ext}"), dpi=130)
    plt.close(fig)
    print(os.path.join(folder, f"{name}.png"))


def title(fig, what, machine):
    # About 13 characters of an 11-point title per inch of figure.
    columns = int(fig.get_figwidth() * 13)
    lines = textwrap.wrap(what, columns) + textwrap.wrap(machine, columns)
    fig.suptitle("\n".join(lines), fontsize=11)


def stage_labels(rows):
    # "stage5@ref nee=off" -> two lines, so that the bars' labels do not collide.
    return [row["integrator"].replace(" ", "\n") for row in rows]


def draw_stages(folder, machine, info):
    rows = read_csv(folder, "stages.csv")
    x = np.arange(len(rows))
    renderer = [float(r["mrays_per_s"]) for r in rows]
    raw = [float(r["raw_mrays_per_s"]) for r in rows]
    fig, ax = plt.subplots(figsize=(9, 4.8))
    width = 0.38
    ax.bar(x - width / 2, renderer, width, label="renderer (whole stage)", color=RENDERER)
    ax.bar(x + width / 2, raw, width, label="raw Embree, the same rays", color=RAW)
    for i, row in enumerate(rows):
        ax.annotate(f"{float(row['ratio']):.2f}×", (x[i] - width / 2, renderer[i]),
                    textcoords="offset points", xytext=(0, 3), ha="center", fontsize=9)
    ax.set_xticks(x, stage_labels(rows))
    ax.set_ylabel("million rays per second")
    ax.set_ylim(0, max(raw + renderer) * 1.15)
    ax.legend(loc="upper right", fontsize=9)
    ax.grid(axis="y", alpha=0.3)
    title(fig, f"Each stage against raw Embree on its own recorded rays ({info['scene']}, "
               f"{info['width']}² px, all cores; label: renderer / raw)", machine)
    save(fig, folder, "stages")


def draw_threads(folder, machine, _info):
    rows = read_csv(folder, "threads.csv")
    low, high = rows[0]["threads_low"], rows[0]["threads_high"]
    x = np.arange(len(rows))
    fig, (rates, speedups) = plt.subplots(1, 2, figsize=(12, 4.8),
                                          gridspec_kw={"width_ratios": [3, 2]})
    width = 0.2
    series = [("mrays_per_s_low", f"renderer, {low} thread", RENDERER, 0.45),
              ("mrays_per_s_high", f"renderer, {high} threads", RENDERER, 1.0),
              ("raw_mrays_per_s_low", f"raw Embree, {low} thread", RAW, 0.45),
              ("raw_mrays_per_s_high", f"raw Embree, {high} threads", RAW, 1.0)]
    for k, (key, label, color, alpha) in enumerate(series):
        rates.bar(x + (k - 1.5) * width, [float(r[key]) for r in rows], width, label=label,
                  color=color, alpha=alpha)
    rates.set_xticks(x, stage_labels(rows))
    rates.set_ylabel("million rays per second")
    rates.legend(fontsize=8, ncol=2, loc="upper right")
    rates.set_ylim(0, max(float(r[s[0]]) for r in rows for s in series) * 1.25)
    rates.grid(axis="y", alpha=0.3)
    rates.set_title("rays per second")

    width = 0.38
    speedups.bar(x - width / 2, [float(r["speedup"]) for r in rows], width, label="renderer",
                 color=RENDERER)
    speedups.bar(x + width / 2, [float(r["raw_speedup"]) for r in rows], width,
                 label="raw Embree", color=RAW)
    ideal = int(high) / int(low)
    speedups.axhline(ideal, color="grey", linestyle="--", linewidth=1)
    speedups.text(len(rows) - 0.5, ideal, f"ideal {ideal:g}×", ha="right", va="bottom",
                  fontsize=8, color="grey")
    speedups.axhline(1.0, color="black", linewidth=0.8)
    speedups.set_xticks(x, stage_labels(rows), fontsize=8, rotation=30, ha="right")
    speedups.set_ylabel(f"speed-up, {high} threads over {low}")
    speedups.set_ylim(0, max(ideal, *(float(r["speedup"]) for r in rows)) * 1.2)
    speedups.legend(fontsize=8, loc="upper left")
    speedups.grid(axis="y", alpha=0.3)
    speedups.set_title("speed-up")
    title(fig, f"Thread scaling: renderer with threads = {low} and {high}, raw Embree replay in a "
               f"{low}- and a {high}-thread arena", machine)
    save(fig, folder, "threads")


def draw_spp(folder, machine, info):
    rows = read_csv(folder, "spp.csv")
    fig, ax = plt.subplots(figsize=(8.5, 5.5))
    integrators = list(dict.fromkeys(r["integrator"] for r in rows))
    for k, name in enumerate(integrators):
        mine = [r for r in rows if r["integrator"] == name]
        spp = np.array([float(r["spp"]) for r in mine])
        seconds = np.array([float(r["seconds"]) for r in mine])
        slope = np.polyfit(np.log(spp), np.log(seconds), 1)[0]
        color = [RENDERER, RAW, *EXTRA][k % 5]
        ax.loglog(spp, seconds, "o-", color=color, label=f"{name}: fitted exponent {slope:.2f}")
        # Slope 1 through the largest render: where a linear cost would put the others.
        ax.loglog(spp, seconds[-1] * spp / spp[-1], ":", color=color, linewidth=1)
    ax.plot([], [], ":", color="grey", label="slope 1 (linear), through the last point")
    ax.set_xscale("log", base=2)
    ax.set_xticks(spp, [f"{int(s)}" for s in spp])
    ax.set_xlabel("samples per pixel")
    ax.set_ylabel("seconds per render (best of the repeats)")
    ax.grid(which="both", alpha=0.3)
    ax.legend(fontsize=9)
    side = info["spp_width"]
    title(fig, f"Cost against samples per pixel: whole renders of {info['scene']} at "
               f"{side}×{side}, all cores", machine)
    save(fig, folder, "spp")


def draw_bvh(folder, machine, info):
    rows = read_csv(folder, "bvh.csv")
    n = np.array([float(r["triangles"]) for r in rows])

    def column(key):
        return np.array([float(r[key]) for r in rows])

    fig, axes = plt.subplots(2, 2, figsize=(12, 8.5))
    build, memory, rate, latency = axes.flat

    build.loglog(n, column("build_s"), "o-", color=RENDERER, label="RayTracer construction")
    build.loglog(n, column("raw_build_s"), "s--", color=RAW, label="raw Embree build")
    build.loglog(n, column("hash_s"), "^:", color=EXTRA[0], label="of which: scene content hash")
    build.loglog(n, column("build_s")[-1] * n / n[-1], color="grey", linewidth=0.8,
                 label="slope 1 (linear), through the last point")
    build.set_ylabel("seconds")
    build.set_title("BVH build time")

    memory.semilogx(n, column("embree_bvh_bytes_per_triangle"), "o-", color=RENDERER,
                    label="BVH, Embree's own count")
    memory.semilogx(n, column("resident_bvh_bytes_per_triangle"), "s--", color=RAW,
                    label="BVH, resident (RSS) growth")
    memory.semilogx(n, column("resident_scene_bytes_per_triangle"), "^:", color=EXTRA[0],
                    label="scene arrays, resident")
    memory.semilogx(n, column("peak_resident_bytes_per_triangle"), "d-.", color=EXTRA[1],
                    label="peak resident, scene + build")
    memory.set_ylabel("bytes per triangle")
    memory.set_yscale("log")
    memory.yaxis.set_major_locator(ticker.FixedLocator([10, 20, 50, 100, 200, 500]))
    memory.yaxis.set_major_formatter(ticker.ScalarFormatter())
    memory.yaxis.set_minor_formatter(ticker.NullFormatter())
    memory.set_title("memory per triangle (fixed costs dominate small scenes)")

    rate.semilogx(n, column("mrays_per_s"), "o-", color=RENDERER, label="RayTracer::intersect")
    rate.semilogx(n, column("raw_mrays_per_s"), "s--", color=RAW, label="raw rtcIntersect1")
    rate.set_ylabel("million primary rays per second")
    rate.set_ylim(bottom=0)
    rate.set_title("primary-ray rate")

    for key, label, color, marker in (("mrays_per_s", "RayTracer::intersect", RENDERER, "o"),
                                      ("raw_mrays_per_s", "raw rtcIntersect1", RAW, "s")):
        ns = 1e3 / column(key)
        slope, intercept = np.polyfit(np.log2(n), ns, 1)
        latency.semilogx(n, ns, marker, color=color, label=f"{label}: +{slope:.0f} ns per doubling")
        latency.semilogx(n, intercept + slope * np.log2(n), "--", color=color, linewidth=1)
    latency.set_ylabel("nanoseconds per primary ray")
    latency.set_ylim(bottom=0)
    latency.set_title("time per primary ray (dashed: fitted a + b·log₂ n)")

    for ax in axes.flat:
        ax.set_xlabel("triangles (generated height-field grid)")
        ax.grid(which="both", alpha=0.3)
        ax.legend(fontsize=8)
    # What the rays walk through, under each size: the BVH (Embree's count) and the scene arrays.
    megabytes = (column("embree_bvh_bytes_per_triangle") +
                 column("resident_scene_bytes_per_triangle")) * n / 2**20
    latency.set_xticks(n, [f"{count:,.0f}\n{mb:.3g} MB" for count, mb in zip(n, megabytes)],
                       fontsize=8)
    latency.xaxis.set_minor_formatter(ticker.NullFormatter())
    latency.set_xlabel("triangles, and BVH + scene arrays in memory")
    title(fig, "How the BVH grows: build time, memory and ray cost from 10k triangles up "
               f"(each size in a fresh process; caches {info.get('caches', 'unknown')})", machine)
    save(fig, folder, "bvh")


def main():
    if len(sys.argv) != 2:
        sys.exit("usage: draw_growth.py DIR   (DIR: the --out folder of `pathway_bench growth`)")
    folder = sys.argv[1]
    machine = machine_line(folder)
    info = {row["key"]: row["value"] for row in read_csv(folder, "machine.csv")}
    for draw in (draw_stages, draw_threads, draw_spp, draw_bvh):
        draw(folder, machine, info)


if __name__ == "__main__":
    main()
