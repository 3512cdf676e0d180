#!/usr/bin/python3
"""Draws the charts of `pathway chart` from the data it writes (summary.json, runs.csv).

    draw_chart.py convergence DIR            relMSE against seconds and against rays (chart.png/svg)
    draw_chart.py bars DIR [--metric M]      RMSE (or relMSE) at equal time and rays (bars.png/svg)
    draw_chart.py rays DIR [--formula naive] rays per camera sample against x, by group (rays.*)
    draw_chart.py sweep DIR --x-label TEXT   cost of an error, and equal-time RMSE, against x (sweep.*)
    draw_chart.py filters DIR --profiles CSV the filters' profiles and looks (filters.png/svg)
    draw_chart.py ratio DIR A B [--spp N]    prints A's error over B's (at N spp or equal time)

Every figure is written as PNG (for slides and the docs) and SVG (for print). See docs/charts.md.
"""
import argparse
import csv
import json
import math
import os
import re
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402  (the backend must be chosen first)
import matplotlib.ticker  # noqa: E402
import numpy as np  # noqa: E402

COLOURS = plt.rcParams["axes.prop_cycle"].by_key()["color"]
GUIDE_SLOPES = [(-1.0, "slope −1 (plain Monte Carlo)"), (-1.25, "slope −1.25"),
                (-1.5, "slope −1.5 (stratified / Sobol', with edges)")]


def load_summary(folder):
    path = os.path.join(folder, "summary.json")
    try:
        with open(path, encoding="utf-8") as f:
            return json.load(f)
    except (OSError, ValueError) as error:
        sys.exit(f"draw_chart.py: cannot read {path}: {error}")


def save(figure, folder, name):
    for extension in ("png", "svg"):
        figure.savefig(os.path.join(folder, f"{name}.{extension}"), dpi=150,
                       bbox_inches="tight")
    plt.close(figure)
    print(f"wrote {os.path.join(folder, name)}.png and .svg")


def fmt(value, digits=3):
    if value is None or (isinstance(value, float) and not math.isfinite(value)):
        return "–"
    return f"{value:.{digits}g}"


def read_off(entry):
    """A {value, extrapolated} pair from summary.json as text; extrapolated values get a '*'."""
    if not entry or entry.get("value") is None:
        return "–"
    return (("≤ " if entry.get("at_most") else "") + fmt(entry["value"]) +
            ("*" if entry.get("extrapolated") else ""))


def with_error(line):
    return [p for p in line["points"] if p.get("rel_mse") is not None]


def add_guides(axis, x_values, y_values):
    """Dashed guide lines through the top-left data point, one per expected slope."""
    if not x_values:
        return
    x0, y0 = min(x_values), max(y_values)
    x1 = max(x_values)
    for (slope, label), style in zip(GUIDE_SLOPES, [(0, (6, 3)), (0, (3, 3)), (0, (1, 2))]):
        xs = np.array([x0, x1])
        axis.plot(xs, y0 * (xs / x0) ** slope, color="0.55", linewidth=0.9, linestyle=style,
                  label=label, zorder=1)


def log_axes(axis):
    """Log-log axes whose minor ticks get labels when the range is under two decades."""
    axis.set_xscale("log")
    axis.set_yscale("log")
    for scale in (axis.xaxis, axis.yaxis):
        scale.set_minor_formatter(
            matplotlib.ticker.LogFormatterSciNotation(labelOnlyBase=False,
                                                      minor_thresholds=(2, 0.5)))
    axis.tick_params(which="minor", labelsize=7)
    axis.grid(True, which="major", color="0.88", linewidth=0.7)
    axis.grid(True, which="minor", color="0.95", linewidth=0.5)


def draw_line(axis, line, points, x_key, colour):
    xs = [p[x_key] for p in points]
    axis.fill_between(xs, [p["rel_mse_low"] for p in points], [p["rel_mse_high"] for p in points],
                      color=colour, alpha=0.18, linewidth=0, zorder=2)
    axis.plot(xs, [p["rel_mse"] for p in points], marker="o", markersize=3.5, color=colour,
              label=line["label"], zorder=3)


