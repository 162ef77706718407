"""Exudyn's planar two-pulley belt drive of thesis chapter 3 (Table 3.1, Eq 3.29).

The belt is a closed loop of ``ObjectANCFCable2D`` elements (Euler-Bernoulli cable, 4
coordinates per node), wrapped around two pulleys of radius R = 0.08125 m centred at
(-0.191441, 0) m (driver) and (0.191441, 0) m (driven).  Material: rho = 1036 kg/m^3,
0.01 m square section, E = 1e8 Pa; the thesis scales the axial and bending parts of
its strain energy by alpha1 = 1 and alpha2 = 0.01, so the cable gets EA = alpha1 E A
[N] and EI = alpha2 E I [N m^2] (the cable has no such parameters, nu and shear do
not enter).  The belt's material length is 1.2727 m; its nodes are placed on the
wrapped centreline (2 l_s + 2 pi R = 1.27627 m) with slopes of length
1.27627 / 1.2727, so it starts stretched by 0.28 %.

Contact: one ``ObjectContactFrictionCircleCable2D`` per element and pulley, on the
belt centreline (``verticalOffset`` 0, as the thesis measures the penetration of the
centreline, Eq 3.21) with ``segments`` straight segments per element.  Exudyn's
coefficients act per segment (a point force at the segment's closest point), the
thesis' per unit length, so each is the thesis value times the segment's material
length l_seg [m]: contactStiffness = k_p l_seg [N/m], contactDamping = c_p l_seg
[N s/m], frictionVelocityPenalty = nu_s l_seg [N s/m] (the creep slope),
frictionCoefficient = mu.  Exudyn's stick/slip logic also needs its tangential
sticking spring: frictionStiffness = 0.2 contactStiffness [N/m], the ratio of
Exudyn's beltDrivesComparison.py (without it, velocity penalty alone, the belt does not
stay at rest before the drive starts).  Per segment the tangential force is
mu_k dx_stick + mu_v v_t while below mu |f_n|, else mu |f_n| in the slip direction;
the stick/slip state is decided in Exudyn's post-Newton (discontinuous) iteration.

Run: a static pre-tension first (both pulleys held, one belt node held in x so the
frictionless loop cannot turn; the belt settles onto the pulleys), then the dynamic
run from that state with the driver's angular velocity prescribed by Eq 3.29
(velocity-level coordinate constraint, a symbolic user function) and the driven
pulley free to turn with I = 0.1 kg m^2; generalised-alpha with a fixed step.

``python -m benchmarks.peers_belt_exudyn N [STEP]`` runs one case and prints the
summary (without the time series) as JSON.
"""
from __future__ import annotations

import json
import math
import sys
import time

import numpy as np

try:
    import exudyn as exu
    from exudyn import itemInterface as ei
    from exudyn.utilities import CreateSymbolicUserFunction
except ImportError:  # optional extra `peers`: the constants and the path serve without it
    exu = ei = CreateSymbolicUserFunction = None

#: Table 3.1 [SI units: m, kg/m^3, Pa, N/m^2, N s/m^2, kg/(m s), kg m^2]
TABLE = {"R": 0.08125, "x_driver": -0.191441, "x_driven": 0.191441, "rho": 1036.0,
         "side": 0.01, "E": 1e8, "length": 1.2727, "k_p": 1e7, "c_p": 10.0, "mu": 1.2,
         "nu_s": 1e5, "inertia": 0.1, "alpha1": 1.0, "alpha2": 0.01}
#: Eq 3.29: start of the ramp [s], end of the ramp [s], final driver speed [rad/s]
RAMP = (0.05, 0.6, 12.0)
PULLEY_MASS = 1.0        # kg; the pulley centres are held, the mass does not enter
STEP = 2.5e-4            # s, Exudyn's step for this contact in beltDrivesComparison.py
SPECTRAL_RADIUS = 0.5    # as in beltDrivesComparison.py
SEGMENTS = 4             # contact segments per element (5 points, as 5 Gauss points)
STICK_SPRING = 0.2       # frictionStiffness / contactStiffness, as in beltDrivesComparison.py
MEAN_WINDOW = 0.2        # s, the driven speed is also averaged over the run's last 0.2 s
SAMPLE_DT = 2e-3         # s, sampling of the angular velocities


def driver_omega(t, lib=None):
    """Eq 3.29: prescribed driver angular velocity [rad/s] at time t [s] (positive =
    counter-clockwise).  ``lib``: module with min/max (``exu.symbolic`` to record a
    symbolic function); builtins by default."""
    lo, hi = (lib.min, lib.max) if lib is not None else (min, max)
    t0, t1, w = RAMP
    return w * lo(hi((t - t0) / (t1 - t0), 0.0), 1.0)


