"""`kinefuse run`: one filter over one recording, estimates to CSV."""
from __future__ import annotations

import sys

import numpy as np

from kinefuse.host import runner
from kinefuse.host.errors import KinefuseError


def register(sub):
    p = sub.add_parser("run", help="run a filter over a recording and write the estimates as CSV")
    p.add_argument("--filter", default=None,
                   help=f"filter name (default: {runner.default_filter()}; see `kinefuse filters`)")
    p.add_argument("--impl", default="f32", choices=runner.IMPLS,
                   help="ref: Python reference (float64); f32: generated float32 C; "
                        "q: generated fixed-point C (default f32)")
    p.add_argument("--input", required=True, help="recording: BROAD .mat or bundled .npz trial")
    p.add_argument("--out", required=True, help="output CSV: t,w,x,y,z (+ status columns)")
    p.add_argument("--param", action="append", metavar="NAME=VALUE", help="parameter override")
    p.add_argument("--preset", help="named parameter set (see `kinefuse filters`)")
    p.add_argument("--status", action="store_true", help="append the filter's status outputs")
    p.add_argument("--frame", default="enu", choices=runner.FRAMES,
                   help="earth frame of the written quaternions (default enu, as BROAD)")
    p.set_defaults(func=run)


def run(args) -> int:
    from kinefuse.host.broad import load_trial
    name = args.filter or runner.default_filter()
    if name not in runner.filter_names():
        raise KinefuseError(f"unknown filter {name!r} (available: {', '.join(runner.filter_names())})")
    prm = runner.parse_params(args.param)
    trial = load_trial(args.input)
    res = runner.run_filter(name, args.impl, trial, prm, args.preset)
    n = len(res.q)
    t = np.arange(n) * float(trial.dt) if np.ndim(trial.dt) == 0 else np.cumsum(trial.dt)
    runner.write_estimates_csv(args.out, t, res, f"kinefuse run --filter {name} --impl {args.impl}; t in s; "
                               f"quaternion w,x,y,z sensor->earth, {runner.FRAME_TEXT[args.frame]}; "
                               f"input {args.input}", status=args.status, frame=args.frame)
    print(f"wrote {n} rows to {args.out} ({name}, {args.impl})", file=sys.stderr)
    return 0
