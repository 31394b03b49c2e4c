"""Time-series figures: tension_strain.png, stress_strain.png, length.png.

Plotted units: time [s], tension [N], strain [%], stress [MPa], length [mm]
below 1 m else [m]; inputs are SI (see :mod:`yarn_plotting.bagdata`).
"""

import numpy as np

from . import style

MPA = 1.0e-6  # Pa -> MPa
PERCENT = 100.0
SCATTER_SHOWN = 1.0e-3  # [-] weakest-edge line drawn if it differs this much from σ_b·πr²
WEAKEST_DASHES = (0, (8, 3))  # longer than the "--" of the breaking-force line


def make_tension_strain(data, strengths, path) -> dict:
    """Max tension [N] and max strain [%] over intact edges vs time, per yarn.

    Break instants (BreakEvent header.stamp) are dotted vertical lines, the
    breaking force sigma_b pi r^2 a dashed horizontal line per yarn, and where
    strength scatter makes the weakest edge's breaking force (material
    ``weakest_breaking_force``) differ from it by more than SCATTER_SHOWN, a
    long-dashed line there.  Returns ``{"break_times": [...], "weakest_lines":
    {yarn: y [N]}}``, the x positions [s] of the drawn break lines and the
    heights of the drawn weakest-edge lines.
    """
    fig = style.new_figure(figsize=(11.5, 6.5), layout="constrained")
    ax_t, ax_e = fig.subplots(2, 1, sharex=True)
    col = style.colours(data.yarns)
    known = {n: strengths[n] for n in data.yarns if strengths.get(n) is not None}
    forces = {n: st.breaking_force for n, st in known.items() if st.breaking_force is not None}
    strains = {n: st.material.breaking_strain * PERCENT for n, st in known.items()
               if st.material is not None and st.material.breaking_strain}
    weakest = {n: w for n, w in ((n, _weakest_force(st)) for n, st in known.items())
               if w is not None}
    force_ls, strain_ls = dash_styles(forces), dash_styles(strains)
    weakest_lines = {}
    for name, y in data.yarns.items():
        ok = y.intact()
        ax_t.plot(y.t, style.masked_max(y.tensions, ok), color=col[name],
                  label="%s: max tension" % name)
        ax_e.plot(y.t, style.masked_max(y.strains, ok) * PERCENT, color=col[name],
                  label="%s: max strain" % name)
        if name in forces:
            ax_t.axhline(forces[name], color=col[name], ls=force_ls[name], lw=1.2,
                         label="%s: breaking force σ$_b$·πr² = %.3g N (σ$_b$ from %s)"
                         % (name, forces[name], known[name].source))
        if name in weakest:
            line = ax_t.axhline(weakest[name], color=col[name], ls=WEAKEST_DASHES, lw=1.2,
                                label="%s: weakest edge (strength scatter): %.3g N"
                                % (name, weakest[name]))
            weakest_lines[name] = float(line.get_ydata()[0])
        if name in strains:
            ax_e.axhline(strains[name], color=col[name], ls=strain_ls[name], lw=1.2,
                         label="%s: breaking strain (%s)" % (name, known[name].source))
    for ax, tops in ((ax_t, list(forces.values()) + list(weakest.values())),
                     (ax_e, list(strains.values()))):
        if tops:  # axhline does not autoscale
            ax.set_ylim(top=max(ax.get_ylim()[1], 1.08 * max(tops)))
    style.draw_breaks(ax_t, data.breaks, col)
    style.draw_breaks(ax_e, data.breaks, col, label=False)
    ax_t.set_ylabel("max tension over edges [N]")
    ax_e.set_ylabel("max strain over edges [%]")
    ax_e.set_xlabel(style.TIME_LABEL)
    ax_t.set_title("Max tension and max strain over the intact edges of each yarn")
    for ax in (ax_t, ax_e):
        ax.grid(alpha=0.3)
        style.legend(ax, fontsize=7, loc="upper left", bbox_to_anchor=(1.01, 1.0))
    style.save(fig, path)
    return {"break_times": style.drawn_breaks(ax_t), "weakest_lines": weakest_lines}


