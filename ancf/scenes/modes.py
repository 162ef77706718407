"""``ancf modes SCENE``: natural frequencies and mode shapes of the static scenes.

The generalised eigenproblem ``K phi = omega^2 M phi`` of the scene's reduced system (its
constraints eliminated as its static solve eliminates them), M the consistent mass of its
elements (density ``rho``: the scene's own, or the one ``ancf modes`` adds), K the tangent
stiffness

* ``about = reference``: at the scene's reference state (the unloaded beam or plate; the
  free belt's laid shape, which is pre-stressed and no equilibrium);
* ``about = equilibrium``: at the scene's static equilibrium under its load, the
  pre-stressed tangent: a compressive load lowers the bending frequencies, and a
  frequency going to zero marks a limit (buckling) point.  The equilibrium is the scene's
  own run (:func:`equilibrium`), checked as ``ancf run`` checks it: an inverted element
  ends the run (exit 3), the strain range, the thin-plate range and the scene's ``warn``
  give their warnings; only the stability check's refusal is left to the modes, whose
  negative eigenvalues show it.

Solved by :func:`ancf.solvers.eigen.lowest` (dense LAPACK for small systems, else
shift-invert Lanczos on the band or sparse LU).  The output has the shape of
``ancf run``'s (``scene``, ``params``, ``converged``, ``message``, ``results``,
``cpu_time_s``, ``compile_cpu_s``, ``warnings``); the results (declared in
``ancf.study.schemas.MODES``) give the lowest ``count`` frequencies ascending, ``omega^2``, the
zero-frequency modes below the stated threshold, the mode shapes sampled on the structure
(beams: centreline points, plates: the mid surface's nodes; each normalised to a largest
displacement of 1, its largest component positive) and the work done.  An eigenvalue
omega^2 < 0 (an unstable state) is reported as the negative frequency
-sqrt(-omega^2) / (2 pi).
"""
from __future__ import annotations

import math
from dataclasses import replace
from functools import partial

import numpy as np

from ancf.common.params import InputError, Param
from ancf.core.validity import UNSTABLE
from ancf.scenes import scene
from ancf.scenes.base import ModalModel, Scene, SceneResult
from ancf.solvers.eigen import EigenFailure, lowest
from ancf.solvers.linear import ZERO_EIGENVALUE_REL

#: the scenes with modes, in the order of ``ancf.scenes.MODULES``
MODAL = ("simply-supported", "cantilever", "axial-bar", "belt-free-static", "plate-square",
         "plate-strip", "beam3d-cantilever")
ABOUT = Param("about", "reference", str, doc="state the tangent stiffness is taken at",
              choices=("reference", "equilibrium"))
#: modes computed when ``count`` is not given (fewer if the reduced system is smaller)
DEFAULT_COUNT = 6
#: about the equilibrium, a lowest omega^2 below this fraction of its value about the
#: reference marks the state as at (or near) a limit point
NEAR_LIMIT = 0.01
#: a mode whose sampled displacement is below this fraction of its largest coordinate
#: leaves the sample points in place (round-off of the mode vector)
STILL = 1e-8


def modal_scene(name: str) -> Scene:
    """The scene ``name`` with the parameters ``ancf modes`` adds (InputError naming the
    scenes with modes for any other name)."""
    if not isinstance(name, str) or name not in MODAL:
        raise InputError(f"modes: unknown name {name!r} or a scene without modes; allowed: "
                         f"{', '.join(MODAL)}")
    sc = scene(name)
    return replace(sc, params=sc.params + sc.modal_params, warn=None)


#: ``ancf sweep|recommend SCENE --quantity frequency``: the bending modes compared
COMPARED = Param("count", 3, int, doc="frequencies compared (sweep and recommend "
                 "--quantity frequency): the lowest K bending modes, those with more than "
                 "half their sampled motion across the first axis", lo=1, hi=50)


def frequency_scene(name: str) -> Scene:
    """``ancf modes NAME`` as a scene of the sweeps (``--quantity frequency``): its
    parameters and ``count`` (:data:`COMPARED`), about the reference state, with the
    lowest 2 count + 2 modes computed (fewer if the reduced system is smaller) so that the
    study layer finds ``count`` bending modes among them; the results are ``ancf
    modes``'s."""
    sc = modal_scene(name)
    return replace(sc, params=sc.params + (COMPARED,), run=partial(_run_compared, scene(name)))


