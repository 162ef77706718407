"""The shared 3D cases in Exudyn: ``ObjectANCFBeam`` and ``ObjectANCFThinPlate``.

    python -m benchmarks.peers_3d_exudyn CASE N [ANGLE_DEG]   (one run, JSON on stdout)

* ``princeton`` / ``cantilever3d``: N ``ObjectANCFBeam`` elements (nodes
  ``NodePointSlope23``: r, r_y, r_z, the coordinates of our ``linear3d``) along +x, every
  coordinate of node 0 fixed (our clamp), the tip force F (0, cos a, sin a) on the tip
  position (a = ANGLE_DEG from -y towards -z for F < 0, as our scenes), section stiffness
  diag(E A, ks G A, ks G A, ks G (I_y + I_z), E I_y, E I_z) with our scene's ks (the
  shear and torsional stiffness of ``linear3d``), cross-section penalty factor 1
  (default); static solver, 10 load steps, full Newton, EigenSparse.
* ``plate-static``: N x N ``ObjectANCFThinPlate`` elements (``NodePointSlope12``: r, r_x,
  r_y, the coordinates of our ``plate36``) over a x a, plane-stress membrane and
  Kirchhoff bending coefficients, 4 x 4 Gauss points (default); the simply supported
  edges of our ``plate-square`` as ``CoordinateConstraint`` s (in-plane coordinates of
  every node, w on the boundary, the slope along the edge); the pressure as its
  consistent generalised forces (:func:`pressure_weights`, ``LoadCoordinate``); static
  solver (nonlinear), 1 load step.
* ``plate-modes``: the same plate with density rho, its lowest :data:`MODE_COUNT`
  frequencies about the reference by ``ComputeODE2Eigenvalues`` with the fixed
  coordinates erased (``constrainedCoordinates``) and its sparse solver.

``cpu_s``: ``time.process_time`` around the solve call only; ``cpu_build_s`` the model
build (nodes, objects, ``Assemble``) before it.
"""
from __future__ import annotations

import json
import math
import os
import sys
import time

import numpy as np

#: our scenes' defaults (ancf/scenes/princeton_beam.py, beam3d_cantilever.py,
#: plate_square.py); the race checks them against the scenes' resolved parameters
PRINCETON = {"L": 0.508, "h": 12.3777e-3, "b": 3.2024e-3, "E": 71.7e9, "nu": 0.31,
             "F": -8.896}
CANTILEVER3D = {"L": 2.0, "h": 0.1, "b": 0.1, "E": 2.07e11, "nu": 0.3, "F": -5e8 * 0.1**3,
                "ks": 5.0 / 6.0}
PLATE = {"a": 1.0, "h": 0.01, "E": 2.1e11, "nu": 0.3, "p": 1e3, "rho": 7850.0}
MODE_COUNT = 6
LOAD_STEPS = 10
REL_TOL = 1e-8


def torsion_ks(h: float, b: float) -> float:
    """Our Princeton default ks = J / (I_y + I_z) (ancf.models.beam3d.torsion_factor)."""
    from ancf.models.beam3d import torsion_factor
    return torsion_factor(h, b)


def pressure_weights(a: float, b: float) -> np.ndarray:
    """Consistent forces of a unit pressure on one a x b element of the incomplete
    cubic, per node (counter-clockwise from (0, 0)) and slot (r, r_x, r_y): ``int S dA``
    = a b / 4 on r, +-a^2 b / 24 on r_x, +-a b^2 / 24 on r_y (the Hermite cubic's
    integrals L / 2 and +-L^2 / 12 times the linear one's b / 2).  Shape (4, 3), m^2/m^3."""
    sx, sy = np.array([1, -1, -1, 1]), np.array([1, 1, -1, -1])
    return np.column_stack([np.full(4, a * b / 4), sx * a * a * b / 24, sy * a * b * b / 24])


def _settings(exu, load_steps: int):
    s = exu.SimulationSettings()
    s.solution.file.write = False
    s.solution.solverInformationFileName = ""
    s.show.statistics = False
    s.show.computationTime = False
    s.linearSolver.solverType = exu.LinearSolverType.EigenSparse
    s.staticSolver.verboseMode = 0
    s.staticSolver.numberOfLoadSteps = load_steps
    s.staticSolver.newton.relativeTolerance = REL_TOL
    return s


