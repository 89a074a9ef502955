"""`kinefuse codegen --check` / `kinefuse codegen` on a generated folder that is stale, missing
files, hand-edited or carrying a removed filter's files."""
from __future__ import annotations

import re
import shutil
import subprocess

import pytest

from kinefuse.codegen import estimators, generate
from kinefuse.host import cli


def test_check_says_what_is_wrong_with_each_file_and_codegen_repairs_it(tmp_path, monkeypatch,
                                                                         capsys):
    gen = tmp_path / "generated"
    shutil.copytree(generate.GENERATED_DIR, gen, ignore=shutil.ignore_patterns("__pycache__"))
    monkeypatch.setattr(generate, "GENERATED_DIR", gen)
    assert cli.main(["codegen", "--check"]) == 0
    assert "up to date" in capsys.readouterr().err

    (gen / "madgwick_q.c").unlink()
    edited = gen / "madgwick_f32.c"
    lines = edited.read_text().splitlines(keepends=True)
    lines[40] = "/* a hand edit */\n"
    edited.write_text("".join(lines))
    crlf = gen / "models" / "mahony_f32.py"
    crlf.write_bytes(crlf.read_bytes().replace(b"\n", b"\r\n"))
    (gen / "oldfilter_f32.c").write_text("/* a removed filter */\n")

    assert cli.main(["codegen", "--check"]) == 1
    err = capsys.readouterr().err.splitlines()
    assert err[0].startswith("kinefuse codegen --check: 4 generated file(s)"), err
    report = {ln.strip().split(":")[0]: ln.strip() for ln in err[1:]}
    assert set(report) == {"madgwick_q.c", "madgwick_f32.c", "models/mahony_f32.py",
                           "oldfilter_f32.c"}, err
    assert report["madgwick_q.c"].endswith(": missing")
    assert "from line 41" in report["madgwick_f32.c"]
    assert "edited by hand" in report["madgwick_f32.c"]
    assert "line endings" in report["models/mahony_f32.py"]
    assert "not produced by the generator" in report["oldfilter_f32.c"]

    # --filter: only that filter's files
    assert cli.main(["codegen", "--check", "--filter", "mahony"]) == 1
    err = capsys.readouterr().err
    assert "models/mahony_f32.py" in err and "madgwick" not in err, err

    assert cli.main(["codegen"]) == 0
    err = capsys.readouterr().err
    assert "(removed) oldfilter_f32.c" in err and "4 file(s) updated" in err, err
    for rel in ("madgwick_q.c", "madgwick_f32.c", "models/mahony_f32.py"):
        assert (gen / rel).read_bytes() == (generate.REPO_ROOT / "firmware" / "generated" /
                                            rel).read_bytes(), rel
    assert not (gen / "oldfilter_f32.c").exists()
    assert cli.main(["codegen", "--check"]) == 0


def test_codegen_filter_keeps_the_operations_table_current(tmp_path, monkeypatch, capsys):
    """`kinefuse codegen --filter NAME` left OPS.md as it was, so a changed filter's row was
    stale and the next `--check` failed; it now updates that filter's rows, the others stay."""
    gen = tmp_path / "generated"
    shutil.copytree(generate.GENERATED_DIR, gen, ignore=shutil.ignore_patterns("__pycache__"))
    monkeypatch.setattr(generate, "GENERATED_DIR", gen)
    ops = gen / "OPS.md"
    original = ops.read_text()
    lines = original.splitlines(keepends=True)
    i = next(k for k, ln in enumerate(lines) if ln.startswith("| mahony | f32 |"))
    j = next(k for k, ln in enumerate(lines) if ln.startswith("| madgwick | q |"))
    lines[i] = "| mahony | f32 | 1 ops (stale) |\n"        # as if mahony's reference changed
    lines[j] = "| madgwick | q | 2 ops (stale) |\n"        # another filter's stale row stays
    ops.write_text("".join(lines))
    assert cli.main(["codegen", "--filter", "mahony"]) == 0
    capsys.readouterr()
    now = ops.read_text().splitlines(keepends=True)
    assert now[i] == original.splitlines(keepends=True)[i]    # regenerated
    assert now[j] == "| madgwick | q | 2 ops (stale) |\n"     # not named: kept as it was
    assert len(now) == len(lines)


