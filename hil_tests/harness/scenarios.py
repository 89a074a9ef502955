"""One scenario format for every loop: a :class:`Case` is an IMU input record series plus truth.

Sources: the simulator (:mod:`kinefuse.hil_tests.sim`, exact ground truth) and BROAD trials
(optical reference).  Units and frames are those of the filters' ``imu`` input record:
gyr rad/s, acc m/s² (specific force, +g up at rest), mag µT, all in the sensor frame;
``dt`` s per sample; ``q_true`` (w, x, y, z) sensor → earth, earth frame East-North-Up (NaN rows
where BROAD's optical reference was lost); ``movement`` marks the samples a score uses.
"""
from __future__ import annotations

import dataclasses
from pathlib import Path

import numpy as np

from kinefuse.host.errors import KinefuseError

#: Simulator scenarios of the CI subset: short (``CI_SECONDS``), every kind of motion filters
#: care about (rest, constant rate, random rotation, translation, magnetic disturbance, gyro
#: bias, timing jitter and drops, saturation).
CI_SCENARIOS = ("rest", "constant_rotation", "slow_rotation", "fast_translation",
                "magnetic_disturbance", "bias_1dps", "jitter_and_drops", "spin_saturation")
CI_SECONDS = 12.0

#: The full scenario set of ``kinefuse sil report`` (whole scenarios).
FULL_SCENARIOS = ("rest", "constant_rotation", "slow_rotation", "fast_rotation", "translation",
                  "fast_translation", "combined", "magnetic_disturbance", "stationary_magnet",
                  "attached_magnet", "tapping", "vibration", "bias_1dps", "jitter_and_drops",
                  "spin_saturation")


@dataclasses.dataclass(eq=False)
class Case:
    """IMU samples in the filters' input record plus ground truth (units: module docstring)."""

    name: str
    source: str                      # "sim" or "broad"
    rate_hz: float
    inputs: dict[str, np.ndarray]    # gyr, acc, mag (N,3); mag_valid (N,) bool; dt (N,)
    q_true: np.ndarray               # (N,4)
    movement: np.ndarray             # (N,) bool
    t: np.ndarray                    # (N,) s

    @property
    def n(self) -> int:
        return len(self.t)

    def head(self, n: int) -> "Case":
        """The first ``n`` samples."""
        return dataclasses.replace(self, inputs={k: v[:n] for k, v in self.inputs.items()},
                                   q_true=self.q_true[:n], movement=self.movement[:n], t=self.t[:n])

    def window(self, start: int, stop: int) -> "Case":
        return dataclasses.replace(self, name=f"{self.name}[{start}:{stop}]",
                                   inputs={k: v[start:stop] for k, v in self.inputs.items()},
                                   q_true=self.q_true[start:stop], movement=self.movement[start:stop],
                                   t=self.t[start:stop] - self.t[start])


def concat(cases: list[Case], name: str | None = None) -> Case:
    """One case from several, in order (the rate of the first; each piece keeps its own ``dt``,
    so a filter continues from the previous piece's state: the jumps are part of the case)."""
    t, off = [], 0.0
    for c in cases:
        t.append(c.t - c.t[0] + off)
        off = t[-1][-1] + float(c.inputs["dt"][-1])
    return Case(name=name or "+".join(c.name for c in cases), source="+".join(sorted({c.source for c in cases})),
                rate_hz=cases[0].rate_hz,
                inputs={k: np.concatenate([c.inputs[k] for c in cases]) for k in cases[0].inputs},
                q_true=np.concatenate([c.q_true for c in cases]),
                movement=np.concatenate([c.movement for c in cases]), t=np.concatenate(t))


def _inputs(gyr, acc, mag, mag_valid, dt) -> dict[str, np.ndarray]:
    return {"gyr": np.asarray(gyr, np.float64), "acc": np.asarray(acc, np.float64),
            "mag": np.asarray(mag, np.float64), "mag_valid": np.asarray(mag_valid, bool),
            "dt": np.asarray(dt, np.float64)}


