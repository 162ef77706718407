"""Drive files (ancf.belts.drive_file, ancf.belts.drive_data): the shipped examples (the
thesis drive equal to belt2d's defaults key for key, the THREAD benchmark's derived
numbers, the serpentine drive's tensioner in balance), overrides, the laws a description
turns into, and every bad input as one line naming the file key and its allowed range."""
from __future__ import annotations

import math

import numpy as np
import pytest

from ancf.belts import drive_data as dd
from ancf.belts import friction, pulleys
from ancf.belts.drive2d import BeltSpec
from ancf.belts.drive_file import describe, load, override, read
from ancf.belts.path import laid_belt
from ancf.common.params import InputError
from ancf.common.paths import REPO
from ancf.scenes import SCENES
from ancf.scenes import belt2d, belt_common

EXAMPLES = REPO / "examples"
THESIS, THREAD, SERPENTINE = (EXAMPLES / f"{n}.toml" for n in
                              ("thesis_table_3_1", "thread_benchmark", "serpentine"))


# ------------------------------------------------------------------ the examples

def test_thesis_example_is_belt2d_defaults_key_for_key():
    """Every parameter of ``ancf run belt2d`` that defines the drive has its value in the
    file (the BDF cross-check's integrator, rtol, atol are not the drive's), and the belt
    laid on the file's path is belt2d's laid belt, bit for bit."""
    d, p = load(THESIS), SCENES["belt2d"].resolve({})
    driver, driven = d.pulleys
    got = {k: d.belt[k] for k in ("n_elements", "E", "nu", "rho", "h", "b", "ks", "alpha1",
                                  "alpha2", "elastic_points")}
    got.update(belt_length=d.belt["length"], R1=driver.radius, R2=driven.radius,
               inertia=driven.params["inertia"], omega_final=driver.params["omega_final"],
               Ta_max=driven.params["load_torque"], **{k: d.contact[k] for k in d.contact},
               **{k: d.friction[k] for k in ("mu", "nu_s")},
               **{k: d.run[k] for k in ("start", "dt", "rho_inf", "newton_tol", "t_end",
                                        "output_dt", "max_steps")})
    assert set(got) == set(p) - {"integrator", "rtol", "atol"}
    want = dict(p, belt_length=belt_common.belt_length(p))
    assert got == {k: want[k] for k in got}
    spec = belt2d.spec(p)
    X = belt_common.X_CENTRE
    assert (driver.centre, driven.centre) == ((-X, 0.0), (X, 0.0))
    assert (driver.params["speed"], driven.params["load"]) == (spec.driver_law, spec.torque_law)
    assert (driver.params["t0"], driver.params["t1"]) == (pulleys.T0, pulleys.T1)
    assert (driven.params["t0"], driven.params["t1"]) == (pulleys.T0, pulleys.T1)
    assert driven.params["damping"] == 0
    assert d.belt["damping_axial"] == d.belt["damping_bending"] == 0
    assert d.friction["law"] == friction.LAW and d.gravity == (0.0, 0.0)
    assert d.run["steady_window"] == belt2d.STEADY_WINDOW
    assert d.belt["contact_offset"] == 0.0
    assert laid_belt(d.path, d.belt["length"], 20).tobytes() == \
        laid_belt(spec.path, spec.belt_length, 20).tobytes()
    assert isinstance(spec, BeltSpec)


def test_thread_example_names_the_bristle_law_and_reaches_the_kernel_with_it():
    """The file's [friction] is the bristle law with its point law's parameters in order;
    the model's prm carries its code and values, and its belt the state per contact
    point (element, Gauss point, pulley) the march steps (tests/belts/test_bristle.py)."""
    from ancf.belts.drive_model import build
    d = load(THREAD, ["belt.damping_axial=0"])
    keys = [k for k in read(THREAD)["friction"] if k != "law"]
    assert keys == [q.name for q in friction.STATE_PARAMS["bristle"]]
    drive = build(d)
    f, c = d.friction, d.contact
    assert np.array_equal(drive.prm, friction.contact_record(
        c["k_p"], c["c_p"], "bristle", f["mu"], f["stiffness"], f["damping"]))
    assert friction.has_state(drive.prm)
    assert drive.kernel().z.shape == (2, d.belt["n_elements"], c["gauss_points"], 2)


