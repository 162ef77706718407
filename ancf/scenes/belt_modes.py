"""The natural frequencies of a running belt drive (``ancf modes belt-drive --file F
--about steady``): the drive's steady state (:mod:`ancf.scenes.belt_steady`) and the
linearised axially moving belt about it (:mod:`ancf.belts.modes2d`): spans moving at the
belt speed, free pulleys' rotations, tensioner arms, the belt's axial motion.

Per mode its frequency (Hz) and damping ratio, a label naming what moves most (the share of
the mode's kinetic energy: a span's belt, a wrap's, a pulley's spin, an arm, the belt's
axial motion) and its shape: the belt nodes' displacement (the real part once the largest
is made real, scaled to 1 m), each free pulley's rotation and each arm's angle on the same
scale.  A mode with Re lambda > 0 (the running drive diverges or flutters: past a critical
speed) is a warning.
"""
from __future__ import annotations

from dataclasses import replace
from functools import partial

import numpy as np

from ancf.belts.arm2d import PULLEY
from ancf.common.params import InputError
from ancf.scenes import belt_steady as bs
from ancf.scenes.base import NUM, STR, SceneResult, field

#: modes reported unless --count says otherwise
DEFAULT_COUNT = 6


def _kinetic_shares(problem, st, lam, z) -> dict:
    """{part: share of the mode's kinetic energy}: the belt nodes' motion across the belt
    (lumped mass, |lambda u|) by the span or wrap they lie on, their motion along it and the
    transport speed's together as "belt axial", each free pulley's I |omega|^2, each arm's
    I |lambda psi|^2."""
    drive, n = problem.drive, problem.n
    full = np.zeros(n + 1 + problem.k, dtype=complex)
    full[problem.keep] = z
    u = _belt_nodes(problem, full)
    t = drive.belt(st.x).reshape(drive.mesh.n_nodes, 3, 2)[:, 1]
    t = t / np.linalg.norm(t, axis=1, keepdims=True)
    along = np.abs(np.sum(u * t, axis=1)) ** 2
    across = np.sum(np.abs(u) ** 2, axis=1) - along
    m_node = float(drive.element.mass().sum()) / 2 / drive.mesh.n_nodes
    e = 0.5 * m_node * abs(lam) ** 2
    parts = {name: e * float(across[sel].sum()) for name, sel in _node_parts(problem, st).items()}
    for j, p in problem.pulley_of.items():
        parts[f"pulley {drive.rig.names[p]}"] = 0.5 * drive.rig.inertia[j] * abs(full[n + 1 + j]) ** 2
    for ja, a in problem.arm_of.items():
        name = drive.rig.names[int(drive.rig.arms[a, PULLEY])]
        parts[f"arm {name}"] = 0.5 * drive.rig.inertia[ja] * abs(lam * full[n + 1 + ja]) ** 2
    parts["belt axial"] = e * float(along.sum()) + 0.5 * m_node * drive.mesh.n_nodes * abs(full[n]) ** 2
    total = sum(parts.values()) or 1.0
    return {k: v / total for k, v in parts.items()}


def _belt_nodes(problem, full) -> np.ndarray:
    """The belt nodes' displacements r (n_nodes, 2), complex, of a vector in the full
    layout (belt, vb, free)."""
    drive, n = problem.drive, problem.n
    pad = np.zeros(problem.k)
    q = drive.belt(np.append(full[:n].real, pad)) + 1j * drive.belt(np.append(full[:n].imag, pad))
    return q.reshape(drive.mesh.n_nodes, 3, 2)[:, 0]


def _node_parts(problem, st) -> dict:
    """{"span A-B" or "wrap P": bool (n_nodes,)} of the belt's nodes at the steady state:
    a node in contact with a pulley is on its wrap, the rest on the span they lie between."""
    from ancf.belts.contact2d import contact_state_moving
    drive = problem.drive
    E, V, omegas, o, odot, _ = bs.state_arrays(problem, st.x, st.w, st.vb, st.lam)
    S0 = np.zeros((E.shape[0], 1, 6))
    S0[:, 0, 0] = 1.0  # each element's first node: r at xi = 0
    _, _, Fn, _, _ = contact_state_moving(E, V, S0, o, odot, drive.radii, omegas, drive.prm)
    on = Fn[:, 0, :] > 0
    lab = np.where(on.any(axis=1), np.argmax(on, axis=1), -1)
    names, npul = drive.rig.names, drive.radii.size
    out, current = {}, None
    start = int(np.flatnonzero(lab >= 0)[0]) if (lab >= 0).any() else 0
    for i in np.roll(np.arange(lab.size), -start):
        if lab[i] >= 0:
            current = int(lab[i])
            key = f"wrap {names[current]}"
        else:
            key = f"span {names[current]}-{names[(current + 1) % npul]}"
        out.setdefault(key, np.zeros(lab.size, dtype=bool))[i] = True
    return out


