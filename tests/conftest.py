"""Shared test configuration: mpmath precision backstop and the hypothesis profiles."""

import os

import mpmath
import pytest
from hypothesis import settings

settings.register_profile("ci", derandomize=True, max_examples=30, deadline=None)
settings.register_profile("dev", max_examples=30, deadline=None)
settings.load_profile("ci" if os.environ.get("CI") else "dev")


@pytest.fixture(autouse=True)
def _reset_mpmath_precision():
    """mpmath's precision is global: restore it after every test."""
    dps = mpmath.mp.dps
    yield
    mpmath.mp.dps = dps
