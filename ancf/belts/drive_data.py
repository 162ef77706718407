"""A belt drive as data: the keys of a drive file (:mod:`ancf.belts.drive_file` reads it),
their units, defaults and ranges, and the validated description it becomes.

A drive file (TOML) has a top-level ``gravity = [g_x, g_y]`` (m/s^2) and these tables
(the key lists below are the declarations; every key has its unit and range there):

* ``[belt]``: the element (``dufva2d``, the planar belt of chapter 3; ``plate36``, the
  thin plate belt of chapter 4, :data:`PLATE_BELT`: its own keys below), ``n_elements``,
  the material (``E`` Pa or ``EA`` N = E b h, one of them), the section ``h`` x ``b``
  (m), ``rho`` (kg/m^3), ``nu``, ``ks``, Dufva's ``alpha1``, ``alpha2`` (Eqs 3.18-3.19),
  the reference length ``length`` L0 (m) or the ``prestretch`` L0 / P - 1 on the wrapped
  path P (one of them), the element's ``axial_strain`` law (``green``: the thesis's Green
  strain, force E A alpha1 (|r_x|^2 - 1)/2; ``engineering``: Exudyn's ANCFCable2D, force
  E A alpha1 (|r_x| - 1), r_x the slope along the stress-free length;
  :mod:`ancf.elements.dufva2d`), the ``strain_reference`` the file's E (or EA) and
  damping are measured on (``stress-free``: per stress-free length, what the element
  takes; ``laid``: per laid length on the path, Exudyn's convention with a reference
  strain, so the element gets E (1 + prestretch) and the damping times (1 + prestretch),
  :func:`laid_factor`),
  the axial and bending strain-rate damping ``damping_axial`` (dEA, N s) and
  ``damping_bending`` (dEI, N m^2 s) and ``contact_offset`` (m): the distance of the
  belt's running surfaces from its centreline, so the centreline's path runs at
  radius + offset round every pulley; the march's ``formulation`` (:data:`FORMULATIONS`).
  The ``plate36`` belt (:class:`ancf.belts.drive3d.Belt3DDrive`: one plate across the
  width, pulley axes along z) takes ``n_elements``, ``E`` or ``EA``, ``nu`` (plane
  stress), ``h`` its thickness, ``b`` its width w (along the pulley axes), ``rho``,
  ``bending`` (``on``: Eq. 4.17's bending energy; ``off``: a membrane),
  ``elastic_points`` (n x n Gauss points per plate), ``length`` or ``prestretch`` and
  ``contact_offset``; its ``[contact]`` is per unit area (``k_p`` N/m^3, ``c_p``
  N s/m^3, ``gauss_points`` 25, 49 or 81 over each plate's mid surface), its friction
  parameters too (``nu_s`` kg/(m^2 s); the bristle law's ``stiffness`` N/m^3, ``damping``
  N s/m^3, its state per contact point in the rim's tangent plane:
  :mod:`ancf.belts.contact3d_state`); a tensioner's arm turns about the z axis through
  its pivot (:mod:`ancf.belts.arm3d`; with a friction law without a state).
* ``[[pulleys]]``, in the belt's counter-clockwise running order (:mod:`ancf.belts.path`):
  ``name``, ``centre`` [x, y] (m), ``radius`` (m), ``side`` (+1 the belt's inner side on
  it, -1 its back) and a ``law`` (a :class:`PulleyRole` of :data:`ROLES`) with its keys:
  ``prescribed`` (``speed``: a law of :data:`ancf.belts.pulleys.SPEED_LAWS` with
  ``omega_final`` rad/s, ``t0``, ``t1`` s, or ``table`` with ``speed_table``),
  ``driven`` (``inertia``, ``damping`` and ``load``: a law of
  :data:`ancf.belts.pulleys.TORQUE_LAWS` with ``load_torque`` N m, ``t0``, ``t1``,
  ``constant`` with ``load_torque``, or ``table`` with ``load_table``; ``load_acts``, how
  it acts, :data:`ancf.belts.pulleys.LOAD_LAWS`: ``signed`` by default, or ``resisting``
  with ``omega_reg`` rad/s, default 0.1), ``idler``
  (``inertia``, ``damping``), ``tensioner`` (an idler on an arm turning about ``pivot``:
  the arm's ``arm_inertia`` about the pivot, torsion spring ``arm_stiffness`` and
  ``arm_preload``, ``arm_damping``; the arm's length is |centre - pivot|) and ``fixed``.
  Any pulley may have its centre moved by a prescribed law (:data:`MOTION`; the thesis's
  Model 1 moves its driver so, Eq. 4.46): ``centre_shift`` [dx, dy] (m, default [0, 0]:
  none), reached at ``centre_shift_time`` (s, default 0.05) by the ``centre_motion`` law
  (:data:`ancf.belts.pulleys.CENTRE_LAWS`: ``ramp``, u = u0 t / t0 up to t0); a
  tensioner's whole arm (its pivot) is carried so.
  A plate belt's pulley may have its axis misaligned (:data:`ALIGNMENT`, degrees, default 0,
  within +-:data:`MAX_ALIGN_DEG`; refused for the 2D belt): ``axis_tilt_deg`` turns it
  toward the running direction of the span entering it (the belt walks along the axis),
  ``axis_roll_deg`` toward the radius to that span's tangent point, both about the mid-face
  (:mod:`ancf.belts.tracking3d` defines them with a sketch); a tilt the belt cannot wrap
  is refused (:func:`ancf.belts.drive_file.wrap_walk`: it would leave the face within its
  wrap).  A plate belt's pulley other than a tensioner may have flanges (:data:`FLANGES`:
  ``flanges`` true or false, default false; ``face_width_m``, the face between them, at
  least the belt's width, default 0: 1.1 b; ``flange_height_m``, default 0.005 m), side
  walls holding a walking belt (:mod:`ancf.belts.flange3d`).  Any plate-belt pulley but a
  tensioner may be crowned (``crown_m``, default 0: a cylinder; at least 0 and below its
  radius; the friction laws without a state), its rim the surface of revolution of radius
  R + crown_m (1 - (2 a / W)^2) (:mod:`ancf.belts.contact3d_state`), and its face (crown and
  flanges) displaced along its axis by ``face_offset_m`` (default 0 m), so the belt starts
  that far off-centre.
  Angular velocities are counter-clockwise positive; a load torque T_a resists the
  pulley's running direction (Eq. 3.26 with -T_a; counter-clockwise on the belt's inner
  side, clockwise on its back); a table is ``[[t, value], ...]``, t increasing,
  interpolated linearly and held beyond its ends.
* ``[friction]``: ``law``, a name of :data:`ancf.belts.friction.ALL_PARAMS`
  (``creep-rate``, ``coulomb``, ``bristle``: its state per contact point carried by the
  march), and that law's parameters (:data:`FRICTION_KEYS`).
* ``[contact]``: the penalty ``k_p`` (N/m^2), ``c_p`` (N s/m^2) and ``gauss_points``.
* ``[run]``: ``t_end``, ``dt``, ``output_dt``, ``steady_window`` (s: the averaging window
  before t_end), ``start`` (``settled`` or ``laid``), ``rho_inf``, ``newton_tol``,
  ``max_steps``, modified Newton's ``refresh_ratio``, ``newton_accept``, ``refresh`` and
  ``give_up``
  (:mod:`ancf.solvers.alpha_march`; their defaults are the march's defaults) and the belt
  damping's part of the iteration matrix ``damping_jacobian``
  (:data:`ancf.belts.forces.DAMPING_JACOBIANS`).

Keys without a default (:data:`REQUIRED`) must be given.
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field, replace
from typing import Callable

import numpy as np

from ancf.belts import friction
from ancf.belts.contact2d import SUPPORTED_POINTS
from ancf.belts.contact3d import SUPPORTED_RULES
from ancf.belts.forces import DAMPING_JACOBIANS
from ancf.belts.path import PulleyPath
from ancf.belts.pulleys import (CENTRE_LAWS, FILE_SPEED_LAWS, FILE_TORQUE_LAWS, LOAD_LAWS, T0,
                                CentreMotion)
from ancf.common.inputs import MAX_STEPS
from ancf.common.params import InputError, Param
from ancf.solvers.alpha_march import ACCEPT, REFRESH, REFRESH_RATIO

REQUIRED = None  # the default of a key that must be given (Param's "no default")
BOUND = 1e3      # m: coordinates of centres and pivots within +-BOUND
#: the march's descriptions of the belt (``belt.formulation``; ``ale``: the 2D belt with a
#: stateless friction law, :mod:`ancf.belts.ale_march2d`)
FORMULATIONS = ("lagrangian", "ale")


@dataclass(frozen=True)
class Vector:
    """A key whose value is [x, y], each a finite number within +-bound."""

    name: str
    default: object = REQUIRED
    unit: str = "m"
    doc: str = ""
    bound: float = BOUND

    def allowed(self) -> str:
        return f"[x, y], two numbers in [-{self.bound:g}, {self.bound:g}] {self.unit}"

    def parse(self, value) -> tuple:
        try:
            v = tuple(float(x) for x in value)
        except (TypeError, ValueError):
            v = ()
        if len(v) != 2 or not all(math.isfinite(x) and abs(x) <= self.bound for x in v):
            raise InputError(f"{self.name} = {value!r} is out of range; allowed: {self.allowed()}")
        return v


@dataclass(frozen=True)
class Table:
    """A key whose value is [[t, value], ...]: at least two rows, t (s) increasing."""

    name: str
    unit: str
    doc: str = ""
    default: object = REQUIRED

    def allowed(self) -> str:
        return (f"[[t, value], ...], at least 2 rows of finite numbers, t (s) from 0 up and "
                f"increasing, value {self.unit}")

    def parse(self, value) -> tuple:
        try:
            rows = tuple((float(t), float(y)) for t, y in value)
        except (TypeError, ValueError):
            rows = ()
        t = np.array([r[0] for r in rows])
        if (len(rows) < 2 or not np.all(np.isfinite(rows)) or np.any(np.diff(t) <= 0)
                or t[0] < 0):
            raise InputError(f"{self.name} = {value!r} is out of range; allowed: {self.allowed()}")
        return rows


@dataclass(frozen=True)
class Switch:
    """A key whose value is TOML's true or false."""

    name: str
    default: object = REQUIRED
    doc: str = ""
    unit: str = ""

    def allowed(self) -> str:
        return "true or false"

    def parse(self, value) -> bool:
        if not isinstance(value, bool):
            raise InputError(f"{self.name} = {value!r} is not valid; allowed: {self.allowed()}")
        return value


