"""Files a command writes: an earlier result is never replaced without ``--force``.

The checks run before any work (a long decode or filter run does not end in a refusal), and a
command's input is never its output, ``--force`` or not.
"""
from __future__ import annotations

import contextlib
import os
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
    not a file, no folder stands where one of ``names`` goes (not even with ``force``: said
    before the work, not when its results are written), and it holds none of them yet unless
    ``force``."""
    if not str(path).strip():     # Path("") is the current folder
        raise KinefuseError(f"{option} is empty: give a folder")
    out = Path(path)
    if out.exists() and not out.is_dir():
        raise KinefuseError(f"{option} {out} is a file, not a folder")
    for n in names or ():
        if (out / n).is_dir():
            raise KinefuseError(f"cannot write {out / n}: a folder of that name is in the way")
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


class Staged:
    """Files written under temporary names and renamed into place together (:func:`staged`)."""

    def __init__(self):
        self.pairs: list[tuple[Path, Path]] = []    # (temporary, final), in the order asked

    def path(self, final) -> Path:
        """The temporary name to write ``final`` under: same folder, hidden, same suffix (writers
        that choose the format by it still do)."""
        final = Path(final)
        tmp = final.with_name(f".{final.stem}.{os.getpid()}.partial{final.suffix}")
        self.pairs.append((tmp, final))
        return tmp


@contextlib.contextmanager
def staged():
    """``with staged() as st: write(st.path(final)) ...``: when the block ends normally every
    temporary file replaces its final one; on any failure (a full disk, an interrupt, an error)
    the temporary files are removed.  A failed write then leaves neither a cut file nor a set
    that is half new, and with --force the earlier files stay as they were."""
    st = Staged()
    try:
        yield st
        for tmp, final in st.pairs:
            os.replace(tmp, final)
    except BaseException:
        for tmp, _final in st.pairs:
            with contextlib.suppress(OSError):
                tmp.unlink()
        raise
