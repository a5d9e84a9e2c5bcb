"""Wrong types get a TypeError naming the argument (issue 13): None, strings, complex numbers and objects
are not numbers, and flat_punch solves one problem at a time."""

import numpy as np
import pytest

from numeric import flat_punch, friction_coefficient, power_law, stick_radius

NOT_NUMBERS = [None, "0.3", 0.3 + 1j, [0.1, "x"], object()]


@pytest.mark.parametrize("bad", NOT_NUMBERS)
def test_sweeps_name_the_argument(bad):
    with pytest.raises(TypeError, match="^mu must be a real number"):
        stick_radius(bad, 0.3)
    with pytest.raises(TypeError, match="^nu must be a real number"):
        stick_radius(0.3, bad)
    with pytest.raises(TypeError, match="^c must be a real number"):
        friction_coefficient(bad, 0.3)


@pytest.mark.parametrize("bad", NOT_NUMBERS[1:])  # mu=None, c=None mean "not given"
def test_flat_punch_and_power_law_name_the_argument(bad):
    with pytest.raises(TypeError, match="^mu must be a real number"):
        flat_punch(nu=0.3, mu=bad)
    with pytest.raises(TypeError, match="^c must be a real number"):
        flat_punch(nu=0.3, c=bad)
    with pytest.raises(TypeError, match="^nu must be a real number"):
        power_law(2, nu=bad, mu=0.3)


def test_flat_punch_takes_one_problem():
    with pytest.raises(TypeError, match="^mu must be a single number for flat_punch"):
        flat_punch(nu=0.3, mu=[0.1, 0.2])
    with pytest.raises(TypeError, match="^nu must be a single number"):
        flat_punch(nu=np.array([0.1, 0.2]), c=0.5)
    # a one-element array is one problem, the same as the number
    assert flat_punch(nu=0.3, mu=np.array([0.2])).c == flat_punch(nu=0.3, mu=0.2).c
