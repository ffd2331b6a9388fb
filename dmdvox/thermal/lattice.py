"""The thermal lattice: cubic cells of edge ``voxel`` that exist from their birth time on.

Cells are kept as a compact list ordered by birth (the plate's cells, born at -inf, first; ties
in linear index order, so the order is deterministic): the cells that exist at time t are always
a prefix ``0 .. n_born``, and the solver steps exactly that prefix. A cell's six neighbours are
cell ids; a face whose neighbour is ``OPEN`` (no cell there ever) or a cell not yet born is
exposed: it loses heat by convection and radiation. ``BOTTOM`` marks the plate's bottom faces
(clamped or adiabatic). Face order: -x, +x, -y, +y, -z, +z.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

OPEN = np.int32(-1)
BOTTOM = np.int32(-2)
FACES = np.array([[-1, 0, 0], [1, 0, 0], [0, -1, 0], [0, 1, 0], [0, 0, -1], [0, 0, 1]], np.int64)


@dataclass(frozen=True, eq=False)
class Lattice:
    """Cells of a regular lattice (cell (i, j, k) centred at ``origin + voxel * (i, j, k)``)."""

    voxel: float  # mm
    origin: np.ndarray  # (3,) float64 centre of cell (0, 0, 0)
    shape: tuple[int, int, int]
    ijk: np.ndarray  # (n, 3) int32, ordered by birth
    birth: np.ndarray  # (n,) float64 s; -inf: there from the start
    neighbour: np.ndarray  # (n, 6) int32 cell ids, OPEN or BOTTOM

    def __len__(self) -> int:
        return int(self.birth.shape[0])

    @property
    def nbytes(self) -> int:
        return int(self.ijk.nbytes + self.birth.nbytes + self.neighbour.nbytes)

    @property
    def centres(self) -> np.ndarray:
        """(n, 3) float64 world positions of the cell centres."""
        return self.origin + self.voxel * self.ijk.astype(np.float64)

    def index_of(self, points) -> np.ndarray:
        """The cell id holding each world point (n, 3), -1 where no cell ever exists."""
        ijk = np.rint((np.asarray(points, np.float64).reshape(-1, 3) - self.origin) / self.voxel).astype(np.int64)
        table = self.id_table()
        inside = np.all((ijk >= 0) & (ijk < np.asarray(self.shape)), axis=1)
        out = np.full(ijk.shape[0], -1, np.int64)
        out[inside] = table[tuple(ijk[inside].T)]
        return out

    def id_table(self) -> np.ndarray:
        """Dense (nx, ny, nz) int32 table of cell ids (-1: none)."""
        table = np.full(self.shape, -1, np.int32)
        table[tuple(self.ijk.T)] = np.arange(len(self), dtype=np.int32)
        return table


def bytes_per_cell() -> int:
    """What the lattice and the solver's state hold per cell (the memory guard's figure): ijk
    12, birth 8, neighbours 24, H, T, k 24, per-cell results 36 (peak, time above, cooling rate,
    gradient, solidification time, remelts, state)."""
    return 12 + 8 + 24 + 24 + 36


def lattice_from_birth(birth: np.ndarray, origin, voxel: float, plate_bottom: bool = True) -> Lattice:
    """The lattice of a dense (nx, ny, nz) array of birth times (+inf: never a cell, -inf:
    there from the start). With ``plate_bottom`` the -z faces of the cells in the lowest layer
    (k = 0) are the plate's bottom."""
    birth = np.asarray(birth, np.float64)
    shape = tuple(int(n) for n in birth.shape)
    flat = birth.reshape(-1)
    exists = np.flatnonzero(flat < np.inf)
    order = exists[np.lexsort((exists, flat[exists]))]
    ijk = np.stack(np.unravel_index(order, shape), axis=1).astype(np.int32)
    table = np.full(shape, -1, np.int32)
    table[tuple(ijk.T)] = np.arange(order.size, dtype=np.int32)
    neighbour = np.empty((order.size, 6), np.int32)
    dims = np.asarray(shape, np.int64)
    for f, step in enumerate(FACES):
        other = ijk.astype(np.int64) + step
        inside = np.all((other >= 0) & (other < dims), axis=1)
        ids = np.full(order.size, OPEN, np.int32)
        ids[inside] = table[tuple(other[inside].T)]
        if plate_bottom and f == 4:
            ids[ijk[:, 2] == 0] = BOTTOM
        neighbour[:, f] = ids
    return Lattice(voxel=float(voxel), origin=np.asarray(origin, np.float64).reshape(3).copy(), shape=shape, ijk=ijk,
                   birth=flat[order].copy(), neighbour=neighbour)


__all__ = ["Lattice", "lattice_from_birth", "bytes_per_cell", "OPEN", "BOTTOM", "FACES"]
