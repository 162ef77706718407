"""``ancf element NAME --json`` (issue 35 item 2): every element's JSON at Chrono's
"SmallDisp" and "SmallVel" states equals Chrono's stored files (the parameters of
``tests/elements/chrono_data``: internal force = minus the stored vector, K and R within
1e-6, mass and gravity within 1e-10; the ancf3423, which has no stored matrices, in
``tests/elements/test_chrono_3423_plate.py``), the defaults are Chrono's test parameters, bad input
is one ``error:`` line naming the field (exit 2), and the output matches its schema."""
from __future__ import annotations

import json

import numpy as np
import pytest

from ancf.elements.chrono import ELEMENTS
from ancf.study.schemas import element_schema, schema, validate
from tests.elements.chrono_data import (ALPHA, BY_NAME, E, G, K_TIMOSHENKO, NU, RHO,
                                        RTOL_FORCE, RTOL_JAC, RTOL_MASS, close, load)

NAMES = [name for name in ELEMENTS if name[-4:] in BY_NAME]  # those with stored files
#: Chrono's moved coordinate as (node, component): the stored files' state
STATE = {name: (BY_NAME[name[-4:]].moved // (ELEMENTS[name].module.NDOF // ELEMENTS[name].nnode),
                BY_NAME[name[-4:]].moved % (ELEMENTS[name].module.NDOF // ELEMENTS[name].nnode))
         for name in NAMES}


def _json(cli, name, *sets):
    argv = ["element", name, "--json"] + [w for s in sets for w in ("--set", s)]
    rc, out, err = cli(*argv)
    assert rc == 0, err
    assert err == ""
    return json.loads(out)


def test_the_registry_is_chronos_five_elements():
    assert set(NAMES) == {f"ancf{el.name}" for el in BY_NAME.values()}
    assert set(ELEMENTS) == set(NAMES) | {"ancf3423"}
    for name in NAMES:
        assert ELEMENTS[name].module is BY_NAME[name[-4:]].module


@pytest.mark.parametrize("name", NAMES)
def test_small_disp_matches_chrono(cli, name):
    """SmallDisp: Q (= -stored), K (both Jacobian files: K is alpha-free at rest
    velocity) and R (the damped file), mass and gravity."""
    el, (node, comp) = BY_NAME[name[-4:]], STATE[name]
    out = _json(cli, name, "displacement=0.001", f"node={node}", f"component={comp}")
    n = el.ndof
    e, _ = el.state("disp", False)
    np.testing.assert_array_equal(out["coordinates"], e)
    close(np.array(out["internal_force"]),
          -load(f"{el.prefix}_IntFrcSmallDispNoVel", (n,)), RTOL_FORCE, el.scale("force"))
    K, R, s = np.array(out["stiffness"]), np.array(out["damping"]), el.scale("force")
    close(K, load(f"{el.prefix}_JacSmallDispNoVelNoDamping", (n, n)), RTOL_JAC, s)
    damped = load(f"{el.prefix}_JacSmallDispNoVelWithDamping", (2 * n, n))
    close(K, damped[:n], RTOL_JAC, s)
    close(R, damped[n:], RTOL_JAC, s)
    close(np.array(out["mass_matrix"]),
          np.kron(load(f"{el.prefix}_MassMatrix", (el.module.NSHAPE,) * 2), np.eye(3)),
          RTOL_MASS)
    close(np.array(out["gravity"]), load(f"{el.prefix}_Grav", (n,)), RTOL_MASS,
          el.scale("mass"))
    assert validate(out, schema(f"element {name}")) == []


@pytest.mark.parametrize("name", NAMES)
def test_small_vel_matches_chrono(cli, name):
    """SmallVel (alpha = 0.01 s): Q (= -stored), K and R."""
    el, (node, comp) = BY_NAME[name[-4:]], STATE[name]
    out = _json(cli, name, "velocity=0.001", f"node={node}", f"component={comp}",
                f"alpha={ALPHA}")
    n = el.ndof
    np.testing.assert_array_equal(out["coordinates"], el.e0())
    close(np.array(out["internal_force"]),
          -load(f"{el.prefix}_IntFrcNoDispSmallVel", (n,)), RTOL_FORCE, el.scale("force"))
    ref = load(f"{el.prefix}_JacNoDispSmallVelWithDamping", (2 * n, n))
    close(np.array(out["stiffness"]), ref[:n], RTOL_JAC, el.scale("force"))
    close(np.array(out["damping"]), ref[n:], RTOL_JAC, el.scale("force"))


@pytest.mark.parametrize("name", NAMES)
def test_defaults_are_chronos_test_parameters(cli, name):
    """At rest (Chrono's NoDisp state) with Chrono's material, dimensions and gravity:
    Q = 0, K the stored undamped file, R the damped one; the output is strict JSON."""
    el = BY_NAME[name[-4:]]
    rc, text, err = cli("element", name, "--json")
    assert rc == 0 and err == ""
    out = json.loads(text, parse_constant=lambda c: pytest.fail(f"non-strict JSON: {c}"))
    p = out["params"]
    dims = [d.name for d in ELEMENTS[name].params[:3]]
    assert tuple(p[d] for d in dims) == el.geometry
    assert (p["rho"], p["E"], p["nu"], p["alpha"]) == (RHO, E, NU, ALPHA)
    assert (p["gx"], p["gy"], p["gz"]) == G
    assert (p["node"], p["component"]) == STATE[name]
    assert p["displacement"] == p["velocity"] == 0.0
    if name in ("ancf3243", "ancf3333"):
        assert p["k1"] == p["k2"] == K_TIMOSHENKO
    assert set(out) == {"element", "params", "coordinates", "mass_matrix", "gravity",
                        "internal_force", "stiffness", "damping", "cpu_time_s", "warnings"}
    assert out["element"] == name and out["warnings"] == [] and out["cpu_time_s"] >= 0
    n = el.ndof
    assert not np.any(out["internal_force"])
    close(np.array(out["stiffness"]), load(f"{el.prefix}_JacNoDispNoVelNoDamping", (n, n)),
          RTOL_JAC)
    close(np.array(out["damping"]),
          load(f"{el.prefix}_JacNoDispNoVelWithDamping", (2 * n, n))[n:], RTOL_JAC)
    assert validate(out, element_schema(name)) == []
    assert validate({**out, "extra": 1}, element_schema(name)) != []


def test_shear_factors_follow_nu_unless_set(cli):
    p = _json(cli, "ancf3243", "nu=0.2", "k2=0.5")["params"]
    assert p["k1"] == pytest.approx(10 * 1.2 / (12 + 2.2)) and p["k2"] == 0.5


def test_summary_without_json(cli):
    rc, out, err = cli("element", "ancf3833")
    assert rc == 0 and err == ""
    lines = out.splitlines()
    assert lines[0].startswith("ancf3833: 72 coordinates")
    assert any(line.split()[:2] == ["stiffness", "72x72"] for line in lines)


@pytest.mark.parametrize("argv, field", [
    (["nope"], "element"),
    (["ancf3243", "--set", "E=-1"], "E"),
    (["ancf3443", "--set", "nu=0.5"], "nu"),
    (["ancf3333", "--set", "node=3"], "node"),
    (["ancf3243", "--set", "node=2"], "node"),
    (["ancf3843", "--set", "component=3"], "component"),
    (["ancf3833", "--set", "E=true"], "E"),
    (["ancf3843", "--set", "L=1"], "L"),
    (["ancf3243", "--set", "Lx=1"], "Lx"),
])
def test_bad_input_is_one_error_line(cli, argv, field):
    rc, out, err = cli("element", *argv, "--json")
    assert rc == 2 and out == ""
    lines = err.splitlines()
    assert len(lines) == 1 and lines[0].startswith(f"error: {field}")
    assert "allowed" in lines[0]
    if argv == ["nope"]:
        assert all(n in lines[0] for n in NAMES)


def test_a_boolean_is_refused_as_a_number():
    with pytest.raises(ValueError, match=r"^E: True is not valid \(a boolean\)"):
        ELEMENTS["ancf3243"].resolve({"E": True})


def test_unknown_schema_name_lists_the_elements():
    with pytest.raises(KeyError, match="element ancf3843"):
        element_schema("element ancf9999")
    assert schema("ancf element ancf3843")["title"] == "ancf element ancf3843 --json"
