"""Tables are printed whole: widened only as far as needed, never cut."""
from __future__ import annotations

import io

from rich.console import Console
from rich.table import Table

from kinefuse.host.console import fitting_width, print_table


def _figures() -> Table:
    t = Table()
    for c in ("impl", "filter", "format", "target", "instr/update", "flash", "goal"):
        t.add_column(c)
    t.add_row("kinefuse", "flagship", "f32", "m4f", "1,939.0", "10752", "≤400 MISSED")
    return t


def _out(width: int, table) -> str:
    con = Console(file=io.StringIO(), width=width, color_system=None)
    print_table(table, con)
    return con.file.getvalue()


def test_numbers_are_not_cut_on_a_narrow_console():
    plain = Console(file=io.StringIO(), width=40, color_system=None)
    plain.print(_figures())
    assert "…" in plain.file.getvalue()          # what rich alone does at 40 columns
    out = _out(40, _figures())
    assert "…" not in out
    for cell in ("kinefuse", "flagship", "1,939.0", "10752", "MISSED"):
        assert cell in out


def test_width_is_the_narrowest_uncut_one_and_the_console_is_restored():
    w = fitting_width(_figures(), 40)
    assert w > 40
    for narrower in (w - 1, w - 5):
        c = Console(file=io.StringIO(), width=narrower, color_system=None)
        c.print(_figures())
        assert "…" in c.file.getvalue()
    con = Console(file=io.StringIO(), width=40, color_system=None)
    print_table(_figures(), con)
    assert con.width == 40


def test_wrapping_text_keeps_the_width():
    t = Table()
    t.add_column("parameter")
    t.add_column("meaning")
    t.add_row("beta", "gradient-descent gain (Madgwick's beta = sqrt(3/4) * gyroscope error) " * 3)
    assert fitting_width(t, 60) == 60
    out = _out(60, t)
    assert max(len(line) for line in out.splitlines()) <= 60 and "…" not in out


def test_an_ellipsis_in_a_cell_is_not_taken_for_a_cut():
    t = Table("what")
    t.add_row("waiting…")
    assert fitting_width(t, 30) == 30