def _keys(*keys) -> dict:
    return {k.name: k for k in keys}


TOP = _keys(Vector("gravity", (0.0, 0.0), "m/s^2", "gravity vector"))

BELT = _keys(
    Param("element", "dufva2d", str, doc="belt element", choices=("dufva2d", "plate36")),
    Param("n_elements", REQUIRED, int, doc="belt elements", lo=4, hi=2000),
    Param("E", REQUIRED, float, "Pa", "Young's modulus (or EA)", lo=0, lo_open=True, hi=1e12),
    Param("EA", REQUIRED, float, "N", "axial stiffness E b h (or E)", lo=0, lo_open=True, hi=1e10),
    Param("nu", 0.3, float, "-", "Poisson's ratio (the shear modulus only)", lo=0, hi=0.5,
          hi_open=True),
    Param("h", REQUIRED, float, "m", "section height", lo=0, lo_open=True, hi=0.05),
    Param("b", REQUIRED, float, "m", "section width", lo=0, lo_open=True, hi=1.0),
    Param("rho", REQUIRED, float, "kg/m^3", "density", lo=0, lo_open=True, hi=1e5),
    Param("ks", 5.0 / 6.0, float, "-", "shear correction factor", lo=0, lo_open=True, hi=2),
    Param("alpha1", 1.0, float, "-", "axial stiffness parameter (Eq. 3.18)", lo=0,
          lo_open=True, hi=10),
    Param("alpha2", 1.0, float, "-", "bending stiffness parameter (Eqs 3.18-3.19)", lo=0,
          lo_open=True, hi=10),
    Param("elastic_points", 5, int, doc="Gauss points per element of the elastic forces",
          lo=2, hi=12),
    Param("length", REQUIRED, float, "m", "reference (unstretched) length L0 (or prestretch)",
          lo=0, lo_open=True, hi=1e3),
    Param("prestretch", REQUIRED, float, "-", "L0 / P - 1 on the wrapped path P (or length)",
          lo=-0.5, hi=0.0),
    Param("axial_strain", "green", str, doc="axial strain law of the element",
          choices=("green", "engineering")),
    Param("strain_reference", "stress-free", str, doc="the length E (or EA) is per: "
          "'stress-free' or 'laid' (E and damping x (1 + prestretch) to the element)",
          choices=("stress-free", "laid")),
    Param("damping_axial", 0.0, float, "N s", "axial strain-rate damping dEA", lo=0, hi=1e9),
    Param("damping_bending", 0.0, float, "N m^2 s", "bending strain-rate damping dEI", lo=0,
          hi=1e9),
    Param("contact_offset", 0.0, float, "m", "running surfaces' distance from the centreline",
          lo=0, hi=0.05),
    Param("formulation", "lagrangian", str, doc="the march's description: 'lagrangian' (the "
          "mesh moves with the material) or 'ale' (the mesh stays on the path, the material "
          "flows through it: ancf.belts.ale_march2d)", choices=FORMULATIONS),
)
#: the plate36 belt's keys (thesis chapter 4; the belt3d scene's, as a drive file names them)
PLATE_BELT = _keys(
    BELT["element"],
    Param("n_elements", REQUIRED, int, doc="plates along the belt (one across its width)", lo=4,
          hi=200),
    BELT["E"], BELT["EA"],
    Param("nu", 0.3, float, "-", "Poisson's ratio (plane stress)", lo=0, hi=0.5, hi_open=True),
    Param("h", REQUIRED, float, "m", "plate thickness", lo=0, lo_open=True, hi=0.1),
    Param("b", REQUIRED, float, "m", "belt width w (along the pulley axes)", lo=0, lo_open=True,
          hi=1.0),
    BELT["rho"],
    Param("bending", "on", str, doc="the plate's bending energy (Eq. 4.17; 'off': a membrane)",
          choices=("on", "off")),
    Param("elastic_points", 4, int, doc="Gauss points per direction of the elastic forces "
          "(n x n per plate)", lo=2, hi=8),
    BELT["length"], BELT["prestretch"], BELT["contact_offset"], BELT["formulation"],
)
#: each element's belt keys
BELT_KEYS = {"dufva2d": BELT, "plate36": PLATE_BELT}
#: pairs of belt keys of which exactly one is given
ONE_OF = (("E", "EA"), ("length", "prestretch"))

