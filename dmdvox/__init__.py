"""dmdvox: predict what a Directed Energy Deposition toolpath builds."""

__version__ = "0.1.0"
