"""`kinefuse codegen [--check]`: regenerate firmware/generated/ from the reference code."""
from __future__ import annotations

import sys

from kinefuse.host.errors import KinefuseError


def register(sub):
    p = sub.add_parser("codegen", help="regenerate the C and Python models of every filter "
                                        "(--check: fail if the committed files are stale)")
    p.add_argument("--check", action="store_true",
                   help="do not write; exit 1 listing the files that differ")
    p.add_argument("--filter", action="append", help="only these filters (default: all)")
    p.set_defaults(func=run)


def run(args) -> int:
    from kinefuse.codegen import generate
    from kinefuse.codegen.fixed import RangeError
    try:
        out_dir = generate.GENERATED_DIR
        if args.check:
            stale = (generate.differences(out_dir, generate.render_all(args.filter, ops_dir=out_dir))
                     if args.filter else generate.check(out_dir))
            if stale:
                print(f"kinefuse codegen --check: {len(stale)} generated file(s) in {out_dir} "
                      "are out of date (run `kinefuse codegen` and commit):\n  "
                      + "\n  ".join(stale), file=sys.stderr)
                return 1
            print("generated files are up to date", file=sys.stderr)
            return 0
        written = generate.write(out_dir, names=args.filter)
    except RangeError as exc:
        raise KinefuseError(f"fixed-point range analysis: {exc}") from None
    except ValueError as exc:
        raise KinefuseError(str(exc)) from None
    for w in written:
        print(f"  {w}", file=sys.stderr)
    print(f"{len(written)} file(s) updated in {generate.GENERATED_DIR}", file=sys.stderr)
    return 0