#: the keys of the pulley laws' time laws (ancf.belts.pulleys.TimeLaw.keys)
TIME_KEYS = _keys(
    Param("omega_final", REQUIRED, float, "rad/s", "final angular velocity", lo=-1e4, hi=1e4),
    Param("load_torque", REQUIRED, float, "N m", "(final) load torque T_a", lo=-1e5, hi=1e5),
    Param("t0", REQUIRED, float, "s", "start of the law", lo=0, hi=100),
    Param("t1", REQUIRED, float, "s", "end of the law (> t0)", lo=0, lo_open=True, hi=100),
    Table("speed_table", "rad/s", "angular velocity against time"),
    Table("load_table", "N m", "load torque T_a against time"),
)


def _zero(t):
    return np.zeros(np.shape(t))


@dataclass(frozen=True, kw_only=True)
class PulleyRole:
    """How a pulley turns (its drive-file ``law``) and what it brings to the model:
    ``keys`` its drive-file keys beyond :data:`PULLEY`'s (units, ranges, defaults);
    ``law_key`` the key naming its time law among ``laws`` (ancf.belts.pulleys.TimeLaw:
    the prescribed angular velocity rad/s, or the load torque N m of a free pulley; None:
    none, zero); ``free`` whether it turns freely (a coordinate with its ``inertia`` and
    ``damping``); ``arm`` whether it sits on a tensioner arm (one more coordinate,
    :mod:`ancf.belts.arm2d`, :mod:`ancf.belts.arm3d`); ``steady`` its entries of the steady
    reference's pulley (:func:`analytic.belt_steady.solve`) from its resolved keys;
    ``derive`` adds derived keys to the resolved ones (InputError naming the key)."""

    name: str
    keys: tuple = ()
    law_key: str | None = None
    laws: dict = field(default_factory=dict)
    free: bool = False
    arm: bool = False
    steady: Callable = lambda p: {}
    derive: Callable = lambda v, prefix: None

    def time_law(self, params: dict) -> Callable:
        """Its time law as a function of t (s, an array), from its resolved keys."""
        return self.laws[params[self.law_key]].of(params) if self.law_key else _zero


