"""Static Newton solver: convergence near the round-off floor, and failure as a result."""
import pytest

from analytic.timoshenko import cantilever_tip_deflection
from ancf.scenes import SCENES


@pytest.mark.parametrize("slenderness", [100, 2000])
def test_small_load_converges_to_the_linear_solution(slenderness):
    """L/h = 100: a 0.1 N load sits near the round-off floor of the axial stiffness
    (absolute coordinates carry eps |q| errors): Newton must stop at that floor, not fail.
    L/h = 2000: the load (4e-6 N) is below that floor, so the floor must not accept the
    undeformed start.  Both equal Timoshenko to the 64 elements' discretisation error,
    today 6.10e-5 relative at both slendernesses; tolerance 1.25 x."""
    h = 2.0 / slenderness
    F = -1e-5 * 2.0 / abs(cantilever_tip_deflection(2.07e11, 0.3, 2.0, h, 0.1, -1.0))
    ref = cantilever_tip_deflection(2.07e11, 0.3, 2.0, h, 0.1, F)
    out, res = SCENES["cantilever"].execute(dict(h=h, F=F, n_elements=64, load_steps=1))
    assert out["converged"], out["message"]
    assert out["results"]["tip_y"] / ref == pytest.approx(1.0, abs=1.25 * 6.10e-5)
    assert res.extra["residuals"][0][-1] < res.extra["residuals"][0][0]


def test_residual_history_is_recorded_per_load_step():
    out, res = SCENES["cantilever"].execute(dict(n_elements=4, load_steps=5))
    assert out["converged"] and len(res.extra["residuals"]) == out["results"]["load_steps_taken"]
    for hist in res.extra["residuals"]:
        assert hist[-1] < 1e-8 * 5e5  # rtol * |F|


def test_singular_tangent_at_the_converged_point_is_not_a_solution():
    """Omar-Shabana with 2 points along x (all=2xe), 4 elements, Model 2: Newton's
    residual reaches the floor at a point whose tangent has a zero-energy mode (eigenvalue
    ~1e-17 of the largest), so the equilibrium is not unique: reported, not accepted.
    The thesis scheme at the same load has no zero eigenvalue."""
    bad = dict(element="omar-shabana", integration="all=2xe", n_elements=4, h=0.5, nu=0.0)
    out, _ = SCENES["cantilever"].execute(bad)
    assert not out["converged"] and "unique" in out["message"]
    good, _ = SCENES["cantilever"].execute(dict(bad, integration="thesis"))
    assert good["converged"] and good["results"]["zero_tangent_eigenvalues"] == 0


@pytest.mark.parametrize("load_steps, max_iterations", [(10, 25), (1, 25), (1, 3), (1, 1)])
def test_compiled_load_stepping_matches_the_python_one(monkeypatch, load_steps, max_iterations):
    """The load stepping compiled with the Newton iterations (``_Newton.march``) against
    the Python loop over Python-assembled iterations (no compiled group): the same steps
    and iteration counts (3 iterations a step: 1031 attempts, 512 steps), the same
    message (1 iteration a step: halved below the smallest increment, not converged),
    |r| histories and coordinates to 1e-9 relative (other assembly code rounds
    differently)."""
    from ancf.core.pattern import ReducedPattern
    ov = dict(n_elements=8, load_steps=load_steps, max_iterations=max_iterations)
    fast, fres = SCENES["cantilever"].execute(ov)
    monkeypatch.setattr(ReducedPattern, "compiled", lambda self, assembly: None)
    slow, sres = SCENES["cantilever"].execute(ov)
    keys = ("newton_iterations", "load_steps_taken", "tangent_evaluations", "factorizations")
    assert [fast["results"][k] for k in keys] == [slow["results"][k] for k in keys]
    assert (fast["converged"], fast["message"][:50]) == (slow["converged"], slow["message"][:50])
    f, s = fres.extra["residuals"], sres.extra["residuals"]
    assert [len(h) for h in f] == [len(h) for h in s]
    for a, b in zip(f, s):
        assert a == pytest.approx(b, rel=1e-9, abs=1e-9 * 5e5)
    assert fres.extra["q"] == pytest.approx(sres.extra["q"], rel=1e-9, abs=1e-12)
