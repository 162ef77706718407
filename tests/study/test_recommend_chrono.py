"""`ancf recommend` across element families (issue 35): the scenes that take Chrono's
elements (the 3D beam scenes: ancf3243, ancf3333; plate-square: ancf3423, ancf3443, ancf3833, its
statics and frequencies) put them in their recommendation grids beside the thesis
elements, and the recommender ranks their runs with the others'."""
from __future__ import annotations

import pandas as pd
import pytest

from ancf.scenes import SCENES
from ancf.study.recommend import recommend
from ancf.study.references import spec

CHRONO_BEAMS = {"ancf3243", "ancf3333"}
CHRONO_SHELLS = {"ancf3423", "ancf3443", "ancf3833"}
#: scene, quantity -> Chrono's elements its recommendation grids must hold
CASES = {("beam3d-cantilever", "results"): CHRONO_BEAMS,
         ("princeton-beam", "results"): CHRONO_BEAMS,
         ("beam3d-bending", "results"): CHRONO_BEAMS,
         ("plate-square", "results"): CHRONO_SHELLS,
         ("plate-square", "frequency"): CHRONO_SHELLS}


@pytest.fixture(scope="module", autouse=True)
def cache(workdir):
    """Every test here uses the module's scratch reference cache."""
    return workdir


def _grid_elements(scene: str, quantity: str) -> set:
    s = spec(scene, quantity)
    default = SCENES[scene].resolve({})["element"]
    return {e for g in s.recommend_grids for e in g.get("element", [default])}


@pytest.mark.parametrize("scene, quantity", list(CASES))
def test_recommend_grids_hold_chronos_elements_and_the_thesis_ones(scene, quantity):
    elements = _grid_elements(scene, quantity)
    allowed = {p for p in SCENES[scene].params if p.name == "element"}.pop().choices
    assert CASES[scene, quantity] <= elements <= set(allowed)
    assert elements - CASES[scene, quantity]          # and the suite's own elements
    assert "element" in spec(scene, quantity).knobs   # a model choice, not the problem


@pytest.mark.slow   # about 10 s: six static runs
def test_recommend_ranks_chrono_runs_with_the_thesis_ones():
    """At 4 elements the Princeton beam's grid is the thesis's four configurations and
    Chrono's two beams, all converged and none excluded for physics; with the tolerance
    just above the most accurate Chrono run's error, the pick meets it (a Chrono beam, or
    a thesis run as accurate and cheaper), and with the element fixed to it, the pick is
    that run."""
    res = recommend("princeton-beam", 1.0, fixed={"n_elements": 4}, workers=1, progress=False)
    df = pd.read_parquet(res["evidence"]["source"])
    assert CHRONO_BEAMS <= set(df["element"]) and set(df["status"]) == {"ok"}
    # every run meets tol = 1 and provides the scene's physics (the 3-node ancf3333 too)
    assert res["evidence"]["runs_meeting_tol"] == len(df) == 6
    assert "excluded_for_physics" not in res["evidence"]
    chrono = df[df["element"].isin(CHRONO_BEAMS)].sort_values("error").iloc[0]
    tol = float(chrono["error"]) * (1 + 1e-9)
    pick = recommend("princeton-beam", tol, fixed={"n_elements": 4}, workers=1, progress=False)
    assert pick["found"] and pick["error"] <= tol
    assert pick["work"] <= float(chrono["work"]) or pick["params"]["element"] in CHRONO_BEAMS
    own = recommend("princeton-beam", tol, fixed={"n_elements": 4, "element": chrono["element"]},
                    workers=1, progress=False)
    assert own["params"]["element"] == chrono["element"]
    assert own["error"] == pytest.approx(float(chrono["error"]), rel=1e-12)
