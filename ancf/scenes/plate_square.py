"""Simply supported square plate under uniform pressure (issue 13 item 4; the thin
plate of thesis 4.3 against Navier's series).

``n_elements`` x ``n_elements`` ``plate36`` elements (bending on, ``ng`` x ``ng`` Gauss
points) over a x a; simply supported: w = 0 and the slope along the edge vanish on the
boundary, the in-plane coordinates are fixed.  ``element`` = ``ancf3423``, ``ancf3443`` or
``ancf3833`` (Chrono's shells): the registry's class on
:func:`ancf.models.chrono_shell.simply_supported_square`'s mesh, w = 0 on the edges
(:meth:`~ancf.models.chrono_shell.Plate.simply_supported`), in-plane rigid motion removed.
Linear (small-deflection) static solve at the flat reference with a sparse direct solver
(``ancf.models.plate``): valid while the centre deflection is small against the
thickness (h/47 at the defaults).
``center_deflection_m`` is signed, positive along the pressure; it is held against
Navier's double series (``ancf analytic navier-plate``, summed as Lévy's single series;
Kirchhoff's rigidity D = E h^3 / (12 (1 - nu^2))).  Inputs whose rigidity, a^4 or
deflection scale p a^4 / D leave double precision are refused, naming the field.

``ancf modes plate-square`` vibrates the same model (density ``rho``, default steel);
about the equilibrium it is Newton's nonlinear equilibrium under the pressure (the
linear solve's deflection is small against h, so the two differ little), refused and
warned as the run (:func:`equilibrium`: round-off, the thin-plate range).  Its
``supports`` (``ancf modes`` only) are ``simple`` (the static run's) or ``free``: no
coordinate fixed, the free-free plate of Exudyn's ``TestModels/ANCFThinPlateTests.py``,
whose six rigid motions are its zero-frequency modes; it has no equilibrium under a
pressure, so ``--about equilibrium`` finds none (exit 3, saying so).  With a shell the
modes are those of its registry class on the same mesh as its run (its mass at ``rho``),
sampled at the shell's nodes (their positions r); the result carries no plate36 mesh.
"""
from __future__ import annotations

import math

import numpy as np

from analytic import navier_plate
from ancf.core.constraints import Elimination
from ancf.elements.registry import ELEMENTS
from ancf.models import chrono_shell
from ancf.models.plate import grid_points, simply_supported, simply_supported_model
from ancf.common.params import InputError, Param
from ancf.scenes import sense
from ancf.scenes.plate_strip import check_cost
from ancf.scenes.base import INT, STEEL_DENSITY, Scene, SceneResult, field, nullable

SUPPORTS = Param("supports", "simple", str, doc="edge supports (ancf modes only): 'simple' "
                 "(the static run's) or 'free' (no coordinate fixed: six rigid-body modes)",
                 choices=("simple", "free"))


#: the scene's elements: the registry's plate (plate36, the default) and its shells
CHOICES = tuple(n for n, t in ELEMENTS.items() if t.kind == "plate") + tuple(
    n for n, t in ELEMENTS.items() if t.kind == "shell")


def params() -> tuple:
    return (
        Param("element", "plate36", str, doc="plate element: plate36, or Chrono's shells "
              "ancf3423 (ANS/EAS), ancf3443, ancf3833 (their own rules, ng ignored)",
              choices=CHOICES),
        Param("a", 1.0, float, "m", "side of the square", lo=0, lo_open=True),
        Param("h", 0.01, float, "m", "thickness", lo=0, lo_open=True),
        Param("E", 2.1e11, float, "Pa", "Young's modulus", lo=0, lo_open=True),
        Param("nu", 0.3, float, "-", "Poisson's ratio", lo=0, hi=0.5, hi_open=True),
        Param("p", 1e3, float, "Pa", "uniform pressure along +z"),
        Param("n_elements", 8, int, doc="elements per side (even: a node at the centre)",
              lo=2, hi=128),
        Param("ng", 4, int, doc="Gauss points per direction (4 integrates the linearised "
                                "stiffness exactly)", lo=1, hi=8),
    )


