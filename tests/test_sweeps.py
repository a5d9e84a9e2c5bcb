"""Batch sweeps: points outside the table are solved one by one or through an executor,
with the same results (the solve of each point is deterministic), and a progress line."""

from concurrent.futures import ThreadPoolExecutor

import numpy as np

from numeric import friction_coefficient, stick_radius


def test_executor_gives_the_serial_results_and_progress_is_reported(capsys):
    mu = np.array([[0.2], [0.4]])  # broadcast against two nu: four solver points
    nu = np.array([0.0, 0.3])
    serial = stick_radius(mu, nu, use_table=False, level=1)
    with ThreadPoolExecutor(2) as pool:
        mapped = stick_radius(mu, nu, use_table=False, level=1, executor=pool, progress=True)
    assert mapped.shape == (2, 2)
    np.testing.assert_array_equal(mapped, serial)  # same deterministic solve per point
    err = capsys.readouterr().err
    assert "stick_radius: 4/4 points solved" in err and "points/s" in err


def test_sweep_round_trip_through_an_executor():
    c = np.array([0.3, 0.6])
    with ThreadPoolExecutor(2) as pool:
        mu = friction_coefficient(c, 0.25, use_table=False, level=1, executor=pool)
        back = stick_radius(mu, 0.25, use_table=False, level=1, executor=pool)
    # level 1 solves c to ~1e-8 (its documented accuracy; the inverse adds its own secant tolerance)
    np.testing.assert_allclose(back, c, rtol=0, atol=1e-7)
