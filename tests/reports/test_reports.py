"""The report generator (issue 15, item 16): `python -m ancf.reports --out DIR --quick`
writes every chapter, every figure is a PNG, every acceptance row agrees with the test that
checks the same claim, and a second speed-accuracy run gives the same tables apart from
the timing columns (issue 15, item 11)."""
import importlib
import importlib.util
import os
import re
import subprocess
import sys
from pathlib import Path

import pandas as pd
import pytest

from ancf.checks.belt3d import CHECK_NAMES as BELT3D_ROWS
from ancf.checks.belt_tracking3d import CROWN as CROWN_SPAN
from ancf.checks.crown3d import NAMES as CROWN_CLASSIC
from ancf.checks.thread_plate import NAME as THREAD_PLATE
from ancf.checks.serpentine_3d import NAMES as SERPENTINE_3D
from ancf.checks.belt_tracking3d import ALIGNED as TRACK_ALIGNED, NAMES as TRACK_NAMES
from ancf.checks.belt2d import GAUSS_CHECK
from ancf.checks.chrono_cable import NAMES as CABLE_NAMES
from ancf.checks.chrono_shell3423 import NAMES as C3423_NAMES
from ancf.checks.chrono_locking import ANS_NAMES
from ancf.checks.belt_drives import SERPENTINE_NAMES
from ancf.reports.belt_drives import THREAD_NAMES
from ancf.checks.frequencies import ACCEPT_MESH, AXIAL_MESHES, SUPPORTS
from ancf.study.extremes import AXES, QUICK_SKIPPED
from ancf.reports.__main__ import CHAPTERS

PNG = b"\x89PNG\r\n\x1a\n"