def _arm_length(v: dict, prefix: str) -> None:
    """A tensioner's arm length |centre - pivot| (m), refused when zero."""
    v["arm_length"] = math.dist(v["centre"], v["pivot"])
    if v["arm_length"] == 0:
        raise InputError(f"{prefix}pivot = {list(v['pivot'])!r} is the pulley's centre; "
                         "allowed: a point other than the centre")


_INERTIA = Param("inertia", REQUIRED, float, "kg m^2", "moment of inertia", lo=0, lo_open=True,
                 hi=1e3)
_DAMPING = Param("damping", REQUIRED, float, "N m s", "rotational damping", lo=0, hi=1e6)
#: every pulley law by name, in the order the drive-file messages list them
ROLES = {role.name: role for role in (
    PulleyRole(name="prescribed", law_key="speed", laws=FILE_SPEED_LAWS,
               keys=(Param("speed", REQUIRED, str, doc="speed law",
                           choices=tuple(FILE_SPEED_LAWS)),),
               steady=lambda p: {"omega": p["omega_final"]}),
    PulleyRole(name="driven", free=True, law_key="load", laws=FILE_TORQUE_LAWS,
               keys=(_INERTIA, _DAMPING,
                     Param("load", REQUIRED, str, doc="load torque law",
                           choices=tuple(FILE_TORQUE_LAWS)),
                     Param("load_acts", "signed", str, doc="how the load torque acts "
                           "(ancf.belts.pulleys.LOAD_LAWS): 'signed', T_a(t) against "
                           "counter-clockwise rotation whatever the pulley does; 'resisting', "
                           "|T_a(t)| tanh(omega / omega_reg) against its rotation (a brake: "
                           "it cannot drive the belt)", choices=tuple(LOAD_LAWS)),
                     Param("omega_reg", 0.1, float, "rad/s", "the resisting load's "
                           "regularising speed (tanh(omega / omega_reg); load_acts = "
                           "'resisting' only)", lo=0, lo_open=True, hi=1e3)),
               steady=lambda p: {"torque": p["load_torque"], "damping": p["damping"]}),
    PulleyRole(name="idler", free=True, keys=(_INERTIA, _DAMPING),
               steady=lambda p: {"damping": p["damping"]}),
    PulleyRole(name="tensioner", free=True, arm=True, derive=_arm_length, keys=(
        _INERTIA, _DAMPING, Vector("pivot", doc="the tensioner arm's pivot"),
        Param("arm_inertia", REQUIRED, float, "kg m^2", "the arm's moment of inertia about the "
              "pivot (with the pulley's mass)", lo=0, lo_open=True, hi=1e3),
        Param("arm_stiffness", REQUIRED, float, "N m/rad", "torsion spring stiffness", lo=0,
              lo_open=True, hi=1e7),
        Param("arm_preload", REQUIRED, float, "N m", "the spring's moment on the arm at the "
              "given centre (counter-clockwise positive)", lo=-1e5, hi=1e5),
        Param("arm_damping", REQUIRED, float, "N m s", "the arm's rotational damping", lo=0,
              hi=1e6)),
        steady=lambda p: {"damping": p["damping"], "pivot": p["pivot"],
                          "stiffness": p["arm_stiffness"], "preload": p["arm_preload"]}),
    PulleyRole(name="fixed"))}