def check(p: dict) -> None:
    try:  # derived quantities in double precision (the Navier reference and the stiffness)
        navier_plate.check_magnitudes(p["a"], p["a"], p["h"], p["E"], p["nu"], p["p"])
    except ValueError as exc:
        raise InputError(str(exc)) from None
    if p["n_elements"] % 2:
        raise InputError(f"n_elements = {p['n_elements']} is out of range; allowed: an even "
                         "integer in [2, 128] (the centre must be a node)")


def _unsolvable(p: dict) -> SceneResult | None:
    """The failed result of a plate no solve can hold (None: it can be solved): a bending
    rigidity outside double precision, or lost in round-off (:func:`sense.near_singular`)."""
    D = navier_plate.rigidity(p["E"], p["nu"], p["h"])
    if not (math.isfinite(D) and D > 0):
        return SceneResult(False, f"No solution: the bending rigidity E h^3/(12 (1 - nu^2)) = "
                                  f"{D:g} N m is not a positive finite number in double precision",
                           _failed())
    singular = sense.near_singular(p["h"], p["a"] / p["n_elements"])
    return SceneResult(False, singular, _failed()) if singular else None


def run(p: dict) -> SceneResult:
    failed = _unsolvable(p)
    if failed:
        return failed
    geo = dict(h=p["h"], E=p["E"], nu=p["nu"], p=p["p"])
    w, extra = _centre_deflection(p, geo)
    w_ref, terms = navier_plate.centre_deflection(p["a"], p["a"], **geo)
    rel = (w - w_ref) / w_ref if w_ref else 0.0
    return SceneResult(True, "linear static solve", {
        "center_deflection_m": w, "navier_center_deflection_m": w_ref, "navier_terms": terms,
        "relative_error": rel,
        "tangent_evaluations": 1, "factorizations": 1}, extra=extra)


