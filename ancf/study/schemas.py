"""JSON schemas of the public output of ``ancf run SCENE --json``, ``ancf analytic NAME
--json`` and ``ancf modes SCENE --json``: one per scene, per analytic reference and per
scene with modes, generated from declarations.

The top level is the same for all (``scene``, ``params``, ``converged``, ``message``,
``results``, ``cpu_time_s``, ``compile_cpu_s``, ``warnings``); ``params`` follows the scene's parameter
declarations (:class:`ancf.scenes.base.Param`); ``results`` follows :data:`RESULTS` below
(:data:`MODES` for ``ancf modes``), the one place where a result key is declared: its JSON
type, whether it is always present and whether it is ``null`` when the run does not
converge.  Result keys not declared are
an error of the schema (``additionalProperties: false``), so a new result key must be
declared here, which publishes it (``python -m ancf.study.schemas`` writes
``reports/schemas.md``).  :func:`validate` is a small validator for the subset of JSON
Schema used (type, properties, required, additionalProperties, items), so that the suite
needs no extra dependency.
"""
from __future__ import annotations

import sys
from pathlib import Path

from ancf.common.paths import REPORTS
from ancf.solvers.linear import ZERO_EIGENVALUE_REL

NUM, INT, STR, BOOL = "number", "integer", "string", "boolean"


def field(kind: str, doc: str, nullable: bool = False, required: bool = True,
          items: str | None = None, keys: dict | None = None) -> dict:
    """Declaration of one result key (``items``: the element type of an array; ``keys``:
    the declarations of an object's keys)."""
    return {"kind": kind, "doc": doc, "nullable": nullable, "required": required,
            "items": items, "keys": keys}


def series(doc: str, nullable: bool = False) -> dict:
    """A sampled time history: an array of numbers (null where not finite; ``nullable``:
    the whole array null when the run stopped)."""
    return field("array", doc, nullable=nullable, items=NUM)


_STATIC = {
    "newton_iterations": field(INT, "Newton iterations over all load steps"),
    "load_steps_taken": field(INT, "converged load steps"),
    "load_factor": field(NUM, "load factor reached (1 when converged)"),
    "tangent_evaluations": field(INT, "tangent-stiffness evaluations", required=False),
    "factorizations": field(INT, "factorisations of the tangent", required=False),
    "negative_tangent_eigenvalues": field(
        INT, "negative eigenvalues of the reduced tangent at the solution (absent when Newton "
             "stopped; null when the model is too large for the dense check)",
        nullable=True, required=False),
    "zero_tangent_eigenvalues": field(INT, "zero eigenvalues of the reduced tangent",
                                      nullable=True, required=False),
    "lowest_tangent_eigenvalue_rel": field(NUM, "lowest eigenvalue / largest |eigenvalue|",
                                           nullable=True, required=False),
}

_DYNAMIC = {
    "times": series("sample times, s"),
    "integrator": field(STR, "time integrator used"),
    "steps": field(INT, "accepted time steps"),
    "nfev": field(INT, "force evaluations"),
    "njev": field(INT, "Jacobian (tangent) evaluations"),
    "nlu": field(INT, "LU factorisations"),
    "newton_iterations": field(INT, "Newton iterations (implicit integrators)"),
    "rejected_steps": field(INT, "rejected time steps"),
    "integration_cpu_s": field(NUM, "CPU time of the integration, s"),
    "constraint_violation_m": field(NUM, "largest constraint violation, m", nullable=True),
    "samples": field(INT, "number of samples"),
    "t_reached": field(NUM, "last time reached, s"),
}


def _nullable(doc: str) -> dict:
    return field(NUM, doc, nullable=True)


