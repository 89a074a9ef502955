"""The per-process cache of built filter programs (hil_tests/harness/qemu_filter.py)."""
from __future__ import annotations

import shutil

from kinefuse.codegen.generate import GENERATED_DIR
from kinefuse.hil_tests.harness import qemu_filter


def test_regenerated_code_is_built_anew(tmp_path, monkeypatch):
    gen = tmp_path / "generated"
    gen.mkdir()
    for p in [GENERATED_DIR / "madgwick_f32.c", *GENERATED_DIR.glob("*.h")]:
        shutil.copy(p, gen / p.name)
    monkeypatch.setattr(qemu_filter, "GENERATED_DIR", gen)
    monkeypatch.setattr(qemu_filter, "_CACHE", {})
    built = []

    def fake_build(name, system, target, params):
        # the program as it would be built now: the text of the source it compiles
        built.append((gen / "madgwick_f32.c").read_text())
        return built[-1]

    monkeypatch.setattr(qemu_filter, "build_filter_program", fake_build)
    params = {"beta": 0.1}
    first = qemu_filter.filter_program("madgwick", "f32", "m4f", params)
    assert qemu_filter.filter_program("madgwick", "f32", "m4f", params) is first   # cached
    assert len(built) == 1
    src = gen / "madgwick_f32.c"
    src.write_text(src.read_text() + "\n/* regenerated */\n")
    again = qemu_filter.filter_program("madgwick", "f32", "m4f", params)
    assert len(built) == 2 and again.endswith("/* regenerated */\n"), "stale program reused"
    # a header the source includes counts too
    h = gen / "kf_fixed.h"
    h.write_text(h.read_text() + "\n/* changed */\n")
    qemu_filter.filter_program("madgwick", "f32", "m4f", params)
    assert len(built) == 3
