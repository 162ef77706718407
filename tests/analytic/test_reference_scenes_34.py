"""The issue-34 references as scenes: ``ancf analytic moving-beam`` (analytic.moving_beam)
and ``ancf analytic belt-span-bending`` (analytic.belt_span_bending).

* the CLI's JSON is the module's answer at the JSON's parameters (the same numbers, bit for
  bit), and its defaults are the thesis belt of ancf.scenes.belt_common (Table 3.1);
* every parameter changes the answer by more than CHANGED (a test per parameter), and the
  changed answer is again the module's;
* a bad value exits 2 with one ``error:`` line naming the field; a speed beyond the
  critical speed (moving beam) or the positive effective tension (belt span) names v;
* independent checks: the critical speed against the frequency determinant's f_1 -> 0
  (f_1^2 is linear in v_c - v there), the stiffless limits against the moving string and
  the string span's closed-form length and tension.
"""
from __future__ import annotations

import json
import math
import re

import numpy as np
import pytest

from analytic import belt_span_bending, moving_beam, moving_string

#: a parameter "changes the answer" when a result moves by more than this (relative); the
#: references' own accuracy is 1e-15 (Brent) and 1.5e-10 (solve_bvp), far below it
CHANGED = 1e-6


def _json(cli, name, warned=False, **sets):
    """(params, results) of ``ancf analytic NAME --set ... --json``; ``warned``: outside the
    range of validity (one warning naming the speed), else none."""
    rc, out, err = cli("analytic", name, *(a for k, v in sets.items()
                                            for a in ("--set", f"{k}={v}")), "--json")
    assert rc == 0, err
    data = json.loads(out)
    assert data["converged"] and len(data["warnings"]) == warned
    assert all("range of validity: the speed over" in w for w in data["warnings"])
    return data["params"], data["results"]


def _moving_beam(p) -> dict:
    """The module's answer at the scene's params."""
    f = moving_beam.span_frequencies(p["T"], p["rho_A"], p["v"], p["L"], p["EI"], p["count"],
                                     p["ends"])
    return {"frequencies_hz": f.tolist(), "critical_speed_m_s": moving_beam.critical_speed(
        p["T"], p["rho_A"], p["L"], p["EI"], p["ends"])}


def _belt_span(p) -> dict:
    s = belt_span_bending.span((-p["D"] / 2, 0.0), p["r1"], (p["D"] / 2, 0.0), p["r2"],
                               p["N1"], p["EI"], p["rhoA"], p["v"], p["EA"])
    return {k: s[k] for k in ("departure_shift_rad", "arrival_shift_rad", "length_m",
                              "tension_mean_N")}


MODULE = {"moving-beam": _moving_beam, "belt-span-bending": _belt_span}


def _change(a: dict, b: dict) -> float:
    """The largest relative change between two results (inf: a list changed its length)."""
    out = 0.0
    for k in a:
        x, y = np.atleast_1d(a[k]), np.atleast_1d(b[k])
        if x.shape != y.shape:
            return math.inf
        out = max(out, float(np.max(np.abs(x - y) / np.abs(y))))
    return out


# ------------------------------------------------------------ the CLI is the module
@pytest.mark.parametrize("name", list(MODULE))
def test_cli_returns_the_modules_numbers(cli, name):
    p, r = _json(cli, name)
    assert r == MODULE[name](p)


def test_defaults_are_the_thesis_belt():
    """EI = alpha2 E b h^3 / 12 and EA = alpha1 E b h of belt_common's Table 3.1 belt (Dufva's
    element bends with E alpha2 I, stretches with E alpha1 A), its mass, pulleys and speed."""
    from ancf.scenes.analytic import REFERENCES
    from ancf.scenes.belt_common import R1, R2, X_CENTRE, belt_params
    t = {p.name: p.default for p in belt_params()}
    EI = t["alpha2"] * t["E"] * t["b"] * t["h"] ** 3 / 12.0
    rhoA, v = t["rho"] * t["b"] * t["h"], 120.0 * R1
    beam = REFERENCES["moving-beam"].resolve({})
    span = REFERENCES["belt-span-bending"].resolve({})
    assert (beam["EI"], beam["rho_A"], beam["v"], beam["L"]) == pytest.approx(
        (EI, rhoA, v, 2 * X_CENTRE), rel=1e-14)
    assert (span["EI"], span["EA"], span["rhoA"], span["v"]) == pytest.approx(
        (EI, t["alpha1"] * t["E"] * t["b"] * t["h"], rhoA, v), rel=1e-14)
    assert (span["r1"], span["r2"], span["D"]) == (R1, R2, 2 * X_CENTRE)


# ------------------------------------------------------------ every parameter counts
BEAM_SETS = {"T": 150.0, "rho_A": 0.2, "v": 5.0, "L": 0.5, "EI": 1e-2, "ends": "pinned",
             "count": 5}
SPAN_SETS = {"r1": 0.07, "r2": 0.07, "D": 0.45, "N1": 150.0, "EI": 1e-2, "rhoA": 0.2,
             "v": 15.0, "EA": 2e3}


def _changes(cli, name, key, value):
    p0, r0 = _json(cli, name)
    p, r = _json(cli, name, **{key: value})
    assert p == {**p0, key: p[key]} and p[key] != p0[key]
    assert r == MODULE[name](p)
    assert _change(r, r0) > CHANGED