def test_thread_example_has_the_benchmark_numbers():
    """The file's typed numbers give the benchmark's: the path at radius 0.09995 + 5e-5 m is 0.4 pi m,
    the stress-free belt 0.38 pi m, E = 1e7 Pa, EI = 4/3e-3 N m^2, the driver ramps to
    12 rad/s over 0.05-0.6 s and the load is 25 (0.5 - 0.5 cos 2 pi (t - 1)) N m on
    1-1.5 s, 25 N m after (THREAD's description, its Eqs for omega_P1 and tau_P2)."""
    d = load(THREAD)
    driver, driven = d.pulleys
    assert driven.centre == (0.1 * math.pi, 0.0)
    assert d.path.length == pytest.approx(0.4 * math.pi, rel=1e-14)
    assert d.belt["length"] == pytest.approx(0.38 * math.pi, rel=1e-14)
    assert d.belt["E"] == pytest.approx(1e7, rel=1e-14)
    b, h = d.belt["b"], d.belt["h"]
    assert d.belt["alpha2"] * d.belt["E"] * b * h**3 / 12 == pytest.approx(4e-3 / 3, rel=1e-14)
    t = np.array([0.0, 0.05, 0.3, 0.6, 0.9, 1.0, 1.2, 1.3, 1.5, 2.0])
    omega = np.where(t < 0.05, 0.0, np.where(t < 0.6, 12 * (t - 0.05) / 0.55, 12.0))
    assert dd.time_law(driver)(t) == pytest.approx(omega, abs=1e-13)
    step = 25 * (0.5 - 0.5 * np.cos(2 * np.pi * (t - 1)))
    tau = np.where(t < 1, 0.0, np.where(t < 1.5, step, 25))
    assert dd.time_law(driven)(t) == pytest.approx(tau, abs=1e-12)
    assert d.gravity == (0.0, -9.81) and driven.params["damping"] == 2.0
    # the bristle per unit length: 5e9 N/m^3 x b, and 10 sqrt(1e8 N/m^3 b rho A) (the stored
    # base solution's per-segment values over its segment 0.4 pi / 960 m)
    rho_A = d.belt["rho"] * b * h
    assert d.friction["stiffness"] == pytest.approx(5e9 * b, rel=1e-14)
    assert d.friction["damping"] == pytest.approx(10 * math.sqrt(1e8 * b * rho_A), rel=1e-5)
    assert d.friction["damping"] == pytest.approx(33.70609928242229 / (0.4 * math.pi / 960),
                                                  rel=1e-5)


def test_serpentine_example_tensioner_balances_the_laid_belt():
    """Five pulleys, two on the belt's back, all wrapped; the arm's preload balances the
    moment about the pivot of the laid belt's tension EA (P/L0 - 1) on the tensioner
    (the two spans' pull T (d_out - d_in)) within 1 %."""
    d = load(SERPENTINE)
    assert [p.law for p in d.pulleys] == ["prescribed", "tensioner", "driven", "idler", "driven"]
    assert [p.side for p in d.pulleys] == [1, -1, 1, -1, 1]
    assert min(d.path.wraps) > math.radians(20)
    k = 1
    ten = d.pulleys[k]
    (into, out) = d.path.spans[k - 1], d.path.spans[k]
    pull = (out.end - out.start) / out.length - (into.end - into.start) / into.length
    T = d.belt["EA"] * (d.path.length / d.belt["length"] - 1)
    arm = np.subtract(ten.centre, ten.params["pivot"])
    moment = T * (arm[0] * pull[1] - arm[1] * pull[0])
    assert ten.params["arm_preload"] == pytest.approx(-moment, rel=1e-2)
    assert ten.params["arm_length"] == pytest.approx(np.hypot(*arm), rel=1e-15)


