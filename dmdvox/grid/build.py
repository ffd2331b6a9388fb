"""Assemble a :class:`SparseGrid` from batches of dense 8^3 blocks, or of blocks already packed.

:func:`pack_blocks` classifies dense blocks in parallel (numba, one block per iteration) and keeps
only their compact form, a :class:`PackedBlocks`; :class:`GridBuilder` collects packed batches,
so peak memory is the compact grid so far plus one dense batch:

- every voxel inside and at or below -band: an inside tile, kept as 8 octant arrival minima;
- every voxel outside and at or above +band: dropped (the block stays ``OUTSIDE``);
- otherwise a leaf: values clamped to [-band, band], active/inside masks, the active sdf and
  the active inside arrival values packed in local voxel order, and the leaf's 8 octant
  arrival minima over all its inside voxels (what its inactive inside voxels read).

Callers pass dense per-voxel arrival for every voxel; the packing reduces it to that layout. A
producer that already knows a block is an inside tile (the deposit engine) adds it as a tile
with its octant minima, never as a dense block.

Inside means ``sdf < 0``: the caller delivers sign-correct values (it resolves touching beads,
where a ``min`` union gives 0 inside the part). Packing positions come from prefix sums over
per-block counts, so the output is independent of the thread count. :meth:`GridBuilder.finish`
orders leaves and tiles by linear block index, whatever order the batches came in.
"""

from __future__ import annotations

from dataclasses import dataclass, replace

import numba as nb
import numpy as np

from .sparse import BLOCK, BLOCK_VOXELS, OUTSIDE, SparseGrid, popcount64

_KIND_OUTSIDE = 0
_KIND_LEAF = 1
_KIND_TILE = 2


@nb.njit(cache=True, parallel=True)
def _classify(sdf, band):
    """Kind, masks and counts (active; active and inside) per dense block; also the number of
    non-finite sdf values."""
    m = sdf.shape[0]
    kind = np.empty(m, np.int8)
    active = np.zeros((m, 8), np.uint64)
    inside = np.zeros((m, 8), np.uint64)
    n_act = np.zeros(m, np.int64)
    n_arr = np.zeros(m, np.int64)
    bad = np.zeros(m, np.int64)
    nband = -band
    for b in nb.prange(m):
        s = sdf[b].reshape(BLOCK_VOXELS)
        all_deep_in = True
        all_far_out = True
        for v in range(BLOCK_VOXELS):
            x = s[v]
            if not np.isfinite(x):
                bad[b] += 1
            w = v >> 6
            bit = np.uint64(1) << np.uint64(v & 63)
            if x < 0:
                inside[b, w] |= bit
                if x > nband:
                    all_deep_in = False
                all_far_out = False
            else:
                if x < band:
                    all_far_out = False
                all_deep_in = False
            if nband < x < band:
                active[b, w] |= bit
        if all_deep_in:
            kind[b] = _KIND_TILE
        elif all_far_out:
            kind[b] = _KIND_OUTSIDE
        else:
            kind[b] = _KIND_LEAF
            ca = 0
            cai = 0
            for w in range(8):
                ca += popcount64(active[b, w])
                cai += popcount64(active[b, w] & inside[b, w])
            n_act[b] = ca
            n_arr[b] = cai
    return kind, active, inside, n_act, n_arr, bad.sum()


@nb.njit(cache=True, parallel=True)
def _box_block_kinds(sdf, scale, band):
    """:func:`_classify`'s kind of each block of a dense box of ``sdf * scale``, read in place,
    and the number of non-finite values."""
    nbx, nby, nbz = sdf.shape[0] // BLOCK, sdf.shape[1] // BLOCK, sdf.shape[2] // BLOCK
    kind = np.empty((nbx, nby, nbz), np.int8)
    bad = np.zeros(nbx, np.int64)
    nband = -band
    for bx in nb.prange(nbx):
        for by in range(nby):
            for bz in range(nbz):
                all_deep_in = True
                all_far_out = True
                for i in range(BLOCK * bx, BLOCK * bx + BLOCK):
                    for j in range(BLOCK * by, BLOCK * by + BLOCK):
                        for k in range(BLOCK * bz, BLOCK * bz + BLOCK):
                            x = sdf[i, j, k] * scale
                            if not np.isfinite(x):
                                bad[bx] += 1
                            if x < 0:
                                all_far_out = False
                                if x > nband:
                                    all_deep_in = False
                            else:
                                all_deep_in = False
                                if x < band:
                                    all_far_out = False
                kind[bx, by, bz] = _KIND_TILE if all_deep_in else _KIND_OUTSIDE if all_far_out else _KIND_LEAF
    return kind, bad.sum()