_BELT_STEADY = {
    "T_tight_N": _nullable("tight-span tension, N"), "T_slack_N": _nullable("slack-span tension, N"),
    "v_tight": _nullable("tight-span speed (= omega R of the driver), m/s"),
    "v_slack": _nullable("slack-span speed (= omega R of the driven pulley), m/s"),
    "slip_arc_driver_rad": _nullable("slip arc on the driver, rad"),
    "slip_arc_driven_rad": _nullable("slip arc on the driven pulley, rad"),
    "omega_ratio": _nullable("omega_driven / omega_driver = v_slack / v_tight"),
    "max_torque_Nm": _nullable("largest transmissible torque (slip over the whole wrap), N m")}

#: result keys per scene / analytic reference
RESULTS = {
    "simply-supported": {**_STATIC, "mid_deflection_m": _nullable("midpoint deflection, m")},
    "cantilever": {**_STATIC, "tip_x": _nullable("tip x, m"), "tip_y": _nullable("tip y, m")},
    "axial-bar": {**_STATIC, "elongation_m": _nullable("elongation, m"),
                  "tip_reaction_y_N": _nullable("transverse reaction at the tip support, N")},
    "pendulum": {
        **_DYNAMIC, "tip_x": series("tip x, m"), "tip_y": series("tip y, m"),
        "energy_max_deviation_J": _nullable("largest |E(t) - E(0)|, J"),
        "energy_kinetic": series("kinetic energy, J"),
        "energy_potential": series("gravitational potential energy, J"),
        "energy_strain": series("strain energy, J"), "energy_total": series("total energy, J")},
    "spinning-beam": {
        **_DYNAMIC, "tip_dx": series("tip minus rigid shadow tip, x, m"),
        "tip_dy": series("tip minus rigid shadow tip, y, m"),
        "tip_axial": series("tip deviation along the rotating beam axis, m"),
        "tip_lateral": series("tip deviation across the rotating beam axis, m"),
        "hub_angle": series("hub angle, rad"), "extension": series("centreline elongation, m"),
        "axial_extension_m": _nullable("mean elongation over the last mean_window s, m"),
        "axial_extension_std_m": _nullable("its standard deviation, m"),
        "tip_axial_mean_m": _nullable("mean axial tip deviation over the window, m"),
        "max_abs_tip_lateral_m": _nullable("largest |lateral tip deviation|, m"),
        "frame": field(STR, "frame of the tip_axial / tip_lateral components")},
    "belt-free-static": {
        "radius_mean_m": _nullable("mean distance of the centreline from its centroid, m"),
        "radius_max_dev_m": _nullable("largest deviation of that distance from its mean, m"),
        "radius_reference_m": field(NUM, "belt_length / (2 pi), the circle's radius, m"),
        "newton_iterations": field(INT, "Newton iterations"),
        "residual_initial": field(NUM, "largest generalised force at the wrapped shape, N"),
        "residual_final": field(NUM, "largest generalised force at the last iterate, N")},
    "belt2d": {
        **_DYNAMIC,
        "omega_driver": series("driver angular velocity (Eq. 3.29), rad/s"),
        "omega_driven": series("driven pulley angular velocity, rad/s"),
        "omega_ratio_steady": _nullable("mean omega_driven / mean omega_driver over the last "
                                        "0.1 s (null before the driver turns)"),
        "mid_tight_y_m": series("tight (upper) span: where the belt crosses the span's "
                                "perpendicular bisector, y, m"),
        "mid_slack_y_m": series("slack (lower) span: the same, m"),
        "tension_tight_N": _nullable("tight span: mean axial force over its middle third at "
                                     "t_end, N"),
        "tension_slack_N": _nullable("slack span: the same, N"),
        "tension_tight_mean_N": _nullable("tight span tension averaged over the samples of the "
                                          "last 0.1 s (the instantaneous one carries the span "
                                          "and pulley oscillations), N"),
        "tension_slack_mean_N": _nullable("slack span: the same, N"),
        "penetration_max_m": _nullable("largest penetration of the belt's centreline sample "
                                       "points into a pulley at t_end, m"),
        "contact_dofs": field(INT, "belt coordinates of the elements touching a pulley at t_end",
                              nullable=True),
        "total_dofs": field(INT, "belt coordinates plus the driven pulley's angle", nullable=True),
        "contact_pairs": field(INT, "element-pulley pairs whose Gauss points were evaluated "
                                    "(after the bounding test), summed over force evaluations"),
        "pretension_iterations": field(INT, "Newton iterations of the static pre-tension "
                                            "(0: start = laid)")},
    "belt3d": {
        **_DYNAMIC,
        "omega_driver": series("driver angular velocity (Eq. 3.29), rad/s"),
        "omega_driven": series("driven pulley angular velocity, rad/s"),
        "slip_driven": _nullable("1 - mean omega_driven / mean omega_driver over the last "
                                 "steady_window (null before the driver turns)"),
        "T_tight_N": _nullable("tight (upper) span: mean tension k eps of strain_measure over its "
                               "middle third at t_end, along the edge y = 0, N"),
        "T_slack_N": _nullable("slack (lower) span: the same, N"),
        "v_tight": _nullable("tight span: mean belt speed along the tangent at t_end, m/s"),
        "v_slack": _nullable("slack span: the same, m/s"),
        "tensions": field("object", "span tensions per measure (green, true, almansi: k eps; "
                          "membrane: the element's own axial force), N", nullable=True,
                          keys={m: field("object", f"{m}: tight and slack, N",
                                         keys={"tight": field(NUM, "tight span, N"),
                                               "slack": field(NUM, "slack span, N")})
                                for m in ("green", "true", "almansi", "membrane")}),
        "torque_from_tensions_Nm": _nullable("(T_tight - T_slack) R of strain_measure, N m"),
        "torques_from_tensions_Nm": field("object", "(T_tight - T_slack) R per measure, N m",
                                          nullable=True,
                                          keys={m: field(NUM, f"{m}, N m") for m in
                                                ("green", "true", "almansi", "membrane")}),
        "torque_from_friction_Nm": _nullable("moment of the contact (friction) forces on the "
                                             "driven pulley at t_end, N m"),
        "penetration_max_m": _nullable("largest penetration of a contact point at t_end, m"),
        "contact_pairs": field(INT, "element-pulley pairs whose points were evaluated (after the "
                                    "bounding test), summed over force evaluations"),
        "pretension_iterations": field(INT, "Newton iterations of the static pre-tension "
                                            "(0: start = laid)"),
        "belt_length_m": field(NUM, "reference (unstretched) belt length used, m"),
        "total_dofs": field(INT, "belt coordinates plus the driven pulley's angle")},
    "belt-drive": {
        **_DYNAMIC,
        "pulleys": field("array", "per pulley, in belt order (null when the run stopped)",
                         items="object", nullable=True, keys={
            "name": field(STR, "pulley name"),
            "omega": series("angular velocity, counter-clockwise positive, rad/s"),
            "torque_Nm": series("the belt's moment on it (friction), counter-clockwise "
                                "positive, N m"),
            "omega_mean": field(NUM, "mean angular velocity over run.steady_window (over every "
                                     "time step of it), rad/s"),
            "torque_mean_Nm": field(NUM, "mean of the belt's moment on it over every time "
                                         "step of run.steady_window, N m"),
            "slip": field(NUM, "1 - its mean rim speed / the driver's (the first prescribed "
                               "pulley) over the window")}),
        "arms": field("array", "per tensioner, in belt order (null when the run stopped)",
                      items="object", nullable=True, keys={
            "name": field(STR, "the tensioner pulley's name"),
            "angle_rad": series("its arm's angle (centre - pivot, counter-clockwise from x), "
                                "rad"),
            "angle_mean_rad": field(NUM, "its mean over run.steady_window, rad")}),
        "spans": field("array", "per span (pulley k to k + 1), in belt order (null when the "
                       "run stopped)", items="object", nullable=True, keys={
            "from": field(STR, "pulley the span leaves"), "to": field(STR, "pulley it reaches"),
            "tension_mean_N": field(NUM, "mean axial force over its middle third, averaged "
                                         "over the samples of run.steady_window, N"),
            "tension_N": field(NUM, "the same at t_end, N")}),
        "belt_s_m": field("array", "belt arc coordinate (reference length from node 0) of "
                          "the points along the belt (the plate belt: along its edge z = 0), "
                          "m", nullable=True, items=NUM),
        "axial_force_N": field("array", "axial force at those points at t_end, N",
                               nullable=True, items=NUM),
        "speed_m_s": field("array", "belt speed at those points at t_end, m/s", nullable=True,
                           items=NUM),
        "penetration_max_m": _nullable("largest penetration of the belt's centreline sample "
                                       "points (the plate belt: its mid surface's contact "
                                       "points) into a pulley at t_end, m"),
        "belt_x_m": field("array", "x of those points at t_end, m", nullable=True, items=NUM),
        "belt_y_m": field("array", "y of those points at t_end, m", nullable=True, items=NUM),
        "normal_force_N_m": field("array", "the pulleys' normal force on the belt per unit "
                                  "length at those points at t_end (summed over the pulleys; "
                                  "0 off contact), N/m", nullable=True, items=NUM),
        "friction_force_N_m": field("array", "the friction force on the belt per unit length "
                                    "along the pulley's counter-clockwise tangent at those "
                                    "points at t_end, summed over the pulleys, N/m", nullable=True,
                                    items=NUM),
        "total_dofs": field(INT, "belt coordinates plus the free pulleys' angles"),
        "contact_pairs": field(INT, "element-pulley pairs whose Gauss points were evaluated "
                                    "(after the bounding test), summed over force evaluations"),
        "pretension_iterations": field(INT, "Newton iterations of the static pre-tension "
                                            "(0: start = laid)")},
    "plate-square": {
        "center_deflection_m": _nullable("centre deflection along the pressure (linear solve), m"),
        "navier_center_deflection_m": _nullable("Navier's series at the same parameters, m"),
        "navier_terms": field(INT, "largest odd index of Navier's series summed"),
        "relative_error": _nullable("center_deflection_m / navier_center_deflection_m - 1"),
        "tangent_evaluations": field(INT, "tangent-stiffness evaluations (1: a linear solve)"),
        "factorizations": field(INT, "factorisations of the tangent (1)")},
    "plate-strip": {**_STATIC, "tip_x": _nullable("mean x of the tip-edge nodes, m"),
                    "tip_y": _nullable("mean y of the tip-edge nodes (b/2 by symmetry), m"),
                    "tip_z": _nullable("mean z of the tip-edge nodes (along the load), m")},
    "beam3d-cantilever": {**_STATIC, "tip_x": _nullable("tip x, m"), "tip_y": _nullable("tip y, m"),
                          "tip_z": _nullable("tip z, m")},
    "princeton-beam": {**_STATIC, "tip_x": _nullable("tip x, m"),
                       "tip_y": _nullable("tip y, m (u_y = tip_y)"),
                       "tip_z": _nullable("tip z, m (u_z = tip_z: the mirror image of the "
                                          "published +z)")},
    "beam3d-bending": {**_STATIC, "tip_x": _nullable("tip x, m (u_x = tip_x - L)"),
                       "tip_y": _nullable("tip y, m"), "tip_z": _nullable("tip z, m")},
    "navier-plate": {"center_deflection_m": _nullable("centre deflection along the pressure, m"),
                     "terms": field(INT, "largest odd series index summed")},
    "timoshenko": {"mid_deflection_m": _nullable("midspan deflection, m")},
    "beam-modes": {
        "frequencies_hz": field("array", "Timoshenko natural frequencies (both spectra), "
                                "ascending, Hz", items=NUM),
        "euler_bernoulli_hz": field("array", "Euler-Bernoulli natural frequencies, ascending, Hz",
                                    items=NUM),
        "cutoff_hz": _nullable("the second spectrum's cut-off sqrt(ks G A / (rho I)) / (2 pi), "
                               "Hz")},
    "plate-modes": {
        "frequencies_hz": field("array", "natural frequencies, ascending, Hz", items=NUM),
        "m": field("array", "half-waves along a of each frequency", items=INT),
        "n": field("array", "half-waves along b of each frequency", items=INT)},
    "moving-string": {
        "frequencies_hz": field("array", "transverse span frequencies n c (1 - v^2/c^2) / (2 L), "
                                "ascending, Hz", items=NUM),
        "wave_speed_m_s": _nullable("c = sqrt(T / rho_A), m/s")},
    "reissner": {"tip_x": _nullable("tip x, m"), "tip_y": _nullable("tip y, m"),
                 "tip_rotation_rad": _nullable("tip section rotation, rad")},
    "spinning-extension": {
        "axial_extension_m": _nullable("steady axial extension (Eq. 2.36), m"),
        "al": _nullable("the parameter a L of Eq. 2.36"),
        "axial_extension_thesis_m": _nullable("the same as printed in the thesis, m")},
    "belt-steady": {
        "path_length_m": field(NUM, "length of the wrapped path at the tensioner's equilibrium, m"),
        "L0_m": field(NUM, "stress-free belt length used, m"),
        "spans": field("array", "per span, in belt order", items="object", keys={
            "from": field(STR, "pulley the span leaves"), "to": field(STR, "pulley it reaches"),
            "length_m": field(NUM, "span length (common tangent), m"),
            "tension_N": field(NUM, "tension T, N"), "speed": field(NUM, "belt speed, m/s")}),
        "pulleys": field("array", "per pulley, in belt order", items="object", keys={
            "name": field(STR, "pulley name"), "law": field(STR, "prescribed, driven, idler or "
                                                            "tensioner"),
            "wrap_rad": field(NUM, "wrap angle, rad"),
            "stick_arc_rad": field(NUM, "stick arc (from the entry), rad"),
            "creep_arc_rad": field(NUM, "creep arc (at the exit), rad"),
            "omega": field(NUM, "angular speed, positive counter-clockwise, rad/s"),
            "torque_Nm": field(NUM, "the belt's moment on it along its rotation (the driver's: "
                                    "minus its driving torque), N m"),
            "slip": field(NUM, "1 - its rim speed / the driver's"),
            "arm_angle_rad": _nullable("a tensioner's arm angle at equilibrium, pivot to "
                                       "centre, counter-clockwise from x, rad (null: no arm)")})},
    "bechtel": {**_BELT_STEADY, "capstan": field("object", "the same keys with the belt's "
                                                 "inertia neglected (capstan model)",
                                                 keys=_BELT_STEADY)},
    "rigid-pendulum": {"times": series("sample times, s"),
                       "theta": series("angle, rad (null when the integration failed)", True),
                       "tip_x": series("tip x, m (null when the integration failed)", True),
                       "tip_y": series("tip y, m (null when the integration failed)", True)},
}

