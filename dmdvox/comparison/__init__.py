"""Deposit vs CAD."""
