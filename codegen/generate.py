"""Regenerate firmware/generated/ from the estimators' reference code (`kinefuse codegen`), or
check that the committed files are up to date (`kinefuse codegen --check`, run in CI)."""
from __future__ import annotations

import functools
from pathlib import Path

from kinefuse.codegen import estimators
from kinefuse.codegen.emit import SYSTEMS, Lowered, c_header, c_input_header, c_source, py_model
from kinefuse.codegen.estimator import trace
from kinefuse.codegen.ir import Graph
from kinefuse.codegen.passes import optimize
from kinefuse.codegen.runtime import RUNTIME_DIR

REPO_ROOT = Path(__file__).resolve().parent.parent
GENERATED_DIR = REPO_ROOT / "firmware" / "generated"


@functools.lru_cache(maxsize=None)
def graph_of(name: str) -> Graph:
    """The optimised graph of one step of estimator `name`."""
    return optimize(trace(estimators.get(name)))


@functools.lru_cache(maxsize=None)
def lowered(name: str, system: str) -> Lowered:
    return Lowered(estimators.get(name), graph_of(name), system)


def source_file(name: str) -> str:
    mod = type(estimators.get(name)).__module__.rsplit(".", 1)[-1]
    return f"codegen/estimators/{mod}.py"


def render_all(names: list[str] | None = None, ops_dir: Path | None = None) -> dict[str, str]:
    """Relative path (under firmware/generated) -> file text, for every estimator and system."""
    files: dict[str, str] = {
        "__init__.py": '"""Generated filters (C sources and their Python models)."""\n',
        "models/__init__.py": '"""Bit-exact Python models of the generated C."""\n',
        "kf_fixed.h": (RUNTIME_DIR / "kf_fixed.h").read_text(),
    }
    rows = []
    owner: dict[str, str] = {}

    def put(rel: str, text: str, name: str) -> None:
        # one file, two different texts: the later filter would silently replace the earlier
        # one's input record (or its whole C: names that differ only in - and _)
        if rel in owner and files[rel] != text:
            raise ValueError(f"filters {owner[rel]} and {name} both generate {rel}, with "
                             "different contents (an input record shared by name must be "
                             "declared identically; filter names must differ after - -> _)")
        files[rel] = text
        owner.setdefault(rel, name)

    for name in names or list(estimators.ESTIMATORS):
        src = source_file(name)
        # an estimator may restrict its number systems (e.g. float32 only: a covariance
        # filter whose fixed-point ranges cannot be bounded)
        for system in getattr(estimators.get(name), "systems", SYSTEMS):
            lo = lowered(name, system)
            for rel, text in _files_of(lo, src).items():
                put(rel, text, name)
            rows.append((name, system, lo.op_summary()))
    if names is None:   # the table covers every registered filter
        files["OPS.md"] = _ops_table(rows)
    elif ops_dir is not None:   # --filter: the others' rows of the existing table stay
        files["OPS.md"] = _ops_table(rows, keep=_ops_rows(Path(ops_dir) / "OPS.md"))
    return files


def _files_of(lo: Lowered, src: str) -> dict[str, str]:
    """The files of one filter in one number system: C source and header, model, input record."""
    P = lo.prefix
    return {f"{P}.h": c_header(lo, src), f"{P}.c": c_source(lo, src),
            f"models/{P}.py": py_model(lo, src),
            f"kf_{lo.est.inputs.name}_{lo.system}.h": c_input_header(lo)}


def render_estimator(est, src: str, systems=None) -> dict[str, str]:
    """Relative path -> file text for an estimator that need not be registered: its files in
    `systems` (default: its own) and the runtime header they include."""
    g = optimize(trace(est))
    files = {"kf_fixed.h": (RUNTIME_DIR / "kf_fixed.h").read_text()}
    for system in systems or est.systems:
        files.update(_files_of(Lowered(est, g, system), src))
    return files


def load_estimator(spec: str):
    """An instance of class Name of ``path/to/file.py:Name`` (imported from that file, not
    registered); ValueError saying what is wrong otherwise."""
    import importlib.util
    import sys

    from kinefuse.codegen.estimator import Estimator
    path, sep, cls_name = spec.rpartition(":")
    if not sep or not path.endswith(".py") or not cls_name.isidentifier():
        raise ValueError(f"--estimator {spec!r}: expected path/to/file.py:ClassName")
    file = Path(path)
    if not file.is_file():
        raise ValueError(f"--estimator: no such file {path}")
    modname = f"kinefuse_estimator_{file.stem}"
    mod_spec = importlib.util.spec_from_file_location(modname, file)
    mod = importlib.util.module_from_spec(mod_spec)
    sys.modules[modname] = mod      # (dataclasses and pickling look the module up by name)
    try:
        mod_spec.loader.exec_module(mod)
    except Exception as exc:
        del sys.modules[modname]
        raise ValueError(f"--estimator: importing {path} failed: {type(exc).__name__}: {exc}") \
            from None
    cls = getattr(mod, cls_name, None)
    if not (isinstance(cls, type) and issubclass(cls, Estimator)) or cls is Estimator:
        found = sorted(k for k, v in vars(mod).items() if isinstance(v, type)
                       and issubclass(v, Estimator) and v.__module__ == modname)
        what = "not defined" if cls is None else "not a subclass of Estimator"
        raise ValueError(f"--estimator: {cls_name} in {path}: {what} (estimators defined "
                         f"there: {', '.join(found) or 'none'})")
    try:
        return cls()
    except Exception as exc:
        raise ValueError(f"--estimator: {cls_name}() failed: {type(exc).__name__}: {exc}") from None


