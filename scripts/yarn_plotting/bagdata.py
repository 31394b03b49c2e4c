"""Read a yarn_tearing bag into numpy arrays.

Topics are found by message type, not by name, so namespaced topics work:
``*/YarnStateArray`` (required), ``*/BreakEvent`` (optional) and a
``std_msgs/String`` topic whose name ends in ``yarn_materials`` (optional
YAML material metadata, see :mod:`yarn_plotting.materials`).

Units: time [s], positions [m], velocities [m/s], lengths [m], tensions [N],
stresses [Pa], strains [-].
"""

import sys
from dataclasses import dataclass, field
from typing import Dict, List, Optional

import numpy as np
import yaml

STATE_TYPE_SUFFIX = "/YarnStateArray"
BREAK_TYPE_SUFFIX = "/BreakEvent"
METADATA_TYPE = "std_msgs/String"
METADATA_TOPIC_SUFFIX = "yarn_materials"

# A first stamp larger than this [s] is taken as wall-clock time (since 1970)
# rather than simulated time, and the time axis then starts at that stamp.
WALL_CLOCK_THRESHOLD = 1.0e6


class BagError(Exception):
    """The bag is missing, unreadable or holds no yarn states."""


@dataclass
class YarnSeries:
    """Time series of one yarn; row i is the i-th state that contained it.

    Per-edge arrays are padded to the largest edge count seen (NaN, or -1 for
    ``edges``, True for ``broken``); per-vertex arrays likewise with NaN.
    """

    name: str
    t: np.ndarray                # (T,) [s] since the time origin
    positions: np.ndarray        # (T, V, 3) [m]
    velocities: np.ndarray       # (T, V, 3) [m/s], NaN if not published
    edges: np.ndarray            # (T, E, 2) vertex indices, -1 = padding
    rest_lengths: np.ndarray     # (T, E) [m]
    tensions: np.ndarray         # (T, E) [N]
    stresses: np.ndarray         # (T, E) [Pa]
    strains: np.ndarray          # (T, E) [-]
    plastic_strains: np.ndarray  # (T, E) [-]
    broken: np.ndarray           # (T, E) bool
    supports: List[np.ndarray]   # T arrays of pinned/grasped vertex indices

    def edge_lengths(self) -> np.ndarray:
        """(T, E) current edge lengths [m] from positions; NaN for padding."""
        e = np.where(self.edges < 0, 0, self.edges)
        rows = np.arange(len(self.t))[:, None]
        d = self.positions[rows, e[..., 1]] - self.positions[rows, e[..., 0]]
        length = np.linalg.norm(d, axis=-1)
        return np.where(self.edges[..., 0] < 0, np.nan, length)

    def intact(self) -> np.ndarray:
        """(T, E) True where the edge exists and is not broken."""
        return ~self.broken & (self.edges[..., 0] >= 0)


@dataclass
class BreakRecord:
    """One BreakEvent. ``t`` [s] is its header.stamp minus the time origin."""

    t: float
    yarn: str
    edge: int
    position: np.ndarray  # (3,) [m]
    tension: float        # [N]
    stress: float         # [Pa]
    strain: float         # [-]
    plastic_strain: float  # [-]


@dataclass
class BagData:
    """Everything the figures need from one bag."""

    yarns: Dict[str, YarnSeries]        # in order of first appearance
    breaks: List[BreakRecord]           # sorted by time
    metadata: Optional[dict]            # parsed yarn_materials YAML, or None
    time_origin: float                  # [s] stamp that maps to t = 0
    frame_id: str = ""
    topics: Dict[str, str] = field(default_factory=dict)  # role -> topic

    def times(self) -> np.ndarray:
        """Sorted union of all yarns' sample times [s]."""
        return np.unique(np.concatenate([y.t for y in self.yarns.values()]))


def _stamps(raw, use_bag_time):
    """[(t [s], bag time [s], msg)] from [(msg, bag time)]: t = header.stamp or bag time."""
    return [((bt if use_bag_time else m.header.stamp).to_sec(), bt.to_sec(), m)
            for m, bt in raw]


def _topics_by_type(info) -> Dict[str, List[str]]:
    """Role -> topics. One state topic (the busiest); break and metadata topics
    in its namespace if there are any there, else all of them."""
    roles = {"states": [], "breaks": [], "metadata": []}
    for topic, tinfo in sorted(info.topics.items()):
        mtype = tinfo.msg_type
        if mtype.endswith(STATE_TYPE_SUFFIX):
            roles["states"].append(topic)
        elif mtype.endswith(BREAK_TYPE_SUFFIX):
            roles["breaks"].append(topic)
        elif mtype == METADATA_TYPE and topic.endswith(METADATA_TOPIC_SUFFIX):
            roles["metadata"].append(topic)
    if roles["states"]:
        roles["states"] = [max(roles["states"], key=lambda t: info.topics[t].message_count)]
        ns = roles["states"][0].rsplit("/", 1)[0] + "/"
        for role in ("breaks", "metadata"):
            roles[role] = [t for t in roles[role] if t.startswith(ns)] or roles[role]
    return roles


def _pad(rows, width, fill, dtype=float, tail=()):
    out = np.full((len(rows), width) + tail, fill, dtype=dtype)
    for i, r in enumerate(rows):
        r = np.asarray(r, dtype=dtype).reshape((-1,) + tail)
        out[i, : len(r)] = r
    return out


def _xyz(points) -> np.ndarray:
    return np.array([[p.x, p.y, p.z] for p in points], dtype=float).reshape(-1, 3)