def _weakest_force(strength):
    """The material's weakest-edge breaking force [N] if it is known and differs from
    sigma_b pi r^2 by more than SCATTER_SHOWN (or that is unknown), else None."""
    weakest = strength.material.weakest_breaking_force if strength.material else None
    nominal = strength.breaking_force
    if weakest is None or (nominal and abs(weakest - nominal) <= SCATTER_SHOWN * nominal):
        return None
    return weakest


def dash_styles(values: dict, on: float = 5.0) -> dict:
    """Yarn -> linestyle for horizontal lines at ``values`` (yarn -> y): "--" for a
    value of one yarn only; equal values get interleaved dashes so each colour shows."""
    out = {}
    for name, v in values.items():
        same = [n for n, w in values.items() if np.isclose(w, v, rtol=1e-9, atol=0.0)]
        n, k = len(same), same.index(name)
        out[name] = "--" if n == 1 else ((n - k) % n * on, (on, (n - 1) * on))
    return out


def _peak_edge(y, breaks):
    """Index of the edge with the highest stress [Pa] over the bag, or None.

    Counts the intact samples and the BreakEvent stresses (a tear usually
    falls between two samples, so its edge carried the highest stress).
    """
    s = np.where(y.intact() & np.isfinite(y.stresses), y.stresses, -np.inf)
    if not s.size:
        return None
    peak = s.max(axis=0)
    for b in breaks:
        if 0 <= b.edge < len(peak):
            peak[b.edge] = max(peak[b.edge], b.stress)
    return int(np.argmax(peak))


def make_stress_strain(data, strengths, path) -> dict:
    """Per yarn: stress [MPa] vs strain [%] path of its most stressed edge.

    Drawn over the material curve when known, with the material's yield and
    break points, the first sample with plastic strain (observed yield) and
    the BreakEvent's (strain, stress) (observed tear).  Returns
    ``{"edges": {yarn: edge index}}``.
    """
    names = list(data.yarns)
    fig = style.new_figure(figsize=(4.6 * len(names) + 0.6, 4.6), layout="constrained")
    axes = fig.subplots(1, len(names), squeeze=False)[0]
    col, chosen = style.colours(names), {}
    for ax, name in zip(axes, names):
        y, st = data.yarns[name], strengths.get(name)
        breaks = [b for b in data.breaks if b.yarn == name]
        e = chosen[name] = _peak_edge(y, breaks)
        m = st.material if st is not None else None
        if m is not None and m.curve is not None:
            ax.plot(m.curve[:, 0] * PERCENT, m.curve[:, 1] * MPA, color="0.6", lw=5,
                    alpha=0.6, label="material curve (%s)" % st.source, zorder=1)
        if m is not None and m.yield_strain is not None and m.yield_stress is not None:
            ax.plot(m.yield_strain * PERCENT, m.yield_stress * MPA, "o", color="0.3",
                    ms=8, label="yield point (material)", zorder=2)
        if m is not None and m.breaking_strain is not None and m.breaking_stress:
            ax.plot(m.breaking_strain * PERCENT, m.breaking_stress * MPA, "X", color="0.3",
                    ms=9, label="break point (material)", zorder=2)
        if e is not None:
            _draw_path(ax, y, e, col[name], [b for b in breaks if b.edge == e][:1])
        for b in breaks:
            ax.plot(b.strain * PERCENT, b.stress * MPA, "*", color="red", ms=13,
                    label="tear of edge %d (t = %.3f s)" % (b.edge, b.t), zorder=5)
        ax.set_title("%s: most stressed edge (%s)" % (name, e))
        ax.set_xlabel("strain [%]")
        ax.set_ylabel("stress [MPa]")
        if ax.dataLim.x0 >= 0:  # start at the origin unless there is compression
            ax.set_xlim(left=0)
        if ax.dataLim.y0 >= 0:
            ax.set_ylim(bottom=0)
        ax.grid(alpha=0.3)
        style.legend(ax, fontsize=7, loc="lower right")
    fig.suptitle("Stress–strain path of the most stressed edge")
    style.save(fig, path)
    return {"edges": chosen}


