"""Write small yarn_tearing bags for the plot tests, without a built package.

Message classes are generated at run time from ../../msg/*.msg with
``genpy.dynamic`` (the full text is what rosbag stores as the definition).

Scenario (simulated time, 30 Hz, t = 0 .. 3.5 s), two vertical yarns of
N_EDGES edges hanging from a pinned top vertex at z = 0, pulled down at the
bottom vertex; tension peaks on one edge (the one that tears):

* ``weak`` (x = 0): load ramps to sigma_b, tears at t = WEAK_BREAK;
* ``strong`` (x = 0.05 m): loaded past yield, released (permanent elongation),
  reloaded, tears at t = STRONG_BREAK.
"""

import os

import numpy as np

MSG_DIR = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "msg")
SEP = "=" * 80 + "\n"
PKG = "yarn_tearing"
DEPS = {
    "std_msgs/Header": "uint32 seq\ntime stamp\nstring frame_id\n",
    "geometry_msgs/Point": "float64 x\nfloat64 y\nfloat64 z\n",
    "geometry_msgs/Vector3": "float64 x\nfloat64 y\nfloat64 z\n",
}

RATE = 30.0             # [Hz]
DURATION = 3.5          # [s]
N_EDGES = 12
REST = 0.02             # [m] original rest length of an edge
RADIUS = 1.0e-4         # [m]
AREA = np.pi * RADIUS ** 2
WEAK_BREAK = 1.0        # [s]
STRONG_BREAK = 2.5      # [s]
MATERIALS = {           # SI units
    "weak": {"breaking_stress": 3.0e8, "breaking_strain": 0.05, "yield_stress": 1.5e8,
             "yield_strain": 0.0075, "curve": [[0, 0], [0.0075, 1.5e8], [0.05, 3.0e8]]},
    "strong": {"breaking_stress": 6.0e8, "breaking_strain": 0.08, "yield_stress": 3.0e8,
               "yield_strain": 0.015, "curve": [[0, 0], [0.015, 3.0e8], [0.08, 6.0e8]]},
}
# [N] yarn_materials weakest_breaking_force: weak's weakest edge is 10 % weaker than
# sigma_b pi r^2 (strength scatter), strong's within 0.1 % (no line drawn for it)
WEAKEST_FORCE = {"weak": 0.9 * 3.0e8 * AREA, "strong": 1.0002 * 6.0e8 * AREA}
TEAR_EDGE = {"weak": 7, "strong": 4}
X0 = {"weak": 0.0, "strong": 0.05}


def message_classes():
    """{'YarnStateArray', 'YarnState', 'BreakEvent', 'String'} -> generated classes."""
    import genpy.dynamic

    def read(name):
        with open(os.path.join(MSG_DIR, name + ".msg")) as f:
            return f.read()

    deps = dict(DEPS, **{PKG + "/YarnState": read("YarnState")})
    dep_text = "".join(SEP + "MSG: %s\n%s\n" % kv for kv in deps.items())
    out = {}
    for name in ("YarnStateArray", "BreakEvent"):
        types = genpy.dynamic.generate_dynamic(PKG + "/" + name, read(name) + "\n" + dep_text)
        out[name] = types[PKG + "/" + name]
        out.setdefault("YarnState", types.get(PKG + "/YarnState"))
        out["Point"] = types["geometry_msgs/Point"]
        out["Vector3"] = types["geometry_msgs/Vector3"]
    out["String"] = genpy.dynamic.generate_dynamic("std_msgs/String", "string data\n")[
        "std_msgs/String"]
    return out


def _strain(stress, mat, plastic):
    """(strain, plastic strain) [-] on the piecewise-linear curve, elastic unloading."""
    c = np.array(mat["curve"], dtype=float)
    e_mod = c[1, 1] / c[1, 0]
    on_curve = float(np.interp(stress, c[:, 1], c[:, 0]))
    if on_curve > plastic + stress / e_mod:  # plastic flow
        return on_curve, on_curve - stress / e_mod
    return plastic + stress / e_mod, plastic


