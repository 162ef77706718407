"""The steady running state of a drive file's 2D belt drive (``ancf steady belt-drive
--file drive.toml``): :mod:`ancf.belts.steady2d`'s Newton solve in the axially moving
description, at the pulley laws' values at ``run.t_end``, instead of a march.

The drive is the one ``ancf run belt-drive`` marches (the same file, the same ``--set``
overrides, :mod:`ancf.scenes.belt_drive`): the Dufva belt (``belt.element = "dufva2d"``)
with a stateless friction law (creep-rate, coulomb).  The results have ``ancf run
belt-drive``'s keys where the meaning is the same, the steady values in place of a window's
means: per pulley its angular velocity, slip, the belt's moment on it, its hubload (the
belt's resultant force on it, what its bearing carries), its stick and creep arcs and the
largest load it carries before gross slip (a driven pulley's, by continuation in its
load alone); per span its free length, tension over the middle third and speed; per
tensioner its arm's angle; along the belt its axial force, speed, contact pressure and
friction.  Exit 3 where no steady state is found, naming the load factor reached and the
pulley whose wrap saturated, and where the state found slips over a whole contact arc
(a load beyond the friction's capacity, the belt's speed beyond the wraps' contact).
"""
from __future__ import annotations

import sys

import numpy as np

from ancf.belts.arm2d import BETA0, COORD, PULLEY
from ancf.belts.drive_file import load
from ancf.common.params import InputError
from ancf.scenes import belt_drive as bd
from ancf.scenes.base import INT, NUM, STR, SceneResult, field

#: a contact point's friction counts as saturated (creep, or gross slip) above this
#: fraction of mu F_n; below it the point sticks (creep-rate: the linear branch)
SATURATED = 0.99
#: the relative width of the bracket :func:`_max_load` narrows the largest load to
LOAD_RTOL = 0.005


def _checked(p: dict):
    desc = _moved(p, load(p["file"], bd._items(p)))
    if desc.belt["element"] != "dufva2d":
        raise InputError(f"belt.element = {desc.belt['element']!r}: the steady solve takes "
                         "the 2D belt; allowed: 'dufva2d'")
    from ancf.belts.friction import REGISTRY
    if REGISTRY[desc.friction["law"]].state:
        allowed = ", ".join(repr(k) for k, v in REGISTRY.items() if not v.state)
        raise InputError(f"friction.law = {desc.friction['law']!r} carries a state and has no "
                         f"steady form here; allowed: {allowed}")
    return desc


def _moved(p: dict, desc):
    """The drive with every prescribed centre motion as it stands at t_end (the steady
    state takes the laws' values there): each moved pulley at that centre (a tensioner's
    pivot moved with it) and no motion left, so that the belt is laid and pre-tensioned on
    the drive whose steady state is sought."""
    from ancf.belts.pulleys import CENTRE_LAWS
    extra = []
    for q in desc.pulleys:
        shift = np.asarray(q.params["centre_shift"], dtype=float)
        if not shift.any():
            continue
        law = CENTRE_LAWS[q.params["centre_motion"]].of(1.0, q.params)
        d = [float(x) for x in shift * float(law(np.array([desc.run["t_end"]]))[0][0])]
        extra += [f"pulleys.{q.name}.centre={[a + b for a, b in zip(q.centre, d)]!r}",
                  f"pulleys.{q.name}.centre_shift=[0.0, 0.0]"]
        if "pivot" in q.params and q.params["pivot"] is not None:
            pivot = [a + b for a, b in zip(q.params["pivot"], d)]
            extra.append(f"pulleys.{q.name}.pivot={pivot!r}")
    return load(p["file"], bd._items(p) + extra) if extra else desc


def steady_route(p: dict) -> dict:
    """What ``ancf recommend belt-drive`` says of the steady route for the drive of ``p``:
    ``command`` (``ancf steady belt-drive`` on the same file and overrides), ``applies``
    and ``why`` (the steady reference's question is a steady state; a file the steady solve
    does not take says which key)."""
    sets = "".join(f" --set {item}" for item in bd._items(p))
    command = f"ancf steady belt-drive --file {p['file']}{sets}"
    try:
        _checked(p)
    except InputError as exc:
        return {"command": command, "applies": False, "why": str(exc)}
    return {"command": command, "applies": True,
            "why": "the steady reference's quantities (span tensions, pulley speeds at the "
                   "laws' final values) are a steady state: one Newton solve in the ALE "
                   "description answers them without a march (reports/running_drives.md)"}