def _draw_path(ax, y, e, colour, tear=()):
    """Stress [MPa] vs strain [%] of edge ``e`` while intact (then to its ``tear``
    BreakEvent, if any), and its first sample with plastic strain."""
    ok = y.intact()[:, e]
    strain, stress = y.strains[ok, e], y.stresses[ok, e]
    for b in tear:  # the tear happens after the last intact sample
        last = np.flatnonzero(y.t[ok] <= b.t)
        strain = np.append(strain[: len(last)], b.strain)
        stress = np.append(stress[: len(last)], b.stress)
    ax.plot(strain * PERCENT, stress * MPA, ".-", color=colour, ms=3, lw=1.2,
            label="edge %d over time" % e, zorder=3)
    yielded = np.flatnonzero(ok & (np.nan_to_num(y.plastic_strains[:, e]) > 1e-9))
    if len(yielded):
        i = yielded[0]
        ax.plot(y.strains[i, e] * PERCENT, y.stresses[i, e] * MPA, "o", mfc="none",
                mec=colour, mew=2, ms=10, label="first plastic strain (t = %.3f s)" % y.t[i],
                zorder=4)


def make_length(data, path) -> dict:
    """Per yarn: length from positions and sum of rest lengths vs time [s].

    Both sum over intact edges only (a torn edge has no length).  The dashed
    reference is the original length: the first sample's rest lengths summed
    over the same (still intact) edges, so it steps down by the torn edge's
    original rest length at a tear, and the gap between it and the rest-length
    sum is the permanent (plastic) elongation.  Returns ``{"original_lengths":
    {yarn: first sample's rest-length sum [m]}, "elongations": {yarn: final
    rest-length sum / original - 1 [-]}}``.
    """
    names = list(data.yarns)
    fig = style.new_figure(figsize=(11.5, 2.7 * len(names) + 0.8), layout="constrained")
    axes = fig.subplots(len(names), 1, sharex=True, squeeze=False)[:, 0]
    col, l0s, grown = style.colours(names), {}, {}
    for ax, name in zip(axes, names):
        y = data.yarns[name]
        ok = y.intact()
        length = style.masked_sum(y.edge_lengths(), ok)
        rest = style.masked_sum(y.rest_lengths, ok)
        original = style.masked_sum(np.broadcast_to(y.rest_lengths[0], ok.shape), ok)
        l0s[name] = float(rest[0])
        grown[name] = float(rest[-1] / original[-1] - 1.0) if original[-1] > 0 else np.nan
        scale, unit = (1e3, "mm") if rest[0] < 1.0 else (1.0, "m")
        ax.plot(y.t, length * scale, color=col[name], label="length from positions")
        ax.plot(y.t, rest * scale, color=col[name], ls="-.", lw=1.2,
                label="sum of rest lengths")
        ax.plot(y.t, original * scale, color="k", ls="--", lw=1, drawstyle="steps-post",
                label="original length of the intact edges (%.4g %s at start)"
                % (rest[0] * scale, unit))
        style.draw_breaks(ax, [b for b in data.breaks if b.yarn == name], col)
        ax.text(0.99, 0.95, "permanent elongation at the end: %+.2f %%"
                % (grown[name] * PERCENT), transform=ax.transAxes, ha="right", va="top", fontsize=8,
                bbox=dict(boxstyle="round", fc="white", ec="0.8"))
        ax.set_ylim(*_focus(length, rest, original, scale))
        ax.set_ylabel("length [%s]" % unit)
        ax.set_title(name, fontsize=10, color=col[name], fontweight="bold")
        ax.grid(alpha=0.3)
        style.legend(ax, fontsize=7, loc="upper left", bbox_to_anchor=(1.01, 1.0))
    axes[-1].set_xlabel(style.TIME_LABEL)
    fig.suptitle("Yarn length (intact edges): permanent elongation after yield")
    style.save(fig, path)
    return {"original_lengths": l0s, "elongations": grown}


def _focus(length, rest, original, scale):
    """y-limits [scaled units] around the rest and original lengths and the bulk of
    the position-based length; brief dips (a torn yarn bunching up) are cut off."""
    lo = min(np.nanmin(rest), np.nanmin(original), np.nanpercentile(length, 5))
    hi = max(np.nanmax(rest), np.nanmax(original), np.nanpercentile(length, 99))
    pad = 0.15 * max(hi - lo, 1e-3 * max(abs(hi), 1e-9))
    return (lo - pad) * scale, (hi + pad) * scale
