"""The physical-sense checks every belt drive runs (issue 33 item 1;
ancf.scenes.sense.drive): each check fed a drive's numbers that fire it and numbers that do
not (fast), the drive files' numbers built from a description (sense_drive), and runs of
the issue's examples: a load above the belt's capacity, signed (the pulley spins
backwards: warned) and resisting (it stalls, never backwards)."""
from __future__ import annotations

import copy
import json
import math

import numpy as np
import pytest

from ancf.belts.drive_file import describe
from ancf.scenes import sense
from ancf.scenes.belt_drive import _arm_into, pretension, sense_drive

from tests.belts.test_drive_keys import MINIMAL, R, _with, toml

T0, K, MU = 30.0, 1e4, 1.2


def _drive(pulleys=None, spans=None, arms=(), finished=True, ramps=None, **kw) -> sense.Drive:
    """A driver, an idler and a driven pulley (each on a wrap of 2.4 rad) at steady
    speeds that pass every check, changed by ``pulleys`` {name: {field: value}}."""
    base = {"driver": dict(role="prescribed", omega=12.0, omega_mean=12.0),
            "idler": dict(role="idler", radius=0.06, omega_mean=12.0 * R / 0.06 * 0.999),
            "driven": dict(role="driven", load=1.0, omega_mean=11.99)}
    t = np.linspace(0.9, 1.0, 11)
    out = []
    for name, f in base.items():
        f = {"radius": R, "wrap": 2.4, "penetration": 1e-5, **f, **(pulleys or {}).get(name, {})}
        f.setdefault("trace", tuple(np.full(t.size, f["omega_mean"])) if f["role"] != "prescribed"
                     else ())
        out.append(sense.Pulley(name, **f))
    return sense.Drive(pulleys=tuple(out), T0=kw.pop("T0", T0), k=K, rhoA=0.01036, mu=MU,
                       t_end=1.0, window=0.1, ramps=ramps or {"driver's law": 0.05}, arms=arms,
                       finished=finished, spans={"a": 33.0, "b": 27.0} if spans is None else spans,
                       times=tuple(t), **kw)


def test_a_sane_drive_passes_every_check():
    assert sense.drive(_drive()) == []
    assert sense.drive(_drive(finished=False)) == []


def test_load_above_the_capstan_bound_per_pulley():
    """2 T0 r tanh(mu theta / 2) on the loaded pulley's own wrap: 4.4 N m here."""
    bound = sense.capstan_torque(T0, MU, 2.4, R)
    assert bound == pytest.approx(2 * T0 * R * math.tanh(0.6 * 2.4))
    assert sense.drive(_drive({"driven": {"load": 0.99 * bound}})) == []
    [line] = sense.drive(_drive({"driven": {"load": 50.0}}, finished=False))
    assert line.startswith("driven: load torque 50 N m is above what friction can transmit")
    small = {"driven": {"load": 0.9 * bound, "wrap": 0.5}}  # a small wrap carries less
    assert "driven: load torque" in sense.drive(_drive(small, finished=False))[0]


def test_the_driver_carries_the_loads_brought_to_its_radius():
    """Two loads each below their own bound, whose sum at the driver's radius is not."""
    b = sense.capstan_torque(T0, MU, 3.0, R)
    lines = sense.drive(_drive({"driver": {"wrap": 1.0}, "driven": {"load": 0.9 * b, "wrap": 3.0},
                                "idler": {"role": "driven", "load": 0.9 * b, "radius": R,
                                          "wrap": 3.0, "omega_mean": 11.99}}, finished=False))
    assert len(lines) == 1 and lines[0].startswith("driver (driver, the loads at its radius)")


def test_a_pulley_turning_against_its_belt():
    [line] = sense.drive(_drive({"driven": {"omega_mean": -354.3}}, spans={"a": 60.0, "b": 1.0}))
    assert line.startswith("driven turns against its belt (rim speed -28.79 m/s")
    [line] = sense.drive(_drive({"idler": {"omega_mean": -1.64}}))
    assert line.startswith("idler turns against its belt")
    # a pulley on the belt's back turns clockwise with the belt: not against it
    back = {"idler": {"side": -1, "omega_mean": -12.0 * R / 0.06}}
    assert sense.drive(_drive(back)) == []
    # a driver turning clockwise: the belt runs the other way round
    cw = {"driver": {"omega": -12.0, "omega_mean": -12.0},
          "idler": {"omega_mean": -12.0 * R / 0.06}, "driven": {"omega_mean": -11.99}}
    assert sense.drive(_drive(cw)) == []


def test_gross_slip_per_free_pulley_against_the_creep():
    """Creep (T_max - T_min) / (k + T_max) = 6 / 10033; slip 0.05 beyond it warns."""
    assert sense.drive(_drive({"driven": {"omega_mean": 12.0 * 0.95}})) == []
    [line] = sense.drive(_drive({"driven": {"omega_mean": 12.0 * 0.9}}))
    assert line.startswith("driven: gross slip: its rim lags the driver's by 0.1")
    [line] = sense.drive(_drive({"idler": {"omega_mean": 12.0 * R / 0.06 * 1.2}}))
    assert "runs ahead of the driver's by 0.2" in line
    d = _drive({"driven": {"omega_mean": 12.0 * 0.9}})
    assert sense.slips(d)[2] == pytest.approx(0.1, rel=1e-12)  # signed, 1 - rim / rim_d


