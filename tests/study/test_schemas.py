"""One JSON schema per scene and analytic reference (issue 15, item 16) and per scene with
modes (issue 24): every default run, and a non-converging run of each scene, validates
against its schema; the validator rejects what the schema forbids; reports/schemas.md is
the generated text."""
import json
from pathlib import Path

import pytest

from ancf.scenes.modes import MODAL, execute as modes
from ancf.study.schemas import RESULTS, registries, schema, schemas_markdown, validate

NAMES = list(registries())

#: one failing input per scene: results are null (or absent) where the run stopped
FAILING = {"simply-supported": {"max_iterations": 1, "load_steps": 1},
           "cantilever": {"max_iterations": 1, "load_steps": 1},
           "axial-bar": {"max_iterations": 1, "load_steps": 1, "F": 5e9},
           "pendulum": {"max_steps": 5}, "spinning-beam": {"max_steps": 5},
           "belt-free-static": {"max_iterations": 2}, "belt2d": {"max_steps": 5, "t_end": 0.1},
           "plate-square": {"a": 1e70},  # the stiffness overflows: a non-finite deflection
           "plate-strip": {"max_iterations": 1, "load_steps": 1},
           "beam3d-cantilever": {"max_iterations": 1, "load_steps": 1},
           "princeton-beam": {"max_iterations": 1, "load_steps": 1},
           "beam3d-bending": {"max_iterations": 1, "load_steps": 1},
           "belt3d": {"max_steps": 5, "t_end": 0.1},
           # DOP853 fails (issue 22: null where arrays were due); t_end within the swing budget
           "rigid-pendulum": {"g": 1e300, "t_end": 1e-150}}
#: shortened "default" runs where the default is a long study (the keys are the same)
SHORT = {"belt3d": {"t_end": 0.02, "output_dt": 0.01}}


def _run(name, overrides):
    command, sc = registries()[name]
    out, _ = sc.execute(overrides)
    return json.loads(json.dumps(out))  # what --json prints, parsed back


def test_every_scene_and_reference_has_a_schema():
    assert set(NAMES) == set(RESULTS) and len(NAMES) >= 9


@pytest.mark.slow
@pytest.mark.parametrize("name", NAMES)
def test_default_run_matches_its_schema(name):
    out = _run(name, SHORT.get(name, {}))
    assert out["converged"]
    assert validate(out, schema(name)) == []


@pytest.mark.parametrize("name", list(FAILING))
def test_non_converged_run_matches_its_schema(name):
    out = _run(name, FAILING[name])
    assert not out["converged"]
    assert validate(out, schema(name)) == []


@pytest.mark.parametrize("about", ["reference", "equilibrium"])
@pytest.mark.parametrize("name", MODAL)
def test_modes_match_their_schema(name, about):
    out = json.loads(json.dumps(modes(name, {}, None, about)[0]))
    assert out["converged"] and out["results"]["about"] == about
    assert validate(out, schema(f"modes {name}")) == []
    assert ("lowest_frequency_reference_hz" in out["results"]) == (about == "equilibrium")


@pytest.mark.parametrize("name", [n for n in MODAL if n != "plate-square"])
def test_modes_without_an_equilibrium_match_their_schema(name):
    """Newton stopped (the failing input of the scene's run): results null where the
    eigenpairs would be."""
    out = json.loads(json.dumps(modes(name, FAILING[name], None, "equilibrium")[0]))
    assert not out["converged"] and out["results"]["frequencies_hz"] is None
    assert validate(out, schema(f"modes {name}")) == []


def test_the_validator_rejects_what_the_schema_forbids():
    out = _run("cantilever", {})
    sch = schema("cantilever")
    bad = json.loads(json.dumps(out))
    bad["results"]["tip_x"] = "1.0"
    bad["results"]["surprise"] = 1
    del bad["results"]["tip_y"]
    bad["params"]["n_elements"] = 8.5
    bad["converged"] = 1
    errors = validate(bad, sch)
    for where in ("$.results.tip_x", "undeclared key 'surprise'", "missing key 'tip_y'",
                  "$.params.n_elements", "$.converged"):
        assert any(where in e for e in errors), (where, errors)
    assert validate({**out, "warnings": ["x"]}, sch) == []
    assert validate({**out, "warnings": [1]}, sch) != []
    assert validate({**out, "scene": "axial-bar"}, sch) != []


def test_published_schemas_are_the_generated_ones():
    path = Path(__file__).resolve().parents[2] / "reports" / "schemas.md"
    assert path.read_text() == schemas_markdown(), "run `python -m ancf.study.schemas`"


def test_schema_names_as_the_readme_writes_them():
    from ancf.study.schemas import SchemaNameError, names
    assert schema("run cantilever") == schema("cantilever") == schema("ancf run cantilever")
    assert schema("analytic reissner")["title"] == "ancf analytic reissner --json"
    assert schema("analytic reissner")["properties"]["scene"]["const"] == "reissner"
    assert set(names()) == ({f"{c} {n}" for n, (c, _) in registries().items()}
                            | {f"modes {n}" for n in MODAL}
                            | {"steady belt-drive", "modes belt-drive"})  # a running drive's
    assert schema("steady belt-drive")["title"] == "ancf steady belt-drive --json"
    assert "hubload_N" in str(schema("steady belt-drive")["properties"]["results"])
    assert "frequencies_hz" in schema("modes belt-drive")["properties"]["results"]["properties"]
    assert schema("modes cantilever")["title"] == "ancf modes cantilever --json"
    assert "rho" in schema("modes cantilever")["properties"]["params"]["properties"]
    assert "rho" not in schema("run cantilever")["properties"]["params"]["properties"]
    for bad in ("run reissner", "analytic cantilever", "run", "cantilever beam", "nope",
                "modes pendulum", "modes reissner"):
        with pytest.raises(KeyError) as exc:  # the old exception type still catches it
            schema(bad)
        assert isinstance(exc.value, (SchemaNameError, ValueError))
        text = str(exc.value)
        assert repr(bad) in text and "run cantilever" in text and "analytic reissner" in text
        assert not text.startswith('"')  # a message, not a KeyError's quoted repr


def test_validate_refuses_swapped_arguments_and_accepts_a_name():
    sch = schema("run cantilever")
    out = {"scene": "cantilever", "params": {}, "converged": True, "message": "",
           "results": {}, "cpu_time_s": 0.0, "compile_cpu_s": 0.0, "warnings": []}
    errors = validate(out, sch)  # missing params and results: violations, not an exception
    assert errors and all(e.startswith("$.") for e in errors)
    assert validate(out, "run cantilever") == errors
    with pytest.raises(TypeError, match="first argument is a schema"):
        validate(sch, out)
    with pytest.raises(TypeError, match="no JSON Schema keywords"):
        validate(out, out)
    with pytest.raises(TypeError, match="not a dict"):
        validate(out, 3)
    with pytest.raises(KeyError, match="allowed"):
        validate(out, "run nope")
    # sub-schemas still validate parts of an output
    tip = sch["properties"]["results"]["properties"]["tip_x"]
    assert validate(1.0, tip) == [] and validate("1.0", tip) != []
    assert any("missing key 'tip_y'" in e for e in validate({"tip_x": 1.0},
                                                              sch["properties"]["results"]))