def _run_compared(static: Scene, p: dict) -> SceneResult:
    mm = static.modal(p)
    n = mm.pattern.n
    if n < 2:
        raise InputError(f"n_elements = {p.get('n_elements')} is out of range for modes: the "
                         "reduced system has fewer than 2 unknowns")
    return _run(static, min(2 * p["count"] + 2, n - 1), "reference", p, mm)


def _count(value) -> int | None:
    """``count`` as an integer >= 1 (None: the default); its upper bound needs the model."""
    allowed = "allowed: an integer >= 1 and below the reduced size of the model"
    if value is None:
        return None
    try:
        v = float(value)
        if not v.is_integer():
            raise ValueError
    except (TypeError, ValueError, OverflowError):
        raise InputError(f"count: {value!r} is not valid; {allowed}") from None
    if v < 1:
        raise InputError(f"count = {int(v)} is out of range; {allowed}")
    return int(v)


def _check_count(count: int | None, n: int) -> int:
    if count is None:
        return min(DEFAULT_COUNT, n - 1)
    if count >= n:
        raise InputError(f"count = {count} is out of range; allowed: an integer in [1, {n - 1}] "
                         f"(below the reduced size {n} of this model)")
    return count


def execute(name: str, overrides: dict | None = None, count=None, about="reference"):
    """Validate, run and time ``ancf modes NAME``; returns (public JSON dict, SceneResult)."""
    sc = modal_scene(name)
    about = ABOUT.parse(about)
    count = _count(count)
    return replace(sc, run=partial(_run, scene(name), count, about)).execute(overrides)


def _signed_hz(lam: np.ndarray) -> list:
    return (np.sign(lam) * np.sqrt(np.abs(lam)) / (2.0 * math.pi)).tolist()


def _shape(u: np.ndarray, phi: np.ndarray) -> np.ndarray:
    """Displacements u of the sample points scaled to a largest |u| of 1, its largest
    component positive; zero where the mode phi leaves them in place (|u| at round-off
    of phi, :data:`STILL`: a beam section's torsion)."""
    size = np.linalg.norm(u, axis=1).max()
    if size <= STILL * np.abs(phi).max():
        return np.zeros_like(u)
    return u / (size * np.sign(u.flat[np.argmax(np.abs(u))]))


def _shapes(mm: ModalModel, vectors: np.ndarray) -> tuple[list, list]:
    """(mode shapes (count, points, dim), shares of each direction (count, dim), zero for a
    mode that leaves the sample points in place)."""
    zero = np.zeros(mm.pattern.n_dofs)
    shapes, shares = [], []
    for v in vectors.T:
        phi = mm.pattern.expand(v, zero)
        u = _shape(mm.points(phi), phi)
        shapes.append(u.tolist())
        sq = (u**2).sum(axis=0)
        shares.append((sq / sq.sum() if sq.any() else sq).tolist())
    return shapes, shares


def _eigen(mm: ModalModel, q, count: int):
    _, K = mm.pattern.assemble(mm.assembly, q)
    return lowest(mm.pattern, K, mm.pattern.mass(mm.assembly), count)


def _empty(about, count, n, mm: ModalModel, q, newton) -> dict:
    """Results of a run that found no eigenpairs (the null keys are nullable)."""
    return {"about": about, "count": count, "method": None, "reduced_size": n,
            "frequencies_hz": None, "eigenvalues_rad2_s2": None, "rigid_body_modes": None,
            "rigid_body_threshold_rel": ZERO_EIGENVALUE_REL, "sampling": mm.sampling,
            "sample_points": mm.points(q).tolist(), "mode_shapes": None,
            "mode_direction_shares": None, "newton_iterations": newton, "factorizations": None,
            "solves": None, "shift_rad2_s2": None, "sturm_count": None, "missed_modes": None}


def equilibrium(static: Scene, p: dict) -> SceneResult:
    """The static equilibrium ``--about equilibrium`` vibrates about: the scene's own
    ``equilibrium`` or its run at the same parameters, with every check ``ancf run`` makes
    (an inverted element: no equilibrium; strain range, thin-plate range, the scene's
    ``warn``: warnings), but one: a point the stability check alone refused (``extra[
    UNSTABLE]``) is kept, since the modes about it show its instability as negative
    eigenvalues (warned by :func:`_warnings`)."""
    res = (static.equilibrium or static.run)(p)
    if res.extra.get(UNSTABLE):
        res.converged, res.message = True, "converged (unstable)"
    res.warnings += static.warn(p, res) if static.warn else []
    return res