_MODES_NULL = "null when no eigenpairs were found"
#: result keys of ``ancf modes SCENE --json`` (every scene with modes)
MODES = {
    "about": field(STR, "state the tangent stiffness is taken at: reference or equilibrium"),
    "count": field(INT, "number of modes asked for (default 6, or the reduced size - 1)"),
    "method": field(STR, "eigensolver: dense LAPACK eigh, or shift-invert Lanczos (ARPACK) on "
                         "the band LU or SuperLU of K - sigma M", nullable=True),
    "reduced_size": field(INT, "unknowns of the reduced system (constraints eliminated)"),
    "frequencies_hz": field("array", "the lowest count natural frequencies, ascending, Hz "
                            "(negative: -sqrt(-omega^2)/(2 pi) of an unstable mode); "
                            + _MODES_NULL, nullable=True, items=NUM),
    "eigenvalues_rad2_s2": field("array", "their omega^2, rad^2/s^2; " + _MODES_NULL,
                                 nullable=True, items=NUM),
    "rigid_body_modes": field(INT, "zero-frequency modes (rigid motion, a mechanism or a "
                              "zero-energy mode of the integration scheme): |phi^T K phi| <= "
                              "rigid_body_threshold_rel |K|_inf phi^T phi", nullable=True),
    "rigid_body_threshold_rel": field(NUM, "that threshold (the static stability check's zero, "
                                           f"{ZERO_EIGENVALUE_REL:g})"),
    "sampling": field(STR, "where the mode shapes are sampled: centreline (beams, the belt) or "
                           "mid-surface grid (plates: the nodes)"),
    "sample_points": field("array", "positions of the sample points in the state vibrated "
                                    "about, m (one [x, y] or [x, y, z] each)", items="array"),
    "mode_shapes": field("array", "per mode, the displacement [dx, dy(, dz)] of every sample "
                                  "point, scaled to a largest magnitude of 1 (its largest "
                                  "component positive; all zero for a mode that leaves the "
                                  "points in place, e.g. a beam section's torsion); "
                                  + _MODES_NULL, nullable=True, items="array"),
    "mode_direction_shares": field("array", "per mode, the share of the squared sampled "
                                            "displacement along x, y(, z) (all zero where the "
                                            "points stay in place); " + _MODES_NULL,
                                   nullable=True, items="array"),
    "newton_iterations": field(INT, "Newton iterations of the static equilibrium (0 about the "
                                    "reference)"),
    "factorizations": field(INT, "factorisations: inertia counts (the shift, the Sturm check) "
                                 "and the shift-inverted LU or Cholesky", nullable=True),
    "solves": field(INT, "Lanczos steps: solves with the factorisation (dense: 0)",
                    nullable=True),
    "shift_rad2_s2": _nullable("the shift sigma, below the lowest eigenvalue"),
    "sturm_count": field(INT, "eigenvalues below the Sturm check's point, by inertia (between "
                              "the highest reported and the next, or above the next where the "
                              "two are one repeated eigenvalue)", nullable=True),
    "missed_modes": field(INT, "sturm_count minus the eigenvalues found below that point (0: "
                               "none missed)", nullable=True),
    "lowest_frequency_reference_hz": field(NUM, "about the equilibrium: the lowest frequency "
                                                "about the reference, Hz", required=False),
}

