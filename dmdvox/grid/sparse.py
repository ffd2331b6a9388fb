"""The sparse signed-distance grid every later stage reads: :class:`SparseGrid`.

Index space and transform
    Voxel (i, j, k) has its centre at ``origin + voxel * (i, j, k)`` (OpenVDB's convention:
    voxel centres on integer index coordinates, a linear transform with voxel size ``voxel``
    and translation ``origin``). Blocks are 8^3 voxels; block (bi, bj, bk) covers voxels
    ``8*bi .. 8*bi + 7`` and so on. Block coordinates are never negative: the caller picks the
    origin so that the domain starts at block 0, which lets the block table be a dense array.

Layout
    ``block`` is a dense (nbx, nby, nbz) int32 table: ``>= 0`` a leaf id, ``OUTSIDE`` (-1) an
    outside tile (also every block never touched), ``<= -2`` an inside tile whose tile id is
    ``-2 - value``. A dense table costs 4 B per block (1/128 B per voxel) and makes every
    lookup one array read, which hash maps or OpenVDB's 3-level tree cannot match in numba.

    Leaves store two 512-bit masks (``leaf_active``: |sdf| < band; ``leaf_inside``: sign) and
    pack the values instead of keeping dense 8^3 arrays: ``sdf`` holds only the active voxels
    and ``arrival`` only the active inside voxels (``leaf_active & leaf_inside``), leaf after
    leaf in local order ``v = lx*64 + ly*8 + lz`` (the C order of an (8, 8, 8) block), located
    by the ``sdf_offset`` / ``arr_offset`` prefix sums and by popcount ranks inside a leaf.
    Inactive voxels need no sdf value: they are exactly +band or -band by the inside mask.

    The inactive inside voxels of a leaf (deeper than the band) keep no arrival of their own:
    they read ``leaf_octant_arrival`` (n_leaf, 2, 2, 2), the minimum arrival over the inside
    voxels (active or not) of each 4^3-voxel octant of the leaf, exactly like inside tiles
    below. Beyond the band the arrival time only serves collision checks and replay, which work
    on coarse boxes and already get the octant resolution from the tiles around; the surface
    (and everything meshed or compared) lies in the band, where arrival stays per voxel.

    Memory: a narrow-band leaf is only ~35-45 % active, so dense float32 sdf + arrival leaves
    would cost ~18-22 B per active voxel, and packing arrival for every inside voxel of a leaf
    still cost 9.7 B on a sphere (leaves hold ~1.16 inside voxels per active one at band = 3
    voxels). Packed by active & inside, per active voxel: sdf 4 B, arrival ~1.9-2.0 B (about
    half the active voxels are inside), leaf masks, coordinates, offsets and octants (188 B a
    leaf) ~1.0 B, block table and inside tiles 0.2-0.6 B. Measured at 0.1 mm, band 3 voxels:
    sphere R 5 mm 7.15 B, spherical shell R 20 / 12 mm 7.58 B (6.7 / 7.1 B at 5 voxels);
    OpenVDB alone costs 12-15 B for the sdf.

    Inside tiles (blocks wholly inside, deeper than the band) keep no voxels, only
    ``tile_arrival`` (2, 2, 2): the minimum arrival time over each 4^3-voxel octant. Deep in the
    part only collision queries need arrival times, and they work on coarse boxes; the octant
    minimum is conservative for "was material there by time t" (it never reports material
    later than it arrived) at 32 B per 512 voxels.

All values are float32 (explicit), stored SDF values are clamped to [-band, band], and
``band`` is kept float32-representable so that comparisons against it agree everywhere
(numba kernels, OpenVDB's float32 background).
"""

from __future__ import annotations

from collections import namedtuple
from dataclasses import dataclass, field, replace
from functools import cached_property

import numba as nb
import numpy as np

BLOCK = 8
BLOCK_VOXELS = 512
OUTSIDE = np.int32(-1)