def sim_case(name: str, seed: int = 1, seconds: float | None = None, **replace) -> Case:
    """A simulator scenario (``seconds`` keeps only the beginning; ``replace`` edits the
    scenario, e.g. ``sensor={...}``)."""
    from kinefuse.hil_tests import sim

    try:
        recs = sim.run(name, seed=seed, **replace)
    except sim.SpecError as exc:
        raise KinefuseError(str(exc)) from None
    rec = recs[sorted(recs)[0]]          # multi-sensor rigs: the first unit by name
    case = Case(name=name, source="sim", rate_hz=rec.rate_hz,
                inputs=_inputs(rec.gyr, rec.acc, rec.mag, rec.mag_valid, rec.dt),
                q_true=np.asarray(rec.q_true, float), movement=np.asarray(rec.movement, bool),
                t=np.asarray(rec.t, float))
    if seconds is not None:
        case = case.head(min(case.n, int(round(seconds * case.rate_hz))))
    return case


def broad_case(path: str | Path, start: int = 0, stop: int | None = None) -> Case:
    """A BROAD trial (``.mat`` or the bundled ``.npz`` excerpt), optionally a window."""
    from kinefuse.host.broad import load_trial
    from kinefuse.host.runner import imu_inputs

    tr = load_trial(path)
    n = tr.n
    # the input record `kinefuse run` gives the filters (a simulator .mat's flags and times)
    case = Case(name=tr.name, source="broad", rate_hz=float(tr.rate_hz),
                inputs=_inputs(**imu_inputs(tr)),
                q_true=np.asarray(tr.quat_ref, float), movement=np.asarray(tr.movement, bool),
                t=np.asarray(tr.t, float))
    if start or stop is not None:
        case = case.window(start, n if stop is None else min(stop, n))
    return case


def default_broad_trial() -> Path:
    """One full BROAD trial: the shared data set when present, else the bundled excerpt."""
    from kinefuse.host import broad

    files, _where = broad.default_data()
    if not files:
        raise KinefuseError("no BROAD trial found (shared data or bundled excerpt)")
    return files[0]


#: a CI piece of a scenario whose event starts after its first ``seconds`` begins this long
#: before the event
EVENT_LEAD_S = 1.0


def scenario_events(name: str) -> list[tuple[float, float]]:
    """(start, end) in s of what a scenario does to the sensors at given times: its timed
    disturbances and the gaps of its timing model (an untimed disturbance lasts throughout)."""
    from kinefuse.hil_tests.sim.library import scenario

    sc = scenario(name)
    ev = [(float(d["t_start_s"]), float(d.get("t_end_s", np.inf)))
          for d in sc.disturbances if "t_start_s" in d]
    ev += [(float(a), float(b)) for a, b in sc.timing.get("gaps_s", ())]
    return sorted(ev)


def ci_case(name: str, seconds: float = CI_SECONDS, seed: int = 1) -> Case:
    """The CI piece of a scenario: its first ``seconds``, or, when its first event starts later
    than that (the field doubling of magnetic_disturbance at 15 s, the gap of jitter_and_drops
    at 20 s), the ``seconds`` from EVENT_LEAD_S before that event: a head alone would test the
    scenario without what it is named for."""
    starts = [a for a, _b in scenario_events(name)]
    late = [a for a in starts if a > seconds - EVENT_LEAD_S]
    if not late or len(late) < len(starts):        # no event, or one within the head
        return sim_case(name, seed=seed, seconds=seconds)
    case = sim_case(name, seed=seed)
    start = int(round((late[0] - EVENT_LEAD_S) * case.rate_hz))
    # from a sample with a magnetometer reading: a filter starting without one takes its heading
    # from gravity alone, and Madgwick's gain needs about a minute to turn it round (130 deg of
    # heading error through the whole piece) - a start-up the heads of the scenarios never have
    with_mag = np.flatnonzero(np.asarray(case.inputs["mag_valid"][start:], bool))
    start += int(with_mag[0]) if len(with_mag) else 0
    stop = min(case.n, start + int(round(seconds * case.rate_hz)))
    return dataclasses.replace(case.window(start, stop),
                               name=f"{name} {start / case.rate_hz:g}-{stop / case.rate_hz:g} s")


def ci_cases(seconds: float = CI_SECONDS, seed: int = 1) -> list[Case]:
    return [ci_case(n, seconds=seconds, seed=seed) for n in CI_SCENARIOS]


def full_cases(seed: int = 1, broad: str | Path | None = None,
               scenarios: tuple[str, ...] = FULL_SCENARIOS) -> list[Case]:
    cases = [sim_case(n, seed=seed) for n in scenarios]
    if broad != "none":
        cases.append(broad_case(broad or default_broad_trial()))
    return cases
