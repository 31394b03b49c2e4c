"""filmstrip.png: the yarns at a few instants, coloured by stress / sigma_b.

Positions [m] are projected on a coordinate plane: x horizontal and z
vertical unless one of them barely varies, then the two axes that vary most.
Yarns that would overlap in the projection are spread side by side (across
their length), so the horizontal coordinate is only a scale, not a position.
"""

from dataclasses import dataclass

import matplotlib
import numpy as np
from matplotlib.cm import ScalarMappable
from matplotlib.collections import LineCollection
from matplotlib.colors import Normalize
from matplotlib.lines import Line2D
from mpl_toolkits.axes_grid1.anchored_artists import AnchoredSizeBar

from . import frames, style

AXES = "xyz"
DEGENERATE = 0.01  # an axis whose variance is below this fraction of the largest


def projection_axes(points: np.ndarray) -> tuple:
    """(horizontal, vertical) coordinate indices (0=x, 1=y, 2=z) for (N, 3) points [m]."""
    pts = points[np.isfinite(points).all(axis=1)]
    if len(pts) < 2:
        return 0, 2
    var = pts.var(axis=0)
    ok = var >= DEGENERATE * var.max()
    if ok[0] and ok[2]:
        return 0, 2
    keep = sorted(np.argsort(-var, kind="stable")[:2])
    return (keep[0], 2) if 2 in keep else (keep[0], keep[1])


def _sample(yarn, t):
    """Index of the yarn's sample at time t [s], or None if it has none near t."""
    i = int(np.argmin(np.abs(yarn.t - t)))
    dt = np.median(np.diff(yarn.t)) if len(yarn.t) > 1 else np.inf
    return i if abs(yarn.t[i] - t) <= 0.5 * dt + 1e-9 else None


def _bbox(xys):
    """(min, max) corners [m] of the finite points of a list of (N, 2) arrays."""
    pts = np.concatenate([np.zeros((0, 2))] + [p for p in xys if p is not None])
    pts = pts[np.isfinite(pts).all(axis=1)]
    return (pts.min(axis=0), pts.max(axis=0)) if len(pts) else (np.zeros(2), np.zeros(2))


def _offsets(boxes, axis):
    """Shift along ``axis`` [m] per yarn so that the yarns' boxes do not overlap."""
    lo = np.array([b[0][axis] for b in boxes])
    hi = np.array([b[1][axis] for b in boxes])
    length = max(max(b[1][1 - axis] - b[0][1 - axis] for b in boxes), 1e-6)
    gap = 0.3 * length
    order = np.argsort((lo + hi) / 2, kind="stable")
    if all(lo[b] >= hi[a] + 0.1 * gap for a, b in zip(order[:-1], order[1:])):
        return np.zeros(len(boxes))
    shift, edge = np.zeros(len(boxes)), lo[order[0]]
    for k in order:
        shift[k] = edge - lo[k]
        edge += hi[k] - lo[k] + gap
    return shift - shift.mean()


@dataclass
class Layout:
    """Where each yarn goes in every panel (projected coordinates [m])."""

    plane: tuple      # (horizontal, vertical) coordinate indices
    tall: bool        # yarns longer vertically: frames in a row, else in a column
    shift: dict       # yarn -> (2,) offset [m] added to its projected points
    boxes: dict       # yarn -> (min, max) corners [m] before the first tear, unshifted
    centre: np.ndarray  # (2,) view centre [m]
    half: np.ndarray    # (2,) view half-size [m]
    span: float         # largest extent of the yarns [m]


def layout(data, idx, times) -> Layout:
    """Projection plane, yarn offsets and a view fitting the yarns before the first tear."""
    names = list(idx)
    pts = [data.yarns[n].positions[i] for n in names for i in idx[n] if i is not None]
    h, v = projection_axes(np.concatenate([np.zeros((0, 3))] + pts))
    # the view frames the yarns before the first tear: torn pieces may fly off
    t_first_tear = min(frames.tear_times(data), default=np.inf)
    ref = [k for k, t in enumerate(times) if t < t_first_tear] or list(range(len(times)))
    boxes = [_bbox([data.yarns[n].positions[idx[n][k]][:, [h, v]] for k in ref
                    if idx[n][k] is not None]) for n in names]
    sizes = np.array([b[1] - b[0] for b in boxes])
    tall = bool(sizes[:, 1].max() >= sizes[:, 0].max())
    across = np.arange(2) == (0 if tall else 1)
    shift = [s * across for s in _offsets(boxes, 0 if tall else 1)]
    lo = np.min([b[0] + s for b, s in zip(boxes, shift)], axis=0)
    hi = np.max([b[1] + s for b, s in zip(boxes, shift)], axis=0)
    span = float(max((hi - lo).max(), 1e-6))
    half = np.maximum((hi - lo) / 2 + 0.08 * span, 0.2 * span)
    return Layout((h, v), tall, dict(zip(names, shift)), dict(zip(names, boxes)),
                  (lo + hi) / 2, half, span)


def _figure(lay, n):
    """Figure and its n panel axes, sized for the view's aspect ratio."""
    aspect = lay.half[0] / lay.half[1]
    if lay.tall:
        pw = float(np.clip(3.8 * aspect, 0.9, 3.0))
        fig = style.new_figure(figsize=(n * pw + 1.6, 5.0), layout="constrained")
        return fig, fig.subplots(1, n, sharex=True, sharey=True, squeeze=False)[0]
    ph = float(np.clip(7.0 / aspect, 0.6, 2.5))
    fig = style.new_figure(figsize=(9.0, n * ph + 1.2), layout="constrained")
    return fig, fig.subplots(n, 1, sharex=True, sharey=True, squeeze=False)[:, 0]


