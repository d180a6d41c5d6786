"""The wheelset call from Python (python/wheelset_module.cpp, mhcontact.Wheelset): the same numbers
as the single-pair call and as single steps, broadcasting, threads, the GIL released, errors.
Breaks guarded (each seen to fail): the binding reading Q_right_N for the left wheel fails
test_each_wheel_is_the_pair_call; the GIL kept during the steps fails test_gil_released."""
import threading
import time

import numpy as np
import pytest

import mhcontact


@pytest.fixture(scope="module")
def pair():
    return mhcontact.Pair(mhcontact.Profile.standard("S1002"), mhcontact.Profile.standard("60E1"),
                          {"rail_inclination": "1:40"})


@pytest.fixture(scope="module")
def wheelset(pair):
    return mhcontact.Wheelset(pair, pair, mu=0.3)


def test_each_wheel_is_the_pair_call(pair):
    ws = mhcontact.Wheelset(pair, pair)  # no friction: the normal forces alone
    y = np.linspace(-6e-3, 8e-3, 15)
    out = ws.step(y, Q_left_N=60e3, Q_right_N=40e3)
    # Each wheel is the pair's solve at that wheel's own t_Y and its roll against its rail,
    # sigma * roll (sigma +1 left, -1 right; docs/c-api.md "The wheelset call").
    for i in range(len(y)):
        roll = out["roll_rad"][i]
        left = pair.solve(out["left_tY_m"][i], Q_N=60e3, roll_rad=roll)
        right = pair.solve(out["right_tY_m"][i], Q_N=40e3, roll_rad=-roll)
        # Fz of each wheel on the wheelset: the pair's Fz (kN in the pair's columns).
        assert out["left_F_N"][i, 2] == pytest.approx(left["Fz_kN"] * 1e3, rel=1e-12)
        assert out["right_F_N"][i, 2] == pytest.approx(right["Fz_kN"] * 1e3, rel=1e-12)
        # Lateral: the left rail's field side is +y, the right one's -y; forces on the wheel oppose the rail's.
        assert out["left_F_N"][i, 1] == pytest.approx(-left["Fy_kN"] * 1e3, rel=1e-12, abs=1e-6)
        assert out["right_F_N"][i, 1] == pytest.approx(right["Fy_kN"] * 1e3, rel=1e-12, abs=1e-6)
        assert out["left_status"][i] == left["status"]


def test_mirror_and_broadcast(wheelset):
    y = np.array([2e-3, 5e-3, 7.5e-3])
    a = wheelset.step(y, Q_left_N=50e3, Q_right_N=50e3, V_m_per_s=30.0)
    b = wheelset.step(-y, Q_left_N=50e3, Q_right_N=50e3, V_m_per_s=30.0)
    np.testing.assert_allclose(a["F_N"][:, 1], -b["F_N"][:, 1], rtol=1e-12, atol=1e-6)
    np.testing.assert_allclose(a["left_N_N"], b["right_N_N"], rtol=1e-12)
    assert a["F_N"].shape == (3, 3)


def test_threads_give_the_same_numbers(wheelset):
    y = np.linspace(-7e-3, 7e-3, 3000)
    one = wheelset.step(y, Q_left_N=50e3, Q_right_N=45e3, yaw_rad=1e-3, V_m_per_s=30.0, threads=1)
    two = wheelset.step(y, Q_left_N=50e3, Q_right_N=45e3, yaw_rad=1e-3, V_m_per_s=30.0, threads=2)
    for k in ("F_N", "M_N_m", "left_N_N", "roll_rad"):
        np.testing.assert_array_equal(one[k], two[k])


def test_position_roll_solved_and_derivatives(wheelset):
    lifted = wheelset.step(3e-3, Z_m=1.0, V_m_per_s=30.0)
    assert lifted["status"][0] == "no_contact"
    Z = 0.5 * (lifted["left_h_m"][0] + lifted["right_h_m"][0]) - 50e-6
    out = wheelset.step(3e-3, Z_m=Z, V_m_per_s=30.0, derivatives=True)
    # The roll solved: both wheels at one penetration (the levers differ, so not exactly 50 µm),
    # to the roll root's tolerance (the rolled heights: 1e-11 m here).
    assert out["left_dz_m"][0] == pytest.approx(out["right_dz_m"][0], abs=1e-10)
    assert 40e-6 < out["left_dz_m"][0] < 60e-6
    h = 3e-6
    up = wheelset.step(3e-3, Z_m=Z + h, roll_rad=out["roll_rad"][0], V_m_per_s=30.0)
    dn = wheelset.step(3e-3, Z_m=Z - h, roll_rad=out["roll_rad"][0], V_m_per_s=30.0)
    fd = (up["F_N"][0, 2] - dn["F_N"][0, 2]) / (2 * h)
    # Analytic in Z (dN/dh0 and FASTSIM's load slope): within the differences' truncation,
    # measured 1.5e-4 here (2 Dec 2026).
    assert out["dF_dvertical_analytic"][0]
    assert out["dF_dvertical"][0, 2] == pytest.approx(fd, rel=2.5e-4)


def test_errors(wheelset):
    with pytest.raises(ValueError, match="pose.Q_left = -1 N"):
        wheelset.step(0.0, Q_left_N=-1.0, Q_right_N=1e3, V_m_per_s=30.0)
    with pytest.raises(ValueError, match="either the loads"):
        wheelset.step(0.0, V_m_per_s=30.0)
    with pytest.raises(ValueError, match="pose.V = 0 m/s"):
        wheelset.step(0.0, Q_left_N=1e3, Q_right_N=1e3, V_m_per_s=0.0)


def test_gil_released(wheelset):
    # A Python thread keeps counting while the steps run: with the GIL held it would stall.
    y = np.linspace(-6e-3, 6e-3, 20000)
    ticks = []
    stop = threading.Event()

    def count():
        while not stop.is_set():
            ticks.append(time.perf_counter())
            time.sleep(0.001)

    t = threading.Thread(target=count, daemon=True)
    t.start()
    try:
        time.sleep(0.01)
        n0 = len(ticks)
        t0 = time.perf_counter()
        wheelset.step(y, Q_left_N=50e3, Q_right_N=50e3, V_m_per_s=30.0, threads=1)
        elapsed = time.perf_counter() - t0
        n1 = len(ticks)
    finally:
        stop.set()
        t.join()
    assert elapsed > 0.05
    assert n1 - n0 >= 10, "the counting thread stalled during the steps: the GIL was held"


def test_roll_in_geometry_keyword(pair):
    # roll_in_geometry=False keeps the wheels upright: each pair's t_Y is +-y exactly; the default
    # rolls them about the axle centre, which moves t_Y (docs/wheelset.md). Break seen to fail:
    # the binding not passing the keyword on (the upright t_Y assertion).
    y = np.array([3e-3, -2e-3])
    up = mhcontact.Wheelset(pair, pair, mu=0.3, roll_in_geometry=False).step(y, Q_left_N=50e3, Q_right_N=50e3)
    rolled = mhcontact.Wheelset(pair, pair, mu=0.3).step(y, Q_left_N=50e3, Q_right_N=50e3)
    assert np.array_equal(up["left_tY_m"], y) and np.array_equal(up["right_tY_m"], -y)
    assert np.all(np.abs(rolled["roll_rad"]) > 1e-5)
    assert np.all(np.abs(rolled["left_tY_m"] - y) > 1e-6)
