"""The two side-by-side cases in Exudyn (``ObjectANCFCable2D``), same mesh, load and step.

* :func:`cantilever`: Model 1 (L = 2 m, b = h = 0.1 m, E = 2.07e11 Pa, tip force
  -5e8 h^3 N), clamped at x = 0 (x, y and the transverse slope r'_y fixed), Exudyn's
  static solver with 10 load steps (linear ramp), full Newton, sparse LU.
* :func:`pendulum`: E = 2.07e7 Pa, rho = 7850 kg/m^3, pinned at the origin, horizontal,
  released under g = 9.81 m/s^2 for 1 s with Exudyn's generalised-alpha (index 3,
  fixed step h, spectral radius rho_inf, Exudyn's default modified Newton).

Each returns a plain dict; ``cpu_s`` is ``time.process_time`` around the solve call
only.  The energies of the pendulum are evaluated afterwards from the sampled nodal
coordinates with the element's own definitions (axial strain |r'| - 1 on 5 Gauss
points, material curvature (r' x r'')/|r'|^2 on 3, exact mass and gravity), so the
deviation is that of the discrete energy Exudyn integrates.

``python -m benchmarks.peers_exudyn cantilever N`` runs one whole process (imports
included) and prints the result as JSON.
"""
from __future__ import annotations

import json
import sys
import time

import numpy as np

import exudyn as exu
from exudyn import itemInterface as ei

from benchmarks.peers_cable import CableEnergy

L, B, H = 2.0, 0.1, 0.1
CANTILEVER = {"E": 2.07e11, "F": -5e8 * H**3}
PENDULUM = {"E": 2.07e7, "rho": 7850.0, "g": 9.81, "t_end": 1.0, "output_dt": 0.01}


def static_rel_tol(n: int) -> float:
    """Exudyn's static Newton relative tolerance: the tightest it reaches at n elements."""
    if n >= 1024:
        return 1e-5
    if n >= 512:
        return 1e-6
    if n >= 256:
        return 1e-7
    return 1e-8


def _chain(mbs, n: int, E: float, rho_a: float, fixed: tuple):
    """n straight Cable2D elements along +x; coordinate constraints on node 0's
    coordinates ``fixed`` (0: x, 1: y, 2: r'_x, 3: r'_y).  Returns (nodes, objects)."""
    le = L / n
    nodes = [mbs.AddNode(ei.NodePoint2DSlope1(referenceCoordinates=[i * le, 0.0, 1.0, 0.0]))
             for i in range(n + 1)]
    objects = [mbs.AddObject(ei.Cable2D(
        length=le, massPerLength=rho_a, bendingStiffness=E * B * H**3 / 12,
        axialStiffness=E * B * H, nodeNumbers=[nodes[i], nodes[i + 1]]))
        for i in range(n)]
    ground = mbs.AddMarker(ei.MarkerNodeCoordinate(
        nodeNumber=mbs.AddNode(ei.NodePointGround()), coordinate=0))
    for k in fixed:
        mk = mbs.AddMarker(ei.MarkerNodeCoordinate(nodeNumber=nodes[0], coordinate=k))
        mbs.AddObject(ei.CoordinateConstraint(markerNumbers=[ground, mk]))
    return nodes, objects


def _settings(sparse: bool = True):
    s = exu.SimulationSettings()
    s.solution.file.write = False
    s.solution.sensors.writePeriod = PENDULUM["output_dt"]
    s.solution.solverInformationFileName = ""
    s.show.statistics = False
    s.show.computationTime = False
    s.linearSolver.solverType = (exu.LinearSolverType.EigenSparse if sparse
                                 else exu.LinearSolverType.EXUdense)
    return s


def _stats(solver, newton) -> dict:
    """Run statistics and the Newton settings in force."""
    it = solver.it
    return {"newton_iterations": int(it.newtonStepsCount),
            "jacobians": int(it.newtonJacobiCount), "steps": int(it.currentStepIndex) - 1,
            "modified_newton": bool(newton.useModifiedNewton),
            "rel_tol": newton.relativeTolerance, "abs_tol": newton.absoluteTolerance}


