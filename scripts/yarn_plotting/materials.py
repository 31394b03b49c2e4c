"""Yarn material properties for the plots, and where they come from.

A material is a mapping with any of these keys (SI units)::

    breaking_stress: 3.0e8     # [Pa]  sigma_b
    breaking_strain: 0.05      # [-]
    yield_stress: 2.0e8        # [Pa]
    yield_strain: 0.01         # [-]
    young_modulus: 2.0e10      # [Pa]  gives yield_strain = yield_stress / E
    area: 3.1e-8               # [m^2] } used only if the bag has no edge with
    radius: 1.0e-4             # [m]   } nonzero stress and no BreakEvent
    weakest_breaking_force: 4.2  # [N] tension at which the weakest edge tears
                                 # (strength scatter; the node publishes it)
    curve: [[0, 0], [0.01, 2.0e8], [0.05, 3.0e8]]   # [[strain, stress Pa], ...]

``stress_strain`` is accepted for ``curve`` (config/materials.yaml); without
explicit values the yield point is the curve's second point, the break point
its last.  This is also the format of the node's latched ``yarn_materials``
topic (which adds ``material``, ``density``... ignored here).

Sources, in order of precedence for each yarn:

1. ``--material yarn=preset``: preset from the material file, a mapping of
   preset name -> material (optionally nested under ``materials:`` or
   ``presets:``);
2. the bag's ``*yarn_materials`` std_msgs/String topic: YAML mapping of yarn
   name -> material (or -> preset name, looked up in the material file);
3. otherwise only sigma_b is known, from the yarn's first BreakEvent stress.

The cross-section area pi r^2 [m^2] is tension / stress of any edge with a
nonzero stress (median over the bag), else the BreakEvent's, else the
material's ``area``, else pi radius^2.
"""

from dataclasses import dataclass
from typing import Dict, Optional

import numpy as np
import yaml

_ALIASES = {
    "breaking_stress": ("breaking_stress", "break_stress", "sigma_b"),
    "breaking_strain": ("breaking_strain", "break_strain", "epsilon_b"),
    "yield_stress": ("yield_stress", "sigma_y"),
    "yield_strain": ("yield_strain", "epsilon_y"),
    "young_modulus": ("young_modulus", "youngs_modulus", "E"),
    "radius": ("radius",),
    "area": ("area",),
    "weakest_breaking_force": ("weakest_breaking_force",),
}


@dataclass
class Material:
    """Stress-strain properties; any field may be None when unknown."""

    breaking_stress: Optional[float] = None  # [Pa]
    breaking_strain: Optional[float] = None  # [-]
    yield_stress: Optional[float] = None     # [Pa]
    yield_strain: Optional[float] = None     # [-]
    radius: Optional[float] = None           # [m]
    area: Optional[float] = None             # [m^2] load-bearing cross-section
    weakest_breaking_force: Optional[float] = None  # [N] tears the weakest edge
    curve: Optional[np.ndarray] = None       # (N, 2): strain [-], stress [Pa]

    @classmethod
    def from_dict(cls, d: dict) -> "Material":
        """Build from a mapping with the keys in the module docstring.

        Missing values are taken from the curve: yield = its second point,
        break = its last point (the node's config/materials.yaml convention).
        """
        get = {k: next((float(d[a]) for a in names if d.get(a) is not None), None)
               for k, names in _ALIASES.items()}
        curve = _curve(d.get("curve", d.get("stress_strain")))
        e_mod = get.pop("young_modulus")
        m = cls(curve=curve, **get)
        if curve is not None:
            yield_point = curve[1] if len(curve) > 2 else None
            if m.yield_stress is None and yield_point is not None:
                m.yield_stress = float(yield_point[1])
            if m.yield_strain is None and m.yield_stress is not None:
                m.yield_strain = float(np.interp(m.yield_stress, curve[:, 1], curve[:, 0]))
            if m.breaking_strain is None:
                m.breaking_strain = float(curve[-1, 0])
            if m.breaking_stress is None:
                m.breaking_stress = float(curve[-1, 1])
            return m
        if m.yield_strain is None and m.yield_stress is not None and e_mod:
            m.yield_strain = m.yield_stress / e_mod
        points = (m.yield_strain, m.yield_stress, m.breaking_strain, m.breaking_stress)
        if None not in points:
            m.curve = np.array([[0.0, 0.0], points[:2], points[2:]])
        return m