#: acceptance row -> the test (module, function) that checks the same claim, and the
#: status that test implies
PUBLISHED = ("test_published_tables", "test_cantilever_tables")
AGREES = {
    **{f"Thesis 120 rad/s, EI and 10 EI: span {q}s within 1 % of Kong & Parker's BVP": (
        ("test_kong_parker", "test_within_the_one_percent_target"), "PASS")
       for q in ("tension", "departure")},
    "Serpentine: rotational modes within 1 % of the discrete model (creeping wraps)": (
        ("test_serpentine_creep_checks", "test_within_one_percent_of_the_creep_model"), "PASS"),
    **{f"{drive}: hubloads within 1 % of the span tensions summed": (
        ("test_running_drives", "test_hubloads_are_the_span_tensions_summed"), "PASS")
       for drive in ("THREAD (creep-rate)", "Serpentine")},
    "Thesis 120 rad/s: span modes 1-2 within 1 % of the moving beam": (
        ("test_running_drives", "test_thesis_span_modes_within_1_percent_of_the_moving_beam"),
        "PASS"),
    "THREAD (creep-rate): span modes 1-2 within 1 % of the moving beam": (
        ("test_running_drives", "test_thread_span_modes_within_1_percent_of_the_moving_beam"),
        "PASS"),
    **{f"Chrono's stored {kind} files: every element within {bound}": (
        ("test_chrono_elements_chapter", "test_every_stored_file_is_reproduced_within_its_bound"),
        "PASS") for kind, bound in (("mass", "1e-10"), ("gravity", "1e-10"), ("force", "1e-08"),
                                    ("Jacobian", "1e-06"))},
    # the chapter's solved rows: skipped by --quick; test_chrono_elements_chapter.py solves
    # them, holds them to these checks and renders the chapter from them
    **{name: (("test_chrono_elements_chapter", test), QUICK_SKIPPED) for name, test in (
        *((f"Chrono's static cases, {els}: within Chrono's tolerances",
           "test_static_case_within_chrono_tolerance")
          for els in ("3243 and 3333", "3843", "3443 and 3833")),
        ("Princeton beam: the 16-element u_z misses at 90° within 0.5 % at 32 elements",
         "test_princeton_uz_miss_at_16_passes_at_32"),
        ("Square plate 16 × 16, 3443: w × (1 − ν)²/(1 − 2ν) within 1 % of Navier",
         "test_plate_rows_and_checks"),
        ("Square plate 16 × 16, 3443 (plane stress): w within 1 % of Navier",
         "test_plate_3443_plane_stress_w_passes_f4_to_f6_miss"),
        ("Square plate 16 × 16, 3423: w within 1 % of Navier", "test_plate_rows_and_checks"),
        *((name, "test_3423_plate_no_locking_and_converges") for name in ANS_NAMES),
        ("Square plate 16 × 16, 3833: w within 1 % of Navier", "test_plate_rows_and_checks"),
        ("Square plate, 3833: first six frequencies within 1 % of the analytic plate",
         "test_plate_rows_and_checks"))},
    # the corner-loaded 3423 plate's history: skipped by --quick; the slow test file solves it
    **{name: (("test_chrono_3423_history", test), QUICK_SKIPPED) for name, test in zip(
        C3423_NAMES, ("test_first_steps_within_chronos_tolerance",
                      "test_whole_history_misses_chronos_tolerance_but_not_the_bound"))},
    # the spinning cable pendulum's history: skipped by --quick; the slow test file solves it
    **{name: (("test_chrono_cable", test), QUICK_SKIPPED) for name, test in zip(
        CABLE_NAMES, ("test_first_steps_within_chronos_tolerance_and_the_files_rounding",
                      "test_whole_history_within_chronos_tolerance"))},
    "Princeton beam, 16 elements: every u_y within 1 % of ANSYS": (
        ("test_chrono_princeton", "test_princeton_against_ansys"), QUICK_SKIPPED),
    "Princeton beam, 2 Gauss points along the axis: every u_z within 0.5 % of ANSYS at 16 "
    "elements (the misses are locking)": (
        ("test_chrono_locking", "test_two_point_axial_rule_brings_every_uz_within_tolerance"),
        QUICK_SKIPPED),
    "Square plate 16 × 16, 3443 (plane stress), G₁₃, G₂₃ × 100: every f above Navier by more "
    "than 10 % (shear locking)": (
        ("test_chrono_locking", "test_3443_frequencies_rise_above_kirchhoff_with_stiffer_shear"),
        QUICK_SKIPPED),
    **{t: (("test_published_tables", "test_simply_supported_tables"), "PASS")
       for t in ("Thesis Table 2.1 (ν = 0)", "Thesis Table 2.2 (ν = 0.3)",
                 "Report Table 1 (ν = 0)", "Report Table 2 (ν = 0.3)")},
    **{f"{t} {el}": (PUBLISHED, "PASS") for t in ("Thesis Table 2.3 (Model 1)",
                                                  "Thesis Table 2.4 (Model 2)",
                                                  "Report Table 5 (Model 2, fixed scheme)")
       for el in ("omar-shabana", "linear")},
    "Report Table 3 (Model 1) linear": (PUBLISHED, "PASS"),
    "Report Table 3 (Model 1) omar-shabana": (
        ("test_published_tables", "test_report_table_3_omar_shabana_single_outlier"),
        "DIFFERS (explained)"),
    "Report Table 4 (Model 2) omar-shabana": (PUBLISHED, "PASS"),
    "Report Table 4 (Model 2) linear": (
        ("test_published_tables", "test_report_table_4_linear_and_no_convergence"), "PASS"),
    "Report Table 6": (("test_published_tables", "test_report_table_6_elongation"), "PASS"),
    "Pendulum: 8 vs 16 elements within 1 % of L (each coordinate)": (
        ("test_dynamics", "test_pendulum_8_and_16_elements_agree_within_1_percent_of_L"), "PASS"),
    "Pendulum: energy deviation below 0.62e-4 J (4 elements)": (
        ("test_dynamics", "test_pendulum_energy_deviation_below_thesis"), "PASS"),
    "Pendulum E = 2.07e11 follows the rigid pendulum within 0.5 % of L": (
        ("test_dynamics", "test_stiff_pendulum_follows_rigid_compound_pendulum"), "PASS"),
    "Elimination = Lagrange multipliers (1e-6 m), violation < 1e-8 m": (
        ("test_dynamics", "test_elimination_and_multipliers_agree"), "PASS"),
    "Spinning beam: axial extension within 2 % of 1.09545e-4 m": (
        ("test_dynamics", "test_spinning_beam_axial_extension_against_eq_2_36"), "PASS"),
    "Spinning beam: ω_s × 10 stable": (
        ("test_dynamics", "test_spinning_beam_tenfold_speed_stays_stable"), "PASS"),
    "Extremes: thesis scheme, L/h = 1e4, n = 64: error < 1 %": (
        ("test_extremes", "test_thesis_scheme_does_not_lock_at_slenderness_1e4"), "PASS"),
    "Extremes: exact integration, L/h = 1e4, n = 64: locks (error > 50 %)": (
        ("test_extremes", "test_exact_integration_locks_at_slenderness_1e4"), "PASS"),
    "Extremes: run over its time limit is killed and reported": (
        ("test_sweep", "test_failures_are_rows_and_do_not_stop_the_others"), "PASS"),
    **{row: (("test_belt_drive", test), status) for row, test, status in (
        ("Belt free: mean radius within 0.2 % of L/(2π)",
         "test_free_belt_is_a_circle_of_its_length", "PASS"),
        ("Belt free: largest radial deviation below 0.5 % of the radius",
         "test_free_belt_is_a_circle_of_its_length", "PASS"),
        ("Belt: driven ω at 1 s with 20, 25, 30 elements within 1 %",
         "test_20_25_30_elements_agree_at_1_s", "PASS"),
        ("Belt: E = 1e9 oscillates less about the driver than E = 1e8 (Fig. 3.8)",
         "test_stiffer_belt_oscillates_less", "PASS"),
        ("Belt: ν_s = 1e4 lags more during the ramp than 1e5, E = 1e9 (Fig. 3.9)",
         "test_smaller_creep_rate_factor_lags_during_the_ramp", "PASS"),
        ("Belt 120 rad/s: ν_s = 1e4 slips more after the ramp than 1e5 (Fig. 3.18)",
         "test_smaller_creep_rate_factor_slips_more_at_120_rad_s", "PASS"),
        ("Belt 120 rad/s: (T_tight − T_slack)·R2 = T_a + I dω/dt within 3 %",
         "test_span_tensions_carry_the_driven_torque", "PASS"),
        ("Belt 120 rad/s: F_n = T/R within 5 % away from inlet and exit",
         "test_normal_force_against_T_over_R_and_the_exact_relation", "PASS"),
        ("Belt 120 rad/s: F_n = (N λ² − ρAv²)/(R − d) within 1 % away from inlet and exit",
         "test_normal_force_against_T_over_R_and_the_exact_relation", "PASS"),
        ("Belt 120 rad/s: Figs 3.10-3.11, the tight free span moves more than the slack "
         "during the ramp", "test_the_slack_span_moves_more_than_the_tight_one_at_120_rad_s",
         "DIFFERS (explained)"),
        (GAUSS_CHECK, "test_5_7_11_contact_points_give_the_same_driven_speed", "PASS"),
        ("Belt R2 = 0.1218 m: steady ω ratio within 2 % of R1/R2 (Fig. 3.21)",
         "test_larger_driven_pulley_turns_at_the_radius_ratio", "PASS"))},
    "Belt element: 4 elements bend into a full circle within 1 % of L (h = 0.08 m)": (
        ("test_belt_element", "test_four_elements_bend_into_a_full_circle_at_moderate_slenderness"),
        "PASS"),
    "Bechtel Model 2, k = 0.2 kN: driven slip vs the thesis's ≈ 14.6 % (Fig. 4.14)": (
        ("test_bechtel", "test_model2_compliant_slip_next_to_the_thesis"), "DIFFERS (explained)"),
    "Bechtel: friction on the driven pulley integrates to T_a within 0.1 %": (
        ("test_bechtel", "test_distributions_integrate_to_the_torque"), "PASS"),
    "Belt element, α1 = α2 = 1: Model 1 tip within 4e-4 m of the Reissner rod": (
        ("test_belt_element", "test_model1_cantilever_converges_to_reissner"), "PASS"),
    **{name: (("test_elements3d", test), "PASS") for name, test in (
        ("Plate square 16 × 16: centre deflection within 1 % of Navier",
         "test_plate_square_within_1_percent_of_navier"),
        ("Plate square: observed order 2 ± 0.2 (4 → 8 → 16 per side)",
         "test_plate_square_observed_order_two"),
        ("Plate strip ν = 0 (linear): tip = P L³/(3EI) on every mesh",
         "test_plate_strip_linear_is_euler_bernoulli"),
        ("Plate strip large deflection (ν = 0, F = EI/L²), 8 × 1: tip within 1e-3 of Reissner",
         "test_plate_strip_large_deflection_near_reissner"),
        ("3D beam, principal-plane bending: nodal displacements = planar scenes",
         "test_beam3d_principal_planes_reproduce_the_planar_scenes"),
        ("beam3d-cantilever 0°: tip = cantilever scene (Model 1)",
         "test_beam3d_scene_at_0_and_90_degrees"),
        ("beam3d-cantilever 90°: the load and the tip turn to −z",
         "test_beam3d_scene_at_0_and_90_degrees"),
        ("3D beam 45°: superposition error within its second-order bound",
         "test_beam3d_superposition_at_45_degrees"),
        ("3D beam torsion: twist = T x/(k_s G I_p) (no warping)",
         "test_beam3d_torsion_is_ks_G_Ip_and_J_is_the_series"),
        ("Torsion constant of the square: J = 0.1406 a⁴ (series)",
         "test_beam3d_torsion_is_ks_G_Ip_and_J_is_the_series"),
        ("Rigid rotation: zero strain energy, 3D beam", "test_rigid_rotation_has_no_strain"),
        ("Rigid rotation: zero elastic force, 3D beam", "test_rigid_rotation_has_no_strain"),
        ("Rigid rotation: zero strain energy, plate", "test_rigid_rotation_has_no_strain"))},
    **{name: (("test_beam3d_benchmarks", test), "PASS") for name, test in (
        ("Tip moment, small rotation: tip = M L²/(2EI), twist = M L/(k_s G I_p) (both "
         "elements)", "test_tip_moment_small_deflection_is_the_closed_form"),
        *((f"Princeton beam, {el} (16 el.): u_{c} vs ANSYS beam, every load and angle",
           "test_princeton_linear3d_and_belt3d_against_ansys")
          for el in ("linear3d", "belt3d") for c in "yz"),
        ("Princeton beam, linear3d exact integration locks: u_z at 90° below 20 % of ANSYS",
         "test_princeton_exact_integration_locks"),
        ("Princeton beam, linear3d k_s = 5/6: torsion too stiff, u_y (F3, 45°) low by more "
         "than 15 %", "test_princeton_default_ks_is_too_stiff_in_torsion"),
        ("3D general bending, linear3d (32 el.): u_z vs Table 4 ANSYS",
         "test_general_bending_u_z_against_table_4"),
        ("3D general bending, linear3d (32 el.): u_x, u_y vs Table 4 ANSYS",
         "test_general_bending_u_x_u_y_against_table_4"),
        ("3D general bending: ours − ANSYS = the continuum's second-order terms (u_x, u_y; "
         "128 el.)", "test_general_bending_difference_is_the_continuum_terms"))},
    **{name: (("test_modes", test), "PASS") for name, test in (
        *((f"Beam {s}, linear thesis, L/h = 20, {ACCEPT_MESH[s]} el.: first three frequencies "
           "within 0.5 % of Timoshenko",
           "test_first_three_bending_frequencies_within_half_a_percent_of_timoshenko")
          for s in SUPPORTS),
        *((f"Beam {s}, linear thesis: convergence order 2 (fit over n = 8…64, modes 1-2)",
           "test_bending_frequencies_converge_at_second_order") for s in SUPPORTS),
        ("Plate simply supported, 8 × 8: fundamental within 1 % of Navier",
         "test_plate_square_fundamental_within_one_percent_of_navier_at_8x8"),
        *((f"Axial bar, {n} el.: ω₁ about the equilibrium vanishes within 1 % of Euler's load",
           "test_axial_bar_first_bending_frequency_vanishes_at_the_euler_load")
          for n in AXIAL_MESHES))},
    **{name: (("test_frequencies", test), "PASS") for name, test in (
        ("Plate free-free, 8 × 8: first three ratios within 0.2 % of the Ritz series",
         "test_free_free_plate_ratios_within_0p2_percent_of_the_ritz_series_and_exudyn"),
        ("Plate free-free: Ritz series = Exudyn's published ratios to their last digit",
         "test_free_free_plate_ratios_within_0p2_percent_of_the_ritz_series_and_exudyn"),
        ("Plate simply supported: first four frequencies converge from below at order 2 (fit "
         "over n = 8…16)", "test_plate_converges_from_below_at_second_order"),
        ("Plate simply supported, 8 × 8: first six frequencies = Exudyn's ANCFThinPlate on the "
         "same mesh and constraints", "test_plate_8x8_frequencies_equal_exudyns_thin_plate"),
        *((f"Belt 120 rad/s, {k} span: mid-span frequency within 5 % of the moving string",
           "test_belt_span_frequency_within_5_percent_of_the_moving_string")
          for k in ("tight", "slack")))},
    **{name: (("test_belt3d_checks", "test_model2_and_model1_checks"), QUICK_SKIPPED)
       for name in BELT3D_ROWS[:7]},
    **{name: (("test_belt3d_checks", "test_settled_pretension_converges_with_the_element_count"),
              QUICK_SKIPPED) for name in BELT3D_ROWS[7:]},
    THREAD_PLATE: (("test_thread_plate", "test_plate_within_two_percent_of_the_planar_belt"),
                   QUICK_SKIPPED),
    **{name: (("test_serpentine_3d_checks", "test_plate_serpentine_within_the_issue_tolerances"),
              QUICK_SKIPPED) for name in SERPENTINE_3D},
    TRACK_ALIGNED: (("test_belt3d_tracking", "test_aligned_drive_does_not_walk"), QUICK_SKIPPED),
    **{name: (("test_belt3d_tracking", "test_entry_walk_follows_the_held_span_reference"),
              QUICK_SKIPPED) for name in TRACK_NAMES[1:]},
    **{name: (("test_belt3d_crown", "test_the_miss_is_the_belts_stretch"), QUICK_SKIPPED)
       for name in CROWN_CLASSIC},
    CROWN_SPAN: (("test_belt3d_centring", "test_crowned_pulleys_centre_the_belt"), QUICK_SKIPPED),
    **{name: (("test_thread", "test_perturbed_copy_fails"), QUICK_SKIPPED)
       for name in THREAD_NAMES},
    **{name: (("test_belt_npulley", "test_serpentine_settles_to_the_steady_reference"),
              QUICK_SKIPPED) for name in SERPENTINE_NAMES},
}
#: rows a quick report does not compute (their test still runs)
QUICK_ONLY_SKIPPED = (GAUSS_CHECK,)


