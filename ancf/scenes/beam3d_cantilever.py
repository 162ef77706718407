"""The cantilever (scene ``cantilever``) with a spatial beam element (issue 13 item 4).

The 2D cantilever's parameters (``L``, ``h`` along y, ``b`` along z, ``E``, ``nu``, ``ks``,
``F``, ``n_elements``, the Newton knobs) and ``load_angle_deg``: the tip force's angle in
the cross-section plane, from -y towards -z for a negative ``F`` (force F (0, cos a,
sin a) on the tip position).  0 is the 2D case: the beam stays in the x-y plane and
reproduces the 2D scene (element ``linear``) to round-off; 90 bends it about y.
``Mx``, ``My``, ``Mz``: tip moments about the fixed global axes, on the section slopes
(:class:`ancf.core.forces.SectionMoment`).
Clamp: every slot of the first node but r_x (position and section orientation), all
three components.  ``element``: the 3D elements of :data:`ancf.models.beam3d.BUILDERS` (the
registry's two-node 3D beams: linear3d, belt3d, ancf3243) and its three-node 3D beams
(ancf3333, on :func:`ancf.models.chrono_beam.quadratic_model`'s mesh of 2n segments);
Chrono's beams take ``ks`` for both shear corrections and ignore ``integration``.
Results ``tip_x``, ``tip_y``, ``tip_z``: the tip node's position.
"""
from __future__ import annotations

import math
from dataclasses import replace

import numpy as np

from ancf.scenes import accuracy
from ancf.elements.registry import ELEMENTS
from ancf.models import beam3d, chrono_beam
from ancf.scenes import beam_static as bs
from ancf.scenes import sense
from ancf.common.params import InputError, Param
from ancf.scenes.base import STATIC_RESULTS, STEEL_DENSITY, ReferenceFailed, Scene, nullable
from ancf.scenes.cantilever import cantilever_params, reissner_tip


#: the registry's three-node 3D beams (ancf3333)
QUADRATIC = tuple(n for n, t in ELEMENTS.items() if t.kind == "beam" and t.dim == 3
                  and t.nodes == 3)
#: the scene's elements
CHOICES = tuple(beam3d.BUILDERS) + QUADRATIC
#: those of them that are Chrono's (ancf3243, ancf3333)
CHRONO = tuple(n for n in CHOICES if ELEMENTS[n].path.startswith("ancf.elements.chrono_element"))


def params(presets: dict | None = None) -> tuple:
    """The scene's parameters; ``presets`` {name: (default, doc)} replaces the default and
    the description of some (the benchmark scenes built on this one)."""
    out = []
    for q in cantilever_params():
        if q.name == "element":
            q = Param("element", "linear3d", str, doc="3D element type",
                      choices=CHOICES)
        elif q.name == "integration":
            q = Param("integration", "thesis", str,
                      doc="integration scheme (linear3d: thesis, exact, report-selective, "
                          "report-fix) or a spec like 'normal=2x2,shear=1x1'; belt3d has one "
                          "rule (elastic_points along the axis, the section in closed form) "
                          "and ignores it")
        elif q.name == "clamp_x_slope":
            continue
        out.append(q)
    out += [
        Param("load_angle_deg", 0.0, float, "deg",
              "angle of the tip force in the section plane, from -y towards -z "
              "(0 = the 2D cantilever)", lo=-360, hi=360),
        Param("alpha1", 1.0, float, "-", "belt3d: axial stiffness parameter (Eq. 4.40)", lo=0,
              lo_open=True, hi=10),
        Param("alpha2", 1.0, float, "-", "belt3d: bending and shear stiffness parameter "
              "(Eqs 4.40-4.42)", lo=0, lo_open=True, hi=10),
        Param("elastic_points", 5, int, doc="belt3d: Gauss points along the axis", lo=1, hi=12)]
    out += [Param(f"M{c}", 0.0, float, "N m", f"tip moment about the global {c} axis (fixed "
                  f"direction{', torsion' if c == 'x' else ''}; acts on the section slopes "
                  "r_y, r_z)") for c in "xyz"]
    presets = presets or {}
    return tuple(replace(q, default=presets[q.name][0], doc=presets[q.name][1])
                 if q.name in presets else q for q in out)


