#!/usr/bin/python3
"""The lecture deck's own figures, drawn at the size the slides show them (slides/lecture.md).

    draw_slides.py [--only NAME ...]

Every figure is laid out in inches at SHOWN_DPI, the pixels per inch of a 1280x720 slide, so
a font size in points maps to a fixed size on the projector (14 pt = 19.4 px; nothing below
13 pt = 18 px), and slides/lecture.md gives each one its width in px (figsize x SHOWN_DPI). The
PNGs are written at twice that resolution for sharpness.

Three kinds, all from real data:
  - derivations (filters, sinc, splat, samples, ray tree, NEE): the stage 1 filter profiles as
    the program tabulates them (slides/figures/filters/filter_profiles.csv), and sample points
    drawn here (Owen-scrambled Sobol' and independent, seeded, so every run draws the same);
  - measurements, re-drawn large from the summary.json files of `pathway chart` (scripts/charts
    makes those; scripts/draw_chart.py draws the full, detailed versions for the docs);
  - viewer screenshots cropped to their image panes (no UI, no file paths), labelled large.
Writes slides/figures/<topic>/<name>.png. See scripts/slides, which runs this.
"""
import argparse
import csv
import json
import os

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402  (the backend must be chosen first)
import numpy as np  # noqa: E402
from PIL import Image  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
FIGURES = os.path.join(ROOT, "slides", "figures")
SHOWN_DPI = 100  # 1 inch of figure = 100 px of the 1280x720 slide
SMALLEST_PT = 13  # 13 pt at 100 dpi is 18 px, the smallest text allowed on a slide
COLOURS = ["#1f77b4", "#ff7f0e", "#2ca02c", "#d62728", "#9467bd", "#8c564b"]
GREY = "0.45"

plt.rcParams.update({
    "font.size": 16, "axes.titlesize": 17, "axes.labelsize": 16, "xtick.labelsize": 14,
    "ytick.labelsize": 14, "legend.fontsize": 14, "figure.titlesize": 18,
    "axes.spines.top": False, "axes.spines.right": False, "lines.linewidth": 2.4,
    "svg.fonttype": "none",
})


def figure(width_px, height_px, **kwargs):
    return plt.subplots(figsize=(width_px / SHOWN_DPI, height_px / SHOWN_DPI),
                        layout="constrained", **kwargs)


def check_fonts(fig):
    """Refuses text below SMALLEST_PT, so a figure cannot quietly become unreadable again."""
    for text in fig.findobj(matplotlib.text.Text):
        if text.get_text().strip() and text.get_visible() and text.get_fontsize() < SMALLEST_PT:
            raise SystemExit(f"draw_slides.py: text {text.get_text()!r} is "
                             f"{text.get_fontsize():g} pt, below {SMALLEST_PT} pt (18 px)")


def save(fig, topic, name):
    check_fonts(fig)
    folder = os.path.join(FIGURES, topic)
    os.makedirs(folder, exist_ok=True)
    path = os.path.join(folder, f"{name}.png")
    # No bbox_inches="tight": the saved size must stay the size the slide shows.
    fig.savefig(path, dpi=2 * SHOWN_DPI, metadata={"Software": None})
    plt.close(fig)
    print(f"wrote {os.path.relpath(path, ROOT)}")


def load(topic):
    with open(os.path.join(FIGURES, topic, "summary.json"), encoding="utf-8") as f:
        return json.load(f)


# ---- Sample points: Sobol' (Joe and Kuo's first four dimensions), Owen-scrambled. ----

def sobol(n, dimensions=4):
    """The first n points of the Sobol' sequence in up to 4 dimensions, as 32-bit integers."""
    polynomials = [None, (1, 0, [1]), (2, 1, [1, 3]), (3, 1, [1, 3, 1])]  # (degree, a, m)
    directions = []
    for d in range(dimensions):
        v = [0] * 32
        if d == 0:
            v = [1 << (31 - k) for k in range(32)]
        else:
            s, a, m = polynomials[d]
            for k in range(s):
                v[k] = m[k] << (31 - k)
            for k in range(s, 32):
                v[k] = v[k - s] ^ (v[k - s] >> s)
                for j in range(1, s):
                    if (a >> (s - 1 - j)) & 1:
                        v[k] ^= v[k - j]
        directions.append(v)
    points = np.zeros((n, dimensions), dtype=np.uint64)
    for i in range(n):
        for d in range(dimensions):
            x, k, bits = 0, 0, i
            while bits:
                if bits & 1:
                    x ^= directions[d][k]
                bits >>= 1
                k += 1
            points[i, d] = x
    return points