def _axis_status(axis) -> str:
    ok, why = axis.applicable()
    if not ok:
        return why
    return "PASS" if axis.quick else QUICK_SKIPPED


def _expected() -> dict:
    """Every acceptance row of a quick report and its status."""
    out = {k: v for k, (_, v) in AGREES.items()}
    out.update(dict.fromkeys(QUICK_ONLY_SKIPPED, QUICK_SKIPPED))
    from ancf.study.references import specs
    out.update({f"Speed–accuracy {name}: Pareto plot + cheapest-configuration table": "PASS"
                for name in specs()})
    from ancf.study.references import FREQUENCY_SPECS
    out.update({f"Speed–accuracy frequencies {name}: Pareto plot + cheapest-configuration "
                "table": "PASS" for name in FREQUENCY_SPECS})
    out.update({f"Extremes: {a.title}": _axis_status(a) for a in AXES})
    if importlib.util.find_spec("exudyn") is None:  # the side-by-side row needs Exudyn
        out = {k: v for k, v in out.items() if "Exudyn's ANCFThinPlate" not in k}
    return out


@pytest.fixture(scope="module")
def quick(workdir):
    """One quick report into the module's scratch folder (its own reference cache)."""
    out = workdir / "reports"
    p = subprocess.run([sys.executable, "-m", "ancf.reports", "--out", str(out), "--quick"],
                       capture_output=True, text=True, timeout=900, env=dict(os.environ))
    assert p.returncode == 0, p.stderr[-3000:]
    return out