def make_filmstrip(data, strengths, times, path, cmap="turbo") -> dict:
    """Draw the yarns at ``times`` [s] into ``path``; return layout info.

    Segments are coloured by sigma / sigma_b (sigma_b from ``strengths``, else
    the yarn's peak stress in the bag); broken edges are not drawn; a red
    cross marks each BreakEvent position in the first frame after it.
    """
    names = list(data.yarns)
    idx = {n: [_sample(data.yarns[n], t) for t in times] for n in names}
    lay = layout(data, idx, times)
    h, v = lay.plane
    fig, axes = _figure(lay, len(times))
    norm, cm = Normalize(0.0, 1.0), matplotlib.colormaps[cmap]
    sigma_ref = {n: _sigma_ref(data.yarns[n], strengths.get(n)) for n in names}
    for k, (ax, t) in enumerate(zip(axes, times)):
        t_prev = times[k - 1] if k else -np.inf
        for name in (n for n in names if idx[n][k] is not None):
            y, off = data.yarns[name], lay.shift[name]
            _draw_yarn(ax, y, idx[name][k], y.positions[idx[name][k]][:, [h, v]] + off,
                       sigma_ref[name], norm, cm)
            for b in (b for b in data.breaks if b.yarn == name and t_prev < b.t <= t):
                p = b.position[[h, v]] + off
                ax.plot(p[0], p[1], "x", color="red", ms=9, mew=2.2, zorder=5)
            if k == 0:
                lo, hi = lay.boxes[name]
                ax.text((lo[0] + hi[0]) / 2 + off[0], hi[1] + off[1] + 0.03 * lay.span, name,
                        ha="center", va="bottom", fontsize=9, fontweight="bold")
        _frame_axes(ax, lay, "t = %.3f s" % t)
    _scale_bar(axes[-1], lay.span)
    # in the title band, right (the title is left-aligned): inside a panel it hid yarn ends
    fig.legend(handles=[
        Line2D([], [], ls="", marker="s", color="k", ms=5, label="support"),
        Line2D([], [], ls="", marker="x", color="red", ms=8, mew=2, label="tear")],
        loc="upper right", ncol=2, fontsize=8, frameon=False, handletextpad=0.2)
    known = all(strengths.get(n) is not None and strengths[n].breaking_stress for n in names)
    fig.colorbar(ScalarMappable(norm, cm), ax=list(axes), shrink=0.85 if lay.tall else 0.5,
                 pad=0.02, label="stress / breaking stress  σ / σ$_b$" if known else
                 "stress / σ$_b$ (or / peak stress if σ$_b$ unknown)")
    fig.suptitle("Yarns over time, coloured by stress (projection on the %s–%s plane)"
                 % (AXES[h], AXES[v]), x=0.01, ha="left")
    style.save(fig, path)
    return {"times": [float(t) for t in times], "plane": AXES[h] + AXES[v],
            "offsets": {n: float(s.sum()) for n, s in lay.shift.items()}}  # [m], across


def _frame_axes(ax, lay, label):
    """Common view, equal aspect, no ticks, the time under (or beside) the panel."""
    ax.set_xlim(lay.centre[0] - lay.half[0], lay.centre[0] + lay.half[0])
    ax.set_ylim(lay.centre[1] - lay.half[1], lay.centre[1] + lay.half[1] + 0.06 * lay.span)
    ax.set_aspect("equal", adjustable="box")
    ax.set_xticks([])
    ax.set_yticks([])
    for spine in ax.spines.values():
        spine.set_color("0.8")
    (ax.set_xlabel if lay.tall else ax.set_ylabel)(label, fontsize=10)


def _sigma_ref(yarn, strength):
    """sigma_b [Pa] for colouring, else the yarn's peak stress in the bag."""
    if strength is not None and strength.breaking_stress:
        return strength.breaking_stress
    peak = np.nanmax(yarn.stresses, initial=0.0)
    return peak if peak > 0 else 1.0


def _draw_yarn(ax, yarn, i, xy, sigma_ref, norm, cm):
    edges, ok = yarn.edges[i], yarn.intact()[i]
    segs = xy[edges[ok]]
    ratio = np.nan_to_num(yarn.stresses[i][ok] / sigma_ref).clip(0.0, 1.0)
    ax.add_collection(LineCollection(segs, colors=cm(norm(ratio)), linewidths=2.4,
                                     capstyle="round", zorder=2))
    sup = yarn.supports[i]
    sup = sup[(sup >= 0) & (sup < len(xy))]
    ax.plot(xy[sup, 0], xy[sup, 1], "s", color="k", ms=5, zorder=3)


def _scale_bar(ax, span):
    """A 1/2/5 x 10^k metre bar about a quarter of ``span`` [m] long."""
    target = span / 4
    exp = np.floor(np.log10(target))
    size = max((m * 10 ** exp for m in (1, 2, 5) if m * 10 ** exp <= target),
               default=10 ** exp)
    label = "%g mm" % (size * 1e3) if size < 0.01 else (
        "%g cm" % (size * 1e2) if size < 1 else "%g m" % size)
    ax.add_artist(AnchoredSizeBar(ax.transData, size, label, "lower right", frameon=False,
                                  pad=0.3, fontproperties={"size": 7}))
