"""The thermal lattice: cubic cells of edge ``voxel`` that exist from their birth time on.

Cells are kept as a compact list ordered by birth (the plate's cells, born at -inf, first; ties
in linear index order, so the order is deterministic): the cells that exist at time t are always
a prefix ``0 .. n_born``, and the solver steps exactly that prefix. A cell's six neighbours are
cell ids; a face whose neighbour is ``OPEN`` (no cell there ever) or a cell not yet born is
exposed: it loses heat by convection and radiation. ``BOTTOM`` marks the plate's bottom faces
(clamped or adiabatic). Face order: -x, +x, -y, +y, -z, +z.

A layer of the lattice may be coarse in z (``layers``): a cell of layer k then spans the fine
layers k .. k + dz - 1 (its index is k, the others hold no cell of their own), its z neighbours
are the cells at k + dz and at the layer ending at k; its x and y neighbours share its height.
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
    dz: np.ndarray = None  # (n,) float64 height in voxels (1 but in a coarse plate layer)

    def __post_init__(self) -> None:
        if self.dz is None:
            object.__setattr__(self, "dz", np.ones(len(self), np.float64))

    def __len__(self) -> int:
        return int(self.birth.shape[0])

    @property
    def nbytes(self) -> int:
        return int(self.ijk.nbytes + self.birth.nbytes + self.neighbour.nbytes)

    @property
    def centres(self) -> np.ndarray:
        """(n, 3) float64 world positions of the cell centres."""
        c = self.origin + self.voxel * self.ijk.astype(np.float64)
        c[:, 2] += 0.5 * self.voxel * (self.dz - 1.0)
        return c

    def index_of(self, points) -> np.ndarray:
        """The cell id holding each world point (n, 3), -1 where no cell ever exists."""
        ijk = np.rint((np.asarray(points, np.float64).reshape(-1, 3) - self.origin) / self.voxel).astype(np.int64)
        table = self.id_table()
        inside = np.all((ijk >= 0) & (ijk < np.asarray(self.shape)), axis=1)
        out = np.full(ijk.shape[0], -1, np.int64)
        out[inside] = table[tuple(ijk[inside].T)]
        return out

    def id_table(self) -> np.ndarray:
        """Dense (nx, ny, nz) int32 table of cell ids (-1: none); a coarse cell at every fine
        layer it spans."""
        table = np.full(self.shape, -1, np.int32)
        ids = np.arange(len(self), dtype=np.int32)
        for extra in range(int(self.dz.max()) if len(self) else 1):
            on = self.dz > extra
            at = self.ijk[on].astype(np.int64)
            at[:, 2] += extra
            table[tuple(at.T)] = ids[on]
        return table


def bytes_per_cell() -> int:
    """What the lattice and the solver's state hold per cell (the memory guard's figure): ijk
    12, birth 8, neighbours 24, H, T, k 24, per-cell results 36 (peak, time above, cooling rate,
    gradient, solidification time, remelts, state), height 8."""
    return 12 + 8 + 24 + 24 + 36 + 8


def lattice_from_birth(birth: np.ndarray, origin, voxel: float, plate_bottom: bool = True,
                       layers: np.ndarray | None = None) -> Lattice:
    """The lattice of a dense (nx, ny, nz) array of birth times (+inf: never a cell, -inf:
    there from the start). With ``plate_bottom`` the -z faces of the cells in the lowest layer
    (k = 0) are the plate's bottom. ``layers``: the height in voxels of the cells of each layer
    (nz,), the layers a coarse one covers above it 0 (their births ignored); None: all 1."""
    birth = np.asarray(birth, np.float64)
    shape = tuple(int(n) for n in birth.shape)
    if layers is None:
        layers = np.ones(shape[2], np.int64)
    layers = np.asarray(layers, np.int64)
    # the layer each fine layer's cells belong to: k itself, or the coarse layer below covering it
    owner = np.repeat(np.flatnonzero(layers > 0), layers[layers > 0])
    if owner.size != shape[2] or np.any(owner > np.arange(shape[2])):
        raise ValueError(f"layers {layers.tolist()} do not tile the {shape[2]} layers")
    birth = np.where((layers > 0)[None, None, :], birth, np.inf)
    flat = birth.reshape(-1)
    exists = np.flatnonzero(flat < np.inf)
    order = exists[np.lexsort((exists, flat[exists]))]
    ijk = np.stack(np.unravel_index(order, shape), axis=1).astype(np.int32)
    table = np.full(shape, -1, np.int32)
    table[tuple(ijk.T)] = np.arange(order.size, dtype=np.int32)
    neighbour = np.empty((order.size, 6), np.int32)
    dims = np.asarray(shape, np.int64)
    height = layers[ijk[:, 2]]
    for f, step in enumerate(FACES):
        other = ijk.astype(np.int64) + step
        if f == 5:  # the cell above starts where this one ends
            other[:, 2] = ijk[:, 2] + height
        elif f == 4:  # the cell below: the owner of the layer under this one's bottom
            below = ijk[:, 2].astype(np.int64) - 1
            other[:, 2] = np.where(below >= 0, owner[np.maximum(below, 0)], -1)
        inside = np.all((other >= 0) & (other < dims), axis=1)
        ids = np.full(order.size, OPEN, np.int32)
        ids[inside] = table[tuple(other[inside].T)]
        if plate_bottom and f == 4:
            ids[ijk[:, 2] == 0] = BOTTOM
        neighbour[:, f] = ids
    return Lattice(voxel=float(voxel), origin=np.asarray(origin, np.float64).reshape(3).copy(), shape=shape, ijk=ijk,
                   birth=birth.reshape(-1)[order].copy(), neighbour=neighbour, dz=height.astype(np.float64))


__all__ = ["Lattice", "lattice_from_birth", "bytes_per_cell", "OPEN", "BOTTOM", "FACES"]