def span() -> float:
    """Free span length l_s [m]: distance of the pulley centres."""
    return TABLE["x_driven"] - TABLE["x_driver"]


def wrapped_length() -> float:
    """Length of the wrapped centreline [m]: two spans and two half circles."""
    return 2 * span() + 2 * math.pi * TABLE["R"]


def _line(start, direction, u: float):
    d = np.asarray(direction, float)
    return np.asarray(start, float) + u * d, d


def _arc(x_centre: float, phi: float):
    """Point and counter-clockwise tangent on a pulley at angle phi [rad]."""
    c, s = math.cos(phi), math.sin(phi)
    return np.array([x_centre + TABLE["R"] * c, TABLE["R"] * s]), np.array([-s, c])


def _legs():
    """(length [m], point and tangent at local arc length u) of the five legs."""
    R, ls, a = TABLE["R"], span(), math.pi * TABLE["R"]
    xd, xn = TABLE["x_driver"], TABLE["x_driven"]
    return ((ls / 2, lambda u: _line((0.0, -R), (1.0, 0.0), u)),
            (a, lambda u: _arc(xn, -math.pi / 2 + u / R)),
            (ls, lambda u: _line((xn, R), (-1.0, 0.0), u)),
            (a, lambda u: _arc(xd, math.pi / 2 + u / R)),
            (ls / 2, lambda u: _line((xd, -R), (1.0, 0.0), u)))


def belt_path(s: float):
    """Point and unit tangent [m, -] at arc length s [m] along the wrapped centreline,
    counter-clockwise from the middle of the lower span (0, -R)."""
    s %= wrapped_length()
    legs = _legs()
    for length, leg in legs[:-1]:
        if s <= length:
            return leg(s)
        s -= length
    return legs[-1][1](s)


def cable_template(n: int) -> dict:
    """Cable2D parameters of one of n elements: material length [m], rho A [kg/m],
    EA [N], EI [N m^2]."""
    a = TABLE["side"]
    return {"length": TABLE["length"] / n, "massPerLength": TABLE["rho"] * a * a,
            "axialStiffness": TABLE["alpha1"] * TABLE["E"] * a * a,
            "bendingStiffness": TABLE["alpha2"] * TABLE["E"] * a**4 / 12}


def contact_coefficients(n: int, segments: int) -> dict:
    """Exudyn's per-segment contact coefficients from the thesis' per-length ones:
    each times the segment's material length l_seg = length / (n segments) [m]; the
    sticking spring STICK_SPRING times the contact stiffness."""
    l_seg = TABLE["length"] / (n * segments)
    return {"contactStiffness": TABLE["k_p"] * l_seg, "contactDamping": TABLE["c_p"] * l_seg,
            "frictionVelocityPenalty": TABLE["nu_s"] * l_seg,
            "frictionStiffness": STICK_SPRING * TABLE["k_p"] * l_seg,
            "frictionCoefficient": TABLE["mu"], "numberOfContactSegments": segments}


def _belt(mbs, n: int):
    """Closed loop of n Cable2D elements on the wrapped centreline, slopes of length
    wrapped / material length (the pre-stretch).  Nodes run clockwise: with the
    counter-clockwise order Exudyn's sticking-spring logic turned the driven pulley
    backwards (-1.0 rad/s at t = 0.15 s, driver +2.2 rad/s).  Returns (nodes, elements)."""
    stretch, ds = wrapped_length() / TABLE["length"], wrapped_length() / n
    nodes = []
    for i in range(n):
        r, t = belt_path(-i * ds)
        nodes.append(mbs.AddNode(ei.NodePoint2DSlope1(
            referenceCoordinates=[*r, *(-stretch * t)])))
    elements = [mbs.AddObject(ei.Cable2D(**cable_template(n),
                                         nodeNumbers=[nodes[i], nodes[(i + 1) % n]]))
                for i in range(n)]
    return nodes, elements


def _hold(mbs, ground, node: int, coordinate: int, **kw) -> int:
    """Coordinate constraint of one node coordinate against ground."""
    mk = mbs.AddMarker(ei.MarkerNodeCoordinate(nodeNumber=node, coordinate=coordinate))
    return mbs.AddObject(ei.CoordinateConstraint(markerNumbers=[ground, mk], **kw))


