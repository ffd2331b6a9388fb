"""The shareable report: one self-contained HTML page with every analysis that applies."""
