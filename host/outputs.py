"""Files a command writes: an earlier result is never replaced without ``--force``.

The checks run before any work (a long decode or filter run does not end in a refusal), and a
command's input is never its output, ``--force`` or not.
"""
from __future__ import annotations

import contextlib
from pathlib import Path

from kinefuse.host.errors import KinefuseError


def add_force_arg(parser, what: str = "the output") -> None:
    parser.add_argument("--force", action="store_true", help=f"overwrite {what} if it exists")


def _same(a: Path, b) -> bool:
    try:
        return a.samefile(b)
    except OSError:          # either does not exist (a missing input is reported by its reader)
        return False


def check_new_file(path, force: bool, *, option: str = "--out", inputs=()) -> Path:
    """``path`` may be written: not an input, not a folder, its folder exists, and it does not
    exist yet unless ``force``."""
    out = Path(path)
    for src in inputs:
        if src is not None and _same(out, src):
            raise KinefuseError(f"{option} {out} is the input {src}: give another file name (the "
                                f"input would be overwritten)")
    if out.is_dir():
        raise KinefuseError(f"{option} {out} is a folder: give a file name")
    parent = out.parent
    if str(parent) and not parent.is_dir():
        raise KinefuseError(f"{option} {out}: folder {parent} does not exist")
    if out.exists() and not force:
        raise KinefuseError(f"{out} exists (use --force to overwrite, or another {option})")
    return out


def check_output_dir(path, force: bool, names=None, *, pattern: str | None = None,
                     option: str = "--out") -> Path:
    """Folder ``path`` may receive the files ``names`` (or any file matching ``pattern``): it is
    not a file, and holds none of them yet unless ``force``."""
    if not str(path).strip():     # Path("") is the current folder
        raise KinefuseError(f"{option} is empty: give a folder")
    out = Path(path)
    if out.exists() and not out.is_dir():
        raise KinefuseError(f"{option} {out} is a file, not a folder")
    if not out.is_dir() or force:
        return out
    found = {n for n in (names or ()) if (out / n).exists()}
    if pattern:
        found |= {p.name for p in out.glob(pattern)}
    found = sorted(found)
    if found:
        more = f" and {len(found) - 3} more" if len(found) > 3 else ""
        raise KinefuseError(f"{out} already holds {', '.join(found[:3])}{more} from an earlier run "
                            f"(use --force to overwrite, or another {option})")
    return out


@contextlib.contextmanager
def output_folder(path, option: str = "--out"):
    """Create folder ``path`` (and missing parents) before the work, so an impossible one fails
    first; if the command then fails before writing into it, the folders this created are
    removed again (no empty folder is left behind)."""
    out = Path(path)
    made, p = [], out
    while not p.exists() and p != p.parent:
        made.append(p)
        p = p.parent
    try:
        out.mkdir(parents=True, exist_ok=True)
    except OSError as exc:
        raise KinefuseError(f"{option} {out}: cannot create the folder ({exc.strerror})") from None
    try:
        yield out
    except BaseException:
        for d in made:                  # innermost first; a folder that received files stays
            try:
                d.rmdir()
            except OSError:
                break
        raise
