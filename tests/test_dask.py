"""Sweeps through a real ``dask.distributed`` cluster (the ``dask`` extra): the executor route of the sweeps gives
the serial run's numbers, and full solutions travel back from a worker process."""

from functools import partial

import numpy as np
import pytest

from numeric import flat_punch, friction_coefficient, stick_radius
from numeric.solutions.solver import ERROR_FLOOR, rounding_floor

distributed = pytest.importorskip("dask.distributed", reason="the dask extra is not installed: pip install -e '.[dask]'")


@pytest.fixture(scope="module")
def client():
    """One worker process with two threads (a separate interpreter: arguments and results are pickled, as for a
    remote scheduler); ~1.5 s to start."""
    with distributed.LocalCluster(n_workers=1, threads_per_worker=2, processes=True, dashboard_address=None) as cluster:
        with distributed.Client(cluster) as connected:
            yield connected


def test_a_sweep_of_full_solutions_gives_the_serial_numbers(client):
    # use_table=False: every point is a level-1 solve in the worker. The solve is deterministic, so the numbers
    # are the serial ones up to the round-off of the LU's summation order (BLAS threads may differ between the two
    # processes), which the solver bounds by its rounding floor: ERROR_FLOOR absolute on the scale of P* ~ 1 (c = 4.4e-5
    # at nu = 0, mu = 0.05: measured 2.8e-15 apart)
    mu = np.array([0.05, 0.2, 0.8, 3.0])
    nu = np.array([[-0.5], [0.0], [0.3]])
    serial = stick_radius(mu, nu, use_table=False, level=1)
    remote = stick_radius(mu, nu, use_table=False, level=1, executor=client.get_executor())
    assert remote.shape == (3, 4)
    assert np.all(np.abs(remote - serial) <= rounding_floor(1.0)), (remote, serial)
    c = np.array([0.3, 0.6, 0.9])
    np.testing.assert_allclose(friction_coefficient(c, 0.25, use_table=False, level=1, executor=client.get_executor()),
                               friction_coefficient(c, 0.25, use_table=False, level=1), rtol=ERROR_FLOOR, atol=0)


def test_solutions_come_back_from_the_worker(client):
    # a FlatPunchSolution with its stress field, computed in the worker process, pickled back
    solve = partial(flat_punch, 0.25, level=1)
    here = [solve(mu) for mu in (0.2, 0.4)]
    there = list(client.get_executor().map(solve, [0.2, 0.4]))
    x = np.array([0.1, 0.5, 0.99])
    for a, b in zip(here, there):
        assert (b.mu, b.route) == (a.mu, a.route)
        np.testing.assert_allclose([b.c, b.compliance], [a.c, a.compliance], rtol=ERROR_FLOOR, atol=0)
        # pointwise the coefficients' round-off grows with the basis toward x = 1: 5 ERROR_FLOOR
        np.testing.assert_allclose(b.pressure(x), a.pressure(x), rtol=5 * ERROR_FLOOR, atol=0)
