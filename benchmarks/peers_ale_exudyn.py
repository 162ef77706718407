"""THREAD's belt drive in Exudyn's axially moving (ALE) form: ``ALECable2D`` elements on a
mesh fixed in space, one ``NodeGenericODE2`` coordinate for the belt's transport, marched
through THREAD's schedule to its steady window (2.0-2.45 s); API as in Exudyn's
``main/pythonDev/Examples/beltDriveALE.py``, the model written here.

Model (SI units): THREAD's layout, belt and pulleys as in :mod:`benchmarks.peers_thread_exudyn`
(r = 0.09995 m, centre distance 0.1 pi m, EA = 8000 N, EI = 1.333e-3 N m^2, rho A =
0.8288 kg/m, reference axial strain -0.05, gravity; driver ramped to 12 rad/s over
0.05-0.6 s, driven pulley I = 0.25 kg m^2, 2 N m s, 25 N m load over 1-1.5 s), at
``N_ELEMENTS`` elements.  Contact and friction from our drive file ``FILE`` per contact
segment of length l_s = l_e / ``SEGMENTS``: contactStiffness k_p l_s, contactDamping
c_p l_s, frictionVelocityPenalty nu_s l_s, frictionStiffness 0, mu.  With no bristle
stiffness Exudyn's friction is f_t = mu_v v_t capped at mu |f_n| (its
ObjectContactFrictionCircleCable2D documentation), our creep-rate law (thesis Eq. 3.23)
per segment; Exudyn's documentation rules the bristle out for ALECable2D.  Contact on the
belt's centreline against a circle of radius r + h/2 = 0.1 m (Exudyn's ALE cable takes no
marker verticalOffset): the same gap as our file's contact_offset h/2 on radius r.
Left different: Exudyn's axial damping dEA acts on the coordinates' time rate only (no
transport term, zero in a steady ALE state), ours on the material strain rate.

Static equilibrium first (drive off, friction off, transport coordinate and pulleys held),
then ``TrapezoidalIndex2`` with step ``STEP``, modified Newton, EigenSparse, one thread.

``python -m benchmarks.peers_ale_exudyn [--t-end 2.45] [--step 2.5e-5] [--elements 120]
[--segments 2]`` prints one JSON object: ``cpu_to_window_s`` (``time.process_time`` from
before the build until the march reaches the window's start), ``cpu_s`` (to t_end), the
window means ``omega_driven_mean`` (rad/s), ``tension_tight_N``, ``tension_slack_N`` (N;
axial force at the element midpoints in the spans' middle thirds), ``driver_torque_mean_Nm``
and ``transport_speed_mean_m_s``, the driven speed's drift over the window (rad/s) and the
run's counts.
"""
from __future__ import annotations

import argparse
import json
import sys
import time

import numpy as np

from ancf.belts.drive_file import load
from benchmarks import peers
from benchmarks import peers_thread_exudyn as px

exu = px.exu
if exu is not None:
    from exudyn import itemInterface as ei
    from exudyn.beams import CreateReevingCurve, PointsAndSlopes2ANCFCable2D

FILE = peers.ROOT / "examples" / "thread_creep_rate.toml"
N_ELEMENTS, SEGMENTS, STEP = 120, 2, 2.5e-5
WINDOW = (2.0, 2.45)                # s, THREAD's steady window
SENSOR_PERIOD = 1e-3                # s


def window_mean(t, y, window=WINDOW) -> np.ndarray:
    """Mean over the samples window[0] <= t <= window[1] (s) of y (rows: samples)."""
    t = np.asarray(t, dtype=float)
    sel = (t >= window[0] - 1e-9) & (t <= window[1] + 1e-9)
    if not sel.any():
        raise ValueError(f"window = {window}: no sample in it; allowed: a window inside "
                         f"[{t.min():g}, {t.max():g}] s")
    return np.mean(np.asarray(y, dtype=float)[sel], axis=0)


