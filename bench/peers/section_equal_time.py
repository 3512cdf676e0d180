"""Section 4, equal time: relMSE against a high-spp reference for several spp, Pathway's
whole-process time against Mitsuba llvm's render time, compared at equal time (log-log
interpolation)."""
import numpy as np

from image_stats import loglog_at, rel_mse
from renderers import LLVM
from report_tables import fmt_s


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