def _progress():
    if not sys.stderr.isatty():
        return None
    return lambda what, value: print(f"steady belt-drive: {what} {value:.3g}",
                                     file=sys.stderr, flush=True)


def run(p: dict, max_loads: bool = True) -> SceneResult:
    """The steady state of the drive of ``p``; ``max_loads`` False leaves the driven
    pulleys' largest loads out (null; ``ancf modes`` needs the state only)."""
    from ancf.belts.drive_model import build
    from ancf.belts.pretension import settle
    from ancf.belts.steady2d import SteadyProblem, solve
    desc = _checked(p)
    drive = build(desc)
    x0, pre = settle(drive)
    if not pre.converged:
        return SceneResult(False, f"pre-tension: {pre.message}", _empty())
    problem = SteadyProblem(drive, desc.run["t_end"])
    st = solve(problem, x0, progress=_progress())
    if not st.converged:
        return SceneResult(False, f"{st.message} ({_saturated(desc, problem, st)}"
                           f"{_centrifugal(desc, st)})",
                           {**_empty(), "load_factor": st.lam, "newton_iterations": st.iterations,
                            "continuation_steps": st.steps}, extra={"steady": st})
    slipping = gross_slip(problem, st.x, st.w, st.vb)
    if slipping is not None:
        return SceneResult(False, f"no steady state without gross slip: pulley "
                           f"{desc.pulleys[slipping].name!r} slips over its whole contact arc "
                           f"(its load or speed beyond the friction's capacity"
                           f"{_centrifugal(desc, st)})",
                           {**_empty(), "load_factor": 1.0, "newton_iterations": st.iterations,
                            "continuation_steps": st.steps}, extra={"steady": st})
    results = _results(desc, problem, st, max_loads)
    results.update(load_factor=1.0, newton_iterations=st.iterations,
                   continuation_steps=st.steps, total_dofs=drive.n + drive.k + 1,
                   pretension_iterations=pre.iterations)
    return SceneResult(True, st.message, results,
                       extra={"steady": st, "problem": problem, "description": desc})


def _centrifugal(desc, st) -> str:
    """A note where the belt's centrifugal force rho A v^2 reaches half its pre-tension
    (the wraps unload as v nears sqrt(T0 / rho A))."""
    b = desc.belt
    rhoA, T0 = b["rho"] * b["b"] * b["h"], bd.pretension(desc)
    v = abs(st.vb)
    if T0 <= 0 or rhoA * v * v < 0.5 * T0:
        return ""
    return (f"; the belt's rho A v^2 = {rhoA * v * v:.3g} N at {v:.3g} m/s against the "
            f"pre-tension {T0:.3g} N: above sqrt(T0 / rho A) = {np.sqrt(T0 / rhoA):.3g} m/s "
            "the wraps lose their contact")


def warn(p: dict, res: SceneResult) -> list:
    """A finished steady state that should not be trusted: Newton stalled above its
    tolerance (a wrap slipping over its whole arc is no steady state: :func:`run`)."""
    st = res.extra.get("steady")
    if st is None or not res.converged:
        return []
    out = []
    from ancf.belts.steady2d import RTOL
    if st.residual > RTOL * st.scale:
        out.append(f"Newton stalled at |R| = {st.residual:.3g} N ({st.residual / st.scale:.2g} "
                   "of the force scale; a contact point switching at a wrap's entry or exit, "
                   "where the penalty damping jumps)")
    return out


def _empty() -> dict:
    """The results of a run without a steady state (the counts filled in by the caller)."""
    return {**{k: None for k in ("pulleys", "spans", "arms", "belt_s_m", "axial_force_N",
                                 "speed_m_s", "contact_pressure_N_m", "friction_force_N_m",
                                 "belt_x_m", "belt_y_m", "transport_speed_m_s")},
            "load_factor": 0.0, "newton_iterations": 0, "continuation_steps": 0}


