"""Validation of the thin plate and the 3D beam (issue 13 item 4) as plain data, shared by
``tests/checks/test_elements3d.py`` and the report chapter ``elements3d``.

Every check is a :class:`~ancf.checks.belt2d.Check` (value, reference, difference,
tolerance, unit, measure).  The plate runs go through the scenes ``plate-square`` and
``plate-strip`` (and :mod:`ancf.models.plate` for the linear strip); the 3D beam runs
through :mod:`ancf.models.beam3d` and the scene ``beam3d-cantilever``, held against the planar
scenes.  Runs are cached within a process.

Problems:

* plate: a = 1 m, h = 0.01 m, E = 2.1e11 Pa, nu = 0.3, p = 1e3 Pa (Navier w_c = h/47);
* strip: 1 m x 0.05 m, h = 0.01 m, end load P = 1 N (linear, against Euler-Bernoulli
  P L^3/(3 E I), I = b h^3/12), and F = E I / L^2 (large deflection, tip at 0.30 L,
  nu = 0, against the Reissner rod with shear switched off: ks = 1e6);
* 3D beam: the planar scenes' cases on the square section 0.1 m x 0.1 m.
"""
from __future__ import annotations

import math
from functools import lru_cache

import numpy as np

from analytic import navier_plate, reissner
from ancf.models import beam3d
from ancf.models import plate as plate_models
from ancf.checks.belt2d import Check
from ancf.models.plate_mesh import PlateMesh
from ancf.core.quadrature import RectangularSection
from ancf.scenes import SCENES

PLATE = dict(a=1.0, h=0.01, E=2.1e11, nu=0.3, p=1e3)
PLATE_NS = (2, 4, 8, 16)
STRIP = dict(L=1.0, b=0.05, h=0.01, E=2.1e11)
STRIP_MESHES = ((1, 1), (2, 1), (4, 1), (8, 1), (8, 2), (16, 2))
STRIP_LARGE_NS = (4, 8, 16)
RIGID_SHEAR_KS = 1e6   # "shear switched off" in the Reissner rod
BEAM_CASES = {  # scene, overrides, supports, loaded node (-1 = last, None = mid)
    "cantilever-small": ("cantilever", {"F": -1000.0}, beam3d.clamp, -1),
    "cantilever-model1": ("cantilever", {}, beam3d.clamp, -1),
    "simply-supported": ("simply-supported", {}, beam3d.pins, None),
}

NAVIER_TOL, ORDER_TOL = 0.01, 0.2
STRIP_TOL, REISSNER_STRIP_TOL = 1e-6, 1e-3
ROUND_OFF = 1e-10


@lru_cache(maxsize=None)
def _scene(name: str, items: tuple) -> dict:
    out, _ = SCENES[name].execute(dict(items))
    if not out["converged"]:
        raise RuntimeError(f"{name} {dict(items)}: {out['message']}")
    return out


def scene(name: str, **overrides) -> dict:
    """The public JSON dict of a converged scene run (cached)."""
    return _scene(name, tuple(sorted(overrides.items())))


# ------------------------------------------------------------------ plate
def plate_convergence(ns=PLATE_NS) -> list[dict]:
    """plate-square per mesh: n, w (m), Navier w (m), relative error, observed order."""
    rows = []
    for n in ns:
        r = scene("plate-square", n_elements=n, **PLATE)["results"]
        rows.append({"n per side": n, "w [m]": r["center_deflection_m"],
                     "Navier w [m]": r["navier_center_deflection_m"],
                     "relative error": r["relative_error"]})
    for prev, row in zip(rows, rows[1:]):
        row["observed order"] = math.log2(abs(prev["relative error"] / row["relative error"]))
    return rows


def euler_bernoulli_tip(P=1.0) -> float:
    """P L^3 / (3 E I) of the strip, m."""
    return P * STRIP["L"] ** 3 / (3 * STRIP["E"] * STRIP["b"] * STRIP["h"] ** 3 / 12)


def strip_linear(nu: float, meshes=STRIP_MESHES) -> list[dict]:
    """Linear strip tip deflection per mesh against Euler-Bernoulli (P = 1 N)."""
    w_eb = euler_bernoulli_tip()
    return [{"mesh": f"{nx} x {ny}", "nu": nu,
             "w [m]": (w := plate_models.strip_linear_tip(nx, ny, nu=nu, P=1.0, **STRIP)),
             "Euler-Bernoulli [m]": w_eb, "relative error": w / w_eb - 1}
            for nx, ny in meshes]