def _series(name, samples) -> YarnSeries:
    """Stack the per-sample dicts of one yarn into a YarnSeries."""
    nv = max(len(s["positions"]) for s in samples)
    ne = max(len(s["edges"]) for s in samples)
    col = lambda key: [s[key] for s in samples]  # noqa: E731
    vel = [v if len(v) == len(p) else np.full_like(p, np.nan)
           for v, p in zip(col("velocities"), col("positions"))]
    return YarnSeries(
        name=name,
        t=np.array(col("t")),
        positions=_pad(col("positions"), nv, np.nan, tail=(3,)),
        velocities=_pad(vel, nv, np.nan, tail=(3,)),
        edges=_pad(col("edges"), ne, -1, dtype=int, tail=(2,)),
        rest_lengths=_pad(col("rest_lengths"), ne, np.nan),
        tensions=_pad(col("tensions"), ne, np.nan),
        stresses=_pad(col("stresses"), ne, np.nan),
        strains=_pad(col("strains"), ne, np.nan),
        plastic_strains=_pad(col("plastic_strains"), ne, np.nan),
        broken=_pad(col("broken"), ne, True, dtype=bool),
        supports=[np.asarray(s, dtype=int) for s in col("supports")],
    )


def _sample(ys, t) -> dict:
    ne = len(ys.edge_vertices) // 2
    fit = lambda a, fill=np.nan: (list(a) + [fill] * ne)[:ne]  # noqa: E731
    return {
        "t": t,
        "positions": _xyz(ys.positions),
        "velocities": _xyz(ys.velocities),
        "edges": np.asarray(ys.edge_vertices, dtype=int)[: 2 * ne].reshape(-1, 2),
        "rest_lengths": fit(ys.rest_lengths),
        "tensions": fit(ys.tensions),
        "stresses": fit(ys.stresses),
        "strains": fit(ys.strains),
        "plastic_strains": fit(ys.plastic_strains, 0.0),
        "broken": fit(ys.broken, False),
        "supports": list(ys.support_vertices),
    }


def read_bag(path: str) -> BagData:
    """Read ``path`` into a :class:`BagData`; raise :class:`BagError` on failure."""
    import genpy
    import rosbag  # imported late so `--help` works without ROS libs

    try:
        bag = rosbag.Bag(path, "r")
    except rosbag.ROSBagUnindexedException as exc:
        raise BagError("bag %r is unindexed (run `rosbag reindex` on it)" % path) from exc
    except Exception as exc:  # rosbag raises several unrelated types
        raise BagError("cannot read bag %r: %s" % (path, exc)) from exc
    try:
        with bag:
            states, breaks, meta, roles = _read_raw(bag)
    except (rosbag.ROSBagException, genpy.DeserializationError, OSError) as exc:
        raise BagError("cannot read bag %r: %s" % (path, exc)) from exc
    if not roles["states"]:
        raise BagError("bag %r has no yarn_tearing/YarnStateArray topic (yarn_states)" % path)
    if not any(msg.yarns for _, _, msg in states):
        raise BagError("bag %r has no yarns on %s" % (path, roles["states"][0]))
    states, breaks = _last_run(states, breaks)
    first = states[0][0]
    origin = first if first > WALL_CLOCK_THRESHOLD else 0.0
    per_yarn: Dict[str, list] = {}
    for stamp, _, msg in states:
        for ys in msg.yarns:
            per_yarn.setdefault(ys.name, []).append(_sample(ys, stamp - origin))
    return BagData(
        yarns={name: _series(name, s) for name, s in per_yarn.items()},
        breaks=sorted((_break(stamp - origin, m) for stamp, _, m in breaks), key=lambda b: b.t),
        metadata=_parse_metadata(meta[-1]) if meta else None,
        time_origin=origin,
        frame_id=states[0][2].header.frame_id,
        topics={role: topics[0] for role, topics in roles.items() if topics},
    )


def _break(t, m) -> BreakRecord:
    return BreakRecord(t=t, yarn=m.yarn, edge=m.edge,
                       position=np.array([m.position.x, m.position.y, m.position.z]),
                       tension=m.tension, stress=m.stress, strain=m.strain,
                       plastic_strain=m.plastic_strain)


def _read_raw(bag):
    """(states, breaks, metadata strings, roles); states and breaks as
    (t [s], bag time [s], msg) in recording order.

    t is header.stamp, or the bag's receive time if no state is stamped.
    """
    roles = _topics_by_type(bag.get_type_and_topic_info())

    def read(role):
        if not roles[role]:
            return []
        return [(m, bt) for _, m, bt in bag.read_messages(topics=roles[role])]

    states, breaks = read("states"), read("breaks")
    unstamped = all(m.header.stamp.is_zero() for m, _ in states)
    meta = [m.data for m, _ in read("metadata")]
    return _stamps(states, unstamped), _stamps(breaks, unstamped), meta, roles


def _last_run(states, breaks):
    """Keep the states and breaks after the last simulation reset (time going back)."""
    t = np.array([s[0] for s in states])
    resets = np.flatnonzero(np.diff(t) < -1e-9) + 1
    if not len(resets):
        return states, breaks
    start = resets[-1]
    print("warning: simulated time goes back %d time(s) in the bag (reset?): plotting only "
          "the last run, from bag time %.3f s" % (len(resets), states[start][1]),
          file=sys.stderr)
    return states[start:], [b for b in breaks if b[1] >= states[start][1]]


def _parse_metadata(text: str) -> Optional[dict]:
    """Parse the yarn_materials YAML; None (with a warning) if it is not a mapping."""
    try:
        data = yaml.safe_load(text)
    except yaml.YAMLError as exc:
        print("warning: ignoring unparsable yarn_materials metadata: %s" % exc, file=sys.stderr)
        return None
    return data if isinstance(data, dict) else None
