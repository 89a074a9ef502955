"""Knee/elbow pipelines on simulated recordings with known joint angles; cycles; outputs."""
import os

import numpy as np
import pytest

from kinefuse.host.errors import KinefuseError
from kinefuse.host.kinematics import cycles, orientation, report, simulate
from kinefuse.host.kinematics import quat as Q


@pytest.fixture(scope="module")
def protocol():
    return simulate.knee_protocol(seed=0)


def pair(d):
    return d["thigh"], d["shank"]


def rmse(res, P):
    truth = P.truth.angles_deg[: len(res.t)]
    return np.sqrt(((res.angles - truth) ** 2).mean(axis=0))


@pytest.fixture(scope="module")
def calibrated(protocol):
    P = protocol
    return report.knee_from_recordings(*pair(P.task), standing=pair(P.standing), lying=pair(P.lying),
                                       mag_recordings=pair(P.mag))


def test_knee_figure_two_posture_with_10deg_misalignment(protocol, calibrated):
    """Required figure: simulated step-up, sensor noise, 10° misalignment, two-posture
    calibration → flexion RMSE ≤ 2°, ab/adduction and rotation ≤ 3°."""
    e = rmse(calibrated, protocol)
    assert e[0] <= 2.0 and e[1] <= 3.0 and e[2] <= 3.0, e
    assert 8.0 < calibrated.info["thigh_mounting_deg"] < 12.0
    assert calibrated.info["heading_alignment"].startswith("none")      # 9-D, magnetic north
    # without the calibration the same data are clearly worse
    raw = report.knee_from_recordings(*pair(protocol.task), mag_recordings=pair(protocol.mag))
    assert rmse(raw, protocol).max() > 2 * e.max()
    assert any("no standing/lying calibration" in w for w in raw.warnings)


def test_knee_from_device_quaternions_with_different_heading_references(protocol):
    """Devices that report their own quaternions in unrelated heading frames (Xsens DOT): the
    shank heading is aligned to the thigh's in the standing posture."""
    P = protocol
    rng = np.random.default_rng(9)

    def with_quat(rec, yaw_deg):
        r = simulate.Recording(**{**rec.__dict__})
        noise = Q.from_rotvec(np.radians(0.2) * rng.standard_normal((len(rec.t), 3)))
        r.quat = Q.mul(Q.mul(Q.elementary("Z", np.radians(yaw_deg)), rec.metadata["quat_true"]), noise)
        return r

    yaw = {"thigh": 40.0, "shank": -75.0}
    task = {s: with_quat(P.task[s], yaw[s]) for s in yaw}
    stand = {s: with_quat(P.standing[s], yaw[s]) for s in yaw}
    res = report.knee_from_recordings(*pair(task), standing=pair(stand), lying=pair(P.lying))
    assert res.info["thigh_orientation"] == "device quaternions"
    assert res.info["heading_alignment"]["reference"] == "standing posture"
    e = rmse(res, P)
    assert e[0] <= 2.0 and e[1] <= 3.0 and e[2] <= 3.0, e
    assert not any("magnetometer calibration not used" in w for w in res.warnings)
    # a figure-eight calibration cannot reach the device's quaternions: said, not dropped silently
    res = report.knee_from_recordings(*pair(task), standing=pair(stand), lying=pair(P.lying),
                                      mag_recordings=pair(P.mag))
    for seg in ("thigh", "shank"):
        assert any(w.startswith(f"{seg} magnetometer calibration not used: the orientation is the device's")
                   for w in res.warnings), res.warnings


def test_step_up_cycles_and_normalisation(protocol, calibrated):
    cs = report.detect_cycles(calibrated, "knee")
    assert len(cs.bounds) == 10 and len(cs.curves) == 10 and not cs.rejected
    # extension (minimum flexion) sits near 50 % of the cycle, as in seed 001 Fig. 8.2
    assert 40 <= int(np.argmin(cs.mean[:, 0])) <= 60
    assert cs.curves.shape == (10, cycles.N_POINTS, 3)
    rom = cs.rom()
    truth_rom = np.ptp(protocol.truth.angles_deg[:, 0][protocol.truth.cycle_starts[1]:protocol.truth.cycle_starts[-1]])
    assert abs(rom["rom_mean"][0] - truth_rom) < 6.0
    # edge cycles can be dropped; an outlier cycle is rejected
    assert len(cycles.normalise(calibrated.t, calibrated.angles, cs.bounds, drop_edge=1).curves) == 8
    bad = calibrated.angles.copy()
    i0, i1 = cs.bounds[4]
    bad[i0:i1, 0] += 25.0
    cs2 = cycles.normalise(calibrated.t, bad, cs.bounds)
    assert [k for k, _ in cs2.rejected] == [4]
    with pytest.raises(KinefuseError, match="no flexion"):
        cycles.step_up_bounds(calibrated.t, np.zeros(len(calibrated.t)))


