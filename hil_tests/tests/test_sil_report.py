"""``kinefuse sil report``: the command users run for the full SIL/PIL comparison.

Run end to end on a short case (host loops and the unit application over its pty, no QEMU, to
stay quick; the PIL loops are covered by test_pil_firmware.py and test_qemu_bitexact.py): exit
status, the JSON summary, the markdown table; a mismatch and a loop error must show as "NO" and
make the command fail; bad arguments are one-line errors.
"""
from __future__ import annotations

import json

import pytest

from kinefuse.hil_tests.harness import compare, firmware, report
from kinefuse.host.cli import main


@pytest.mark.skipif(firmware.firmware_missing() is not None, reason=str(firmware.firmware_missing()))
def test_sil_report_end_to_end(tmp_path, capsys):
    rc = main(["sil", "report", "--filters", "madgwick,flagship", "--scenarios", "slow_rotation",
               "--seconds", "1.5", "--broad", "none", "--no-qemu", "--firmware", "--json",
               "--out", str(tmp_path)])
    out = json.loads(capsys.readouterr().out.strip().splitlines()[-1])
    assert rc == 0 and out["all_bitexact"]
    rows = out["bitexact"]
    loops_seen = {(r["filter"], r["loop"]) for r in rows}
    for name in ("madgwick", "flagship"):
        # the generated C on the host and the unit application, both number systems
        assert {(name, "host-f32"), (name, "host-q"), (name, "sil-f32"), (name, "sil-q")} <= loops_seen
    assert all(r["samples"] == 150 and r["mismatch"] is None and r["error"] is None for r in rows)
    md = (tmp_path / "sil_report.md").read_text()
    assert "| flagship | q | sil-q vs q unit model | 1 | 150 | yes |" in md
    full = json.loads((tmp_path / "sil_report.json").read_text())
    err = {(e["filter"], e["system"]): e for e in full["errors"]}
    # an honest error figure, not NaN or zero: the filters track the simulated rotation
    assert 0.0 < err[("flagship", "f32")]["total"] < 5.0
    assert (tmp_path / "sil_report.png").exists()


def test_report_marks_mismatches_and_errors(tmp_path):
    rep = report.Report(["case"], ["madgwick"])
    ok = {"filter": "madgwick", "case": "case", "system": "q", "model": "q model", "loop": "host-q",
          "samples": 10, "mismatch": None, "error": None}
    rep.bitexact = [ok]
    assert rep.all_bitexact
    bad = dict(ok, loop="sil-q", mismatch=compare.Mismatch("q model", "sil-q", 7, 1, 10, ["q_raw"]).as_dict())
    rep.bitexact = [ok, bad]
    assert not rep.all_bitexact
    md = report.write_markdown(rep, tmp_path, None).read_text()
    assert "| NO | case sample 7 (q_raw)" in md and "| yes |" in md
    rep.bitexact = [ok, dict(ok, loop="pil-m0-q", error="KinefuseError: HIL: 3 answers missing")]
    assert not rep.all_bitexact
    assert "| NO |" in report.write_markdown(rep, tmp_path, None).read_text()


@pytest.mark.parametrize("argv,msg", [
    (["--filters", "nosuch"], "unknown IMU filter"),
    (["--seconds", "0"], "--seconds must be positive"),
    (["--seconds", "inf"], "--seconds must be positive and finite"),
    (["--seconds", "nan"], "--seconds must be positive and finite"),
    (["--broad-seconds", "nan"], "--broad-seconds must be positive and finite"),
    (["--broad-seconds", "inf"], "--broad-seconds must be positive and finite"),
    # ran twice, each row repeated in the table and counted twice in "N of M identical"
    (["--filters", "madgwick,madgwick"], "--filters names madgwick twice"),
    (["--scenarios", "rest, rest"], "--scenarios names rest twice"),
    # accepted and ignored before
    (["--jobs", "2"], "--jobs sets the firmware loops: add --firmware"),
    (["--pil-samples", "10"], "--pil-samples sets the firmware loops: add --firmware"),
    (["--broad", "none", "--broad-seconds", "5"], "--broad-seconds: this report has no BROAD trial (--broad none)"),
    (["--ci", "--broad-seconds", "5"], "--broad-seconds: this report has no BROAD trial (--ci leaves it out"),
    (["--firmware", "--pil-samples", "-1"], "--pil-samples and --sil-samples must be >= 0"),
    (["--firmware", "--sil-samples", "-1"], "--pil-samples and --sil-samples must be >= 0"),
    # (the base has --no-qemu) the PIL loops were left out and N ignored without a word
    (["--firmware", "--pil-samples", "10"], "--pil-samples sets the PIL loops (QEMU), which --no-qemu leaves out"),
])
def test_sil_report_bad_arguments(tmp_path, capsys, argv, msg):
    rc = main(["sil", "report", "--no-qemu", "--out", str(tmp_path)] + argv)
    err = capsys.readouterr().err
    assert rc == 2 and msg in err and "Traceback" not in err


