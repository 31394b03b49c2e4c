"""Figures of a fabric tear test from a bag's ``*/FabricStateArray`` (and ``*/BreakEvent``).

fabric_filmstrip.png  the fabric at a few instants from the first grasp through the tear, its
                      intact segments coloured by stress / the largest stress any segment
                      reached (the breaking stress of the weakest one that tore)
tear_force.png        force-extension curve of the moving grips: extension = increase of the
                      separation of the two groups of grips [m], force = the force they pull
                      with along their motion, mean of the two groups [N]; the peak before each
                      tear (the largest sample since the last one, the state with the tear left
                      out) marked, and their mean

The grips are the supports that move (more than 1 mm over the bag); they are split in two
groups by the sign of their displacement along the direction the farthest one moved. States are
sampled at the node's publish_rate, so the peaks are those of the samples; a state less than
TEAR_STEP (the default time_step) after a break is left out (a tear step's grip forces include
the length stop's).
"""

from dataclasses import dataclass, field
from typing import Dict, List

import numpy as np
from matplotlib.cm import ScalarMappable
from matplotlib.collections import LineCollection
from matplotlib.colors import Normalize

from . import style

STATE_TYPE = "yarn_tearing/FabricStateArray"
BREAK_TYPE = "yarn_tearing/BreakEvent"
FIGURES = ("fabric_filmstrip", "tear_force")
MOVING = 1.0e-3  # [m] a support that moves farther is a grip
TEAR_STEP = 1.0e-3  # [s] a state less than this after a break is of the tear's step (time_step)


@dataclass
class FabricSeries:
    """One fabric's states: T samples, N vertices, E segments."""
    name: str
    t: np.ndarray            # (T,) simulated time [s]
    positions: np.ndarray    # (T, N, 3) [m]
    edges: np.ndarray        # (E, 2) vertex indices
    stresses: np.ndarray     # (T, E) [Pa]
    broken: np.ndarray       # (T, E) bool
    supports: List[Dict[int, np.ndarray]] = field(default_factory=list)  # per T: vertex -> [N]


@dataclass
class TearCurve:
    extension: np.ndarray  # (T,) [m]
    force: np.ndarray      # (T,) [N]
    peaks: List[float]     # [N]
    peak_index: List[int]  # sample of each peak
    mean_peak: float       # [N], nan without peaks


def read_fabrics(path: str):
    """({fabric name: FabricSeries}, [(sim_time [s], fabric name)] of the fabric breaks)."""
    import rosbag  # imported late so that --help works without ROS libs

    with rosbag.Bag(path, "r") as bag:
        info = bag.get_type_and_topic_info()
        topics = {kind: [t for t, ti in info.topics.items() if ti.msg_type == kind]
                  for kind in (STATE_TYPE, BREAK_TYPE)}
        samples: Dict[str, list] = {}
        if topics[STATE_TYPE]:
            for _, msg, _ in bag.read_messages(topics=topics[STATE_TYPE]):
                for f in msg.fabrics:
                    samples.setdefault(f.name, []).append((msg.sim_time, f))
        breaks = []
        if topics[BREAK_TYPE]:
            breaks = [(m.sim_time, m.fabric) for _, m, _ in
                      bag.read_messages(topics=topics[BREAK_TYPE]) if m.fabric]
    return {name: _series(name, s) for name, s in samples.items()}, sorted(breaks)


def _series(name, samples) -> FabricSeries:
    first = samples[0][1]
    edges = np.asarray(first.edge_vertices, dtype=int).reshape(-1, 2)
    return FabricSeries(
        name=name,
        t=np.array([t for t, _ in samples]),
        positions=np.array([[[p.x, p.y, p.z] for p in f.positions] for _, f in samples]),
        edges=edges,
        stresses=np.array([list(f.stresses) for _, f in samples], dtype=float),
        broken=np.array([list(f.broken) for _, f in samples], dtype=bool),
        supports=[{v: np.array([s.x, s.y, s.z]) for v, s in
                   zip(f.support_vertices, f.support_forces)} for _, f in samples],
    )


def tear_curve(fabric: FabricSeries, break_times) -> TearCurve:
    """The grips' force-extension curve and its peaks (module doc)."""
    vertices = sorted(set().union(*fabric.supports)) if fabric.supports else []
    moves = {v: fabric.positions[:, v] - fabric.positions[0, v] for v in vertices}
    grips = [v for v in vertices if np.nanmax(np.linalg.norm(moves[v], axis=1)) > MOVING]
    n = len(fabric.t)
    if not grips:
        return TearCurve(np.zeros(n), np.zeros(n), [], [], float("nan"))
    farthest = max(grips, key=lambda v: np.linalg.norm(moves[v][-1]))
    axis = moves[farthest][-1] / np.linalg.norm(moves[farthest][-1])
    side = {v: np.sign(moves[v][-1] @ axis) or 1.0 for v in grips}
    groups = [[v for v in grips if side[v] > 0], [v for v in grips if side[v] < 0]]
    groups = [g for g in groups if g]
    travel = [np.mean([moves[v] @ axis for v in g], axis=0) for g in groups]
    extension = travel[0] - travel[1] if len(groups) == 2 else np.abs(travel[0])
    force = np.zeros(n)
    for g in groups:
        for v in g:
            # The fabric pulls the grip back: -side * its force along the axis.
            force -= side[v] * np.array([s.get(v, np.zeros(3)) @ axis for s in fabric.supports])
    force /= len(groups)
    # A state of a step with a tear: its grips' forces include the length stop's (doc/method.md,
    # "Breaking-length stop"), up to 10^6 times the yarn's; left out of the curve.
    breaks = np.asarray(break_times, dtype=float)
    for i, t in enumerate(fabric.t):
        if np.any((breaks <= t + 1e-9) & (breaks > t - TEAR_STEP)):
            force[i] = np.nan
    peaks, where = [], []
    start = 0
    for bt in break_times:
        i = int(np.searchsorted(fabric.t, bt - 1e-9))  # first state at or after the break
        if i > start:
            if np.all(np.isnan(force[start:i])):
                start = max(start, i + 1)
                continue
            k = start + int(np.nanargmax(force[start:i]))
            peaks.append(float(force[k]))
            where.append(k)
        start = max(start, i + 1)
    return TearCurve(extension, force, peaks, where,
                     float(np.mean(peaks)) if peaks else float("nan"))


