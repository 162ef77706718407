"""The serpentine's rotational modes (``ancf modes belt-drive --about steady``) against the
discrete model with creeping wraps (:mod:`analytic.serpentine_creep`; issue 34's "serpentine
rotational modes within 1 % of the discrete model").

Inputs of the model, from the drive description and the steady state of the same settings:
the pulleys, inertias, arm and span tensions as :func:`ancf.checks.serpentine_modes.inputs`
(the string's steady reference); the belt's rho A with its fastest span's speed (the model's
belt mass and transport speed); each span's tangent stiffness from the element's EA and
``axial_strain`` law (eq. 7 there); c = ``friction.nu_s`` and ``friction.mu``; the
bearings' ``damping``, the arm's ``arm_damping`` and the belt's ``damping_axial``; and the
saturated zones of each wrap where our steady solve (``ancf steady belt-drive``) has the
creep-rate law at its bound (|f| = mu p at the belt's contact points, :func:`zones`).

Settings (:data:`SETTINGS`).  The model's rims are rigid and its wraps resolved exactly, so
ours is taken where both hold: 240 elements (5 mm, against the creep layer's lag length
sqrt(EA / (omega c)) of about 2 cm; the file's 60 elements are 21 mm) and a contact penalty
of 1e9 N/m^2 (the file's 1e8 lets the belt sink T / (r k_p) = 8e-5 m into the 3 cm
alternator, which lowers its mode 0.4 %).
"""
from __future__ import annotations

import math

import numpy as np

from analytic import serpentine_creep as sc
from ancf.checks.belt2d import Check

#: the comparison's overrides of examples/serpentine.toml (module docstring)
SETTINGS = ("belt.n_elements=240", "contact.k_p=1e9")
#: the issue's acceptance, %
TOL = 1.0
#: the modes compared: ours -> the model's label
MODES = {"arm tensioner": "psi", "pulley alternator": "theta_alternator",
         "pulley pump": "theta_pump"}
#: a contact point is saturated where |f| >= (1 - SAT) mu p
SAT = 1e-6


def _on_rim(res: dict, lay, i: int) -> np.ndarray:
    """Indices of the steady belt's contact points on pulley i's rim (within 3 mm)."""
    x, y = np.asarray(res["belt_x_m"]), np.asarray(res["belt_y_m"])
    d = np.hypot(x - lay.centres[i][0], y - lay.centres[i][1])
    return np.where((np.abs(d - lay.radii[i]) < 3e-3)
                    & (np.asarray(res["contact_pressure_N_m"]) > 0))[0]


def zones(res: dict, lay, mu: float) -> list[list]:
    """Per pulley of ``lay`` (the model's layout) the saturated zones [(start m, end m,
    sigma)] from the wrap's entry: each run of contact points of ``res`` (the steady JSON's
    results) where |friction| >= mu p, widened by half a point spacing and cut to the wrap;
    sigma the sign of the tension's rise along the running belt there (eq. 2)."""
    f, p = np.asarray(res["friction_force_N_m"]), np.asarray(res["contact_pressure_N_m"])
    T = np.asarray(res["axial_force_N"])
    x, y = np.asarray(res["belt_x_m"]), np.asarray(res["belt_y_m"])
    out = []
    for i in range(len(lay.radii)):
        idx = _on_rim(res, lay, i)
        c, r, L = lay.centres[i], lay.radii[i], lay.radii[i] * lay.wrap[i]
        entry = lay.end[i - 1] - c
        ang = np.arctan2(y[idx] - c[1], x[idx] - c[0]) - math.atan2(entry[1], entry[0])
        pos = (ang * lay.sense[i]) % (2 * math.pi) * r
        keep = pos <= L
        idx, pos = idx[keep], pos[keep]
        order = np.argsort(pos)
        idx, pos = idx[order], pos[order]
        sat = np.abs(f[idx]) >= (1 - SAT) * mu * p[idx]
        half = 0.5 * float(np.median(np.diff(pos))) if len(pos) > 1 else 0.0
        out.append(_runs(pos, sat, T[idx], half, L))
    return out