def test_span_in_compression_and_undefined_spans():
    [line] = sense.drive(_drive(spans={"a": 33.0, "b": -0.4}))
    assert "b span is in compression" in line
    lines = sense.drive(_drive(spans={"a": 33.0, "b": None}))
    assert any("middle third of the b span" in w for w in lines)
    assert any("middle third" in w for w in sense.drive(_drive(spans={"a": float("nan")})))


def test_belt_off_a_pulley():
    [line] = sense.drive(_drive({"idler": {"penetration": -0.031}}))
    assert line.startswith("the belt is off pulley idler at t_end") and "-31 mm" in line
    assert sense.drive(_drive({"idler": {"penetration": None}})) == []  # not measured


def test_tensioner_arm_travel_and_preload_direction():
    ok = sense.Arm("tensioner", preload=-6.85, into=-1.0, turn=math.radians(0.3))
    assert sense.drive(_drive(arms=(ok,))) == []
    [line] = sense.drive(_drive(arms=(sense.Arm("tensioner", -6.85, -1.0, math.radians(143)),)))
    assert "its arm turned 143 deg from its start (bound 30 deg)" in line
    [line] = sense.drive(_drive(arms=(sense.Arm("tensioner", 6.85, -1.0),), finished=False))
    assert "preload 6.85 N m turns the arm away from the belt" in line
    assert sense.drive(_drive(arms=(sense.Arm("tensioner", 0.0, 1.0),), finished=False)) == []


def test_steady_window_in_a_ramp_and_drift():
    lines = sense.drive(_drive({"driven": {"omega_mean": -354.3}}, ramps={"driven's law": 0.95}))
    assert len(lines) == 1 and "starts before the driven's law ends at 0.95 s" in lines[0]
    rising = tuple(np.linspace(11.0, 12.0, 11))
    [line] = sense.drive(_drive({"driven": {"trace": rising, "omega_mean": 11.99}}))
    assert line.startswith("driven: not steady: the speed changes by 1 rad/s")


def test_pretension_against_the_centrifugal_tension():
    lines = sense.drive(_drive(T0=0.5, finished=False))  # rho A v^2 = 0.0098 N: fine
    assert not any("lifts off" in w for w in lines)
    assert "lifts off" in sense.drive(_drive(T0=0.005, finished=False))[0]


# ------------------------------------------------------------------ drive files' numbers

def test_sense_drive_of_a_description():
    """The file's numbers: T0 from the prestretch by the Green law on E A alpha1, the
    wraps of the path, the final load, the ramps' end times, the arm's direction."""
    d = describe(copy.deepcopy(MINIMAL))
    lam = 1 / (1 - 0.003)
    assert pretension(d) == pytest.approx(0.5 * 1e4 * lam * (lam ** 2 - 1), rel=1e-12)
    s = sense_drive(d, None)
    assert [q.wrap for q in s.pulleys] == list(d.path.wraps)
    assert [q.load for q in s.pulleys] == [0.0, 0.0, 1.0]
    assert s.pulleys[0].omega == 12.0 and s.ramps == {"driver's law": 0.05}
    assert not s.finished and s.arms[0].into in (1.0, -1.0)
    eng = describe(_with(belt__axial_strain="engineering"))
    assert pretension(eng) == pytest.approx(1e4 * (lam - 1), rel=1e-12)


def test_arm_into_presses_the_tensioner_into_the_belt():
    """Turning the arm in the direction _arm_into names lengthens the path: checked
    against the path of the turned layout directly."""
    d = describe(copy.deepcopy(MINIMAL))
    into = _arm_into(d, 1)
    q = d.pulleys[1]
    P, c = np.array(q.params["pivot"]), np.array(q.centre)
    a = math.atan2(*(c - P)[::-1]) + into * 0.05
    turned = _with(pulleys__1__centre=list(P + q.params["arm_length"] * np.array(
        [math.cos(a), math.sin(a)])))
    assert describe(turned).path.length > d.path.length


# ------------------------------------------------------------------ runs

def _run(cli, tmp_path, data: dict, *sets):
    f = tmp_path / "drive.toml"
    f.write_text(toml(data))
    rc, out, err = cli("run", "belt-drive", "--file", str(f), *sets, "--json")
    return rc, json.loads(out), err


def _overloaded(acts: str) -> dict:
    data = _with(pulleys__2__load_torque=50.0, pulleys__2__load_acts=acts,
                 run__t_end=0.12, run__steady_window=0.04)
    del data["pulleys"][1]
    data["pulleys"].insert(1, {"name": "idler", "centre": [0.0, -0.2], "radius": 0.06,
                               "law": "idler", "inertia": 1e-3, "damping": 0.0})
    return data


@pytest.mark.slow
def test_signed_overload_spins_backwards_and_is_warned(cli, tmp_path):
    rc, out, err = _run(cli, tmp_path, _overloaded("signed"))
    driven = out["results"]["pulleys"][2]
    assert rc == 0 and driven["omega_mean"] < -10 and driven["slip"] > 1
    assert "driven: load torque 50 N m is above what friction can transmit" in err
    assert "driven turns against its belt" in err


@pytest.mark.slow
def test_resisting_overload_stalls_never_backwards(cli, tmp_path):
    """The same drive with the resisting law: the pulley stalls (slip near 1) but never
    turns backwards faster than omega_reg's noise; the capstan and slip checks warn."""
    rc, out, err = _run(cli, tmp_path, _overloaded("resisting"))
    driven = out["results"]["pulleys"][2]
    assert rc == 0 and min(driven["omega"]) > -0.1 and driven["slip"] > 0.9
    assert "driven: load torque 50 N m is above" in err and "gross slip" in err
    assert "turns against" not in err
