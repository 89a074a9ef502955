"""kinefuse.hil_tests.sim — motion and sensor simulator: ground truth for every filter test.

Quick use::

    from kinefuse.hil_tests import sim
    rec = sim.simulate("slow_rotation", seed=1)          # one sensor → Recording
    recs = sim.run("gait", seed=1)                        # {"thigh": Recording, "shank": ...}
    broad = rec.to_broad()                                # BROAD trial layout for the runners
    sc = sim.scenario("rest").replace(sensor={"preset": "xsens_dot", "rate_hz": 60})

Conventions: quaternions (w,x,y,z) sensor → earth, earth frame East-North-Up (z up); gyr rad/s
(sensor frame), acc m/s² specific force (+g up at rest), mag µT, t in s.  See the module
docstrings: segments (single-body motion), gait, hinge, disturbances, sensor, presets, timing,
recording, scenario, library.
"""
from .library import names, scenario
from .presets import PRESET_NAMES, preset
from .recording import RAW_DTYPE, Recording
from .scenario import Scenario, build, run, simulate
from .segments import SpecError

__all__ = ["names", "scenario", "preset", "PRESET_NAMES", "Recording", "RAW_DTYPE", "Scenario",
           "build", "run", "simulate", "SpecError"]