def _run(static: Scene, count, about, p: dict, mm: ModalModel | None = None) -> SceneResult:
    mm = mm or static.modal(p)
    n = mm.pattern.n
    count = _check_count(count, n)
    q, newton, checked = mm.q0, 0, []
    extra = {"q0": mm.q0, "model": mm} | ({} if mm.mesh is None else {"mesh": mm.mesh})
    if about == "equilibrium":
        eq = equilibrium(static, p)
        q, newton = eq.extra.get("q", mm.q0), eq.results.get("newton_iterations") or 0
        checked = eq.warnings
        if not eq.converged:
            return SceneResult(False, f"No equilibrium to vibrate about: {eq.message}",
                               _empty(about, count, n, mm, q, newton), extra | {"q": q}, checked)
    extra["q"] = q
    try:
        pairs = _eigen(mm, q, count)
        ref = _eigen(mm, mm.q0, 1).values[0] if about == "equilibrium" else None
    except EigenFailure as exc:
        return SceneResult(False, f"No eigenpairs: {exc}", _empty(about, count, n, mm, q, newton),
                           extra, checked)
    results, warnings = _results(mm, pairs, q, about, count, newton, ref)
    extra["vectors"] = np.stack([mm.pattern.expand(v, np.zeros(mm.pattern.n_dofs))
                                 for v in pairs.vectors.T], axis=1)
    return SceneResult(True, "converged", results, extra, checked + warnings)


def _results(mm, pairs, q, about, count, newton, ref) -> tuple[dict, list]:
    lam = pairs.values
    rigid = pairs.stiffness_rel <= ZERO_EIGENVALUE_REL
    shapes, shares = _shapes(mm, pairs.vectors)
    results = {
        "about": about, "count": count, "method": pairs.method, "reduced_size": mm.pattern.n,
        "frequencies_hz": _signed_hz(lam), "eigenvalues_rad2_s2": lam.tolist(),
        "rigid_body_modes": int(rigid.sum()), "rigid_body_threshold_rel": ZERO_EIGENVALUE_REL,
        "sampling": mm.sampling, "sample_points": mm.points(q).tolist(), "mode_shapes": shapes,
        "mode_direction_shares": shares, "newton_iterations": newton,
        "factorizations": pairs.factorizations, "solves": pairs.solves,
        "shift_rad2_s2": pairs.shift, "sturm_count": pairs.sturm_count,
        "missed_modes": pairs.missed}
    if ref is not None:
        results["lowest_frequency_reference_hz"] = _signed_hz(np.array([ref]))[0]
    return results, _warnings(lam, rigid, about, ref, pairs.missed)


def _warnings(lam, rigid, about, ref, missed) -> list:
    out = []
    negative = int(np.sum((lam < 0) & ~rigid))
    if negative and about == "equilibrium":
        out.append(f"at or beyond a limit point: {negative} negative eigenvalue(s) of the "
                   f"pre-stressed tangent (omega^2 down to {lam[0]:.4g} rad^2/s^2, reported as "
                   "negative frequencies): the equilibrium is unstable")
    elif negative:
        out.append(f"{negative} negative eigenvalue(s) of the tangent at the reference state "
                   f"(omega^2 down to {lam[0]:.4g} rad^2/s^2, reported as negative "
                   "frequencies): the reference is no stable equilibrium (or its stiffness is "
                   "lost to round-off)")
    elif about == "equilibrium" and ref > 0 and lam[0] < NEAR_LIMIT * ref:
        out.append(f"at or beyond a limit point: the lowest omega^2 about the equilibrium is "
                   f"{lam[0] / ref:.3g} of its value about the reference (below {NEAR_LIMIT:g})")
    if rigid.any():
        out.append(f"{int(rigid.sum())} zero-frequency mode(s) (|phi^T K phi| <= "
                   f"{ZERO_EIGENVALUE_REL:g} |K| |phi|^2): a mechanism, or a zero-energy mode of "
                   "the integration scheme")
    if missed:
        out.append(f"the Sturm check finds {missed} eigenvalue(s) more than were computed "
                   "below the highest reported: mode(s) missed")
    return out