def _statuses(root: Path) -> dict:
    text = (root / "README.md").read_text().split("## Acceptance summary", 1)[1]
    rows = re.findall(r"^\| (.+?) \| (.+?) \|$", text, flags=re.M)
    return {k: v for k, v in rows if k != "check"}


@pytest.mark.slow
def test_every_chapter_is_written(quick):
    for name in CHAPTERS + ("README.md", "schemas.md"):
        assert (quick / name).stat().st_size > 200, name
    assert "--quick" in (quick / "README.md").read_text()


@pytest.mark.slow
def test_every_figure_is_a_png_and_every_data_file_exists(quick):
    seen = 0
    for name in CHAPTERS:
        text = (quick / name).read_text()
        for fig in re.findall(r"\]\((figures/[^)]+)\)", text):
            assert (quick / fig).read_bytes()[:8] == PNG, (name, fig)
            seen += 1
        for data in re.findall(r"`(data/[a-z0-9_]+\.csv)`", text):
            assert (quick / data).stat().st_size > 0, (name, data)
    assert seen >= 10
    assert all(p.read_bytes()[:8] == PNG for p in (quick / "figures").glob("*.png"))


def _test_module(module: str):
    """The test module ``module`` (its file found anywhere below tests/), imported."""
    path = next(Path(__file__).resolve().parents[1].rglob(f"{module}.py"))
    spec = importlib.util.spec_from_file_location(f"_agrees_{module}", path)
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    return mod