_U1 = np.uint64(1)
_U63 = np.uint64(63)
_M1 = np.uint64(0x5555555555555555)
_M2 = np.uint64(0x3333333333333333)
_M4 = np.uint64(0x0F0F0F0F0F0F0F0F)
_H01 = np.uint64(0x0101010101010101)
_S1 = np.uint64(1)
_S2 = np.uint64(2)
_S4 = np.uint64(4)
_S56 = np.uint64(56)


@nb.njit(cache=True, inline="always")
def popcount64(x):
    """Number of set bits of a uint64 (numba has no popcount intrinsic for uint64)."""
    x = x - ((x >> _S1) & _M1)
    x = (x & _M2) + ((x >> _S2) & _M2)
    x = (x + (x >> _S4)) & _M4
    return np.int64((x * _H01) >> _S56)


@nb.njit(cache=True, inline="always")
def bit_is_set(mask, v):
    """Bit ``v`` (0..511) of a leaf's (8,) uint64 mask."""
    return ((mask[v >> 6] >> np.uint64(v & 63)) & _U1) != 0


@nb.njit(cache=True, inline="always")
def bit_rank(mask, v):
    """Number of set bits of the (8,) uint64 mask strictly before bit ``v``."""
    w = v >> 6
    r = np.int64(0)
    for i in range(w):
        r += popcount64(mask[i])
    b = np.uint64(v & 63)
    if b != 0:
        r += popcount64(mask[w] & ((_U1 << b) - _U1))
    return r


@nb.njit(cache=True, inline="always")
def bit_rank_and(mask_a, mask_b, v):
    """Number of bits set in both (8,) uint64 masks strictly before bit ``v``."""
    w = v >> 6
    r = np.int64(0)
    for i in range(w):
        r += popcount64(mask_a[i] & mask_b[i])
    b = np.uint64(v & 63)
    if b != 0:
        r += popcount64(mask_a[w] & mask_b[w] & ((_U1 << b) - _U1))
    return r


@nb.njit(cache=True)
def decode_leaf_into(leaf, leaf_active, leaf_inside, sdf_offset, sdf, arr_offset, arrival, leaf_octant_arrival, band,
                     out_sdf, out_arr):
    """Expand leaf ``leaf`` into flat (512,) views ``out_sdf`` / ``out_arr`` (v order).

    Inactive voxels become +band or -band by the inside mask; arrival is per voxel for active
    inside voxels, the octant minimum for inactive inside ones and +inf outside.
    """
    ks = sdf_offset[leaf]
    ka = arr_offset[leaf]
    act = leaf_active[leaf]
    ins = leaf_inside[leaf]
    octs = leaf_octant_arrival[leaf]
    nband = -band
    for v in range(BLOCK_VOXELS):
        inside = bit_is_set(ins, v)
        if bit_is_set(act, v):
            out_sdf[v] = sdf[ks]
            ks += 1
            if inside:
                out_arr[v] = arrival[ka]
                ka += 1
            else:
                out_arr[v] = np.inf
        elif inside:
            out_sdf[v] = nband
            out_arr[v] = octs[v >> 8, (v >> 5) & 1, (v >> 2) & 1]
        else:
            out_sdf[v] = band
            out_arr[v] = np.inf


# The grid as kernels take it: one named structure (numba passes it as a tuple of arrays).
GridView = namedtuple("GridView", ["block", "leaf_active", "leaf_inside", "sdf_offset", "sdf", "arr_offset", "arrival",
                                   "leaf_octant_arrival", "tile_arrival", "band"])


@nb.njit(cache=True)
def decode_sdf_into(g, leaf, out):
    """SDF of leaf ``leaf`` into a flat (512,) view ``out`` (v order): inactive voxels +-band."""
    ks = g.sdf_offset[leaf]
    act = g.leaf_active[leaf]
    ins = g.leaf_inside[leaf]
    for v in range(BLOCK_VOXELS):
        if bit_is_set(act, v):
            out[v] = g.sdf[ks]
            ks += 1
        elif bit_is_set(ins, v):
            out[v] = -g.band
        else:
            out[v] = g.band