def test_report_files(tmp_path, calibrated):
    cs = report.detect_cycles(calibrated, "knee")
    s = report.write_report(str(tmp_path), "knee", calibrated, cs, title="Right knee, step-up",
                            inputs={"thigh": "a.csv", "shank": "b.csv"})
    for f in s["files"]:
        assert os.path.getsize(tmp_path / f) > 0
    head = open(tmp_path / "knee_mean_sd.csv").read().splitlines()[:2]
    assert head[0].startswith("# right knee") and "Grood & Suntay" in head[0] and "+adduction" in head[0]
    assert head[1].startswith("percent,flexion_mean_deg,flexion_sd_deg")
    data = np.loadtxt(tmp_path / "knee_cycles.csv", delimiter=",", comments="#", skiprows=2)
    assert data.shape == (10 * cycles.N_POINTS, 5)
    md = open(tmp_path / "knee_summary.md").read()
    assert "Range of motion" in md and "two-posture" in md
    assert open(tmp_path / "knee_angles.png", "rb").read(8) == b"\x89PNG\r\n\x1a\n"
    assert s["n_cycles_kept"] == 10


def _elbow_recordings(seed=0):
    return simulate.elbow_flexion(seed)


def test_elbow_pipeline_flexion():
    arm, fore, flex = _elbow_recordings()
    res = report.elbow_from_recordings(arm, fore)
    assert np.sqrt(np.mean((res.angles[:, 0] - flex[: len(res.t)]) ** 2)) < 2.0
    cs = report.detect_cycles(res, "elbow")
    assert len(cs.curves) == 6          # first from motion onset, last until rest
    assert abs(cs.rom()["rom_mean"][0] - 90.0) < 3.0


def test_filter_parameter_resolution():
    assert orientation.resolve_filter("simple") is orientation.complementary_filter
    f = orientation.resolve_filter("kinefuse.host.kinematics.orientation:complementary_filter")
    assert f is orientation.complementary_filter
    with pytest.raises(KinefuseError, match="unknown orientation filter"):
        orientation.resolve_filter("kalman9000")
    with pytest.raises(KinefuseError, match="cannot load"):
        orientation.resolve_filter("no.such.module:f")
    # a custom callable is used as is; a broken one is reported in one line
    arm, fore, _ = _elbow_recordings()
    with pytest.raises(KinefuseError, match="returned"):
        report.elbow_from_recordings(arm, fore, filter=lambda t, a, g, m: np.zeros((3, 4)))


def test_a_failing_user_filter_is_a_one_line_error():
    """--filter module:function whose call raises was an internal error ('please report it');
    it is the user's function, named in a one-line error."""
    arm, fore, _ = _elbow_recordings()
    with pytest.raises(KinefuseError, match=r"orientation filter 'os:getcwd' failed: TypeError: .*"
                                            r"called as f\(t, acc, gyr, mag\)"):
        report.elbow_from_recordings(arm, fore, filter="os:getcwd")

    def broken(t, acc, gyr, mag):
        raise ZeroDivisionError("division by zero")
    with pytest.raises(KinefuseError, match="failed: ZeroDivisionError: division by zero"):
        report.elbow_from_recordings(arm, fore, filter=broken)


@pytest.mark.parametrize("fs", [60.0, 100.0])
def test_step_up_cycle_durations_are_the_period(fs):
    """Step-up cycles ended one sample before the next one's start: every duration one sample
    short (2.99 s for 3 s at 100 Hz) and 100 % not the next cycle's 0 %.  The elbow's cycles
    (between minima) already included their end sample."""
    P = 3.0
    t = np.arange(0, 8 * P, 1 / fs)
    flex = 40 + 40 * np.cos(2 * np.pi * t / P)          # extensions at P/2 + kP
    b = cycles.step_up_bounds(t, flex)
    cs = cycles.normalise(t, np.column_stack([flex] * 3), b)
    assert len(b) == 7
    np.testing.assert_allclose(cs.durations_s, P, atol=1e-9)
    assert all(b[k][1] - 1 == b[k + 1][0] for k in range(len(b) - 1))     # end sample = next start
    np.testing.assert_allclose(cs.curves[:, 0, 0], cs.curves[:, -1, 0], atol=1e-9)   # 0 % = 100 %