def state_arrays(problem, x, w, vb, lam: float = 1.0) -> tuple:
    """(E, V, omegas, o, odot, T) of the state (x, w, vb) at load factor lam
    (:class:`ancf.belts.steady2d.Steady`'s fields): the element coordinates and material
    velocities, the pulleys' angular velocities (rad/s), centres and their velocities and
    the belt's moments on them (N m)."""
    from ancf.belts.ale2d import ale_terms
    drive = problem.drive
    E, V, _, _, c, _ = ale_terms(problem.kern, x, w, vb, problem.P, problem.scaled(lam), False)
    omegas = np.where(drive.rig.free < 0, problem.scaled(lam)[: drive.radii.size], 0.0)
    for j, q in problem.pulley_of.items():
        omegas[q] = w[problem.n + j]
    o, odot = drive.moved(x, np.zeros_like(x), problem.t_end)
    return E, V, omegas, o, np.zeros_like(odot), c[4]


def _results(desc, problem, st, max_loads: bool = True) -> dict:
    from ancf.belts.post2d import sample_elements, span_speed, span_tension
    drive = problem.drive
    E, V, omegas, o, odot, T = state_arrays(problem, st.x, st.w, st.vb, st.lam)
    smp = sample_elements(drive, E, V, omegas, o, odot)
    R = float(drive.radii.min())
    path = desc.path
    ends = [path(np.array([a, b]))[0] for _, a, b in path.pieces()[1::2]]
    names = [q.name for q in desc.pulleys]
    N = len(names)
    lengths = _free_lengths(smp, N)
    spans = [{"from": names[k], "to": names[(k + 1) % N], "length_m": lengths[k],
              "tension_mean_N": span_tension(smp, e, R), "speed_m_s": span_speed(smp, e, R)}
             for k, e in enumerate(ends)]
    hub = hubloads(drive, E, V, omegas, o, odot)
    stick, creep = _arcs(drive, smp)
    d = next(i for i, q in enumerate(desc.pulleys) if q.law == "prescribed")
    rim = np.array([q.side for q in desc.pulleys]) * omegas * drive.radii
    slip = 1.0 - rim / rim[d] if rim[d] != 0 else np.full(rim.size, np.nan)
    loads = _max_loads(desc, problem, st) if max_loads else {}
    pulleys = [{"name": q.name, "omega": float(omegas[i]), "slip": float(slip[i]),
                "torque_Nm": float(T[i]), "hubload_N": hub[i].tolist(),
                "stick_arc_rad": stick[i], "creep_arc_rad": creep[i],
                "max_load_Nm": loads.get(i), "penetration_max_m": float(smp.d[:, i].max())}
               for i, q in enumerate(desc.pulleys)]
    arms = [{"name": drive.rig.names[int(a[PULLEY])],
             "angle_rad": float(a[BETA0] + st.x[drive.n + int(a[COORD])])}
            for a in drive.rig.arms]
    return dict(pulleys=pulleys, spans=spans, arms=arms, belt_s_m=smp.s.tolist(),
                axial_force_N=smp.N.tolist(), speed_m_s=smp.speed.tolist(),
                contact_pressure_N_m=smp.Fn.sum(axis=1).tolist(),
                friction_force_N_m=smp.Ft.sum(axis=1).tolist(),
                belt_x_m=smp.r[:, 0].tolist(), belt_y_m=smp.r[:, 1].tolist(),
                transport_speed_m_s=st.vb)


def hubloads(drive, E, V, omegas, o, odot) -> np.ndarray:
    """The belt's resultant force on each pulley (np, 2), N: minus the contact forces on the
    belt (normal and friction per unit length) integrated over the contact Gauss points."""
    from ancf.belts.contact2d import contact_state_moving
    r, _, Fn, phi, _ = contact_state_moving(E, V, drive.S0, o, odot, drive.radii, omegas,
                                            drive.prm)
    out = np.zeros((drive.radii.size, 2))
    for p in range(drive.radii.size):
        a = r - o[p]
        rho = np.linalg.norm(a, axis=-1)
        f0 = (Fn[..., p] * a[..., 0] - phi[..., p] * a[..., 1]) / rho
        f1 = (Fn[..., p] * a[..., 1] + phi[..., p] * a[..., 0]) / rho
        out[p] = -np.array([np.sum(drive.w * f0), np.sum(drive.w * f1)])
    return out