def owen_scramble(points, seed):
    """Owen's scrambling: each bit flips by a random choice that depends on the bits above it
    (a hash of the prefix), so strata stay strata and every point is uniformly distributed."""
    out = np.zeros(points.shape)
    for d in range(points.shape[1]):
        for i, value in enumerate(points[:, d]):
            value, result = int(value), 0
            for bit in range(31, 7, -1):  # 24 bits are plenty for a picture
                prefix = value >> (bit + 1)
                flip = hash((seed, d, 31 - bit, prefix)) & 1  # hash of ints: deterministic
                result |= (((value >> bit) & 1) ^ flip) << bit
            out[i, d] = (result + 0.5 * (1 << 8)) / 2.0 ** 32
    return out


def sobol_points(n, dimensions, seed=7):
    return owen_scramble(sobol(n, dimensions), seed)


# ---- Pixel filters ----

def profiles():
    with open(os.path.join(FIGURES, "filters", "filter_profiles.csv"), encoding="utf-8") as f:
        rows = list(csv.DictReader(f))
    x = np.array([float(row["x"]) for row in rows])
    return x, {name: np.array([float(row[name]) for row in rows]) for name in rows[0]
               if name != "x"}


def filter_shapes():
    """Box, tent and Gaussian: one panel each, as stage 1 evaluates them."""
    x, values = profiles()
    fig, axes = figure(1100, 260, ncols=3, sharey=True)
    for axis, name, title, colour in zip(axes, ["box", "tent", "gaussian"],
                                         ["box", "tent", "Gaussian, σ = 0.5"],
                                         COLOURS):
        axis.plot(x, values[name], color=colour)
        axis.fill_between(x, values[name], color=colour, alpha=0.15)
        axis.axhline(0, color=GREY, linewidth=1)
        axis.set_title(title)
        axis.set_xlim(-2, 2)
        axis.set_xticks([-2, -1, 0, 1, 2])
        axis.set_xlabel("x (pixels from the centre)")
    axes[0].set_ylabel("f(x)")
    save(fig, "filters", "shapes")


def filter_mitchell():
    x, values = profiles()
    fig, axis = figure(520, 300)
    y = values["mitchell"]
    axis.plot(x, y, color=COLOURS[3])
    axis.fill_between(x, y, where=y < 0, color=COLOURS[3], alpha=0.35, label="negative lobes")
    axis.axhline(0, color=GREY, linewidth=1)
    axis.set_xlim(-2.2, 2.2)
    axis.set_xticks([-2, -1, 0, 1, 2])
    axis.set_xlabel("x (pixels from the centre)")
    axis.set_ylabel("f(x)")
    axis.legend(loc="upper right", frameon=False)
    save(fig, "filters", "mitchell")


def filter_sinc():
    """An ideal low-pass filter (sinc) against Mitchell on a step edge: sinc overshoots."""
    fig, (shape, edge) = figure(1100, 340, ncols=2)
    x = np.linspace(-6, 6, 2401)
    shape.plot(x, np.sinc(x), color=COLOURS[4], label="sinc")
    xm, values = profiles()
    shape.plot(xm, values["mitchell"], color=COLOURS[3], label="Mitchell")
    shape.axhline(0, color=GREY, linewidth=1)
    shape.set_xlim(-6, 6)
    shape.set_xlabel("x (pixels)")
    shape.set_title("sinc: no end, lobes of both signs")
    shape.legend(frameon=False)
    # The step convolved with each filter, normalised: the filtered edge each one makes.
    t = np.linspace(-6, 6, 2401)
    step = (t > 0).astype(float)
    dt = t[1] - t[0]
    for name, kernel, colour in (("sinc (cut at ±30)", None, COLOURS[4]),
                                 ("Mitchell", "mitchell", COLOURS[3]),
                                 ("box", "box", COLOURS[0])):
        if kernel is None:
            k = np.linspace(-30, 30, 12001)
            f = np.sinc(k)
            wide = np.concatenate([np.zeros(6000), step, np.ones(6000)])
            response = np.convolve(wide, f[::-1], mode="same")[6000:6000 + len(t)] / f.sum()
        else:
            f = np.interp(np.arange(-2.5, 2.5 + dt / 2, dt), xm, values[kernel])
            response = np.convolve(np.concatenate([np.zeros(len(f)), step, np.ones(len(f))]),
                                   f[::-1], mode="same")[len(f):len(f) + len(t)] / f.sum()
        edge.plot(t, response, color=colour, label=name)
    edge.axhline(1, color=GREY, linewidth=1, linestyle=":")
    edge.axhline(0, color=GREY, linewidth=1, linestyle=":")
    edge.set_xlim(-5, 5)
    edge.set_xlabel("x (pixels from a hard edge)")
    edge.set_title("a filtered edge: sinc rings (Gibbs)")
    edge.legend(frameon=False, loc="upper left")
    save(fig, "filters", "sinc")


