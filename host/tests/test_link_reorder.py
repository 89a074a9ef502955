"""Frames swapped in transit (UDP, a Wi-Fi bridge deliver frame N+1 before N): reordered, not
lost and not a reboot, in stats and live; the kfr reader puts the late sample in its place.
A reboot (device clock and counter restarting) is still one."""
from __future__ import annotations

from types import SimpleNamespace

import numpy as np
import pytest

from kinefuse.host.link import stats
from kinefuse.host.link.frames import decode_file
from kinefuse.host.readers import read_recording

from test_readers_kfr import MIN_LATENCY, _frames, _motion, _write_kfr

MINE = ("stats_cmd",)
SWAPS = (100, 501, 503, 1207)      # frame k arrives after k + 1 (501, 503: swaps one after another)
LATE3 = 700                         # frame 700 arrives after 703


def _arrival(n: int) -> list[int]:
    order = list(range(n))
    for k in SWAPS:
        i = order.index(k)
        order[i], order[i + 1] = order[i + 1], order[i]
    order.remove(LATE3)
    order.insert(order.index(LATE3 + 3) + 1, LATE3)
    return order


def _swapped_kfr(path, n=2000):
    """Unit 4 at 200 Hz, its frames delivered in :func:`_arrival` order."""
    t, acc, gyr, mag = _motion(n)
    fr, dev = _frames(t, acc, gyr, mag, sysid=4, boot_s=3.0, drift_ppm=40)
    _write_kfr(path, [[(t[k], fr[k]) for k in _arrival(n)]])
    return t, acc, dev


def test_sample_loss_counts_swaps_as_reordered():
    """One swap was a reset and two samples lost."""
    order = np.array(_arrival(2000))
    r = stats.sample_loss(5000 * order, order)
    assert (r["samples_lost"], r["resets"], r["duplicates"], r["reordered"]) == (0, 0, 0, len(SWAPS) + 1)
    # a genuine loss stays a loss; a reboot (clock and counter back to a time never sent) a reset
    kept = order[order != 1500]
    boot = np.arange(300)
    t = np.concatenate([5000 * kept, 250_000 + 5000 * boot])
    r = stats.sample_loss(t, np.concatenate([kept, boot]))
    assert (r["samples_lost"], r["resets"], r["reordered"]) == (1, 1, len(SWAPS) + 1)


def test_the_reorder_window():
    """Late by up to REORDER_US of device time (and its counter behind): reordered; further
    back onto a time not sent before, or with the counter ahead: a new clock segment."""
    w = stats.REORDER_US
    t = np.array([0, 1000, 2000, 2000 + w + 1000, 1000 + w, 3000 + w + 1000])
    c = np.array([0, 1, 2, 10, 9, 11])
    starts, keep = stats.device_segments(t, c)
    assert starts == [0] and keep.all()
    t2 = t.copy()
    t2[4] = 999                     # w + 1001 us behind the latest
    assert stats.device_segments(t2, c)[0] == [0, 4]
    c2 = c.copy()
    c2[4] = 12                      # counter ahead of the latest: not the same stream's sample
    assert stats.device_segments(t, c2)[0] == [0, 4]
    assert not stats.reordered(5, 3, 5, 4) and stats.reordered(4, 0xFFFFFFFF, 5, 0)   # wrap-safe


def test_stats_of_a_swapped_recording(tmp_path, run):
    p = tmp_path / "swapped.kfr"
    _swapped_kfr(p)
    (u,) = stats.compute(decode_file(p))["streams"][0]["units"]
    m = u["messages"]["KF_RAW_SAMPLE"]
    assert (m["samples_lost"], m["resets"], m["duplicates"], m["reordered"]) == (0, 0, 0, len(SWAPS) + 1)
    assert m["rate_hz"] == pytest.approx(200 * (1 + 40e-6), rel=1e-4)   # over all 10 s, not the last piece
    assert u["clock"]["drift_ppm"] == pytest.approx(40, abs=5)
    assert not u.get("warnings")
    code, out, err = run("stats", p)
    assert code == 0, err
    row = next(ln.split() for ln in out.splitlines() if ln.strip().startswith("KF_RAW_SAMPLE"))
    # lost, loss %, resets, reordered
    assert "reordered" in out and row[-4:] == ["0", "0.000", "0", str(len(SWAPS) + 1)], out


def test_the_reader_puts_a_late_sample_in_its_place(tmp_path):
    """The reader dropped the late frame of each swap (as a repeat)."""
    p = tmp_path / "swapped.kfr"
    t, acc, dev = _swapped_kfr(p)
    r = read_recording(str(p))
    assert len(r) == 2000 and r.metadata["device_clock_segments"] == 1
    assert r.channels["sample_counter"].tolist() == list(range(2000))
    assert np.array_equal(r.channels["device_time_s"], dev / 1e6)
    assert np.all(np.diff(r.t) > 0) and np.abs(r.t - (t + MIN_LATENCY)).max() < 1e-4
    from test_readers_kfr import _counts
    from kinefuse.host.link.dialect import RAW_SCALE
    assert np.array_equal(r.acc, _counts(acc, RAW_SCALE["acc"]) * RAW_SCALE["acc"])
    assert (r.metadata["reordered"], r.metadata["duplicates_dropped"], r.metadata["samples_lost"]) == \
        (len(SWAPS) + 1, 0, 0)
    assert r.warnings == []


def test_live_counts_swaps_as_reordered():
    """live took a swap for a reboot (the rate window restarted) and counted two samples lost;
    a swap across two settle_counters calls too."""
    from kinefuse.host.commands.live_cmd import UnitView
    u = UnitView(0, 1, "fake:")
    order = _arrival(2000)
    for k, c in enumerate(order):
        u.raw(SimpleNamespace(time_boot_us=5000 * c, sample_counter=c))
        if k % 10 == 0:             # the swap of 100 (arriving at 101) settles between the two
            u.settle_counters()
    u.settle_counters(final=True)
    assert (u.lost, u.resets, u.repeats, u.reordered) == (0, 0, 0, len(SWAPS) + 1)
    assert u.rate_hz == pytest.approx(200.0) and list(u.window) == sorted(u.window)
    u.raw(SimpleNamespace(time_boot_us=400_000, sample_counter=0))   # a reboot still is one
    u.settle_counters(final=True)
    assert u.resets == 1 and len(u.window) == 1