_PARAM_TYPES = {float: NUM, int: INT, str: STR, bool: BOOL}


def _type(kind: str, nullable: bool):
    return [kind, "null"] if nullable else kind


def _result_schema(decl: dict) -> dict:
    props = {}
    for k, f in decl.items():
        props[k] = {"type": _type(f["kind"], f["nullable"]), "description": f["doc"]}
        if f["items"] and f["keys"]:  # an array of objects
            props[k]["items"] = _result_schema(f["keys"])
        elif f["items"]:
            props[k]["items"] = {"type": [f["items"], "null"]}
        elif f["keys"]:
            props[k].update({kk: v for kk, v in _result_schema(f["keys"]).items() if kk != "type"})
    return {"type": "object", "properties": props, "additionalProperties": False,
            "required": [k for k, f in decl.items() if f["required"]]}


def _params_schema(scene) -> dict:
    props = {p.name: {"type": _type(_PARAM_TYPES[p.kind], p.default is None),
                      "description": f"{p.doc} ({p.unit})" if p.unit else p.doc}
             for p in scene.params}
    return {"type": "object", "properties": props, "additionalProperties": False,
            "required": list(props)}


def registries() -> dict:
    """{name: (command, Scene)} of every scene and analytic reference."""
    from ancf.scenes.analytic import REFERENCES
    from ancf.scenes import SCENES
    return {**{n: ("run", s) for n, s in SCENES.items()},
            **{n: ("analytic", s) for n, s in REFERENCES.items()}}