def splat():
    """One sample reaches every pixel whose filter covers it: the Gaussian (σ = 0.5, cut at 1.5),
    9 pixels. Each adds f·L to its numerator and f to its denominator; Σ f is not 1."""
    xs, values = profiles()

    def gaussian(t):
        return float(np.interp(t, xs, values["gaussian"]))

    fig, axis = figure(500, 470)
    sample = np.array([2.35, 2.7])
    total = 0.0
    for px in range(5):
        for py in range(5):
            cx, cy = px + 0.5, py + 0.5
            w = gaussian(sample[0] - cx) * gaussian(sample[1] - cy)
            if w != 0:
                total += w
                colour = COLOURS[0] if w > 0 else COLOURS[3]
                axis.add_patch(plt.Rectangle((px, py), 1, 1, color=colour,
                                             alpha=0.12 + min(abs(w), 0.8) * 0.7))
                axis.text(cx, cy - 0.2, f"{w:.2f}", ha="center", va="center", fontsize=16)
            else:
                axis.plot(cx, cy, "o", color="0.6", markersize=4)
    for i in range(6):
        axis.plot([i, i], [0, 5], color="0.75", linewidth=1)
        axis.plot([0, 5], [i, i], color="0.75", linewidth=1)
    axis.plot(*sample, "*", color="0.1", markersize=20)
    axis.set_xlim(0, 5)
    axis.set_ylim(0, 5)
    axis.set_aspect("equal")
    axis.axis("off")
    axis.set_title(f"Gaussian: 9 pixels reached, Σ f = {total:.2f}", fontsize=16)
    save(fig, "filters", "splat")


# ---- Nested against joint sampling ----

def unit_square(axis, ylim, xlabel, ylabel):
    """A scatter plot's frame: [0, 1] across, `ylim` up (room for marks below 0), equal scales."""
    axis.set_xlim(0, 1)
    axis.set_ylim(*ylim)
    axis.set_aspect("equal")
    axis.set_xticks([0, 1])
    axis.set_yticks([0, 1])
    axis.set_xlabel(xlabel)
    axis.set_ylabel(ylabel)


def scatter_1d1d():
    """16 samples of ∫∫ f(x, y) dy dx: nested (4 x's, 4 y's each) against one 2D point set."""
    rng = np.random.default_rng(3)
    fig, axes = figure(760, 360, ncols=2)
    xs = rng.random(4)
    nested = np.array([(x, rng.random()) for x in xs for _ in range(4)])
    joint = sobol_points(16, 2)
    for axis, points, title in ((axes[0], nested, "nested: pick x, then 4 y's"),
                                (axes[1], joint, "2D: 16 points (x, y), Sobol'")):
        axis.plot(points[:, 0], points[:, 1], "o", color=COLOURS[0], markersize=10)
        for v in points[:, 0]:
            axis.plot([v, v], [-0.06, -0.01], color=COLOURS[3], linewidth=2)
        unit_square(axis, (-0.07, 1.04), "x (outer)", "y (inner)")
        axis.set_title(f"{title}\n{len(set(np.round(points[:, 0], 9)))} distinct x")
    save(fig, "samples", "nested-vs-2d")


def scatter_4d():
    """64 rays as 32 two-ray samples of 4D AO: the screen position against the first AO number.
    Nested reuses each eye position for 4 directions; 4D Sobol' spreads the pairs."""
    rng = np.random.default_rng(5)
    fig, axes = figure(760, 360, ncols=2)
    eye = rng.random((8, 2))
    nested = np.array([(e[0], e[1], *rng.random(2)) for e in eye for _ in range(4)])
    joint = sobol_points(32, 4)
    for axis, points, title in ((axes[0], nested, "nested: 8 eyes × 4"),
                                (axes[1], joint, "4D Sobol': 32 × 1")):
        axis.plot(points[:, 0], points[:, 2], "o", color=COLOURS[0], markersize=9)
        unit_square(axis, (-0.03, 1.03), "x in the pixel", "u₁ of the direction")
        axis.set_title(title)
    save(fig, "samples", "ao-4d")


