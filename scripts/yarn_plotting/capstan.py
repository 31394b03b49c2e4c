"""capstan.png: a yarn wrapped round an obstacle (launch/capstan_demo.launch), the tension on
each side of it and their ratio against the capstan law T_last = T_first * e^(mu theta).

The sides are the yarn's end edges (edge 0 at vertex 0, the last edge at the last vertex), away
from the obstacle; theta [rad] is the angle the yarn turns through between them (the angle
between the first edge's direction, vertex 0 -> 1, and the last edge's). Only states before the
yarn's first tear count (after it the sides are two pieces).
"""

from dataclasses import dataclass
from typing import Optional

import numpy as np

from . import style
from .bagdata import BagData, YarnSeries

# The ratio is drawn where the first side carries at least this share of its largest tension
# (a slack side's ratio is noise).
MIN_SHARE = 0.05


@dataclass
class CapstanSeries:
    """Per state before the first tear: time [s], end tensions [N], wrap angle [rad]."""

    t: np.ndarray
    first: np.ndarray   # [N] tension of edge 0 (the side of vertex 0)
    last: np.ndarray    # [N] tension of the last edge (the side of the last vertex)
    theta: np.ndarray   # [rad] turn of the yarn between its end edges

    def ratio(self) -> np.ndarray:
        """T_last / T_first, NaN where the first side carries < MIN_SHARE of its peak."""
        loaded = self.first >= MIN_SHARE * np.nanmax(self.first, initial=0.0)
        with np.errstate(divide="ignore", invalid="ignore"):
            return np.where(loaded & (self.first > 0.0), self.last / self.first, np.nan)


def _direction(p: np.ndarray) -> np.ndarray:
    """(T, 3) unit vectors of (T, 3) vectors."""
    return p / np.linalg.norm(p, axis=-1, keepdims=True)


def capstan_series(yarn: YarnSeries, tear_time: Optional[float]) -> CapstanSeries:
    """The end edges' tensions and the wrap angle of ``yarn`` before ``tear_time`` [s]."""
    keep = yarn.t < tear_time if tear_time is not None else np.ones(len(yarn.t), bool)
    n_edges = int(np.max(np.sum(yarn.edges[..., 0] >= 0, axis=1)))
    x = yarn.positions[keep]
    u_first = _direction(x[:, 1] - x[:, 0])
    u_last = _direction(x[:, n_edges] - x[:, n_edges - 1])
    cos = np.clip(np.sum(u_first * u_last, axis=-1), -1.0, 1.0)
    return CapstanSeries(t=yarn.t[keep], first=yarn.tensions[keep, 0],
                         last=yarn.tensions[keep, n_edges - 1], theta=np.arccos(cos))


def make_capstan(data: BagData, yarn_name: str, mu: float, path: str) -> dict:
    """Writes capstan.png for yarn ``yarn_name`` with friction coefficient ``mu``; returns the
    series and the ratio and law at the last state before the tear (``final_ratio``,
    ``final_law``)."""
    yarn = data.yarns[yarn_name]
    tears = [b.t for b in data.breaks if b.yarn == yarn_name]
    series = capstan_series(yarn, min(tears) if tears else None)
    ratio = series.ratio()
    law = np.exp(mu * series.theta)
    fig = style.new_figure(figsize=(7.0, 6.0))
    ax_t, ax_r = fig.subplots(2, 1, sharex=True)
    ax_t.plot(series.t, series.last, label="last edge's side (pulled)")
    ax_t.plot(series.t, series.first, label="edge 0's side (held)")
    ax_t.set_ylabel("tension [N]")
    ax_t.set_title("%s wrapped round an obstacle: tension on each side" % yarn_name)
    ax_r.plot(series.t, ratio, label="T_last / T_first")
    ax_r.plot(series.t, law, ls="--", color="k", label="capstan law e^(mu theta), mu = %g" % mu)
    ax_r.set_ylabel("tension ratio [-]")
    ax_r.set_xlabel(style.TIME_LABEL)
    for ax in (ax_t, ax_r):
        style.draw_breaks(ax, [b for b in data.breaks if b.yarn == yarn_name], {}, label=False)
        style.legend(ax, loc="upper left", fontsize=8)
    fig.tight_layout()
    style.save(fig, path)
    valid = np.flatnonzero(np.isfinite(ratio))
    last = valid[-1] if len(valid) else None
    return {"series": series,
            "final_ratio": float(ratio[last]) if last is not None else float("nan"),
            "final_law": float(law[last]) if last is not None else float("nan"),
            "final_theta": float(series.theta[last]) if last is not None else float("nan")}