def coefficients(path, elements: int, segments: int) -> dict:
    """Exudyn's per-segment contact coefficients from our file's per-length ones (x l_s)."""
    desc = load(path, [])
    l_s = desc.path.length / elements / segments
    return {"contactStiffness": desc.contact["k_p"] * l_s,
            "contactDamping": desc.contact["c_p"] * l_s,
            "frictionVelocityPenalty": desc.friction["nu_s"] * l_s, "frictionStiffness": 0.0,
            "frictionCoefficient": desc.friction["mu"]}


def _belt(mbs, elements: int):
    """The ALE belt on THREAD's path: (reeving, PointsAndSlopes2ANCFCable2D's lists, ALE node)."""
    ale = mbs.AddNode(ei.NodeGenericODE2(numberOfODE2Coordinates=1, referenceCoordinates=[0],
                                         initialCoordinates=[0], initialCoordinates_t=[0]))
    A, I = px.B * px.H_STIFF, px.B * px.H_STIFF ** 3 / 12
    reeving = CreateReevingCurve([[[0.0, 0.0], px.R, "L"], [[px.D, 0.0], px.R, "L"]],
                                 drawingLinesPerCircle=64, radialOffset=0.5 * px.HC,
                                 closedCurve=True, numberOfANCFnodes=elements)
    template = ei.ALECable2D(nodeNumbers=[-1, -1, ale], physicsMassPerLength=px.RHO * A,
                             physicsBendingStiffness=0.02 * px.E_MOD * I,
                             physicsAxialStiffness=px.E_MOD * A, physicsAxialDamping=px.DEA,
                             physicsReferenceAxialStrain=px.PRESTRETCH,
                             useReducedOrderIntegration=2, strainIsRelativeToReference=False,
                             physicsAddALEvariation=False)
    ancf = PointsAndSlopes2ANCFCable2D(mbs, reeving["ancfPointsSlopes"], reeving["elementLengths"],
                                       template, massProportionalLoad=[0, -9.81, 0],
                                       fixedConstraintsNode0=[1, 0, 0, 0],
                                       firstNodeIsLastNode=True)
    return reeving, ancf, ale


def _span_sensors(mbs, reeving, belt) -> dict:
    """ForceLocal sensors at the midpoints of the elements in the spans' middle thirds."""
    pts = np.array(reeving["ancfPointsSlopes"])[:, :2]
    out = {"tight": [], "slack": []}
    for k, e in enumerate(belt):
        x, y = 0.5 * (pts[k] + pts[(k + 1) % len(belt)])
        if px.D / 3 < x < 2 * px.D / 3:
            l_e = reeving["elementLengths"][k]
            out["tight" if y > 0 else "slack"].append(mbs.AddSensor(ei.SensorBody(
                bodyNumber=e, localPosition=[0.5 * l_e, 0, 0], storeInternal=True,
                outputVariableType=exu.OutputVariableType.ForceLocal)))
    return out