# ---- Recursion ----

def ray_tree():
    """Naive recursion with b = 3, d = 3, every ray hitting: 1 + 3 + 9 + 27 rays."""
    b, d = 3, 3
    fig, axis = figure(1100, 430)
    width = b ** d
    positions = {(): (width / 2 - 0.5, 0)}
    for level in range(1, d + 1):
        for index in range(b ** level):
            path = tuple(int(c) for c in np.base_repr(index, b).zfill(level))
            span = width / b ** level
            positions[path] = (index * span + span / 2 - 0.5, -level)
    for path, (x, y) in positions.items():
        if path:
            px, py = positions[path[:-1]]
            axis.plot([px, x], [py, y], color=COLOURS[len(path) % len(COLOURS)],
                      linewidth=3.2 - 0.6 * len(path))
    for path, (x, y) in positions.items():
        axis.plot(x, y, "o", color="0.2", markersize=9 - 1.5 * len(path))
    axis.plot(width / 2 - 0.5, 0.55, "s", color="0.2", markersize=14)
    axis.plot([width / 2 - 0.5, width / 2 - 0.5], [0.55, 0], color="0.2", linewidth=3)
    axis.text(width / 2 + 0.2, 0.55, "eye", va="center", fontsize=16)
    total = 1
    for level in range(0, d + 1):
        total_here = b ** level
        total = (b ** (level + 1) - 1) // (b - 1)
        power = str(level).translate(str.maketrans("0123456789", "⁰¹²³⁴⁵⁶⁷⁸⁹"))
        label = "eye ray: 1" if level == 0 else f"bounce {level}: {b}{power} = {total_here}"
        axis.text(width + 0.3, -level, f"{label}   (total {total})", va="center", fontsize=16)
    axis.set_xlim(-1, width + 9)
    axis.set_ylim(-d - 0.4, 0.9)
    axis.axis("off")
    axis.set_title(f"branching factor b = {b}, depth d = {d}: "
                   f"{(b ** (d + 1) - 1) // (b - 1)} rays for one camera sample", loc="left")
    save(fig, "recursion", "tree")


def nee_geometry():
    """The geometry of one shadow ray: a point x, a point y on the light, both cosines and r."""
    fig, axis = figure(440, 330)
    x, y = np.array([0.0, 0.0]), np.array([1.3, 2.0])
    axis.plot([-1.2, 2.6], [0, 0], color="0.3", linewidth=3)
    axis.plot([0.7, 2.2], [2.0, 2.0], color="#e8a500", linewidth=7)
    axis.text(2.25, 2.0, " light,\n area A", va="center", fontsize=15)
    axis.annotate("", y, x, arrowprops={"arrowstyle": "-", "color": COLOURS[0], "lw": 2.5})
    axis.annotate("", (0, 0.9), x, arrowprops={"arrowstyle": "->", "color": "0.3", "lw": 2})
    axis.annotate("", (1.3, 1.1), y, arrowprops={"arrowstyle": "->", "color": "0.3", "lw": 2})
    axis.text(0.05, 0.95, "n", fontsize=16)
    axis.text(1.35, 1.15, "n′", fontsize=16)
    axis.text(0.12, 0.5, "θ", fontsize=18)
    axis.text(1.13, 1.5, "θ′", fontsize=18)
    axis.text(0.75, 0.95, "r", fontsize=18, color=COLOURS[0])
    axis.plot(*x, "o", color="0.1", markersize=9)
    axis.plot(*y, "o", color="0.1", markersize=9)
    axis.text(-0.1, -0.25, "x", fontsize=18, va="top")
    axis.text(1.3, 2.12, "y, pdf 1/A", fontsize=16, ha="center", va="bottom")
    axis.set_xlim(-1.3, 3.3)
    axis.set_ylim(-0.6, 2.6)
    axis.set_aspect("equal")
    axis.axis("off")
    save(fig, "nee", "geometry")


# ---- Measurements, re-drawn large ----

