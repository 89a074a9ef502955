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
        head = self.header[j].strip().lower() if j < len(self.header) else None
        for cell, ln in zip(cells, self.lines):
            if head and cell.lower() == head:   # two exports joined into one file
                raise ReaderError(self.path, "the header line repeats here (files joined into one?): "
                                             "give each recording as its own file", int(ln))
            if cell == "":
                raise ReaderError(self.path, f"column {nm!r} is empty", int(ln))
            try:
                float(cell)
            except ValueError:
                raise ReaderError(self.path, f"column {nm!r}: {cell!r} is not a number", int(ln)) from None
        raise AssertionError("unreachable")


def sniff_sep(sample_lines: list[str]) -> str:
    """The delimiter: ';' or tab when one is on every non-empty line (the one present more
    often), else ','."""
    lines = [l for l in sample_lines if l.strip()]
    counts = {s: min((l.count(s) for l in lines), default=0) for s in (",", ";", "\t")}
    # ';' or a tab on every line is the separator: with a decimal comma in every cell the
    # commas outnumber it by one, and "," was taken (a ';' kinefuse CSV read as one column)
    alt = max((";", "\t"), key=counts.get)
    if counts[alt] > 0:
        return alt
    return ","


def read(path: str, *, header_pred=None, max_preamble: int = 20, has_header: bool = True,
         sep: str | None = None) -> Table:
    """Read a delimited file; the header is the first line satisfying ``header_pred(cells)``."""
    if not os.path.exists(path):
        raise ReaderError(path, "file not found")
    if os.path.isdir(path):
        raise ReaderError(path, "is a directory; give one recording file")
    try:
        text = read_text(path)
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
    # a decimal comma (Excel in a comma-decimal locale) goes with ';' or a tab: judged over
    # the first rows (a first row of whole numbers read "0,5" below it as not a number) and
    # for tab-separated files too (refused as "'-0,0015' is not a number")
    if sep != "," and any("," in c for row in rows[:50] for c in row):
        decimal = ","
    return Table(path, header, rows, lines, sep, preamble, decimal)


def read_text(path: str) -> str:
    """The file's text: UTF-16 with its BOM (Excel's "Unicode Text" export; was an unknown
    format), UTF-8 with or without BOM, else Latin-1."""
    with open(path, "rb") as f:
        raw = f.read()
    if raw[:2] in (b"\xff\xfe", b"\xfe\xff"):
        try:
            return raw.decode("utf-16")
        except UnicodeDecodeError:
            pass
    try:
        return raw.decode("utf-8-sig")
    except UnicodeDecodeError:
        return raw.decode("latin-1")
