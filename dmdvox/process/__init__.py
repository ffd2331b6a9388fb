"""What the machine really does with the program: planned motion, material, landing.

Floors: this package sits above ``toolpath`` and below ``grid``/``deposit``; it reads a
:class:`~dmdvox.toolpath.model.Toolpath` and hands the deposit engine the beads to sweep.
"""
