"""Physical validity of a configuration: no element turned inside out.

Green strain with a St Venant-Kirchhoff material has a second equilibrium branch
past the compressive limit point, where the material turns inside out
(``det F <= 0``, ``F = J J0^-1``, ``J = [r_x r_y]``).  Newton and the integrators
converge there happily; these checks turn such states into non-convergence.

Only what the elements expose is used: ``shapes`` ("x", "y" evaluators of (X, Y, L)),
``lengths``, ``section.rule(n)``, ``nel``, ``nshape``, and the reference
coordinates ``q0`` restricted by each group's DOF map.
"""
from __future__ import annotations

import weakref

import numpy as np

from ancf.core.quadrature import gauss01

N_AXIAL, N_SECTION = 3, 3  # check points per element: 3 Gauss points along x x 3 across y
AREA_FACTOR = 2.0  # det F beyond [1 / AREA_FACTOR, AREA_FACTOR]: strains far past the material's range
#: ``extra`` key of a static scene result: True when Newton converged and the stability check
#: alone refused the point (``ancf modes`` vibrates about it: its negative or zero eigenvalues
#: are what it reports)
UNSTABLE = "unstable"


_BASES = weakref.WeakKeyDictionary()  # element -> shape-function derivatives at the check points
_REFERENCE = weakref.WeakKeyDictionary()  # element -> (its q0 coordinates' bytes, det J0)


def _check_basis(el):
    """d S / dx and d S / dy (nel, npts, nshape) at the check points, evaluated once per element."""
    if el not in _BASES:
        xi, _ = gauss01(N_AXIAL)
        yq, _ = el.section.rule(N_SECTION)
        X = (xi[None, :, None] * el.lengths[:, None, None]) * np.ones((1, 1, yq.size))
        Y = np.broadcast_to(yq[None, None, :], X.shape)
        L = np.broadcast_to(el.lengths[:, None, None], X.shape)
        _BASES[el] = [el.shapes[d](X, Y, L).reshape(el.nel, -1, el.nshape) for d in ("x", "y")]
    return _BASES[el]


def _gradients(el, E):
    """r_x, r_y (..., nel, npts, 2) of element coordinates E (..., nel, nshape, 2)."""
    return [b @ E for b in _check_basis(el)]


def _det(rx, ry):
    return rx[..., 0] * ry[..., 1] - rx[..., 1] * ry[..., 0]


def _reference_det(el, E0) -> np.ndarray:
    """det J0 at the check points of element coordinates E0 (nel, nshape, 2), kept per
    element for the last E0 it was asked for (a scene's runs share their reference)."""
    key = E0.tobytes()
    kept = _REFERENCE.get(el)
    if kept is None or kept[0] != key:
        kept = (key, _det(*_gradients(el, E0)))
        kept[1].flags.writeable = False
        _REFERENCE[el] = kept
    return kept[1]


def deformation_dets(groups, q, q0) -> np.ndarray:
    """det(J J0^-1) at the check points: (..., all elements, points) for q (..., n_dofs)."""
    q, q0 = np.asarray(q, dtype=float), np.asarray(q0, dtype=float)
    out = []
    for g in groups:
        el = g.element
        shape = (el.nel, el.nshape, 2)
        E = q[..., g.dofmap].reshape(q.shape[:-1] + shape)
        out.append(_det(*_gradients(el, E)) / _reference_det(el, q0[g.dofmap].reshape(shape)))
    return np.concatenate(out, axis=-2)


def min_det(groups, q, q0) -> tuple[float, int]:
    """(smallest det(J J0^-1), index of its element counted over all groups) at q."""
    d = deformation_dets(groups, q, q0).min(axis=-1)
    i = int(np.argmin(d))
    return float(d[i]), i


def _inverted(det, element, n) -> str:
    return (f"element {element + 1} of {n} is inverted (det of the deformation gradient "
            f"{det:.3g} <= 0 at a quadrature point): not a physical state")


def check_static(res, assembly, q0):
    """A converged static point with an inverted element becomes non-convergence
    (results kept, flagged by the message, as for an unstable equilibrium); one whose
    area changes by more than AREA_FACTOR somewhere gets a warning."""
    if not res.converged:
        return res
    d = deformation_dets(assembly.groups, res.extra["q"], q0)
    lo, hi = d.min(axis=-1), d.max(axis=-1)
    n = lo.size
    if lo.min() <= 0:
        res.converged = False
        res.message = ("No convergence to a physical equilibrium: "
                       + _inverted(float(lo.min()), int(lo.argmin()), n))
        return res
    res.warnings += _strained(np.maximum(hi, 1.0 / lo))
    return res


def _strained(factor, when: str = "") -> list[str]:
    """The warning of an area change beyond AREA_FACTOR (``factor``: per element, >= 1)."""
    k = int(factor.argmax())
    if not factor[k] > AREA_FACTOR:
        return []
    return [f"element {k + 1} of {factor.size} changes its area by a factor {factor[k]:.3g}"
            f"{when}: strains far beyond the small-strain range of the St Venant-Kirchhoff "
            "material, the result is a property of the model, not of a beam"]


def check_dynamic(res, assembly, q0, t, Q):
    """The first sample with an inverted element ends trust in the run (a run that
    already failed keeps its own message first); an area changed by more than
    AREA_FACTOR at any sample (the static check's range) gets a warning."""
    Q = np.asarray(Q, dtype=float)
    if Q.size == 0:
        return res
    dets = deformation_dets(assembly.groups, Q, q0)  # (samples, elements, points)
    d = dets.min(axis=-1)
    with np.errstate(all="ignore"):
        factor = np.maximum(dets.max(axis=-1), 1.0 / np.where(d > 0, d, np.inf))
    worst = np.nanmax(np.where(np.isfinite(factor), factor, 0.0), axis=1)
    s = int(np.argmax(worst))
    res.warnings += _strained(np.nan_to_num(factor[s], posinf=0.0), f" at t = {t[s]:.6g} s")
    bad = np.flatnonzero(d.min(axis=-1) <= 0)
    if bad.size:
        k = int(bad[0])
        el = int(np.argmin(d[k]))
        note = f"Not trusted from t = {t[k]:.6g} s on: " + _inverted(float(d[k, el]), el, d.shape[1])
        res.message = note if res.converged else f"{res.message}; {note}"
        res.converged = False
    return res
