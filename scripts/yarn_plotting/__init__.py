"""Figures from a yarn_tearing bag (used by scripts/plot_bag and the tests).

Entry point: :func:`make_all`.  The submodules read the bag
(:mod:`.bagdata`), resolve material strengths (:mod:`.materials`), choose the
filmstrip frames (:mod:`.frames`) and draw the figures (:mod:`.filmstrip`,
:mod:`.curves`) with matplotlib's Agg canvas only.
"""

from .api import FIGURES, make_all
from .bagdata import BagError, read_bag

__all__ = ["FIGURES", "make_all", "BagError", "read_bag"]