def check(p: dict) -> None:
    cls = ELEMENTS[p["element"]].build(p)[0]
    if not cls.schemes:  # one rule (belt3d)
        return
    try:
        cls.scheme_terms(p["integration"], np.eye(3), np.eye(3))
    except (ValueError, AttributeError) as exc:
        raise InputError(f"integration = {p['integration']!r} is not valid for element "
                         f"{p['element']} ({exc}); allowed: {', '.join(cls.schemes)} "
                         "or a spec 'normal=NXxNY,shear=NXxNY'") from None


def model(p):
    """(mesh, q0, assembly) of ``p["element"]``: :func:`ancf.models.beam3d.model` or, a
    three-node element, :func:`ancf.models.chrono_beam.quadratic_model`."""
    t = ELEMENTS[p["element"]]
    return beam3d.model(p) if t.nodes == 2 else chrono_beam.quadratic_model(p, *t.build(p))


def setup(p):
    """(mesh, q0, assembly, elimination, load vector) of the 3D cantilever (density
    ``p["rho"]`` if given); the tip force on the mesh's last node."""
    m, q0, asm = model(p)
    elim = beam3d.elimination(m, q0, beam3d.clamp(m))
    load = beam3d.tip_load({**p, "n_elements": m.n_nodes - 1})
    return m, q0, asm, elim, beam3d.load_vector(m, load)


def run(p):
    m, q0, asm, elim, Qk = setup(p)
    dofs = [m.dof(m.n_nodes - 1, "r", c) for c in range(3)]
    return bs.solve(p, m, q0, asm, elim, Qk,
                    lambda q: {f"tip_{c}": float(q[d]) for c, d in zip("xyz", dofs)},
                    forces=beam3d.tip_moment(m, p))


def chords(mesh, q) -> np.ndarray:
    """Element chord lengths (m): distances between consecutive nodes' positions in q."""
    r = np.array([[q[mesh.dof(k, "r", c)] for c in range(3)]
                  for k in range(mesh.n_elements + 1)])
    return np.linalg.norm(np.diff(r, axis=0), axis=1)


def warn(p, res) -> list:
    """The static accuracy checks and, as the 2D scenes' area check, an element stretched
    or shortened beyond its factor (:func:`ancf.scenes.sense.stretch`)."""
    out = accuracy.static(p, res)
    if res.converged and "q" in res.extra:
        m, q, q0 = res.extra["mesh"], res.extra["q"], res.extra["q0"]
        out += sense.stretch(chords(m, q), chords(m, q0))
    return out


def modal(p):
    return bs.modal(p, *setup(p))


def _reissner_3d(p):
    """The Reissner rod in the load plane (h = b, or the load along a principal axis)."""
    if any(p.get(f"M{c}", 0.0) for c in "xyz"):
        raise ReferenceFailed("Reissner reference: a tip force only (Mx = My = Mz = 0)")
    a = math.radians(p["load_angle_deg"])
    c, s = math.cos(a), math.sin(a)
    if abs(p["h"] - p["b"]) > 1e-12 * p["h"] and min(abs(c), abs(s)) > 1e-12:
        raise ReferenceFailed("Reissner reference: a load off the principal axes of a "
                              "non-square section bends the beam out of the load plane")
    h, b = (p["h"], p["b"]) if abs(c) >= abs(s) else (p["b"], p["h"])
    ref = reissner_tip({**p, "h": h, "b": b})
    return {"tip_x": ref["tip_x"], "tip_y": ref["tip_y"] * c, "tip_z": ref["tip_y"] * s}


