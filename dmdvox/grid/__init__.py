"""Sparse SDF grid: layout, builder, analyses, block tree; OpenVDB and mesh export.

``vdbio`` and ``surface`` import OpenVDB and are left to explicit imports.
"""

from .analysis import Pore, Porosity, pores, porosity, volume
from .build import GridBuilder, grid_from_dense, split_blocks
from .enclosure import Voids, enclosed_voids
from .sparse import OUTSIDE, SparseGrid
from .tree import BlockTree, TreeLevel, block_tree

__all__ = [
    "OUTSIDE", "BlockTree", "GridBuilder", "Pore", "Porosity", "SparseGrid", "TreeLevel", "Voids", "block_tree",
    "enclosed_voids", "grid_from_dense", "pores", "porosity", "split_blocks", "volume",
]