def _pulley(mbs, h, i, x, m_ground, co, segments) -> None:
    """Pulley i at (x, 0): held centre, drive (i = 0) or damper and load, contacts."""
    node = mbs.AddNode(ei.NodeRigidBody2D(referenceCoordinates=[x, 0, 0]))
    body = mbs.AddObject(ei.ObjectRigidBody2D(mass=px.WHEEL_MASS,
                                              inertia=px.WHEEL_INERTIA, nodeNumber=node))
    for k in (0, 1):
        m = mbs.AddMarker(ei.MarkerNodeCoordinate(nodeNumber=node, coordinate=k))
        mbs.AddObject(ei.CoordinateConstraint(markerNumbers=[m_ground, m]))
    rot = mbs.AddMarker(ei.MarkerNodeCoordinate(nodeNumber=node, coordinate=2))
    out = exu.OutputVariableType
    h["omega"].append(mbs.AddSensor(ei.SensorNode(
        nodeNumber=node, storeInternal=True, outputVariableType=out.AngularVelocity)))
    if i == 0:
        h["drive"] = mbs.AddObject(ei.CoordinateConstraint(
            markerNumbers=[m_ground, rot], velocityLevel=True, offsetUserFunction_t=px._omega))
        h["torque"] = mbs.AddSensor(ei.SensorObject(
            objectNumber=h["drive"], storeInternal=True, outputVariableType=out.Force))
    else:
        mbs.AddObject(ei.CoordinateSpringDamper(markerNumbers=[m_ground, rot],
                                                damping=px.WHEEL_DAMPING))
        mbs.AddLoad(ei.LoadCoordinate(markerNumber=rot, load=0, loadUserFunction=px._load))
    h["holds"].append(mbs.AddObject(ei.CoordinateConstraint(markerNumbers=[m_ground, rot])))
    m_body = mbs.AddMarker(ei.MarkerBodyRigid(bodyNumber=body))
    for cable in h["belt"]:
        m_cable = mbs.AddMarker(ei.MarkerBodyCable2DShape(
            bodyNumber=cable, numberOfSegments=segments, verticalOffset=0.0))
        data = mbs.AddNode(ei.NodeGenericData(
            initialCoordinates=[0.1] * segments + [-2] * segments + [0] * segments,
            numberOfDataCoordinates=3 * segments))
        h["contacts"].append(mbs.AddObject(ei.ObjectContactFrictionCircleCable2D(
            markerNumbers=[m_body, m_cable], nodeNumber=data, numberOfContactSegments=segments,
            circleRadius=px.R + px.HC / 2, **co)))


def build(elements: int, segments: int, path=FILE):
    """The system and its handles (holds, drive, contacts, sensors, coefficients)."""
    sc = exu.SystemContainer()
    mbs = sc.AddSystem()
    reeving, ancf, ale = _belt(mbs, elements)
    g_node = mbs.AddNode(ei.NodePointGround())
    m_ground = mbs.AddMarker(ei.MarkerNodeCoordinate(nodeNumber=g_node, coordinate=0))
    m_ale = mbs.AddMarker(ei.MarkerNodeCoordinate(nodeNumber=ale, coordinate=0))
    co = coefficients(path, elements, segments)
    h = {"holds": [mbs.AddObject(ei.CoordinateConstraint(markerNumbers=[m_ground, m_ale]))],
         "contacts": [], "omega": [], "belt": ancf[1], "coeffs": co,
         "transport": mbs.AddSensor(ei.SensorNode(
             nodeNumber=ale, storeInternal=True,
             outputVariableType=exu.OutputVariableType.Coordinates_t)),
         "spans": _span_sensors(mbs, reeving, ancf[1])}
    for i, x in enumerate((0.0, px.D)):
        _pulley(mbs, h, i, x, m_ground, co, segments)
    mbs.Assemble()
    return mbs, sc, h


def settings(t_end: float, step: float):
    """Exudyn's solver settings: sensors every SENSOR_PERIOD, no solution file, one thread."""
    s = exu.SimulationSettings()
    s.linearSolver.solverType = exu.LinearSolverType.EigenSparse
    s.solution.file.write = False
    s.solution.sensors.writePeriod = SENSOR_PERIOD
    s.parallel.numberOfThreads = 1
    s.show.statistics = s.show.computationTime = False
    ti = s.timeIntegration
    ti.endTime, ti.numberOfSteps, ti.verboseMode = t_end, int(round(t_end / step)), 0
    ti.newton.useModifiedNewton = True
    ti.discontinuous.iterationTolerance = 1e-3
    ti.discontinuous.maxIterations = px.DISCONTINUOUS
    st = s.staticSolver
    st.adaptiveStep, st.loadStepGeometric, st.loadStepGeometricRange = False, True, 1e4
    st.numberOfLoadSteps, st.stabilizerODE2term = 10, 1e5
    st.newton.relativeTolerance = st.newton.absoluteTolerance = 1e-6
    return s