@pytest.mark.slow
def test_acceptance_statuses_agree_with_the_tests(quick):
    assert _statuses(quick) == _expected()
    for (module, name), _ in AGREES.values():
        mod = _test_module(module)
        assert callable(getattr(mod, name, None)), f"{module}.{name} is gone: update AGREES"


@pytest.mark.slow
def test_speed_accuracy_tables_are_reproducible(quick, workdir):
    """A second quick speed-accuracy chapter (fresh sweeps, fresh timings): the same page
    and the same data files; the CPU times and the calibration went to its timing page
    and ``data/timing/``."""
    from ancf.reports import output
    from ancf.reports.speed_accuracy import speed_accuracy_chapter
    before = output.settings()
    try:
        output.configure(workdir / "again", quick=True)
        output.take_timing()
        again, status = speed_accuracy_chapter()
        timing = "\n".join(output.take_timing())
    finally:
        output.configure(before.root, before.quick)
    first = (quick / "speed_accuracy.md").read_text()
    assert set(status.values()) == {"PASS"}
    assert "CPU ms" in timing and "Calibration of work to seconds on this machine" in timing
    assert "CPU ms" not in again and "cpu_time_s" not in again
    assert first.startswith(again) and "timing/speed_accuracy.md" in first[len(again):]
    data = sorted(p for p in (quick / "data").glob("speed_accuracy_*.csv")
                  if not p.stem.endswith("_frequency"))  # speed_accuracy_frequencies.md's
    assert len(data) >= 10
    for path in data:
        assert (workdir / "again" / "data" / path.name).read_bytes() == path.read_bytes(), path.name
    assert (quick / "timing" / "speed_accuracy.md").exists()