def _shape(problem, lam, z) -> dict:
    """The mode's shape: belt node displacements, pulley rotations (omega / lambda) and arm
    angles, rotated to make the largest belt component real and scaled to 1."""
    drive, n = problem.drive, problem.n
    full = np.zeros(n + 1 + problem.k, dtype=complex)
    full[problem.keep] = z
    r = _belt_nodes(problem, full)
    big = r.flat[np.argmax(np.abs(r))]
    scale = big if abs(big) > 0 else 1.0
    out = {"belt_dx_m": (r[:, 0] / scale).real.tolist(),
           "belt_dy_m": (r[:, 1] / scale).real.tolist(),
           "pulleys_rad": {drive.rig.names[p]: float(abs(full[n + 1 + j] / lam / scale))
                           for j, p in problem.pulley_of.items()},
           "arms_rad": {drive.rig.names[int(drive.rig.arms[a, PULLEY])]:
                        float(abs(full[n + 1 + ja] / scale)) for ja, a in problem.arm_of.items()}}
    return out


def run(p: dict, count: int) -> SceneResult:
    from ancf.belts.modes2d import running_modes
    steady = bs.run(p, max_loads=False)
    if not steady.converged:
        return SceneResult(False, f"steady state: {steady.message}", _empty(),
                           warnings=[])
    problem, st = steady.extra["problem"], steady.extra["steady"]
    m = running_modes(problem, st, count)
    labels, shares, shapes = [], [], []
    for lam, z in zip(m.lam, m.z.T):
        sh = _kinetic_shares(problem, st, lam, z)
        top = max(sh, key=sh.get)
        labels.append(top)
        shares.append(round(sh[top], 4))
        shapes.append(_shape(problem, lam, z))
    r = steady.results
    results = {"frequencies_hz": m.frequencies_hz.tolist(),
               "damping_ratios": m.damping_ratios.tolist(), "labels": labels,
               "label_shares": shares, "mode_shapes": shapes,
               "unstable_hz": [float(abs(l.imag) / (2 * np.pi)) for l in m.unstable],
               "steady": {"transport_speed_m_s": r["transport_speed_m_s"],
                          "belt_x_m": r["belt_x_m"][::8], "belt_y_m": r["belt_y_m"][::8],
                          "spans": r["spans"], "pulleys": [
                              {k: q[k] for k in ("name", "omega", "torque_Nm")}
                              for q in r["pulleys"]]}}
    return SceneResult(True, "running modes", results,
                       extra={**steady.extra, "modes": m, "steady_result": steady})


def _empty() -> dict:
    return {k: None for k in ("frequencies_hz", "damping_ratios", "labels", "label_shares",
                              "mode_shapes", "unstable_hz", "steady")}


def warn(p: dict, res: SceneResult) -> list:
    """The steady state's warnings, and a mode that grows (Re lambda > 0)."""
    steady = res.extra.get("steady_result")
    out = bs.warn(p, steady) if steady is not None else []
    for f in (res.results.get("unstable_hz") or []):
        out.append(f"a mode at {f:.4g} Hz grows (Re lambda > 0): the running drive is "
                   "unstable (divergence or flutter past a critical speed)")
    return out


RESULTS = {
    "frequencies_hz": field("array", "the lowest oscillatory modes' frequencies, ascending, Hz",
                            nullable=True, items=NUM),
    "damping_ratios": field("array", "their damping ratios -Re lambda / |lambda|",
                            nullable=True, items=NUM),
    "labels": field("array", "what moves most in each (a span's or a wrap's belt, a pulley's "
                    "spin, an arm, the belt's axial motion)", nullable=True, items=STR),
    "label_shares": field("array", "that part's share of the mode's kinetic energy",
                          nullable=True, items=NUM),
    "mode_shapes": field("array", "per mode: belt_dx_m, belt_dy_m (per node), pulleys_rad, "
                         "arms_rad (by name), scaled to a largest belt component of 1",
                         nullable=True, items="object"),
    "unstable_hz": field("array", "frequencies of modes with Re lambda > 0 among those found",
                         nullable=True, items=NUM),
    "steady": field("object", "the steady state the modes are about (transport speed, belt "
                    "points, spans, pulleys)", nullable=True)}


def execute(overrides: dict, count=None, about: str = "steady"):
    """``ancf modes belt-drive --about steady``: (public JSON dict, SceneResult)."""
    if about != "steady":
        raise InputError(f"--about {about!r}: a belt drive vibrates about its running state; "
                         "allowed: steady")
    k = DEFAULT_COUNT if count is None else int(count)
    if not 1 <= k <= 200:
        raise InputError(f"--count {k}: allowed: 1 to 200")
    return replace(SCENE, run=partial(run, count=k)).execute(overrides)


SCENE = replace(bs.SCENE, doc="The natural frequencies of a drive file's running 2D belt "
                "drive about its steady state (ancf modes belt-drive --about steady).",
                run=partial(run, count=DEFAULT_COUNT), warn=warn, results=RESULTS)