def test_sil_report_refuses_seconds_shorter_than_a_sample(tmp_path, capsys):
    # 1 ms of a 100 Hz scenario is no sample: every loop failed on an empty input and the report
    # listed the failures as loop errors
    rc = main(["sil", "report", "--no-qemu", "--filters", "madgwick", "--scenarios", "rest",
               "--seconds", "0.001", "--broad", "none", "--out", str(tmp_path)])
    err = capsys.readouterr().err
    assert rc == 2 and "--seconds keeps no sample of rest (100 Hz): give at least 0.01 s" in err
    assert not (tmp_path / "sil_report.md").exists()
    # a report that stops before writing leaves no empty folder behind (it was created first)
    out = tmp_path / "new" / "report"
    rc = main(["sil", "report", "--no-qemu", "--filters", "madgwick", "--scenarios", "rest",
               "--seconds", "0.001", "--broad", "none", "--out", str(out)])
    assert rc == 2 and not (tmp_path / "new").exists()
    (tmp_path / "blocker").write_text("x")
    rc = main(["sil", "report", "--no-qemu", "--out", str(tmp_path / "blocker" / "r")])
    assert rc == 2 and "cannot create the folder" in capsys.readouterr().err


@pytest.mark.parametrize("text, msg", [
    ('{"rows": [{"filter": "madgwick"}]}', "row 0 of 'rows' is not a `kinefuse bench cost --json` row"),
    ('[1]', "is not `kinefuse bench cost --json` output (no 'rows' list)"),
    ('{}', "is not `kinefuse bench cost --json` output (no 'rows' list)"),
])
def test_sil_report_checks_the_cost_json_before_running(tmp_path, capsys, text, msg):
    # a row without 'impl' was an internal error (KeyError) from the Markdown writer after every
    # loop had run; a JSON that was not an object gave "list indices must be integers ..."
    cost = tmp_path / "cost.json"
    cost.write_text(text)
    rc = main(["sil", "report", "--no-qemu", "--filters", "madgwick", "--scenarios", "rest",
               "--seconds", "0.5", "--broad", "none", "--cost", str(cost), "--out", str(tmp_path / "r")])
    err = capsys.readouterr().err
    assert rc == 2 and msg in err and err.count("\n") == 1
    assert not (tmp_path / "r").exists()


def test_sil_report_keeps_an_earlier_report_unless_forced(tmp_path, capsys):
    (tmp_path / "sil_report.md").write_text("an earlier report")
    argv = ["sil", "report", "--filters", "madgwick", "--scenarios", "slow_rotation",
            "--seconds", "0.5", "--broad", "none", "--no-qemu", "--out", str(tmp_path)]
    rc = main(argv)
    err = capsys.readouterr().err
    assert rc == 2 and "already holds sil_report.md from an earlier run (use --force" in err
    assert (tmp_path / "sil_report.md").read_text() == "an earlier report"
    assert not (tmp_path / "sil_report.json").exists()        # refused before any work
    assert main(argv + ["--force"]) == 0
    assert (tmp_path / "sil_report.md").read_text().startswith("# kinefuse SIL/PIL report")
    (tmp_path / "file").write_text("x")
    assert main(argv[:-1] + [str(tmp_path / "file")]) == 2
    assert "is a file, not a folder" in capsys.readouterr().err


