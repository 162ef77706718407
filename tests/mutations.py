"""Deliberate bugs, one at a time: each must fail the test(s) named next to it.

    .venv/bin/python tests/mutations.py [NAME ...] [--out FILE]    # from the project root

For each mutation: copy the checkout to a fixed temporary folder (file times kept, so
numba's cache there, NUMBA_CACHE_DIR, serves the untouched modules from one mutation to
the next; a mutated file holding compiled code gets an empty cache), replace one string in
one source file there (it must occur exactly once) or, for a file of ``EVERYWHERE``,
every occurrence of it in every ``.py`` file of the package (``ancf/`` and ``analytic/``:
a constant changed consistently in scenes and references alike), run the named tests
in the copy with a time limit, and print a markdown row: caught (the failing test and
its first assertion) or missed.  The checkout itself is never written.  Exit code 0
when every mutation was caught.  Not collected by pytest (no ``test_`` prefix).
``--out FILE`` also writes the table to FILE; ``--fast`` runs only the named tests that are
not marked slow (the fast tier, ``make test-fast``), so a row says whether that tier catches it.  One run at a time (the copy's path is fixed).
"""
from __future__ import annotations

import os
import shutil
import subprocess
import sys
import tempfile
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
EVERYWHERE = "ancf/ analytic/"   # every .py file of the package
PACKAGE = ("ancf", "analytic")
TIME_LIMIT = 900  # s per mutation (all its tests)
WORK = Path(tempfile.gettempdir()) / "ancf-mutations"
FAST = []  # ["-m", "not slow"] with --fast: only the fast tier's tests (make test-fast) of those named
TD, TP = "tests/scenes/test_dynamics.py::", "tests/scenes/test_published_tables.py::"
TA = "tests/analytic/test_analytic.py::"
TB = "tests/belts/test_belt_drive.py::"
T3 = "tests/belts/test_contact3d.py::"
TM = "tests/scenes/test_modes.py::"
TPIN = "tests/scenes/test_pinned.py::"
TW = "tests/belts/test_belt_wiring.py::"


def plus_1_percent(before: str, value: str, after: str = "") -> tuple[str, str]:
    """(old, new) source text with the literal ``value`` raised by 1 %."""
    return f"{before}{value}{after}", f"{before}1.01 * {value}{after}"