def _load(name, t):
    """Bottom force [N] at time t (None after the tear)."""
    fb = MATERIALS[name]["breaking_stress"] * AREA / _PEAK
    if name == "weak":
        return fb * t / WEAK_BREAK if t < WEAK_BREAK - 1e-9 else None
    f_mid = 0.75 * fb
    if t <= 1.0:
        return f_mid * t
    if t <= 1.5:
        return f_mid * (1.5 - t) / 0.5
    if t <= 1.8:
        return 0.0
    return fb * (t - 1.8) / (STRONG_BREAK - 1.8) if t < STRONG_BREAK - 1e-9 else None


_PEAK = 1.02  # the torn edge carries 2 % more than the others


def states(name, x0):
    """Yield (t, dict of per-yarn arrays) for one yarn over the whole bag."""
    mat, k = MATERIALS[name], TEAR_EDGE[name]
    shape = 1.0 + (_PEAK - 1.0) * np.exp(-((np.arange(N_EDGES) - k) ** 2))
    plastic = np.zeros(N_EDGES)
    broken = np.zeros(N_EDGES, bool)
    last, t_tear = None, None
    for i in range(int(round(DURATION * RATE)) + 1):
        t = i / RATE
        force = _load(name, t)
        if force is None and t_tear is None:
            t_tear, broken[k] = t, True
        tension = np.zeros(N_EDGES) if force is None else force * shape
        strain = np.empty(N_EDGES)
        for e in range(N_EDGES):
            strain[e], plastic[e] = _strain(tension[e] / AREA, mat, plastic[e])
        lengths = REST * (1.0 + strain)
        z = -np.concatenate([[0.0], np.cumsum(lengths)])
        x = np.full(N_EDGES + 1, x0)
        if t_tear is not None:  # upper part recoils and sways, lower part falls
            s = t - t_tear
            x[: k + 1] += 0.01 * np.sin(20 * s) * np.exp(-s / 0.15) * np.arange(k + 1) / k
            z[: k + 1] += 0.004 * np.arange(k + 1) / k * (1 - np.exp(-s / 0.05))
            z[k + 1:] -= 4.9 * s ** 2 + 0.02 * s
        pos = np.stack([x, np.zeros_like(x), z], axis=1)
        vel = np.zeros_like(pos) if last is None else (pos - last) * RATE
        last = pos
        yield t, dict(positions=pos, velocities=vel, tension=tension, strain=strain,
                      plastic=plastic.copy(), broken=broken.copy(), t_tear=t_tear)


def node_metadata():
    """yarn_materials text in the node's format (materials_description.cpp)."""
    f = lambda x: "%.9e" % x  # noqa: E731  (YAML 1.1 float: '.' and signed exponent)
    out = []
    for name, m in MATERIALS.items():
        out.append('"%s":\n  material: "%s_preset"\n' % (name, name))
        out += ["  %s: %s\n" % (k, f(m[k])) for k in
                ("breaking_stress", "breaking_strain", "yield_stress", "yield_strain")]
        out.append("  youngs_modulus: %s\n  area: %s\n  weakest_breaking_force: %s\n"
                   "  radius: %s\n  density: 1.5e+03\n"
                   % (f(m["curve"][1][1] / m["curve"][1][0]), f(AREA), f(WEAKEST_FORCE[name]),
                      f(RADIUS)))
        out.append("  curve: [%s]\n" % ", ".join("[%s, %s]" % (f(a), f(b))
                                                 for a, b in m["curve"]))
    return "".join(out)


def _points(cls, rows):
    return [cls(x=float(v[0]), y=float(v[1]), z=float(v[2])) for v in rows]


