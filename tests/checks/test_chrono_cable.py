"""Chrono's spinning cable pendulum over the whole stored history (20000 steps, about 2 CPU s
warm): ``ancf/checks/chrono_cable.py``'s rows and checks, as the chapter ``chrono_elements``
shows them.

Claims (tolerances stated with each): Chrono's check (mid y and tip z within 1e-6 m over its
first 200 steps) holds, and to the file's rounding (1e-7 m: 6 significant digits of values
below 0.1 m); the same bound holds over all 20000 steps (2 s, the cable swung through large
rotations); no column of the file differs from ours by more than 5e-7 m beyond its rounding;
gravity 9.81 m/s^2 instead of Chrono's 9.8 fails Chrono's own check, so the check sees a
0.1 % change of one constant.
"""
from __future__ import annotations

import numpy as np
import pytest

from ancf.checks import chrono_cable as cc

pytestmark = pytest.mark.slow

ROUNDING = 1e-7    # m: the file's rounding over the first 200 rows (|values| < 0.1 m)
BEYOND = 5e-7      # m: what any column may differ beyond the file's rounding (seen 3.2e-7)


@pytest.fixture(scope="module")
def rows():
    return cc.history_rows()


def test_first_steps_within_chronos_tolerance_and_the_files_rounding(rows):
    s = cc.summary(rows)
    assert s["first"] <= ROUNDING < cc.TOL
    assert cc.checks(rows)[0].passed


def test_whole_history_within_chronos_tolerance(rows):
    s = cc.summary(rows)
    assert s["all"] <= cc.TOL and cc.checks(rows)[1].passed
    assert np.all(s["beyond rounding"] <= BEYOND)
    tip = rows["file"][:, 5]
    assert tip.max() > 0.5 and tip.min() < -0.5  # m: the cable swings through large angles


def test_a_consistent_change_of_gravity_fails_chronos_check(rows):
    assert cc.summary(rows)["g other"] > cc.TOL