LAWS = tuple(ROLES)
PULLEY = _keys(
    Param("name", REQUIRED, str, doc="the pulley's name"),
    Vector("centre", doc="centre"),
    Param("radius", REQUIRED, float, "m", "radius", lo=0, lo_open=True, hi=10),
    Param("side", 1, int, doc="+1: the belt's inner side on it, -1: its back", choices=(1, -1)),
    Param("law", REQUIRED, str, doc="how the pulley turns", choices=LAWS),
)
#: the keys of a pulley centre's prescribed motion, any pulley's (a tensioner's: its pivot's)
MOTION = _keys(
    Vector("centre_shift", (0.0, 0.0), "m", "the centre's displacement at the end of its "
           "motion ([0, 0]: it stays)"),
    Param("centre_shift_time", T0, float, "s", "when the centre reaches its shift (Eq. 4.46's "
          "t0)", lo=0, lo_open=True, hi=100),
    Param("centre_motion", "ramp", str, doc="the centre's motion law "
          "(ancf.belts.pulleys.CENTRE_LAWS; 'ramp': Eq. 4.46)", choices=tuple(CENTRE_LAWS)),
)
#: the largest misalignment of a pulley axis, deg: within it tan(angle) is the angle to 1 %
#: (the tracking rule's linear regime) and the belt laid on the aligned path lies within
#: (w / 2) sin(angle) <= 0.087 w of the turned face at its edges (settling puts it on)
MAX_ALIGN_DEG = 10.0
#: the plate belt's pulley axis misalignment (ancf.belts.tracking3d), any pulley's
ALIGNMENT = _keys(
    Param("axis_tilt_deg", 0.0, float, "deg", "the axis turned toward the running direction "
          "of the span entering the pulley (about the radius to that span's tangent point): "
          "the belt walks along the axis at -v tan(tilt) (ancf.belts.tracking3d)",
          lo=-MAX_ALIGN_DEG, hi=MAX_ALIGN_DEG),
    Param("axis_roll_deg", 0.0, float, "deg", "the axis turned toward the radius to the "
          "entering span's tangent point (about that span's direction; after the tilt)",
          lo=-MAX_ALIGN_DEG, hi=MAX_ALIGN_DEG),
)
#: a plate belt pulley's flanges (ancf.belts.flange3d), any pulley's but a tensioner's
FLANGES = _keys(
    Switch("flanges", False, "a side wall at each end of the pulley's face, penalty contact "
           "on the belt's edges (k_p h and c_p h per unit edge length; ancf.belts.flange3d)"),
    Param("face_width_m", 0.0, float, "m", "the face's width between the flanges (0: the "
          "belt's width b times 1.1, ancf.belts.flange3d.FACE_CLEARANCE; else at least b)",
          lo=0, hi=1.0),
    Param("flange_height_m", 0.005, float, "m", "the flanges' height above the rim (their "
          "stiffness tapers to 0 over its outer half)", lo=0, lo_open=True, hi=0.1),
    Param("crown_m", 0.0, float, "m", "the crown: the rim's radius rise at mid-face, "
          "R(a) = R + crown_m (1 - (2 a / W)^2) at the axial offset a from mid-face, W the "
          "face width (face_width_m; ancf.belts.contact3d_state); the parabola continues past "
          "the face's ends, so the contact force stays smooth; below the radius, and its "
          "slope at the face's ends 4 crown_m / W at most 0.1 (ancf.belts.tracking3d."
          "MAX_CROWN_SLOPE)", lo=0, hi=1.0),
    Param("face_offset_m", 0.0, float, "m", "the face's mid-plane (its crown's and flanges') "
          "displaced along the axis from the belt's laid mid-line (a belt that starts "
          "off-centre by -face_offset_m); at most W / 2 (the belt's mid-line on the face), "
          "with flanges (W - b) / 2 (the belt between them)", lo=-0.5, hi=0.5),
)
#: every key a pulley law or its time law may take (beyond PULLEY's)
LAW_PARAMS = {**{k.name: k for role in ROLES.values() for k in role.keys}, **TIME_KEYS}
#: the keys of each pulley law (beyond PULLEY's); its time law adds that law's keys
LAW_KEYS = {name: tuple(k.name for k in role.keys) for name, role in ROLES.items()}


