"""Section 3, agreement: global channel means within 1 % and every region of a 4x4 grid within
3 %, over independent renders of a small image; finer blocks judged by Welch's t."""
import numpy as np

from image_stats import mean_and_se, regions, rel_diff, t_two_sided_p
from renderers import LLVM
from report_tables import pct


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