def strip_load() -> float:
    """F = E I / L^2, N."""
    return STRIP["E"] * STRIP["b"] * STRIP["h"] ** 3 / 12 / STRIP["L"] ** 2


@lru_cache(maxsize=None)
def reissner_strip() -> tuple[float, float]:
    """(tip x, tip deflection) of the Reissner rod under F = E I / L^2, nu = 0, ks = 1e6."""
    s = STRIP
    r = reissner.tip_position(s["E"], 0.0, s["L"], s["h"], s["b"], strip_load(), ks=RIGID_SHEAR_KS)
    if not r.converged:
        raise RuntimeError(f"Reissner strip: {r.message}")
    return r.tip_x, r.tip_y


def strip_large(ns=STRIP_LARGE_NS) -> list[dict]:
    """plate-strip (nu = 0, n x 1, F = E I / L^2) against the Reissner rod: largest relative
    error of the tip coordinates x and z."""
    rx, rz = reissner_strip()
    rows = []
    for n in ns:
        r = scene("plate-strip", n_elements=n, n_width=1, nu=0.0, F=strip_load(), load_steps=4,
                  rtol=1e-10, **STRIP)["results"]
        rows.append({"n_elements": n, "tip x [m]": r["tip_x"], "tip z [m]": r["tip_z"],
                     "Reissner x [m]": rx, "Reissner z [m]": rz,
                     "relative error": max(abs(r["tip_x"] / rx - 1), abs(r["tip_z"] / rz - 1))})
    return rows


def plate_rigid_motion() -> float:
    """Largest element energy of a rigidly rotated and moved 2 x 2 plate over E h a b."""
    m = PlateMesh(0.6, 0.4, 2, 2)
    asm = plate_models.assembly(m, PLATE["h"], PLATE["E"], PLATE["nu"])
    q = _move(m.reference(), m.n_nodes, _rotation([1.0, 2.0, 3.0], 1.3), [0.3, -2.0, 5.0])
    el = asm.groups[0].element
    return float(np.abs(el.energy(q[m.dofmap])).max() / (PLATE["E"] * PLATE["h"] * m.a * m.b))


# ------------------------------------------------------------------ 3D beam
def _rotation(axis, angle):
    """Rodrigues' rotation matrix about ``axis`` by ``angle`` rad."""
    k = np.asarray(axis, float) / np.linalg.norm(axis)
    Kx = np.array([[0, -k[2], k[1]], [k[2], 0, -k[0]], [-k[1], k[0], 0]])
    return np.eye(3) + np.sin(angle) * Kx + (1 - np.cos(angle)) * Kx @ Kx


def _move(q, n_nodes, R, shift):
    """r -> R r + shift, slopes -> R slopes (three 3-vector slots per node, r first)."""
    V = q.reshape(n_nodes, 3, 3) @ R.T
    V[:, 0, :] += shift
    return V.ravel()


def beam_solve(p, supports, loads) -> np.ndarray:
    """Nodal displacements (n_nodes, 3, 3) of a converged 3D static solve (ancf.models.beam3d)."""
    res, m, q0, _ = beam3d.solve({**p, "element": "linear3d"}, supports, loads)
    if not res.converged:
        raise RuntimeError(f"3D beam: {res.message}")
    return (res.q - q0).reshape(m.n_nodes, 3, 3)


def principal_plane(case: str, scheme: str = "thesis", axis: int = 1) -> tuple[float, float]:
    """The planar scene's load along -y (axis 1) or -z (axis 2) on the square section:
    (largest in-plane nodal difference, largest out-of-plane displacement), each over the
    largest 2D displacement."""
    name, over, supports, node = BEAM_CASES[case]
    over = {"element": "linear", "integration": scheme, **over}
    _, res = SCENES[name].execute(over)
    if not res.converged:
        raise RuntimeError(f"{name}: {res.message}")
    u2 = (res.extra["q"] - res.extra["q0"]).reshape(-1, 2, 2)
    p = SCENES[name].resolve(over)
    node = u2.shape[0] // 2 if node is None else node % u2.shape[0]
    u3 = beam_solve(p, supports, {(node, "r", axis): p["F"]})
    inplane = np.ix_(range(u3.shape[0]), [0, axis], [0, axis])
    scale = np.abs(u2).max()
    out = u3.copy()
    out[inplane] = 0.0
    return float(np.abs(u3[inplane] - u2).max() / scale), float(np.abs(out).max() / scale)


