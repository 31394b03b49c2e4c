"""Pick the filmstrip frames: from first load, through the tears, to the recoil.

All times are in seconds on the BagData time axis.
"""

from typing import List

import numpy as np


def load_onset(data, fraction: float = 0.01) -> float:
    """First time any edge tension exceeds ``fraction`` of the bag's max tension [s]."""
    peaks = [(y.t, np.nanmax(y.tensions, axis=1, initial=0.0)) for y in data.yarns.values()]
    top = max(p.max(initial=0.0) for _, p in peaks)
    loaded = [t[p > fraction * top] for t, p in peaks]
    starts = [float(t[0]) for t in loaded if len(t)]
    return min(starts) if top > 0.0 and starts else float(data.times()[0])


def tear_times(data) -> List[float]:
    """Distinct tear instants [s]: BreakEvent stamps, else when ``broken`` flags flip."""
    if data.breaks:
        return sorted({b.t for b in data.breaks})
    times = set()
    for y in data.yarns.values():
        n_broken = y.broken.sum(axis=1) - (y.edges[..., 0] < 0).sum(axis=1)
        times.update(y.t[1:][np.diff(n_broken) > 0].tolist())
    return sorted(times)


def max_speed(data) -> tuple:
    """(times [s], max vertex speed over all yarns [m/s]) on the union time axis.

    Uses the published velocities, or finite differences of positions if absent.
    """
    times = data.times()
    speed = np.zeros(len(times))
    for y in data.yarns.values():
        v = np.linalg.norm(y.velocities, axis=-1)
        if np.isnan(v).all() and len(y.t) > 1:
            dt = np.maximum(np.diff(y.t), 1e-12)[:, None]
            v = np.vstack([np.zeros((1, v.shape[1])),
                           np.linalg.norm(np.diff(y.positions, axis=0), axis=-1) / dt])
        idx = np.searchsorted(times, y.t)
        speed[idx] = np.maximum(speed[idx], np.nan_to_num(np.nanmax(v, axis=1, initial=0.0)))
    return times, speed


def recoil_end(data, t_tear: float, t_load: float, settle: float = 0.25,
               min_window: float = 0.3) -> float:
    """End of the recoil after the tear at ``t_tear`` [s].

    The first time after the post-tear speed peak when the max vertex speed has
    fallen below ``settle`` times that peak, but no later than
    ``t_tear + max(min_window, 0.2 (t_tear - t_load))`` nor the bag's end.
    """
    times, speed = max_speed(data)
    cap = min(times[-1], t_tear + max(min_window, 0.2 * (t_tear - t_load)))
    after = (times >= t_tear) & (times <= cap)
    if not after.any() or speed[after].max() <= 0.0:
        return float(cap)
    i_peak = np.flatnonzero(after)[np.argmax(speed[after])]
    calm = np.flatnonzero((speed < settle * speed[i_peak]) & after)
    calm = calm[calm > i_peak]
    return float(times[calm[0]]) if len(calm) else float(cap)


def choose_frames(data, n: int = 8) -> np.ndarray:
    """About ``n`` sample times [s] from first load to the recoil after the last tear.

    Always includes the load onset, the last samples before the first and last
    tears, the first sample at or after each tear (only the first and last
    tears if space is short) and the recoil end; the rest fill the largest
    time gaps.
    """
    times = data.times()
    t_load = load_onset(data)
    tears = [t for t in tear_times(data) if t >= t_load] or tear_times(data)
    t_end = recoil_end(data, tears[-1], t_load) if tears else float(times[-1])
    t_load = min(t_load, t_end)
    keys = [t_load, t_end]
    if tears:  # the most loaded states: just before the first and last tears
        keys += [times[max(np.searchsorted(times, t) - 1, 0)] for t in {tears[0], tears[-1]}]
        tear_frames = [times[min(np.searchsorted(times, t), len(times) - 1)] for t in tears]
        room = max(n - 4, 1)
        if len(tear_frames) > room:
            tear_frames = tear_frames[: room - 1] + tear_frames[-1:]
        keys += tear_frames
    window = times[(times >= t_load) & (times <= t_end)]
    chosen = sorted({float(times[np.argmin(np.abs(times - k))]) for k in keys})
    while len(chosen) < n:
        best = None  # (gap length, sample nearest the gap's middle)
        for a, b in zip(chosen[:-1], chosen[1:]):
            free = window[(window > a) & (window < b)]
            if len(free) and (best is None or b - a > best[0]):
                best = (b - a, float(free[np.argmin(np.abs(free - (a + b) / 2))]))
        if best is None:
            break
        chosen = sorted(chosen + [best[1]])
    return np.array(chosen)