class SchemaNameError(KeyError, ValueError):
    """An unknown schema name; the message lists the allowed ones (a ``KeyError``, as
    before, and a ``ValueError``; printed without ``KeyError``'s quotes)."""

    def __str__(self) -> str:
        return str(self.args[0]) if self.args else ""


def names() -> list[str]:
    """Every schema name in the README's form: ``run SCENE``, ``analytic NAME`` and
    ``modes SCENE``."""
    from ancf.scenes.modes import MODAL
    return [f"{command} {n}" for n, (command, _) in registries().items()] + [
        f"modes {n}" for n in MODAL]


def _lookup(name: str) -> tuple[str, str, object]:
    """(command, bare name, Scene) of ``run SCENE``, ``analytic NAME``, ``modes SCENE``
    (also with a leading ``ancf``) or the bare ``SCENE`` / ``NAME`` (its run)."""
    from ancf.scenes.modes import MODAL, modal_scene
    regs = registries()
    words = name.split() if isinstance(name, str) else []
    if words[:1] == ["ancf"]:
        words = words[1:]
    if len(words) == 2 and words[0] in ("run", "analytic", "modes"):
        command, bare = words
    elif len(words) == 1:
        command, bare = None, words[0]
    else:
        command, bare = None, None
    if command == "modes" and bare in MODAL:
        return command, bare, modal_scene(bare)
    if bare in regs and command in (None, regs[bare][0]):
        return regs[bare][0], bare, regs[bare][1]
    raise SchemaNameError(f"schema: unknown name {name!r}; allowed: {', '.join(names())} "
                          "(or the bare scene or reference name)")