@nb.njit(cache=True, parallel=True)
def _gather_blocks(sdf, scale, coords, out):
    """Blocks ``coords`` (local block coordinates) of a dense box of ``sdf * scale``."""
    for n in nb.prange(coords.shape[0]):
        i0, j0, k0 = BLOCK * coords[n, 0], BLOCK * coords[n, 1], BLOCK * coords[n, 2]
        for i in range(BLOCK):
            for j in range(BLOCK):
                for k in range(BLOCK):
                    out[n, i, j, k] = sdf[i0 + i, j0 + j, k0 + k] * scale


@nb.njit(cache=True, parallel=True)
def _pack(sdf, arrival, leaf_blocks, active, inside, sdf_off, arr_off, band):
    """Packed active sdf and active inside arrival of the leaf blocks, at precomputed offsets,
    and per leaf the octant minima of the arrival over its inside voxels (+inf if none)."""
    out_sdf = np.empty(sdf_off[-1], np.float32)
    out_arr = np.empty(arr_off[-1], np.float32)
    out_oct = np.empty((leaf_blocks.shape[0], 2, 2, 2), np.float32)
    for n in nb.prange(leaf_blocks.shape[0]):
        b = leaf_blocks[n]
        s = sdf[b].reshape(BLOCK_VOXELS)
        a = arrival[b].reshape(BLOCK_VOXELS)
        octs = out_oct[n]
        octs[:] = np.inf
        ks = sdf_off[n]
        ka = arr_off[n]
        for v in range(BLOCK_VOXELS):
            w = v >> 6
            bit = np.uint64(1) << np.uint64(v & 63)
            is_act = (active[b, w] & bit) != 0
            if is_act:
                out_sdf[ks] = min(max(s[v], -band), band)
                ks += 1
            if inside[b, w] & bit:
                if is_act:
                    out_arr[ka] = a[v]
                    ka += 1
                ox, oy, oz = v >> 8, (v >> 5) & 1, (v >> 2) & 1
                octs[ox, oy, oz] = min(octs[ox, oy, oz], a[v])
    return out_sdf, out_arr, out_oct


@nb.njit(cache=True, parallel=True)
def octant_min(arrival, tile_blocks):
    """Minimum arrival over each 4^3-voxel octant of the dense blocks ``tile_blocks``."""
    out = np.empty((tile_blocks.shape[0], 2, 2, 2), np.float32)
    for n in nb.prange(tile_blocks.shape[0]):
        a = arrival[tile_blocks[n]]
        for ox in range(2):
            for oy in range(2):
                for oz in range(2):
                    out[n, ox, oy, oz] = a[4 * ox:4 * ox + 4, 4 * oy:4 * oy + 4, 4 * oz:4 * oz + 4].min()
    return out


@nb.njit(cache=True, parallel=True)
def _scatter_runs(values, off, dest_off, out):
    """Copy run n of ``values`` (``off[n]:off[n + 1]``) to ``out`` from ``dest_off[n]`` on."""
    for n in nb.prange(off.shape[0] - 1):
        src = off[n]
        dst = dest_off[n]
        for q in range(off[n + 1] - src):
            out[dst + q] = values[src + q]


def _offsets(counts: np.ndarray) -> np.ndarray:
    off = np.zeros(counts.shape[0] + 1, np.int64)
    np.cumsum(counts, out=off[1:])
    return off


@dataclass(frozen=True)
class PackedBlocks:
    """Blocks in the grid's compact form: leaves (masks, counts, packed values, octant minima)
    and inside tiles (octant minima). Picklable: a task returns it, the builder merges it."""

    leaf_coord: np.ndarray  # (m, 3) int32
    active: np.ndarray  # (m, 8) uint64
    inside: np.ndarray  # (m, 8) uint64
    n_act: np.ndarray  # (m,) int64 active voxels of each leaf
    n_arr: np.ndarray  # (m,) int64 active inside voxels of each leaf
    sdf: np.ndarray  # (sum n_act,) float32
    arr: np.ndarray  # (sum n_arr,) float32
    leaf_oct: np.ndarray  # (m, 2, 2, 2) float32
    tile_coord: np.ndarray  # (t, 3) int32
    tile_arr: np.ndarray  # (t, 2, 2, 2) float32


