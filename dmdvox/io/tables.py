"""Tables of rows (dicts) as CSV: floats with every digit (``repr``), so a table read back is
the table written."""

from __future__ import annotations

import csv
import io


def rows_to_csv(rows: list[dict], keys: tuple[str, ...] | list[str]) -> str:
    buffer = io.StringIO()
    writer = csv.DictWriter(buffer, fieldnames=list(keys), lineterminator="\n")
    writer.writeheader()
    for row in rows:
        writer.writerow({k: repr(v) if isinstance(v, float) else v for k, v in row.items()})
    return buffer.getvalue()