def _ops_rows(path: Path) -> dict[tuple[str, str], str]:
    """(filter, system) -> operations of an existing OPS.md ({} when there is none)."""
    if not path.is_file():
        return {}
    rows = {}
    for line in path.read_text(encoding="utf-8").splitlines():
        cells = [c.strip() for c in line.strip().strip("|").split("|")]
        if len(cells) == 3 and cells[0] in estimators.ESTIMATORS:
            rows[(cells[0], cells[1])] = cells[2]
    return rows


def _ops_table(rows, keep: dict | None = None) -> str:
    """The table of ``rows`` (filter, system, ops); with ``keep`` (``codegen --filter``) the
    other registered filters' rows of the existing table stay, in registry order (a partial
    regeneration left OPS.md stale, so ``--check`` then failed)."""
    if keep is not None:
        new = {(n, s): o for n, s, o in rows}
        merged = {**keep, **new}
        rows = [(n, s, merged[(n, s)]) for n in estimators.ESTIMATORS
                for s in getattr(estimators.get(n), "systems", SYSTEMS) if (n, s) in merged]
    lines = ["# Generated filters: operations per update", "",
             "Produced by `kinefuse codegen` (do not edit).  Counts are graph operations after",
             "constant folding, common-subexpression elimination and dead-code removal; a",
             "number system's row leaves out what it emits no code for (f32: the min/max of a",
             "`bound`).", "",
             "| filter | number system | operations per update |", "|---|---|---|"]
    lines += [f"| {n} | {s} | {o} |" for n, s, o in rows]
    return "\n".join(lines) + "\n"


def write(out_dir: Path = GENERATED_DIR, names: list[str] | None = None) -> list[str]:
    """Write every generated file; remove stale generated C/model files.  Returns paths written."""
    files = render_all(names, ops_dir=out_dir)
    out_dir.mkdir(parents=True, exist_ok=True)
    (out_dir / "models").mkdir(exist_ok=True)
    written = []
    for rel, text in files.items():
        path = out_dir / rel
        data = text.encode("utf-8")
        if not path.exists() or path.read_bytes() != data:
            path.write_bytes(data)     # bytes: UTF-8 and \n whatever the locale and platform
            written.append(rel)
    if names is None:
        for rel in _extra(out_dir, files):
            (out_dir / rel).unlink()
            written.append(f"(removed) {rel}")
    return written


def _extra(out_dir: Path, files: dict[str, str]) -> list[str]:
    """Generated-looking files in out_dir that the generator does not produce (any more)."""
    return [str(p.relative_to(out_dir)) for p in
            sorted(out_dir.glob("*.[ch]")) + sorted((out_dir / "models").glob("*.py"))
            if str(p.relative_to(out_dir)) not in files]


def differences(out_dir: Path, files: dict[str, str]) -> list[str]:
    """``path: why`` for every file of `files` that is missing or differs in out_dir (compared
    byte for byte: a file re-saved with other line endings or encoding differs too)."""
    out = []
    for rel, text in files.items():
        path = out_dir / rel
        if not path.is_file():
            out.append(f"{rel}: missing")
            continue
        have, want = path.read_bytes(), text.encode("utf-8")
        if have == want:
            continue
        if have.replace(b"\r\n", b"\n") == want:
            out.append(f"{rel}: differs in its line endings only (CRLF: re-saved by an editor?)")
            continue
        hl, wl = have.split(b"\n"), want.split(b"\n")
        line = next((i for i, (a, b) in enumerate(zip(hl, wl)) if a != b), min(len(hl), len(wl)))
        out.append(f"{rel}: differs from the generator's output from line {line + 1} "
                   "(edited by hand, or the reference code changed)")
    return out


def check(out_dir: Path = GENERATED_DIR) -> list[str]:
    """``path: why`` for every file that differs from what the generator produces now
    (empty: up to date)."""
    files = render_all()
    return differences(out_dir, files) + [
        f"{e}: not produced by the generator (`kinefuse codegen` removes it)"
        for e in _extra(out_dir, files)]
