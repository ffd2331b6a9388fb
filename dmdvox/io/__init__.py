"""Readers and writers: every output goes through :func:`atomic_path`."""
