"""Shared figure helpers: Agg-only figures, yarn colours, saving."""

import numpy as np
from matplotlib.backends.backend_agg import FigureCanvasAgg
from matplotlib.figure import Figure

YARN_COLOURS = ("tab:blue", "tab:orange", "tab:green", "tab:red", "tab:purple",
                "tab:brown", "tab:pink", "tab:olive", "tab:cyan", "tab:gray")
BREAK_GID = "break"  # gid of the vertical lines drawn at BreakEvent stamps
TIME_LABEL = "simulated time t [s]"


def new_figure(**kwargs) -> Figure:
    """A Figure on the Agg canvas (no pyplot, no display needed)."""
    fig = Figure(**kwargs)
    FigureCanvasAgg(fig)
    return fig


def colours(names) -> dict:
    """Yarn name -> matplotlib colour, stable across figures."""
    return {n: YARN_COLOURS[i % len(YARN_COLOURS)] for i, n in enumerate(names)}


def save(fig: Figure, path: str) -> str:
    """Write ``fig`` as a 150 dpi PNG and return ``path``."""
    fig.savefig(path, dpi=150)
    return path


def masked_max(values: np.ndarray, mask: np.ndarray) -> np.ndarray:
    """Row-wise max of ``values`` over ``mask`` (NaN-safe); NaN for empty rows."""
    ok = mask & np.isfinite(values)
    out = np.max(np.where(ok, values, -np.inf), axis=1, initial=-np.inf)
    return np.where(np.isfinite(out), out, np.nan)


def masked_sum(values: np.ndarray, mask: np.ndarray) -> np.ndarray:
    """Row-wise sum of ``values`` over ``mask``, ignoring NaN."""
    return np.where(mask & np.isfinite(values), values, 0.0).sum(axis=1)


def draw_breaks(ax, breaks, colour_of, label=True) -> None:
    """Vertical dotted lines (gid ``BREAK_GID``) at each BreakEvent time [s]."""
    for b in breaks:
        ax.axvline(b.t, color=colour_of.get(b.yarn, "k"), ls=":", lw=1.4, gid=BREAK_GID,
                   label="tear of %s (t = %.3f s)" % (b.yarn, b.t) if label else None)


def drawn_breaks(ax) -> list:
    """x positions [s] of the break lines actually drawn on ``ax``."""
    return [float(np.asarray(ln.get_xdata())[0]) for ln in ax.get_lines()
            if ln.get_gid() == BREAK_GID]


def legend(ax, **kwargs) -> None:
    """ax.legend(**kwargs) if anything on ``ax`` has a label."""
    if ax.get_legend_handles_labels()[0]:
        ax.legend(**kwargs)
