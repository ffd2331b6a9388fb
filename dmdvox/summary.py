"""What every command's result shares: its summary is the object ``--json`` prints."""

from __future__ import annotations

import json


class SummaryResult:
    """A result holding ``summary``, the JSON object of its command: read as ``result[key]``,
    ``key in result``, and ``to_json()`` (a plain copy, as it would be printed)."""

    def __getitem__(self, key: str):
        return self.summary[key]

    def __contains__(self, key: str) -> bool:
        return key in self.summary

    def to_json(self) -> dict:
        return json.loads(json.dumps(self.summary))