def solve(mbs, h, s, c0: float) -> dict:
    """Static equilibrium (drive and friction off), then the march; ``cpu_to_window_s`` is
    the process CPU from ``c0`` to the first step at or past WINDOW[0]."""
    px._set(mbs, [h["drive"]], "activeConnector", False)
    px._set(mbs, h["contacts"], "frictionCoefficient", 0.0)
    mbs.SolveStatic(s, updateInitialValues=True)
    px._set(mbs, h["contacts"], "frictionCoefficient", h["coeffs"]["frictionCoefficient"])
    px._set(mbs, h["holds"], "activeConnector", False)
    px._set(mbs, [h["drive"]], "activeConnector", True)
    reached = {}

    def mark(mbs, t):
        if t >= WINDOW[0] - 1e-12 and not reached:
            reached["cpu"] = time.process_time() - c0
        return True
    mbs.SetPreStepUserFunction(mark)
    ok = mbs.SolveDynamic(s, solverType=exu.DynamicSolverType.TrapezoidalIndex2)
    it = mbs.sys["dynamicSolver"].it
    return {"converged": bool(ok), "cpu_to_window_s": reached.get("cpu"),
            "steps": int(it.currentStepIndex) - 1, "newton_iterations": int(it.newtonStepsCount),
            "jacobians": int(it.newtonJacobiCount),
            "discontinuous_iterations": int(it.discontinuousIterationsCount)}


def _means(mbs, h, window) -> dict:
    """The window means of the sensors (and the driven speed's drift over the window)."""
    w = mbs.GetSensorStoredData(h["omega"][1])
    t = w[:, 0]
    sel = (t >= window[0] - 1e-9) & (t <= window[1] + 1e-9)
    drift = (np.polyfit(t[sel], w[sel, 3], 1)[0] * (window[1] - window[0])
             if sel.sum() > 1 else None)
    torque = mbs.GetSensorStoredData(h["torque"])[:, 1]
    span = {k: float(np.mean([window_mean(t, mbs.GetSensorStoredData(i)[:, 1], window)
                              for i in ids])) for k, ids in h["spans"].items()}
    return {"omega_driven_mean": float(window_mean(t, w[:, 3], window)),
            "omega_driven_drift": None if drift is None else float(drift),
            "driver_torque_mean_Nm": float(-window_mean(t, torque, window)),
            "transport_speed_mean_m_s": float(window_mean(
                t, mbs.GetSensorStoredData(h["transport"])[:, 1], window)),
            "tension_tight_N": span["tight"], "tension_slack_N": span["slack"],
            "span_elements": {k: len(v) for k, v in h["spans"].items()}}


def run(t_end: float = WINDOW[1], step: float = STEP, elements: int = N_ELEMENTS,
        segments: int = SEGMENTS) -> dict:
    """One run: CPU to the window and to t_end, window means (last half if t_end < 2.45 s)."""
    c0 = time.process_time()
    mbs, _sc, h = build(elements, segments)
    out = solve(mbs, h, settings(t_end, step), c0)
    out["cpu_s"] = time.process_time() - c0
    window = WINDOW if t_end >= WINDOW[1] else (t_end / 2, t_end)
    return {"t_end": t_end, "step": step, "n_elements": elements, "segments": segments,
            "window": list(window), "exudyn_version": exu.__version__,
            "coefficients": h["coeffs"], **out, **_means(mbs, h, window)}


def main(argv=None) -> int:
    if exu is None:
        print("error: exudyn is not installed (optional extra `peers`)", file=sys.stderr)
        return 2
    ap = argparse.ArgumentParser(prog="python -m benchmarks.peers_ale_exudyn",
                                 description=__doc__.split("\n")[0])
    ap.add_argument("--t-end", type=float, default=WINDOW[1], help="s")
    ap.add_argument("--step", type=float, default=STEP, help="s")
    ap.add_argument("--elements", type=int, default=N_ELEMENTS)
    ap.add_argument("--segments", type=int, default=SEGMENTS)
    a = ap.parse_args(argv)
    print(json.dumps(run(a.t_end, a.step, a.elements, a.segments), indent=1))
    return 0


if __name__ == "__main__":
    sys.exit(main())