def convergence(folder, _args):
    summary = load_summary(folder)
    lines = [line for line in summary["lines"] if with_error(line)]
    if not lines:
        sys.exit("draw_chart.py: the chart has no errors to draw (made with --no-reference?)")
    figure = plt.figure(figsize=(13, 5.2 + 0.32 * len(lines)))
    grid = figure.add_gridspec(2, 2, height_ratios=[5.2, 0.32 * len(lines) + 0.9], hspace=0.28,
                               wspace=0.08)
    by_time = figure.add_subplot(grid[0, 0])
    by_rays = figure.add_subplot(grid[0, 1], sharey=by_time)
    all_x_time, all_x_rays, all_y = [], [], []
    for index, line in enumerate(lines):
        points = with_error(line)
        colour = COLOURS[index % len(COLOURS)]
        draw_line(by_time, line, points, "seconds", colour)
        draw_line(by_rays, line, points, "rays", colour)
        all_x_time += [p["seconds"] for p in points]
        all_x_rays += [p["rays"] for p in points]
        all_y += [p["rel_mse"] for p in points]
    add_guides(by_time, all_x_time, all_y)
    add_guides(by_rays, all_x_rays, all_y)
    target = summary["target_rel_mse"]
    show_target = min(all_y) < 3 * target  # else it would squash the curves
    for axis in (by_time, by_rays):
        log_axes(axis)
        if show_target:
            axis.axhline(target, color="0.3", linewidth=0.7, linestyle=":")
    if show_target:
        by_time.text(min(all_x_time), target, f" relMSE {target:g}", va="bottom", fontsize=8,
                     color="0.3")
    by_time.set_xlabel("wall-clock seconds per image (median over seeds)")
    by_time.set_ylabel(f"relMSE = mean (x − r)² / (r² + {summary['rel_mse_epsilon']:g})")
    by_rays.set_xlabel("total rays per image (exact counts: comparable on any machine)")
    plt.setp(by_rays.get_yticklabels(), visible=False)
    by_time.set_title("error against time", fontsize=10)
    by_rays.set_title("error against rays", fontsize=10)
    handles, labels = by_time.get_legend_handles_labels()
    by_rays.legend(handles, labels, fontsize=8, loc="upper left", bbox_to_anchor=(1.02, 1.0))
    seeds = summary["seeds"]
    figure.suptitle(
        (summary.get("title") or "Convergence") +
        f"\nmedian of {seeds} seeds, band: min–max; spp 1, 2, 4 …; {summary['machine']}",
        fontsize=11)

    # The efficiency table under the plots.
    table_axis = figure.add_subplot(grid[1, :])
    table_axis.axis("off")
    columns = ["configuration", "rays / sample", "slope vs spp", "relMSE at max spp",
               "s at max spp", "efficiency 1/(relMSE·s)", f"s to relMSE {target:g}",
               f"relMSE at {fmt(summary['equal_seconds'])} s", "RMSE at equal time"]
    rows = []
    for line in lines:
        last = with_error(line)[-1]
        fit = line.get("fit_rel_mse_by_spp")
        rows.append([line["label"], fmt(line["rays_per_sample"]),
                     fmt(fit["slope"]) if fit else "–", fmt(last["rel_mse"]),
                     fmt(last["seconds"]), fmt(last["efficiency"]),
                     read_off(line.get("seconds_to_target")),
                     read_off(line.get("rel_mse_at_equal_seconds")),
                     read_off(line.get("rmse_at_equal_seconds"))])
    table = table_axis.table(cellText=rows, colLabels=columns, loc="upper center",
                             cellLoc="center")
    table.auto_set_font_size(False)
    table.set_fontsize(8)
    table.scale(1.0, 1.25)
    table.auto_set_column_width(list(range(len(columns))))
    for (row, _column), cell in table.get_celld().items():
        cell.set_edgecolor("0.8")
        if row == 0:
            cell.set_facecolor("0.93")
    table_axis.text(0.0, -0.02, "* extrapolated along the fitted line (the measured points do "
                    "not reach it).  Slopes: least squares over the upper half of the spp range.",
                    transform=table_axis.transAxes, fontsize=7.5, color="0.35", va="top")
    save(figure, folder, "chart")


