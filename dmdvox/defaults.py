"""Defaults shared by several stages, in one place so that the library, the command line's
help and the documents agree."""

BAND_VOXELS = 3.0  # every grid's narrow band, each side of its surface, in voxels
STANDOFF_MM = 12.7  # nozzle tip above the programmed bead bottom: the seed's experiments
CLEARANCE_MM = 1.0  # the nozzle closer than this to anything is a near miss
SLAB_BLOCKS = 1 << 16  # occupied blocks per slab of a comparison task: a few hundred MB at most