def _stats(solver, newton) -> dict:
    it = solver.it
    return {"newton_iterations": int(it.newtonStepsCount),
            "jacobians": int(it.newtonJacobiCount),
            "modified_newton": bool(newton.useModifiedNewton),
            "rel_tol": newton.relativeTolerance, "abs_tol": newton.absoluteTolerance}


def _static(exu, mbs, s) -> tuple:
    solver = exu.MainSolverStatic()
    t0 = time.process_time()
    ok = solver.SolveSystem(mbs, s)
    return bool(ok), time.process_time() - t0, _stats(solver, s.staticSolver.newton)


def beam(n: int, angle_deg: float, P: dict, ks: float) -> dict:
    """A cantilever of n ``ObjectANCFBeam`` elements with a tip force; tip position."""
    import exudyn as exu
    from exudyn import itemInterface as ei
    t0 = time.process_time()
    E, nu, h, b, L = P["E"], P["nu"], P["h"], P["b"], P["L"]
    G, A, Iy, Iz = E / (2 * (1 + nu)), h * b, h * b**3 / 12, b * h**3 / 12
    sec = exu.BeamSection()
    sec.stiffnessMatrix = np.diag([E * A, ks * G * A, ks * G * A, ks * G * (Iy + Iz),
                                   E * Iy, E * Iz])
    sec.massPerLength = 1.0
    SC = exu.SystemContainer()
    mbs = SC.AddSystem()
    nodes = [mbs.AddNode(ei.NodePointSlope23(referenceCoordinates=[i * L / n, 0, 0,
                                                                   0, 1, 0, 0, 0, 1]))
             for i in range(n + 1)]
    for i in range(n):
        mbs.AddObject(ei.ObjectANCFBeam(nodeNumbers=[nodes[i], nodes[i + 1]],
                                        length=L / n, sectionData=sec))
    _fix(mbs, ei, nodes[0], range(9))
    a = math.radians(angle_deg)
    tip = mbs.AddMarker(ei.MarkerNodePosition(nodeNumber=nodes[-1]))
    mbs.AddLoad(ei.Force(markerNumber=tip, loadVector=[0.0, P["F"] * math.cos(a),
                                                        P["F"] * math.sin(a)]))
    mbs.Assemble()
    build = time.process_time() - t0
    ok, cpu, stats = _static(exu, mbs, _settings(exu, LOAD_STEPS))
    x, y, z = mbs.GetNodeOutput(nodes[-1], exu.OutputVariableType.Position)
    return {"cpu_s": cpu, "cpu_build_s": build, "converged": ok, "tip_x": float(x),
            "tip_y": float(y), "tip_z": float(z), "ks": ks, "load_steps": LOAD_STEPS, **stats}


def _fix(mbs, ei, node: int, coords) -> None:
    """CoordinateConstraints holding node's ``coords`` at their reference values."""
    ground = mbs.AddMarker(ei.MarkerNodeCoordinate(
        nodeNumber=mbs.AddNode(ei.NodePointGround()), coordinate=0))
    for k in coords:
        mk = mbs.AddMarker(ei.MarkerNodeCoordinate(nodeNumber=node, coordinate=k))
        mbs.AddObject(ei.CoordinateConstraint(markerNumbers=[ground, mk]))


def supported(i: int, j: int, n: int) -> list:
    """Fixed NodePointSlope12 coordinates (r 0-2, r_x 3-5, r_y 6-8) of node (i, j) of the
    simply supported n x n plate: in-plane ones, w on the boundary, the slope along the
    edge (r_y,z on x = 0, a; r_x,z on y = 0, a)."""
    on_x, on_y = i in (0, n), j in (0, n)
    return sorted({0, 1, 3, 4, 6, 7} | ({2} if on_x or on_y else set())
                  | ({8} if on_x else set()) | ({5} if on_y else set()))


