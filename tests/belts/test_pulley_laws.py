"""The contract of every pulley law (ancf.belts.pulleys.SPEED_LAWS, TORQUE_LAWS): a law
of time, 0 up to t0 and its final value from t1 on, finite, proportional to that final
value; a name that is no law is refused naming the spec field."""
from __future__ import annotations

import numpy as np
import pytest

from ancf.belts import pulleys

LAWS = [(table, name) for table in ("SPEED_LAWS", "TORQUE_LAWS")
        for name in getattr(pulleys, table)]
T0, T1 = 0.05, 0.6


@pytest.mark.parametrize("table, name", LAWS)
def test_a_law_starts_at_zero_and_ends_at_its_final_value(table, name):
    f = getattr(pulleys, table)[name]
    t = np.linspace(0.0, 2.0, 401)
    y = f(t, 7.0, T0, T1)
    assert y.shape == t.shape and np.all(np.isfinite(y))
    assert np.all(y[t <= T0] == 0.0)
    assert y[t >= T1] == pytest.approx(7.0, rel=1e-14)
    assert f(t, -14.0, T0, T1) == pytest.approx(-2.0 * y, rel=1e-14, abs=1e-300)


@pytest.mark.parametrize("table, name", LAWS)
def test_a_law_rises_monotonically_without_a_jump(table, name):
    """Between t0 and t1 a law climbs to its final value: never down, and no step larger
    than 2 % of the final value on a 0.1 ms grid (the largest is the cosine ramp's jump
    at t0 = 0.05 s as printed, Eq. 3.30: (1 - cos(pi t0 / t1)) / 2 = 1.7 % for t1 = 0.6 s);
    a law turned upside down or reversed fails here."""
    f = getattr(pulleys, table)[name]
    t = np.linspace(0.0, 2.0, 20001)
    steps = np.diff(f(t, 7.0, T0, T1))
    assert steps.min() >= -1e-12 * 7.0
    assert steps.max() <= 0.02 * 7.0


@pytest.mark.parametrize("table, field", [("SPEED_LAWS", "driver_law"),
                                          ("TORQUE_LAWS", "torque_law")])
def test_an_unknown_law_is_refused_naming_the_field(table, field):
    with pytest.raises(ValueError, match=f"{field} = 'nope' is not a law; allowed: "):
        pulleys.law(getattr(pulleys, table), "nope", field)


@pytest.mark.parametrize("module, drive", [("belt2d", "BeltDrive"), ("belt3d", "Belt3DDrive")])
def test_the_drives_use_the_laws_their_spec_names(module, drive):
    import dataclasses
    import importlib
    scene = importlib.import_module(f"ancf.scenes.{module}")
    spec = scene.spec(scene.SCENE.resolve({"n_elements": 8}))
    cls = getattr(importlib.import_module(f"ancf.belts.drive{module[-2:]}"), drive)
    built = cls(spec)
    assert built.speed_law is pulleys.SPEED_LAWS[spec.driver_law]
    assert built.torque_law is pulleys.TORQUE_LAWS[spec.torque_law]
    with pytest.raises(ValueError, match="torque_law = 'nope'"):
        cls(dataclasses.replace(spec, torque_law="nope"))


def test_every_time_law_declares_its_drive_file_keys():
    """A law's keys are drive-file keys (ancf.belts.drive_data.TIME_KEYS); a role's time
    law key chooses among its laws."""
    from ancf.belts import drive_data as dd
    for table in (pulleys.FILE_SPEED_LAWS, pulleys.FILE_TORQUE_LAWS):
        for name, law in table.items():
            assert law.name == name and set(law.keys) <= set(dd.TIME_KEYS)
    for role in dd.ROLES.values():
        if role.law_key:
            assert dd.LAW_PARAMS[role.law_key].choices == tuple(role.laws)