def _yarn_state(cls, name, d):
    ys = cls["YarnState"](name=name)
    ys.positions = _points(cls["Point"], d["positions"])
    ys.velocities = _points(cls["Vector3"], d["velocities"])
    ys.edge_vertices = [v for e in range(N_EDGES) for v in (e, e + 1)]
    ys.rest_lengths = list(REST * (1.0 + d["plastic"]))
    ys.tensions = list(d["tension"])
    ys.stresses = list(d["tension"] / AREA)
    ys.strains = list(d["strain"])
    ys.plastic_strains = list(d["plastic"])
    ys.strain_limits = list(d["strain"])
    ys.broken = [bool(b) for b in d["broken"]]
    ys.support_vertices = [0]
    ys.support_forces = _points(cls["Vector3"], [[0, 0, float(d["tension"][0])]])
    return ys


def _break_event(cls, name, prev, stamp):
    """BreakEvent of ``name``'s TEAR_EDGE; ``prev`` = the state just before the tear."""
    k = TEAR_EDGE[name]
    ev = cls["BreakEvent"](yarn=name, edge=k, vertex_a=k, vertex_b=k + 1)
    ev.header.stamp, ev.header.frame_id = stamp, "world"
    ev.position = cls["Point"](*(0.5 * (prev["positions"][k] + prev["positions"][k + 1])))
    ev.stress = MATERIALS[name]["breaking_stress"]
    ev.tension = ev.stress * AREA
    ev.strain = MATERIALS[name]["breaking_strain"]
    ev.plastic_strain = float(prev["plastic"][k])
    return ev


def write_bag(path, with_states=True, with_breaks=True, with_metadata=True, ns="/sim",
              t0=0.0, overlap=False, reset=False):
    """Write the scenario to ``path``; return {yarn: break time [s]} (without t0).

    ``t0`` [s] is added to every stamp (e.g. 1.7e9 for wall-clock stamps);
    ``overlap`` puts both yarns at x = 0; ``reset`` records first an aborted
    run (0.5 s, a tear of ``weak`` at 0.2 s) then the scenario from t = 0 again.
    """
    import rosbag
    import rospy

    cls = message_classes()
    yarns = ("weak", "strong")
    series = {n: list(states(n, 0.0 if overlap else X0[n])) for n in yarns}
    t_breaks = {}
    time = rospy.Time.from_sec
    with rosbag.Bag(path, "w") as bag:
        if with_metadata:
            bag.write(ns + "/yarn_materials", cls["String"](data=node_metadata()), time(t0))
        bag.write("/chatter", cls["String"](data="unrelated"), time(t0 + 1e-3))
        if reset:  # an aborted first run; its bag times precede the real run's
            for i in range(int(0.5 * RATE)):
                msg = cls["YarnStateArray"](yarns=[_yarn_state(cls, "weak", series["weak"][i][1])])
                msg.header.stamp = time(t0 + i / RATE)
                bag.write(ns + "/yarn_states", msg, time(t0 + i / RATE))
            bag.write(ns + "/break_events", _break_event(cls, "weak", series["weak"][0][1],
                                                         time(t0 + 0.2)), time(t0 + 0.2))
        bag_t0 = t0 + (1.0 if reset else 0.0)  # receive time = stamp + this offset
        for i in range(len(series["weak"])):
            t = series["weak"][i][0]
            stamp = time(t0 + t)
            msg = cls["YarnStateArray"]()
            msg.header.stamp, msg.header.frame_id = stamp, "world"
            for n in yarns:
                d = series[n][i][1]
                msg.yarns.append(_yarn_state(cls, n, d))
                if d["t_tear"] == t and with_breaks:
                    ev = _break_event(cls, n, series[n][i - 1][1], stamp)
                    bag.write(ns + "/break_events", ev, time(bag_t0 + t))
                    t_breaks[n] = t
            if with_states:
                bag.write(ns + "/yarn_states", msg, time(bag_t0 + t))
    return t_breaks