def _centre_deflection(p: dict, geo: dict) -> tuple:
    """(w at the centre node in m, the result's extra) of the linear solve: plate36's
    (``ancf.models.plate``) or a shell's (:func:`ancf.models.chrono_shell.simply_supported_square`,
    the registry's class on Chrono's plate mesh)."""
    n = p["n_elements"]
    if p["element"] == "plate36":
        m, u = simply_supported(n, p["a"], p["a"], ng=p["ng"], **geo)
        w = float(u[m.dof(m.node(n // 2, n // 2), "r", 2)])
        return w, {"mesh": m, "q0": m.reference(), "q": m.reference() + u}
    plate, u = chrono_shell.simply_supported_square(ELEMENTS[p["element"]].cls, n, p["a"],
                                                    p["h"], p["E"], p["nu"], p["p"])
    return float(u[plate.coordinate(chrono_shell.centre_node(plate), 0, 2)]), {}


def _failed() -> dict:
    """The results of a run that solved nothing."""
    return dict.fromkeys(("center_deflection_m", "navier_center_deflection_m",
                          "relative_error")) | {
        "navier_terms": 0, "tangent_evaluations": 0, "factorizations": 0}


def warn(p: dict, res: SceneResult) -> list:
    """A centre deflection beyond the linear thin-plate range (:func:`ancf.scenes.sense.thin_plate`)
    and a plate too thick for Kirchhoff's theory (:func:`ancf.scenes.sense.thick_plate`,
    the element's and its Navier reference's)."""
    w = res.results.get("center_deflection_m")
    if w is None:
        return []
    share = sense.kirchhoff_shear_share(p["a"], p["a"], p["h"], p["nu"])
    return sense.thin_plate(w, p["h"]) + sense.thick_plate(share, p["h"], p["a"], sense.SHEAR_SHARE)


def _model(p: dict):
    """(mesh, q0, assembly, elimination, load) of the nonlinear plate of ``ancf modes``
    (refused before it is built when it would not fit in memory); a shell's mesh is
    None (:func:`_shell_model`)."""
    if p["element"] != "plate36":
        return _shell_model(p)
    check_cost(p["n_elements"], p["n_elements"])
    m, q0, asm, elim, load = simply_supported_model(p["n_elements"], p["a"], p["a"], p["h"],
                                                    p["E"], p["nu"], p["p"], p["ng"], p["rho"])
    return m, q0, asm, (elim if p["supports"] == "simple" else Elimination(m.n_dofs)), load


def _shell_model(p: dict):
    """(None, q0, assembly, elimination, load) of a Chrono shell's plate: the registry's
    class on :class:`ancf.models.chrono_shell.Plate`'s n x n mesh (q0 its reference, m),
    density ``rho``; ``simple``: w = 0 on the four edges and the in-plane rigid motions
    fixed, as the run's; the pressure p (Pa) along +z as a dead load (N)."""
    from ancf.core.assembly import Assembly, ElementGroup  # not needed by ancf run
    n, a, cls = p["n_elements"], p["a"], ELEMENTS[p["element"]].cls
    plate = _shell_plate(p)
    q0 = plate.reference()
    el = cls(np.full(n * n, a / n), np.full(n * n, a / n), p["h"], p["E"], p["nu"],
             rho=p["rho"], e0=q0[plate.dofs])
    elim = Elimination(plate.ndof)
    if p["supports"] == "simple":
        fixed = [plate.simply_supported(e) for e in chrono_shell.EDGES] + [plate.in_plane_rigid()]
        for d in np.unique(np.concatenate([np.ravel(f) for f in fixed])):
            elim.fix(int(d), q0[d])
    return (None, q0, Assembly(plate.ndof, [ElementGroup(el, plate.dofs)]), elim,
            chrono_shell.pressure(plate, p["p"]))


def _shell_plate(p: dict) -> chrono_shell.Plate:
    """The n x n plate of the shell ``element`` (m, Pa, kg/m^3 as p)."""
    n, a = p["n_elements"], p["a"]
    return chrono_shell.Plate(ELEMENTS[p["element"]].cls.module.__name__[-4:], n, n, a, a,
                              p["h"], p["E"], p["nu"], rho=p["rho"])


def _centre_dof(p: dict, m) -> int:
    """The index of the centre node's z-position: plate36's (mesh m) or a shell's."""
    if m is not None:
        return m.dof(m.node(p["n_elements"] // 2, p["n_elements"] // 2), "r", 2)
    plate = _shell_plate(p)
    return int(plate.coordinate(chrono_shell.centre_node(plate), 0, 2))


def _node_positions(ncoord: int):
    """q -> (nodes, 3): the r slot of every node of a shell plate (``ancf modes``'s sample
    points, m; its coordinates ``ncoord`` per node, r first)."""
    return lambda q: np.asarray(q).reshape(-1, ncoord)[:, :3]


def modal(p: dict):
    from ancf.scenes import beam_static as bs  # its modal model; not needed by ancf run
    m, q0, asm, elim, load = _model(p)
    if m is None:
        ncoord = asm.groups[0].element.ndof // asm.groups[0].element.module.NNODE
        return bs.modal(p, m, q0, asm, elim, load, _node_positions(ncoord), "shell nodes")
    return bs.modal(p, m, q0, asm, elim, load, grid_points(m), "mid-surface grid")


def equilibrium(p: dict) -> SceneResult:
    """``ancf modes --about equilibrium``: Newton's nonlinear equilibrium under the
    pressure (default Newton options, the stability check), refused as the run refuses a
    plate (:func:`_unsolvable`), its ``center_deflection_m`` judged by :func:`warn` as the
    run's; a free plate has none."""
    from ancf.scenes import beam_static as bs  # not needed by ancf run
    failed = _unsolvable(p)
    if failed or p["supports"] == "free":
        return failed or SceneResult(
            False, "a free plate has no static equilibrium under a pressure", _failed())
    m, q0, asm, elim, load = _model(p)
    c = _centre_dof(p, m)
    return bs.solve(p, m, q0, asm, elim, load,
                    lambda q: {"center_deflection_m": float(q[c] - q0[c])})


PLATE_KNOBS = ("element", "n_elements", "ng")
#: the recommender's shells: Chrono's (ancf3423, ancf3443, ancf3833) on meshes up to 16 x 16
#: (the 3833 at 16 x 16: about 7400 coordinates)
SHELL_GRID = {"element": [n for n in CHOICES if ELEMENTS[n].kind == "shell"],
              "n_elements": [2, 4, 8, 16]}


def _navier(p):
    return {"center_deflection_m": navier_plate.centre_deflection(
        p["a"], p["a"], p["h"], p["E"], p["nu"], p["p"])[0]}


def _navier_modes(p):
    from analytic import plate_modes
    return {"frequencies_hz": [float(x) for x in plate_modes.navier_frequencies(
        p["a"], p["a"], p["h"], p["E"], p["nu"], p["rho"], int(p["count"]))[0]]}


RESULTS = {
    "center_deflection_m": nullable("centre deflection along the pressure (linear solve), m"),
    "navier_center_deflection_m": nullable("Navier's series at the same parameters, m"),
    "navier_terms": field(INT, "largest odd index of Navier's series summed"),
    "relative_error": nullable("center_deflection_m / navier_center_deflection_m - 1"),
    "tangent_evaluations": field(INT, "tangent-stiffness evaluations (1: a linear solve)"),
    "factorizations": field(INT, "factorisations of the tangent (1)")}


def study():
    """What sweeps measure this scene against: its references, errors and grids."""
    from ancf.scenes.spec import Reference, SceneSpec, relative
    refs = {"navier": Reference(
        "navier", "analytic",
        "Navier's double series of the simply supported Kirchhoff plate (`ancf analytic "
        "navier-plate`, truncation below 1e-10); error = |w − w_ref| / |w_ref| of the centre "
        "deflection", _navier, relative("center_deflection_m"),
        measure="relative centre-deflection error")}
    grid = ({"n_elements": [2, 4, 8, 16, 32], "ng": [4]},)
    return SceneSpec("plate-square", PLATE_KNOBS, frozenset({"bending", "3D"}), refs, "navier",
                     report_grids=grid + (SHELL_GRID,), recommend_grids=grid + (SHELL_GRID,),
                     provides=frozenset({"bending", "3D"}),
                     notes="Simply supported square plate (linear) against Navier's series.")


def frequency_study():
    """What ``--quantity frequency`` measures: the lowest frequencies against Navier's."""
    from ancf.scenes.spec import Reference, SceneSpec, FREQUENCY_ERROR, frequency_error
    name = "navier-frequencies"
    refs = {name: Reference(
        name, "analytic", "Navier's frequencies of the simply supported Kirchhoff plate "
        f"(`analytic/plate_modes.py`); {FREQUENCY_ERROR}", _navier_modes, frequency_error)}
    grid = ({"n_elements": [2, 4, 6, 8, 12, 16, 24], "ng": [3, 4]},)
    return SceneSpec("plate-square", PLATE_KNOBS, frozenset({"bending", "3D"}), refs, name,
                     report_grids=grid + (SHELL_GRID,), recommend_grids=grid + (SHELL_GRID,),
                     provides=frozenset({"bending", "3D"}), quantity="frequency",
                     notes="The simply supported square plate's lowest frequencies against "
                           "Navier.")


#: the scene's place in the scene list (ancf.scenes.MODULES, ancf scenes, reports/schemas.md)
ORDER = 80
#: its place among the scenes with a frequency reference (FREQUENCY_SPECS)
FREQUENCY_ORDER = 30
SCENE = Scene(
    "plate-square",
    "Simply supported square thin plate under uniform pressure, linear, against Navier.",
    params(), run, check, warn=warn, modal=modal,
    modal_params=(STEEL_DENSITY, SUPPORTS), equilibrium=equilibrium,
    results=RESULTS, study=study, frequency_study=frequency_study)
