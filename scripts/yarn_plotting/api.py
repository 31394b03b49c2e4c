"""make_all: every figure of one bag in one call."""

import os
from typing import Dict, Optional

from . import curves, filmstrip, frames, materials
from .bagdata import read_bag

FIGURES = ("filmstrip", "tension_strain", "stress_strain", "length")


def make_all(bag_path: str, out_dir: str, material_file: Optional[str] = None,
             assignments: Optional[Dict[str, str]] = None, n_frames: int = 8) -> dict:
    """Read ``bag_path`` and write the four PNG figures into ``out_dir``.

    ``assignments`` maps yarn name -> preset name in ``material_file`` (see
    :mod:`yarn_plotting.materials` for precedence).  Returns a dict with
    ``paths`` (figure name -> PNG path), ``break_times`` (x positions [s] of
    the break lines drawn in tension_strain.png), ``frame_times`` [s],
    ``time_origin`` [s] (the bag stamp plotted as t = 0), ``strengths``
    (yarn -> materials.YarnStrength), the figures' other returned info and
    ``data`` (the bagdata.BagData read).
    Raises bagdata.BagError for a missing/unreadable bag or one without
    yarn states, KeyError for an unknown preset.
    """
    data = read_bag(bag_path)
    presets = materials.load_presets(material_file) if material_file else {}
    strengths = materials.resolve(data, presets, assignments)
    os.makedirs(out_dir, exist_ok=True)
    path = {name: os.path.join(out_dir, name + ".png") for name in FIGURES}
    times = frames.choose_frames(data, n_frames)
    info = {
        "filmstrip": filmstrip.make_filmstrip(data, strengths, times, path["filmstrip"]),
        "tension_strain": curves.make_tension_strain(data, strengths, path["tension_strain"]),
        "stress_strain": curves.make_stress_strain(data, strengths, path["stress_strain"]),
        "length": curves.make_length(data, path["length"]),
    }
    return {
        "paths": path,
        "break_times": info["tension_strain"]["break_times"],
        "frame_times": info["filmstrip"]["times"],
        "time_origin": data.time_origin,
        "strengths": strengths,
        "info": info,
        "data": data,
    }