@nb.njit(cache=True)
def block_sdf_into(g, bx, by, bz, out):
    """SDF of block (bx, by, bz) into (512,) ``out``: a leaf decoded, a tile or the outside
    constant (blocks beyond the table are outside)."""
    nx, ny, nz = g.block.shape
    val = -1
    if 0 <= bx < nx and 0 <= by < ny and 0 <= bz < nz:
        val = g.block[bx, by, bz]
    if val >= 0:
        decode_sdf_into(g, val, out)
    else:
        out[:] = g.band if val == OUTSIDE else -g.band


@nb.njit(cache=True)
def sdf_at(g, i, j, k):
    """SDF at integer index (i, j, k); +band beyond the table."""
    bi, bj, bk = i >> 3, j >> 3, k >> 3
    if i < 0 or j < 0 or k < 0 or bi >= g.block.shape[0] or bj >= g.block.shape[1] or bk >= g.block.shape[2]:
        return g.band
    val = g.block[bi, bj, bk]
    if val >= 0:
        return leaf_value(val, (i & 7) * 64 + (j & 7) * 8 + (k & 7), g.leaf_active, g.leaf_inside, g.sdf_offset,
                          g.sdf, g.band)
    return g.band if val == OUTSIDE else -g.band


@nb.njit(cache=True, parallel=True)
def trilinear_sdf(g, index_points):
    """SDF trilinearly interpolated at continuous index coordinates (n, 3)."""
    n = index_points.shape[0]
    out = np.empty(n)
    for p in nb.prange(n):
        x, y, z = index_points[p, 0], index_points[p, 1], index_points[p, 2]
        i, j, k = np.int64(np.floor(x)), np.int64(np.floor(y)), np.int64(np.floor(z))
        tx, ty, tz = x - i, y - j, z - k
        value = 0.0
        for di in range(2):
            wx = tx if di else 1.0 - tx
            for dj in range(2):
                wy = ty if dj else 1.0 - ty
                for dk in range(2):
                    wz = tz if dk else 1.0 - tz
                    value += wx * wy * wz * sdf_at(g, i + di, j + dj, k + dk)
        out[p] = value
    return out


@nb.njit(cache=True)
def leaf_value(leaf, v, leaf_active, leaf_inside, sdf_offset, sdf, band):
    """SDF of local voxel ``v`` of leaf ``leaf`` (rank lookup, no decoding)."""
    act = leaf_active[leaf]
    if bit_is_set(act, v):
        return sdf[sdf_offset[leaf] + bit_rank(act, v)]
    if bit_is_set(leaf_inside[leaf], v):
        return -band
    return band


@nb.njit(cache=True)
def leaf_arrival(leaf, v, leaf_active, leaf_inside, arr_offset, arrival, leaf_octant_arrival):
    """Arrival time of local voxel ``v`` of leaf ``leaf``: per voxel if active, else the octant's (+inf outside)."""
    ins = leaf_inside[leaf]
    if not bit_is_set(ins, v):
        return np.float32(np.inf)
    act = leaf_active[leaf]
    if bit_is_set(act, v):
        return arrival[arr_offset[leaf] + bit_rank_and(act, ins, v)]
    return leaf_octant_arrival[leaf, v >> 8, (v >> 5) & 1, (v >> 2) & 1]