def against_rays(topic, name, labels=None, title=None):
    """relMSE against rays per image (exact, comparable on any machine), one line per method."""
    summary = load(topic)
    fig, axis = figure(1000, 400)
    for index, line in enumerate(summary["lines"]):
        points = [p for p in line["points"] if p.get("rel_mse")]
        label = (labels or {}).get(line["label"], line["label"])
        axis.loglog([p["rays"] for p in points], [p["rel_mse"] for p in points], marker="o",
                    markersize=6, color=COLOURS[index % len(COLOURS)], label=label)
    axis.set_xlabel("rays per image")
    axis.set_ylabel("relMSE (lower is better)")
    axis.grid(True, which="major", color="0.9")
    axis.legend(frameon=False, loc="lower left")
    if title:
        axis.set_title(title)
    save(fig, topic, name)


def equal_time_bars(topic, name, order=None):
    """RMSE at equal time, one bar per configuration; the best in green."""
    summary = load(topic)
    lines = [line for line in summary["lines"] if line.get("rmse_at_equal_seconds")]
    if order:
        lines.sort(key=lambda line: order.index(line["label"]))
    values = np.array([line["rmse_at_equal_seconds"]["value"] for line in lines])
    best = values.min()
    fig, axis = figure(1000, 60 + 40 * len(lines))
    colours = ["#2a7" if v == best else COLOURS[0] for v in values]
    axis.barh(np.arange(len(lines)), values, color=colours)
    for i, value in enumerate(values):
        note = "best" if value == best else f"{value / best:.2f}×"
        axis.text(value, i, f"  {note}", va="center", fontsize=16)
    labels = [line["label"].replace("naive N=", "naive, b = ") for line in lines]
    axis.set_yticks(np.arange(len(lines)), labels)
    axis.invert_yaxis()
    axis.set_xlim(0, values.max() * 1.2)
    axis.set_xlabel(f"RMSE after the same {summary['equal_seconds']:.2g} s (lower is better)")
    axis.spines["left"].set_visible(False)
    axis.tick_params(axis="y", length=0)
    save(fig, topic, name)


def rays_per_sample():
    summary = load("recursion/rays")
    groups = {}
    for line in summary["lines"]:
        groups.setdefault(line["group"], []).append(line)
    fig, axis = figure(1000, 420)
    for index, (group, members) in enumerate(groups.items()):
        members.sort(key=lambda line: line["x"])
        axis.semilogy([m["x"] for m in members], [m["rays_per_sample"] for m in members],
                      marker="o", color=COLOURS[index], label=group.replace("N=", "b = "))
        if group.startswith("naive"):
            b = float(group.split("=")[1])
            d = np.arange(0, 6)
            axis.semilogy(d, (b ** (d + 1) - 1) / (b - 1), linestyle="--", linewidth=1.5,
                          color=COLOURS[index])
    axis.set_xlabel("depth d (bounces)")
    axis.set_ylabel("rays per camera sample")
    axis.grid(True, color="0.9")
    axis.legend(frameon=False, loc="upper left")
    axis.set_title("measured (dots) against (b^(d+1) − 1)/(b − 1) (dashes)", loc="left")
    save(fig, "recursion", "rays-slide")


def nee_sweep():
    """Cost of an error as the light shrinks; the x axis runs from large to small lights."""
    summary = load("nee")
    groups = {}
    for line in summary["lines"]:
        groups.setdefault(line["group"], []).append(line)
    fig, axis = figure(1000, 420)
    for index, (group, members) in enumerate(groups.items()):
        members.sort(key=lambda line: -line["x"])
        last = [[p for p in m["points"] if p.get("rel_mse")][-1] for m in members]
        axis.loglog([m["x"] for m in members], [p["rel_mse"] * p["seconds"] for p in last],
                    marker="o", color=COLOURS[index], label=group)
    axis.invert_xaxis()  # shrinking runs left to right, as one reads
    xs = sorted({line["x"] for line in summary["lines"]}, reverse=True)
    axis.set_xticks(xs, [f"{x:g}" for x in xs])
    axis.minorticks_off()
    axis.set_xlabel("side of the light (m), shrinking →  (power fixed)")
    axis.set_ylabel("relMSE × seconds\n(cost of an error)")
    axis.grid(True, color="0.9")
    axis.legend(frameon=False, loc="center left")
    save(fig, "nee", "sweep-slide")