LOWPASS = '''\
from kinefuse.codegen.estimator import Estimator, Param, Var
from kinefuse.codegen.estimators.angle_kf import ANGLE, ANGLE_MAX
from kinefuse.codegen.estimators.common import REJECTED
from kinefuse.codegen.scalar import assume, clamp, fabs, inc_if, logical_not, select


class Lowpass(Estimator):
    """y += k (angle - y)"""
    name = "cli-lowpass"
    inputs = ANGLE
    params = (Param("k", 0.5, "", 0.0, 1.0, "gain"),)
    state = (Var("angle", 1, -ANGLE_MAX, ANGLE_MAX, "rad", "filtered", init=0.0), REJECTED)
    outputs = (Var("angle", 1, -ANGLE_MAX, ANGLE_MAX, "rad", "filtered"), REJECTED)

    def step(self, x, u, p):
        ok = fabs(u.angle) <= ANGLE_MAX
        y = assume(x.angle + p.k * (clamp(u.angle, -ANGLE_MAX, ANGLE_MAX) - x.angle),
                   -ANGLE_MAX, ANGLE_MAX)
        y = select(ok, y, x.angle)
        r = inc_if(x.rejected, logical_not(ok))
        return {"angle": y, "rejected": r}, {"angle": y, "rejected": r}


class Broken(Lowpass):
    name = "cli-broken"

    def step(self, x, u, p):
        return x.angle if u.angle > 0.0 else x.angle  # line 28


class NeedsArgs(Lowpass):
    def __init__(self, k):
        self.k = k
'''


def test_codegen_estimator_writes_an_unregistered_estimator(tmp_path, capsys):
    src = tmp_path / "lowpass.py"
    src.write_text(LOWPASS)
    out = tmp_path / "out"
    assert cli.main(["codegen", "--estimator", f"{src}:Lowpass", "--out", str(out)]) == 0
    assert "9 file(s) written" in capsys.readouterr().err
    files = {str(p.relative_to(out)) for p in out.rglob("*") if p.is_file()}
    assert files == {"kf_fixed.h", "kf_angle_f32.h", "kf_angle_q.h", "models/cli_lowpass_f32.py",
                     "models/cli_lowpass_q.py"} | {f"cli_lowpass_{s}.{e}" for s in ("f32", "q")
                                                   for e in "ch"}
    for system in ("f32", "q"):
        c = out / f"cli_lowpass_{system}.c"
        assert set(re.findall(r"/\* ([\w.]+\.py):\d+", c.read_text())) == {"lowpass.py"}
        r = subprocess.run(["gcc", "-std=c99", "-Wall", "-Werror", "-ffp-contract=off", "-c",
                            f"-I{out}", str(c), "-o", str(tmp_path / f"{system}.o")],
                           capture_output=True, text=True)
        assert r.returncode == 0, r.stderr[:2000]
        ns = {}
        exec(compile((out / "models" / f"cli_lowpass_{system}.py").read_text(), "m", "exec"), ns)
        assert ns["NAME"] == "cli-lowpass" and ns["SYSTEM"] == system
    assert "cli-lowpass" not in estimators.ESTIMATORS
    assert not list(generate.GENERATED_DIR.glob("cli_lowpass*"))
    # an earlier result is only replaced with --force (the repository's rule for --out)
    (out / "kf_fixed.h").write_text("/* kept */\n")
    assert cli.main(["codegen", "--estimator", f"{src}:Lowpass", "--out", str(out)]) == 2
    assert "already holds" in capsys.readouterr().err
    assert (out / "kf_fixed.h").read_text() == "/* kept */\n"
    assert cli.main(["codegen", "--estimator", f"{src}:Lowpass", "--out", str(out),
                     "--force"]) == 0
    assert (out / "kf_fixed.h").read_text() != "/* kept */\n"


@pytest.mark.parametrize("argv, words", [
    (["--estimator", "{src}", "--out", "{out}"], "expected path/to/file.py:ClassName"),
    (["--estimator", "{tmp}/nope.py:Lowpass", "--out", "{out}"], "no such file"),
    (["--estimator", "{src}:Nope", "--out", "{out}"],
     "Nope in {src}: not defined (estimators defined there: Broken, Lowpass, NeedsArgs)"),
    (["--estimator", "{src}:NeedsArgs", "--out", "{out}"], "NeedsArgs() failed: TypeError"),
    (["--estimator", "{src}:ANGLE_MAX", "--out", "{out}"], "not a subclass of Estimator"),
    (["--estimator", "{tmp}/syntax.py:Lowpass", "--out", "{out}"], "importing {tmp}/syntax.py "
     "failed: SyntaxError"),
    (["--estimator", "{src}:Broken", "--out", "{out}"], "cli-broken: {src}:28 (return"),
    (["--estimator", "{src}:Lowpass"], "--estimator needs --out DIR"),
    (["--estimator", "{src}:Lowpass", "--out", "{out}", "--check"], "takes no --check"),
    (["--out", "{out}"], "--out and --force are for --estimator"),
    (["--force"], "--out and --force are for --estimator"),
])
def test_codegen_estimator_errors_are_one_line(tmp_path, capsys, argv, words):
    src = tmp_path / "lowpass.py"
    src.write_text(LOWPASS)
    (tmp_path / "syntax.py").write_text("def (:\n")
    fill = {"src": str(src), "out": str(tmp_path / "out"), "tmp": str(tmp_path)}
    assert cli.main(["codegen"] + [a.format(**fill) for a in argv]) == 2
    err = capsys.readouterr().err
    assert len(err.strip().splitlines()) == 1 and words.format(**fill) in err, err
    assert not (tmp_path / "out").exists()