def _arcs(drive, smp) -> tuple:
    """Per pulley the wrap angle (rad) where its friction sticks (below SATURATED mu F_n)
    and where it creeps (at or above): each sample point's reference length over the
    pulley's radius."""
    ds = smp.s[1] - smp.s[0]
    mu = drive.prm.mu
    stick, creep = [], []
    for p in range(drive.radii.size):
        on = smp.Fn[:, p] > 0
        sat = on & (np.abs(smp.Ft[:, p]) >= SATURATED * mu * smp.Fn[:, p])
        stick.append(float((on & ~sat).sum() * ds / drive.radii[p]))
        creep.append(float(sat.sum() * ds / drive.radii[p]))
    return stick, creep


def _free_lengths(smp, npul: int) -> list:
    """Each span's free length (m): the belt's length between the last sample point in
    contact with pulley k and the first with pulley k + 1 (belt order)."""
    on = smp.Fn > 0
    lab = np.where(on.any(axis=1), np.argmax(on, axis=1), -1)
    seg = np.linalg.norm(np.diff(np.vstack([smp.r, smp.r[:1]]), axis=0), axis=1)
    out = []
    for k in range(npul):
        last = np.flatnonzero(lab == k)
        first = np.flatnonzero(lab == (k + 1) % npul)
        if not (last.size and first.size):
            out.append(float("nan"))
            continue
        a, b = _gap(last, first, lab.size)
        idx = np.arange(a, a + (b - a) % lab.size) % lab.size
        out.append(float(seg[idx].sum()))
    return out


def _gap(last, first, m) -> tuple:
    """(a, b): the free run from wrap k's end a to wrap k + 1's start b along the loop."""
    for a in last[::-1]:
        nxt = (a + 1) % m
        if nxt not in last:
            after = (first - a) % m
            return int(a), int(first[np.argmin(after)])
    return int(last[-1]), int(first[0])


def _max_loads(desc, problem, st) -> dict:
    """{pulley: the largest load torque (N m) it carries before gross slip} for each
    driven pulley with a load (:func:`_max_load`)."""
    return {i: _max_load(problem, st, i) for i, q in enumerate(desc.pulleys)
            if q.law == "driven" and problem.laws[i] != 0.0}


def gross_slip(problem, x, w, vb) -> int | None:
    """The first pulley whose friction is saturated (at SATURATED mu F_n or above) at every
    contact Gauss point of its wrap at the state (x, w, vb): the belt slides over the whole
    wrap; None if every wrap keeps a sticking zone."""
    from ancf.belts.contact2d import contact_state_moving
    E, V, omegas, o, odot, _ = state_arrays(problem, x, w, vb)
    _, _, Fn, phi, _ = contact_state_moving(E, V, problem.drive.S0, o, odot,
                                            problem.drive.radii, omegas, problem.kern.prm)
    for p in range(Fn.shape[-1]):
        on = Fn[..., p] > 0
        if on.any() and np.all(np.abs(phi[..., p][on])
                               >= SATURATED * problem.kern.prm.mu * Fn[..., p][on]):
            return p
    return None


def _max_load(problem, st, p: int) -> float | None:
    """Pulley p's load (the others at the file's) raised by 1.25 a step from the file's
    until the steady state slips over a whole wrap (:func:`gross_slip`) or no longer
    exists, then the bracket narrowed to LOAD_RTOL by bisection; None past 1000 times the
    file's load."""
    base, saved = problem.laws[p], problem.laws.copy()
    good, bad, state = 1.0, None, (st.x, st.w, st.vb)
    try:
        while bad is None or bad / good > 1 + LOAD_RTOL:
            trial = good * 1.25 if bad is None else np.sqrt(good * bad)
            problem.laws[p] = base * trial
            x, w, vb, ok, _, _ = problem.newton(*state, 1.0, st.scale)
            if ok and gross_slip(problem, x, w, vb) is None:
                good, state = trial, (x, w, vb)
            else:
                bad = trial
            if good > 1e3:
                return None
    finally:
        problem.laws[:] = saved
    return float(base * good)