def scene_at_zero_degrees() -> float:
    """beam3d-cantilever at 0 deg (defaults, Model 1) against the cantilever scene:
    largest relative difference of tip_x, tip_y (and |tip_z| over |tip_y|)."""
    r2 = scene("cantilever", element="linear")["results"]
    r3 = scene("beam3d-cantilever")["results"]
    return max(abs(r3["tip_x"] / r2["tip_x"] - 1), abs(r3["tip_y"] / r2["tip_y"] - 1),
               abs(r3["tip_z"] / r2["tip_y"]))


def scene_at_90_degrees() -> float:
    """beam3d-cantilever at 90 deg against 0 deg (square section): max relative difference
    of (x, z) at 90 deg and (x, y) at 0 deg, and |tip_y| at 90 deg over |tip_y| at 0."""
    r0 = scene("beam3d-cantilever")["results"]
    r9 = scene("beam3d-cantilever", load_angle_deg=90.0)["results"]
    return max(abs(r9["tip_x"] / r0["tip_x"] - 1), abs(r9["tip_z"] / r0["tip_y"] - 1),
               abs(r9["tip_y"] / r0["tip_y"]))


def superposition_45() -> dict:
    """The small-deflection cantilever (F = -1000 N) with F at 45 deg against the sum of the
    solves with F/sqrt 2 along -y and -z: the differences over their second-order bounds,
    (w/L)^2 max |u_r| for positions and w/L max |u_slope| for slopes (w the tip
    deflection), and the 45-degree symmetry |u_y - u_z| / |u_y| of the tip."""
    p = SCENES["cantilever"].resolve({"element": "linear", "F": -1000.0})
    f, tip = p["F"] / math.sqrt(2.0), p["n_elements"]
    u_y = beam_solve(p, beam3d.clamp, {(tip, "r", 1): f})
    u_z = beam_solve(p, beam3d.clamp, {(tip, "r", 2): f})
    u = beam_solve(p, beam3d.clamp, {(tip, "r", 1): f, (tip, "r", 2): f})
    wl = np.linalg.norm(u[tip, 0]) / p["L"]
    d = u - u_y - u_z
    return {"position": float(np.abs(d[:, 0]).max() / (wl**2 * np.abs(u[:, 0]).max())),
            "slope": float(np.abs(d[:, 1:]).max() / (wl * np.abs(u[:, 1:]).max())),
            "symmetry": float(abs(u[tip, 0, 1] - u[tip, 0, 2]) / abs(u[tip, 0, 1])),
            "w_over_L": float(wl)}


def torsion(scheme: str = "thesis", ks: float = 5.0 / 6.0) -> dict:
    """A cantilever (square section a = h) twisted by a tip torque T (the couple of a linear
    shear traction on the end face, tip twist 1e-6 rad): the twist's largest relative
    difference from T x / (ks G I_p), the element's torsional stiffness ks G I_p and
    St-Venant's G J (J = 0.1406 a^4), and their ratio G J / (ks G I_p) = J / (ks I_p)."""
    p = SCENES["cantilever"].resolve({"element": "linear", "integration": scheme, "ks": ks,
                                      "nu": 0.3})
    a, tip = p["h"], p["n_elements"]
    p["b"] = a
    G = p["E"] / (2.0 * (1.0 + p["nu"]))
    s = RectangularSection(a, a)
    Iy, Iz = s.h * s.b**3 / 12.0, s.second_moment
    Ip = Iy + Iz
    T = 1e-6 * ks * G * Ip / p["L"]
    u = beam_solve(p, beam3d.clamp, {(tip, "r_y", 2): T * Iz / Ip, (tip, "r_z", 1): -T * Iy / Ip})
    phi = np.arctan2(u[:, 1, 2], 1.0 + u[:, 1, 1])
    x = np.linspace(0.0, p["L"], tip + 1)
    exact = T * x / (ks * G * Ip)
    J = beam3d.torsion_constant_square(a)
    stiffness = T * p["L"] / phi[-1]
    return {"twist_error": float(np.abs(phi[1:] / exact[1:] - 1).max()),
            "stiffness_Nm2": float(stiffness), "ks_G_Ip_Nm2": ks * G * Ip, "G_J_Nm2": float(G * J),
            "J_over_a4": float(J / a**4), "ratio": float(G * J / stiffness),
            "J_over_ks_Ip": float(J / (ks * Ip))}