def _runs(pos, sat, T, half: float, L: float) -> list:
    """The zones of consecutive saturated points (see :func:`zones`)."""
    found, k = [], 0
    while k < len(pos):
        if not sat[k]:
            k += 1
            continue
        m = k
        while m + 1 < len(pos) and sat[m + 1]:
            m += 1
        lo, hi = max(0.0, pos[k] - half), min(L, pos[m] + half)
        j0, j1 = max(k - 1, 0), min(m + 1, len(pos) - 1)
        rise = T[j1] - T[j0]
        if hi > lo and rise != 0:
            found.append((float(lo), float(hi), int(np.sign(rise))))
        k = m + 1
    return found


def model(desc, steady_res: dict, creep: float | None = None, saturated: bool = True) -> dict:
    """:func:`analytic.serpentine_creep.modes` on the drive ``desc`` and its steady results
    (diagnostics: ``creep`` instead of the file's ``nu_s``; ``saturated`` False: without
    the saturated zones)."""
    from ancf.checks import serpentine_modes as sm
    from analytic import serpentine_rotational as sr
    inp = sm.inputs(desc)
    b = desc.belt
    speed = max((s["speed"] for s in inp["steady"]["spans"]), key=abs)
    lay = sr.matrices(inp["pulleys"], EA=inp["EA"], J=inp["J"], T=inp["T"],
                      J_arm=inp["J_arm"], arm_angle=inp["arm_angle"])["layout"]
    mu = desc.friction["mu"]
    arm = next(p for p in desc.pulleys if p.law == "tensioner")
    return sc.modes(inp["pulleys"], EA=sc.tangent_stiffness(inp["EA"], inp["T"],
                                                            b["axial_strain"]),
                    J=inp["J"], T=inp["T"], creep=creep or desc.friction["nu_s"], mu=mu,
                    transport_speed=speed,
                    zones=zones(steady_res, lay, mu) if saturated else None,
                    damping=[p.params.get("damping", 0.0) for p in desc.pulleys],
                    arm_damping=arm.params["arm_damping"], belt_damping=b["damping_axial"],
                    J_arm=inp["J_arm"], arm_angle=inp["arm_angle"], belt_mass=inp["rhoA"],
                    belt_speed=abs(speed))


def rows(items: tuple = SETTINGS) -> list[dict]:
    """Per mode of :data:`MODES`: ours (the running drive's modes on the serpentine with
    ``items``), the creep model's and the sticking model's (both with the belt's mass)."""
    from ancf.checks import running_drives as rd
    out, res = rd.modes(rd.SERPENTINE, items, 16)
    desc = res.extra["description"]
    ref = model(desc, rd.steady(rd.SERPENTINE, items, max_loads=False)[0]["results"])
    r = out["results"]
    got = []
    for ours, theirs in MODES.items():
        k = ref["labels"].index(theirs)
        f_ref = ref["frequencies_hz"][k]
        cand = [j for j, lab in enumerate(r["labels"]) if lab == ours]
        j = min(cand, key=lambda j: abs(r["frequencies_hz"][j] - f_ref))
        got.append({"mode": ours, "ours": r["frequencies_hz"][j], "zeta": r["damping_ratios"][j],
                    "creep model": f_ref, "creep model zeta": ref["damping_ratios"][k],
                    "sticking model": ref["sticking_hz"][k],
                    "error_pct": 100 * (r["frequencies_hz"][j] / f_ref - 1)})
    return got


def check(got: list[dict]) -> Check:
    worst = max(abs(g["error_pct"]) for g in got)
    return Check("Serpentine: rotational modes within 1 % of the discrete model (creeping "
                 "wraps)", worst, 0.0, worst, TOL, "%", "largest abs(f / f_model − 1): arm, "
                 "alternator, pump (analytic/serpentine_creep.py; 240 elements, k_p 1e9)")