def test_every_friction_law_declares_its_parameters():
    assert set(friction.PARAMS) == set(friction.LAWS)
    assert set(friction.STATE_PARAMS) == set(friction.STATE_LAWS)
    assert set(dd.FRICTION_KEYS) == set(friction.ALL_PARAMS) == \
        set(friction.LAWS) | set(friction.STATE_LAWS)


def test_the_friction_law_a_file_names_reaches_the_kernel():
    """[friction] law = "coulomb" with its mu, v_reg: the model's prm carries the law's
    code and parameters, and the compiled kernel's friction on the laid belt, pressed
    0.1 % into the pulleys and sliding, is -mu F_n tanh(v_t / v_reg) (numpy)
    wherever F_n > 0 (to 64 ulps of the largest)."""
    from ancf.belts.contact2d import contact_state
    from ancf.belts.drive_model import build
    data = read(THESIS)
    data["friction"] = {"law": "coulomb", "mu": 0.7, "v_reg": 0.05}
    drive = build(describe(data))
    c = data["contact"]
    assert np.array_equal(drive.prm, friction.contact_record(c["k_p"], c["c_p"], "coulomb", 0.7,
                                                             0.05))
    rng = np.random.default_rng(5)
    E = drive.element_coords(drive.q0 * (1 - 1e-3))
    V = 0.05 * rng.standard_normal(E.shape)
    _, _, Fn, phi, vt = contact_state(E, V, drive.S0, drive.centres, drive.radii,
                                      np.array([0.3, -0.3]), drive.prm)
    ref = -0.7 * Fn * np.tanh(vt / 0.05)
    assert (Fn > 0).sum() > 20 and np.any(np.abs(vt) < 0.05) and np.any(np.abs(vt) > 0.05)
    np.testing.assert_allclose(phi, ref, rtol=0, atol=64 * np.finfo(float).eps * np.abs(ref).max())


def test_tables_and_constants_become_laws_of_time():
    data = override(read(THESIS), ["pulleys.driven.load=constant", "pulleys.driven.load_torque=3"])
    for key in ("t0", "t1"):
        del data["pulleys"][1][key]
    data["pulleys"][0] = {k: v for k, v in data["pulleys"][0].items()
                          if k not in ("omega_final", "t0", "t1")}
    data["pulleys"][0].update(speed="table", speed_table=[[0.0, 0.0], [0.5, 10.0], [1.0, 10.0]])
    d = describe(data)
    t = np.array([0.0, 0.25, 0.5, 2.0])
    assert dd.time_law(d.pulleys[0])(t) == pytest.approx([0.0, 5.0, 10.0, 10.0], abs=1e-14)
    assert dd.time_law(d.pulleys[1])(t) == pytest.approx([3.0] * 4, abs=0)


# ------------------------------------------------------------------ overrides

def test_overrides_set_any_key_before_validation():
    d = load(THESIS, ["friction.mu=1.0", "contact.k_p=4e8", "pulleys.1.inertia=0.5",
                      "pulleys.driver.omega_final=120", "gravity=[0, -9.81]", "run.start=laid",
                      "belt.n_elements=30"])
    assert d.friction["mu"] == 1.0 and d.contact["k_p"] == 4e8
    assert d.pulleys[1].params["inertia"] == 0.5 and d.pulleys[0].params["omega_final"] == 120.0
    assert d.gravity == (0.0, -9.81) and d.run["start"] == "laid" and d.belt["n_elements"] == 30
    assert read(THESIS)["friction"]["mu"] == 1.2  # the file's data are not changed


@pytest.mark.parametrize("item, message", [
    ("friction.mu", "--set 'friction.mu': expected key=value"),
    ("belt..E=1", "--set 'belt..E=1': expected key=value"),
    ("belt.E.x=1", "belt.E.x: not a key; allowed: gravity, section.key or pulleys.<index or "
                   "name>.key"),
    ("pulleys.7.inertia=1", r"pulleys.7: no such pulley; allowed: an index 0-1 or a name "
                            r"\(driver, driven\)"),
    ("pulleys.nope.inertia=1", "pulleys.nope: no such pulley"),
    ("gravity.x=1", r"gravity: \[0.0, 0.0\] is not a table; allowed: a table"),
])
def test_bad_overrides_are_one_line(item, message):
    with pytest.raises(InputError, match=message):
        load(THESIS, [item])


