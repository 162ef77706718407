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


def test_within_the_one_percent_target(table):
    """Span tensions (seen within 0.1 %) and departure points (within 0.36 % of the wrap)
    within 1 %, at EI and 10x EI."""
    assert all(abs(row[3]) < kp.TARGET for tab in table.values() for row in tab)


def test_the_law_and_the_rim_matter():
    """The file's Green strain (true tension EA eps (1 + 3 eps / 2)) puts the tensions
    3-5 % above the linear reference: outside the 1 % target, so the comparison can fail."""
    tab = kp.rows(('belt.axial_strain="green"',))
    assert max(abs(r[3]) for r in tab if "tension" in r[0]) > 2 * kp.TARGET
