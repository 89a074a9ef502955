"""The application's parser and parameter handler under ASan + UBSan, on a generated corpus of
real frames (valid and invalid PARAM_SETs, reads, commands, HIL samples, damaged frames) with
a power cut at a random storage write.  The fuzz target's invariants (every parameter in range
while running and after the restart; restored values never invented) abort on violation.
The coverage-guided run is a separate bounded job: ``python -m kinefuse.hil_tests.fuzz``."""
from __future__ import annotations

import re
import shutil

import pytest

pytest.importorskip("kinefuse.firmware.build")

from kinefuse.hil_tests import fuzz  # noqa: E402

pytestmark = pytest.mark.skipif(shutil.which("gcc") is None, reason="host gcc not installed")
FILTERS = ["madgwick", "vac"]      # a smaller application builds faster under the sanitizers


def test_seed_corpus_under_sanitizers(tmp_path):
    paths = fuzz.seed_corpus(tmp_path / "seeds", n=40, seed=3)
    res = fuzz.replay(paths, filters=FILTERS)
    assert res.returncode == 0, res.stderr[-3000:]
    m = re.search(r"(\d+) inputs replayed; (\d+) changed parameters, (\d+) restarted", res.stdout)
    assert m, res.stdout
    n, changed, restored = map(int, m.groups())
    assert n == 40
    # the corpus has teeth: parameter writes were accepted, and some survived the power cut
    assert changed >= 5 and restored >= 1, res.stdout


def test_replay_reports_an_unreadable_input(tmp_path):
    res = fuzz.replay([tmp_path / "missing"], filters=FILTERS)
    assert res.returncode == 2 and "cannot open" in res.stderr


@pytest.mark.skipif(shutil.which("clang") is None, reason="clang not installed (apt-get install clang libclang-rt-14-dev)")
def test_libfuzzer_bounded_run(tmp_path, capfd):
    """The coverage-guided job itself, bounded to 30 s (CI installs clang): no crash, no
    ASan/UBSan aborts or invariant violation, and the fuzzer really explored (thousands of runs,
    new coverage beyond the seed corpus)."""
    corpus = tmp_path / "corpus"
    fuzz.seed_corpus(corpus, n=40, seed=5)
    rc = fuzz.fuzz(30, corpus=corpus, work=tmp_path)
    err = capfd.readouterr().err
    crashes = sorted(p.name for p in tmp_path.glob("crash-*"))
    assert rc == 0 and not crashes, (crashes, err[-3000:])
    stats = dict(re.findall(r"stat::(\w+):\s+(\d+)", err))
    assert int(stats["number_of_executed_units"]) > 2000, stats
    assert int(stats["new_units_added"]) > 0, stats
