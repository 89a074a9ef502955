"""Small delimited-text reader that remembers line numbers (for one-line errors)."""
from __future__ import annotations

import csv
import io
import os

import numpy as np

from kinefuse.host.readers.recording import ReaderError


class Table:
    """Header cells, data rows (lists of str) and the 1-based file line of each row."""

    def __init__(self, path: str, header: list[str], rows: list[list[str]], lines: list[int],
                 sep: str, preamble: list[str], decimal: str = "."):
        self.path, self.header, self.rows = path, header, rows
        self.lines = np.asarray(lines, dtype=int)
        self.sep, self.preamble, self.decimal = sep, preamble, decimal

    def col(self, name: str, *, start: int = 0) -> int:
        """Index of the first column named ``name`` (case-insensitive) at or after ``start``."""
        low = [h.strip().lower() for h in self.header]
        try:
            return low.index(name.lower(), start)
        except ValueError:
            raise ReaderError(self.path, f"missing column {name!r}", 1 + len(self.preamble)) from None

    def has(self, name: str) -> bool:
        return name.lower() in [h.strip().lower() for h in self.header]

    def numeric(self, idx: list[int], *, allow_empty: bool = False, sentinel: float | None = None,
                names: list[str] | None = None) -> np.ndarray:
        """Columns ``idx`` as float (N×k); blank cells → NaN only if ``allow_empty``."""
        out = np.empty((len(self.rows), len(idx)))
        for c, j in enumerate(idx):
            cells = [row[j].strip() if j < len(row) else "" for row in self.rows]
            if self.decimal == ",":
                cells = [x.replace(",", ".") for x in cells]
            if allow_empty:
                cells = [x if x else "nan" for x in cells]
            try:
                col = np.array(cells, dtype=float)       # fast path
            except ValueError:
                col = self._locate_bad(cells, j, c, names)
            if sentinel is not None:
                col[col == sentinel] = np.nan
            out[:, c] = col
        return out

    def empty(self, idx: list[int]) -> np.ndarray:
        """N×k: True where the cell of column ``idx[c]`` is blank (or the row ends before it)."""
        return np.array([[not (row[j].strip() if j < len(row) else "") for j in idx]
                         for row in self.rows], dtype=bool).reshape(len(self.rows), len(idx))

    def _locate_bad(self, cells, j, c, names):
        nm = names[c] if names else self.header[j]
        for cell, ln in zip(cells, self.lines):
            if cell == "":
                raise ReaderError(self.path, f"column {nm!r} is empty", int(ln))
            try:
                float(cell)
            except ValueError:
                raise ReaderError(self.path, f"column {nm!r}: {cell!r} is not a number", int(ln)) from None
        raise AssertionError("unreachable")


def sniff_sep(sample_lines: list[str]) -> str:
    """The delimiter (',', ';' or tab) present the most times on every non-empty line."""
    lines = [l for l in sample_lines if l.strip()]
    counts = {s: min((l.count(s) for l in lines), default=0) for s in (",", ";", "\t")}
    best = max(counts, key=counts.get)
    return best if counts[best] > 0 else ","


def read(path: str, *, header_pred=None, max_preamble: int = 20, has_header: bool = True,
         sep: str | None = None) -> Table:
    """Read a delimited file; the header is the first line satisfying ``header_pred(cells)``."""
    if not os.path.exists(path):
        raise ReaderError(path, "file not found")
    if os.path.isdir(path):
        raise ReaderError(path, "is a directory; give one recording file")
    try:
        try:
            with open(path, encoding="utf-8-sig", newline="") as f:
                text = f.read()
        except UnicodeDecodeError:
            with open(path, encoding="latin-1", newline="") as f:
                text = f.read()
    except OSError as exc:
        raise ReaderError(path, f"cannot open ({exc.strerror or exc})") from None
    all_lines = text.splitlines()
    if not any(l.strip() for l in all_lines):
        raise ReaderError(path, "file is empty")
    probe = [l for l in all_lines[: max_preamble + 20] if l.strip()]
    sep = sep or sniff_sep(probe[-min(len(probe), 10):])
    # newline=None: a line may end in \r\n, \n or a lone \r (Excel's "CSV (Macintosh)"), as
    # for splitlines; csv.reader and splitlines agree on line count without quoted newlines
    reader = csv.reader(io.StringIO(text, newline=None), delimiter=sep)
    try:
        rows_all = list(reader)
    except csv.Error as exc:
        raise ReaderError(path, f"not a readable table ({exc})", reader.line_num) from None
    preamble: list[str] = []
    start = 0
    header: list[str] = []
    if has_header:
        for i, cells in enumerate(rows_all[: max_preamble + 1]):
            if not any(c.strip() for c in cells):
                preamble.append("")
                continue
            if header_pred is None or header_pred([c.strip() for c in cells]):
                header = [c.strip() for c in cells]
                start = i + 1
                break
            preamble.append(sep.join(cells))
        else:
            raise ReaderError(path, "no recognisable header line in the first "
                                    f"{max_preamble + 1} lines")
    rows, lines = [], []
    for i in range(start, len(rows_all)):
        cells = rows_all[i]
        if not any(c.strip() for c in cells):
            continue
        rows.append(cells)
        lines.append(i + 1)
    if not rows:
        raise ReaderError(path, "no data rows")
    decimal = "."
    if sep == ";" and any("," in c for c in rows[0]):
        decimal = ","
    return Table(path, header, rows, lines, sep, preamble, decimal)