@nb.njit(cache=True)
def block_values_into(val, leaf_active, leaf_inside, sdf_offset, sdf, arr_offset, arrival, leaf_octant_arrival,
                      tile_arrival, band, want_sdf, dst):
    """The sdf (``want_sdf``) or arrival of the block whose table value is ``val`` into an
    (8, 8, 8) view ``dst``: a leaf decoded, an inside tile's -band or octant arrival, outside
    +band or +inf."""
    if val >= 0:
        s8 = np.empty(BLOCK_VOXELS, np.float32)
        a8 = np.empty(BLOCK_VOXELS, np.float32)
        decode_leaf_into(val, leaf_active, leaf_inside, sdf_offset, sdf, arr_offset, arrival, leaf_octant_arrival,
                         band, s8, a8)
        src = s8 if want_sdf else a8
        for v in range(BLOCK_VOXELS):
            dst[v >> 6, (v >> 3) & 7, v & 7] = src[v]
    elif val == OUTSIDE:
        dst[:] = band if want_sdf else np.float32(np.inf)
    elif want_sdf:
        dst[:] = -band
    else:
        t = -2 - val
        for lx in range(BLOCK):
            for ly in range(BLOCK):
                for lz in range(BLOCK):
                    dst[lx, ly, lz] = tile_arrival[t, lx >> 2, ly >> 2, lz >> 2]


