"""Bead deposition geometry: cross-section profiles and the 3-D bead solids built from them."""