def test_elbow_summary_names_the_gyroscope_bias_it_removed():
    """The elbow pipeline removed a gyroscope bias from each sensor (static windows of the task)
    but, unlike the knee's, its summary did not list that processing step."""
    arm, fore, _ = _elbow_recordings()
    res = report.elbow_from_recordings(arm, fore)
    for seg in ("arm", "forearm"):
        b = res.info[f"{seg}_gyro_bias_rad_s"]
        assert len(b["value"]) == 3 and np.any(np.asarray(b["value"]) != 0)
        assert "static samples of" in b["source"]


def test_mag_calibration_unused_for_lack_of_magnetometer_is_a_warning(protocol):
    """Figure-eight recordings given for task recordings without a magnetometer were fitted and
    then dropped without a word: the summary listed the calibration among the inputs and ran 6-D."""
    import dataclasses
    P = protocol
    task = [dataclasses.replace(r, mag=None) for r in pair(P.task)]
    res = report.knee_from_recordings(*task, standing=pair(P.standing), lying=pair(P.lying),
                                      mag_recordings=pair(P.mag))
    for seg in ("thigh", "shank"):
        assert any(w.startswith(f"{seg} magnetometer calibration given") and "no magnetometer data" in w
                   for w in res.warnings), res.warnings
        assert res.info[f"{seg}_orientation"].endswith("(6-D)")


def test_a_filter_the_device_quaternions_replace_is_a_warning(protocol):
    """--filter with recordings that carry device quaternions (orientation 'auto') was dropped
    without a word: the report read as the filter's, its angles were the device's."""
    import dataclasses
    P = protocol
    task = {s: dataclasses.replace(P.task[s], quat=P.task[s].metadata["quat_true"]) for s in P.task}
    res = report.knee_from_recordings(*pair(task), filter="madgwick")
    for seg in ("thigh", "shank"):
        assert res.info[f"{seg}_orientation"] == "device quaternions"
        assert any(w.startswith(f"{seg}: filter 'madgwick' not used:") and "device quaternions" in w
                   for w in res.warnings), res.warnings
    # the filter where it runs, and no filter asked for: no such warning
    for kw in ({"filter": "madgwick", "orientation": "filter"}, {}):
        res = report.knee_from_recordings(*pair(task), **kw)
        assert not any("not used: " in w and "filter" in w for w in res.warnings), res.warnings
    arm, fore, _ = _elbow_recordings()
    arm = dataclasses.replace(arm, quat=Q.normalize(np.tile([1.0, 0, 0, 0], (len(arm.t), 1))))
    res = report.elbow_from_recordings(arm, fore, filter="simple")
    assert [w for w in res.warnings if "not used" in w] == [
        f"arm: filter 'simple' not used: {os.path.basename(arm.source)} has device quaternions, "
        f"and orientation 'auto' uses them (orientation 'filter' runs the filter)"]


def test_unit_calibration_of_readings_the_unit_calibrated_is_refused(protocol):
    """A .kfr whose samples the unit had calibrated (flag 'calibrated') got the unit file's maps
    applied once more: biases removed twice, scales squared, without a word."""
    import dataclasses
    from kinefuse.host.calib import unitfile
    P = protocol
    doc = unitfile.new("DOT-7")
    unitfile.set_sensor(doc, "gyro", np.eye(3), [0.01, 0.0, 0.0], method="static")
    task = {s: dataclasses.replace(P.task[s], metadata={**P.task[s].metadata, "calibrated_on_unit": True})
            for s in P.task}
    with pytest.raises(KinefuseError, match=r"applied its stored calibration to these readings already"):
        report.knee_from_recordings(*pair(task), unit_calibrations=(doc, doc))
    arm, fore, _ = _elbow_recordings()
    cal_arm = dataclasses.replace(arm, metadata={**arm.metadata, "calibrated_on_unit": True})
    with pytest.raises(KinefuseError, match=r"\(--unit-cal\) would apply one a second time"):
        report.elbow_from_recordings(cal_arm, fore, unit_calibrations=(doc, doc))
    # readings the unit did not calibrate take the file, and calibrated ones without a file run
    raw = {s: dataclasses.replace(P.task[s], metadata={**P.task[s].metadata, "calibrated_on_unit": False})
           for s in P.task}
    report.knee_from_recordings(*pair(raw), unit_calibrations=(doc, doc))
    report.elbow_from_recordings(cal_arm, fore)