# (name, file, (old, new), test that must fail)
MUTATIONS = [
    ("pendulum g 9.81 -> 9.80", "ancf/scenes/pendulum.py",
     ('Param("g", 9.81,', 'Param("g", 9.80,'), TD + "test_stiff_pendulum_follows_rigid_compound_pendulum"),
    ("spinning beam rho +1 %", "ancf/scenes/spinning_beam.py",
     plus_1_percent('Param("rho", ', "2766.67"), TD + "test_spinning_beam_axial_extension_against_eq_2_36"),
    ("pendulum rho +1 %", "ancf/scenes/beam_dynamic.py",
     plus_1_percent('Param("rho", ', "7850.0"), TD + "test_stiff_pendulum_follows_rigid_compound_pendulum"),
    ("Baumgarte position term dropped", "ancf/core/multipliers.py",
     ("out = out - self.beta ** 2 * con.value(q, t)", "out = out"),
     TD + "test_baumgarte_restores_a_violated_pin_critically_damped"),
    ("Baumgarte velocity term dropped", "ancf/core/multipliers.py",
     ("out = out - 2.0 * self.alpha * (con.jacobian(q, t) @ v + con.time_derivative(q, t))",
      "out = out"), TD + "test_baumgarte_restores_a_violated_pin_critically_damped"),
    ("LinearBeam2D's own ks default +1 %", "ancf/elements/linear2d.py",
     plus_1_percent("rho=0.0, ks=", "5.0 / 6.0", ", integration"),
     TP + "test_linear_element_default_ks_reproduces_report_table_1"),
    ("static scenes' ks default +1 %", "ancf/scenes/beam_static.py",
     plus_1_percent('Param("ks", ', "5.0 / 6.0"), TP + "test_simply_supported_tables"),
    ("static scenes' E +1 %", "ancf/scenes/beam_static.py",
     plus_1_percent("def element_params(E=", "2.07e11"), TP + "test_simply_supported_tables"),
    ("static scenes' h +1 %", "ancf/scenes/beam_static.py",
     plus_1_percent("def element_params(E=2.07e11, nu=0.0, h=", "0.1"), TP + "test_simply_supported_tables"),
    ("cantilever nu = 0.3 +1 %", "ancf/scenes/cantilever.py",
     plus_1_percent("bs.element_params(nu=", "0.3"), TP + "test_model_1_is_the_cantilever_defaults"),
    ("cantilever h +1 %", "ancf/scenes/cantilever.py",
     plus_1_percent("bs.element_params(nu=0.3, h=", "0.1"), TP + "test_model_1_is_the_cantilever_defaults"),
    ("Timoshenko reference's ks default +1 %", "analytic/timoshenko.py",
     plus_1_percent("F: float,\n                   ks: float = ", "5.0 / 6.0"),
     TA + "test_nu0_matches_published_analytic"),
    ("Reissner reference's ks default +1 %", "analytic/reissner.py",
     plus_1_percent("Fx: float = 0.0, ks: float = ", "5.0 / 6.0"),
     TA + "test_reissner_matches_independent_shooting"),
    ("pendulum E +1 %", "ancf/scenes/pendulum.py",
     plus_1_percent("n_elements=4, E=", "2.07e7"), TD + "test_defaults_are_the_thesis_problem"),
    ("spinning beam E +1 %", "ancf/scenes/spinning_beam.py",
     plus_1_percent("n_elements=3, E=", "6.895e10"), TD + "test_spinning_beam_axial_extension_against_eq_2_36"),
    ("opposing torque T_a helps the driven pulley", "ancf/belts/forces.py",
     ("fz[n + j] = -T[p] + laws[p] + drive.damping[j] * omegas[p]",
      "fz[n + j] = -T[p] - laws[p] + drive.damping[j] * omegas[p]"),
     TB + "test_span_tensions_carry_the_driven_torque"),
    ("driver ramp ends at 0.5 s (Eq. 3.29)", "ancf/belts/pulleys.py",
     ("T0, T1 = 0.05, 0.6", "T0, T1 = 0.05, 0.5"), TB + "test_eq_3_29_at_its_breakpoints"),
    ("Table 3.1 R1 +1 %", "ancf/scenes/belt_common.py",
     plus_1_percent("R1, R2, X_CENTRE = ", "0.08125"), TB + "test_table_3_1_span_and_path_length"),
    ("creep slope nu_s halved in the linear branch", "ancf/belts/friction/creep_rate.py",
     ("f[i] = -nu * v[i]", "f[i] = -0.5 * nu * v[i]"),
     "tests/belts/test_contact.py::test_rotating_ring_slides_by_the_tri_linear_law"),
    ("3D creep slope nu_s halved in the linear branch", "ancf/belts/friction/creep_rate.py",
     ("f[i] = -nu * v[i]", "f[i] = -0.5 * nu * v[i]"),
     T3 + "test_sliding_strip_follows_the_creep_rate_law"),
    ("3D pulley surface speed with the wrong sign along x", "ancf/belts/contact3d.py",
     ("vs0 = vr[0] - om * R * t0 - wn * n0", "vs0 = vr[0] + om * R * t0 - wn * n0"),
     T3 + "test_sliding_strip_follows_the_creep_rate_law"),
    ("3D bounding disc without its radius", "ancf/belts/contact3d.py",
     ("    return dist - rb <= R + BOUND_MARGIN * scale", "    return dist <= R + BOUND_MARGIN * scale"),
     T3 + "test_bounding_test_never_skips_a_pair_in_contact"),
    ("saturated friction without df/dF_n", "ancf/belts/friction/creep_rate.py",
     ("D[i, c] = -mu * u[i] * gF[c] - g * (G[i, c] - u[i] * ug)",
      "D[i, c] = -g * (G[i, c] - u[i] * ug)"),
     "tests/belts/test_friction.py::test_chain_matches_central_differences_of_the_force"),
    ("3D Jacobian without the turning of n", "ancf/belts/contact3d.py",
     ("D[i, c] += Fn * t[i] * t[c] / rho", "D[i, c] += 0.0"),
     T3 + "test_jacobians_match_central_differences"),
    ("3D Jacobian without the damper's dn/dr", "ancf/belts/contact3d.py",
     ("gF[c] = -kp * n[c] - cp * tv * t[c] / rho", "gF[c] = -kp * n[c]"),
     T3 + "test_jacobians_match_central_differences"),
    ("modes' steel density +1 %", "ancf/scenes/base.py",
     plus_1_percent('STEEL_DENSITY = Param("rho", ', "7850.0"),
     TM + "test_first_three_bending_frequencies_within_half_a_percent_of_timoshenko"),
    ("modes about the reference at the equilibrium too", "ancf/scenes/modes.py",
     ("_, K = mm.pattern.assemble(mm.assembly, q)", "_, K = mm.pattern.assemble(mm.assembly, mm.q0)"),
     TM + "test_axial_bar_first_bending_frequency_vanishes_at_the_euler_load"),
    ("modes' Sturm check without the extra mode", "ancf/solvers/eigen.py",
     ("k = min(count + 1, n - 1)", "k = count"),
     TM + "test_the_sturm_check_tells_a_repeated_pair_from_a_missed_mode"),
    ("tip moment's torque split evenly (unweighted fit)", "ancf/models/beam3d.py",
     ('SectionMoment(m.n_dofs, dofs, M, (moments["Q2_0"],', 'SectionMoment(m.n_dofs, dofs, M, (1.0,'),
     "tests/models/test_beam3d_benchmarks.py::test_tip_moment_small_deflection_is_the_closed_form"),
    ("section moment's Jacobian without the turning of the slopes", "ancf/core/forces.py",
     ("J[3 * k:3 * k + 3, 3 * k:3 * k + 3] += wk * _skew(m)", "J[3 * k:3 * k + 3, 3 * k:3 * k + 3] += 0.0"),
     "tests/models/test_beam3d_benchmarks.py::test_section_moment_jacobian_matches_differences"),
    ("Princeton beam's torsion factor from h only", "ancf/scenes/princeton_beam.py",
     ('torsion_factor(v["h"], v["b"])', 'torsion_factor(v["h"], v["h"])'),
     "tests/models/test_beam3d_benchmarks.py::test_princeton_linear3d_and_belt3d_against_ansys"),
    # issue 22: constants changed consistently in scenes and references alike
    ("g 9.81 -> 9.71 everywhere in the package", EVERYWHERE, ("9.81", "9.71"),
     (TPIN + "test_pendulum_defaults_are_the_thesis_problem_as_printed",
      TPIN + "test_rigid_pendulum_reaches_the_vertical_at_the_elliptic_integral_time")),
    ("steel density 7850 -> 7928 everywhere in the package", EVERYWHERE, ("7850", "7928"),
     (TPIN + "test_pendulum_defaults_are_the_thesis_problem_as_printed",
      TPIN + "test_beam_modes_reference_defaults_are_the_thesis_steel_beam",
      TPIN + "test_plate_modes_reference_defaults_against_the_closed_form",
      TPIN + "test_modes_scenes_default_density_is_steel")),
    ("spinning beam rho 2766.67 -> 2794.34 everywhere in the package", EVERYWHERE,
     ("2766.67", "2794.34"), TPIN + "test_spinning_beam_defaults_are_wu_and_haugs_as_printed"),
    ("steel E 2.07e11 -> 2.09e11 everywhere in the package", EVERYWHERE, ("2.07e11", "2.09e11"),
     TPIN + "test_beam_modes_reference_defaults_are_the_thesis_steel_beam"),
    # issue 22: how the 3D drive is put together
    ("3D driver shift along +x (Eq. 4.46)", "ancf/belts/drive3d.py",
     ("SHIFT = np.array([-1.0, 0.0, 0.0])", "SHIFT = np.array([1.0, 0.0, 0.0])"),
     (TW + "test_model_1_driver_moves_away_from_the_driven_pulley",
      TW + "test_model_1_belt_is_tensioned_once_the_driver_has_moved")),
    ("3D driver shift reversed inside the kernel", "ancf/belts/forces.py",
     ("o[p] += laws[npul + 2 * i] * drive.shift[i]\n        odot[p] =",
      "o[p] -= laws[npul + 2 * i] * drive.shift[i]\n        odot[p] ="),
     TW + "test_model_1_belt_is_tensioned_once_the_driver_has_moved"),
    ("3D driven pulley inertia x 1.25 (scene to drive)", "ancf/scenes/belt3d.py",
     ('inertia=p["inertia"],', 'inertia=1.25 * p["inertia"],'),
     (TW + "test_belt3d_record_is_table_4_1",
      TW + "test_model_2_driven_pulley_obeys_its_equation_of_motion_during_the_ramp")),
    ("3D c_p halved (scene to kernel)", "ancf/scenes/belt3d.py",
     ('c_p=p["c_p"],', 'c_p=0.5 * p["c_p"],'),
     TW + "test_belt3d_record_is_table_4_1"),
    ("3D c_p halved (drive to kernel)", "ancf/belts/drive3d.py",
     ("friction.contact_record(s.k_p, s.c_p,", "friction.contact_record(s.k_p, 0.5 * s.c_p,"),
     TW + "test_belt3d_record_is_table_4_1"),
    ("2D driven pulley inertia x 1.25 (scene to drive)", "ancf/scenes/belt2d.py",
     ('inertia=p["inertia"],', 'inertia=1.25 * p["inertia"],'),
     TW + "test_belt2d_record_is_table_3_1"),
    ("2D driver ramp ends at 0.63 s (Eq. 3.29: 0.6 s)", "ancf/belts/pulleys.py",
     ("T0, T1 = 0.05, 0.6", "T0, T1 = 0.05, 0.63"),
     TW + "test_belt2d_driver_follows_eq_3_29_as_the_march_sees_it"),
    ("Bechtel reference's Model 2 mu 0.6 -> 0.66", "analytic/bechtel.py",
     ('"mu": 0.6,', '"mu": 0.66,'),
     TPIN + "test_bechtel_reference_is_model_2_and_its_stiff_limit_the_closed_form"),
    ("belt3d Model 2 mu 0.6 -> 0.66 (Table 4.1)", "ancf/scenes/belt3d.py",
     ("nu_s=2e5, mu=0.6,", "nu_s=2e5, mu=0.66,"), TW + "test_belt3d_record_is_table_4_1"),
    ("0.8 mm jump along the spans of the wrapped path", "ancf/belts/path.py",
     ("r[sel] = p + sl[:, None] * d", "r[sel] = p + (sl[:, None] + 8e-4) * d"),
     (TW + "test_belt2d_laid_belt_lies_on_the_path_at_equal_arc_spacing",
      TW + "test_belt3d_laid_belt_lies_on_the_path_at_equal_arc_spacing")),    # issue 32: a wrong sign in an element, a law or a solver (the fast tier must catch each)
    ("Coulomb friction pushes along the sliding", "ancf/belts/friction/coulomb.py",
     ("f[i] = -g * v[i]", "f[i] = g * v[i]"), "tests/belts/test_friction.py"),
    ("bristle spring and damper push along the sliding", "ancf/belts/friction/bristle.py",
     ("f[i] = -(kt * z0[i] + c * v[i])", "f[i] = (kt * z0[i] + c * v[i])"),
     "tests/belts/test_friction.py"),
    ("cosine-step load law turned upside down", "ancf/belts/pulleys.py",
     ("step = 0.5 * final * (1.0 - np.cos(", "step = 0.5 * final * (1.0 + np.cos("),
     "tests/belts/test_pulley_laws.py"),
    ("Green strain's quadratic part with the wrong sign (2D elements)", "ancf/elements/green2d.py",
     ("exx = a0 * ux0 + a1 * ux1 + 0.5 * (", "exx = a0 * ux0 + a1 * ux1 - 0.5 * ("),
     "tests/elements"),
    ("element field's Green strain with the wrong sign of its 1", "ancf/elements/compiled_element.py",
     ('return 0.5 * (np.einsum("...d,...d->...", a, a) - 1.0)',
      'return 0.5 * (np.einsum("...d,...d->...", a, a) + 1.0)'), "tests/elements"),
    ("static Newton residual with the internal force's sign flipped", "ancf/solvers/static.py",
     ("r = lam * Qr - grad", "r = lam * Qr + grad"), "tests/solvers"),
    ("generalized-alpha gamma with af and am swapped", "ancf/solvers/generalized_alpha.py",
     ("gamma = 0.5 + af - am", "gamma = 0.5 - af + am"), "tests/solvers"),
    # issue 33: the five planted bugs that survived the whole suite, and the bristle post-processing
    ("tensioner arm inertia read from the pulley's own field", "ancf/belts/drive_model.py",
     ('[p.params["arm_inertia"] for p in arms]', '[p.params["inertia"] for p in arms]'),
     "tests/belts/test_drive_keys.py::test_arm_inertia_and_damping_are_the_arms_own"),
    ("tensioner arm damping read from the pulley's own field", "ancf/belts/drive_model.py",
     ('[p.params["arm_damping"] for p in arms]', '[p.params["damping"] for p in arms]'),
     "tests/belts/test_drive_keys.py::test_arm_inertia_and_damping_are_the_arms_own"),
    ("post-processing ignores the pulley centre's velocity", "ancf/belts/post2d.py",
     ("contact_state_stepped(E, V, S0, o, odot,", "contact_state_stepped(E, V, S0, o, 0 * odot,"),
     "tests/belts/test_balance.py::test_a_swinging_tensioner_gets_friction_from_its_centres_velocity"),
    ("drive-file contact.gauss_points default 7 -> 5", "ancf/belts/drive_data.py",
     ('Param("gauss_points", 7, int,', 'Param("gauss_points", 5, int,'),
     "tests/belts/test_drive_keys.py::test_documented_defaults_are_the_ones_the_docs_name"),
    ("zero-energy-mode measure without its normalisation", "ancf/solvers/eigen.py",
     ('rel = np.abs(w) / (pattern.inf_norm(K) * np.einsum("ij,ij->j", V, V))',
      "rel = np.abs(w)"),
     "tests/solvers/test_eigen_zero_modes.py"),
    ("tensioner arm preload with the wrong sign", "ancf/belts/drive_model.py",
     ('preload=p.params["arm_preload"]))', 'preload=-p.params["arm_preload"]))'),
     "tests/belts/test_drive_keys.py::test_arm_preload_is_counter_clockwise_positive"),
    ("plate-belt friction reported along the clockwise tangent", "ancf/belts/post3d.py",
     ("tang = np.cross(drive.axes, a / np.linalg.norm(a, axis=-1, keepdims=True))",
      "tang = np.cross(a / np.linalg.norm(a, axis=-1, keepdims=True), drive.axes)"),
     "tests/belts/test_balance.py::test_plate_belt_reported_fields_obey_their_balances"),
    ("tensioner arm start angle from pivot to centre reversed", "ancf/belts/drive_model.py",
     ("beta0=math.atan2(c[1] - P[1], c[0] - P[0]),", "beta0=math.atan2(P[1] - c[1], P[0] - c[0]),"),
     "tests/belts/test_drive_keys.py::test_arm_start_is_the_files_centre"),
    ("3423 transverse shear at the Gauss point, not the ANS edge midpoints",
     "ancf/elements/ancf3423.py",
     ("Hq[3] += p * _sym(sp[2], sp[3])", "Hq[3] += p * _sym(s[2], s[3])"),
     "tests/reports/test_chrono_elements_chapter.py::test_3423_plate_no_locking_and_converges"),
    ("3423 stress without its damping's strain rate (Eq. (7))", "ancf/elements/ancf3423.py",
     ("eps[q, k] = 0.5 * s + alpha * t", "eps[q, k] = 0.5 * s"),
     "tests/elements/test_chrono_3423.py::test_3423_first_steps_within_chronos_tolerance"),
    ("axial damping's dQ_d/de without its dm/de (Hs e')^T term", "ancf/elements/dufva2d.py",
     ("np.dot(Hs, ve, u)", "u[:] = 0.0"),
     "tests/belts/test_belt_damping.py::test_damping_jacobians_match_central_differences"),
    ("axial damping's slope Hessian transposed in its upper triangle", "ancf/elements/dufva2d.py",
     ("Hs[a, b] = BX[e, q, k] * (h[d, b % 2] * BX[e, q, b // 2])",
      "Hs[a, b] = BX[e, q, b // 2] * (h[b % 2, d] * BX[e, q, k])"),
     "tests/belts/test_belt_damping.py::"
     "test_axial_damping_loops_are_the_general_kernels_bit_for_bit"),
    ("plate belt's friction state not dispatched (stateless contact)", "ancf/belts/arm3d.py",
     ("    if friction.has_state(drive.prm):  # its state z", "    if False:  # its state z"),
     "tests/belts/test_belt3d_bristle.py"),
    ("plate belt's crowned rims not dispatched (cylinders' contact)", "ancf/belts/arm3d.py",
     ("    if drive.flanges.crowns.shape[0]:  # crowned rims", "    if False:  # crowned rims"),
     "tests/belts/test_belt3d_centring.py::test_crowned_pulleys_centre_the_belt"),
]