def test_sil_report_failed_write_leaves_the_earlier_report(tmp_path, capsys, monkeypatch):
    """The files were written one after the other after the work: a full disk on the Markdown
    left this run's PNG next to the earlier run's Markdown and JSON (with --force)."""
    import errno
    argv = ["sil", "report", "--filters", "madgwick", "--scenarios", "slow_rotation",
            "--seconds", "0.5", "--broad", "none", "--no-qemu", "--out", str(tmp_path), "--force"]
    for name in ("sil_report.md", "sil_report.png", "sil_report.json"):
        (tmp_path / name).write_text(f"earlier {name}")

    def full_disk(*a, **k):
        raise OSError(errno.ENOSPC, "No space left on device")
    real = report.write_markdown
    monkeypatch.setattr(report, "write_markdown", full_disk)
    assert main(argv) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "cannot write the report in" in err and "No space left" in err, err
    assert sorted(p.name for p in tmp_path.iterdir()) == ["sil_report.json", "sil_report.md",
                                                           "sil_report.png"]
    for name in ("sil_report.md", "sil_report.png", "sil_report.json"):
        assert (tmp_path / name).read_text() == f"earlier {name}"
    # the same run, written: every file is new, and the Markdown names the final PNG
    monkeypatch.setattr(report, "write_markdown", real)
    assert main(argv) == 0
    # the wall-clock time said as such ("(0 s)" read as scenarios of no length)
    out = capsys.readouterr().out
    assert "loop comparisons identical (run time " in out and " s)" in out and "(0 s)" not in out, out
    assert sorted(p.name for p in tmp_path.iterdir()) == ["sil_report.json", "sil_report.md",
                                                           "sil_report.png"]
    assert "![errors](sil_report.png)" in (tmp_path / "sil_report.md").read_text()
    assert (tmp_path / "sil_report.png").read_bytes().startswith(b"\x89PNG")
    assert json.loads((tmp_path / "sil_report.json").read_text())["filters"] == ["madgwick"]
    # a folder in the way of a report file: said before the work
    (tmp_path / "sil_report.json").unlink()
    (tmp_path / "sil_report.json").mkdir()
    monkeypatch.setattr(report, "build_report", full_disk)
    assert main(argv) == 2
    assert "sil_report.json: a folder of that name is in the way" in capsys.readouterr().err
    # a new folder whose report could not be written is not left behind empty
    monkeypatch.undo()
    monkeypatch.setattr(report, "write_markdown", full_disk)
    new = tmp_path / "new"
    assert main(argv[:-3] + ["--out", str(new)]) == 2
    assert not new.exists()


def test_report_states_its_run_time_as_such(tmp_path):
    rep = report.Report(["case"], ["madgwick"])
    rep.seconds = 0.43
    md = report.write_markdown(rep, tmp_path, None).read_text()
    assert "1 filters × 1 scenarios, run time 0.4 s." in md
    rep.seconds = 3123.4
    assert "run time 3,123 s." in report.write_markdown(rep, tmp_path, None).read_text()


def test_sil_report_cost_that_cannot_be_read(tmp_path, capsys):
    """A folder or a missing file as --cost said "[Errno 21] Is a directory: '...'"."""
    base = ["sil", "report", "--no-qemu", "--filters", "madgwick", "--scenarios", "rest",
            "--seconds", "0.5", "--broad", "none", "--out", str(tmp_path / "r")]
    for cost, why in ((tmp_path, "Is a directory"), (tmp_path / "none.json", "No such file or directory")):
        assert main(base + ["--cost", str(cost)]) == 2
        err = capsys.readouterr().err
        assert err.strip() == f"kinefuse: error: cannot read cost JSON {cost}: {why}", err
    assert not (tmp_path / "r").exists()


def test_sil_report_cost_table_tells_9d_from_6d_rows(tmp_path):
    # a 9D and a 6D row of one filter (`bench cost --sensors 9d,6d`) were two identical-looking
    # lines; rows of older cost JSON have no sensors and keep an empty cell
    from kinefuse.hil_tests.harness.report import Report, write_markdown
    row = {"impl": "kinefuse", "filter": "madgwick", "format": "f32", "target": "m4f",
           "flash_bytes": 2792, "ram_bytes": 64}
    rep = Report(cases=[], filters=[], cost=[{**row, "sensors": "9d", "instructions_per_update": 389.0},
                                             {**row, "sensors": "6d", "instructions_per_update": 328.0},
                                             {**row, "instructions_per_update": 370.0}])
    text = write_markdown(rep, tmp_path, None).read_text()
    assert "| impl | filter | sensors | format |" in text
    assert "| kinefuse | madgwick | 9d | f32 | m4f | 389.0 |" in text
    assert "| kinefuse | madgwick | 6d | f32 | m4f | 328.0 |" in text
    assert "| kinefuse | madgwick |  | f32 | m4f | 370.0 |" in text
