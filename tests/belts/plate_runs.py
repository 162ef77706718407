"""The comparison the plate-belt drive-file tests share: a ``belt-drive`` run of a drive
file against the ``belt3d`` preset's run of the same model, bit for bit (not collected by
pytest: no ``test_`` prefix)."""
import numpy as np


def assert_file_run_is_belt3d(xa, a: dict, xb, b: dict):
    """Every sample's t, q, v (xa, xb: the runs' DynamicResult), the pulley speeds, the span
    tensions (the membrane's, along the edge z = 0), the driven pulley's friction moment and
    the run statistics of the file's results ``a`` equal the preset's ``b`` (both the
    JSON-loaded ``results``)."""
    for name in ("t", "q", "v"):
        assert np.array_equal(getattr(xa, name), getattr(xb, name)), name
    assert a["pulleys"][0]["omega"] == b["omega_driver"]
    assert a["pulleys"][1]["omega"] == b["omega_driven"]
    lower, upper = a["spans"]  # driver -> driven below, driven -> driver above (tight)
    T = b["tensions"]["membrane"]
    assert (upper["tension_N"], lower["tension_N"]) == (T["tight"], T["slack"])
    assert a["pulleys"][1]["torque_Nm"][-1] == b["torque_from_friction_Nm"]
    for key in ("steps", "nfev", "newton_iterations", "contact_pairs", "penetration_max_m",
                "total_dofs", "pretension_iterations"):
        assert a[key] == b[key], key