def test_timing_columns_leave_the_page_and_the_data_file(tmp_path):
    """A column named 'timing...' goes to data/timing/NAME.csv and the chapter's timing page
    only; the page's table and data/NAME.csv keep the rest (reproducible across runs)."""
    from ancf.reports import output
    before = output.settings()
    try:
        output.configure(tmp_path)
        output.take_timing()
        df = pd.DataFrame({"n": [1, 2], "error": [0.5, 0.25], "timing: CPU s": [0.1, 0.2]})
        output.write_csv(df, "t")
        page = output.markdown_table(df, 3, "A table")
        timing = "\n".join(output.take_timing())
        with pytest.raises(ValueError, match="timing"):
            output.markdown_table(df)               # a timing column needs its heading
    finally:
        output.configure(before.root, before.quick)
    assert "timing" not in page and "0.25" in page
    assert "## A table" in timing and "timing: CPU s" in timing and "0.2" in timing
    assert list(pd.read_csv(tmp_path / "data" / "t.csv").columns) == ["n", "error"]
    assert list(pd.read_csv(tmp_path / "data" / "timing" / "t.csv").columns) == list(df.columns)
    assert output.take_timing() == []


def test_run_store_meets_overrides_spelled_differently(tmp_path, monkeypatch):
    """A kept run is found under its resolved parameters; without a store nothing is kept."""
    from ancf.scenes import store
    out = {"converged": True, "results": {"x": 0.1 + 0.2}, "cpu_time_s": 1.0}
    store.keep("axial-bar", {}, out)                      # no store set: nothing happens
    monkeypatch.setenv(store.ENV, str(tmp_path))
    assert store.stored("axial-bar", {}) is None
    store.keep("axial-bar", {}, out)
    default_n = __import__("ancf.scenes", fromlist=["SCENES"]).SCENES["axial-bar"].resolve({})[
        "n_elements"]
    assert store.stored("axial-bar", {"n_elements": default_n}) == out
    assert store.stored("axial-bar", {"n_elements": default_n + 1}) is None
    store.keep("axial-bar", {"n_elements": default_n + 1}, {**out, "converged": False})
    assert store.stored("axial-bar", {"n_elements": default_n + 1}) is None


