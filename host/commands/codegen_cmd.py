"""`kinefuse codegen [--check]`: regenerate firmware/generated/ from the reference code;
`kinefuse codegen --estimator FILE.py:CLASS --out DIR`: one unregistered estimator into DIR."""
from __future__ import annotations

import sys

from kinefuse.host.errors import KinefuseError
from kinefuse.host.outputs import add_force_arg, check_output_dir, output_folder


def register(sub):
    p = sub.add_parser("codegen", help="regenerate the C and Python models of every filter "
                                        "(--check: fail if the committed files are stale)")
    p.add_argument("--check", action="store_true",
                   help="do not write; exit 1 listing the files that differ")
    p.add_argument("--filter", action="append", help="only these filters (default: all)")
    p.add_argument("--estimator", metavar="FILE.py:CLASS",
                   help="an estimator outside the registry: write its f32/q C, headers and "
                        "models to --out (nothing in firmware/generated/ changes)")
    p.add_argument("--out", metavar="DIR", help="--estimator: the folder to write to")
    add_force_arg(p, "--estimator's files in --out")
    p.set_defaults(func=run)


def run_estimator(args) -> int:
    from kinefuse.codegen import generate
    if args.check or args.filter:
        raise KinefuseError("--estimator writes one unregistered estimator to --out: it takes "
                            "no --check or --filter")
    if not args.out:
        raise KinefuseError("--estimator needs --out DIR (the folder to write its files to)")
    files = generate.render_estimator(generate.load_estimator(args.estimator), args.estimator)
    out = check_output_dir(args.out, args.force, names=list(files))
    with output_folder(out):
        (out / "models").mkdir(exist_ok=True)
        for rel, text in files.items():
            (out / rel).write_bytes(text.encode("utf-8"))
            print(f"  {rel}", file=sys.stderr)
    print(f"{len(files)} file(s) written to {out}", file=sys.stderr)
    return 0


def run(args) -> int:
    from kinefuse.codegen import generate
    from kinefuse.codegen.fixed import RangeError
    try:
        if args.estimator:
            return run_estimator(args)
        if args.out or args.force:
            raise KinefuseError("--out and --force are for --estimator; registered filters are "
                                f"written to {generate.GENERATED_DIR}")
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

