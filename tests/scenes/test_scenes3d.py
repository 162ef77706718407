"""The scenes of issue 13 item 4: plate-square, plate-strip, beam3d-cantilever.

Their numbers against the references are checked in tests/checks/test_elements3d.py (the
checks of reports/elements3d.md); here: the scene contract (results, signs, the 2D
cantilever reproduced by the 3D beam at 0 degrees, the load rotated at 90 degrees) and
bad input as one error line naming the field and its range.
"""
import pytest

from ancf.cli import main
from ancf.scenes import SCENES
from ancf.common.params import InputError

NEW = ("plate-square", "plate-strip", "beam3d-cantilever")


def test_plate_square_is_positive_along_the_pressure_and_near_navier():
    r = SCENES["plate-square"].execute({})[0]["results"]
    assert r["center_deflection_m"] > 0 and 0 < r["relative_error"] < 0.02
    assert r["center_deflection_m"] / r["navier_center_deflection_m"] - 1 == pytest.approx(
        r["relative_error"], rel=1e-12)
    neg = SCENES["plate-square"].execute({"p": -1e3})[0]["results"]
    assert neg["center_deflection_m"] == pytest.approx(-r["center_deflection_m"], rel=1e-12)


def test_plate_strip_bends_along_the_load_and_stays_symmetric():
    out, _ = SCENES["plate-strip"].execute({})
    r, p = out["results"], out["params"]
    assert out["converged"] and r["tip_z"] < -0.2 * p["L"] and r["tip_x"] < p["L"]
    assert r["tip_y"] == pytest.approx(p["b"] / 2, rel=1e-10)


@pytest.mark.parametrize("common", [{}, {"n_elements": 4, "F": -1e5, "nu": 0.0}],
                         ids=["model1", "small"])
def test_beam3d_at_zero_degrees_reproduces_the_2d_cantilever(common):
    r2 = SCENES["cantilever"].execute({"element": "linear", **common})[0]["results"]
    r3 = SCENES["beam3d-cantilever"].execute(common)[0]["results"]
    for k in ("tip_x", "tip_y"):
        assert r3[k] == pytest.approx(r2[k], rel=1e-10)
    assert abs(r3["tip_z"]) <= 1e-10 * abs(r2["tip_y"])


@pytest.mark.parametrize("element", ["linear3d", "belt3d"])
def test_beam3d_at_90_degrees_rotates_the_load_onto_minus_z(element):
    common = {"n_elements": 4, "F": -1e5, "element": element}
    r0 = SCENES["beam3d-cantilever"].execute(common)[0]["results"]
    r9 = SCENES["beam3d-cantilever"].execute({**common, "load_angle_deg": 90})[0]["results"]
    assert r9["tip_x"] == pytest.approx(r0["tip_x"], rel=1e-10)
    assert r9["tip_z"] == pytest.approx(r0["tip_y"], rel=1e-10)  # square section
    assert abs(r9["tip_y"]) <= 1e-10 * abs(r0["tip_y"])


def test_belt3d_cantilever_halving_alpha2_doubles_a_small_deflection():
    """The belt element's alpha2 scales bending and shear (Eqs 4.40-4.42): in the linear
    range the tip deflection doubles (tolerance 1e-6: the load is small, not zero)."""
    common = {"element": "belt3d", "n_elements": 4, "F": -0.25, "load_angle_deg": 30}
    r1 = SCENES["beam3d-cantilever"].execute(common)[0]["results"]
    r2 = SCENES["beam3d-cantilever"].execute({**common, "alpha2": 0.5})[0]["results"]
    for k in ("tip_y", "tip_z"):
        assert r2[k] / r1[k] == pytest.approx(2.0, rel=1e-6)


BAD = [("plate-square", "a", "0"), ("plate-square", "n_elements", "0"),
       ("plate-square", "n_elements", "5"), ("plate-square", "nu", "0.5"),
       ("plate-square", "h", "0"), ("plate-square", "h", "-0.01"),
       ("plate-strip", "b", "0"), ("plate-strip", "L", "0"), ("plate-strip", "n_elements", "0"),
       ("plate-strip", "n_width", "0"), ("plate-strip", "nu", "0.5"), ("plate-strip", "h", "0"),
       ("beam3d-cantilever", "L", "0"), ("beam3d-cantilever", "b", "0"),
       ("beam3d-cantilever", "n_elements", "0"), ("beam3d-cantilever", "nu", "0.5"),
       ("beam3d-cantilever", "h", "0"), ("beam3d-cantilever", "element", "linear"),
       ("beam3d-cantilever", "integration", "bogus"),
       ("beam3d-cantilever", "load_angle_deg", "1e3")]


@pytest.mark.parametrize("name, field, value", BAD)
def test_bad_input_is_one_line_naming_the_field(name, field, value, capsys):
    with pytest.raises(InputError, match=f"^{field}"):
        SCENES[name].resolve({field: value})
    assert main(["run", name, "--set", f"{field}={value}"]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and err[0].startswith(f"error: {field} = ") and "allowed" in err[0]


@pytest.mark.parametrize("name", NEW)
def test_every_new_scene_has_a_reference(name):
    from ancf.study.references import spec
    assert spec(name).reference().kind in ("analytic", "self")
