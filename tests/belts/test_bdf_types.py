"""The BDF cross-check calls the belt forces with the march's argument types
(:func:`ancf.belts.forces.evaluate_record`): a drive that runs with both integrators
compiles :func:`ancf.belts.forces.evaluate` and its kernels once, for the drive as its
struct, never for the drive's NamedTuple record (about 12 CPU-s more, cold, per drive type)."""
from numba.core import types

from ancf.belts import forces
from ancf.scenes import SCENES


def test_bdf_runs_the_forces_with_the_drive_as_its_struct(workdir):
    """A BDF run of belt2d adds no signature of evaluate whose drive is a NamedTuple (the
    old call from Python added one; the tests that call the forces from Python use
    evaluate_record too, so none is there before), and converges."""
    before = set(forces.evaluate.signatures)
    out, _ = SCENES["belt2d"].execute({"integrator": "bdf", "t_end": 0.002})
    drives = [sig[3] for sig in set(forces.evaluate.signatures) - before]
    assert not [d for d in drives if isinstance(d, types.BaseNamedTuple)], drives
    assert out["converged"], out["message"]
