"""The runs a process shares (``ancf.scenes.store``): :func:`execute_once` runs a scene once
for each resolved parameter set, whatever the spelling of its overrides."""
from ancf.scenes import scene
from ancf.scenes.store import execute_once, run_key


def test_overrides_spelled_differently_share_one_run():
    """A default named, left out or given as text is one run; another value is another."""
    n = scene("axial-bar").resolve({})["n_elements"]
    first = execute_once("axial-bar", {})
    assert execute_once("axial-bar", {"n_elements": n}) is first
    assert execute_once("axial-bar", {"n_elements": str(n)}) is first
    other = execute_once("axial-bar", {"n_elements": n + 1})
    assert other is not first
    assert other[0]["params"]["n_elements"] == n + 1 and first[0]["params"]["n_elements"] == n


def test_the_key_is_the_resolved_parameters():
    assert run_key("belt2d", {"nu_s": 1e5}) == run_key("belt2d", {})
    assert run_key("belt2d", {"nu_s": 1e4}) != run_key("belt2d", {})
    assert run_key("pendulum", {"element": "linear", "n_elements": "4"}) == \
        run_key("pendulum", {"n_elements": 4})