def plate(n: int, rho: float = 0.0, constrain: bool = True):
    """(SystemContainer, mbs, nodes) of the n x n plate (pressure loads, constraints)."""
    import exudyn as exu
    from exudyn import itemInterface as ei
    P = PLATE
    le = P["a"] / n
    SC = exu.SystemContainer()
    mbs = SC.AddSystem()
    nodes = [[mbs.AddNode(ei.NodePointSlope12(referenceCoordinates=[i * le, j * le, 0,
                                                                    1, 0, 0, 0, 1, 0]))
              for j in range(n + 1)] for i in range(n + 1)]
    c = np.array([[1, P["nu"], 0], [P["nu"], 1, 0], [0, 0, (1 - P["nu"]) / 2]])
    c /= 1 - P["nu"] ** 2
    strain, curv = exu.Matrix3DList(), exu.Matrix3DList()
    strain.Append(P["E"] * P["h"] * c)
    curv.Append(P["E"] * P["h"] ** 3 / 12 * c)
    f = np.zeros((n + 1, n + 1, 3))
    corners = ((0, 0), (1, 0), (1, 1), (0, 1))
    for i in range(n):
        for j in range(n):
            mbs.AddObject(ei.ObjectANCFThinPlate(
                nodeNumbers=[nodes[i + di][j + dj] for di, dj in corners], thickness=P["h"],
                strainCoefficients=strain, curvatureCoefficients=curv, density=rho))
            for (di, dj), w in zip(corners, pressure_weights(le, le)):
                f[i + di, j + dj] += P["p"] * w
    if constrain:
        for i in range(n + 1):
            for j in range(n + 1):
                _fix(mbs, ei, nodes[i][j], supported(i, j, n))
                for slot, k in ((0, 2), (1, 5), (2, 8)):
                    mk = mbs.AddMarker(ei.MarkerNodeCoordinate(nodeNumber=nodes[i][j],
                                                               coordinate=k))
                    mbs.AddLoad(ei.LoadCoordinate(markerNumber=mk, load=f[i, j, slot]))
    mbs.Assemble()
    return SC, mbs, nodes


def plate_static(n: int) -> dict:
    """Centre deflection (m, along the pressure) of the simply supported plate."""
    import exudyn as exu
    t0 = time.process_time()
    SC, mbs, nodes = plate(n)
    build = time.process_time() - t0
    ok, cpu, stats = _static(exu, mbs, _settings(exu, 1))
    w = mbs.GetNodeOutput(nodes[n // 2][n // 2], exu.OutputVariableType.Displacement)[2]
    return {"cpu_s": cpu, "cpu_build_s": build, "converged": ok,
            "center_deflection_m": float(w), "load_steps": 1, **stats}


def plate_modes(n: int, count: int = MODE_COUNT) -> dict:
    """Lowest ``count`` frequencies (Hz) of the simply supported plate about the reference."""
    import exudyn as exu
    t0 = time.process_time()
    SC, mbs, nodes = plate(n, rho=PLATE["rho"], constrain=False)
    fixed = [mbs.GetNodeODE2Index(nodes[i][j]) + k for i in range(n + 1)
             for j in range(n + 1) for k in supported(i, j, n)]
    build = time.process_time() - t0
    t1 = time.process_time()
    hz, _ = mbs.ComputeODE2Eigenvalues(useSparseSolver=True, numberOfEigenvalues=count,
                                       constrainedCoordinates=fixed, convert2Frequencies=True)
    cpu = time.process_time() - t1
    return {"cpu_s": cpu, "cpu_build_s": build, "converged": True,
            "frequencies_hz": [float(x) for x in np.sort(hz)[:count]],
            "reduced_size": mbs.systemData.ODE2Size() - len(fixed)}


def run(case: str, n: int, angle_deg: float = 0.0) -> dict:
    """One case (see the module docstring)."""
    if case == "princeton":
        return beam(n, angle_deg, PRINCETON, torsion_ks(PRINCETON["h"], PRINCETON["b"]))
    if case == "cantilever3d":
        return beam(n, angle_deg, CANTILEVER3D, CANTILEVER3D["ks"])
    if case == "plate-static":
        return plate_static(n)
    if case == "plate-modes":
        return plate_modes(n)
    raise ValueError(f"case = {case!r}; allowed: princeton, cantilever3d, plate-static, "
                     "plate-modes")


def main(argv=None) -> int:
    argv = sys.argv[1:] if argv is None else argv
    out = os.fdopen(os.dup(1), "w")
    os.dup2(2, 1)                    # whatever Exudyn prints goes to stderr
    sys.stdout = sys.stderr
    angle = float(argv[2]) if len(argv) > 2 else 0.0
    res = run(argv[0], int(argv[1]), angle)
    import exudyn
    out.write(json.dumps(res | {"exudyn": exudyn.__version__}) + "\n")
    out.flush()
    return 0


if __name__ == "__main__":
    sys.exit(main())
