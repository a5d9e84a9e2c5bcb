"""Batch sweeps: points outside the table are solved one by one or through an executor,
with the same results (the solve of each point is deterministic), and a progress bar."""

import io
from concurrent.futures import ThreadPoolExecutor

import numpy as np
import pytest

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
    assert "stick_radius: 100%" in err and "4/4" in err and "point/s" in err  # a tqdm bar, with its rate


class _Terminal(io.StringIO):
    def isatty(self) -> bool:
        return True


@pytest.mark.parametrize("progress, terminal, drawn", [("auto", False, False), ("auto", True, True),
                                                       (True, False, True), (False, True, False)])
def test_progress_is_drawn_by_default_on_a_terminal_only(monkeypatch, progress, terminal, drawn):
    stderr = _Terminal() if terminal else io.StringIO()
    monkeypatch.setattr("sys.stderr", stderr)
    stick_radius(np.array([0.2, 0.4]), 0.0, use_table=False, level=0, progress=progress)
    assert ("2/2" in stderr.getvalue()) == drawn


@pytest.mark.parametrize("bad, error", [("yes", ValueError), (None, TypeError), (1, TypeError)])
def test_progress_takes_auto_true_or_false(bad, error):
    with pytest.raises(error, match="^progress must be 'auto', True or False"):
        stick_radius(0.3, 0.0, progress=bad)


def test_sweep_round_trip_through_an_executor():
    c = np.array([0.3, 0.6])
    with ThreadPoolExecutor(2) as pool:
        mu = friction_coefficient(c, 0.25, use_table=False, level=1, executor=pool)
        back = stick_radius(mu, 0.25, use_table=False, level=1, executor=pool)
    # level 1 solves c to ~1e-8 (its documented accuracy; the inverse adds its own secant tolerance)
    np.testing.assert_allclose(back, c, rtol=0, atol=1e-7)
