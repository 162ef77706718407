"""Spinning flexible beam, Wu & Haug (thesis Fig. 2.9, Figs 2.10-2.11).

L = 8 m, width b = 1.986e-3 m (z), height h = 3.675e-2 m (y, in the plane of
rotation), E = 6.895e10 Pa, rho = 2766.67 kg/m^3, 3 linear elements, no gravity.
The hub is a clamp at the origin whose slope is driven (rheonomic): node 0 has
r = 0 and r_y = (-sin theta, cos theta), theta(t) the spin-up law of Eq. 2.35
reaching omega_s after T_s.  For the Omar-Shabana element ``hub_x_slope =
prescribed`` also drives r_x = (cos theta, sin theta); that fixes the axial
strain at the root to zero (the exact root strain is the largest) and lowers the
extension by ~6 %, so the default clamps r and r_y only, as the static
cantilever scene does.

Results: the endpoint minus the rigid 'shadow' beam tip L (cos theta, sin theta),
in global axes (``tip_dx``, ``tip_dy``, as in Figs 2.10-2.11, which plot global
differences) and in the rotating hub frame (``tip_axial``, ``tip_lateral``).
The steady axial extension (``axial_extension_m``) is the mean over the last
``mean_window`` seconds of the centreline elongation (deformed length of the
y = 0 line minus L).  The mean of ``tip_axial`` (``tip_axial_mean_m``) is ~2.5 %
lower: the residual lateral vibration (~8 mm at the tip) foreshortens the chord;
its maxima (beam passing through straight) match the elongation.  Reference:
``ancf analytic spinning-extension`` (thesis Eq. 2.36).
"""
from __future__ import annotations

import math

import numpy as np

from ancf.scenes import accuracy
from ancf.core.constraints import Elimination
from ancf.common.inputs import following
from ancf.core.quadrature import gauss01
from ancf.scenes import beam_dynamic as bd
from ancf.scenes import beam_static as bs
from ancf.common.params import InputError, Param
from ancf.scenes.base import DYNAMIC_RESULTS, STR, Scene, SceneResult, field, nullable, series
from ancf.core.validity import check_dynamic


def hub_angle(t: float, omega_s: float, T_s: float):
    """Eq. 2.35: (theta, theta', theta'')."""
    if t < T_s:
        k = 2.0 * math.pi / T_s
        th = omega_s / T_s * (0.5 * t * t + (math.cos(k * t) - 1.0) / (k * k))
        return th, omega_s / T_s * (t - math.sin(k * t) / k), omega_s / T_s * (1.0 - math.cos(k * t))
    return omega_s * (t - 0.5 * T_s), omega_s, 0.0


def slope_motion(omega_s, T_s, slot):
    """motion(t) of r_y (or r_x) at the hub: value, velocity, acceleration (2-vectors)."""
    def motion(t):
        th, w, al = hub_angle(t, omega_s, T_s)
        c, s = math.cos(th), math.sin(th)
        if slot == "r_y":
            u, du = np.array([-s, c]), np.array([-c, -s])  # e2(theta), de2/dtheta
        else:
            u, du = np.array([c, s]), np.array([-s, c])
        return u, du * w, du * al - u * w * w
    return motion


def setup(p: dict):
    mesh, q0, asm = bs.build(p)
    elim = Elimination(mesh.n_dofs)
    for k in (0, 1):
        elim.fix(mesh.dof(0, "r", k), 0.0)
    slots = ("r_x", "r_y") if p["hub_x_slope"] == "prescribed" else ("r_y",)
    for slot in (s for s in mesh.slots if s in slots):
        elim.prescribe([mesh.dof(0, slot, 0), mesh.dof(0, slot, 1)],
                       slope_motion(p["omega_s"], p["T_s"], slot))
    mdl, forces = bd.model(p, asm, [], elim)
    return mesh, q0, asm, mdl, forces


def centreline_length(assembly, Q, nx: int = 8) -> np.ndarray:
    """Length of the deformed centreline (y = 0) at each sample, m: nx-point Gauss
    quadrature of |r_x| per element (exact for the linear element)."""
    out = np.zeros(len(Q))
    xi, w = gauss01(nx)
    for grp in assembly.groups:
        el = grp.element
        l = el.lengths[:, None]
        Bx = el.shapes["x"](xi[None, :] * l, np.zeros_like(xi[None, :] * l), np.broadcast_to(l, (el.nel, nx)))
        E = np.asarray(Q)[:, grp.dofmap].reshape(len(Q), el.nel, el.nshape, 2)
        rx = np.einsum("eqk,tekd->teqd", Bx, E)
        out += np.einsum("eq,teq->t", w[None, :] * l, np.linalg.norm(rx, axis=-1))
    return out


def run(p: dict) -> SceneResult:
    mesh, q0, asm, mdl, _ = setup(p)
    res = bd.simulate(p, mdl, q0, np.zeros_like(q0))
    ext = centreline_length(asm, res.q) - p["L"]
    n = p["n_elements"]
    tip = res.q[:, [mesh.dof(n, "r", 0), mesh.dof(n, "r", 1)]]
    th = np.array([hub_angle(t, p["omega_s"], p["T_s"])[0] for t in res.t])
    e1 = np.stack([np.cos(th), np.sin(th)], 1)
    e2 = np.stack([-np.sin(th), np.cos(th)], 1)
    d = tip - p["L"] * e1
    axial, lateral = np.einsum("ti,ti->t", d, e1), np.einsum("ti,ti->t", d, e2)
    window = res.t >= p["t_end"] - p["mean_window"] - 1e-12
    done = res.converged and res.t.size and res.t[-1] >= p["t_end"] - 1e-12
    results = {"times": bd.as_list(res.t), "tip_dx": bd.as_list(d[:, 0]), "tip_dy": bd.as_list(d[:, 1]),
               "tip_axial": bd.as_list(axial), "tip_lateral": bd.as_list(lateral),
               "hub_angle": bd.as_list(th),
               "extension": bd.as_list(ext),
               "axial_extension_m": float(ext[window].mean()) if done else None,
               "axial_extension_std_m": float(ext[window].std()) if done else None,
               "tip_axial_mean_m": float(axial[window].mean()) if done else None,
               "max_abs_tip_lateral_m": float(np.abs(lateral).max()) if res.t.size else None,
               "frame": "tip_dx/tip_dy global axes; tip_axial/tip_lateral rotating hub frame"}
    results.update(bd.stats(res))
    out = SceneResult(res.converged, res.message, results, extra={"result": res, "mesh": mesh})
    return check_dynamic(out, asm, q0, res.t, res.q)