def schema(name: str) -> dict:
    """The JSON schema of ``ancf run|analytic|modes NAME --json``; ``name`` as the README
    writes it (``"run cantilever"``, ``"analytic reissner"``, ``"modes cantilever"``) or
    bare (``"cantilever"``: its run).  An unknown name raises :class:`SchemaNameError` (a
    ``KeyError``) listing the allowed ones."""
    command, name, sc = _lookup(name)
    props = {"scene": {"type": STR, "const": name}, "params": _params_schema(sc),
             "converged": {"type": BOOL}, "message": {"type": STR},
             "results": _result_schema(MODES if command == "modes" else RESULTS[name]), "cpu_time_s": {"type": NUM, "description": "process CPU seconds of the run, without "
                            "compiling or loading numba kernels"},
             "compile_cpu_s": {"type": NUM, "description": "process CPU seconds spent compiling "
                               "numba kernels or loading them from numba's cache during the run "
                               "(0 when all were loaded before)"},
             "warnings": {"type": "array", "items": {"type": STR},
                          "description": "accuracy warnings, empty when none"}}
    return {"$schema": "https://json-schema.org/draft/2020-12/schema",
            "title": f"ancf {command} {name} --json", "type": "object", "properties": props,
            "required": list(props), "additionalProperties": False}


