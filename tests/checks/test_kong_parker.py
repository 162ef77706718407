"""ancf/checks/kong_parker.py: our steady thesis drive against Kong & Parker's BVP."""
import math

import pytest

from ancf.checks import kong_parker as kp


@pytest.fixture(scope="module")
def table():
    return kp.compare()


def test_rows_are_finite_and_ten_times_ei_moves_the_reference(table):
    """Every row is finite; 10x EI moves the reference's departure lift-off earlier."""
    for tab in table.values():
        assert all(math.isfinite(x) for row in tab for x in row[1:])
    dep = [[row[2] for row in tab if "departure" in row[0]] for tab in table.values()]
    moved = [abs(math.remainder(b - a, 2 * math.pi)) for a, b in zip(*dep)]
    assert min(moved) > 1e-3


@pytest.mark.xfail(strict=True, reason="penetration not in the reference's loop closure "
                   "(module docstring): tensions 11-25 %, departures 4-6 % of the wrap")
def test_within_the_one_percent_target(table):
    assert all(abs(row[3]) < kp.TARGET for tab in table.values() for row in tab)