def _copy() -> Path:
    """A fresh copy of the checkout (without .git, pytest's cache and __pycache__) at
    WORK/tree, always the same path: numba's cache (NUMBA_CACHE_DIR, keyed by the source
    file's path and time stamp) then serves the untouched modules from one mutation to
    the next."""
    dst = WORK / "tree"
    shutil.rmtree(dst, ignore_errors=True)
    shutil.copytree(ROOT, dst, symlinks=True, copy_function=shutil.copy2,
                    ignore=shutil.ignore_patterns(".git", ".pytest_cache", ".cache", "__pycache__"))
    return dst


def _patch(tree: Path, path: str, old: str, new: str) -> list | str:
    """Apply the mutation in ``tree``: the files changed, or why it could not be applied."""
    if path == EVERYWHERE:
        files = [f for top in PACKAGE for f in sorted((tree / top).rglob("*.py"))]
        hits = [f for f in files if old in f.read_text()]
        if not hits:
            return f"not applied ({old!r} occurs nowhere)"
        for f in hits:
            f.write_text(f.read_text().replace(old, new))
        return hits
    src = tree / path
    text = src.read_text()
    if text.count(old) != 1:
        return f"not applied ({old!r} occurs {text.count(old)} times)"
    src.write_text(text.replace(old, new))
    return [src]