def cantilever(n: int, rel_tol: float | None = None, load_steps: int = 10) -> dict:
    """Static Model 1 cantilever with n elements; tip position and run statistics."""
    rel_tol = static_rel_tol(n) if rel_tol is None else rel_tol
    SC = exu.SystemContainer()
    mbs = SC.AddSystem()
    nodes, _ = _chain(mbs, n, CANTILEVER["E"], 1.0, fixed=(0, 1, 3))
    tip = mbs.AddMarker(ei.MarkerNodePosition(nodeNumber=nodes[-1]))
    mbs.AddLoad(ei.Force(markerNumber=tip, loadVector=[0.0, CANTILEVER["F"], 0.0]))
    mbs.Assemble()
    s = _settings()
    s.staticSolver.verboseMode = 0
    s.staticSolver.numberOfLoadSteps = load_steps
    s.staticSolver.newton.relativeTolerance = rel_tol
    solver = exu.MainSolverStatic()
    t0 = time.process_time()
    ok = solver.SolveSystem(mbs, s)
    cpu = time.process_time() - t0
    x, y = mbs.GetNodeOutput(nodes[-1], exu.OutputVariableType.Position)[:2]
    return {"cpu_s": cpu, "converged": bool(ok), "tip_x": float(x), "tip_y": float(y),
            "load_steps": load_steps, **_stats(solver, s.staticSolver.newton)}


def pendulum(n: int, h: float = 1e-3, spectral_radius: float = 0.9) -> dict:
    """Flexible pendulum, n elements, generalised-alpha with fixed step h for 1 s."""
    p = PENDULUM
    rho_a = p["rho"] * B * H
    SC = exu.SystemContainer()
    mbs = SC.AddSystem()
    nodes, objects = _chain(mbs, n, p["E"], rho_a, fixed=(0, 1))
    for o in objects:
        mbs.AddLoad(ei.LoadMassProportional(
            markerNumber=mbs.AddMarker(ei.MarkerBodyMass(bodyNumber=o)),
            loadVector=[0.0, -p["g"], 0.0]))
    sensors = [[mbs.AddSensor(ei.SensorNode(nodeNumber=nd, storeInternal=True, writeToFile=False,
                                            outputVariableType=v))
                for v in (exu.OutputVariableType.Coordinates, exu.OutputVariableType.Coordinates_t)]
               for nd in nodes]
    mbs.Assemble()
    s = _settings()
    ti = s.timeIntegration
    ti.endTime, ti.numberOfSteps = p["t_end"], int(round(p["t_end"] / h))
    ti.verboseMode = 0
    ti.generalizedAlpha.spectralRadius = spectral_radius
    solver = exu.MainSolverImplicitSecondOrder()
    t0 = time.process_time()
    ok = solver.SolveSystem(mbs, s)
    cpu = time.process_time() - t0
    q, v = _sampled(mbs, nodes, sensors)
    energy = CableEnergy(L / n, p["E"] * B * H, p["E"] * B * H**3 / 12, rho_a, p["g"]).total(q, v)
    return {"cpu_s": cpu, "converged": bool(ok), "tip_x": q[:, -1, 0].tolist(),
            "tip_y": q[:, -1, 1].tolist(), "energy_max_deviation_J": float(
                np.max(np.abs(energy - energy[0]))), "spectral_radius": spectral_radius,
            "h": h, **_stats(solver, ti.newton)}


def _sampled(mbs, nodes, sensors):
    """Total nodal coordinates and velocities at every sample: (samples, nodes, 4) each."""
    ref = np.array([mbs.GetNodeParameter(nd, "referenceCoordinates") for nd in nodes])
    q = np.stack([mbs.GetSensorStoredData(s)[:, 1:] for s, _ in sensors], axis=1) + ref
    v = np.stack([mbs.GetSensorStoredData(s)[:, 1:] for _, s in sensors], axis=1)
    return q, v


def main(argv=None) -> int:
    """Whole process: ``python -m benchmarks.peers_exudyn cantilever N``."""
    argv = sys.argv[1:] if argv is None else argv
    print(json.dumps(cantilever(int(argv[1]))))
    return 0


if __name__ == "__main__":
    sys.exit(main())