# ------------------------------------------------------------------ bad input

def _without(path: tuple):
    def edit(data):
        table = data
        for key in path[:-1]:
            table = table[key]
        del table[path[-1]]
    return edit


def _set(path: tuple, value):
    def edit(data):
        table = data
        for key in path[:-1]:
            table = table[key]
        table[path[-1]] = value
    return edit


def _stiff_thin_belt(data):
    """EA = 1e10 N on a 0.01 x 0.001 m section: E = 1e15 Pa (to rounding)."""
    del data["belt"]["E"]
    data["belt"].update(EA=1e10, h=1e-3)


IDLER = {"name": "idler", "centre": [0.0, 0.3], "radius": 0.03, "side": -1, "law": "idler",
         "inertia": 1e-4, "damping": 0.0}

BAD = [  # (overrides, or an edit of the thesis file's data; the one line it gives)
    (["belt.Ee=1"], r"belt.Ee: unknown key \(element 'dufva2d'\); allowed: element, "
     "n_elements, E, EA, nu,"),
    (["belt.bending=on"], r"belt.bending: unknown key \(element 'dufva2d'\); allowed:"),
    (["belt.element=belt3d"], "belt.element = 'belt3d' is out of range; allowed: one of "
     "dufva2d, plate36"),
    (["beltt.E=1"], "beltt: unknown key; allowed: gravity, belt, pulleys, friction, contact, run"),
    (_without(("pulleys", 1, "inertia")), r"pulleys.1.inertia: missing \(law 'driven': inertia, "
     r"damping, load, load_acts, omega_reg, load_torque, t0, t1\); allowed: a number in "
     r"\(0, 1000\] kg m\^2"),
    (["pulleys.0.inertia=1"], r"pulleys.0.inertia: unknown key \(law 'prescribed': speed, "
     r"omega_final, t0, t1\); allowed: name, centre, radius, side, law, speed, omega_final"),
    (["pulleys.0.law=spinning"], "pulleys.0.law = 'spinning' is out of range; allowed: one of "
     "prescribed, driven, idler, tensioner, fixed"),
    (["pulleys.0.speed=jump"], "pulleys.0.speed = 'jump' is out of range; allowed: one of "
     "ramp, table"),
    (["pulleys.1.load=jump"], "pulleys.1.load = 'jump' is out of range; allowed: one of "
     "cosine-ramp, cosine-step, constant, table"),
    (["friction.law=lugre"], "friction.law = 'lugre' is out of range; allowed: one of "
     "creep-rate, coulomb, bristle"),
    (["friction.law=bristle"], r"friction.nu_s: unknown key \(law 'bristle'\); allowed: law, "
     "mu, stiffness, damping"),
    (_without(("friction", "mu")), r"friction.mu: missing \(law 'creep-rate'\); allowed: a "
     r"number in \[0, 10\] -"),
    (_without(("friction", "law")), "friction.law: missing; allowed: one of creep-rate"),
    (_set(("friction", "law"), "coulomb"), r"friction.nu_s: unknown key \(law 'coulomb'\); "
     "allowed: law, mu, v_reg"),
    (_set(("friction",), {"law": "coulomb", "mu": 0.5}), r"friction.v_reg: missing \(law "
     r"'coulomb'\); allowed: a number in \(0, 1000\] m/s"),
    (_set(("friction",), {"law": "coulomb", "mu": 0.5, "v_reg": 0.0}), r"friction.v_reg = 0.0 "
     r"is out of range; allowed: a number in \(0, 1000\]"),
    (["belt.E=-1"], r"belt.E = -1.0 is out of range; allowed: a number in \(0, 1e\+12\]"),
    (["belt.n_elements=many"], r"belt.n_elements: 'many' is not valid; allowed: an integer "
     r"in \[4, 2000\]"),
    (["contact.gauss_points=6"], "contact.gauss_points = 6 is out of range; allowed: one of "
     "3, 4, 5, 7, 11"),
    (["belt.EA=1e4"], "belt.E, belt.EA: both given; allowed: exactly one"),
    (_without(("belt", "E")), r"belt.E: missing \(or belt.EA\); allowed: a number in "
     r"\(0, 1e\+12\] Pa"),
    (_stiff_thin_belt, r"belt.EA / \(b h\) = [0-9.e+]+ is out of range; allowed: a number in "
     r"\(0, 1e\+12\]"),
    (["belt.prestretch=-0.01"], "belt.length, belt.prestretch: both given; allowed: exactly one"),
    (["belt.prestretch=-0.6"], r"belt.prestretch = -0.6 is out of range; allowed: a number in "
     r"\[-0.5, 0\]"),
    (["pulleys.1.centre=[-0.1, 0.0]"], "pulleys: pulleys 'driver' and 'driven' overlap: centre "
     "distance 0.091441 m; allowed: more than the sum of their radii 0.1625 m"),
    (["belt.length=0.6"], r"belt.length = 0.6 is out of range for the wrapped path \(1.27627 m\); "
     r"allowed: a number in \[0.638136, 1.27627\] m"),
    (["belt.length=1.3"], r"belt.length = 1.3 is out of range for the wrapped path"),
    (lambda data: data["pulleys"].append(dict(IDLER)),  # above the upper span, not touching
     "pulleys: pulley 'idler' cannot be wrapped: the belt would turn .* deg around it and 0 "
     "times around the loop; allowed: one counter-clockwise turn"),
    (lambda data: data["pulleys"].append(dict(IDLER, centre=[0.0, 0.11125])),  # touching it
     "pulleys: pulley 'idler' is not wrapped: the belt passes it in a straight line"),
    (["pulleys.0.t1=0.01"], "pulleys.0.t1 = 0.01 is out of range; allowed: a number > t0 = 0.05 s"),
    (["pulleys.0.speed=table"], r"pulleys.0.omega_final: unknown key \(law 'prescribed': speed, "
     r"speed_table\)"),
    (_set(("pulleys", 1), {"name": "driven", "centre": [0.191441, 0.0], "radius": 0.08125,
                           "law": "driven", "inertia": 0.1, "damping": 0.0, "load": "table",
                           "load_table": [[0.0, 1.0], [0.0, 2.0]]}),
     r"pulleys.1.load_table = \[\[0.0, 1.0\], \[0.0, 2.0\]\] is out of range; allowed: "
     r"\[\[t, value\], ...\], at least 2 rows of finite numbers, t \(s\) from 0 up and "
     r"increasing, value N m"),
    (["pulleys.1.name=driver"], "pulleys.1.name = 'driver' is the name of pulley 0; allowed: "
     "a name used once"),
    (_set(("pulleys", 0), {"name": "driver", "centre": [-0.191441, 0.0], "radius": 0.08125,
                           "law": "fixed"}),
     r"pulleys: no pulley has law = 'prescribed'; allowed: at least one \(the driver\)"),
    (_set(("pulleys",), []), "pulleys: 0 given; allowed: an array of at least 2 tables"),
    (_without(("pulleys",)), "pulleys: missing or not an array; allowed: an array of at least "
     "2 tables"),
    (["pulleys.0.centre=[0]"], r"pulleys.0.centre = \[0\] is out of range; allowed: \[x, y\], "
     r"two numbers in \[-1000, 1000\] m"),
    (["gravity=[0, 1, 2]"], r"gravity = \[0, 1, 2\] is out of range; allowed: \[x, y\], two "
     r"numbers in \[-1000, 1000\] m/s\^2"),
    (["pulleys.0.side=0"], "pulleys.0.side = 0 is out of range; allowed: one of 1, -1"),
    (["run.output_dt=2"], r"run.output_dt = 2.0 is out of range; allowed: a number in "
     r"\[t_end/100000, t_end\] = \[1e-05, 1\] s"),
    (["run.dt=0.01"], r"run.dt = 0.01 is out of range; allowed: a number in "
     r"\[t_end/10000000, output_dt\] = \[1e-07, 0.005\] s"),
    (["run.steady_window=2"], r"run.steady_window = 2.0 is out of range; allowed: a number in "
     r"\(0, t_end = 1\] s"),
    (_without(("run", "t_end")), r"run.t_end: missing; allowed: a number in \(0, 100\] s"),
    (["belt.formulation=eulerian"], "belt.formulation = 'eulerian' is out of range; "
     "allowed: one of lagrangian, ale"),
    (_set(("belt",), 5), r"belt: 5 is not a table; allowed: a table \[belt\]"),
    (_set(("pulleys", 1), 5), r"pulleys.1: 5 is not a table; allowed: a table \[\[pulleys\]\]"),
]


