"""One JSON schema per scene and analytic reference (issue 15, item 16): every default run,
and a non-converging run of each scene, validates against its schema; the validator
rejects what the schema forbids; reports/schemas.md is the generated text."""
import json
from pathlib import Path

import pytest

from ancf.study.schemas import RESULTS, registries, schema, schemas_markdown, validate

NAMES = list(registries())

#: one failing input per scene: results are null (or absent) where the run stopped
FAILING = {"simply-supported": {"max_iterations": 1, "load_steps": 1},
           "cantilever": {"max_iterations": 1, "load_steps": 1},
           "axial-bar": {"max_iterations": 1, "load_steps": 1, "F": 5e9},
           "pendulum": {"max_steps": 5}, "spinning-beam": {"max_steps": 5},
           "belt-free-static": {"max_iterations": 2}, "belt2d": {"max_steps": 5, "t_end": 0.1},
           "plate-square": {"h": 1e-300},
           "plate-strip": {"max_iterations": 1, "load_steps": 1},
           "beam3d-cantilever": {"max_iterations": 1, "load_steps": 1},
           "belt3d": {"max_steps": 5, "t_end": 0.1}}
#: shortened "default" runs where the default is a long study (the keys are the same)
SHORT = {"belt3d": {"t_end": 0.02, "output_dt": 0.01}}


def _run(name, overrides):
    command, sc = registries()[name]
    out, _ = sc.execute(overrides)
    return json.loads(json.dumps(out))  # what --json prints, parsed back


def test_every_scene_and_reference_has_a_schema():
    assert set(NAMES) == set(RESULTS) and len(NAMES) >= 9


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
    path = Path(__file__).resolve().parents[1] / "reports" / "schemas.md"
    assert path.read_text() == schemas_markdown(), "run `python -m ancf.study.schemas`"
