"""`kinefuse filters`: the registered filters, their parameters, defaults and units."""
from __future__ import annotations

import json

from kinefuse.codegen import estimators
from kinefuse.codegen.estimator import bound_text, range_text  # noqa: F401 (params uses them)
from kinefuse.host.console import print_table


def register(sub):
    p = sub.add_parser("filters", help="list filters, parameters, defaults and units")
    p.add_argument("names", nargs="*", metavar="NAME", help="only these filters (default: all)")
    p.add_argument("--json", action="store_true", help="one JSON object on stdout")
    p.set_defaults(func=run)


def describe() -> dict:
    out = {}
    for name, cls in estimators.ESTIMATORS.items():
        out[name] = {
            "title": cls.title,
            "input": cls.inputs.name,
            "params": [{"name": p.name, "default": p.default, "unit": p.unit, "min": p.lo,
                        "max": p.hi, "doc": p.doc, "choices": list(p.choices),
                        "labels": list(p.labels)} for p in cls.params],
            "presets": cls.presets,
            "outputs": [{"name": v.name, "size": v.size, "unit": v.unit, "doc": v.doc}
                        for v in cls.outputs],
            "implementations": ["ref", *cls.systems],
        }
    return out


def run(args) -> int:
    info = describe()
    if args.names:
        from kinefuse.host.errors import KinefuseError
        unknown = [n for n in args.names if n not in info]
        if unknown:
            raise KinefuseError(f"unknown filter {unknown[0]!r} (available: {', '.join(info)})")
        info = {n: info[n] for n in dict.fromkeys(args.names)}
    if args.json:
        print(json.dumps(info, indent=1))
        return 0
    from rich.console import Console
    from rich.table import Table
    console = Console()
    for name, d in info.items():
        t = Table(title=f"{name} — {d['title']}  (input: {d['input']}; "
                        f"--impl {'|'.join(d['implementations'])})",
                  title_justify="left", show_edge=False)
        for col in ("parameter", "default", "unit", "range", "meaning"):
            t.add_column(col)
        for p in d["params"]:
            rng = (" | ".join(f"{c:g}" + (f" ({n})" if n else "") for c, n in
                              zip(p["choices"], p["labels"] or [""] * len(p["choices"])))
                   if p["choices"] else range_text(p["min"], p["max"]))
            t.add_row(p["name"], f"{p['default']:g}", p["unit"], rng, p["doc"])
        print_table(t, console)
        if d["presets"]:
            console.print("  presets: " + "; ".join(
                f"{k} ({', '.join(f'{a}={b:g}' for a, b in v.items())})" for k, v in d["presets"].items()))
        console.print("  outputs: " + ", ".join(
            f"{o['name']}[{o['size']}]" + (f" {o['unit']}" if o["unit"] else "") for o in d["outputs"]))
        console.print()
    return 0