def _one_line(path, bad, message):
    """``bad`` (overrides, or an edit of the file's data) gives one line matching ``message``."""
    data = read(path)
    with pytest.raises(InputError, match=message) as exc:
        if callable(bad):
            bad(data)
            describe(data)
        else:
            describe(override(data, bad))
    assert "\n" not in str(exc.value) and "allowed:" in str(exc.value)


@pytest.mark.parametrize("bad, message", BAD, ids=[m.split(":")[0].split(" ")[0] + f"-{i}"
                                                   for i, (_, m) in enumerate(BAD)])
def test_bad_input_is_one_line_naming_the_key(bad, message):
    _one_line(THESIS, bad, message)


PLATE = EXAMPLES / "three_pulleys_3d.toml"
BAD_PLATE = [  # (overrides, or an edit of the 3D example's data; the one line it gives)
    (["belt.bending=sometimes"], "belt.bending = 'sometimes' is out of range; allowed: one "
     "of on, off"),
    (["belt.elastic_points=1"], r"belt.elastic_points = 1 is out of range; allowed: an "
     r"integer in \[2, 8\]"),
    (["belt.h=0.2"], r"belt.h = 0.2 is out of range; allowed: a number in \(0, 0.1\]"),
    (["belt.b=0"], r"belt.b = 0.0 is out of range; allowed: a number in \(0, 1\]"),
    (["belt.nu=0.5"], r"belt.nu = 0.5 is out of range; allowed: a number in \[0, 0.5\)"),
    (["belt.n_elements=201"], r"belt.n_elements = 201 is out of range; allowed: an integer "
     r"in \[4, 200\]"),
    (["belt.alpha1=1"], r"belt.alpha1: unknown key \(element 'plate36'\); allowed: element, "
     "n_elements, E, EA, nu, h, b, rho, bending, elastic_points, length, prestretch, "
     "contact_offset"),
    (["belt.damping_axial=1"], r"belt.damping_axial: unknown key \(element 'plate36'\)"),
    (["contact.gauss_points=7"], "contact.gauss_points = 7 is out of range; allowed: one of "
     "25, 49, 81"),
    (["contact.k_p=0"], r"contact.k_p = 0.0 is out of range; allowed: a number in "
     r"\(0, 1e\+13\]"),
    (["contact.c_p=-1"], r"contact.c_p = -1.0 is out of range; allowed: a number in "
     r"\[0, 1e\+09\]"),
    (_without(("contact", "k_p")), r"contact.k_p: missing \(element 'plate36'\); allowed: a "
     r"number in \(0, 1e\+13\] N/m\^3"),
    (_without(("friction", "nu_s")), r"friction.nu_s: missing \(law 'creep-rate'\); allowed: "
     r"a number in \(0, 1e\+09\] kg/\(m\^2 s\)"),
    (["pulleys.idler.law=tensioner"], r"pulleys.1.pivot: missing \(law 'tensioner': "),
    (["friction.law=bristle", "pulleys.idler.law=tensioner", "pulleys.idler.pivot=[0.0185, -0.08]",
      "pulleys.idler.arm_inertia=1e-5", "pulleys.idler.arm_stiffness=5.0",
      "pulleys.idler.arm_preload=-2.0", "pulleys.idler.arm_damping=0.03"],
     r"friction.law = 'bristle' is out of range for belt.element = 'plate36'; allowed: one of "
     r"creep-rate, coulomb \(a law with a state per contact point is not carried by the plate "
     r"belt's tensioner arms\)"),
]