#: the JSON Schema keywords this module writes and :func:`validate` understands
KEYWORDS = frozenset(("$schema", "title", "type", "properties", "required",
                      "additionalProperties", "items", "const", "description"))


def _check_schema(sch, value) -> dict:
    """``sch`` as a schema dict (a name is looked up), or a TypeError saying what is wrong
    (above all: the output and the schema passed the wrong way round)."""
    if isinstance(sch, str):
        return schema(sch)
    swapped = isinstance(value, dict) and "$schema" in value
    if not isinstance(sch, dict):
        raise TypeError(f"validate(value, schema): the schema is a {type(sch).__name__}, not a "
                        "dict or a schema name")
    unknown = sorted(set(sch) - KEYWORDS)
    if swapped or unknown:
        why = ("the first argument is a schema" if swapped
               else f"the second argument has key(s) {', '.join(map(repr, unknown[:3]))} that "
                    "are no JSON Schema keywords")
        raise TypeError(f"validate(value, schema): {why}; call validate(output, schema(name)), "
                        "the output first")
    return sch


_CHECK = {NUM: lambda v: isinstance(v, (int, float)) and not isinstance(v, bool),
          INT: lambda v: isinstance(v, int) and not isinstance(v, bool),
          STR: lambda v: isinstance(v, str), BOOL: lambda v: isinstance(v, bool),
          "null": lambda v: v is None, "array": lambda v: isinstance(v, list),
          "object": lambda v: isinstance(v, dict)}


