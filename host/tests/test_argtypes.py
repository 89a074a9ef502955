"""Numeric options are checked by argparse before any work: one line, exit 2, no traceback."""
from __future__ import annotations

import pytest

from kinefuse.host import cli


@pytest.mark.parametrize("argv, text", [
    # each of these was an internal error (a ValueError or IndexError from inside the bench)
    (["bench", "seed001", "--seed", "-1"], "argument --seed: -1 is less than 0"),
    (["bench", "decode", "--seed", "-1"], "argument --seed: -1 is less than 0"),
    (["bench", "dynamics", "--seed", "-1"], "argument --seed: -1 is less than 0"),
    (["bench", "seed004", "--seed", "-1"], "argument --seed: -1 is less than 0"),
    (["bench", "calibration", "--runs", "0"], "argument --runs: 0 is not 1 .. 10000"),
    (["bench", "joint-angles", "--runs", "0"], "argument --runs: 0 is not 1 .. 10000"),
    (["bench", "joint-angles", "--misalign", "nan"], "argument --misalign: nan is not in [0, 90]"),
    # silently taken as 1
    (["bench", "cost", "--jobs", "0"], "argument --jobs: 0 is not 1 .. 256"),
    (["bench", "bitexact", "--jobs", "0"], "argument --jobs: 0 is not 1 .. 256"),
    (["bench", "joint-angles", "--runs", "two"], "argument --runs: 'two' is not a whole number"),
    (["bench", "joint-angles", "--posture", "x"], "argument --posture: 'x' is not a number"),
    (["sil", "report", "--seed", "-3"], "argument --seed: -3 is less than 0"),
    (["sim", "run", "rest", "--seed", "-3"], "argument --seed: -3 is less than 0"),
])
def test_bad_numeric_options_are_one_line_usage_errors(capsys, argv, text):
    with pytest.raises(SystemExit) as exc:
        cli.main(argv)
    out, err = capsys.readouterr()
    assert exc.value.code == 2 and out == "" and err.strip() == f"kinefuse: error: {text}", err