@pytest.mark.parametrize("bad, message", BAD_PLATE,
                         ids=[m.split(" ")[0].rstrip(":") + f"-{i}"
                              for i, (_, m) in enumerate(BAD_PLATE)])
def test_bad_plate_belt_input_is_one_line_naming_the_key(bad, message):
    _one_line(PLATE, bad, message)


def test_a_tensioner_pivot_at_its_centre_is_refused():
    data = read(SERPENTINE)
    data["pulleys"][1]["pivot"] = data["pulleys"][1]["centre"]
    with pytest.raises(InputError, match=r"pulleys.1.pivot = \[0.155, 0.095\] is the pulley's "
                                         "centre; allowed: a point other than the centre"):
        describe(data)


def test_a_contact_offset_is_named_when_the_path_fails(tmp_path):
    with pytest.raises(InputError, match=r"pulleys: pulleys 'driver' and 'driven' overlap: .*"
                                         r"\(the belt's centreline at radius \+ "
                                         r"belt.contact_offset = 0.02 m\)"):
        load(THESIS, ["belt.contact_offset=0.02", "pulleys.1.centre=[0.0, 0.0]"])


@pytest.mark.parametrize("content, message", [
    (b"[belt\nE = 1\n", r"malformed TOML: .*\(at line 1, column 6\); allowed: a TOML drive file"),
    (b"[belt]\nE = = 1\n", r"malformed TOML: .*\(at line 2, column 5\)"),
    (b"\xff\xfe[belt]\n", "not UTF-8 text; allowed: a TOML drive file"),
])
def test_a_malformed_file_is_one_line_with_its_place(tmp_path, content, message):
    f = tmp_path / "drive.toml"
    f.write_bytes(content)
    with pytest.raises(InputError, match=message) as exc:
        load(f)
    assert str(exc.value).startswith(str(f)) and "\n" not in str(exc.value)


