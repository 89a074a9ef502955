"""`kinefuse codegen --check` / `kinefuse codegen` on a generated folder that is stale, missing
files, hand-edited or carrying a removed filter's files."""
from __future__ import annotations

import shutil

from kinefuse.codegen import generate
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
