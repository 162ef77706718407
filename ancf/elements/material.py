"""Materials of the planar continuum beams and the energy terms they are split into.

A material is a 3x3 matrix acting on Voigt Green strains ``[eps_xx, eps_yy, 2 eps_xy]``
(Pa), or for the spatial beams and Chrono's ANCF elements a 6x6 one on ``[eps_xx,
eps_yy, eps_zz, 2 eps_yz, 2 eps_xz, 2 eps_xy]`` (``isotropic_3d``, ``orthotropic_3d``,
``rotate_about_z``).  An element's strain energy is a sum of :class:`EnergyTerm` s, each a part of
the material integrated with its own rule: this is how selective and reduced
integration are expressed (``normal=2x2,shear=1x1``; ``e`` = exact across the height).
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ancf.core.quadrature import EXACT
from ancf.elements.continuum3d import VOIGT


@dataclass(frozen=True)
class EnergyTerm:
    """Material matrix ``C`` (3x3, Pa) integrated with ``nx`` Gauss points along the
    axis and ``ny`` points (or ``"exact"``) across the height."""

    name: str
    C: np.ndarray
    nx: int
    ny: object


def lame_matrix(E: float, nu: float) -> np.ndarray:
    """Eq. 2.17: plane-strain matrix of Lamé constants, Pa."""
    lam = E * nu / ((1.0 + nu) * (1.0 - 2.0 * nu))
    mu = E / (2.0 * (1.0 + nu))
    return np.array([[lam + 2 * mu, lam, 0.0], [lam, lam + 2 * mu, 0.0], [0.0, 0.0, mu]])


def beam_material(E: float, nu: float, ks: float) -> tuple[np.ndarray, np.ndarray]:
    """Eq. 2.18 without Poisson coupling, split into its normal part diag(E, E, 0)
    and its shear part diag(0, 0, ks G), G = E / (2 (1 + nu))."""
    G = E / (2.0 * (1.0 + nu))
    return np.diag([E, E, 0.0]), np.diag([0.0, 0.0, ks * G])


def beam_material_3d(E: float, nu: float, ks: float) -> tuple[np.ndarray, np.ndarray]:
    """:func:`beam_material` in 3D: normal part diag(E, E, E, 0, 0, 0) and shear part
    diag(0, 0, 0, ks G, ks G, ks G) on the spatial Voigt strains, Pa."""
    C_normal, C_shear = beam_material(E, nu, ks)
    e, ksg = C_normal[0, 0], C_shear[2, 2]
    return np.diag([e, e, e, 0.0, 0.0, 0.0]), np.diag([0.0, 0.0, 0.0, ksg, ksg, ksg])


def parse_rule(text: str):
    """'2x2' -> (2, 2); '1xe' -> (1, 'exact')."""
    try:
        nx, ny = text.lower().split("x")
        ny = EXACT if ny in ("e", "exact") else int(ny)
        nx = int(nx)
        if nx < 1 or (ny != EXACT and ny < 1):
            raise ValueError
        return nx, ny
    except ValueError:
        raise ValueError(f"integration rule {text!r} must look like 'NXxNY' with NX >= 1 "
                         f"Gauss points along x and NY >= 1 or 'e' (exact) across y") from None


def _merge_same_rule(terms):
    """Terms sharing a quadrature rule are one term with the summed material matrix
    (the thesis scheme then costs one kernel evaluation, not two)."""
    merged = {}
    for t in terms:
        key = (t.nx, t.ny)
        if key in merged:
            m = merged[key]
            merged[key] = EnergyTerm(f"{m.name}+{t.name}", m.C + t.C, t.nx, t.ny)
        else:
            merged[key] = t
    return list(merged.values())


def scheme_terms(schemes: dict, integration: str, C_normal, C_shear):
    """Energy terms of a named scheme of ``schemes`` or of a spec 'normal=2x2,shear=1x1'."""
    usage = (f"integration must be one of {sorted(schemes)} or a spec like "
             f"'normal=2x2,shear=1x1' (got {integration!r})")
    if not isinstance(integration, str):
        raise ValueError(usage)
    terms = []
    for part in schemes.get(integration, integration).split(","):
        try:
            group, rule = (s.strip() for s in part.split("="))
        except ValueError:
            raise ValueError(usage) from None
        C = {"normal": C_normal, "shear": C_shear, "all": C_normal + C_shear}.get(group)
        if C is None:
            raise ValueError(f"integration group {group!r} must be normal, shear or all")
        terms.append(EnergyTerm(group, C, *parse_rule(rule)))
    groups = sorted(t.name for t in terms)
    if groups not in (["all"], ["normal", "shear"]):
        raise ValueError(f"integration spec {integration!r} must give each of 'normal' and "
                         f"'shear' once, or 'all' alone (got {', '.join(groups)})")
    return _merge_same_rule(terms)


def isotropic_3d(E: float, nu: float) -> np.ndarray:
    """The isotropic 3D law D (6, 6), Pa, Voigt order [11, 22, 33, 23, 13, 12] (shear
    rows on the engineering strains 2E_IJ): lambda + 2 mu on the diagonal of the normal
    block, lambda off it, mu on the shear diagonal; lambda = E nu/((1+nu)(1-2nu)),
    mu = E/(2(1+nu)) (Chrono's ``ChMaterialShellANCF(rho, E, nu)``, ``ChMaterialHexaANCF``)."""
    mu = E / (2.0 * (1.0 + nu))
    lam = E * nu / ((1.0 + nu) * (1.0 - 2.0 * nu))
    D = np.diag([2.0 * mu] * 3 + [mu] * 3)
    D[:3, :3] += lam
    return D


def orthotropic_3d(E, nu, G) -> np.ndarray:
    """The 3D orthotropic stiffness D (6, 6), Pa, Voigt order [11, 22, 33, 23, 13, 12]
    (engineering shears), as the inverse of the compliance: E = (E_x, E_y, E_z) in Pa,
    nu = (nu_xy, nu_xz, nu_yz) with nu_ji = nu_ij E_j / E_i, G = (G_xy, G_xz, G_yz) in Pa
    (the arguments of Chrono's orthotropic ``ChMaterialShellANCF``)."""
    (Ex, Ey, Ez), (nxy, nxz, nyz), (Gxy, Gxz, Gyz) = E, nu, G
    C = np.diag([1 / Ex, 1 / Ey, 1 / Ez])
    C[0, 1] = C[1, 0] = -nxy / Ex
    C[0, 2] = C[2, 0] = -nxz / Ex
    C[1, 2] = C[2, 1] = -nyz / Ey
    D = np.zeros((6, 6))
    D[:3, :3] = np.linalg.inv(C)
    D[3:, 3:] = np.diag([Gyz, Gxz, Gxy])
    return D


def rotate_about_z(D: np.ndarray, theta: float) -> np.ndarray:
    """D (6, 6) of a layer whose material axes 1, 2 are turned by theta (rad) about z
    from the element's x, y (1 along (cos theta, sin theta, 0)): D_elem = T D T^T with
    T the stress transformation sigma_elem = T sigma_mat (order [11, 22, 33, 23, 13, 12]).
    Chrono's 3443 (``RotateReorderStiffnessMatrix``) equals rotate_about_z(D, -theta) on the
    normal/in-plane-shear block but rotate_about_z(D, +theta) on the (23, 13) block: the
    same for isotropic layers or G_xz = G_yz, or theta = 0 (its stored data); unchecked else."""
    c, s = np.cos(theta), np.sin(theta)
    Rm = np.array([[c, -s, 0.0], [s, c, 0.0], [0.0, 0.0, 1.0]])  # columns: material axes
    T = np.array([[Rm[i, k] * Rm[j, l] + (Rm[i, l] * Rm[j, k] if k != l else 0.0)
                   for k, l in VOIGT] for i, j in VOIGT])
    return T @ D @ T.T