def pack_blocks(coords: np.ndarray, sdf: np.ndarray, arrival: np.ndarray, band: float) -> PackedBlocks:
    """Dense blocks (coords (m, 3), sdf and arrival (m, 8, 8, 8)) in compact form; ``band`` is
    float32-representable (see :class:`GridBuilder`). Blocks wholly outside the band are dropped."""
    coords = np.asarray(coords, np.int32).reshape(-1, 3)
    m = coords.shape[0]
    sdf = np.ascontiguousarray(sdf, np.float32)
    arrival = np.ascontiguousarray(arrival, np.float32)
    if sdf.shape != (m, 8, 8, 8) or arrival.shape != (m, 8, 8, 8):
        raise ValueError(f"expected sdf and arrival of shape ({m}, 8, 8, 8), got {sdf.shape} and {arrival.shape}")
    band32 = np.float32(band)
    kind, active, inside, n_act, n_arr, bad = _classify(sdf, band32)
    if bad:
        raise ValueError(f"{bad} non-finite sdf values in the batch")
    leaf_blocks = np.flatnonzero(kind == _KIND_LEAF)
    tile_blocks = np.flatnonzero(kind == _KIND_TILE)
    la, lf = n_act[leaf_blocks], n_arr[leaf_blocks]
    if leaf_blocks.size:
        packed_sdf, packed_arr, leaf_oct = _pack(sdf, arrival, leaf_blocks, active, inside, _offsets(la),
                                                 _offsets(lf), band32)
    else:
        packed_sdf, packed_arr = np.zeros(0, np.float32), np.zeros(0, np.float32)
        leaf_oct = np.zeros((0, 2, 2, 2), np.float32)
    return PackedBlocks(leaf_coord=coords[leaf_blocks], active=active[leaf_blocks], inside=inside[leaf_blocks],
                        n_act=la, n_arr=lf, sdf=packed_sdf, arr=packed_arr, leaf_oct=leaf_oct,
                        tile_coord=coords[tile_blocks], tile_arr=octant_min(arrival, tile_blocks))