def make_fabric_figures(path: str, out_dir: str, n_frames: int = 6) -> dict:
    """Write FIGURES for the first fabric of the bag into ``out_dir``; {} without fabrics.

    Returns {"paths": {figure: path}, "curve": TearCurve, "fabric": name}.
    """
    import os

    fabrics, breaks = read_fabrics(path)
    if not fabrics:
        return {}
    name = sorted(fabrics)[0]
    fabric = fabrics[name]
    break_times = [t for t, f in breaks if f == name]
    curve = tear_curve(fabric, break_times)
    os.makedirs(out_dir, exist_ok=True)
    paths = {f: os.path.join(out_dir, f + ".png") for f in FIGURES}
    _filmstrip(fabric, curve, break_times, n_frames, paths["fabric_filmstrip"])
    _force_extension(curve, name, paths["tear_force"])
    return {"paths": paths, "curve": curve, "fabric": name}


def _frame_indices(fabric, curve, break_times, n_frames):
    """From the last state before the grips move to the end, evenly in time."""
    moving = np.flatnonzero(np.abs(curve.extension) > MOVING)
    first = max(int(moving[0]) - 1, 0) if len(moving) else 0
    if break_times:
        first = min(first, int(np.searchsorted(fabric.t, break_times[0])))
    times = np.linspace(fabric.t[first], fabric.t[-1], n_frames)
    return sorted(set(int(np.argmin(np.abs(fabric.t - t))) for t in times))


def _filmstrip(fabric, curve, break_times, n_frames, path):
    frames = _frame_indices(fabric, curve, break_times, n_frames)
    scale = np.nanmax(np.where(fabric.broken, np.nan, fabric.stresses))
    scale = scale if np.isfinite(scale) and scale > 0 else 1.0
    norm = Normalize(0.0, 1.0)
    cols = min(4, len(frames))
    rows = -(-len(frames) // cols)
    points = fabric.positions[frames].reshape(-1, 3)
    lo, hi = np.nanmin(points, axis=0), np.nanmax(points, axis=0)
    aspect = (hi[2] - lo[2] + 0.01) / (hi[0] - lo[0] + 0.01)
    fig = style.new_figure(figsize=(2.6 * cols + 1.0, 2.6 * aspect * rows + 0.9),
                           layout="constrained")
    axes = fig.subplots(rows, cols, sharex=True, sharey=True, squeeze=False).ravel()
    for ax in axes[len(frames):]:
        ax.set_visible(False)
    axes = axes[: len(frames)]
    for ax, i in zip(axes, frames):
        keep = ~fabric.broken[i]
        xz = fabric.positions[i][:, [0, 2]]
        segments = np.stack([xz[fabric.edges[keep, 0]], xz[fabric.edges[keep, 1]]], axis=1)
        lines = LineCollection(segments, cmap="viridis", norm=norm, linewidths=0.8)
        lines.set_array(np.clip(fabric.stresses[i][keep] / scale, 0.0, 1.0))
        ax.add_collection(lines)
        ax.set_xlim(lo[0] - 0.005, hi[0] + 0.005)
        ax.set_ylim(lo[2] - 0.005, hi[2] + 0.005)
        ax.set_aspect("equal")
        ax.set_title("t = %.3f s" % fabric.t[i], fontsize=8)
        ax.set_xlabel("x [m]", fontsize=7)
        ax.tick_params(labelsize=6)
    for ax in axes[::cols]:
        ax.set_ylabel("z [m]", fontsize=7)
    bar = ScalarMappable(norm=norm, cmap="viridis")
    fig.colorbar(bar, ax=list(axes), shrink=0.8).set_label(
        "stress / %.3g Pa (largest)" % scale, fontsize=7)
    fig.suptitle("fabric '%s': %d segments torn" % (fabric.name, len(break_times)), fontsize=9)
    style.save(fig, path)


def _force_extension(curve, name, path):
    fig = style.new_figure(figsize=(6.0, 4.0))
    ax = fig.add_subplot(1, 1, 1)
    ax.plot(1e3 * curve.extension, curve.force, color="tab:blue", lw=1.0, label="grips")
    if curve.peaks:
        ax.plot(1e3 * curve.extension[curve.peak_index], curve.peaks, "v", color="tab:red",
                label="peaks (%d)" % len(curve.peaks))
        ax.axhline(curve.mean_peak, color="tab:red", ls="--", lw=0.8,
                   label="mean peak %.3g N" % curve.mean_peak)
    ax.set_xlabel("extension (grip separation) [mm]")
    ax.set_ylabel("tear force [N]")
    ax.set_title("trouser tear of '%s'" % name)
    ax.legend(fontsize=8)
    ax.grid(alpha=0.3)
    fig.tight_layout()
    style.save(fig, path)