def _tip3_error(res, ref, p):
    """|tip - tip_ref| / |tip_ref - (L, 0, 0)|."""
    d = math.dist((ref["tip_x"], ref["tip_y"], ref["tip_z"]), (p["L"], 0.0, 0.0))
    return math.dist((res["tip_x"], res["tip_y"], res["tip_z"]),
                     (ref["tip_x"], ref["tip_y"], ref["tip_z"])) / d


#: the grids of the 3D beam benchmarks (princeton-beam, beam3d-bending)
PUBLISHED_GRIDS = (
    {"element": ["linear3d"], "integration": ["thesis", "exact", "report-fix"],
     "n_elements": [2, 4, 8, 16, 32, 64], "rtol": [1e-8]},
    {"element": ["belt3d"], "n_elements": [2, 4, 8, 16, 32], "rtol": [1e-8]})
def chrono_grid(ns) -> dict:
    """Chrono's beams (:data:`CHRONO`; exact rules, no integration knob) on the meshes
    ``ns``: what the recommender's grids add to the thesis elements."""
    return {"element": list(CHRONO), "n_elements": list(ns), "rtol": [1e-8]}


#: the grids of the 3D beam benchmarks' speed-accuracy sweeps and of the recommender: the
#: thesis's and Chrono's beams, so that the Pareto front is drawn across both families
RECOMMEND_GRIDS = PUBLISHED_GRIDS + (chrono_grid([2, 4, 8, 16, 32]),)


def self_study(scene: str, quantities: tuple, error, what: str, measure: str):
    """The converged self-reference of the 3D beam benchmarks (linear3d, 256 elements)."""
    from ancf.scenes.spec import self_reference
    return self_reference(
        scene, {"element": "linear3d", "integration": "thesis", "n_elements": 256,
                "rtol": 1e-10, "load_steps": 10, "max_iterations": 25},
        quantities, error, "converged self-reference: linear3d, thesis scheme, 256 elements, "
        f"Newton rtol 1e-10 (cached); error = {what}; measures the discretisation error only",
        check={"n_elements": 128}, measure=measure)


RESULTS = {**STATIC_RESULTS, "tip_x": nullable("tip x, m"), "tip_y": nullable("tip y, m"),
           "tip_z": nullable("tip z, m")}


def study():
    """What sweeps measure this scene against: its references, errors and grids."""
    from ancf.scenes.spec import STATIC_KNOBS, Reference, SceneSpec, relative
    refs = {"reissner": Reference(
        "reissner", "analytic",
        "geometrically exact Reissner rod in the load plane (`ancf analytic reissner`; a square "
        "section or a load along a principal axis); error = |tip − tip_ref| / |tip_ref − (L, 0, "
        "0)|", _reissner_3d, _tip3_error, measure="relative tip-position error")}
    grid = ({"element": ["linear3d"], "integration": ["thesis"], "n_elements": [1, 2, 4, 8, 16],
             "rtol": [1e-8]},
            {"element": ["belt3d"], "n_elements": [1, 2, 4, 8, 16], "rtol": [1e-8]})
    return SceneSpec("beam3d-cantilever", STATIC_KNOBS,
                     frozenset({"axial", "bending", "shear", "large-rotation", "3D"}), refs,
                     "reissner", report_grids=grid + (chrono_grid([1, 2, 4, 8, 16]),),
                     recommend_grids=grid + (chrono_grid([1, 2, 4, 8, 16]),),
                     notes="Model 1 cantilever with the 3D linear element and the 3D belt "
                           "element (alpha1 = alpha2 = 1) against the Reissner rod.")


#: the scene's place in the scene list (ancf.scenes.MODULES, ancf scenes, reports/schemas.md)
ORDER = 100
SCENE = Scene(
    "beam3d-cantilever",
    "The cantilever with a 3D beam element, tip force at an angle in the section plane.",
    params(), run, check, warn=warn, modal=modal, modal_params=(STEEL_DENSITY,),
    results=RESULTS, study=study)
