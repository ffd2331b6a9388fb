"""Enclosed voids of a :class:`SparseGrid`: the substrate, the channel rule, sub-voxel volumes.

Definitions (docs/POROSITY.md has the reasoning and the convergence figures)

Solid
    The deposit (sdf < 0) and the substrate: everything below the plate ``z_p`` (the caller's,
    by default the lowest deposit, read sub-voxel from the bottom row's depths). A voxel whose
    centre is at or below the plate is solid.

Empty fraction
    The deposit leaves ``e_s`` of a cell empty: ``clamp(0.5 + sdf / voxel, 0, 1)`` (the planar
    estimate :func:`analysis.volume` uses for the inside), but never more than the lines through
    the voxel to its neighbours allow (the three axes and the two horizontal diagonals): the
    material balls of the voxel and of its two neighbours on a line (radius: their depth) leave
    a segment on either side, counted as a slab across the line. That bound is exact for a
    slab of any thickness across one of the lines (slicers' lines run at 0, 90 and 45 degrees),
    so a sheet thinner than a voxel keeps its thickness and a seam of zero width (two faces
    meeting to within rounding) has none; a single face leaves the planar estimate as it is.
    (Lines across layers are left out: a neighbour's depth there may be the engine's estimate,
    larger than the truth, whose ball would erase a real void.) The plate leaves
    ``a_p = clamp((z - z_p) / voxel + 0.5, 0, 1)``. Where both cut a cell they combine by the
    face's slope: nested (``max(0, e_s + a_p - 1)``) where the face lies flat on the plate (a
    bead's bottom: the cell is full, not a quarter empty), independent (``e_s a_p``) where it
    stands across it (a wall meeting the plate). Voxels with ``e > 0`` whose centre is solid
    (*partial* voxels: a wall or a sliver narrower than a voxel crosses them) belong to the void
    they face, so a void keeps its sub-voxel volume. An empty centre whose cell is all but full
    (``e < 1e-3``: a seam open by rounding) counts as solid, so that it joins nothing.

Channel rule
    With the bead width ``w``, the channel width is ``s = CHANNEL_FRACTION * w`` (a quarter of
    the bead). Powder drains, gas escapes and an inspection reaches only through passages that
    hold a ball of diameter ``s``: the ball centres are the empty voxels at least ``s / 2``
    from the solid (read from the SDF within the band, propagated beyond it by a chamfer
    distance). Their 6-connected components that reach the table's boundary (the space beyond
    the table is open, except below the plate) are the *exterior centres*. The exterior is what
    the balls from outside touch plus a reach into what is narrower: every empty or partial
    voxel within a geodesic distance (26-neighbour chamfer through non-solid voxels, never
    squeezing diagonally between two solid voxels) ``R = max(s, s/2 + REACH_SLACK_VOXELS *
    voxel)`` of the exterior centres' boundary (placed sub-voxel, where the clearance crosses
    ``s/2``): the ball's radius and half a channel width beyond it into a crevice or a
    channel's mouth; at coarse voxels at least a voxel and a half beyond the ball, so that the
    partial voxels of every open wall are reached.

    Everything else that is empty is enclosed: cavities a ball fits in but cannot reach from
    outside (their centres form components of their own), and the voids narrower than ``s``
    beyond ``R`` from the outside (lack of fusion between beads, slivers through the layers).
    A cavity connected to the outside only through channels narrower than ``s`` is therefore
    enclosed, with the channels beyond the reach as part of it. Without a bead width the rule
    is off (``s = 0``, unlimited reach): any connection to the outside, however thin (partial
    voxels included), opens a void; only the substrate still closes voids.

Pores and specks
    The enclosed voxels (ball centres not reached from outside, unreached empty and partial
    voxels) form 6-connected components, each one void. A void smaller than the speck floor
    ``max(pi s^3 / 6, SPECK_VOXELS * voxel^3)`` (the ball of the channel width, and never below
    a few voxels) is a *speck*: counted with its volume, not listed as a pore.

Sparse layout
    Every leaf is a work block, and so are the outside tiles the rule must see voxel by voxel:
    those within ``s / 2`` of a leaf when that exceeds the band, and those crossing the plate.
    Other outside tiles are whole: open and a ball centre, or below the plate and solid. Per
    work block the kernels keep a class byte, the SDF as float32 and a distance and labels
    (about 12 B a voxel, for the analysis only); the empty fractions are recomputed where voids
    are. Classification, labels and the direct reach (where the surface is flat or convex the
    exterior centre that reaches a voxel lies straight out along the clearance gradient: one
    lookup) run per block in parallel; the clearance beyond the band (only when ``s / 2``
    exceeds it) and the reach into crevices and channels are sequential Dijkstra searches over
    the voxels concerned.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, replace

import numba as nb
import numpy as np

from .sparse import BLOCK, BLOCK_VOXELS, OUTSIDE, SparseGrid, bit_is_set, sdf_at

CHANNEL_FRACTION = 0.25  # s = CHANNEL_FRACTION * bead width
REACH_SLACK_VOXELS = 1.5  # R = max(s, s/2 + this many voxels)
SPECK_VOXELS = 8.0  # the speck floor never falls below this many voxel volumes

# voxel classes (low 3 bits of the state byte)
FULL = np.uint8(0)  # solid, no empty part
PARTIAL = np.uint8(1)  # centre solid, part of the cell empty
RESIDUAL = np.uint8(2)  # centre empty, closer than s/2 to the solid
CENTRE = np.uint8(3)  # centre empty, a ball of diameter s fits
UNKNOWN = np.uint8(4)  # centre empty, beyond the band: clearance not known yet
CLASS_MASK = np.uint8(7)
EXTERIOR = np.uint8(8)  # flag: an exterior centre, or reached from one
_NO_LABEL = np.uint16(0xFFFF)
_BEYOND = -(2**31)
_PLATE_EPS = 1e-4  # voxels: a centre this close above the plate is on it (the cut leaves -1e-7)
_MIN_OPEN = 1e-3  # an empty centre whose cell is less empty than this is solid
_MIN_PARTIAL = 1e-6  # a solid centre's cell must be this empty to count (not the plate's rounding)


@dataclass(frozen=True, eq=False)
class Voids:
    """Enclosed voids (pores and specks) with the voxels they own.

    Components are numbered pores first (descending volume), then specks (descending volume).
    ``block_coord`` / ``block_label`` / ``block_fraction`` cover the blocks that hold voxels of a
    component: per voxel (local order ``v = lx*64 + ly*8 + lz``) its component or -1, and the
    empty fraction it credits to it. ``tile_coord`` / ``tile_label``: outside tiles wholly in a
    component (every voxel credits 1).
    """

    voxel: float
    origin: np.ndarray
    plate_z: float  # -inf: no substrate
    channel_mm: float  # s (0: the rule is off)
    reach_mm: float  # R
    speck_floor_mm3: float
    volume_mm3: np.ndarray  # (n,)
    centroid_mm: np.ndarray  # (n, 3)
    bbox_mm: np.ndarray  # (n, 2, 3) min and max corners of the component's voxel cells
    voxels: np.ndarray  # (n,) int64 voxels with a non-zero fraction
    wide: np.ndarray  # (n,) bool: holds a ball of diameter s (a cavity, not a sliver)
    speck: np.ndarray  # (n,) bool
    block_coord: np.ndarray  # (m, 3) int32
    block_label: np.ndarray  # (m, 512) int32
    block_fraction: np.ndarray  # (m, 512) float32
    tile_coord: np.ndarray  # (t, 3) int32
    tile_label: np.ndarray  # (t,) int32

    @property
    def n_pores(self) -> int:
        return int(np.count_nonzero(~self.speck))

    def widened(self, origin: np.ndarray) -> "Voids":
        """The same voids indexed in a grid whose voxel 0 sits at ``origin``, whole blocks lower
        (:meth:`SparseGrid.widened`)."""
        shift = np.rint((self.origin - np.asarray(origin, np.float64)) / (BLOCK * self.voxel)).astype(np.int32)
        return replace(self, origin=np.asarray(origin, np.float64).copy(), block_coord=self.block_coord + shift,
                       tile_coord=self.tile_coord + shift)

    def volume_where(self, weight) -> np.ndarray:
        """Per component, the volume (mm^3) of its voxels weighted by ``weight(ijk)`` (a callable
        taking (k, 3) int64 index coordinates and returning (k,) values, e.g. the CAD's
        occupancy in [0, 1]): how much of each void lies inside a part."""
        n = self.volume_mm3.shape[0]
        out = np.zeros(n)
        local = np.stack(np.unravel_index(np.arange(BLOCK_VOXELS), (8, 8, 8)), -1)
        if self.block_coord.shape[0]:
            own = self.block_label >= 0
            ijk = (8 * self.block_coord[:, None, :].astype(np.int64) + local[None])[own]
            w = np.asarray(weight(ijk), np.float64) * self.block_fraction[own]
            out += np.bincount(self.block_label[own], weights=w, minlength=n)
        for t in range(self.tile_coord.shape[0]):
            w = np.asarray(weight(8 * self.tile_coord[t].astype(np.int64) + local), np.float64)
            out[self.tile_label[t]] += w.sum()
        return out * self.voxel**3

    def label_at(self, ijk: np.ndarray) -> np.ndarray:
        """The component owning each voxel of ``ijk`` ((k, 3) int64 index coordinates of the
        grid), -1 where none does (material, open air, a voxel with no empty fraction)."""
        ijk = np.asarray(ijk, np.int64).reshape(-1, 3)
        label = np.full(len(ijk), -1, np.int64)
        if not (self.block_coord.shape[0] or self.tile_coord.shape[0]):
            return label
        coords = np.concatenate([self.block_coord, self.tile_coord]).astype(np.int64)
        # entries: a row of the block tables, or -2 - label for an outside tile, -1 for neither
        table = np.full(coords.max(axis=0) + 1, -1, np.int64)
        table[tuple(self.block_coord.T)] = np.arange(self.block_coord.shape[0])
        table[tuple(self.tile_coord.T)] = -2 - self.tile_label.astype(np.int64)
        block = ijk // BLOCK
        inside = np.all((block >= 0) & (block < table.shape), axis=1)
        entry = np.full(len(ijk), -1, np.int64)
        entry[inside] = table[tuple(block[inside].T)]
        in_leaf = entry >= 0
        local = ijk[in_leaf] - BLOCK * block[in_leaf]
        label[in_leaf] = self.block_label[entry[in_leaf], (local[:, 0] * BLOCK + local[:, 1]) * BLOCK + local[:, 2]]
        in_tile = entry <= -2
        label[in_tile] = -2 - entry[in_tile]
        return label


def void_walls(voids: Voids, vertices: np.ndarray, triangles: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """The triangles of the deposit's surface (outward normals) that wall a pore (not a speck):
    their indices and the pore of each.

    A pore's wall is the deposit's own zero level where the empty side belongs to the pore, so
    the walls come from the surface every command meshes, at any part size and with its
    sub-voxel accuracy. The empty side is probed half a voxel and a voxel out along the face's
    normal (the voxel just beyond a face can hold no empty fraction when the face lies on its
    centre)."""
    corners = np.asarray(vertices, np.float64)[np.asarray(triangles, np.int64)]
    centre = corners.mean(axis=1)
    normal = np.cross(corners[:, 1] - corners[:, 0], corners[:, 2] - corners[:, 0])
    length = np.linalg.norm(normal, axis=1)
    normal /= np.where(length > 0, length, 1.0)[:, None]
    pore = np.full(len(centre), -1, np.int64)
    n_pores = int(np.count_nonzero(~voids.speck))  # numbered pores first, then specks
    for reach in (0.5, 1.0):
        todo = np.flatnonzero((pore < 0) & (length > 0))
        ijk = np.rint((centre[todo] + reach * voids.voxel * normal[todo] - voids.origin) / voids.voxel)
        found = voids.label_at(ijk.astype(np.int64))
        pore[todo] = np.where(found < n_pores, found, -1)
    walls = np.flatnonzero(pore >= 0)
    return walls, pore[walls]


# ---- small helpers --------------------------------------------------------------------------

@nb.njit(cache=True, inline="always")
def _find(parent, x):
    root = x
    while parent[root] != root:
        root = parent[root]
    while parent[x] != root:
        nxt = parent[x]
        parent[x] = root
        x = nxt
    return root


@nb.njit(cache=True, inline="always")
def _union(parent, a, b):
    ra = _find(parent, a)
    rb = _find(parent, b)
    # the smaller id becomes the root, so roots do not depend on the order of unions
    if ra < rb:
        parent[rb] = ra
    elif rb < ra:
        parent[ra] = rb


@nb.njit(cache=True)
def _heap_push(keys, ids, n, key, idx):
    if n == keys.shape[0]:
        k2 = np.empty(2 * n, keys.dtype)
        i2 = np.empty(2 * n, ids.dtype)
        k2[:n] = keys[:n]
        i2[:n] = ids[:n]
        keys, ids = k2, i2
    c = n
    keys[c] = key
    ids[c] = idx
    while c > 0:
        p = (c - 1) >> 1
        if keys[p] <= keys[c]:
            break
        keys[p], keys[c] = keys[c], keys[p]
        ids[p], ids[c] = ids[c], ids[p]
        c = p
    return keys, ids, n + 1


@nb.njit(cache=True)
def _heap_pop(keys, ids, n):
    key = keys[0]
    idx = ids[0]
    n -= 1
    keys[0] = keys[n]
    ids[0] = ids[n]
    c = 0
    while True:
        a = 2 * c + 1
        if a >= n:
            break
        b = a + 1
        m = b if b < n and keys[b] < keys[a] else a
        if keys[c] <= keys[m]:
            break
        keys[c], keys[m] = keys[m], keys[c]
        ids[c], ids[m] = ids[m], ids[c]
        c = m
    return key, idx, n


# ---- the plate ------------------------------------------------------------------------------

@nb.njit(cache=True)
def _lowest_deposit(leaf_coord, leaf_active, leaf_inside, sdf_offset, sdf, inv_voxel):
    """Index z of the lowest deposit surface: the lowest row holding inside voxels, less the
    largest depth found on it (a flat bottom lies that far below the row), at most a voxel."""
    k0 = np.iinfo(np.int64).max
    for leaf in range(leaf_coord.shape[0]):
        ins = leaf_inside[leaf]
        for v in range(BLOCK_VOXELS):
            if bit_is_set(ins, v):
                k0 = min(k0, 8 * np.int64(leaf_coord[leaf, 2]) + (v & 7))
    if k0 == np.iinfo(np.int64).max:
        return -np.inf
    depth = 0.0
    for leaf in range(leaf_coord.shape[0]):
        if 8 * np.int64(leaf_coord[leaf, 2]) > k0 or 8 * np.int64(leaf_coord[leaf, 2]) + 7 < k0:
            continue
        act = leaf_active[leaf]
        ins = leaf_inside[leaf]
        k = sdf_offset[leaf]
        for v in range(BLOCK_VOXELS):
            a = bit_is_set(act, v)
            s = np.float64(sdf[k]) * inv_voxel if a else -1.0
            if a:
                k += 1
            if bit_is_set(ins, v) and 8 * np.int64(leaf_coord[leaf, 2]) + (v & 7) == k0:
                depth = max(depth, min(-s, 1.0))
    return np.float64(k0) - depth


# ---- classification -------------------------------------------------------------------------

@nb.njit(cache=True, inline="always")
def _value_vox(g, inv_voxel, i, j, k):
    """SDF (voxel units) at index (i, j, k) by rank lookup; beyond the table: outside."""
    return np.float64(sdf_at(g, i, j, k)) * inv_voxel


@nb.njit(cache=True, inline="always")
def _beyond(u):
    """Fraction of a cell beyond a plane ``u`` voxels from its centre (the planar estimate)."""
    return min(max(0.5 - u, 0.0), 1.0)


@nb.njit(cache=True, inline="always")
def _line_empty(s_minus, s, s_plus, length):
    """Empty fraction of the cell by the line through the voxel (SDF ``s``) to its two neighbours
    ``length`` voxels away on either side (``s_minus``, ``s_plus``): the material balls of the
    three (radius their depth) leave a segment on each side, each counted as a slab across the
    line. Exact for a slab of any thickness across the line, so a sheet thinner than a voxel
    keeps its own thickness and a zero-width seam has none; never below the planar estimate
    where nothing lies beyond the face."""
    dp = max(0.0, -s)
    lower = 0.0
    a, b = -(length - max(0.0, -s_minus)), -dp
    if b > a:
        lower = _beyond(a) - _beyond(b)
    upper = 0.0
    a, b = dp, length - max(0.0, -s_plus)
    if b > a:
        upper = _beyond(a) - _beyond(b)
    return lower + upper


# The lines through a voxel that bound its empty fraction: the three axes and the two horizontal
# diagonals (slicers lay lines at 0, 90 and +-45 degrees in a layer). The other diagonals cross
# layers, where a neighbour's depth may be the engine's estimate (overlapping beads of unequal
# heights), larger than the truth: a ball of that radius would erase a real void sheet.
_LINES = np.array([[1, 0, 0], [0, 1, 0], [0, 0, 1], [1, 1, 0], [1, -1, 0]], np.int64)


@nb.njit(cache=True, inline="always")
def _local_or_lookup(s_out, lx, ly, lz, bx, by, bz, g, inv_voxel):
    if 0 <= lx < 8 and 0 <= ly < 8 and 0 <= lz < 8:
        return s_out[lx * 64 + ly * 8 + lz]
    return _value_vox(g, inv_voxel, bx + lx, by + ly, bz + lz)


@nb.njit(cache=True)
def _block_values(w, wcoord, g, inv_voxel, band_vox, zp, s_out, in_out, e_out):
    """SDF (voxels), inside flag and empty fraction (module docstring) of the 512 voxels of work
    block ``w``. The deposit's part ``e_s`` is the planar estimate ``clamp(0.5 + s)``, bounded by
    the lines through the voxel to its neighbours (:func:`_line_empty`)."""
    is_leaf = w < g.leaf_active.shape[0]  # work blocks are numbered leaves first
    k = g.sdf_offset[w] if is_leaf else 0
    for v in range(BLOCK_VOXELS):
        inside = False
        s = band_vox
        if is_leaf:
            if bit_is_set(g.leaf_active[w], v):
                s = np.float64(g.sdf[k]) * inv_voxel
                k += 1
                inside = bit_is_set(g.leaf_inside[w], v)
            elif bit_is_set(g.leaf_inside[w], v):
                s = -band_vox
                inside = True
        s_out[v] = s
        in_out[v] = inside
    bx, by, bz = 8 * np.int64(wcoord[w, 0]), 8 * np.int64(wcoord[w, 1]), 8 * np.int64(wcoord[w, 2])
    for v in range(BLOCK_VOXELS):
        s = s_out[v]
        e_s = min(max(0.5 + s, 0.0), 1.0)
        hz = np.float64(bz + (v & 7)) - zp
        a_p = min(max(hz + 0.5, 0.0), 1.0)
        g2 = 0.0  # squared SDF gradient (central differences on the axes) and its z part
        gz = 0.0
        if is_leaf and e_s > 0.0 and s < 0.5:
            lx, ly, lz = v >> 6, (v >> 3) & 7, v & 7
            for m in range(_LINES.shape[0]):
                dx, dy, dz = _LINES[m, 0], _LINES[m, 1], _LINES[m, 2]
                sm = _local_or_lookup(s_out, lx - dx, ly - dy, lz - dz, bx, by, bz, g, inv_voxel)
                sp = _local_or_lookup(s_out, lx + dx, ly + dy, lz + dz, bx, by, bz, g, inv_voxel)
                e_s = min(e_s, _line_empty(sm, s, sp, math.sqrt(dx * dx + dy * dy + dz * dz)))
                if m < 3:
                    grad = 0.5 * (sp - sm)
                    g2 += grad * grad
                    if m == 2:
                        gz = grad
        if a_p >= 1.0 or e_s <= 0.0:
            e_out[v] = e_s * a_p
        else:
            # The deposit's face and the plate cut the cell: nested where the face lies flat on
            # the plate (a bead's bottom: the cell is full), independent where it stands across
            # it (a wall meeting the plate: a quarter of the cell empty), by the face's slope.
            flat = gz * gz / g2 if g2 > 0.0 else 1.0
            e_out[v] = flat * max(0.0, e_s + a_p - 1.0) + (1.0 - flat) * e_s * a_p


@nb.njit(cache=True, parallel=True)
def _classify(wcoord, g, inv_voxel, band_vox, zp, r_vox, state, dep):
    """Per work block: the class byte, and the deposit's SDF in voxels (``band_vox`` where
    unknown, i.e. beyond the band)."""
    n = wcoord.shape[0]
    unknown_possible = r_vox > band_vox - 1e-6
    for w in nb.prange(n):
        bz = 8 * np.int64(wcoord[w, 2])
        s8 = np.empty(BLOCK_VOXELS)
        i8 = np.empty(BLOCK_VOXELS, np.bool_)
        e8 = np.empty(BLOCK_VOXELS)
        _block_values(w, wcoord, g, inv_voxel, band_vox, zp, s8, i8, e8)
        for v in range(BLOCK_VOXELS):
            s = s8[v]
            inside = i8[v]
            hz = np.float64(bz + (v & 7)) - zp
            dep[w, v] = s
            if inside or hz <= _PLATE_EPS or e8[v] < _MIN_OPEN:
                # a centre outside by a hair, in a seam of zero width, is solid: it must not join voids
                state[w, v] = PARTIAL if e8[v] > _MIN_PARTIAL else FULL
            elif unknown_possible and s >= band_vox - 1e-6 and hz >= r_vox:
                state[w, v] = UNKNOWN
            elif min(s, hz) >= r_vox:
                state[w, v] = CENTRE
            else:
                state[w, v] = RESIDUAL


# the 26-neighbour steps' lengths, by neighbour (dx+1)*9 + (dy+1)*3 + dz+1
_CHAMFER = np.array([math.sqrt((f // 9 - 1) ** 2 + ((f // 3) % 3 - 1) ** 2 + (f % 3 - 1) ** 2) for f in range(27)])


@nb.njit(cache=True, inline="always")
def _interior(v):
    """Whether all 26 neighbours of local voxel ``v`` lie in its own block."""
    lx, ly, lz = v >> 6, (v >> 3) & 7, v & 7
    return 0 < lx < 7 and 0 < ly < 7 and 0 < lz < 7


@nb.njit(cache=True, inline="always")
def _around(nbr, w, v, f, interior):
    """Neighbour ``f`` ((dx+1)*9 + (dy+1)*3 + dz+1) of voxel ``v`` of work block ``w``: (its work
    block, < 0 when it is not one; its local voxel), the block table skipped when ``interior``."""
    dx, dy, dz = f // 9 - 1, (f // 3) % 3 - 1, f % 3 - 1
    if interior:
        return np.int64(w), v + 64 * dx + 8 * dy + dz
    b, v2, _ = _step(nbr, w, v, dx, dy, dz)
    return b, v2


@nb.njit(cache=True)
def _extend_clearance(wid, wcoord, state, dep, band_vox, r_vox, n_leaf, exhaustive=False):
    """Deposit distance beyond the band by chamfer distance from the band's exact distances;
    UNKNOWN voxels become CENTRE (>= r_vox) or RESIDUAL, and ``dep`` keeps the distance where
    :func:`_reach` reads it: below ``r_vox + 1`` everywhere, and up to ``r_vox + 2`` at the axis
    neighbours of the RESIDUAL and PARTIAL voxels (its direct reach's clearance and gradient);
    elsewhere ``dep`` is at least ``r_vox + 1`` (an exterior centre's start saturates there).

    The band's voxels outside (0 < s < band) hand ``s`` plus the step to their UNKNOWN
    neighbours (the least of them, where under ``r_vox + 2``, seeds each); frontier rounds
    settle the paths under ``r_vox + 1``, which only the thin shell below ``r_vox`` hands on, so
    the work is the band's skin, never the UNKNOWN voxels deeper out (most of them on thin walls,
    whose outside tiles the rule must see voxel by voxel). A value in ``[r_vox + 1, r_vox + 2)``
    comes from its seed or one step from a settled voxel (a step is at least 1), so where it is
    read it is found in one pull (:func:`_clearance_read_points`). Each is the least path
    length from the seeds with every prefix under ``r_vox + 2``, summed in path order, the
    unique fixed point whatever the order of the updates. ``exhaustive``: the rounds settle
    every path under ``r_vox + 2`` instead (``dep`` exact everywhere, the reference)."""
    limit = r_vox + 2.0
    exact = limit if exhaustive else r_vox + 1.0
    nbr = _block_neighbours(wid, wcoord)
    dist = _clearance_seeds(nbr, state, dep, band_vox, limit, n_leaf)
    _clearance_settle(nbr, state, dist, exact)
    if not exhaustive:
        _clearance_read_points(nbr, state, dep, dist, band_vox, exact, limit)
    _clearance_classes(state, dep, dist, r_vox, limit)


@nb.njit(cache=True)
def _clearance_read_points(nbr, state, dep, dist, band_vox, exact, limit):
    """The distances in ``[exact, limit)`` (``exact = limit - 1``) at the UNKNOWN axis neighbours
    of the RESIDUAL and PARTIAL voxels: the least of the seed and a settled neighbour's distance
    (below ``exact``) plus the step. Only a RESIDUAL or PARTIAL voxel that hands no seed on (no
    band value outside) can have one: a band voxel's neighbours hold seeds under ``band + 1 <=
    exact``. Neighbours are read below ``exact`` only and written at or above it, so the order of
    the updates does not matter."""
    n = nbr.shape[0]
    for w in range(n):
        for v in range(BLOCK_VOXELS):
            st = state[w, v]
            if st != RESIDUAL and st != PARTIAL:
                continue
            s = np.float64(dep[w, v])
            if s > 0.0 and s < band_vox - 1e-6:
                continue
            for a in range(6):
                f = (4, 22, 10, 16, 12, 14)[a]  # the six axis neighbours
                b, v2 = _around(nbr, w, v, f, _interior(v))
                if b < 0 or state[b, v2] != UNKNOWN:
                    continue
                g2 = b * BLOCK_VOXELS + v2
                best = dist[g2]
                if best < exact:
                    continue
                interior = _interior(v2)
                for f2 in range(27):
                    if f2 == 13:
                        continue
                    b3, v3 = _around(nbr, b, v2, f2, interior)
                    if b3 < 0 or state[b3, v3] != UNKNOWN:
                        continue
                    d = dist[b3 * BLOCK_VOXELS + v3]
                    if d < exact:
                        best = min(best, d + _CHAMFER[f2])
                dist[g2] = best if best < limit else np.inf


@nb.njit(cache=True, parallel=True)
def _clearance_classes(state, dep, dist, r_vox, limit):
    for w in nb.prange(state.shape[0]):
        for v in range(BLOCK_VOXELS):
            if state[w, v] == UNKNOWN:
                d = dist[w * BLOCK_VOXELS + v]
                state[w, v] = RESIDUAL if d < r_vox else CENTRE
                dep[w, v] = min(d, limit)


@nb.njit(cache=True, parallel=True)
def _clearance_seeds(nbr, state, dep, band_vox, limit, n_leaf):
    """Per voxel, UNKNOWN ones only, the least of ``s`` plus the step from a band voxel next to
    it (outside, 0 < s < band), +inf at or beyond ``limit``: the seeds of
    :func:`_extend_clearance`. Per block in parallel, the band's values read once into a
    10^3 window (the block and a voxel around it), so the 26 neighbours are local reads; only
    leaves (work blocks ``< n_leaf``) hold band voxels, so a block with none around is skipped
    (the plate's and the rule's outside tiles far from the part)."""
    n = nbr.shape[0]
    dist = np.full(n * BLOCK_VOXELS, np.inf)
    for w in nb.prange(n):
        todo = False
        for c in range(27):
            if 0 <= nbr[w, c] < n_leaf:
                todo = True
                break
        if not todo:
            continue
        todo = False
        for v in range(BLOCK_VOXELS):
            if state[w, v] == UNKNOWN:
                todo = True
                break
        if not todo:
            continue
        src = np.full(1000, np.inf)  # window voxel (lx + 1) * 100 + (ly + 1) * 10 + lz + 1
        found = False
        for hx in range(10):
            cx = 0 if hx == 0 else (2 if hx == 9 else 1)
            for hy in range(10):
                cy = 0 if hy == 0 else (2 if hy == 9 else 1)
                for hz in range(10):
                    cz = 0 if hz == 0 else (2 if hz == 9 else 1)
                    b = nbr[w, cx * 9 + cy * 3 + cz]
                    if b < 0:
                        continue
                    v2 = ((hx - 1) & 7) * 64 + ((hy - 1) & 7) * 8 + ((hz - 1) & 7)
                    s = np.float64(dep[b, v2])
                    if state[b, v2] != UNKNOWN and s > 0.0 and s < band_vox - 1e-6:
                        src[hx * 100 + hy * 10 + hz] = s
                        found = True
        if not found:
            continue
        for v in range(BLOCK_VOXELS):
            if state[w, v] != UNKNOWN:
                continue
            h0 = ((v >> 6) + 1) * 100 + (((v >> 3) & 7) + 1) * 10 + (v & 7) + 1
            best = np.inf
            for f in range(27):
                val = src[h0 + 100 * (f // 9 - 1) + 10 * ((f // 3) % 3 - 1) + f % 3 - 1]
                if f != 13 and val < np.inf:
                    best = min(best, val + _CHAMFER[f])
            if best < limit:
                dist[w * BLOCK_VOXELS + v] = best
    return dist


@nb.njit(cache=True)
def _clearance_settle(nbr, state, dist, limit):
    """Settle the chamfer distances from the seeds in ``dist`` through the UNKNOWN voxels, every
    prefix under ``limit`` (in place): rounds over a frontier, the voxels lowered in the last
    round (the seeds first) handing their distance on; a path under the limit has only a few
    steps, so a few rounds settle it, each over its frontier in memory order (a heap's random
    order over millions of voxels costs more than the rounds' repeats)."""
    total = dist.shape[0]
    mark = np.zeros(total, np.bool_)
    count = 0
    for g in range(total):
        if dist[g] < np.inf:
            count += 1
    frontier = np.empty(count, np.int64)
    count = 0
    for g in range(total):
        if dist[g] < np.inf:
            frontier[count] = g
            count += 1
    nxt = np.empty(max(16, count), np.int64)
    while count > 0:
        m = 0
        for q in range(count):
            g = frontier[q]
            d = dist[g]
            w = g // BLOCK_VOXELS
            v = g % BLOCK_VOXELS
            interior = _interior(v)
            for f in range(27):
                if f == 13:
                    continue
                nd = d + _CHAMFER[f]
                if nd >= limit:
                    continue
                b, v2 = _around(nbr, w, v, f, interior)
                if b < 0 or state[b, v2] != UNKNOWN:
                    continue
                g2 = b * BLOCK_VOXELS + v2
                if nd < dist[g2]:
                    dist[g2] = nd
                    if not mark[g2]:
                        mark[g2] = True
                        if m == nxt.shape[0]:
                            grown = np.empty(2 * m, np.int64)
                            grown[:m] = nxt[:m]
                            nxt = grown
                        nxt[m] = g2
                        m += 1
        frontier = np.sort(nxt[:m])
        for q in range(m):
            mark[frontier[q]] = False
        count = m
    return dist


# ---- connected components -------------------------------------------------------------------

@nb.njit(cache=True, parallel=True)
def _label_blocks(member):
    """6-connected components of each work block's member voxels: labels (n, 512), counts."""
    n = member.shape[0]
    labels = np.empty((n, BLOCK_VOXELS), np.uint16)
    counts = np.zeros(n, np.int64)
    for w in nb.prange(n):
        mem = member[w]
        parent = np.empty(BLOCK_VOXELS, np.int64)
        for v in range(BLOCK_VOXELS):
            parent[v] = v
        for v in range(BLOCK_VOXELS):
            if not mem[v]:
                continue
            if (v >> 6) > 0 and mem[v - 64]:
                _union(parent, v, v - 64)
            if ((v >> 3) & 7) > 0 and mem[v - 8]:
                _union(parent, v, v - 8)
            if (v & 7) > 0 and mem[v - 1]:
                _union(parent, v, v - 1)
        lab = labels[w]
        c = 0
        for v in range(BLOCK_VOXELS):
            if not mem[v]:
                lab[v] = _NO_LABEL
            else:
                r = _find(parent, v)
                if r == v:
                    lab[v] = c
                    c += 1
                else:
                    lab[v] = lab[r]
        counts[w] = c
    return labels, counts


@nb.njit(cache=True, inline="always")
def _face_voxel(axis, layer, a, b):
    if axis == 0:
        return layer * 64 + a * 8 + b
    if axis == 1:
        return a * 64 + layer * 8 + b
    return a * 64 + b * 8 + layer


@nb.njit(cache=True)
def _connect(wid, tile_member, wcoord, labels, comp_off):
    """Union-find over member space; returns the compressed root of every node.

    Nodes: table blocks by linear index (only whole member tiles are joined), the exterior
    node ``nblk`` (beyond the table), then work-block components ``nblk + 1 + comp_off[w] + label``.
    """
    nx, ny, nz = wid.shape
    nblk = nx * ny * nz
    ext = nblk
    base = nblk + 1
    parent = np.arange(base + comp_off[-1])
    for bx in range(nx):
        for by in range(ny):
            for bz in range(nz):
                b = (bx * ny + by) * nz + bz
                if wid[bx, by, bz] != -1 or not tile_member[b]:
                    continue
                if bx == 0 or by == 0 or bz == 0 or bx == nx - 1 or by == ny - 1 or bz == nz - 1:
                    _union(parent, b, ext)
                if bx + 1 < nx and wid[bx + 1, by, bz] == -1 and tile_member[b + ny * nz]:
                    _union(parent, b, b + ny * nz)
                if by + 1 < ny and wid[bx, by + 1, bz] == -1 and tile_member[b + nz]:
                    _union(parent, b, b + nz)
                if bz + 1 < nz and wid[bx, by, bz + 1] == -1 and tile_member[b + 1]:
                    _union(parent, b, b + 1)
    dims = np.array([nx, ny, nz])
    nbr = np.empty(3, np.int64)
    for w in range(wcoord.shape[0]):
        lab = labels[w]
        node0 = base + comp_off[w]
        for axis in range(3):
            for side in range(2):
                for q in range(3):
                    nbr[q] = wcoord[w, q]
                nbr[axis] += 1 if side == 1 else -1
                layer = 7 if side == 1 else 0
                if nbr[axis] < 0 or nbr[axis] >= dims[axis]:
                    target = ext
                else:
                    val = wid[nbr[0], nbr[1], nbr[2]]
                    lin = (nbr[0] * ny + nbr[1]) * nz + nbr[2]
                    if val == -1:
                        if not tile_member[lin]:
                            continue
                        target = lin
                    elif val >= 0:
                        if side == 0:
                            continue  # joined once, from the lower block
                        other = labels[val]
                        node1 = base + comp_off[val]
                        for a in range(8):
                            for b in range(8):
                                la = lab[_face_voxel(axis, 7, a, b)]
                                lb = other[_face_voxel(axis, 0, a, b)]
                                if la != _NO_LABEL and lb != _NO_LABEL:
                                    _union(parent, node0 + la, node1 + lb)
                        continue
                    else:
                        continue
                for a in range(8):
                    for b in range(8):
                        la = lab[_face_voxel(axis, layer, a, b)]
                        if la != _NO_LABEL:
                            _union(parent, node0 + la, target)
    for x in range(parent.shape[0]):
        parent[x] = _find(parent, x)
    return parent


@nb.njit(cache=True, parallel=True)
def _mark_exterior_centres(state, labels, comp_off, root, ext_root, nblk):
    n = state.shape[0]
    for w in nb.prange(n):
        base = nblk + 1 + comp_off[w]
        for v in range(BLOCK_VOXELS):
            if state[w, v] == CENTRE and root[base + labels[w, v]] == ext_root:
                state[w, v] |= EXTERIOR


# ---- reach from the exterior ----------------------------------------------------------------

@nb.njit(cache=True, parallel=True)
def _block_neighbours(wid, wcoord):
    """Per work block, the table value of its 27 neighbouring blocks ((dx+1)*9 + (dy+1)*3 + dz+1):
    a work block id, -1 a whole outside tile, <= -2 an inside tile, ``_BEYOND`` off the table."""
    nx, ny, nz = wid.shape
    n = wcoord.shape[0]
    out = np.empty((n, 27), np.int64)
    for w in nb.prange(n):
        for c in range(27):
            i = wcoord[w, 0] + c // 9 - 1
            j = wcoord[w, 1] + (c // 3) % 3 - 1
            k = wcoord[w, 2] + c % 3 - 1
            if i < 0 or j < 0 or k < 0 or i >= nx or j >= ny or k >= nz:
                out[w, c] = _BEYOND
            else:
                out[w, c] = wid[i, j, k]
    return out


@nb.njit(cache=True, inline="always")
def _step(nbr, w, v, dx, dy, dz):
    """The voxel at (dx, dy, dz) from voxel ``v`` of work block ``w``: (table value of its block,
    local voxel, index of the block in ``nbr``'s 27)."""
    lx = (v >> 6) + dx
    ly = ((v >> 3) & 7) + dy
    lz = (v & 7) + dz
    cx = 0 if lx < 0 else (2 if lx > 7 else 1)
    cy = 0 if ly < 0 else (2 if ly > 7 else 1)
    cz = 0 if lz < 0 else (2 if lz > 7 else 1)
    c = cx * 9 + cy * 3 + cz
    return nbr[w, c], (lx & 7) * 64 + (ly & 7) * 8 + (lz & 7), c


@nb.njit(cache=True, inline="always")
def _open_at(nbr, state, tile_open, tile_lin, above_plate, w, v, dx, dy, dz):
    """Whether the voxel at (dx, dy, dz) from (w, v) is not wholly solid."""
    b, v2, c = _step(nbr, w, v, dx, dy, dz)
    if b >= 0:
        return (state[b, v2] & CLASS_MASK) != FULL
    if b == -1:
        return tile_open[tile_lin[w, c]]
    if b == _BEYOND:
        return above_plate
    return False


@nb.njit(cache=True, inline="always")
def _clearance(nbr, dep, wcoord, zp, w, v, dx, dy, dz, band_vox):
    """Clearance (voxels: distance to the deposit or the plate, negative inside) at an offset."""
    b, v2, c = _step(nbr, w, v, dx, dy, dz)
    kz = np.float64(8 * np.int64(wcoord[w, 2]) + (v & 7) + dz) - zp
    if b >= 0:
        return min(np.float64(dep[b, v2]), kz)
    if b == -1 or b == _BEYOND:
        return min(band_vox, kz)
    return -band_vox


@nb.njit(cache=True, parallel=True)
def _reach_direct(nbr, wid, wcoord, state, dep, tile_ext, zp, r_vox, reach_vox, band_vox, dist):
    """Where the surface is flat or convex, the exterior centre that reaches a voxel lies straight
    out along the clearance gradient, ``r_vox`` from the surface: one lookup per voxel, in
    parallel. Sets ``dist`` (to the centres' boundary, ``r_vox - c`` straight out) where that
    centre is an exterior one within reach; the rest (crevices, channels, concave corners) is left to the search."""
    n = wcoord.shape[0]
    nx, ny, nz = wid.shape
    for w in nb.prange(n):
        for v in range(BLOCK_VOXELS):
            c0 = state[w, v] & CLASS_MASK
            if c0 != RESIDUAL and c0 != PARTIAL:
                continue
            c = _clearance(nbr, dep, wcoord, zp, w, v, 0, 0, 0, band_vox)
            gx = 0.5 * (_clearance(nbr, dep, wcoord, zp, w, v, 1, 0, 0, band_vox)
                        - _clearance(nbr, dep, wcoord, zp, w, v, -1, 0, 0, band_vox))
            gy = 0.5 * (_clearance(nbr, dep, wcoord, zp, w, v, 0, 1, 0, band_vox)
                        - _clearance(nbr, dep, wcoord, zp, w, v, 0, -1, 0, band_vox))
            gz = 0.5 * (_clearance(nbr, dep, wcoord, zp, w, v, 0, 0, 1, band_vox)
                        - _clearance(nbr, dep, wcoord, zp, w, v, 0, 0, -1, band_vox))
            g = math.sqrt(gx * gx + gy * gy + gz * gz)
            if g < 0.5:
                continue  # not a clean distance field here (a ridge, a crease): search instead
            out = r_vox + 0.5 - c
            i = 8 * np.int64(wcoord[w, 0]) + (v >> 6)
            j = 8 * np.int64(wcoord[w, 1]) + ((v >> 3) & 7)
            k = 8 * np.int64(wcoord[w, 2]) + (v & 7)
            ti = i + np.int64(round(out * gx / g))
            tj = j + np.int64(round(out * gy / g))
            tk = k + np.int64(round(out * gz / g))
            d = math.sqrt(np.float64((ti - i) ** 2 + (tj - j) ** 2 + (tk - k) ** 2))
            if d > reach_vox:
                continue
            if ti < 0 or tj < 0 or tk < 0 or (ti >> 3) >= nx or (tj >> 3) >= ny or (tk >> 3) >= nz:
                ok = np.float64(tk) - zp > r_vox
            else:
                b = wid[ti >> 3, tj >> 3, tk >> 3]
                if b >= 0:
                    st = state[b, (ti & 7) * 64 + (tj & 7) * 8 + (tk & 7)]
                    ok = (st & CLASS_MASK) == CENTRE and (st & EXTERIOR) != 0
                elif b == -1:
                    ok = tile_ext[(np.int64(ti >> 3) * ny + (tj >> 3)) * nz + (tk >> 3)]
                else:
                    ok = False
            if ok:
                # a distance field grows a voxel a voxel: the centres' boundary is r - c away
                dist[w * BLOCK_VOXELS + v] = np.float32(max(0.0, r_vox - c))


_REACH_MARGIN = 1e-3  # voxels: beyond the float32 rounding of any path within the reach


@nb.njit(cache=True, parallel=True)
def _unreached_boxes(wid, wcoord, state, dist, reach_vox, exhaustive):
    """Per work block, the index box (lo, hi; empty: lo > hi) that holds every RESIDUAL or
    PARTIAL voxel the direct reach left beyond ``reach_vox`` within ``reach_vox`` (plus a
    rounding margin) of the block: only those voxels' flags can still change, and a chamfer path
    is never shorter than the straight line, so the search need not enter a voxel farther than
    what is left of the reach from that box (:func:`_reach`). The whole table when
    ``exhaustive`` or the reach is unlimited.

    The search starts at ``-1`` at the least (an exterior centre's start) and steps of at least
    1 lead to any RESIDUAL or PARTIAL voxel, so every such voxel it holds has a distance >= 0;
    a block at Chebyshev block distance D >= 1 keeps its voxels at least ``8 (D - 1) + 1``
    from another's, so the boxes of the blocks within ``rings`` of it cover the rest."""
    n = wcoord.shape[0]
    far = np.int64(1) << 40  # beyond any table, and no overflow in a difference
    lo = np.full((n, 3), far, np.int64)
    hi = np.full((n, 3), -far, np.int64)
    if exhaustive or not reach_vox < np.inf:
        lo[:] = -far
        hi[:] = far
        return lo, hi
    for w in nb.prange(n):
        for v in range(BLOCK_VOXELS):
            c0 = state[w, v] & CLASS_MASK
            if (c0 == RESIDUAL or c0 == PARTIAL) and not dist[w * BLOCK_VOXELS + v] <= reach_vox:
                ijk = (8 * np.int64(wcoord[w, 0]) + (v >> 6), 8 * np.int64(wcoord[w, 1]) + ((v >> 3) & 7),
                       8 * np.int64(wcoord[w, 2]) + (v & 7))
                for q in range(3):
                    lo[w, q] = min(lo[w, q], ijk[q])
                    hi[w, q] = max(hi[w, q], ijk[q])
    rings = max(1, int(math.floor((reach_vox + _REACH_MARGIN - 1.0) / 8.0)) + 1)
    nx, ny, nz = wid.shape
    lo2 = lo.copy()
    hi2 = hi.copy()
    for w in nb.prange(n):
        for i in range(max(0, wcoord[w, 0] - rings), min(nx, wcoord[w, 0] + rings + 1)):
            for j in range(max(0, wcoord[w, 1] - rings), min(ny, wcoord[w, 1] + rings + 1)):
                for k in range(max(0, wcoord[w, 2] - rings), min(nz, wcoord[w, 2] + rings + 1)):
                    b = wid[i, j, k]
                    if b < 0:
                        continue  # not a work block: no RESIDUAL or PARTIAL voxel
                    for q in range(3):
                        lo2[w, q] = min(lo2[w, q], lo[b, q])
                        hi2[w, q] = max(hi2[w, q], hi[b, q])
    return lo2, hi2


@nb.njit(cache=True, inline="always")
def _box_gap(lo, hi, w, i, j, k):
    """Distance (voxels) from index (i, j, k) to the box ``lo[w]``..``hi[w]`` (+inf: empty box)."""
    if lo[w, 0] > hi[w, 0]:
        return np.inf
    acc = 0.0
    p = (i, j, k)
    for q in range(3):
        gap = max(lo[w, q] - p[q], p[q] - hi[w, q], 0)
        acc += np.float64(gap) * np.float64(gap)
    return math.sqrt(acc)


@nb.njit(cache=True)
def _reach(wid, wcoord, state, dep, tile_open, tile_ext, zp, r_vox, reach_vox, band_vox, exhaustive):
    """Flag EXTERIOR on the RESIDUAL and PARTIAL voxels within ``reach_vox`` (26-neighbour
    chamfer, geodesic through non-solid voxels, a diagonal step only past a non-solid face
    neighbour) of the exterior centres, whole exterior tiles and the space beyond the table.

    Distances start at the centres' boundary placed sub-voxel: an exterior centre of clearance
    ``c`` (a distance field: it grows by a voxel a voxel) lies ``c - r_vox`` beyond it, so it
    starts at ``-(c - r_vox)``. The search after the direct reach enters only the voxels from
    which a path could still flag a voxel the direct reach left out (:func:`_unreached_boxes`;
    every voxel when ``exhaustive``): the flags are the same, the work follows the concave
    corners, crevices and channels."""
    n = wcoord.shape[0]
    nx, ny, nz = wid.shape
    nbr = _block_neighbours(wid, wcoord)
    tile_lin = np.empty((n, 27), np.int64)
    for w in range(n):
        for c in range(27):
            i = wcoord[w, 0] + c // 9 - 1
            j = wcoord[w, 1] + (c // 3) % 3 - 1
            k = wcoord[w, 2] + c % 3 - 1
            tile_lin[w, c] = (i * ny + j) * nz + k if nbr[w, c] == -1 else 0
    dist = np.full(n * BLOCK_VOXELS, np.inf, np.float32)
    _reach_direct(nbr, wid, wcoord, state, dep, tile_ext, zp, r_vox, reach_vox, band_vox, dist)
    lo, hi = _unreached_boxes(wid, wcoord, state, dist, reach_vox, exhaustive)
    keys = np.empty(4096, np.float64)
    ids = np.empty(4096, np.int64)
    hn = 0
    # seeds: voxels reached directly next to one that is not; exterior centres next to a voxel
    # the reach may enter and not reached directly; and those voxels themselves where the
    # exterior next to them is a whole tile or off the table (each one a step at most from a
    # voxel left unreached, so inside or next to its block's box)
    for w in range(n):
        if lo[w, 0] > hi[w, 0]:
            continue
        for v in range(BLOCK_VOXELS):
            st = state[w, v]
            c0 = st & CLASS_MASK
            is_ext = c0 == CENTRE and (st & EXTERIOR) != 0
            if not is_ext and c0 != RESIDUAL and c0 != PARTIAL:
                continue
            if _box_gap(lo, hi, w, 8 * np.int64(wcoord[w, 0]) + (v >> 6), 8 * np.int64(wcoord[w, 1]) + ((v >> 3) & 7),
                        8 * np.int64(wcoord[w, 2]) + (v & 7)) > 1.75:
                continue
            g0 = w * BLOCK_VOXELS + v
            if not is_ext and dist[g0] < np.inf:
                for f in range(26):
                    f2 = f + (f >= 13)
                    b, v2, c = _step(nbr, w, v, f2 // 9 - 1, (f2 // 3) % 3 - 1, f2 % 3 - 1)
                    if b >= 0:
                        c2 = state[b, v2] & CLASS_MASK
                        if (c2 == RESIDUAL or c2 == PARTIAL) and dist[b * BLOCK_VOXELS + v2] == np.inf:
                            keys, ids, hn = _heap_push(keys, ids, hn, np.float64(dist[g0]), g0)
                            break
                continue
            above = np.float64(8 * np.int64(wcoord[w, 2]) + (v & 7)) - zp
            for f in range(6):
                dx = (f == 0) - (f == 1)
                dy = (f == 2) - (f == 3)
                dz = (f == 4) - (f == 5)
                b, v2, c = _step(nbr, w, v, dx, dy, dz)
                if is_ext:
                    if b >= 0:
                        c2 = state[b, v2] & CLASS_MASK
                        if (c2 == RESIDUAL or c2 == PARTIAL) and dist[b * BLOCK_VOXELS + v2] == np.inf:
                            g = w * BLOCK_VOXELS + v
                            start = -min(max(min(np.float64(dep[w, v]), above) - r_vox, 0.0), 1.0)
                            start = np.float64(np.float32(start))
                            if start < dist[g]:
                                dist[g] = start
                                keys, ids, hn = _heap_push(keys, ids, hn, start, g)
                            break
                else:
                    ext = False
                    if b == -1:
                        ext = tile_ext[tile_lin[w, c]]
                    elif b == _BEYOND:
                        ext = above + dz > _PLATE_EPS
                    if ext:
                        g = g0
                        if 1.0 < dist[g]:
                            dist[g] = 1.0
                            keys, ids, hn = _heap_push(keys, ids, hn, 1.0, g)
    while hn > 0:
        d, g, hn = _heap_pop(keys, ids, hn)
        if d > dist[g]:
            continue
        w = g // BLOCK_VOXELS
        v = g % BLOCK_VOXELS
        i0 = 8 * np.int64(wcoord[w, 0]) + (v >> 6)
        j0 = 8 * np.int64(wcoord[w, 1]) + ((v >> 3) & 7)
        k0 = 8 * np.int64(wcoord[w, 2]) + (v & 7)
        above = np.float64(k0) - zp
        for dx in range(-1, 2):
            for dy in range(-1, 2):
                for dz in range(-1, 2):
                    if dx == 0 and dy == 0 and dz == 0:
                        continue
                    b, v2, _ = _step(nbr, w, v, dx, dy, dz)
                    if b < 0:
                        continue
                    c2 = state[b, v2] & CLASS_MASK
                    if c2 != RESIDUAL and c2 != PARTIAL:
                        continue
                    # keys are the float32 distances kept, so that a popped key matches its entry
                    nd = np.float64(np.float32(d + math.sqrt(dx * dx + dy * dy + dz * dz)))
                    g2 = b * BLOCK_VOXELS + v2
                    if nd >= dist[g2] or nd > reach_vox:
                        continue
                    if nd + _box_gap(lo, hi, b, i0 + dx, j0 + dy, k0 + dz) > reach_vox + _REACH_MARGIN:
                        continue  # no voxel left out lies within what is left of the reach
                    if abs(dx) + abs(dy) + abs(dz) > 1 and not (
                            (dx != 0 and _open_at(nbr, state, tile_open, tile_lin, above > _PLATE_EPS, w, v, dx, 0, 0))
                            or (dy != 0 and _open_at(nbr, state, tile_open, tile_lin, above > _PLATE_EPS, w, v, 0, dy, 0))
                            or (dz != 0 and _open_at(nbr, state, tile_open, tile_lin, above + dz > _PLATE_EPS, w, v,
                                                     0, 0, dz))):
                        continue  # no squeezing between two solid voxels that share an edge
                    dist[g2] = nd
                    keys, ids, hn = _heap_push(keys, ids, hn, nd, g2)
    for w in range(n):
        for v in range(BLOCK_VOXELS):
            c0 = state[w, v] & CLASS_MASK
            if c0 != RESIDUAL and c0 != PARTIAL:
                continue
            d = dist[w * BLOCK_VOXELS + v]
            if d < np.inf and d <= reach_vox:
                state[w, v] |= EXTERIOR


# ---- pores ----------------------------------------------------------------------------------

@nb.njit(cache=True, parallel=True)
def _enclosed_members(state):
    n = state.shape[0]
    member = np.zeros((n, BLOCK_VOXELS), np.bool_)
    for w in nb.prange(n):
        for v in range(BLOCK_VOXELS):
            s = state[w, v]
            c = s & CLASS_MASK
            member[w, v] = c != FULL and (s & EXTERIOR) == 0
    return member


@nb.njit(cache=True)
def _number(root, ext_root, nblk, wid, tile_member, comp_off):
    """Void id per node (-1: exterior or not a member), numbered in node order."""
    nx, ny, nz = wid.shape
    flat = wid.reshape(nblk)
    void_of_root = np.full(root.shape[0], -1, np.int64)
    vid = np.full(root.shape[0], -1, np.int64)
    n = 0
    for x in range(root.shape[0]):
        if x == nblk:
            continue
        if x < nblk and (flat[x] != -1 or not tile_member[x]):
            continue
        r = root[x]
        if r == ext_root:
            continue
        if void_of_root[r] < 0:
            void_of_root[r] = n
            n += 1
        vid[x] = void_of_root[r]
    return vid, n


@nb.njit(cache=True, parallel=True)
def _holding(labels, comp_off, vid, nblk):
    """Work blocks holding a voxel of some void."""
    n = labels.shape[0]
    out = np.zeros(n, np.bool_)
    for w in nb.prange(n):
        node0 = nblk + 1 + comp_off[w]
        for v in range(BLOCK_VOXELS):
            la = labels[w, v]
            if la != _NO_LABEL and vid[node0 + la] >= 0:
                out[w] = True
                break
    return out


@nb.njit(cache=True, parallel=True)
def _fractions(blocks, wcoord, g, inv_voxel, band_vox, zp):
    """Empty fractions of the given work blocks' voxels, (m, 512) float64."""
    m = blocks.shape[0]
    out = np.empty((m, BLOCK_VOXELS))
    for i in nb.prange(m):
        s8 = np.empty(BLOCK_VOXELS)
        i8 = np.empty(BLOCK_VOXELS, np.bool_)
        _block_values(blocks[i], wcoord, g, inv_voxel, band_vox, zp, s8, i8, out[i])
    return out


@nb.njit(cache=True)
def _void_stats(wid, wcoord, state, labels, comp_off, vid, n_void, tile_member, blocks, frac):
    """Per void: volume (voxels), weighted index sums, index bbox, voxel count, wide flag.
    Sequential, so sums do not depend on the thread count."""
    nx, ny, nz = wid.shape
    nblk = nx * ny * nz
    base = nblk + 1
    vol = np.zeros(n_void)
    csum = np.zeros((n_void, 3))
    lo = np.full((n_void, 3), np.iinfo(np.int64).max, np.int64)
    hi = np.full((n_void, 3), np.iinfo(np.int64).min, np.int64)
    count = np.zeros(n_void, np.int64)
    wide = np.zeros(n_void, np.bool_)
    for bx in range(nx):
        for by in range(ny):
            for bz in range(nz):
                lin = (bx * ny + by) * nz + bz
                if wid[bx, by, bz] != -1 or not tile_member[lin]:
                    continue
                p = vid[lin]
                if p < 0:
                    continue
                _add_whole_tile(p, bx, by, bz, vol, csum, lo, hi, count, wide)
    for i in range(blocks.shape[0]):
        w = blocks[i]
        node0 = base + comp_off[w]
        for v in range(BLOCK_VOXELS):
            la = labels[w, v]
            if la == _NO_LABEL:
                continue
            p = vid[node0 + la]
            if p < 0:
                continue
            if (state[w, v] & CLASS_MASK) == CENTRE:
                wide[p] = True
            f = frac[i, v]
            if f <= _MIN_PARTIAL:
                continue
            _add_voxel(p, f, wcoord[w], v, vol, csum, lo, hi, count)
    return vol, csum, lo, hi, count, wide


@nb.njit(cache=True)
def _add_whole_tile(p, bx, by, bz, vol, csum, lo, hi, count, wide):
    """Void ``p``'s sums take the whole empty tile at block ``(bx, by, bz)`` (wide: a ball fits)."""
    vol[p] += BLOCK_VOXELS
    count[p] += BLOCK_VOXELS
    wide[p] = True
    csum[p, 0] += BLOCK_VOXELS * (8.0 * bx + 3.5)
    csum[p, 1] += BLOCK_VOXELS * (8.0 * by + 3.5)
    csum[p, 2] += BLOCK_VOXELS * (8.0 * bz + 3.5)
    g = (8 * bx, 8 * by, 8 * bz)
    for q in range(3):
        lo[p, q] = min(lo[p, q], g[q])
        hi[p, q] = max(hi[p, q], g[q] + 7)


@nb.njit(cache=True)
def _add_voxel(p, f, block_coord, v, vol, csum, lo, hi, count):
    """Void ``p``'s sums take voxel ``v`` of the block at ``block_coord``, empty by fraction ``f``."""
    ijk = (8 * np.int64(block_coord[0]) + (v >> 6), 8 * np.int64(block_coord[1]) + ((v >> 3) & 7),
           8 * np.int64(block_coord[2]) + (v & 7))
    vol[p] += f
    count[p] += 1
    for q in range(3):
        csum[p, q] += f * ijk[q]
        lo[p, q] = min(lo[p, q], ijk[q])
        hi[p, q] = max(hi[p, q], ijk[q])


@nb.njit(cache=True, parallel=True)
def _owned(blocks, frac, labels, comp_off, vid, nblk, remap):
    m = blocks.shape[0]
    out_label = np.full((m, BLOCK_VOXELS), -1, np.int32)
    out_frac = np.zeros((m, BLOCK_VOXELS), np.float32)
    for i in nb.prange(m):
        w = blocks[i]
        node0 = nblk + 1 + comp_off[w]
        for v in range(BLOCK_VOXELS):
            la = labels[w, v]
            if la == _NO_LABEL:
                continue
            p = vid[node0 + la]
            if p < 0 or frac[i, v] <= _MIN_PARTIAL or remap[p] < 0:
                continue
            out_label[i, v] = remap[p]
            out_frac[i, v] = frac[i, v]
    return out_label, out_frac


# ---- work blocks ----------------------------------------------------------------------------

def _work_blocks(grid: SparseGrid, zp: float, r_vox: float, band_vox: float):
    """The work-block table (>= 0 work id, -1 a whole tile, <= -2 an inside tile), the work blocks'
    coordinates (leaves first, in leaf order), and per block whether a whole tile is open."""
    block = grid.block
    nx, ny, nz = block.shape
    wid = block.copy()
    outside = block == OUTSIDE
    need = np.zeros(block.shape, bool)
    if r_vox > band_vox - 1e-6 and grid.n_leaf:
        # an outside tile at Chebyshev block distance D from any non-outside block has every
        # voxel at least max(band, 8 (D - 1) + 0.5) voxels from the deposit
        rings = int(math.ceil((r_vox - 0.5) / 8.0))
        solid = ~outside
        grown = solid.copy()
        for _ in range(rings):
            g = grown.copy()
            for axis in range(3):
                for step in (-1, 1):
                    src = [slice(None)] * 3
                    dst = [slice(None)] * 3
                    if step == 1:
                        src[axis], dst[axis] = slice(0, -1), slice(1, None)
                    else:
                        src[axis], dst[axis] = slice(1, None), slice(0, -1)
                    g[tuple(dst)] |= grown[tuple(src)]
            grown = g
        need |= grown & outside
    kz_lo = 8.0 * np.arange(nz)
    hz_lo = kz_lo - zp
    hz_hi = kz_lo + 7 - zp
    below = hz_hi <= _PLATE_EPS  # whole block at or below the plate
    whole_open = hz_lo >= max(r_vox, 0.5)  # whole block clear of the plate
    need |= outside & ~(below | whole_open)[None, None, :]
    extra = np.argwhere(need).astype(np.int32)  # C order: linear block order
    wcoord = np.concatenate([grid.leaf_coord, extra]).astype(np.int32)
    wid[tuple(extra.T)] = grid.n_leaf + np.arange(extra.shape[0], dtype=np.int32)
    tile_open = (outside & ~need & ~below[None, None, :]).reshape(-1)
    return np.ascontiguousarray(wid), np.ascontiguousarray(wcoord), tile_open


def dense_empty_fraction(sdf: np.ndarray, voxel: float, z: np.ndarray | None = None,
                         plate_z: float | None = None) -> np.ndarray:
    """The empty fraction of every cell of a dense SDF array (2 or 3 axes, one voxel apart), as
    the void analysis counts it (module docstring): the planar estimate bounded by the lines to
    the neighbours (in a 2-D array: its two axes); with ``plate_z`` (and ``z``, the world z of the last axis), the plate cuts the
    cells below it, nested with the deposit's face (the deposit lies on it). Beyond the array's
    edges nothing bounds the lines."""
    s = np.asarray(sdf, np.float64) / voxel
    e = np.clip(0.5 + s, 0.0, 1.0)
    d = np.maximum(0.0, -s)
    padded = np.pad(d, 1, constant_values=0.0)

    def beyond(u):
        return np.clip(0.5 - u, 0.0, 1.0)

    for line in _LINES:
        step = line[3 - s.ndim:] if s.ndim < 3 else line
        if s.ndim < 3 and (np.any(line[:3 - s.ndim]) or np.count_nonzero(line) > 1):
            continue  # a 2-D array is a vertical section: only its own axes
        length = float(np.sqrt(np.sum(step**2)))
        d_minus = padded[tuple(slice(1 - k, padded.shape[a] - 1 - k) for a, k in enumerate(step))]
        d_plus = padded[tuple(slice(1 + k, padded.shape[a] - 1 + k) for a, k in enumerate(step))]
        lo_a, lo_b = -(length - d_minus), -d
        up_a, up_b = d, length - d_plus
        bound = (np.where(lo_b > lo_a, beyond(lo_a) - beyond(lo_b), 0.0)
                 + np.where(up_b > up_a, beyond(up_a) - beyond(up_b), 0.0))
        e = np.minimum(e, bound)
    if plate_z is not None and z is not None:
        a_p = np.clip((np.asarray(z, np.float64) - plate_z) / voxel + 0.5, 0.0, 1.0)
        e = np.maximum(0.0, e + a_p - 1.0)
    return e


@nb.njit(cache=True)
def cell_empty(g, i, j, k, inv_voxel):
    """Empty fraction of voxel (i, j, k) of a deposit grid (a :data:`~.sparse.GridView`) as the
    void analysis counts it (module docstring): the planar estimate, bounded by the axis lines
    through the voxel, so a gap thinner than a voxel weighs its own thickness rather than the
    quarter voxel the planar estimate gives any thin sheet. For occupancy sums (the comparison's
    void and overbuild): ``1 - cell_empty`` is the cell's material."""
    s = np.float64(sdf_at(g, i, j, k)) * inv_voxel
    e = min(max(0.5 + s, 0.0), 1.0)
    if e > 0.0 and s < 0.5:
        for m in range(_LINES.shape[0]):
            dx, dy, dz = _LINES[m, 0], _LINES[m, 1], _LINES[m, 2]
            sm = np.float64(sdf_at(g, i - dx, j - dy, k - dz)) * inv_voxel
            sp = np.float64(sdf_at(g, i + dx, j + dy, k + dz)) * inv_voxel
            e = min(e, _line_empty(sm, s, sp, math.sqrt(dx * dx + dy * dy + dz * dz)))
    return e


def lowest_deposit_z(grid: SparseGrid) -> float:
    """World z of the deposit's lowest surface (-inf for an empty grid)."""
    k = _lowest_deposit(grid.leaf_coord, grid.leaf_active, grid.leaf_inside, grid.sdf_offset, grid.sdf,
                        1.0 / grid.voxel)
    return float(grid.origin[2] + k * grid.voxel) if np.isfinite(k) else -math.inf


def speck_floor(voxel: float, channel_mm: float) -> float:
    """Volume (mm^3) below which a void is a speck: the ball of the channel width, at least
    ``SPECK_VOXELS`` voxels."""
    return max(math.pi * channel_mm**3 / 6.0, SPECK_VOXELS * voxel**3)


def enclosed_voids(grid: SparseGrid, plate_z: float | None = None, bead_width: float | None = None, *,
                   exhaustive: bool = False) -> Voids:
    """The enclosed voids of ``grid`` (module docstring): pores and specks with their voxels.

    ``plate_z``: the substrate's top (world mm; None: the lowest deposit; -inf: no substrate).
    ``bead_width``: sets the channel width ``s = CHANNEL_FRACTION * bead_width`` (None: no
    channel rule). ``exhaustive``: the searches visit every voxel instead of only where an
    answer can still change, and the clearance beyond the band is settled everywhere up to its
    limit (the same voids, slower: the reference the tests hold the fast path to).
    """
    v = float(grid.voxel)
    if plate_z is None:
        plate_z = lowest_deposit_z(grid)
    plate_z = float(plate_z)
    zp = (plate_z - grid.origin[2]) / v if np.isfinite(plate_z) else -np.inf
    channel = 0.0 if bead_width is None else CHANNEL_FRACTION * float(bead_width)
    if not (math.isfinite(channel) and channel >= 0):
        raise ValueError(f"bead width must be a non-negative length, got {bead_width!r}")
    r_vox = 0.5 * channel / v
    band_vox = float(np.float32(grid.band)) / v
    # Without a channel width any connection opens a void, however thin (sub-voxel included).
    # The slack matters only at coarse voxels: a partial voxel on an open wall lies up to about
    # s/2 + 1.4 voxels from the nearest exterior centre.
    reach_vox = max(channel / v, 0.5 * channel / v + REACH_SLACK_VOXELS) if channel > 0 else math.inf
    floor = speck_floor(v, channel)

    wid, wcoord, tile_open = _work_blocks(grid, zp, r_vox, band_vox)
    n_work = wcoord.shape[0]
    state = np.empty((n_work, BLOCK_VOXELS), np.uint8)
    dep = np.empty((n_work, BLOCK_VOXELS), np.float32)
    packed = (grid.view(), 1.0 / v, band_vox, zp)
    _classify(wcoord, *packed, r_vox, state, dep)
    if r_vox > band_vox - 1e-6:
        _extend_clearance(wid, wcoord, state, dep, band_vox, r_vox, grid.n_leaf, exhaustive)
    nblk = int(wid.size)

    # exterior centres: components of the ball centres (whole open tiles included) that reach
    # beyond the table
    labels, counts = _label_blocks(state == CENTRE)
    comp_off = np.zeros(n_work + 1, np.int64)
    np.cumsum(counts, out=comp_off[1:])
    root = _connect(wid, tile_open, wcoord, labels, comp_off)
    ext_root = root[nblk]
    _mark_exterior_centres(state, labels, comp_off, root, ext_root, nblk)
    tile_ext = tile_open & (root[:nblk] == ext_root)
    del labels, root

    _reach(wid, wcoord, state, dep, tile_open, tile_ext, zp, r_vox, reach_vox, band_vox, exhaustive)
    del dep

    member = _enclosed_members(state)
    tile_member = tile_open & ~tile_ext
    labels, counts = _label_blocks(member)
    del member
    comp_off = np.zeros(n_work + 1, np.int64)
    np.cumsum(counts, out=comp_off[1:])
    root = _connect(wid, tile_member, wcoord, labels, comp_off)
    vid, n_void = _number(root, root[nblk], nblk, wid, tile_member, comp_off)
    blocks = np.flatnonzero(_holding(labels, comp_off, vid, nblk))
    frac = _fractions(blocks, wcoord, *packed)
    vol, csum, lo, hi, count, wide = _void_stats(wid, wcoord, state, labels, comp_off, vid, n_void, tile_member, blocks,
                                                 frac)
    speck = vol * v**3 < floor
    order, remap = pore_order(vol, lo, speck)
    block_label, block_fraction = _owned(blocks, frac, labels, comp_off, vid, nblk, remap)
    keep_blocks = np.any(block_label >= 0, axis=1)
    blocks, block_label, block_fraction = blocks[keep_blocks], block_label[keep_blocks], block_fraction[keep_blocks]
    tiles = np.flatnonzero(tile_member & (vid[:nblk] >= 0))
    tile_label = remap[vid[tiles]]
    tiles, tile_label = tiles[tile_label >= 0], tile_label[tile_label >= 0]
    return voids_of(grid, plate_z, channel, reach_vox, floor, order, (vol, csum, lo, hi, count, wide, speck),
                    wcoord[blocks], block_label, block_fraction, tiles, tile_label)


def pore_order(vol: np.ndarray, lo: np.ndarray, speck: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """The voids' order (those of positive volume): pores first, then specks; each by descending
    volume, ties by bbox corner (never by node order); and ``remap``, node -> place (-1: none)."""
    order = np.lexsort((lo[:, 2], lo[:, 1], lo[:, 0], -vol, speck))
    order = order[(vol > 0)[order]]
    remap = np.full(vol.size, -1, np.int32)
    remap[order] = np.arange(order.size, dtype=np.int32)
    return order, remap


def voids_of(grid: SparseGrid, plate_z: float, channel: float, reach_vox: float, floor: float, order: np.ndarray,
             stats: tuple, block_coord, block_label, block_fraction, tiles, tile_label) -> Voids:
    """The :class:`Voids` of the sums ``stats`` (:func:`_void_stats`' and the speck flags) in
    ``order``, with the blocks and whole tiles (linear indices) that hold them."""
    vol, csum, lo, hi, count, wide, speck = stats
    v = float(grid.voxel)
    safe = np.where(vol > 0, vol, 1.0)
    return Voids(
        voxel=v, origin=grid.origin.copy(), plate_z=plate_z, channel_mm=channel, reach_mm=reach_vox * v,
        speck_floor_mm3=floor,
        volume_mm3=vol[order] * v**3,
        centroid_mm=grid.index_to_world(csum[order] / safe[order, None]),
        bbox_mm=np.stack([grid.index_to_world(lo[order]) - 0.5 * v, grid.index_to_world(hi[order]) + 0.5 * v], axis=1),
        voxels=count[order], wide=wide[order], speck=speck[order],
        block_coord=np.asarray(block_coord).astype(np.int32), block_label=block_label, block_fraction=block_fraction,
        tile_coord=np.stack(np.unravel_index(tiles, grid.block_shape), -1).astype(np.int32).reshape(-1, 3),
        tile_label=np.asarray(tile_label).astype(np.int32),
    )
