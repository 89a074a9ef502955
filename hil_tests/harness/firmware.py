"""Firmware loops: the unit application receiving samples as HIL_SENSOR over its UART.

* ``sil-f32`` / ``sil-q``: the application built for the host (``firmware/ports/host``),
  talking over a pseudo-terminal;
* ``pil-m4f-f32`` / ``pil-m4f-q``: the application built for the Cortex-M4F (``mps2-an386``) in
  QEMU with float32 / fixed-point filters (``build_target("m4f", system="q")``); ``pil-m0-q``:
  Cortex-M0 (``mps2-an385``), fixed-point filters; UART0 on a loopback TCP port.  The PIL images hold every
  wired filter (``filters="all"``: the M0's default build has only four, to fit a 256 kB part;
  QEMU's board has room for all).

The host encodes HIL_SENSOR frames (sensor frame, SI, mag in gauss), the unit answers each
sample with KF_RAW_SAMPLE (the counts it derived) and KF_ORIENTATION, decoded by the real host
decoder (:mod:`kinefuse.host.link`).  The expected output is what the generated Python models
compute for that path (:func:`kinefuse.firmware.hostunit.unit_model`: counts, the generated
calibration map, the filter).  Compared bit for bit: every KF_RAW_SAMPLE count, KF_ORIENTATION's
quaternion and covariance (binary32), and for the q builds the raw Q-format quaternion, which the
unit sends in a MEMORY_VECT after each KF_ORIENTATION when ``KF_HIL_MODE`` has bit 1 set (the
harness sets it).  A q build's covariance is compared as the binary32 the unit sends,
``float32(raw) * 2^-frac``, against the model's raw value through the same conversion (no raw
covariance goes over the link).

:class:`UnitRunner` keeps one unit (host process or QEMU) for many runs: each run selects the
filter afresh (KF_FILTER 0, then the filter: a new state, the first sample gets the nominal
time step).  QEMU's UART delivers one byte at a time: a few hundred samples per second
(README, "Software- and processor-in-the-loop"); PIL runs in CI use slices (``PIL_SAMPLES``),
``kinefuse sil report --firmware --pil-samples 0`` whole cases.
"""
from __future__ import annotations

import contextlib
from dataclasses import dataclass

import numpy as np

from kinefuse.host.errors import KinefuseError

FIRMWARE_LOOPS = {"f32": ("sil-f32", "pil-m4f-f32"), "q": ("sil-q", "pil-m4f-q", "pil-m0-q")}
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
        # [:k]: no samples give no stamps (not the lone first stamp of an empty case)
        t = t0_us + np.round(np.concatenate([[0.0], np.cumsum(case.inputs["dt"][1:k])])[:k] * 1e6).astype(np.int64)
        mag = np.nan_to_num(case.inputs["mag"][:k], nan=0.0)
        return cls(t, case.inputs["acc"][:k], case.inputs["gyr"][:k], mag,
                   case.inputs["mag_valid"][:k] & np.all(np.isfinite(case.inputs["mag"][:k]), axis=1),
                   int(round(case.rate_hz)))

    def inputs(self) -> dict[str, np.ndarray]:
        """The per-sample inputs a mismatch report names."""
        return {"time_us": self.time_us, "acc": self.acc, "gyr": self.gyr, "mag": self.mag,
                "mag_valid": self.mag_valid}


def loop_target(loop: str) -> tuple[str, str]:
    """("host" | "m4f" | "m0", "f32" | "q") of a firmware loop name."""
    parts = loop.split("-")
    if parts[0] == "sil" and len(parts) == 2 and parts[1] in ("f32", "q"):
        return "host", parts[1]
    if parts[0] == "pil" and len(parts) == 3 and parts[1] in ("m4f", "m0") and parts[2] in ("f32", "q"):
        return parts[1], parts[2]
    raise KinefuseError(f"unknown firmware loop {loop!r}")


def pil_image(loop: str):
    """The cross-built application of a PIL loop (every wired filter), cached."""
    from kinefuse.firmware.build import build_target
    target, system = loop_target(loop)
    return build_target(target, filters="all", system=system)


@contextlib.contextmanager
def unit_session(loop: str):
    """A :class:`kinefuse.host.link.session.Session` to a running unit for ``loop``."""
    from kinefuse.host.link.session import Session
    target, system = loop_target(loop)
    if target == "host":
        from kinefuse.firmware.hostunit import HostUnit
        with HostUnit(system, sensor=False) as unit:
            s = unit.session()
            try:
                yield s
            finally:
                s.close()
        return
    from kinefuse.hil_tests.qemu.runner import QemuSession
    from kinefuse.host.link.connection import open_connection
    fw = pil_image(loop)
    # UART0 on a loopback TCP port (QEMU holds the board until the host connects): 1.3-1.6x the
    # samples per second of a pty, with less of QEMU's time in system calls (measured)
    with QemuSession(fw.elf, target, uart="tcp") as q:
        s = Session(open_connection(q.uart_url))
        try:
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
    """Rate, HIL mode, then the filter: KF_FILTER goes through 0 so that the filter restarts even
    when it was selected already (a fresh state; the next sample gets the nominal time step)."""
    from kinefuse.host.link.params import ParamClient
    # Emulated boards answer slowly: with ParamClient's default 0.5 s a retried read's late
    # PARAM_VALUE can be taken as the answer to the following PARAM_SET ("unit kept" the old
    # value).  A long timeout, and the queue drained after each read, avoid that race.
    pc = ParamClient(session, 1, timeout=timeout)
    for k, v in (("KF_RATE_HZ", rate_hz), ("KF_HIL_MODE", mode), ("KF_FILTER", 0),
                 ("KF_FILTER", filter_ids()[name])):
        pc.get(k)
        session.poll(0.05)
        session.drain()
        pc.set(k, v)


