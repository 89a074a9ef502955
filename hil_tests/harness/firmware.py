"""Firmware loops: the unit application receiving samples as HIL_SENSOR over its UART.

* ``sil-f32`` / ``sil-q``: the application built for the host (``firmware/ports/host``),
  talking over a pseudo-terminal;
* ``pil-m4f-f32``: the application built for the Cortex-M4F (``mps2-an386``) in QEMU, float32
  filters; ``pil-m0-q``: Cortex-M0 (``mps2-an385``), fixed-point filters; UART0 on a pty.  Both
  PIL images hold every wired filter (``filters="all"``: the M0's default build has only four,
  to fit a 256 kB part; QEMU's board has room for all).

The host encodes HIL_SENSOR frames (sensor frame, SI, mag in gauss), the unit answers each
sample with KF_RAW_SAMPLE (the counts it derived) and KF_ORIENTATION, decoded by the real host
decoder (:mod:`kinefuse.host.link`).  The expected output is what the generated Python models
compute for that path (:func:`kinefuse.firmware.hostunit.unit_model`: counts, the generated
calibration map, the filter).  KF_ORIENTATION carries binary32, so the q builds are compared
on ``float32(raw · 2^-frac)`` — the raw Q values are compared bit for bit in the batch loops.

QEMU's UART moves a few kB/s: PIL runs use short scenarios (``PIL_SAMPLES``).
"""
from __future__ import annotations

import contextlib
from dataclasses import dataclass

import numpy as np

from kinefuse.host.errors import KinefuseError

FIRMWARE_LOOPS = {"f32": ("sil-f32", "pil-m4f-f32"), "q": ("sil-q", "pil-m0-q")}
PIL_SAMPLES = 300


def firmware_missing() -> str | None:
    """None when the unit application and its host tools are in the tree, else why not."""
    try:
        import kinefuse.firmware.build  # noqa: F401
        import kinefuse.firmware.hostunit  # noqa: F401
    except ImportError as exc:
        return f"firmware application not available ({exc})"
    return None


def filter_ids() -> dict[str, int]:
    """Registry name -> KF_FILTER id of the filters wired into the application."""
    from kinefuse.firmware import apptables
    return {e.name: int(e.id) for e in apptables.read_list()}


def firmware_loops(name: str, system: str) -> list[str]:
    if firmware_missing() or name not in filter_ids():
        return []
    return list(FIRMWARE_LOOPS[system])


@dataclass
class HilInput:
    """A case as the unit receives it over HIL (µs stamps on the unit's clock)."""

    time_us: np.ndarray
    acc: np.ndarray          # m/s²
    gyr: np.ndarray          # rad/s
    mag: np.ndarray          # µT
    mag_valid: np.ndarray
    rate_hz: int

    @classmethod
    def from_case(cls, case, n: int | None = None, t0_us: int = 1_000_000) -> "HilInput":
        k = case.n if n is None else min(n, case.n)
        t = t0_us + np.round(np.concatenate([[0.0], np.cumsum(case.inputs["dt"][1:k])]) * 1e6).astype(np.int64)
        mag = np.nan_to_num(case.inputs["mag"][:k], nan=0.0)
        return cls(t, case.inputs["acc"][:k], case.inputs["gyr"][:k], mag,
                   case.inputs["mag_valid"][:k] & np.all(np.isfinite(case.inputs["mag"][:k]), axis=1),
                   int(round(case.rate_hz)))


@contextlib.contextmanager
def unit_session(loop: str):
    """A :class:`kinefuse.host.link.session.Session` to a running unit for ``loop``."""
    from kinefuse.host.link.connection import open_tty_raw
    from kinefuse.host.link.session import Session
    if loop.startswith("sil-"):
        from kinefuse.firmware.hostunit import HostUnit
        with HostUnit(loop.split("-")[1], sensor=False) as unit:
            s = unit.session()
            try:
                yield s
            finally:
                s.close()
        return
    if not loop.startswith("pil-"):
        raise KinefuseError(f"unknown firmware loop {loop!r}")
    from kinefuse.firmware.build import build_target
    from kinefuse.hil_tests.qemu.runner import QemuSession
    target = loop.split("-")[1]
    fw = build_target(target, filters="all")   # every wired filter (the M0 default set has four)
    with QemuSession(fw.elf, target, uart="pty", paused=True) as q:
        s = Session(open_tty_raw(q.uart_device))
        try:
            q.resume()
            wait_ready(s, loop)
            yield s
        finally:
            s.close()


