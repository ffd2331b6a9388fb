"""Defaults shared by several stages, in one place so that the library, the command line's
help and the documents agree."""

BAND_VOXELS = 3.0  # every grid's narrow band, each side of its surface, in voxels
STANDOFF_MM = 12.7  # nozzle tip above the programmed bead bottom: the seed's experiments
CLEARANCE_MM = 1.0  # the nozzle closer than this to anything is a near miss
SLAB_BLOCKS = 1 << 16  # occupied blocks per slab of a comparison task: a few hundred MB at most
CACHE_MAX_BYTES = 4 << 30  # the deposit cache's folder (deposit/cache.py): about 16 solid 100 mm blocks at 0.1 mm
CACHE_MIN_ACTIVE_VOXELS = 1_000_000  # smaller deposits sweep about as fast as they load