def _cache(changed: list) -> Path:
    """numba's cache folder for a run with the files ``changed``: the shared one, or a fresh
    one when a changed file holds compiled code (numba does not recompile a cached kernel
    when a kernel it calls, from another module, changes)."""
    if not any("numba" in f.read_text() for f in changed):
        return WORK / "numba-cache"
    fresh = WORK / "numba-fresh"
    shutil.rmtree(fresh, ignore_errors=True)
    return fresh


def caught(path: str, old: str, new: str, tests) -> str:
    """Apply in a copy, run ``tests`` there; 'yes: <failed test>: <first assertion>' if a
    test failed, 'NO' if all passed."""
    tests = (tests,) if isinstance(tests, str) else tuple(tests)
    tree = _copy()
    try:
        changed = _patch(tree, path, old, new)
        if isinstance(changed, str):
            return changed
        env = dict(os.environ, PYTHONPATH=str(tree), NUMBA_CACHE_DIR=str(_cache(changed)))
        try:
            run = subprocess.run([sys.executable, "-m", "pytest", "-q", "-rf", "-p",
                                  "no:cacheprovider", *FAST, *tests], cwd=tree, env=env,
                                 capture_output=True, text=True, timeout=TIME_LIMIT)
        except subprocess.TimeoutExpired:
            return f"timed out after {TIME_LIMIT} s"
    finally:
        shutil.rmtree(tree, ignore_errors=True)
    if run.returncode == 5:
        return "NO (no fast test named)"
    if run.returncode != 1:
        return "NO" if run.returncode == 0 else f"pytest exit code {run.returncode}"
    failed = [ln.split()[1].split("::", 1)[1] for ln in run.stdout.splitlines()
              if ln.startswith("FAILED ")]
    why = next((ln[1:].strip() for ln in run.stdout.splitlines() if ln.startswith("E ")), "")
    return f"yes: {', '.join(f'`{f}`' for f in failed)}: `{why[:90]}`"


def _names(tests) -> str:
    tests = (tests,) if isinstance(tests, str) else tuple(tests)
    return "<br>".join(f"`{t.split('::', 1)[-1]}`" for t in tests)


def main(args) -> int:
    out = None
    if "--fast" in args:
        args = [a for a in args if a != "--fast"]
        FAST[:] = ["-m", "not slow"]
    if "--out" in args:
        i = args.index("--out")
        out, args = Path(args[i + 1]), args[:i] + args[i + 2:]
    rows = ["| mutation | file | tests that must fail | caught |", "|---|---|---|---|"]
    print("\n".join(rows), flush=True)
    missed = 0
    for name, path, (old, new), tests in MUTATIONS:
        if args and name not in args:
            continue
        verdict = caught(path, old, new, tests)
        missed += not verdict.startswith("yes")
        rows.append(f"| {name} | `{path}` | {_names(tests)} | {verdict} |")
        print(rows[-1], flush=True)
    if out is not None:
        out.write_text("\n".join(rows) + "\n")
    return 1 if missed else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