def bars(folder, args):
    summary = load_summary(folder)
    lines = [line for line in summary["lines"] if line.get("rel_mse_at_equal_seconds")]
    if not lines:
        sys.exit("draw_chart.py: no equal-time errors in summary.json")
    figure, (left, right) = plt.subplots(1, 2, figsize=(12, 0.45 * len(lines) + 1.8),
                                         sharey=True)
    labels = [line["label"] for line in lines]
    positions = np.arange(len(lines))
    metric = {"rmse": "RMSE", "rel-mse": "relMSE"}[args.metric]
    prefix = args.metric.replace("-", "_")
    for axis, key, title in ((left, f"{prefix}_at_equal_seconds",
                              f"{metric} at equal time ({fmt(summary['equal_seconds'])} s)"),
                             (right, f"{prefix}_at_equal_rays",
                              f"{metric} at equal rays ({summary['equal_rays']:,.0f} per image)")):
        values = [line[key]["value"] if line[key]["value"] is not None else float("nan")
                  for line in lines]
        best = int(np.nanargmin(values))
        colours = ["#2a7" if i == best else COLOURS[0] for i in range(len(lines))]
        axis.barh(positions, np.nan_to_num(values), color=colours)
        for i, (value, line) in enumerate(zip(values, lines)):
            if not math.isfinite(value):
                axis.text(0, i, " – (no measurement reaches this point)", va="center", fontsize=8)
                continue
            ratio = "best" if i == best else f"{value / values[best]:.2f}× the best"
            axis.text(value, i, f" {fmt(value)}{'*' if line[key]['extrapolated'] else ''}"
                      f"  ({ratio})", va="center", fontsize=8)
        axis.set_title(title, fontsize=10)
        axis.grid(True, axis="x", color="0.9")
        axis.set_xlim(0, max(v for v in values if math.isfinite(v)) * 1.6)
    left.set_yticks(positions, labels)
    left.invert_yaxis()
    figure.suptitle((summary.get("title") or "") + "\nlower is better; green: the best; "
                    "* extrapolated", fontsize=11)
    figure.tight_layout()
    save(figure, folder, "bars")


def parameter(line, name):
    match = re.search(rf"\b{re.escape(name)}=([^\s]+)", line["description"])
    return float(match.group(1)) if match else None


def rays(folder, args):
    summary = load_summary(folder)
    groups = {}
    for line in summary["lines"]:
        if line.get("x") is None:
            sys.exit(f"draw_chart.py: configuration {line['label']!r} has no x=")
        groups.setdefault(line["group"], []).append(line)
    figure, axis = plt.subplots(figsize=(7.5, 5))
    for index, (group, members) in enumerate(groups.items()):
        members.sort(key=lambda line: line["x"])
        xs = [line["x"] for line in members]
        colour = COLOURS[index % len(COLOURS)]
        axis.plot(xs, [line["rays_per_sample"] for line in members], marker="o", color=colour,
                  label=f"{group}: measured")
        n = parameter(members[0], "branching")
        if args.formula == "naive" and n is not None:
            depths = np.arange(min(xs), max(xs) + 1)
            formula = depths + 1 if n == 1 else (n ** (depths + 1) - 1) / (n - 1)
            axis.plot(depths, formula, linestyle="--", color=colour, linewidth=1,
                      label=f"{group}: (N^(D+1) − 1)/(N − 1), every ray hitting")
    axis.set_yscale("log")
    axis.set_xlabel(args.x_label or "x")
    axis.set_ylabel("rays per camera sample")
    axis.grid(True, color="0.9")
    axis.legend(fontsize=8)
    axis.set_title((summary.get("title") or "Rays per camera sample") + "\n" + summary["machine"],
                   fontsize=10)
    save(figure, folder, "rays")


