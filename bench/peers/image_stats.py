"""Statistics on images and on series of renders: relMSE, region means, means with standard
errors, relative differences, Student's t tail (scipy) and log-log interpolation."""
import math

import numpy as np
from scipy import stats


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


def t_two_sided_p(t, dof):
    """P(|T| > |t|) for Student's t with `dof` degrees of freedom (arrays; dof need not be an
    integer, as Welch's is not)."""
    return 2.0 * stats.t.sf(np.abs(t), dof)


def loglog_at(times, errors, t):
    """relMSE at time t, linear in log-log between the measured points (None outside them)."""
    lt, le = np.log(times), np.log(errors)
    order = np.argsort(lt)
    lt, le = lt[order], le[order]
    if not lt[0] <= math.log(t) <= lt[-1]:
        return None
    return float(np.exp(np.interp(math.log(t), lt, le)))
