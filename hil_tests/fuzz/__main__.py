"""``python -m kinefuse.hil_tests.fuzz --seconds N``: bounded libFuzzer run of the application's
parser and parameter handler (see the package docstring)."""
from __future__ import annotations

import argparse
import sys
from pathlib import Path

from kinefuse.hil_tests import fuzz
from kinefuse.host.errors import KinefuseError


def main(argv=None) -> int:
    p = argparse.ArgumentParser(prog="python -m kinefuse.hil_tests.fuzz", description=__doc__.splitlines()[0])
    p.add_argument("--seconds", type=int, default=300, help="wall-clock budget (default 300)")
    p.add_argument("--jobs", type=int, default=1, help="parallel fuzzing processes (default 1)")
    p.add_argument("--corpus", type=Path, default=None, help="corpus directory (default: cache)")
    p.add_argument("--replay", nargs="*", type=Path, default=None,
                   help="replay these inputs with the gcc ASan/UBSan build instead of fuzzing")
    a = p.parse_args(argv)
    try:
        if a.replay is not None:
            res = fuzz.replay(a.replay or fuzz.seed_corpus(fuzz.cache_dir() / "seeds"))
            sys.stdout.write(res.stdout)
            sys.stderr.write(res.stderr[-4000:])
            return res.returncode
        if a.seconds <= 0:
            raise KinefuseError("--seconds must be positive")
        return fuzz.fuzz(a.seconds, a.jobs, a.corpus)
    except KinefuseError as exc:
        print(f"fuzz: error: {exc}", file=sys.stderr)
        return 2


if __name__ == "__main__":
    sys.exit(main())