def sweep(folder, args):
    summary = load_summary(folder)
    groups = {}
    for line in summary["lines"]:
        if line.get("x") is None or not with_error(line):
            sys.exit(f"draw_chart.py: configuration {line['label']!r} needs x= and errors")
        groups.setdefault(line["group"], []).append(line)
    figure, (cost, equal) = plt.subplots(1, 2, figsize=(12, 4.8))
    for index, (group, members) in enumerate(groups.items()):
        members.sort(key=lambda line: line["x"])
        xs = [line["x"] for line in members]
        colour = COLOURS[index % len(COLOURS)]
        # relMSE · seconds at the largest spp: the time it takes to reach relMSE 1, a cost that
        # does not depend on the spp chosen when the error falls as 1/time.
        cost.plot(xs, [with_error(line)[-1]["rel_mse"] * with_error(line)[-1]["seconds"]
                       for line in members], marker="o", color=colour, label=group)
        equal.plot(xs, [line["rmse_at_equal_seconds"]["value"] for line in members], marker="o",
                   color=colour, label=group)
    xs = sorted({line["x"] for line in summary["lines"]})
    for axis in (cost, equal):
        log_axes(axis)
        axis.set_xlabel(args.x_label or "x")
    if args.guide_slope is not None:
        anchor = [line for line in summary["lines"] if line["x"] == xs[-1]]
        y0 = max(with_error(line)[-1]["rel_mse"] * with_error(line)[-1]["seconds"]
                 for line in anchor)
        guide = np.array(xs)
        cost.plot(guide, y0 * (guide / xs[-1]) ** args.guide_slope, color="0.5", linestyle="--",
                  linewidth=0.9, label=args.guide_label or f"slope {args.guide_slope:g}")
    cost.set_ylabel("relMSE × seconds (inverse efficiency)")
    cost.set_title("cost of an error: lower is better", fontsize=10)
    equal.set_ylabel(f"RMSE at equal time ({fmt(summary['equal_seconds'])} s)")
    equal.set_title("equal-time RMSE", fontsize=10)
    cost.legend(fontsize=8)
    equal.legend(fontsize=8)
    figure.suptitle((summary.get("title") or "") + "\n" + summary["machine"], fontsize=11)
    figure.tight_layout()
    save(figure, folder, "sweep")