def _saturated(desc, problem, st) -> str:
    """Which wrap carries friction at its limit in the last state reached."""
    from ancf.belts.post2d import sample_elements
    E, V, omegas, o, odot, _ = state_arrays(problem, st.x, st.w, st.vb, st.lam)
    smp = sample_elements(problem.drive, E, V, omegas, o, odot)
    stick, creep = map(np.array, _arcs(problem.drive, smp))
    share = creep / np.maximum(stick + creep, 1e-12)
    worst = int(np.argmax(share))
    return (f"pulley {desc.pulleys[worst].name!r}: friction saturated over "
            f"{share[worst]:.0%} of its contact arc (gross slip)")


RESULTS = {
    "pulleys": field("array", "per pulley, in belt order (null when no steady state)",
                     items="object", nullable=True, keys={
        "name": field(STR, "pulley name"),
        "omega": field(NUM, "angular velocity, counter-clockwise positive, rad/s"),
        "slip": field(NUM, "1 - its rim speed / the driver's (ancf run belt-drive's slip)"),
        "torque_Nm": field(NUM, "the belt's moment on it (friction), counter-clockwise "
                                "positive, N m"),
        "hubload_N": field("array", "the belt's resultant force on it [x, y] (its bearing's "
                           "load), N", items=NUM),
        "stick_arc_rad": field(NUM, "wrap angle where friction is below 0.99 mu F_n, rad"),
        "creep_arc_rad": field(NUM, "wrap angle where friction is at mu F_n, rad"),
        "max_load_Nm": field(NUM, "a driven pulley's largest load torque with a steady state "
                             "(the others' at the file's), N m; null for other pulleys",
                             nullable=True),
        "penetration_max_m": field(NUM, "the belt's largest penetration into it, m")}),
    "spans": field("array", "per span (pulley k to k + 1), in belt order (null when no "
                   "steady state)", items="object", nullable=True, keys={
        "from": field(STR, "pulley the span leaves"), "to": field(STR, "pulley it reaches"),
        "length_m": field(NUM, "free length between the two wraps' contact ends, m; null "
                               "where a wrap has no contact point", nullable=True),
        "tension_mean_N": field(NUM, "mean axial force over its middle third, N"),
        "speed_m_s": field(NUM, "mean belt speed over its middle third, m/s")}),
    "arms": field("array", "per tensioner, in belt order (null when no steady state)",
                  items="object", nullable=True, keys={
        "name": field(STR, "the tensioner pulley's name"),
        "angle_rad": field(NUM, "its arm's angle (centre - pivot, counter-clockwise from x), "
                                "rad")}),
    "belt_s_m": field("array", "belt arc coordinate (reference length from node 0) of the "
                      "points along the belt, m", nullable=True, items=NUM),
    "axial_force_N": field("array", "axial force at those points, N", nullable=True,
                           items=NUM),
    "speed_m_s": field("array", "material speed at those points, m/s", nullable=True,
                       items=NUM),
    "contact_pressure_N_m": field("array", "the pulleys' normal force on the belt per unit "
                                  "length at those points, N/m", nullable=True, items=NUM),
    "friction_force_N_m": field("array", "the friction force on the belt per unit length "
                                "along the pulley's counter-clockwise tangent, N/m",
                                nullable=True, items=NUM),
    "belt_x_m": field("array", "x of those points, m", nullable=True, items=NUM),
    "belt_y_m": field("array", "y of those points, m", nullable=True, items=NUM),
    "transport_speed_m_s": field(NUM, "the ALE transport speed vb (reference length per "
                                 "second), m/s", nullable=True),
    "load_factor": field(NUM, "the pulley laws' scale reached by the continuation (1: "
                              "converged)"),
    "newton_iterations": field(INT, "Newton iterations over the continuation"),
    "continuation_steps": field(INT, "converged continuation steps"),
    "total_dofs": field(INT, "unknowns: belt coordinates less the gauge, the transport speed, "
                             "the free pulleys' speeds and the arms' angles", required=False),
    "pretension_iterations": field(INT, "Newton iterations of the static pre-tension",
                                   required=False)}


SCENE = bd.FileScene(
    "belt-drive",
    "The steady running state of a drive file's 2D belt drive (ancf steady belt-drive --file "
    "drive.toml): Newton in the axially moving (ALE) description at the laws' final values.",
    bd.SCENE.params, run, warn=warn, results=RESULTS, swept=False)