@pytest.mark.slow
def test_heartbeat_speaks_after_silence_and_ends_with_its_input():
    """`python -m ancf.reports.heartbeat`: silent while lines come, then one line per
    silence naming the last step; it ends when its input closes."""
    p = subprocess.Popen([sys.executable, "-m", "ancf.reports.heartbeat", "test", "1"],
                         stdin=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    p.stdin.write("belt3d: Model 2\n")
    p.stdin.flush()
    import time
    time.sleep(3.5)
    p.stdin.close()
    err = p.stderr.read()
    assert p.wait(timeout=10) == 0
    lines = err.strip().splitlines()
    assert 2 <= len(lines) <= 4
    assert all("test: still running belt3d: Model 2" in line for line in lines)


def test_a_process_done_with_its_chapters_stops_its_heartbeat():
    """A report process that idles until the other one is done (a pool's worker) says so
    no more: its heartbeat ends, not 'still running' its last step."""
    from ancf.reports import output
    output.heartbeat("test", 0.5)
    beat = output._BEAT[0]
    output.progress("belt3d: Model 1")
    output.heartbeat_stop()
    assert beat.poll() is not None and not output._BEAT


def test_the_3d_belt_chapter_comes_after_its_sweep():
    """Two report processes: the speed-accuracy sweeps in one, the 3D belt's first; every
    other chapter in the other, the 3D belt's last (its Model 2 runs are that sweep's)."""
    from ancf.reports.__main__ import GROUPS
    from ancf.reports.speed_accuracy import FIRST
    assert sorted(c for g in GROUPS for c in g) == sorted(CHAPTERS)
    sweeps, other = GROUPS
    assert sweeps == ("speed_accuracy.md",) and other[-1] == "belt3d.md"
    assert FIRST == ("belt3d",)


@pytest.mark.slow
def test_no_chapter_page_holds_a_timing(quick):
    """CPU times vary per run: no table column and no plot of them on a chapter page (they
    belong on its timing page), so a regeneration leaves the pages as they were."""
    pages = [p for p in quick.glob("*.md") if p.name not in ("README.md", "schemas.md")]
    assert len(pages) >= 10
    for page in pages:
        text = page.read_text()
        headers = [line for line in text.splitlines() if line.startswith("| ")
                   and re.search(r"\bCPU\b", line, re.IGNORECASE)]
        assert not headers, (page.name, headers[:1])
        assert not re.findall(r"\(figures/[^)/]*cpu[^)/]*\.png\)", text), page.name