def validate(value, sch, path: str = "$") -> list[str]:
    """Violations of ``sch`` by ``value`` (empty when valid), one line each with its path.

    ``sch`` is a schema (:func:`schema`) or its name (``"run cantilever"``).  Arguments
    passed the wrong way round (``validate(schema, output)``) raise a TypeError instead of
    passing silently.
    """
    return _validate(value, _check_schema(sch, value), path)


def _validate(value, sch: dict, path: str) -> list[str]:
    types = sch.get("type")
    types = [types] if isinstance(types, str) else types
    if types and not any(_CHECK[t](value) for t in types):
        return [f"{path}: {type(value).__name__} is not {' or '.join(types)}"]
    if "const" in sch and value != sch["const"]:
        return [f"{path}: {value!r} is not {sch['const']!r}"]
    errors = []
    if isinstance(value, dict):
        props = sch.get("properties", {})
        errors += [f"{path}: missing key {k!r}" for k in sch.get("required", ()) if k not in value]
        for k, v in value.items():
            if k in props:
                errors += _validate(v, props[k], f"{path}.{k}")
            elif sch.get("additionalProperties") is False:
                errors.append(f"{path}: undeclared key {k!r}")
    if isinstance(value, list) and "items" in sch:
        for i, v in enumerate(value):
            errors += _validate(v, sch["items"], f"{path}[{i}]")
    return errors


def _type_text(s: dict) -> str:
    t = s["type"]
    text = " or ".join(t) if isinstance(t, list) else t
    if "items" not in s:
        return text
    item = s["items"]["type"]
    return f"{text} of {item if isinstance(item, str) else ' or '.join(item)}"


def schemas_markdown() -> str:
    """reports/schemas.md: every schema as a table, and as JSON."""
    import json
    parts = ["# JSON output schemas\n",
             "Generated from `ancf/study/schemas.py` (`python -m ancf.study.schemas`); do not edit. One "
             "schema per `ancf run SCENE --json`, `ancf analytic NAME --json` and `ancf modes "
             "SCENE --json`; the suite validates every scene's and reference's default run "
             "(and every scene's modes) against it "
             "(`tests/study/test_schemas.py`). Top level: `scene`, `params` (every parameter used), "
             "`converged`, `message`, `results`, `cpu_time_s` (the run's process CPU seconds "
             "without compiling or loading numba kernels), `compile_cpu_s` (those), "
             "`warnings` (a list of strings, "
             "empty when none). Result keys marked nullable are `null` where the run did not "
             "converge; optional keys are absent when the solver did not get that far.\n"]
    for full in names():
        command, name = full.split()
        s = schema(full)
        res = s["properties"]["results"]
        parts += [f"## `ancf {command} {name}`\n", "| result key | type | required | meaning |",
                  "|---|---|---|---|"]
        parts += [f"| `{k}` | {_type_text(v)} | {'yes' if k in res['required'] else 'no'} | "
                  f"{v['description']} |" for k, v in res["properties"].items()]
        parts += ["", "<details><summary>JSON schema</summary>\n", "```json",
                  json.dumps(s, indent=1, ensure_ascii=False), "```", "</details>\n"]
    return "\n".join(parts)


def main(argv=None) -> int:
    """``python -m ancf.study.schemas [FILE]``: write the Markdown (default reports/schemas.md)."""
    argv = sys.argv[1:] if argv is None else argv
    out = Path(argv[0]) if argv else REPORTS / "schemas.md"
    out.write_text(schemas_markdown())
    print(out)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