# ---- Viewer screenshots, cropped to their image panes ----

# The demos render their panes 400 pixels wide (viewer_demos.h); in a 1280 x 720 window the
# viewer draws its panel over x < 380 and shows each pane's image scaled to 448 pixels wide,
# centred in its pane, with the pane's caption below it.
PANEL = 380


def panes(name, boxes, titles, out, height_px):
    """The panes side by side, height_px tall with a title line; as wide as their shape needs."""
    shot = Image.open(os.path.join(FIGURES, "viewer", f"{name}.png")).convert("RGB")
    image_height = height_px - 60  # the rest is the title line
    width_px = sum(image_height * (b[2] - b[0]) / (b[3] - b[1]) for b in boxes) + 20 * len(boxes)
    fig, axes = figure(width_px, height_px, ncols=len(boxes))
    axes = np.atleast_1d(axes)
    for axis, box, title in zip(axes, boxes, titles):
        axis.imshow(shot.crop(box), interpolation="lanczos")
        axis.set_title(title)
        axis.axis("off")
    save(fig, "viewer", out)


def ray_explosion():
    """Naive recursion at depths 1 and 3 beside path tracing at depth 3: the demo at its start
    and two presses of Up later, on the demo's one log scale (1 to 1365 rays per sample)."""
    # The rays display's legend pushes the panes' captions up over the images' bottom rows.
    left, right = (PANEL + 1, 137, 828, 530), (833, 137, 1280, 530)
    crops = [("ray-explosion", left, "naive, depth 1"),
             ("ray-explosion-depth3", left, "naive, depth 3"),
             ("ray-explosion-depth3", right, "path tracing, depth 3")]
    fig, axes = figure(1100, 420, ncols=3)
    for axis, (name, box, title) in zip(axes, crops):
        shot = Image.open(os.path.join(FIGURES, "viewer", f"{name}.png")).convert("RGB")
        axis.imshow(shot.crop(box), interpolation="lanczos")
        axis.set_title(title)
        axis.axis("off")
    save(fig, "viewer", "ray-explosion-panes")


def viewer_crops():
    # Square scenes: each pane's image is 448 x 448 from the top of row 136.
    left, right = (PANEL + 1, 137, 828, 583), (833, 137, 1280, 583)
    panes("nested-vs-4d", [left, right], ["nested, independent, 1 : 4", "4D, Sobol'"],
          "nested-vs-4d-panes", 420)
    panes("nee-small-light", [left, right], ["NEE on", "NEE off"], "nee-small-light-panes", 420)
    panes("naive-vs-path", [left, right], ["path tracing, no NEE", "naive recursion, b = 3"],
          "naive-vs-path-panes", 420)
    ray_explosion()
    # Mitchell against the box, the same samples: the white square's corner magnified without
    # smoothing, where Mitchell's negative lobes draw dark rims along the bright edges.
    shot = Image.open(os.path.join(FIGURES, "viewer", "mitchell-lobes.png")).convert("RGB")
    fig, axes = figure(900, 390, ncols=2)
    pane_offset = 452  # the right pane's image starts 452 pixels right of the left one's
    for axis, shift, title in zip(axes, (0, pane_offset), ("Mitchell–Netravali", "box")):
        box = (515 + shift, 425, 585 + shift, 495)
        axis.imshow(shot.crop(box), interpolation="nearest")
        axis.set_title(f"{title}, 2 spp, magnified")
        axis.axis("off")
    save(fig, "viewer", "mitchell-lobes-pane")


DRAWINGS = {
    "filters": [filter_shapes, filter_mitchell, filter_sinc, splat],
    "samples": [scatter_1d1d, scatter_4d],
    "recursion": [ray_tree, rays_per_sample],
    "nee": [nee_geometry, nee_sweep],
    "measured": [
        lambda: against_rays("filters", "rays-slide"),
        lambda: equal_time_bars("ao-splits", "bars-slide"),
        lambda: equal_time_bars("recursion", "bars-slide"),
        lambda: against_rays("samplers/stage3", "rays-slide"),
    ],
    "viewer": [viewer_crops],
}


def main():
    parser = argparse.ArgumentParser(description=__doc__,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--only", nargs="+", choices=sorted(DRAWINGS), help="only these groups")
    args = parser.parse_args()
    for group in args.only or DRAWINGS:
        for draw in DRAWINGS[group]:
            draw()


if __name__ == "__main__":
    main()
