"""SparseGrid layout, GridBuilder, volume, pores and the block tree against closed forms."""

import math

import numba
import numpy as np
import pytest

from dmdvox.grid.analysis import porosity, pores, volume
from dmdvox.grid.build import GridBuilder, split_blocks, grid_from_dense
from dmdvox.grid.sparse import OUTSIDE, SparseGrid
from dmdvox.grid.tree import EMPTY, FULL, PARTIAL, block_tree


def field_grid(n: int, voxel: float, sdf_of_xyz, band_voxels: float = 3.0, centre_offset: float = 0.0,
               arrival_of_xyz=None, meta=None):
    """Grid of an analytic SDF sampled on n^3 voxels centred on the world origin (+ offset)."""
    first = -(n - 1) / 2 + centre_offset / voxel
    # dividing by 1/voxel (an integer here) keeps round coordinates such as 3.0 exact
    ax = (first + np.arange(n)) / (1.0 / voxel)
    origin = np.full(3, ax[0])
    X, Y, Z = np.meshgrid(ax, ax, ax, indexing="ij")
    sdf = sdf_of_xyz(X, Y, Z).astype(np.float32)
    arr_inside = (10.0 + Z) if arrival_of_xyz is None else arrival_of_xyz(X, Y, Z)
    arrival = np.where(sdf < 0, arr_inside, np.inf).astype(np.float32)
    grid = grid_from_dense(sdf, arrival, voxel, origin, band_voxels * voxel, meta=meta)
    return grid, sdf, arrival


def sphere(R, c=(0.0, 0.0, 0.0)):
    return lambda X, Y, Z: np.sqrt((X - c[0]) ** 2 + (Y - c[1]) ** 2 + (Z - c[2]) ** 2) - R


def shell(R, r):
    return lambda X, Y, Z: np.maximum(sphere(R)(X, Y, Z), -sphere(r)(X, Y, Z))


@pytest.fixture(scope="module")
def ball():
    """R = 5 mm sphere at 0.1 mm (128^3 voxels, 16^3 blocks), band 3 voxels."""
    return field_grid(128, 0.1, sphere(5.0))


def popcount_rows(masks):
    return np.unpackbits(masks.view(np.uint8), axis=1).sum(axis=1)


def mask_to_bool(masks):
    """(n, 8) uint64 masks -> (n, 512) bool in local order v (word v >> 6, bit v & 63)."""
    bits = np.unpackbits(masks.view(np.uint8), axis=1, bitorder="little")
    return bits.astype(bool)


def octant_min(blocks):
    """(m, 8, 8, 8) -> (m, 2, 2, 2) minima over each 4^3 octant."""
    return blocks.reshape(-1, 2, 4, 2, 4, 2, 4).min(axis=(2, 4, 6))