def beam_rigid_motion(scheme: str = "thesis") -> tuple[float, float]:
    """A rigid rotation (any axis) plus translation of the reference of a 3-element 3D beam:
    (largest element energy over E A L, largest elastic force over |K| |q|)."""
    p = SCENES["cantilever"].resolve({"element": "linear", "integration": scheme, "nu": 0.3,
                                      "n_elements": 3})
    m, q0, asm = beam3d.model({**p, "element": "linear3d"})
    el = asm.groups[0].element
    q = _move(q0, m.n_nodes, _rotation([0.3, -1.0, 0.6], 1.1), [0.4, -0.2, 0.7])
    g, K = el.gradient(q[m.dofmap], tangent=True)
    A = p["b"] * p["h"]
    return (float(np.abs(el.energy(q[m.dofmap])).max() / (p["E"] * A * p["L"])),
            float(np.abs(g).max() / (np.abs(K).max() * np.abs(q).max())))


# ------------------------------------------------------------------ the checks
@lru_cache(maxsize=None)
def checks() -> tuple:
    """Every acceptance check of the chapter, in table order (cached)."""
    plate = plate_convergence()
    orders = [r["observed order"] for r in plate[2:]]  # 4 -> 8 -> 16
    eb0 = strip_linear(0.0)
    large = strip_large()
    w_ref = navier_plate.centre_deflection(PLATE["a"], PLATE["a"], PLATE["h"], PLATE["E"],
                                           PLATE["nu"], PLATE["p"])[0]
    pp = max(max(principal_plane(c, "thesis", ax)) for c in BEAM_CASES for ax in (1, 2))
    sup = superposition_45()
    tor = torsion()
    rig_e, rig_f = beam_rigid_motion()
    rig_p = plate_rigid_motion()
    at90 = scene_at_90_degrees()
    return (
        Check("Plate square 16 × 16: centre deflection within 1 % of Navier",
              plate[-1]["w [m]"], w_ref, abs(plate[-1]["relative error"]), NAVIER_TOL, "m",
              "relative"),
        Check("Plate square: observed order 2 ± 0.2 (4 → 8 → 16 per side)", min(orders), 2.0,
              max(abs(o - 2) for o in orders), ORDER_TOL, "-", "largest abs(order − 2)"),
        Check("Plate strip ν = 0 (linear): tip = P L³/(3EI) on every mesh",
              eb0[-1]["w [m]"], eb0[-1]["Euler-Bernoulli [m]"],
              max(abs(r["relative error"]) for r in eb0), STRIP_TOL, "m",
              "largest relative over the meshes"),
        Check("Plate strip large deflection (ν = 0, F = EI/L²), 8 × 1: tip within 1e-3 of "
              "Reissner", large[1]["tip z [m]"], large[1]["Reissner z [m]"],
              large[1]["relative error"], REISSNER_STRIP_TOL, "m",
              "largest relative of tip x and z"),
        Check("3D beam, principal-plane bending: nodal displacements = planar scenes",
              pp, 0.0, pp, ROUND_OFF, "-",
              "largest difference over the largest 2D displacement (3 cases × y, z)"),
        Check("beam3d-cantilever 0°: tip = cantilever scene (Model 1)",
              scene("beam3d-cantilever")["results"]["tip_y"],
              scene("cantilever", element="linear")["results"]["tip_y"],
              scene_at_zero_degrees(), ROUND_OFF, "m", "relative"),
        Check("beam3d-cantilever 90°: the load and the tip turn to −z", at90,
              0.0, at90, ROUND_OFF, "-", "relative"),
        Check("3D beam 45°: superposition error within its second-order bound",
              max(sup["position"], sup["slope"]), 1.0, max(sup["position"], sup["slope"]), 1.0,
              "-", "difference / ((w/L)² max u_r, (w/L) max u_slope)"),
        Check("3D beam torsion: twist = T x/(k_s G I_p) (no warping)", tor["stiffness_Nm2"],
              tor["ks_G_Ip_Nm2"], tor["twist_error"], 1e-8, "N m²", "relative"),
        Check("Torsion constant of the square: J = 0.1406 a⁴ (series)", tor["J_over_a4"], 0.1406,
              abs(tor["J_over_a4"] - 0.1406), 5e-5, "a⁴", "absolute"),
        Check("Rigid rotation: zero strain energy, 3D beam", rig_e, 0.0, rig_e, 1e-20, "E A L",
              "energy / (E A L)"),
        Check("Rigid rotation: zero elastic force, 3D beam", rig_f, 0.0, rig_f, 1e-12, "-",
              "force / (max K · max q)"),
        Check("Rigid rotation: zero strain energy, plate", rig_p, 0.0, rig_p, 1e-12, "E h a b", "energy / (E h a b)"),
    )
