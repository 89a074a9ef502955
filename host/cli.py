"""The ``kinefuse`` command.

Each sub-command lives in its own module that exposes ``register(subparsers)``; the module
adds its parser and sets ``func`` (called with the parsed args, returns an exit code).
Benchmarks register under ``kinefuse bench`` through ``register_bench(bench_subparsers)``.
Adding a command means adding its module name to the lists below.
"""
from __future__ import annotations

import argparse
import importlib
import os
import sys

from kinefuse.host.errors import KinefuseError

# Modules providing top-level sub-commands (order = order in --help).
COMMAND_MODULES = [
    "kinefuse.host.commands.filters_cmd",
    "kinefuse.host.commands.run_cmd",
    "kinefuse.host.commands.replay_cmd",
    "kinefuse.host.commands.opensense_cmd",
    "kinefuse.host.commands.demo_cmd",
    "kinefuse.host.commands.plot_cmd",
    "kinefuse.host.commands.codegen_cmd",
    "kinefuse.hil_tests.sim.cli_cmd",
    "kinefuse.host.commands.calibrate_cmd",
    "kinefuse.host.commands.report_cmd",
    "kinefuse.host.commands.record_cmd",
    "kinefuse.host.commands.decode_cmd",
    "kinefuse.host.commands.export_cmd",
    "kinefuse.host.commands.stats_cmd",
    "kinefuse.host.commands.live_cmd",
    "kinefuse.host.commands.params_cmd",
    "kinefuse.host.commands.signing_cmd",
    "kinefuse.host.commands.command_cmd",
    "kinefuse.host.commands.ports_cmd",
    "kinefuse.host.commands.sil_cmd",
    "kinefuse.host.commands.flash_cmd",
]
# Modules providing `kinefuse bench <name>` sub-commands.
BENCH_MODULES = [
    "kinefuse.host.bench.accuracy",
    "kinefuse.host.bench.bitexact",
    "kinefuse.host.bench.speed",
    "kinefuse.host.calib.bench",
    "kinefuse.host.kinematics.bench",
    "kinefuse.host.bench.decode",
    "kinefuse.hil_tests.qemu.bench",
    "kinefuse.host.bench.dynamics",
    "kinefuse.host.bench.seed001",
    "kinefuse.host.bench.seed004",
    "kinefuse.host.bench.cost",
    "kinefuse.firmware.app_bench",
]


class _Parser(argparse.ArgumentParser):
    """argparse that reports errors in one line and exits with status 2."""

    def error(self, message):  # noqa: D401 - argparse API
        self.exit(2, f"kinefuse: error: {message}\n")


def build_parser() -> argparse.ArgumentParser:
    parser = _Parser(prog="kinefuse", description=__doc__.splitlines()[0] if __doc__ else None)
    parser.add_argument("--debug", action="store_true", help="show tracebacks for internal errors")
    sub = parser.add_subparsers(dest="command", metavar="COMMAND", parser_class=_Parser)
    for name in COMMAND_MODULES:
        _load(name).register(sub)
    bench = sub.add_parser("bench", help="benchmarks (accuracy, bit-exactness, speed, ...)")
    bench_sub = bench.add_subparsers(dest="bench", metavar="BENCH", parser_class=_Parser)
    for name in BENCH_MODULES:
        _load(name).register_bench(bench_sub)
    bench.set_defaults(func=lambda args: (bench.print_help(), 2)[1])
    return parser


def _load(module_name: str):
    return importlib.import_module(module_name)


def main(argv: list[str] | None = None) -> int:
    try:
        parser = build_parser()   # imports every command: Ctrl-C may come in the first second
    except KeyboardInterrupt:
        print("kinefuse: interrupted", file=sys.stderr)
        return 130
    args = parser.parse_args(argv)
    if not getattr(args, "func", None):
        parser.print_help()
        return 2
    try:
        code = args.func(args)
    except KinefuseError as exc:
        print(f"kinefuse: error: {exc}", file=sys.stderr)
        return 2
    except KeyboardInterrupt:
        print("kinefuse: interrupted", file=sys.stderr)
        return 130
    except BrokenPipeError:
        # output piped into `head` etc.
        os.dup2(os.open(os.devnull, os.O_WRONLY), sys.stdout.fileno())
        return 0
    except Exception as exc:  # an internal bug: one line unless --debug
        if args.debug:
            raise
        print(f"kinefuse: internal error: {type(exc).__name__}: {exc} "
              f"(re-run with --debug for a traceback and please report it)", file=sys.stderr)
        return 3
    return int(code or 0)


if __name__ == "__main__":
    sys.exit(main())