def _pulley(mbs, ground, x: float, inertia: float):
    """Pulley at (x, 0) turning about its held centre.  Returns (node, rigid marker,
    the constraint holding its rotation)."""
    node = mbs.AddNode(ei.NodeRigidBody2D(referenceCoordinates=[x, 0.0, 0.0]))
    mbs.AddObject(ei.ObjectRigidBody2D(mass=PULLEY_MASS, inertia=inertia,
                                       nodeNumber=node))
    for k in (0, 1):
        _hold(mbs, ground, node, k)
    return node, mbs.AddMarker(ei.MarkerNodeRigid(nodeNumber=node)), _hold(mbs, ground, node, 2)


def _contacts(mbs, marker: int, elements, coeffs: dict) -> list:
    """One circle-cable friction contact per element with the pulley of ``marker``."""
    nseg = coeffs["numberOfContactSegments"]
    out = []
    for e in elements:
        shape = mbs.AddMarker(ei.MarkerBodyCable2DShape(bodyNumber=e, numberOfSegments=nseg,
                                                        verticalOffset=0.0))
        data = mbs.AddNode(ei.NodeGenericData(numberOfDataCoordinates=3 * nseg,
                                              initialCoordinates=[0.1] * nseg + [-2] * nseg
                                              + [0.0] * nseg))
        out.append(mbs.AddObject(ei.ObjectContactFrictionCircleCable2D(
            markerNumbers=[marker, shape], nodeNumber=data, circleRadius=TABLE["R"],
            **coeffs)))
    return out


def _drive(mbs, ground, node: int) -> int:
    """Velocity-level constraint of the driver's rotation to Eq 3.29 (inactive until
    the dynamic run)."""
    mk = mbs.AddMarker(ei.MarkerNodeCoordinate(nodeNumber=node, coordinate=2))
    c = mbs.AddObject(ei.CoordinateConstraint(markerNumbers=[ground, mk], velocityLevel=True,
                                              activeConnector=False))

    def omega(mbs, t, item, offset):
        return driver_omega(t, exu.symbolic)

    mbs.SetObjectParameter(c, "offsetUserFunction_t",
                           CreateSymbolicUserFunction(mbs, omega, "offsetUserFunction_t", c))
    return c


def build(n: int, segments: int = SEGMENTS):
    """The model; returns (mbs, SC, handles) with handles a dict of item numbers."""
    SC = exu.SystemContainer()
    mbs = SC.AddSystem()
    ground = mbs.AddMarker(ei.MarkerNodeCoordinate(nodeNumber=mbs.AddNode(ei.NodePointGround()),
                                                   coordinate=0))
    nodes, elements = _belt(mbs, n)
    driver, m_driver, hold_driver = _pulley(mbs, ground, TABLE["x_driver"], TABLE["inertia"])
    driven, m_driven, hold_driven = _pulley(mbs, ground, TABLE["x_driven"], TABLE["inertia"])
    coeffs = contact_coefficients(n, segments)
    contacts = _contacts(mbs, m_driver, elements, coeffs) + _contacts(mbs, m_driven, elements,
                                                                      coeffs)
    handles = {"static_holds": [hold_driver, hold_driven, _hold(mbs, ground, nodes[0], 0)],
               "drive": _drive(mbs, ground, driver), "contacts": contacts, "friction": coeffs,
               "sensors": [mbs.AddSensor(ei.SensorNode(
                   nodeNumber=p, storeInternal=True, writeToFile=False,
                   outputVariableType=exu.OutputVariableType.AngularVelocity))
                   for p in (driver, driven)]}
    mbs.Assemble()
    return mbs, SC, handles


def _settings(t_end: float, step: float, spectral_radius: float):
    s = exu.SimulationSettings()
    s.solution.file.write = False
    s.solution.sensors.writePeriod = SAMPLE_DT
    s.solution.solverInformationFileName = ""
    s.show.statistics = False
    s.show.computationTime = False
    s.linearSolver.solverType = exu.LinearSolverType.EigenSparse
    s.parallel.numberOfThreads = 1
    ti = s.timeIntegration
    ti.endTime, ti.numberOfSteps, ti.verboseMode = t_end, max(1, round(t_end / step)), 0
    ti.generalizedAlpha.spectralRadius = spectral_radius
    ti.newton.useModifiedNewton = True
    ti.newton.numericalDifferentiation.minimumCoordinateSize = 1
    ti.discontinuous.maxIterations = 7
    s.staticSolver.verboseMode = 0
    return s


def _set_active(mbs, items, active: bool) -> None:
    for c in items:
        mbs.SetObjectParameter(c, "activeConnector", active)