def _curve(points) -> Optional[np.ndarray]:
    """(N, 2) [strain, stress] array; columns swapped if given as [stress, strain]."""
    try:
        c = np.asarray(points, dtype=float).reshape(-1, 2)
    except (TypeError, ValueError):
        return None
    if len(c) < 2:
        return None
    if np.abs(c[:, 0]).max() > np.abs(c[:, 1]).max():  # stress [Pa] >> strain
        c = c[:, ::-1]
    return c[np.argsort(c[:, 0], kind="stable")]


def load_presets(path: str) -> Dict[str, dict]:
    """Preset name -> material mapping from a YAML material file.

    Raises OSError if unreadable, yaml.YAMLError or KeyError if malformed.
    """
    with open(path) as f:
        data = yaml.safe_load(f) or {}
    if not isinstance(data, dict):
        raise KeyError("material file %s is not a YAML mapping of presets" % path)
    for key in ("materials", "presets", "yarn_materials"):
        if isinstance(data.get(key), dict):
            data = data[key]
            break
    return {str(k): v for k, v in data.items() if isinstance(v, dict)}


@dataclass
class YarnStrength:
    """What the plots know about one yarn's strength."""

    material: Optional[Material]
    breaking_stress: Optional[float]  # [Pa] sigma_b
    source: str                       # where sigma_b came from, for legends
    area: Optional[float]             # [m^2] pi r^2

    @property
    def breaking_force(self) -> Optional[float]:
        """sigma_b * pi r^2 [N], or None if either is unknown."""
        if self.breaking_stress is None or self.area is None:
            return None
        return self.breaking_stress * self.area


def _area(series, breaks, material) -> Optional[float]:
    s, t = series.stresses, series.tensions
    ok = np.isfinite(s) & np.isfinite(t) & (np.abs(s) > 0) & (np.abs(t) > 0)
    if ok.any():
        return float(np.median(t[ok] / s[ok]))
    for b in breaks:
        if b.stress and b.tension:
            return b.tension / b.stress
    if material is not None and material.area:
        return material.area
    if material is not None and material.radius:
        return float(np.pi * material.radius ** 2)
    return None


def resolve(data, presets: Optional[Dict[str, dict]] = None,
            assignments: Optional[Dict[str, str]] = None) -> Dict[str, YarnStrength]:
    """Yarn name -> :class:`YarnStrength` for every yarn of ``data`` (BagData)."""
    presets, assignments = presets or {}, assignments or {}
    strangers = sorted(set(assignments) - set(data.yarns))
    if strangers:
        raise KeyError("no yarn named %s in the bag (have: %s)"
                       % (", ".join(strangers), ", ".join(data.yarns)))
    unknown = sorted(set(assignments.values()) - set(presets))
    if unknown:
        raise KeyError("unknown material preset(s): %s (have: %s)"
                       % (", ".join(unknown), ", ".join(sorted(presets)) or "none"))
    meta = data.metadata or {}
    out = {}
    for name, series in data.yarns.items():
        material, source = None, ""
        if name in assignments:
            material = Material.from_dict(presets[assignments[name]])
            source = "preset " + assignments[name]
        elif isinstance(meta.get(name), dict):
            material, source = Material.from_dict(meta[name]), "bag metadata"
        elif isinstance(meta.get(name), str) and meta[name] in presets:
            material = Material.from_dict(presets[meta[name]])
            source = "preset " + meta[name]
        breaks = [b for b in data.breaks if b.yarn == name]
        sigma_b = material.breaking_stress if material else None
        if sigma_b is None and breaks:
            sigma_b, source = breaks[0].stress, "break event"
        out[name] = YarnStrength(material, sigma_b, source if sigma_b else "unknown",
                                 _area(series, breaks, material))
    return out