#: each friction law's parameters (ancf.belts.friction.ALL_PARAMS), all required
FRICTION_KEYS = {law: _keys(*(replace(q, default=REQUIRED) for q in params))
                 for law, params in friction.ALL_PARAMS.items()}
#: a unit per unit length of belt (2D) -> per unit area (the plate belt)
PER_AREA = {"kg/(m s)": "kg/(m^2 s)", "N/m^2": "N/m^3", "N s/m^2": "N s/m^3"}
#: each element's friction laws and their parameters (the plate belt's per unit area)
ELEMENT_FRICTION = {
    "dufva2d": FRICTION_KEYS,
    "plate36": {law: {k: replace(q, unit=PER_AREA.get(q.unit, q.unit)) for k, q in keys.items()}
                for law, keys in FRICTION_KEYS.items()}}

CONTACT = _keys(
    Param("k_p", REQUIRED, float, "N/m^2", "penalty stiffness per unit length", lo=0,
          lo_open=True, hi=1e12),
    Param("c_p", 0.0, float, "N s/m^2", "penalty damping per unit length", lo=0, hi=1e8),
    Param("gauss_points", 7, int, doc="contact Gauss points per element", choices=SUPPORTED_POINTS),
)

#: each element's contact keys (the plate belt's per unit area of its mid surface)
CONTACT_KEYS = {"dufva2d": CONTACT, "plate36": _keys(
    Param("k_p", REQUIRED, float, "N/m^3", "penalty stiffness per unit area", lo=0,
          lo_open=True, hi=1e13),
    Param("c_p", 0.0, float, "N s/m^3", "penalty damping per unit area", lo=0, hi=1e9),
    Param("gauss_points", 81, int, doc="contact points per plate (n x n Gauss rule over its "
          "mid surface)", choices=SUPPORTED_RULES),
)}