def wait_ready(session, what: str, timeout: float = 60.0) -> None:
    """Ask for a parameter until the unit answers: bytes sent while the board boots and loads
    its storage may be lost, as on a unit just powered up (waiting for the 1 Hz HEARTBEAT
    instead costs up to a second of emulated time, which is much longer under load).  The
    probe reads a parameter nobody configures next, so late answers cannot be mistaken for
    the answer to a write."""
    import time
    deadline = time.monotonic() + timeout
    while time.monotonic() < deadline:
        session.send("PARAM_REQUEST_READ", target_system=1, target_component=200,
                     param_id="KF_SERIAL_NO", param_index=-1)
        if session.wait_for("PARAM_VALUE", timeout=0.5) is not None:
            session.poll(0.2)
            session.drain()
            return
    raise KinefuseError(f"{what}: the unit did not answer within {timeout:.0f} s")


def configure(session, name: str, rate_hz: int, mode: int = 0, timeout: float = 5.0) -> None:
    from kinefuse.host.link.params import ParamClient
    # Emulated boards answer slowly: with ParamClient's default 0.5 s a retried read's late
    # PARAM_VALUE can be taken as the answer to the following PARAM_SET ("unit kept" the old
    # value).  A long timeout, and the queue drained after each read, avoid that race.
    pc = ParamClient(session, 1, timeout=timeout)
    for k, v in (("KF_FILTER", filter_ids()[name]), ("KF_RATE_HZ", rate_hz), ("KF_HIL_MODE", mode)):
        pc.get(k)
        session.poll(0.05)
        session.drain()
        pc.set(k, v)


def run_unit(loop: str, name: str, hil: HilInput, window: int = 50, timeout: float = 30.0) -> dict:
    """The unit's answers to the case (``hil_run``'s arrays: q float32, counts, counters...)."""
    from kinefuse.firmware.hostunit import hil_run
    with unit_session(loop) as s:
        configure(s, name, hil.rate_hz)
        return hil_run(s, hil.time_us, hil.acc, hil.gyr, hil.mag, hil.mag_valid, window=window,
                       timeout=timeout)


def expected(name: str, system: str, hil: HilInput) -> dict:
    from kinefuse.firmware.hostunit import unit_model
    return unit_model(name, system, hil.time_us, hil.acc, hil.gyr, hil.mag, hil.mag_valid,
                      rate_hz=hil.rate_hz, mode=0)


def compare_unit(loop: str, name: str, case, n: int | None = None):
    """(Mismatch or None, got, expected) for one firmware loop on one case."""
    from kinefuse.hil_tests.harness.compare import compare
    system = loop.rsplit("-", 1)[-1]
    hil = HilInput.from_case(case, n if n is not None else (PIL_SAMPLES if loop.startswith("pil-") else None))
    got = run_unit(loop, name, hil)
    ref = expected(name, system, hil)
    inputs = {"time_us": hil.time_us, "acc": hil.acc, "gyr": hil.gyr, "mag": hil.mag,
              "mag_valid": hil.mag_valid}
    counts = np.concatenate([got["acc"], got["gyr"], got["mag"]], axis=1)
    m = compare(f"{system} unit model", {"q": ref["q"], "counts": ref["counts"]}, loop,
                {"q": got["q"], "counts": counts}, inputs)
    return m, got, ref


def run_firmware_loop(loop, name, info, e):  # pragma: no cover - loops.run_loop dispatch
    raise KinefuseError("firmware loops take HIL input (counts + calibration), not the filter's "
                        "encoded record: use harness.firmware.compare_unit")