def filters(folder, args):
    summary = load_summary(folder)
    with open(args.profiles, encoding="utf-8") as f:
        rows = list(csv.DictReader(f))
    names = [name for name in rows[0] if name != "x"]
    looks = [line for line in summary["lines"] if line.get("reference")]
    figure = plt.figure(figsize=(13, 11))
    grid = figure.add_gridspec(3, max(len(looks), 1), height_ratios=[1.0, 1.1, 0.9], hspace=0.35)
    profile = figure.add_subplot(grid[0, :])
    x = np.array([float(row["x"]) for row in rows])
    colour_of = {name: COLOURS[index % len(COLOURS)] for index, name in enumerate(names)}
    for name in names:
        values = np.array([float(row[name]) for row in rows])
        profile.plot(x, values, color=colour_of[name], label=name, linewidth=1.6)
        if values.min() < 0:
            lowest = int(values.argmin())
            profile.annotate(f"{name}: min {values[lowest]:.4f} at |x| = {abs(x[lowest]):.3f}",
                             (x[lowest], values[lowest]), xytext=(30, 45),
                             textcoords="offset points", fontsize=8,
                             arrowprops={"arrowstyle": "->", "color": "0.4"})
    profile.axhline(0, color="0.3", linewidth=0.7)
    profile.set_xlabel("offset from the pixel centre (pixels)")
    profile.set_ylabel("f(x), as the code evaluates it")
    profile.set_title("1D profiles of the pixel filters, from stage 1's filter functions",
                      fontsize=10)
    profile.legend(fontsize=8)
    profile.grid(True, color="0.92")
    scanline = figure.add_subplot(grid[2, :])
    rows_of = {}
    for index, line in enumerate(looks):
        image = plt.imread(line["reference"]["png"])[..., :3]
        height, width = image.shape[:2]
        cx, cy, size = args.crop if args.crop else (width // 2, height // 2,
                                                    min(width, height) // 2)
        top, left = max(0, cy - size // 2), max(0, cx - size // 2)
        cut = image[top:cy + size // 2, left:cx + size // 2]
        row = min(cut.shape[0] - 1, cut.shape[0] * 3 // 4)  # below the thin diagonal line
        axis = figure.add_subplot(grid[1, index])
        axis.imshow(cut, interpolation="nearest")
        axis.axhline(row, color="white", linewidth=0.6, linestyle=":")
        axis.set_title(f"{line['label']}\n{line['reference']['spp']} spp, "
                       f"{cut.shape[1]}×{cut.shape[0]} px crop", fontsize=9)
        axis.set_xticks([])
        axis.set_yticks([])
        rows_of[line["label"]] = (np.arange(cut.shape[1]) + left, cut[row].mean(axis=1))
    # Each filter's row minus the box's: blur and ringing as signed deviations from hard edges.
    baseline = rows_of.get("box")
    for label, (columns, values) in rows_of.items():
        shown = values - baseline[1] if baseline is not None else values
        scanline.step(columns, shown, where="mid", color=colour_of.get(label, "0.3"),
                      label=label, linewidth=1.4)
    scanline.set_xlabel("pixel column")
    scanline.set_ylabel("mean of R, G, B (sRGB)" + (" minus box" if baseline is not None else ""))
    scanline.set_title("along the dotted row: the Gaussian blurs edges most; Mitchell's negative "
                       "lobes darken the pixels beside a bright edge (ringing)", fontsize=10)
    scanline.legend(fontsize=8, ncol=len(looks))
    scanline.grid(True, color="0.92")
    figure.suptitle((summary.get("title") or "Pixel filters") +
                    "\nlooks: converged renders, pixels magnified without smoothing", fontsize=11)
    save(figure, folder, "filters")


def ratio(folder, args):
    """Prints the error of line A over that of line B: at one spp, or at equal time."""
    summary = load_summary(folder)
    lines = {line["label"]: line for line in summary["lines"]}
    for label in (args.a, args.b):
        if label not in lines:
            sys.exit(f"draw_chart.py: no configuration {label!r} in {folder} "
                     f"(there are: {', '.join(lines)})")
    metric = args.metric.replace("-", "_")
    if args.spp:
        def error(line):
            point = next((p for p in line["points"] if p["spp"] == args.spp), None)
            if point is None or point.get("rel_mse") is None:
                sys.exit(f"draw_chart.py: {line['label']!r} has no error at {args.spp} spp")
            return math.sqrt(point["mse"]) if metric == "rmse" else point["rel_mse"]
        where = f"at {args.spp} spp"
    else:
        def error(line):
            return line[f"{metric}_at_equal_seconds"]["value"]
        where = f"at equal time ({fmt(summary['equal_seconds'])} s)"
    a, b = error(lines[args.a]), error(lines[args.b])
    if a is None or b is None:
        sys.exit(f"draw_chart.py: no error {where} for {args.a!r} or {args.b!r}")
    name = {"rmse": "RMSE", "rel_mse": "relMSE"}[metric]
    print(f"{name} {where}: {args.a} {fmt(a)}, {args.b} {fmt(b)}, ratio {a / b:.3g}")


def main():
    parser = argparse.ArgumentParser(description=__doc__,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("kind",
                        choices=["convergence", "bars", "rays", "sweep", "filters", "ratio"])
    parser.add_argument("folder", help="the folder `pathway chart -o` wrote")
    parser.add_argument("a", nargs="?", help="ratio: the label of the numerator")
    parser.add_argument("b", nargs="?", help="ratio: the label of the denominator")
    parser.add_argument("--spp", type=int, help="ratio: at this spp (default: at equal time)")
    parser.add_argument("--x-label", help="rays, sweep: what x= measures")
    parser.add_argument("--metric", choices=["rmse", "rel-mse"], default="rmse",
                        help="bars: the error shown (default: rmse)")
    parser.add_argument("--formula", choices=["naive"], help="rays: overlay a formula")
    parser.add_argument("--guide-slope", type=float, help="sweep: a guide line of this slope")
    parser.add_argument("--guide-label", help="sweep: its legend entry")
    parser.add_argument("--profiles", help="filters: the CSV of `pathway chart --filter-profiles`")
    parser.add_argument("--crop", type=int, nargs=3, metavar=("X", "Y", "SIZE"),
                        help="filters: the crop's centre and side in pixels")
    args = parser.parse_args()
    if args.kind == "filters" and not args.profiles:
        parser.error("filters needs --profiles CSV")
    if args.kind == "ratio" and not (args.a and args.b):
        parser.error("ratio needs two labels")
    if args.kind != "ratio" and args.a:
        parser.error(f"unexpected argument {args.a!r}")
    {"convergence": convergence, "bars": bars, "rays": rays, "sweep": sweep, "filters": filters,
     "ratio": ratio}[args.kind](args.folder, args)


if __name__ == "__main__":
    main()