class UnitRunner:
    """One running unit for ``loop`` (host process or QEMU board), many HIL runs.

    ``with UnitRunner("pil-m0-q") as u: got = u.run("flagship", hil)``."""

    def __init__(self, loop: str, window: int = 50, timeout: float = 60.0):
        self.loop, self.window, self.timeout = loop, window, timeout
        self.target, self.system = loop_target(loop)
        self._cm = None
        self.session = None
        self.samples = 0
        self.seconds = 0.0           # time spent streaming samples (configuration excluded)

    def __enter__(self) -> "UnitRunner":
        self._cm = unit_session(self.loop)
        self.session = self._cm.__enter__()
        return self

    def __exit__(self, *exc) -> None:
        cm, self._cm, self.session = self._cm, None, None
        if cm is not None:
            cm.__exit__(*exc)

    def run(self, name: str, hil: "HilInput") -> dict:
        """The unit's answers to ``hil`` from a freshly selected ``name`` (``hil_run``'s arrays;
        q loops also ``q_raw``)."""
        import time

        from kinefuse.firmware.hostunit import HIL_Q_RAW, hil_run
        q_raw = self.system == "q"
        configure(self.session, name, hil.rate_hz, mode=HIL_Q_RAW if q_raw else 0)
        t0 = time.perf_counter()
        got = hil_run(self.session, hil.time_us, hil.acc, hil.gyr, hil.mag, hil.mag_valid,
                      window=self.window, timeout=self.timeout, q_raw=q_raw)
        self.seconds += time.perf_counter() - t0
        self.samples += len(hil.time_us)
        return got


def run_unit(loop: str, name: str, hil: HilInput, window: int = 50, timeout: float = 60.0) -> dict:
    """The unit's answers to the case (a unit started for this one run)."""
    with UnitRunner(loop, window=window, timeout=timeout) as u:
        return u.run(name, hil)


def expected(name: str, system: str, hil: HilInput) -> dict:
    from kinefuse.firmware.hostunit import unit_model
    return unit_model(name, system, hil.time_us, hil.acc, hil.gyr, hil.mag, hil.mag_valid,
                      rate_hz=hil.rate_hz, mode=0)


def compared_outputs(system: str, unit_out: dict, from_model: bool) -> dict:
    """The outputs compared bit for bit (unit answers or unit model, same names)."""
    counts = unit_out["counts"] if from_model else \
        np.concatenate([unit_out["acc"], unit_out["gyr"], unit_out["mag"]], axis=1)
    # KF_RAW_SAMPLE's gyro fields are in units of 2^gyro_shift mrad/s: the shift is compared too
    out = {"q": unit_out["q"], "cov": unit_out["cov"], "counts": counts, "gyro_shift": unit_out["gyro_shift"]}
    if system == "q":
        out["q_raw"] = unit_out["q_raw"]
    return out


def compare_unit(loop: str, name: str, case, n: int | None = None, runner: UnitRunner | None = None):
    """(Mismatch or None, got, expected) for one firmware loop on one case (``n``: its first
    samples; None: ``PIL_SAMPLES`` on PIL loops, the whole case on SIL; 0: the whole case).
    ``runner``: a running unit for ``loop`` (else one is started for this case)."""
    from kinefuse.hil_tests.harness.compare import compare
    _target, system = loop_target(loop)
    if n is None:
        n = PIL_SAMPLES if loop.startswith("pil-") else 0
    hil = HilInput.from_case(case, n or None)
    if runner is not None:
        if runner.loop != loop:
            raise KinefuseError(f"runner is for {runner.loop}, not {loop}")
        got = runner.run(name, hil)
    else:
        got = run_unit(loop, name, hil)
    ref = expected(name, system, hil)
    m = compare(f"{system} unit model", compared_outputs(system, ref, True), loop,
                compared_outputs(system, got, False), hil.inputs())
    return m, got, ref


def run_firmware_loop(loop, name, info, e):  # pragma: no cover - loops.run_loop dispatch
    raise KinefuseError("firmware loops take HIL input (counts + calibration), not the filter's "
                        "encoded record: use harness.firmware.compare_unit")