def test_a_missing_file_or_a_directory_is_one_line(tmp_path):
    with pytest.raises(InputError, match="nope.toml: no such file; allowed: a TOML drive file"):
        load(tmp_path / "nope.toml")
    with pytest.raises(InputError, match=r"cannot be read \(Is a directory\); allowed: a "
                                         "readable TOML drive file"):
        load(tmp_path)


def test_thread_example_takes_exudyns_cable_law_on_the_laid_stiffness():
    """THREAD's file states Exudyn's law: the engineering strain, EA per laid length, so
    the element gets E (1 + prestretch) = 0.95e7 Pa (EA 7600 N), computed from the file's
    E and prestretch; the thesis's file keeps the Green law on its own E."""
    from ancf.belts import drive_model
    d = load(THREAD)
    assert (d.belt["axial_strain"], d.belt["strain_reference"]) == ("engineering", "laid")
    E_el = d.belt["E"] * (1.0 + d.belt["prestretch"])
    assert dd.element_modulus(d.belt) == pytest.approx(0.95e7, rel=1e-14) == E_el
    s = drive_model.spec(d)
    assert s.E == E_el and s.axial == "engineering"
    damping = drive_model.build(d).strain_damping
    assert damping[0] == d.belt["damping_axial"] * (1.0 + d.belt["prestretch"]) == 0.95
    thesis = load(THESIS)
    assert (thesis.belt["axial_strain"], thesis.belt["strain_reference"]) == ("green",
                                                                               "stress-free")
    assert drive_model.spec(thesis).E == thesis.belt["E"]
    assert drive_model.spec(thesis).axial == "green"
    stress_free = load(THREAD, ["belt.strain_reference=stress-free"])
    assert dd.element_modulus(stress_free.belt) == stress_free.belt["E"]


@pytest.mark.parametrize("key", ["axial_strain", "strain_reference"])
def test_axial_law_keys_refuse_unknown_values(key):
    with pytest.raises(InputError, match=f"^belt.{key} = 'log' is out of range; allowed: one of"):
        load(THREAD, [f"belt.{key}=log"])