def expected_arrival(sdf, arrival, band):
    """What the grid reads back: the voxel's own arrival, except inside voxels at or beyond -band
    (in leaves and tiles alike), which read the minimum arrival over the inside voxels of their
    block's 4^3 octant (``arrival`` is +inf outside, so a plain octant minimum)."""
    octs = octant_min(split_blocks(arrival))
    x, y, z = (n // 8 for n in arrival.shape)
    per_voxel = octs.reshape(x, y, z, 2, 2, 2).transpose(0, 3, 1, 4, 2, 5).reshape(2 * x, 2 * y, 2 * z)
    per_voxel = np.repeat(np.repeat(np.repeat(per_voxel, 4, 0), 4, 1), 4, 2)
    return np.where(sdf <= -band, per_voxel, arrival)


# ---- layout -----------------------------------------------------------------------------------

def test_layout_matches_the_dense_field(ball):
    grid, sdf, arrival = ball
    band = np.float32(grid.band)
    blocks = split_blocks(sdf).reshape(-1, 512)
    barr = split_blocks(arrival).reshape(-1, 512)
    lin = np.ravel_multi_index(grid.leaf_coord.T, grid.block_shape)
    assert np.all(np.diff(lin) > 0), "leaves sorted by linear block index"
    assert np.array_equal(grid.block.reshape(-1)[lin], np.arange(grid.n_leaf))
    dense = blocks[lin]
    assert np.array_equal(mask_to_bool(grid.leaf_active), np.abs(dense) < band)
    assert np.array_equal(mask_to_bool(grid.leaf_inside), dense < 0)
    assert np.array_equal(grid.sdf, dense[np.abs(dense) < band])
    # per-voxel arrival only for the active inside voxels; octant minima over all inside voxels
    fine = (np.abs(dense) < band) & (dense < 0)
    assert np.array_equal(grid.arrival, barr[lin][fine])
    assert np.array_equal(np.diff(grid.sdf_offset), popcount_rows(grid.leaf_active))
    assert np.array_equal(np.diff(grid.arr_offset), popcount_rows(grid.leaf_active & grid.leaf_inside))
    leaf_octs = octant_min(np.where(dense < 0, barr[lin], np.inf).reshape(-1, 8, 8, 8))
    assert np.array_equal(grid.leaf_octant_arrival, leaf_octs)
    assert np.array_equal(grid.leaf_octant_arrival, octant_min(split_blocks(arrival)[lin]))
    no_inside = ~(dense < 0).reshape(-1, 2, 4, 2, 4, 2, 4).any(axis=(2, 4, 6))
    assert no_inside.any() and np.all(np.isinf(grid.leaf_octant_arrival[no_inside]))
    assert np.all(np.isfinite(grid.leaf_octant_arrival[~no_inside]))

    tile_lin = np.ravel_multi_index(grid.tile_coord.T, grid.block_shape)
    assert np.all(np.diff(tile_lin) > 0)
    assert np.array_equal(grid.block.reshape(-1)[tile_lin], -2 - np.arange(grid.n_tile))
    assert np.all(blocks[tile_lin] <= -band)
    assert np.array_equal(grid.tile_arrival, octant_min(split_blocks(arrival)[tile_lin]))
    rest = np.setdiff1d(np.arange(blocks.shape[0]), np.concatenate([lin, tile_lin]))
    assert np.all(blocks[rest] >= band) and np.all(grid.block.reshape(-1)[rest] == OUTSIDE)
    # a leaf for every block the band crosses, a tile for every block wholly deeper than it
    assert grid.n_leaf == np.count_nonzero((np.abs(blocks) < band).any(axis=1))
    assert grid.n_tile == np.count_nonzero((blocks <= -band).all(axis=1))


def test_dense_decoding_and_lookups(ball):
    grid, sdf, arrival = ball
    band = np.float32(grid.band)
    assert np.array_equal(grid.dense_sdf(), np.clip(sdf, -band, band))
    dense_arr = grid.dense_arrival()
    assert np.array_equal(dense_arr, expected_arrival(sdf, arrival, band))
    # active inside voxels keep their exact arrival; outside is +inf
    in_band = (np.abs(sdf) < band) & (sdf < 0)
    assert np.array_equal(dense_arr[in_band], arrival[in_band])
    assert np.all(np.isinf(dense_arr[sdf >= 0]))
    # deeper inside voxels (in leaves and tiles) carry their octant minimum: never later than
    # the true arrival, and earlier for most (arrival = 10 + z varies across an octant)
    deep = sdf <= -band
    in_leaf = np.repeat(np.repeat(np.repeat(grid.block >= 0, 8, 0), 8, 1), 8, 2)
    assert np.all(dense_arr[deep] <= arrival[deep])
    deep_leaf = deep & in_leaf
    assert np.count_nonzero(dense_arr[deep_leaf] < arrival[deep_leaf]) > 0.7 * np.count_nonzero(deep_leaf)

    sub = grid.dense_sdf((3, 4, 5), (9, 10, 18))  # reaches past the table: reads as outside
    assert sub.shape == (48, 48, 104)
    assert np.array_equal(sub[:, :, :88], np.clip(sdf[24:72, 32:80, 40:128], -band, band))
    assert np.all(sub[:, :, 88:] == band)

    leaf = grid.block[8, 8, 2]
    s8, a8 = grid.decode_leaf(leaf)
    box = np.s_[64:72, 64:72, 16:24]
    assert np.array_equal(s8, np.clip(sdf[box], -band, band))
    assert np.array_equal(a8, expected_arrival(sdf[box], arrival[box], band))
    leaf_fine = (np.abs(sdf[box]) < band) & (sdf[box] < 0)
    leaf_deep = sdf[box] <= -band
    assert leaf_fine.any() and leaf_deep.any()  # this leaf has both kinds
    assert np.array_equal(a8[leaf_fine], arrival[box][leaf_fine])
    octs = grid.leaf_octant_arrival[leaf]
    lx, ly, lz = np.nonzero(leaf_deep)
    assert np.array_equal(a8[leaf_deep], octs[lx >> 2, ly >> 2, lz >> 2])
    # the octant minimum is over all inside voxels: 10 + the lowest inside z of the octant
    z_mm = grid.index_to_world(np.array([[0, 0, 16]]))[0, 2]
    assert octs[0, 0, 0] == np.float32(10.0 + z_mm)

    ijk = np.random.default_rng(1).integers(-4, 132, (20000, 3))
    inside_table = np.all((ijk >= 0) & (ijk < 128), axis=1)
    got = grid.value_at_index(ijk)
    assert np.array_equal(got[inside_table], np.clip(sdf, -band, band)[tuple(ijk[inside_table].T)])
    assert np.all(got[~inside_table] == band)
    got_arr = grid.arrival_at_index(ijk)
    assert np.array_equal(got_arr[inside_table], dense_arr[tuple(ijk[inside_table].T)])
    assert np.all(np.isinf(got_arr[~inside_table]))
    # every active inside voxel and every deep inside voxel of a leaf, by rank lookups
    for which in (in_band, deep_leaf):
        pts = np.argwhere(which)
        assert np.array_equal(grid.arrival_at_index(pts), dense_arr[which])


def test_leaf_arrival_fine_in_the_band_octant_minimum_deeper():
    band = np.float32(0.3)
    builder = GridBuilder(0.1, (0, 0, 0), (1, 1, 1), band)
    sdf = np.full((1, 8, 8, 8), 1.0, np.float32)
    sdf[0, :, :, :6] = -0.1  # inside and active
    sdf[0, :, :, :3] = -0.5  # deeper than the band: inactive inside
    arr = np.where(sdf < 0, np.float32(20.0), np.float32(np.inf))
    arr[0, 1, 2, 4] = 3.0  # active inside, in octant (0, 0, 1)
    arr[0, 2, 3, 1] = 7.0  # deep, in octant (0, 0, 0)
    arr[0, 5, 6, 2] = 4.0  # deep, in octant (1, 1, 0)
    arr[0, 6, 1, 5] = 2.0  # active inside, in octant (1, 0, 1), lower than any deep voxel
    arr[0, 6, 1, 2] = np.inf  # deep voxel never reached (as a caller may pass): ignored by the minimum
    builder.add_blocks([[0, 0, 0]], sdf, arr)
    grid = builder.finish()

    assert grid.n_leaf == 1 and grid.active_voxels == 8 * 8 * 3
    assert grid.arrival.size == 8 * 8 * 3  # the active voxels here are all inside
    expect_oct = np.full((2, 2, 2), 20.0, np.float32)
    expect_oct[0, 0, 0] = 7.0
    expect_oct[1, 1, 0] = 4.0
    expect_oct[0, 0, 1] = 3.0
    expect_oct[1, 0, 1] = 2.0
    assert np.array_equal(grid.leaf_octant_arrival[0], expect_oct)
    ijk = np.array([[1, 2, 4], [6, 1, 5], [0, 0, 5], [2, 3, 1], [0, 0, 0], [5, 6, 2], [4, 7, 0], [6, 1, 2],
                    [7, 7, 7], [0, 0, 6]])
    want = np.array([3.0, 2.0, 20.0, 7.0, 7.0, 4.0, 4.0, 20.0, np.inf, np.inf], np.float32)
    assert np.array_equal(grid.arrival_at_index(ijk), want)
    _, a8 = grid.decode_leaf(0)
    assert np.array_equal(a8[tuple(ijk.T)], want)
    assert np.array_equal(grid.dense_arrival(), a8)
    # deep voxels of octant (1, 0, 0) read the octant minimum 20 even where their own arrival was +inf
    assert a8[6, 1, 2] == 20.0
    tree = block_tree(grid)
    assert tree.levels[0].min_arrival[0, 0, 0] == np.float32(2.0)  # a fine value
    # a leaf whose earliest arrival is deep: the tree takes it from the octants
    builder = GridBuilder(0.1, (0, 0, 0), (1, 1, 1), band)
    arr[0, 1, 2, 4] = arr[0, 6, 1, 5] = 20.0
    builder.add_blocks([[0, 0, 0]], sdf, arr)
    assert block_tree(builder.finish()).levels[0].min_arrival[0, 0, 0] == np.float32(4.0)


def test_transform_puts_voxel_centres_on_integer_indices(ball):
    grid, _, _ = ball
    assert np.array_equal(grid.index_to_world([0, 0, 0]), grid.origin)
    assert np.allclose(grid.index_to_world([10, 20, 30]), grid.origin + [1.0, 2.0, 3.0])
    pts = np.random.default_rng(2).uniform(-6, 6, (100, 3))
    assert np.allclose(grid.index_to_world(grid.world_to_index(pts)), pts)
    centre = np.rint(grid.world_to_index([0.0, 0.0, 0.0])).astype(np.int64)
    assert grid.value_at_index(centre[None])[0] == -np.float32(grid.band)


def test_memory_accounting(ball):
    grid, _, _ = ball
    arrays = [grid.origin, grid.block, grid.leaf_coord, grid.leaf_active, grid.leaf_inside, grid.sdf_offset,
              grid.sdf, grid.arr_offset, grid.arrival, grid.leaf_octant_arrival, grid.tile_arrival]
    assert grid.memory_bytes == sum(a.nbytes for a in arrays)
    _, sdf, _ = ball
    band = np.float32(grid.band)
    active = np.count_nonzero(np.abs(sdf) < band)
    active_inside = np.count_nonzero((np.abs(sdf) < band) & (sdf < 0))
    assert grid.active_voxels == grid.sdf.size == active
    assert grid.arrival.size == active_inside
    # The band is the shell |r - 5| < 0.3 mm: 4/3 pi (5.3^3 - 4.7^3) mm^3 of 0.001 mm^3 voxels,
    # its inner half 4/3 pi (5^3 - 4.7^3); counting voxel centres misses by O(voxel / R)^2.
    shell = 4 / 3 * math.pi * (5.3**3 - 4.7**3) / 1e-3
    inner = 4 / 3 * math.pi * (5.0**3 - 4.7**3) / 1e-3
    assert active == pytest.approx(shell, rel=0.005) and active_inside == pytest.approx(inner, rel=0.005)
    assert grid.leaf_octant_arrival.nbytes == 32 * grid.n_leaf
    # The documented layout (grid/sparse.py): 4 B sdf per active voxel, 4 B arrival per active
    # inside voxel, 188 B a leaf (two 64 B masks, 12 B coordinates, 2 x 8 B offsets, 32 B
    # octants), 32 B an inside tile, 4 B a block of the table; the offsets' closing entries
    # (2 x 8 B) and the origin (24 B).
    expected = (4 * active + 4 * active_inside + 188 * grid.n_leaf + 32 * grid.n_tile
                + 4 * grid.block.size + 16 + 24)
    assert grid.memory_bytes == expected
    # goal: at most 8 B per active voxel, arrival included
    assert grid.memory_bytes / grid.active_voxels <= 8.0
    wide, _, _ = field_grid(128, 0.1, sphere(5.0), band_voxels=5.0)
    assert wide.memory_bytes / wide.active_voxels <= 7.0


# ---- builder ------------------------------------------------------------------------------------

def assert_same_grid(a: SparseGrid, b: SparseGrid):
    for name in ("block", "leaf_coord", "leaf_active", "leaf_inside", "sdf_offset", "sdf", "arr_offset",
                 "arrival", "leaf_octant_arrival", "tile_coord", "tile_arrival", "origin"):
        assert np.array_equal(getattr(a, name), getattr(b, name)), name
    assert (a.voxel, a.band) == (b.voxel, b.band)


def test_builder_is_independent_of_batch_order_and_threads(ball):
    grid, sdf, arrival = ball
    coords = np.argwhere(np.ones(grid.block_shape, bool)).astype(np.int32)
    s_blocks, a_blocks = split_blocks(sdf), split_blocks(arrival)
    perm = np.random.default_rng(3).permutation(coords.shape[0])
    threads = numba.get_num_threads()
    numba.set_num_threads(1)
    try:
        builder = GridBuilder(grid.voxel, grid.origin, grid.block_shape, grid.band)
        for part in np.array_split(perm, 7):
            builder.add_blocks(coords[part], s_blocks[part], a_blocks[part])
        shuffled = builder.finish()
    finally:
        numba.set_num_threads(threads)
    assert_same_grid(grid, shuffled)


@pytest.mark.parametrize("bx0, bx1", [(0, 16), (0, 1), (3, 9), (7, 8), (15, 16)])
def test_crop_is_the_slab_of_the_grid(bx0, bx1):
    """A slab handed to a task: the same values and arrivals as the whole grid's blocks there,
    on the lattice moved to its first block; the whole range is the grid itself."""
    grid, _, _ = field_grid(128, 0.1, shell(5.5, 3.0), arrival_of_xyz=lambda X, Y, Z: 100.0 + 3 * X + Z)
    assert grid.n_tile > 0 and grid.n_leaf > 0  # the shell has both: tiles inside its wall
    crop = grid.crop_x(bx0, bx1)
    lo, hi = (bx0, 0, 0), (bx1, *grid.block_shape[1:])
    assert np.array_equal(crop.dense_sdf(), grid.dense_sdf(lo, hi))
    assert np.array_equal(crop.dense_arrival(), grid.dense_arrival(lo, hi))
    assert np.array_equal(crop.index_to_world(np.zeros((1, 3))), grid.index_to_world(np.array([[8.0 * bx0, 0, 0]])))
    if (bx0, bx1) == (0, 16):
        assert_same_grid(crop, grid)


def test_builder_rejects_bad_blocks():
    builder = GridBuilder(0.1, (0, 0, 0), (2, 2, 2), 0.3)
    far = np.full((1, 8, 8, 8), 1.0, np.float32)
    builder.add_blocks([[0, 0, 0]], far, far)
    with pytest.raises(ValueError, match="twice"):
        builder.add_blocks([[0, 0, 0]], far, far)  # an outside block is remembered too
    with pytest.raises(ValueError, match="twice"):
        builder.add_blocks([[1, 1, 1], [1, 1, 1]], np.repeat(far, 2, 0), np.repeat(far, 2, 0))
    with pytest.raises(ValueError, match="outside the table"):
        builder.add_blocks([[2, 0, 0]], far, far)
    with pytest.raises(ValueError, match="non-finite"):
        builder.add_blocks([[0, 1, 0]], np.full((1, 8, 8, 8), np.nan, np.float32), far)
    with pytest.raises(ValueError, match="3 voxels"):
        GridBuilder(0.1, (0, 0, 0), (2, 2, 2), 0.2)
    empty = GridBuilder(0.1, (0, 0, 0), (2, 2, 2), 0.3).finish()
    assert empty.n_leaf == empty.n_tile == 0 and np.all(empty.block == OUTSIDE)
    assert volume(empty) == 0.0 and pores(empty) == []


# ---- volume ---------------------------------------------------------------------------------------

def test_volume_of_a_sphere(ball):
    grid, _, _ = ball
    assert volume(grid) == pytest.approx(4 / 3 * math.pi * 125, rel=3e-3)


def test_volume_of_a_grid_aligned_box():
    # faces at x = +-3.0, y = +-2.0, z = +-1.5 pass through voxel centres (origin on the lattice)
    half = np.array([3.0, 2.0, 1.5])

    def box(X, Y, Z):
        q = np.stack([np.abs(X), np.abs(Y), np.abs(Z)], -1) - half
        return np.linalg.norm(np.maximum(q, 0), axis=-1) + np.minimum(q.max(-1), 0)

    grid, sdf, _ = field_grid(80, 0.1, box, centre_offset=0.05)
    assert np.any(sdf == 0)
    assert volume(grid) == pytest.approx(np.prod(2 * half), rel=3e-3)
    # exactly: lattice points strictly inside count 1, points on the faces 0.5 (faces are exact;
    # the 0.13 mm^3 excess is edges and corners, whose cells are 1/4 and 1/8 full, not 1/2)
    closed = np.prod(2 * half / 0.1 + 1)
    interior = np.prod(2 * half / 0.1 - 1)
    assert volume(grid) == pytest.approx((interior + 0.5 * (closed - interior)) * 1e-3, rel=1e-12)


# ---- pores ----------------------------------------------------------------------------------------

def test_hollow_sphere_has_one_pore_with_consistent_volume():
    grid, _, _ = field_grid(136, 0.1, shell(6.0, 3.0))
    result = porosity(grid)
    assert len(result.pores) == 1
    pore = result.pores[0]
    assert pore.volume_mm3 == pytest.approx(4 / 3 * math.pi * 27, rel=0.02)
    assert np.allclose(pore.centroid_mm, 0.0, atol=1e-9)
    assert np.allclose(pore.bbox_mm, [[-3.05] * 3, [3.05] * 3], atol=0.051)
    assert pore.equivalent_diameter_mm == pytest.approx((6 * pore.volume_mm3 / math.pi) ** (1 / 3))
    # deposit + pore volume = the same sphere without its cavity, voxel by voxel fractions
    solid, _, _ = field_grid(136, 0.1, sphere(6.0))
    assert result.deposit_volume_mm3 == volume(grid)
    assert result.deposit_volume_mm3 + pore.volume_mm3 == pytest.approx(volume(solid), rel=1e-12)
    assert result.porosity_percent == pytest.approx(100 * pore.volume_mm3 / volume(solid), rel=1e-12)


def test_shell_open_to_the_outside_has_no_pore():
    def opened(X, Y, Z):
        hole = np.where(Z > 0, np.sqrt(X**2 + Y**2) - 1.0, np.inf)  # a 2 mm drill through the top
        return np.maximum(shell(6.0, 3.0)(X, Y, Z), -hole)

    grid, _, _ = field_grid(136, 0.1, opened)
    result = porosity(grid)
    assert result.pores == () and result.porosity_percent == 0.0


def test_two_cavities_sorted_by_volume():
    def two(X, Y, Z):
        body = sphere(6.0)(X, Y, Z)
        return np.maximum(body, np.maximum(-sphere(1.5, (-2.5, 0, 0))(X, Y, Z), -sphere(2.0, (2.5, 0.3, 0))(X, Y, Z)))

    grid, _, _ = field_grid(136, 0.1, two)
    found = pores(grid)
    assert len(found) == 2
    big, small = found
    assert big.volume_mm3 == pytest.approx(4 / 3 * math.pi * 8.0, rel=0.02)
    assert small.volume_mm3 == pytest.approx(4 / 3 * math.pi * 3.375, rel=0.02)
    assert np.allclose(big.centroid_mm, [2.5, 0.3, 0.0], atol=0.01)
    assert np.allclose(small.centroid_mm, [-2.5, 0.0, 0.0], atol=0.01)


def test_pore_walls_are_cut_from_the_deposit_surface():
    """Two spherical cavities in a ball: the surface triangles that wall a pore lie on that
    pore's sphere (to a voxel's rounding), carry its number (the larger first) and add up to the
    sphere's area; the ball's outer surface walls nothing."""
    from dmdvox.grid.enclosure import void_walls
    from dmdvox.grid.surface import surface_mesh

    def two(X, Y, Z):
        body = sphere(6.0)(X, Y, Z)
        return np.maximum(body, np.maximum(-sphere(1.5, (-2.5, 0, 0))(X, Y, Z), -sphere(2.0, (2.5, 0.3, 0))(X, Y, Z)))

    grid, _, _ = field_grid(136, 0.1, two)
    vertices, triangles = surface_mesh(grid)
    walls, owner = void_walls(porosity(grid).voids, vertices, triangles)
    corners = vertices[triangles[walls]]
    centre = corners.mean(axis=1)
    area = 0.5 * np.linalg.norm(np.cross(corners[:, 1] - corners[:, 0], corners[:, 2] - corners[:, 0]), axis=1)
    for number, (c, r) in enumerate((((2.5, 0.3, 0.0), 2.0), ((-2.5, 0.0, 0.0), 1.5))):
        mine = owner == number
        assert np.allclose(np.linalg.norm(centre[mine] - c, axis=1), r, atol=0.02)
        assert area[mine].sum() == pytest.approx(4 * math.pi * r**2, rel=0.01)
    assert set(owner) == {0, 1}
    outer = np.linalg.norm(vertices[triangles].mean(axis=1), axis=1) > 5.5
    assert outer.any() and not np.isin(np.flatnonzero(outer), walls).any()


def test_large_cavity_with_outside_tiles_inside_the_part():
    grid, _, _ = field_grid(72, 0.2, shell(6.5, 5.0))
    centres = grid.index_to_world(np.argwhere(np.ones(grid.block_shape, bool)) * 8 + 3.5)
    deep_in_cavity = np.linalg.norm(centres, axis=1) < 5.0 - 0.6 - 0.8 * math.sqrt(3)
    assert deep_in_cavity.sum() >= 8
    assert np.all(grid.block.reshape(-1)[deep_in_cavity] == OUTSIDE)
    found = pores(grid)
    assert len(found) == 1
    assert found[0].volume_mm3 == pytest.approx(4 / 3 * math.pi * 125, rel=0.02)
    assert np.allclose(found[0].centroid_mm, 0.0, atol=1e-9)


def test_pores_do_not_depend_on_thread_count():
    grid, _, _ = field_grid(136, 0.1, shell(6.0, 3.0))
    threads = numba.get_num_threads()
    numba.set_num_threads(1)
    try:
        one = porosity(grid)
    finally:
        numba.set_num_threads(threads)
    many = porosity(grid)
    assert one.pore_volume_mm3 == many.pore_volume_mm3
    assert np.array_equal(one.pores[0].centroid_mm, many.pores[0].centroid_mm)


# ---- block tree -----------------------------------------------------------------------------------

def test_block_tree_levels_on_a_synthetic_table():
    band = np.float32(0.3)
    builder = GridBuilder(0.1, (0, 0, 0), (3, 3, 3), band)
    solid = np.argwhere(np.ones((2, 2, 2), bool)).astype(np.int32)
    arr_solid = np.broadcast_to(np.arange(8, dtype=np.float32)[:, None, None, None] + 5, (8, 8, 8, 8))
    builder.add_blocks(solid, np.full((8, 8, 8, 8), -1.0, np.float32), arr_solid)
    leaf_sdf = np.full((1, 8, 8, 8), 1.0, np.float32)
    leaf_sdf[0, :4] = -0.05
    leaf_arr = np.where(leaf_sdf < 0, np.float32(2.5), np.float32(np.inf))
    leaf_arr[0, 3, 3, 3] = 1.25
    builder.add_blocks([[2, 2, 2]], leaf_sdf, leaf_arr)
    tree = block_tree(builder.finish())

    assert [lv.occupancy.shape for lv in tree.levels] == [(3, 3, 3), (2, 2, 2), (1, 1, 1)]
    l0, l1, root = tree.levels
    assert np.array_equal(l0.occupancy[:2, :2, :2], np.full((2, 2, 2), FULL))
    assert l0.occupancy[2, 2, 2] == PARTIAL and l0.min_arrival[2, 2, 2] == np.float32(1.25)
    assert (l0.occupancy == EMPTY).sum() == 27 - 9 and np.isinf(l0.min_arrival[0, 0, 2])
    assert np.array_equal(l0.min_arrival[:2, :2, :2].reshape(-1), np.arange(8, dtype=np.float32) + 5)
    expect = np.full((2, 2, 2), EMPTY)
    expect[0, 0, 0] = FULL
    expect[1, 1, 1] = PARTIAL  # a leaf plus padding beyond the table
    assert np.array_equal(l1.occupancy, expect)
    assert l1.min_arrival[0, 0, 0] == 5 and l1.min_arrival[1, 1, 1] == np.float32(1.25)
    assert np.isinf(l1.min_arrival[0, 1, 0])
    assert root.occupancy[0, 0, 0] == PARTIAL and root.min_arrival[0, 0, 0] == np.float32(1.25)
    lo, hi = tree.node_bounds(1, np.array([[1, 1, 1]]))
    assert np.allclose(lo, 1.6 - 0.05) and np.allclose(hi, 3.2 - 0.05)


def test_block_tree_of_a_sphere(ball):
    grid, _, arrival = ball
    tree = block_tree(grid)
    assert tree.levels[-1].occupancy.shape == (1, 1, 1)
    assert len(tree.levels) == 5  # 16 -> 8 -> 4 -> 2 -> 1
    assert tree.levels[-1].min_arrival[0, 0, 0] == arrival.min()
    per_block = split_blocks(arrival).reshape(grid.block_shape + (512,)).min(axis=-1)
    leaves = grid.block >= 0
    assert np.array_equal(tree.levels[0].min_arrival[leaves], per_block[leaves])
    for fine, coarse in zip(tree.levels[:-1], tree.levels[1:]):
        assert fine.min_arrival.min() == coarse.min_arrival.min()
        assert (fine.occupancy == FULL).sum() >= 8 * (coarse.occupancy == FULL).sum()


def test_a_static_part_is_the_grid_its_dense_box_gives():
    """GridBuilder.add_static (the CAD and fixture path: values in voxels, arrival 0 inside)
    against add_dense on the scaled box and its arrival: leaves, inside tiles and outside
    blocks, at an offset in a larger table."""
    voxel, band = 0.1, 0.3
    n = 48
    ax = np.arange(n) * voxel
    X, Y, Z = np.meshgrid(ax, ax, ax, indexing="ij")
    in_voxels = ((np.sqrt((X - 2.4) ** 2 + (Y - 2.4) ** 2 + (Z - 2.0) ** 2) - 1.7) / voxel).astype(np.float32)
    in_voxels[0, 0, 0] = -30.0  # a lone inside voxel deep in a corner block
    lo = (1, 2, 0)
    table = (8, 9, 7)
    static = GridBuilder(voxel, np.zeros(3), table, band)
    static.add_static(in_voxels, voxel, lo)
    scaled = in_voxels * np.float32(voxel)
    dense = GridBuilder(voxel, np.zeros(3), table, band)
    dense.add_dense(scaled, np.where(scaled < 0, np.float32(0.0), np.float32(np.inf)), lo)
    a, b = static.finish(), dense.finish()
    assert a.n_leaf > 0 and a.n_tile > 0 and np.count_nonzero(a.block == OUTSIDE) > np.prod(table) - 6**3
    for name in ("block", "leaf_coord", "leaf_active", "leaf_inside", "sdf_offset", "sdf", "arr_offset", "arrival",
                 "leaf_octant_arrival", "tile_arrival"):
        np.testing.assert_array_equal(getattr(a, name), getattr(b, name), err_msg=name)
    bad = in_voxels.copy()
    bad[5, 5, 5] = np.nan
    with pytest.raises(ValueError, match="non-finite"):
        GridBuilder(voxel, np.zeros(3), table, band).add_static(bad, voxel, lo)