RUN = _keys(
    Param("t_end", REQUIRED, float, "s", "simulated time", lo=0, lo_open=True, hi=100),
    Param("dt", REQUIRED, float, "s", "time step", lo=1e-7, hi=1e-2),
    Param("output_dt", 0.005, float, "s", "sampling interval (at most t_end)", lo=0,
          lo_open=True, hi=10),
    Param("steady_window", 0.1, float, "s", "averaging window before t_end (at most t_end)",
          lo=0, lo_open=True, hi=100),
    Param("start", "settled", str, doc="'settled': at rest on the pulleys first; 'laid': on "
          "the wrapped path", choices=("settled", "laid")),
    Param("rho_inf", 0.5, float, "-", "generalized-alpha spectral radius", lo=0, hi=1),
    Param("newton_tol", 1e-7, float, "-", "Newton tolerance", lo=1e-14, hi=1e-3),
    Param("max_steps", 400_000, int, doc="step budget", lo=1, hi=MAX_STEPS),
    Param("refresh_ratio", REFRESH_RATIO, float, "-", "modified Newton: the kept iteration "
          "matrix is refactored when an increment exceeds this fraction of the one before",
          lo=0.1, hi=0.95),
    Param("newton_accept", ACCEPT[0], str, doc="the converged step's state: 'applied', the "
          "iterate after the last increment; 'evaluated', the last evaluated iterate once the "
          "increment from it is below newton_tol (one residual evaluation fewer per step)",
          choices=ACCEPT),
    Param("refresh", REFRESH[0], str, doc="modified Newton: 'contraction', an increment above "
          "refresh_ratio of the one before refactors the iteration matrix; 'once', only if it "
          "was not refactored within the step yet (a growing or damped increment always does)",
          choices=REFRESH),
    Param("give_up", 0, int, doc="modified Newton: a step whose residual has not halved by "
          "its give_up-th damped increment (a contact point cycling across the jump of its "
          "damping force) is given up and halved at once; 0: never (it iterates to its "
          "limit); the Lagrangian march's", lo=0, hi=12),
    Param("damping_jacobian", DAMPING_JACOBIANS[0], str, doc="the belt damping's part of the "
          "iteration matrix: 'exact', or 'rate' (dQ_d/dz' only, dQ_d/dz left out: the same "
          "residual, a cheaper matrix)", choices=DAMPING_JACOBIANS),
)