@nb.njit(cache=True, parallel=True)
def _dense_box(block, lo, hi, leaf_active, leaf_inside, sdf_offset, sdf, arr_offset, arrival, leaf_octant_arrival,
               tile_arrival, band, want_sdf):
    """Dense sdf (``want_sdf``) or arrival over blocks lo..hi-1, one block per iteration."""
    nx, ny, nz = hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]
    out = np.empty((nx * BLOCK, ny * BLOCK, nz * BLOCK), np.float32)
    for n in nb.prange(nx * ny * nz):
        bx = n // (ny * nz)
        by = (n // nz) % ny
        bz = n % nz
        gx, gy, gz = bx + lo[0], by + lo[1], bz + lo[2]
        inside_table = 0 <= gx < block.shape[0] and 0 <= gy < block.shape[1] and 0 <= gz < block.shape[2]
        val = block[gx, gy, gz] if inside_table else OUTSIDE
        block_values_into(val, leaf_active, leaf_inside, sdf_offset, sdf, arr_offset, arrival, leaf_octant_arrival,
                          tile_arrival, band, want_sdf,
                          out[bx * BLOCK:(bx + 1) * BLOCK, by * BLOCK:(by + 1) * BLOCK, bz * BLOCK:(bz + 1) * BLOCK])
    return out


@nb.njit(cache=True, inline="always")
def value_at(g, i, j, k, want_sdf):
    """The SDF (``want_sdf``) or the arrival time (float32) of voxel (i, j, k) of the grid ``g``
    (:data:`GridView`); beyond the table +band or +inf."""
    bi, bj, bk = i >> 3, j >> 3, k >> 3
    block = g.block
    if i < 0 or j < 0 or k < 0 or bi >= block.shape[0] or bj >= block.shape[1] or bk >= block.shape[2]:
        return g.band if want_sdf else np.float32(np.inf)
    val = block[bi, bj, bk]
    lx, ly, lz = i & 7, j & 7, k & 7
    if val >= 0:
        v = lx * 64 + ly * 8 + lz
        if want_sdf:
            return leaf_value(val, v, g.leaf_active, g.leaf_inside, g.sdf_offset, g.sdf, g.band)
        return leaf_arrival(val, v, g.leaf_active, g.leaf_inside, g.arr_offset, g.arrival, g.leaf_octant_arrival)
    if val == OUTSIDE:
        return g.band if want_sdf else np.float32(np.inf)
    if want_sdf:
        return -g.band
    return g.tile_arrival[-2 - val, lx >> 2, ly >> 2, lz >> 2]


@nb.njit(cache=True, parallel=True)
def _lookup(g, ijk, want_sdf):
    out = np.empty(ijk.shape[0], np.float32)
    for p in nb.prange(ijk.shape[0]):
        out[p] = value_at(g, ijk[p, 0], ijk[p, 1], ijk[p, 2], want_sdf)
    return out


def _packed_subset(offset: np.ndarray, values: np.ndarray, leaves: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """The packed values of ``leaves`` (ascending) and their new prefix offsets."""
    counts = offset[leaves + 1] - offset[leaves]
    new_offset = np.zeros(leaves.size + 1, np.int64)
    np.cumsum(counts, out=new_offset[1:])
    starts = np.repeat(offset[leaves] - new_offset[:-1], counts)
    return new_offset, values[starts + np.arange(new_offset[-1])]


@dataclass(frozen=True, eq=False)
class SparseGrid:
    """A narrow-band SDF plus arrival times (per voxel in the band) in 8^3 blocks (see module docstring)."""

    voxel: float
    origin: np.ndarray  # (3,) float64 world position of voxel (0, 0, 0)'s centre
    band: float  # narrow-band half width, mm; float32-representable
    block: np.ndarray  # (nbx, nby, nbz) int32
    leaf_coord: np.ndarray  # (n_leaf, 3) int32
    leaf_active: np.ndarray  # (n_leaf, 8) uint64
    leaf_inside: np.ndarray  # (n_leaf, 8) uint64
    sdf_offset: np.ndarray  # (n_leaf + 1,) int64
    sdf: np.ndarray  # (n_active,) float32
    arr_offset: np.ndarray  # (n_leaf + 1,) int64, into arrival
    arrival: np.ndarray  # (n_active_inside,) float32 seconds, packed by leaf_active & leaf_inside
    leaf_octant_arrival: np.ndarray  # (n_leaf, 2, 2, 2) float32 octant minima over each leaf's inside voxels
    tile_arrival: np.ndarray  # (n_tile, 2, 2, 2) float32 octant minima
    meta: dict = field(default_factory=dict, compare=False)

    def __post_init__(self) -> None:
        expect = {
            "block": (np.int32, 3),
            "leaf_coord": (np.int32, 2),
            "leaf_active": (np.uint64, 2),
            "leaf_inside": (np.uint64, 2),
            "sdf_offset": (np.int64, 1),
            "sdf": (np.float32, 1),
            "arr_offset": (np.int64, 1),
            "arrival": (np.float32, 1),
            "leaf_octant_arrival": (np.float32, 4),
            "tile_arrival": (np.float32, 4),
        }
        for name, (dtype, ndim) in expect.items():
            a = getattr(self, name)
            if a.dtype != dtype or a.ndim != ndim:
                raise ValueError(
                    f"SparseGrid.{name} must be {np.dtype(dtype).name} with {ndim} dims, got {a.dtype} {a.shape}"
                )
        n_leaf = self.leaf_coord.shape[0]
        if not (self.leaf_active.shape == self.leaf_inside.shape == (n_leaf, 8)):
            raise ValueError("SparseGrid leaf masks must be (n_leaf, 8)")
        if self.sdf_offset.shape != (n_leaf + 1,) or self.arr_offset.shape != (n_leaf + 1,):
            raise ValueError("SparseGrid offsets must be (n_leaf + 1,)")
        if self.sdf_offset[-1] != self.sdf.shape[0] or self.arr_offset[-1] != self.arrival.shape[0]:
            raise ValueError("SparseGrid offsets do not match the packed arrays")
        if self.leaf_octant_arrival.shape != (n_leaf, 2, 2, 2):
            raise ValueError("SparseGrid.leaf_octant_arrival must be (n_leaf, 2, 2, 2)")
        if self.tile_arrival.shape[1:] != (2, 2, 2) or self.tile_arrival.shape[0] != np.count_nonzero(self.block <= -2):
            raise ValueError("SparseGrid.tile_arrival must be (n_tile, 2, 2, 2), one per inside tile of the block table")
        if self.origin.shape != (3,) or self.origin.dtype != np.float64:
            raise ValueError("SparseGrid.origin must be (3,) float64")

    # -- sizes -------------------------------------------------------------------------------
    @property
    def block_shape(self) -> tuple[int, int, int]:
        return tuple(int(n) for n in self.block.shape)  # type: ignore[return-value]

    @property
    def n_leaf(self) -> int:
        return int(self.leaf_coord.shape[0])

    @property
    def n_tile(self) -> int:
        return int(self.tile_arrival.shape[0])

    @cached_property
    def tile_coord(self) -> np.ndarray:
        """(n_tile, 3) int32 block coordinates of the inside tiles, in tile order.

        Derived from the block table rather than stored: tiles are numbered in linear block
        order, and on solid parts their coordinates alone would cost 12 B per 512 voxels."""
        return np.argwhere(self.block <= -2).astype(np.int32)

    @property
    def active_voxels(self) -> int:
        return int(self.sdf.shape[0])

    @property
    def memory_bytes(self) -> int:
        arrays = (
            self.origin, self.block, self.leaf_coord, self.leaf_active, self.leaf_inside, self.sdf_offset,
            self.sdf, self.arr_offset, self.arrival, self.leaf_octant_arrival, self.tile_arrival,
        )
        return int(sum(a.nbytes for a in arrays))

    def view(self) -> GridView:
        """The grid as kernels take it (:data:`GridView`)."""
        return GridView(self.block, self.leaf_active, self.leaf_inside, self.sdf_offset, self.sdf, self.arr_offset,
                        self.arrival, self.leaf_octant_arrival, self.tile_arrival, np.float32(self.band))

    def crop_x(self, bx0: int, bx1: int) -> "SparseGrid":
        """The blocks ``bx0 <= bx < bx1`` as a grid of their own (origin moved to block ``bx0``):
        a slab to hand to a task. Leaves keep their order, tiles their values."""
        block = self.block[bx0:bx1].copy()
        keep = np.flatnonzero((self.leaf_coord[:, 0] >= bx0) & (self.leaf_coord[:, 0] < bx1))
        renumber = np.full(self.n_leaf, -1, np.int32)
        renumber[keep] = np.arange(keep.size, dtype=np.int32)
        leaves = block >= 0
        block[leaves] = renumber[block[leaves]]
        # tiles are numbered in linear block order, so a slab's tiles are one run of numbers
        tiles = block <= -2
        first_tile = int(np.count_nonzero(self.block[:bx0] <= -2))
        n_tile = int(np.count_nonzero(tiles))
        block[tiles] += first_tile
        leaf_coord = self.leaf_coord[keep].copy()
        leaf_coord[:, 0] -= bx0
        origin = self.origin.copy()
        origin[0] += BLOCK * bx0 * self.voxel
        sdf_offset, sdf = _packed_subset(self.sdf_offset, self.sdf, keep)
        arr_offset, arrival = _packed_subset(self.arr_offset, self.arrival, keep)
        return SparseGrid(self.voxel, origin, self.band, block, leaf_coord, self.leaf_active[keep],
                          self.leaf_inside[keep], sdf_offset, sdf, arr_offset, arrival,
                          self.leaf_octant_arrival[keep], self.tile_arrival[first_tile:first_tile + n_tile].copy(),
                          dict(self.meta))

    def widened(self, origin: np.ndarray, block_shape: tuple[int, int, int]) -> "SparseGrid":
        """The same grid in a larger block table on the same lattice, whose block 0 sits at
        ``origin``: the new blocks are outside tiles. Leaves and tiles keep their numbers (tiles
        count in linear block order, which a shift of every block preserves); the packed
        values are shared, not copied."""
        shift = np.rint((self.origin - np.asarray(origin, np.float64)) / (BLOCK * self.voxel)).astype(np.int64)
        if np.any(shift < 0) or np.any(shift + self.block.shape > np.asarray(block_shape)) or \
                not np.allclose(origin + shift * BLOCK * self.voxel, self.origin, rtol=0.0, atol=1e-9 * self.voxel):
            raise ValueError(f"a table of {block_shape} blocks at {origin} does not hold this grid's "
                             f"{self.block.shape} blocks at {self.origin} on whole blocks")
        block = np.full(block_shape, OUTSIDE, np.int32)
        block[shift[0]:shift[0] + self.block.shape[0], shift[1]:shift[1] + self.block.shape[1],
              shift[2]:shift[2] + self.block.shape[2]] = self.block
        return replace(self, origin=np.asarray(origin, np.float64).copy(), block=block,
                       leaf_coord=self.leaf_coord + shift.astype(np.int32), meta=dict(self.meta))

    def trilinear(self, world_points: np.ndarray) -> np.ndarray:
        """SDF (float64) trilinearly interpolated at world points (n, 3); +band beyond the table."""
        index = np.ascontiguousarray(self.world_to_index(np.asarray(world_points, np.float64).reshape(-1, 3)))
        return trilinear_sdf(self.view(), index)

    # -- transform ---------------------------------------------------------------------------
    def world_to_index(self, xyz: np.ndarray) -> np.ndarray:
        """Continuous index coordinates (float64) of world points; round for the nearest voxel."""
        return (np.asarray(xyz, np.float64) - self.origin) / self.voxel

    def index_to_world(self, ijk: np.ndarray) -> np.ndarray:
        """World position (float64, mm) of index coordinates (voxel centres for integers)."""
        return self.origin + np.asarray(ijk, np.float64) * self.voxel

    # -- decoding ----------------------------------------------------------------------------
    def _packed(self):
        return (self.leaf_active, self.leaf_inside, self.sdf_offset, self.sdf, self.arr_offset, self.arrival,
                self.leaf_octant_arrival)

    def decode_leaf(self, leaf: int) -> tuple[np.ndarray, np.ndarray]:
        """Dense (8, 8, 8) float32 sdf and arrival of one leaf (octant minima on inactive inside voxels)."""
        s8 = np.empty(BLOCK_VOXELS, np.float32)
        a8 = np.empty(BLOCK_VOXELS, np.float32)
        decode_leaf_into(np.int64(leaf), *self._packed(), np.float32(self.band), s8, a8)
        return s8.reshape(BLOCK, BLOCK, BLOCK), a8.reshape(BLOCK, BLOCK, BLOCK)

    def _box(self, lo_block, hi_block, want_sdf: bool) -> np.ndarray:
        lo = np.zeros(3, np.int64) if lo_block is None else np.asarray(lo_block, np.int64).reshape(3)
        hi = np.asarray(self.block.shape, np.int64) if hi_block is None else np.asarray(hi_block, np.int64).reshape(3)
        if np.any(hi < lo):
            raise ValueError(f"empty block box {lo.tolist()}..{hi.tolist()}")
        return _dense_box(self.block, lo, hi, *self._packed(), self.tile_arrival, np.float32(self.band), want_sdf)

    def dense_sdf(self, lo_block=None, hi_block=None) -> np.ndarray:
        """Dense float32 SDF of blocks ``lo_block <= b < hi_block`` (default: the whole table).

        The result's voxel (0, 0, 0) is index ``8 * lo_block``; blocks outside the table read
        as outside (+band), inside tiles as -band.
        """
        return self._box(lo_block, hi_block, True)

    def dense_arrival(self, lo_block=None, hi_block=None) -> np.ndarray:
        """Dense float32 arrival times like :meth:`dense_sdf`: +inf outside, per voxel on active inside
        voxels, octant minima on inactive inside voxels of leaves and in tiles."""
        return self._box(lo_block, hi_block, False)

    def value_at_index(self, ijk: np.ndarray) -> np.ndarray:
        """SDF (float32) at integer index coordinates (n, 3); +band outside the table."""
        ijk = np.ascontiguousarray(np.asarray(ijk, np.int64).reshape(-1, 3))
        return _lookup(self.view(), ijk, True)

    def arrival_at_index(self, ijk: np.ndarray) -> np.ndarray:
        """Arrival time (float32 s) at integer index coordinates (n, 3), as :meth:`dense_arrival`; +inf outside."""
        ijk = np.ascontiguousarray(np.asarray(ijk, np.int64).reshape(-1, 3))
        return _lookup(self.view(), ijk, False)