class GridBuilder:
    """Collect blocks batch by batch, then :meth:`finish` into a :class:`SparseGrid`."""

    def __init__(self, voxel: float, origin, block_shape, band: float):
        self.voxel = float(voxel)
        self.origin = np.asarray(origin, np.float64).reshape(3).copy()
        self.block_shape = tuple(int(n) for n in block_shape)
        # OpenVDB stores the background as float32; keeping band float32-exact makes
        # "|sdf| < band" agree between numba, numpy and a round trip through a .vdb file.
        self.band = float(np.float32(band))
        if not self.voxel > 0:
            raise ValueError(f"voxel size must be > 0, got {voxel}")
        if len(self.block_shape) != 3 or min(self.block_shape) < 1:
            raise ValueError(f"block_shape must be 3 positive ints, got {block_shape}")
        if not self.band >= 3.0 * self.voxel * (1 - 1e-6):
            raise ValueError(f"band {band} mm must be at least 3 voxels ({3 * self.voxel} mm)")
        self._seen = np.zeros(self.block_shape, np.bool_)
        self._parts: list[PackedBlocks] = []

    def _claim(self, coords: np.ndarray) -> None:
        """Mark blocks as added; each block coordinate may be added at most once."""
        m = coords.shape[0]
        if m == 0:
            return
        if coords.min() < 0 or np.any(coords.max(axis=0) >= self.block_shape):
            raise ValueError(f"block coordinates outside the table {self.block_shape}")
        seen = self._seen[coords[:, 0], coords[:, 1], coords[:, 2]]
        lin = np.ravel_multi_index(coords.T, self.block_shape)
        if seen.any() or np.unique(lin).shape[0] != m:
            raise ValueError("a block coordinate was added twice")
        self._seen[coords[:, 0], coords[:, 1], coords[:, 2]] = True

    def add_blocks(self, coords: np.ndarray, sdf: np.ndarray, arrival: np.ndarray) -> None:
        """Add dense blocks: coords (m, 3) block coordinates, sdf and arrival (m, 8, 8, 8).

        ``arrival`` is per voxel (only inside voxels' values are used); the builder keeps it per
        voxel for active inside voxels and as octant minima for the other inside voxels (module
        docstring). Each block coordinate may be added at most once over the builder's life.
        """
        coords = np.asarray(coords, np.int32).reshape(-1, 3)
        self._claim(coords)
        self._parts.append(pack_blocks(coords, sdf, arrival, self.band))

    def add_packed(self, packed: PackedBlocks) -> None:
        """Add blocks packed elsewhere (:func:`pack_blocks` with this builder's band, plus tiles)."""
        self._claim(np.concatenate([packed.leaf_coord, packed.tile_coord]).astype(np.int32))
        self._parts.append(packed)

    def add_dense(self, sdf: np.ndarray, arrival: np.ndarray, lo_block) -> None:
        """Add every block of a dense box (shape a multiple of 8) starting at block ``lo_block``."""
        if sdf.ndim != 3 or any(n % 8 for n in sdf.shape):
            raise ValueError(f"dense box shape must be a multiple of 8, got {sdf.shape}")
        lo = np.asarray(lo_block, np.int32).reshape(3)
        counts = [n // 8 for n in sdf.shape]
        axes = (lo[q] + np.arange(counts[q], dtype=np.int32) for q in range(3))
        coords = np.stack(np.meshgrid(*axes, indexing="ij"), -1)
        self.add_blocks(coords.reshape(-1, 3), split_blocks(sdf), split_blocks(arrival))

    def add_static(self, sdf: np.ndarray, scale: float, lo_block) -> None:
        """Add every block of a dense box (shape a multiple of 8, values ``sdf * scale``) of a
        part that is there from the start (arrival 0 inside), starting at block ``lo_block``.

        The same blocks as :meth:`add_dense` with that arrival, without its two block-ordered
        copies of the whole box: only the leaves are gathered; inside tiles are coordinates."""
        if sdf.ndim != 3 or any(n % 8 for n in sdf.shape):
            raise ValueError(f"dense box shape must be a multiple of 8, got {sdf.shape}")
        scale32 = np.float32(scale)
        kind, bad = _box_block_kinds(sdf, scale32, np.float32(self.band))
        if bad:
            raise ValueError(f"{bad} non-finite sdf values in the box")
        lo = np.asarray(lo_block, np.int32).reshape(3)
        leaves = np.argwhere(kind == _KIND_LEAF).astype(np.int32)
        tiles = np.argwhere(kind == _KIND_TILE).astype(np.int32)
        leaf_sdf = np.empty((leaves.shape[0], BLOCK, BLOCK, BLOCK), np.float32)
        _gather_blocks(sdf, scale32, leaves, leaf_sdf)
        leaf_arrival = np.where(leaf_sdf < 0, np.float32(0.0), np.float32(np.inf))
        packed = pack_blocks(leaves + lo, leaf_sdf, leaf_arrival, self.band)
        self.add_packed(replace(packed, tile_coord=tiles + lo,
                                tile_arr=np.zeros((tiles.shape[0], 2, 2, 2), np.float32)))

    def finish(self, meta: dict | None = None) -> SparseGrid:
        """The grid, leaves and tiles sorted by linear block index. The builder is emptied.

        Each batch is copied straight to its leaves' and tiles' places and released: the
        batches and the grid are never both whole (no concatenation, no reordering copy)."""
        shape = self.block_shape
        parts, self._parts = self._parts, []

        def lin(coords):
            return np.ravel_multi_index(coords.T, shape) if coords.size else np.zeros(0, np.int64)

        def ranks(values):
            order = np.argsort(values, kind="stable")
            rank = np.empty_like(order)
            rank[order] = np.arange(order.shape[0])
            return order, rank

        leaf_lin = np.concatenate([lin(p.leaf_coord) for p in parts] + [np.zeros(0, np.int64)])
        tile_lin = np.concatenate([lin(p.tile_coord) for p in parts] + [np.zeros(0, np.int64)])
        leaf_order, leaf_rank = ranks(leaf_lin)
        tile_order, tile_rank = ranks(tile_lin)
        leaf_lin, tile_lin = leaf_lin[leaf_order], tile_lin[tile_order]
        n_leaf, n_tile = leaf_lin.shape[0], tile_lin.shape[0]
        sdf_off = _offsets(np.concatenate([p.n_act for p in parts] + [np.zeros(0, np.int64)])[leaf_order])
        arr_off = _offsets(np.concatenate([p.n_arr for p in parts] + [np.zeros(0, np.int64)])[leaf_order])
        del leaf_order, tile_order
        leaf_coord = np.empty((n_leaf, 3), np.int32)
        active = np.empty((n_leaf, 8), np.uint64)
        inside = np.empty((n_leaf, 8), np.uint64)
        leaf_oct = np.empty((n_leaf, 2, 2, 2), np.float32)
        sdf = np.empty(sdf_off[-1], np.float32)
        arr = np.empty(arr_off[-1], np.float32)
        tile_coord = np.empty((n_tile, 3), np.int32)
        tile_arr = np.empty((n_tile, 2, 2, 2), np.float32)
        leaf_at = tile_at = 0
        parts.reverse()  # popped from the end: first batch first
        while parts:
            part = parts.pop()
            rank = leaf_rank[leaf_at:leaf_at + part.leaf_coord.shape[0]]
            leaf_at += rank.shape[0]
            leaf_coord[rank] = part.leaf_coord
            active[rank] = part.active
            inside[rank] = part.inside
            leaf_oct[rank] = part.leaf_oct
            _scatter_runs(part.sdf, _offsets(part.n_act), sdf_off[rank], sdf)
            _scatter_runs(part.arr, _offsets(part.n_arr), arr_off[rank], arr)
            rank = tile_rank[tile_at:tile_at + part.tile_coord.shape[0]]
            tile_at += rank.shape[0]
            tile_coord[rank] = part.tile_coord
            tile_arr[rank] = part.tile_arr
            del part

        block = np.full(shape, OUTSIDE, np.int32)
        flat = block.reshape(-1)
        flat[leaf_lin] = np.arange(leaf_lin.shape[0], dtype=np.int32)
        flat[tile_lin] = -2 - np.arange(tile_lin.shape[0], dtype=np.int32)
        self._seen = np.zeros(shape, np.bool_)
        return SparseGrid(
            voxel=self.voxel,
            origin=self.origin.copy(),
            band=self.band,
            block=block,
            leaf_coord=np.ascontiguousarray(leaf_coord, np.int32),
            leaf_active=np.ascontiguousarray(active),
            leaf_inside=np.ascontiguousarray(inside),
            sdf_offset=sdf_off,
            sdf=sdf,
            arr_offset=arr_off,
            arrival=arr,
            leaf_octant_arrival=np.ascontiguousarray(leaf_oct, np.float32),
            tile_arrival=np.ascontiguousarray(tile_arr, np.float32),
            meta=dict(meta or {}),
        )


def grid_from_dense(sdf: np.ndarray, arrival: np.ndarray, voxel: float, origin, band: float,
                    meta: dict | None = None, batch_blocks: int = 4096) -> SparseGrid:
    """Grid from dense (X, Y, Z) arrays whose shape is a multiple of 8 (tests, small inputs).

    Voxel (0, 0, 0) of the arrays is index (0, 0, 0); blocks are fed in x-slabs of at most
    ``batch_blocks`` blocks so that only one slab's block copy exists at a time.
    """
    sdf = np.asarray(sdf, np.float32)
    arrival = np.asarray(arrival, np.float32)
    if sdf.shape != arrival.shape or sdf.ndim != 3 or any(n % 8 for n in sdf.shape):
        raise ValueError(
            f"dense arrays must have equal shapes that are multiples of 8, got {sdf.shape}, {arrival.shape}"
        )
    nbx, nby, nbz = (n // 8 for n in sdf.shape)
    builder = GridBuilder(voxel, origin, (nbx, nby, nbz), band)
    step = max(1, batch_blocks // (nby * nbz))
    for x0 in range(0, nbx, step):
        x1 = min(nbx, x0 + step)
        builder.add_dense(sdf[8 * x0:8 * x1], arrival[8 * x0:8 * x1], (x0, 0, 0))
    return builder.finish(meta)


def split_blocks(a: np.ndarray) -> np.ndarray:
    """(8X, 8Y, 8Z) -> (X*Y*Z, 8, 8, 8) blocks in C order of their block coordinates."""
    x, y, z = (n // 8 for n in a.shape)
    return np.ascontiguousarray(a.reshape(x, 8, y, 8, z, 8).transpose(0, 2, 4, 1, 3, 5)).reshape(-1, 8, 8, 8)
