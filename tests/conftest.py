"""Shared test configuration: mpmath precision backstop and the hypothesis profiles."""

import os

import mpmath
import pytest
from hypothesis import settings

# The default suite runs derandomised and bounded, so that it passes or fails the same way everywhere;
# HYPOTHESIS_PROFILE=explore searches afresh with more examples (what a developer runs to look for new failures).
settings.register_profile("ci", derandomize=True, max_examples=30, deadline=None)
settings.register_profile("explore", max_examples=300, deadline=None)
settings.load_profile(os.environ.get("HYPOTHESIS_PROFILE", "ci"))


@pytest.fixture(autouse=True)
def _reset_mpmath_precision():
    """mpmath's precision is global: restore it after every test."""
    dps = mpmath.mp.dps
    yield
    mpmath.mp.dps = dps
