"""Exudyn's THREAD belt drive as its example ``main/pythonDev/Examples/beltDriveReevingSystem.py``
sets it up (``improvedBelt = True``), written again with Exudyn's API.

Model (SI units): two pulleys r = 0.09995 m at (0, 0) and (0.1 pi, 0) m, a closed loop of
``N_ELEMENTS`` = 240 ``ObjectANCFCable2D`` elements laid by ``CreateReevingCurve`` on the
path at radius r + h/2 (h = 1e-4 m geometric height; stiffness height 0.01 m, width 0.08
m), E = 1e7 Pa, EA = 8000 N, EI = 0.02 E I = 1.333e-3 N m^2, rho = 1036 kg/m^3, axial
damping dEA = 1 N s, reference axial strain -0.05 (``strainIsRelativeToReference`` off),
gravity 9.81 m/s^2 on the belt.  Contact: one ``ObjectContactFrictionCircleCable2D`` per
element and pulley, ``SEGMENTS`` = 2 segments, with cFact = b l_e / segments:
contactStiffness 4e9 cFact, contactDamping 8e4 cFact, frictionStiffness 5e9 cFact (the
bristle), frictionVelocityPenalty 10 sqrt(1e8 cFact rhoA l_e / segments), mu = 0.5; the
example's general contact with the two pulleys as spheres (no belt in it) is added too.
Pulleys: rigid bodies (mass 50 kg, I = 0.25 kg m^2), centres held; the driver's angular
velocity by a velocity-level coordinate constraint with a Python user function (ramp to
12 rad/s over 0.05-0.6 s); the driven pulley with rotational damping 2 N m s and the
load torque 25 SmoothStep(t, 1, 1.5) N m (Python user function).  Static equilibrium
first (drive off, friction off, both pulleys and one belt node held), then the
``TrapezoidalIndex2`` solver with step ``STEP`` = 1e-4 s to 2.45 s, modified Newton,
EigenSparse, one thread, discontinuous iterations <= 3 (tolerance 1e-3).  Left out of the
example: graphics, the solution file (every 2 ms) and the per-element sensors (every
1 ms): output only, so Exudyn's time here is at most the example's.

``python -m benchmarks.peers_thread_exudyn [T_END]`` runs one case and prints the summary
as JSON (times in s, angular velocities in rad/s, forces in N, torques in N m).
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
    from exudyn.beams import CreateReevingCurve, PointsAndSlopes2ANCFCable2D
    from exudyn.utilities import SmoothStep
except ImportError:  # optional extra `peers`
    exu = None

N_ELEMENTS, SEGMENTS, STEP, T_END = 240, 2, 1e-4, 2.45
R, D, HC, B, H_STIFF = 0.09995, 0.1 * math.pi, 1e-4, 0.08, 0.01
E_MOD, RHO, DEA, PRESTRETCH, MU = 1e7, 1036.0, 1.0, -0.05, 0.5
RAMP = (0.05, 0.6, 12.0)            # s, s, rad/s
LOAD = (1.0, 1.5, 25.0)             # s, s, N m
WHEEL_MASS, WHEEL_INERTIA, WHEEL_DAMPING = 50.0, 0.25, 2.0
DISCONTINUOUS = 3
WINDOW = 0.45                       # s, means over the run's last WINDOW (2.0-2.45 s)


def _belt(mbs):
    A, I = B * H_STIFF, B * H_STIFF ** 3 / 12
    circles = [[[0.0, 0.0], R, "L"], [[D, 0.0], R, "L"]]
    reeving = CreateReevingCurve(circles, drawingLinesPerCircle=64, radialOffset=0.5 * HC,
                                 closedCurve=True, numberOfANCFnodes=N_ELEMENTS)
    template = ei.Cable2D(physicsMassPerLength=RHO * A, physicsBendingStiffness=0.02 * E_MOD * I,
                          physicsAxialStiffness=E_MOD * A, physicsBendingDamping=0.0,
                          physicsAxialDamping=DEA, physicsReferenceAxialStrain=PRESTRETCH,
                          physicsReferenceCurvature=0.0, useReducedOrderIntegration=2,
                          strainIsRelativeToReference=False)
    ancf = PointsAndSlopes2ANCFCable2D(mbs, reeving["ancfPointsSlopes"], reeving["elementLengths"],
                                       template, massProportionalLoad=[0, -9.81, 0],
                                       fixedConstraintsNode0=[1, 0, 0, 0], firstNodeIsLastNode=True)
    return reeving, ancf


def _coefficients(total_length: float) -> dict:
    l_e = total_length / N_ELEMENTS
    c = B * l_e / SEGMENTS
    return {"contactStiffness": 1e8 * 40 * c, "contactDamping": 2000 * 40 * c,
            "frictionStiffness": 1e8 * 50 * c,
            "frictionVelocityPenalty": 10 * math.sqrt(1e8 * c * RHO * B * H_STIFF * l_e / SEGMENTS)}


def _omega(mbs, t, item, offset):
    t0, t1, w = RAMP
    return 0.0 if t < t0 else (w * (t - t0) / (t1 - t0) if t < t1 else w)


def _load(mbs, t, load):
    return -LOAD[2] * SmoothStep(t, LOAD[0], LOAD[1], 0.0, 1.0)


def build():
    """The system and its handles (holds for the static solve, the drive, sensors)."""
    sc = exu.SystemContainer()
    mbs = sc.AddSystem()
    reeving, ancf = _belt(mbs)
    co = _coefficients(reeving["totalLength"])
    ground = mbs.AddObject(ei.ObjectGround())
    g_node = mbs.AddNode(ei.NodePointGround())
    m_ground = mbs.AddMarker(ei.MarkerNodeCoordinate(nodeNumber=g_node, coordinate=0))
    general = mbs.AddGeneralContact()
    general.ancfCableUseExactMethod = False
    general.ancfCableNumberOfContactSegments = SEGMENTS
    general.SetSearchTreeCellSize(numberOfCells=[16, 16, 1])
    h = {"holds": list(ancf[4]), "contacts": [], "sensors": [], "belt": ancf[1], "coeffs": co}
    for i, x in enumerate((0.0, D)):
        node = mbs.AddNode(ei.NodeRigidBody2D(referenceCoordinates=[x, 0, 0]))
        body = mbs.AddObject(ei.ObjectRigidBody2D(physicsMass=WHEEL_MASS,
                                                  physicsInertia=WHEEL_INERTIA, nodeNumber=node))
        m_node = mbs.AddMarker(ei.MarkerNodeRigid(nodeNumber=node))
        for k in (0, 1):
            m = mbs.AddMarker(ei.MarkerNodeCoordinate(nodeNumber=node, coordinate=k))
            mbs.AddObject(ei.CoordinateConstraint(markerNumbers=[m_ground, m]))
        rot = mbs.AddMarker(ei.MarkerNodeCoordinate(nodeNumber=node, coordinate=2))
        h["sensors"].append(mbs.AddSensor(ei.SensorNode(
            nodeNumber=node, storeInternal=True, outputVariableType=exu.OutputVariableType.AngularVelocity)))
        if i == 0:
            h["drive"] = mbs.AddObject(ei.CoordinateConstraint(
                markerNumbers=[m_ground, rot], velocityLevel=True, offsetUserFunction_t=_omega))
            h["torque"] = mbs.AddSensor(ei.SensorObject(
                objectNumber=h["drive"], storeInternal=True,
                outputVariableType=exu.OutputVariableType.Force))
        else:
            mbs.AddObject(ei.CoordinateSpringDamper(markerNumbers=[m_ground, rot],
                                                    damping=WHEEL_DAMPING))
            mbs.AddLoad(ei.LoadCoordinate(markerNumber=rot, load=0, loadUserFunction=_load))
        h["holds"].append(mbs.AddObject(ei.CoordinateConstraint(markerNumbers=[m_ground, rot])))
        general.AddSphereWithMarker(m_node, radius=R, contactStiffness=co["contactStiffness"],
                                    contactDamping=co["contactDamping"], frictionMaterialIndex=0)
        m_body = mbs.AddMarker(ei.MarkerBodyRigid(bodyNumber=body))
        for cable in ancf[1]:
            m_cable = mbs.AddMarker(ei.MarkerBodyCable2DShape(
                bodyNumber=cable, numberOfSegments=SEGMENTS, verticalOffset=-HC / 2))
            data = mbs.AddNode(ei.NodeGenericData(
                initialCoordinates=[0.1] * SEGMENTS + [-2] * SEGMENTS + [0] * SEGMENTS,
                numberOfDataCoordinates=3 * SEGMENTS))
            h["contacts"].append(mbs.AddObject(ei.ObjectContactFrictionCircleCable2D(
                markerNumbers=[m_body, m_cable], nodeNumber=data, numberOfContactSegments=SEGMENTS,
                frictionCoefficient=MU, circleRadius=R, **co)))
    general.SetFrictionPairings(np.array([[MU, 0.0], [0.0, 0.0]]))
    del ground
    mbs.Assemble()
    return mbs, sc, h


def settings(t_end: float):
    s = exu.SimulationSettings()
    s.linearSolverType = exu.LinearSolverType.EigenSparse
    s.solution.file.write = False
    s.solution.sensors.writePeriod = 0.001
    s.parallel.numberOfThreads = 1
    s.show.statistics = False
    s.show.computationTime = False
    ti = s.timeIntegration
    ti.endTime, ti.numberOfSteps, ti.verboseMode = t_end, int(round(t_end / STEP)), 0
    ti.newton.useModifiedNewton = True
    ti.discontinuous.iterationTolerance = 1e-3
    ti.discontinuous.maxIterations = DISCONTINUOUS
    st = s.staticSolver
    st.adaptiveStep, st.loadStepGeometric, st.loadStepGeometricRange = False, True, 1e4
    st.numberOfLoadSteps, st.stabilizerODE2term = 10, 1e5
    st.newton.relativeTolerance = st.newton.absoluteTolerance = 1e-6
    return s


def _set(mbs, items, name, value) -> None:
    for i in items:
        mbs.SetObjectParameter(i, name, value)


def solve(mbs, h, s) -> dict:
    """Static equilibrium (drive off, friction off), then the dynamic run; counts."""
    _set(mbs, [h["drive"]], "activeConnector", False)
    _set(mbs, h["contacts"], "frictionCoefficient", 0.0)
    _set(mbs, h["contacts"], "frictionStiffness", 1e-8)
    mbs.SolveStatic(s, updateInitialValues=True)
    _set(mbs, h["contacts"], "frictionCoefficient", MU)
    _set(mbs, h["contacts"], "frictionStiffness", h["coeffs"]["frictionStiffness"])
    _set(mbs, h["holds"], "activeConnector", False)
    _set(mbs, [h["drive"]], "activeConnector", True)
    c0 = time.process_time()
    ok = mbs.SolveDynamic(s, solverType=exu.DynamicSolverType.TrapezoidalIndex2)
    it = mbs.sys["dynamicSolver"].it
    return {"converged": bool(ok), "dynamic_cpu_s": time.process_time() - c0,
            "steps": int(it.currentStepIndex) - 1, "newton_iterations": int(it.newtonStepsCount),
            "jacobians": int(it.newtonJacobiCount),
            "discontinuous_iterations": int(it.discontinuousIterationsCount)}


def span_forces(mbs, belt) -> tuple[float, float]:
    """(upper, lower): mean axial force (N) of the element midpoints in the middle third
    of each span (0.1 pi / 3 < x < 0.2 pi / 3) at the end of the run."""
    upper, lower = [], []
    for e in belt:
        l_e = mbs.GetObjectParameter(e, "length")
        p = mbs.GetObjectOutputBody(e, exu.OutputVariableType.Position, [0.5 * l_e, 0, 0])
        if D / 3 < p[0] < 2 * D / 3:
            f = mbs.GetObjectOutputBody(e, exu.OutputVariableType.ForceLocal, [0.5 * l_e, 0, 0])
            (upper if p[1] > 0 else lower).append(float(np.ravel(f)[0]))
    return float(np.mean(upper)), float(np.mean(lower))


def run(t_end: float = T_END) -> dict:
    """One run: CPU (build, static and dynamic: ``cpu_s``), driven speed and span forces."""
    c0, w0 = time.process_time(), time.perf_counter()
    mbs, _sc, h = build()
    out = solve(mbs, h, settings(t_end))
    out |= {"cpu_s": time.process_time() - c0, "wall_s": time.perf_counter() - w0}
    w = mbs.GetSensorStoredData(h["sensors"][1])
    q = mbs.GetSensorStoredData(h["torque"])
    t, win = w[:, 0], w[:, 0] >= t_end - min(WINDOW, t_end / 2) - 1e-9
    tight, slack = span_forces(mbs, h["belt"])
    return {"t_end": t_end, "n_elements": N_ELEMENTS, "segments": SEGMENTS, "step": STEP,
            "exudyn_version": exu.__version__, **out, "omega_driven": float(w[-1, 3]),
            "omega_driven_mean": float(np.mean(w[win, 3])),
            "driver_torque_mean_Nm": float(-np.mean(q[win, 1])),
            "tension_tight_N": tight, "tension_slack_N": slack,
            "t_series": t.tolist(), "omega_driven_series": w[:, 3].tolist()}


def main(argv=None) -> int:
    argv = sys.argv[1:] if argv is None else argv
    res = run(float(argv[0]) if argv else T_END)
    print(json.dumps({k: v for k, v in res.items() if not k.endswith("_series")}, indent=1))
    return 0


if __name__ == "__main__":
    sys.exit(main())