@dataclass(frozen=True)
class PulleySpec:
    """One pulley: name, centre (m), radius (m), side, law and the law's keys (SI units)."""

    name: str
    centre: tuple
    radius: float
    side: int
    law: str
    params: dict


@dataclass(frozen=True)
class DriveDescription:
    """A validated drive: every key of every table resolved (defaults filled in; the belt
    with both E and EA, both length and prestretch), the pulleys in running order and
    the belt centreline's wrapped path (radius + contact_offset)."""

    belt: dict
    pulleys: tuple
    friction: dict
    contact: dict
    run: dict
    gravity: tuple
    path: PulleyPath


def laid_factor(belt: dict) -> float:
    """The factor (-) from the file's section constants to the element's: 1, or
    1 + prestretch when ``strain_reference`` is ``laid``.  Exudyn's cable on its laid
    length s = x / (1 + prestretch) (x the stress-free length): the slope |r'| = (1 +
    prestretch) |r_x|, so its force EA (|r'| - 1 - prestretch) is E A (1 + prestretch)
    (|r_x| - 1); its energies and damping per ds, with its curvature and strain rates,
    are those per dx times 1 + prestretch alike.  A plate belt (``plate36``) has no
    ``strain_reference``: its membrane is on the stress-free length (1)."""
    return 1.0 + belt["prestretch"] if belt.get("strain_reference") == "laid" else 1.0


def element_modulus(belt: dict) -> float:
    """Young's modulus the element gets (Pa) from a resolved belt table: E times
    :func:`laid_factor`."""
    return belt["E"] * laid_factor(belt)


def time_law(pulley: PulleySpec) -> Callable:
    """The pulley's time law (t an array of s): a prescribed pulley's omega(t) (rad/s), a
    driven one's load torque T_a(t) (N m), else zero (:meth:`PulleyRole.time_law`)."""
    return ROLES[pulley.law].time_law(pulley.params)


def centre_motion(pulley: PulleySpec, index: int, dim: int = 2) -> CentreMotion | None:
    """The prescribed motion of pulley ``index``'s centre (direction in ``dim``
    dimensions, the x-y plane), or None if its ``centre_shift`` is zero."""
    shift = pulley.params["centre_shift"]
    distance = math.hypot(*shift)
    if distance == 0:
        return None
    direction = np.zeros(dim)
    direction[:2] = [x / distance for x in shift]
    law = CENTRE_LAWS[pulley.params["centre_motion"]]
    return CentreMotion(pulley=index, direction=direction, law=law.of(distance, pulley.params))


def shifted(pulley: PulleySpec) -> tuple:
    """The pulley's centre at the end of its prescribed motion, m."""
    return tuple(c + d for c, d in zip(pulley.centre, pulley.params["centre_shift"]))