@pytest.mark.parametrize("key", list(BEAM_SETS))
def test_every_moving_beam_param_changes_the_answer(cli, key):
    _changes(cli, "moving-beam", key, BEAM_SETS[key])


@pytest.mark.parametrize("key", list(SPAN_SETS))
def test_every_belt_span_param_changes_the_answer(cli, key):
    _changes(cli, "belt-span-bending", key, SPAN_SETS[key])


def test_every_param_is_covered():
    from ancf.scenes.analytic import REFERENCES
    for name, sets in (("moving-beam", BEAM_SETS), ("belt-span-bending", SPAN_SETS)):
        assert set(sets) == {p.name for p in REFERENCES[name].params}


# ------------------------------------------------------------ bad input: exit 2, one line
BEAM_BAD = {"T": "0", "rho_A": "-1", "v": "nan", "L": "0", "EI": "-1", "ends": "fixed",
            "count": "0"}
SPAN_BAD = {"r1": "0", "r2": "-0.1", "D": "-1", "N1": "0", "EI": "0", "rhoA": "-1",
            "v": "inf", "EA": "0"}


def _refused(cli, name, field, **sets) -> str:
    rc, out, err = cli("analytic", name, *(a for k, v in sets.items()
                                            for a in ("--set", f"{k}={v}")))
    lines = err.strip().splitlines()
    assert rc == 2 and out == "" and len(lines) == 1, err
    assert re.match(rf"error: {field}( =|:) ", lines[0]), lines[0]
    return lines[0]


@pytest.mark.parametrize("name,field,value", [("moving-beam", k, v) for k, v in BEAM_BAD.items()]
                         + [("belt-span-bending", k, v) for k, v in SPAN_BAD.items()])
def test_a_bad_value_names_its_field(cli, name, field, value):
    _refused(cli, name, field, **{field: value})


@pytest.mark.parametrize("ends", list(moving_beam.ENDS))
@pytest.mark.parametrize("sign", (1.0, -1.0))
def test_beyond_the_critical_speed_names_v(cli, ends, sign):
    from ancf.scenes.analytic import REFERENCES
    p = REFERENCES["moving-beam"].resolve({"ends": ends})
    v_c = moving_beam.critical_speed(p["T"], p["rho_A"], p["L"], p["EI"], ends)
    line = _refused(cli, "moving-beam", "v", v=sign * 1.001 * v_c, ends=ends)
    assert f"v_c = {v_c:.6g} m/s" in line and ends in line
    _json(cli, "moving-beam", v=sign * 0.9 * v_c, ends=ends)  # below it: a run


def test_belt_span_refuses_a_slack_span_overlapping_pulleys_and_a_stiff_belt(cli):
    from ancf.scenes.analytic import REFERENCES
    p = REFERENCES["belt-span-bending"].resolve({})
    v_max = math.sqrt(p["N1"] * (1 + p["N1"] / p["EA"]) / p["rhoA"])  # P1 = 0 (eq. 4)
    assert f"{v_max:.6g} m/s" in _refused(cli, "belt-span-bending", "v", v=-1.001 * v_max)
    _refused(cli, "belt-span-bending", "D", D=0.999 * (p["r1"] + p["r2"]))
    _refused(cli, "belt-span-bending", "EI", EI=100.0)  # no span within 90 degrees


# ------------------------------------------------------------ independent checks
def test_critical_speed_is_where_the_first_frequency_vanishes(cli):
    """f_1^2 falls linearly to 0 at v_c: its secant through v_c (1 - 1e-6) and v_c (1 - 1e-7)
    meets 0 at the scene's critical_speed_m_s within 1e-9 (a 1e-8 error fails)."""
    _, r = _json(cli, "moving-beam")
    v_c = r["critical_speed_m_s"]
    v = v_c * (1.0 - np.array([1e-6, 1e-7]))
    f2 = [_json(cli, "moving-beam", True, v=x, count=1)[1]["frequencies_hz"][0] ** 2 for x in v]
    root = v[1] - f2[1] * (v[1] - v[0]) / (f2[1] - f2[0])
    assert root == pytest.approx(v_c, rel=1e-9)
    assert root != pytest.approx(v_c * (1 + 1e-8), rel=1e-9)


def test_stiffless_limits_are_the_moving_string_and_the_string_span(cli):
    """EI -> 0: the pinned beam's frequencies are the moving string's within 1e-8
    (O(EI / (T L^2)) = 6e-11); the span from r1 to r2 = 0.05 m is the common tangent
    sqrt(D^2 - (r1 - r2)^2) within 1e-6 (shifts of 1.3e-6 rad) at the tension N1 within
    1e-9 (the string's P is constant)."""
    p, r = _json(cli, "moving-beam", EI=1e-9, ends="pinned")
    string = moving_string.span_frequencies(p["T"], p["rho_A"], p["v"], p["L"], p["count"])
    assert r["frequencies_hz"] == pytest.approx(string.tolist(), rel=1e-8)
    assert _change({"f": string}, {"f": r["frequencies_hz"]}) > 1e-10  # not the string itself
    p, r = _json(cli, "belt-span-bending", EI=1e-12, r2=0.05)
    tangent = math.sqrt(p["D"] ** 2 - (p["r1"] - p["r2"]) ** 2)
    assert r["length_m"] == pytest.approx(tangent, rel=1e-6)
    assert r["length_m"] != pytest.approx(p["D"], rel=1e-6)
    assert r["tension_mean_N"] == pytest.approx(p["N1"], rel=1e-9)