def _friction(mbs, contacts, coeffs: dict) -> None:
    for c in contacts:
        for k in ("frictionCoefficient", "frictionStiffness"):
            mbs.SetObjectParameter(c, k, coeffs[k])


def solve_static(mbs, handles, settings) -> dict:
    """Pre-tension: pulleys and one belt node held, friction off (a unit sticking
    spring, as Exudyn's example, so the contact still initialises); the settled
    state becomes the initial state.  Returns wall time [s] and the static counts."""
    _friction(mbs, handles["contacts"], {"frictionCoefficient": 0.0, "frictionStiffness": 1.0})
    solver = exu.MainSolverStatic()
    t0 = time.perf_counter()
    ok = solver.SolveSystem(mbs, settings)
    wall = time.perf_counter() - t0
    _friction(mbs, handles["contacts"], handles["friction"])
    mbs.systemData.SetSystemState(systemStateList=mbs.systemData.GetSystemState(),
                                  configuration=exu.ConfigurationType.Initial)
    return {"static_wall_s": wall, "static_converged": bool(ok),
            "static_newton_iterations": int(solver.it.newtonStepsCount)}


def solve_dynamic(mbs, handles, settings) -> dict:
    """Drive on, holds off; generalised-alpha.  Wall and CPU time [s] and counts."""
    _set_active(mbs, handles["static_holds"], False)
    _set_active(mbs, [handles["drive"]], True)
    solver = exu.MainSolverImplicitSecondOrder()
    t0, c0 = time.perf_counter(), time.process_time()
    ok = solver.SolveSystem(mbs, settings)
    wall, cpu = time.perf_counter() - t0, time.process_time() - c0
    it = solver.it
    return {"wall_s": wall, "cpu_s": cpu, "converged": bool(ok),
            "steps": int(it.currentStepIndex) - 1, "newton_iterations": int(it.newtonStepsCount),
            "jacobians": int(it.newtonJacobiCount),
            "discontinuous_iterations": int(it.discontinuousIterationsCount),
            "rejected_modified_newton_steps": int(it.rejectedModifiedNewtonSteps)}


def _omegas(mbs, handles) -> tuple:
    """Sample times [s] and angular velocities [rad/s] of driver and driven pulley."""
    data = [mbs.GetSensorStoredData(s) for s in handles["sensors"]]
    return data[0][:, 0], data[0][:, 3], data[1][:, 3]


def exudyn_belt(n_elements: int, t_end: float = 1.0, step: float = STEP,
                segments: int = SEGMENTS, spectral_radius: float = SPECTRAL_RADIUS) -> dict:
    """Build, pre-tension and run the belt drive with n_elements elements for t_end [s]
    with the fixed step [s].  Times in s (``wall_s`` / ``cpu_s``: the dynamic solve;
    ``static_wall_s``; ``total_wall_s`` / ``total_cpu_s``: build + static + dynamic);
    angular velocities in rad/s (positive = counter-clockwise); ``omega_driven_mean_last``
    the driven one's mean over the last MEAN_WINDOW; ``omega_driven_series`` sampled
    every SAMPLE_DT at ``t_series``."""
    t0, c0 = time.perf_counter(), time.process_time()
    mbs, _sc, handles = build(n_elements, segments)
    settings = _settings(t_end, step, spectral_radius)
    res = {"n": n_elements, "t_end": t_end, "step": step, "segments": segments,
           "spectral_radius": spectral_radius, **solve_static(mbs, handles, settings),
           **solve_dynamic(mbs, handles, settings)}
    res["total_wall_s"], res["total_cpu_s"] = time.perf_counter() - t0, time.process_time() - c0
    t, w1, w2 = _omegas(mbs, handles)
    return {**res, "omega_driver": float(w1[-1]), "omega_driven": float(w2[-1]),
            "ratio_driven_driver": float(w2[-1] / w1[-1]) if w1[-1] else None,
            "omega_driver_prescribed": driver_omega(t_end),
            "omega_driven_mean_last": float(np.mean(w2[t >= t_end - MEAN_WINDOW - 1e-12])),
            "t_series": t.tolist(), "omega_driven_series": w2.tolist()}


def main(argv=None) -> int:
    """``python -m benchmarks.peers_belt_exudyn N [STEP]``: one run, summary as JSON."""
    argv = sys.argv[1:] if argv is None else argv
    res = exudyn_belt(int(argv[0]), step=float(argv[1]) if len(argv) > 1 else STEP)
    print(json.dumps({k: v for k, v in res.items() if not k.endswith("_series")}, indent=1))
    return 0


if __name__ == "__main__":
    sys.exit(main())
