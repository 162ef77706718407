"""Drive files in `ancf sweep` and `ancf recommend` (issue 21 item 7): the model choices of
a drive file (belt.n_elements, run.dt, contact.gauss_points) are the belt-drive scene's
parameters n_elements, dt, gauss_points, and the reference is the steady belt on the
file's layout (analytic/belt_steady.py: span tensions and pulley speeds)."""
import json
import sys
from pathlib import Path

import numpy as np
import pandas as pd
import pytest

from ancf.belts.drive_file import load
from ancf.common.params import InputError
from ancf.common.paths import REPO
from ancf.scenes import SCENES
from ancf.scenes.belt_drive import steady_reference
from ancf.study.references import spec

EXAMPLES = REPO / "examples"
THREE = str(EXAMPLES / "three_pulleys.toml")
#: a short run, the laws ramped over 0.05 s: the sweep's machinery, not the steady state
#: (its error, 0.77 seen, is the start-up's)
SHORT = sum((("--set", s) for s in ("run.t_end=0.1", "run.steady_window=0.03",
                                    "pulleys.driver.t0=0", "pulleys.driver.t1=0.05",
                                    "pulleys.driven.t0=0", "pulleys.driven.t1=0.05")), ())


@pytest.fixture(scope="module", autouse=True)
def cache(workdir):
    return workdir


@pytest.mark.parametrize("name", ["three_pulleys.toml", "serpentine.toml"])
def test_steady_reference_is_the_npulley_tests_reference(name):
    """The library's steady reference of a drive file equals the one test_belt_npulley.py
    builds by hand from the file."""
    sys.path.insert(0, str(Path(__file__).parents[1] / "belts"))
    import test_belt_npulley as npulley
    p = SCENES["belt-drive"].resolve({"file": str(EXAMPLES / name)})
    assert steady_reference(p) == npulley._reference(load(EXAMPLES / name, []))


def test_model_parameters_resolve_to_the_files_values_and_move_out_of_set():
    sc = SCENES["belt-drive"]
    p = sc.resolve({"file": THREE, "belt.n_elements": "40", "friction.mu": "1.0"})
    assert (p["n_elements"], p["dt"], p["gauss_points"]) == (40, 2.5e-4, 7)
    assert p["set"] == "friction.mu=1.0"
    assert spec("belt-drive").physical(p) == {"file": THREE, "set": "friction.mu=1.0"}
    with pytest.raises(InputError, match="belt.n_elements: given twice"):
        sc.resolve({"n_elements": "30", "belt.n_elements": "40"})


@pytest.mark.slow
def test_sweep_and_recommend_a_drive_file(tmp_path, cli):
    """Two meshes of three_pulleys.toml, 0.1 s: both rows scored against the steady
    reference; recommend from the rows picks the cheaper where both meet the tolerance,
    and reports no model where none does."""
    out = tmp_path / "drive.csv"
    rc, stdout, err = cli("sweep", "belt-drive", "--file", THREE, *SHORT, "--grid",
                           "n_elements=40,60", "--out", str(out), "--workers", "2",
                           "--no-progress", "--json")
    assert rc == 0, err
    data = json.loads(stdout)
    assert data["status"] == {"ok": 2} and data["reference"] == "steady"
    df = pd.read_csv(out)
    assert list(df["n_elements"]) == [40, 60] and np.all(np.isfinite(df["error"]))
    assert df["work"].iloc[0] < df["work"].iloc[1]
    tol = float(1.01 * df["error"].max())
    rc, stdout, _ = cli("recommend", "belt-drive", "--file", THREE, *SHORT, "--tol",
                         f"{tol!r}", "--data", str(out), "--json")
    rec = json.loads(stdout)
    assert rc == 0 and rec["found"] and rec["params"]["n_elements"] == 40
    assert rec["error"] == pytest.approx(df["error"].iloc[0], rel=1e-12)
    route = rec["evidence"]["steady_route"]  # the steady question's route without a march
    assert route["applies"] and route["command"].startswith("ancf steady belt-drive --file")
    assert route["command"] in rec["message"]
    rc, stdout, _ = cli("recommend", "belt-drive", "--file", THREE, *SHORT, "--tol",
                         f"{float(0.5 * df['error'].min())!r}", "--data", str(out), "--json")
    assert rc == 3 and not json.loads(stdout)["found"]


@pytest.mark.parametrize("argv, text", [
    (("sweep", "belt-drive", "--file", THREE, "--grid", "n_elements=2"),
     "error: belt.n_elements = 2 is out of range; allowed: an integer in [4, 2000]"),
    (("sweep", "cantilever", "--file", THREE), "error: --file: scene 'cantilever' takes no file"),
    (("sweep", "belt-drive", "--set", "friction.mu=-1"), "error: friction.mu = -1"),
])
def test_drive_sweep_bad_input(cli, argv, text, tmp_path):
    rc, _, err = cli(*argv, "--out", str(tmp_path / "x.csv"), "--no-progress")
    errors = [line for line in err.splitlines() if not line.startswith("sweep ")]  # its count
    assert rc == 2 and len(errors) == 1 and errors[0].startswith(text), err