def _check(p):
    bd.check(p)
    if p["mean_window"] > p["t_end"]:
        raise InputError(f"mean_window = {p['mean_window']!r} is out of range; allowed: a number "
                         f"in (0, t_end = {p['t_end']:g}]")


def _params():
    dyn = {q.name: q for q in bd.dynamic_params(t_end=20.0, integrator="generalized-alpha",
                                                 dt=5e-3, rho_inf=0.8, output_dt=0.05)}
    dyn["rho"] = Param("rho", 2766.67, float, "kg/m^3", "density", lo=0, lo_open=True)
    return (bd.section_params(n_elements=3, E=6.895e10, nu=0.0, L=8.0, h=3.675e-2, b=1.986e-3)
            + tuple(dyn.values())
            + (Param("omega_s", 4.0, float, "rad/s", "steady hub angular velocity", lo=0, hi=1e4),
               Param("T_s", 15.0, float, "s", "spin-up time (Eq. 2.35)", lo=0, lo_open=True, hi=1e4),
               Param("hub_x_slope", "free", str,
                     doc="Omar-Shabana only: 'prescribed' also drives r_x = (cos, sin) at the hub, "
                         "which forces zero axial strain there; 'free' clamps r and r_y only, like "
                         "the static cantilever", choices=("free", "prescribed")),
               Param("mean_window", following(5.0, "t_end"), float, "s",
                     "window at the end over which the axial extension is averaged "
                     "(default 5 s, at most t_end)",
                     lo=0, lo_open=True)))


def _spinning_ref(p):
    """The steady extension (``ancf analytic spinning-extension``) at p's parameters."""
    from ancf.scenes.spec import analytic_values
    return analytic_values("spinning-extension", p, ("axial_extension_m",))


def warn(p: dict, res) -> list[str]:
    """The accuracy warnings of a finished run: the step against the first bending mode's
    period, an averaging window that reaches into the spin-up."""
    out = accuracy.step(p, accuracy.bending_period(p, accuracy.CLAMPED_FREE),
                        "first bending mode")
    if p["t_end"] - p["mean_window"] < p["T_s"]:
        out.append(f"the averaging window starts at t = {p['t_end'] - p['mean_window']:g} s, "
                   f"before the spin-up ends (T_s = {p['T_s']:g} s): axial_extension_m is not "
                   "the steady value")
    return out


RESULTS = {
    **DYNAMIC_RESULTS, "tip_dx": series("tip minus rigid shadow tip, x, m"),
    "tip_dy": series("tip minus rigid shadow tip, y, m"),
    "tip_axial": series("tip deviation along the rotating beam axis, m"),
    "tip_lateral": series("tip deviation across the rotating beam axis, m"),
    "hub_angle": series("hub angle, rad"), "extension": series("centreline elongation, m"),
    "axial_extension_m": nullable("mean elongation over the last mean_window s, m"),
    "axial_extension_std_m": nullable("its standard deviation, m"),
    "tip_axial_mean_m": nullable("mean axial tip deviation over the window, m"),
    "max_abs_tip_lateral_m": nullable("largest |lateral tip deviation|, m"),
    "frame": field(STR, "frame of the tip_axial / tip_lateral components")}


def study():
    """What sweeps measure this scene against: its references, errors and grids."""
    from ancf.scenes.spec import DYNAMIC_KNOBS, Reference, SceneSpec, relative
    refs = {
        "spinning-extension": Reference(
            "spinning-extension", "analytic",
            "steady axial extension of the spinning beam (thesis Eq. 2.36, "
            "analytic.dynamics_refs); error = |u − u_ref| / |u_ref| of the extension averaged "
            "over the last mean_window seconds", _spinning_ref, relative("axial_extension_m"),
            measure="relative axial-extension error"),
    }
    grids = ({"element": ["linear"], "integration": ["thesis"], "n_elements": [2, 3, 4, 8],
              "integrator": ["generalized-alpha"], "dt": [1e-2, 5e-3, 2.5e-3]},
             {"element": ["omar-shabana"], "integration": ["thesis"], "n_elements": [2, 3, 4],
              "integrator": ["generalized-alpha"], "dt": [1e-2, 5e-3]})
    return SceneSpec("spinning-beam", DYNAMIC_KNOBS,
                     frozenset({"axial", "large-rotation", "inertia"}), refs, "spinning-extension",
                     report_grids=grids, recommend_grids=grids, dynamic=True,
                     notes="Spinning beam (thesis Eq. 2.35 spin-up) against the steady extension.")


#: the scene's place in the scene list (ancf.scenes.MODULES, ancf scenes, reports/schemas.md)
ORDER = 50
SCENE = Scene(
    "spinning-beam",
    "Spin-up of a flexible beam driven at the hub (Wu & Haug; thesis Figs 2.9-2.11).",
    _params(), run, _check, warn=warn,
    results=RESULTS, study=study)
