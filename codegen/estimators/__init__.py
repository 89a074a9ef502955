"""The estimators' reference code.  Every estimator listed here is generated to float32 C,
fixed-point C and their Python models by `kinefuse codegen`."""
from __future__ import annotations

from kinefuse.codegen.estimator import Estimator
from kinefuse.codegen.estimators.complementary import Complementary
from kinefuse.codegen.estimators.flagship import Flagship
from kinefuse.codegen.estimators.eskf import Eskf
from kinefuse.codegen.estimators.madgwick import Madgwick
from kinefuse.codegen.estimators.ecompass import Ecompass
from kinefuse.codegen.estimators.triad import Triad
from kinefuse.codegen.estimators.vac import Vac
from kinefuse.codegen.estimators.vak import Vak
from kinefuse.codegen.estimators.guo import Guo
from kinefuse.codegen.estimators.angle_kf import AngleEKF, AngleKF, AngleSRUKF, AngleUKF
from kinefuse.codegen.estimators.mahony import Mahony
from kinefuse.codegen.estimators.dynamics.pendulum import PendulumEKF
from kinefuse.codegen.estimators.dynamics.leg import LegEKF, LegFootEKF
from kinefuse.codegen.estimators.calib_apply import CalibApply
from kinefuse.codegen.estimators.joint_angle import JointAngle

# Registry order = order in `kinefuse filters`.
ESTIMATORS: dict[str, type[Estimator]] = {cls.name: cls for cls in (
    Madgwick,
    Mahony,
    Complementary,
    Ecompass,
    Triad,
    Vac,
    Vak,
    Guo,
    AngleKF,
    AngleEKF,
    AngleUKF,
    AngleSRUKF,
    Flagship,
    Eskf,
    PendulumEKF,
    LegEKF,
    LegFootEKF,
    CalibApply,
    JointAngle,
)}


def get(name: str) -> Estimator:
    """An instance of the registered estimator `name` (ValueError naming the choices if unknown)."""
    try:
        return ESTIMATORS[name]()
    except KeyError:
        raise ValueError(f"unknown filter {name!r} (available: {', '.join(ESTIMATORS)})") from None
