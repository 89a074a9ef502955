"""Shared fixtures of the host tests."""
from __future__ import annotations

import pytest

from kinefuse.host import cli


@pytest.fixture
def run(request, monkeypatch, capsys):
    """``run(*argv) -> (exit code, stdout, stderr)`` of ``kinefuse`` in-process.

    A test module that defines ``MINE`` (command module names, e.g. ``("replay_cmd",)``) gets
    only those commands registered, and of the ``bench`` modules only those ending in one of
    ``MINE_BENCH`` (none by default): a module being edited elsewhere cannot break the test's
    command line.  Without ``MINE`` every command is there."""
    mine = getattr(request.module, "MINE", None)
    if mine is not None:
        monkeypatch.setattr(cli, "COMMAND_MODULES",
                            [m for m in cli.COMMAND_MODULES if m.rsplit(".", 1)[-1] in mine])
        bench = tuple(getattr(request.module, "MINE_BENCH", ()))
        monkeypatch.setattr(cli, "BENCH_MODULES",
                            [m for m in cli.BENCH_MODULES if bench and m.endswith(bench)])

    def _run(*argv):
        code = cli.main([str(a) for a in argv])
        out, err = capsys.readouterr()
        return code, out, err
    return _run
