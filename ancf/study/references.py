"""What each scene is measured against, collected from the scenes.

Every scene declares its :class:`~ancf.scenes.spec.SceneSpec` in its own file (the
``study`` function of its :class:`~ancf.scenes.base.Scene`: knobs, needed physics,
references with their errors, report and recommend grids; ``frequency_study`` for its
natural frequencies); :func:`spec` and :func:`specs` serve them to sweeps, ``ancf
recommend`` and the reports, :data:`SPECS` / :data:`FREQUENCY_SPECS` (scene name -> spec
factory) are derived from ``SCENES`` on first use.  A scene without ``study`` gets a spec
from its optional ``knobs`` / ``needs`` fields with a self-reference at 8x the default
element count.  The classes and the self-reference machinery live in
:mod:`ancf.scenes.spec`; the names are re-exported here.
"""
from __future__ import annotations

from functools import lru_cache

import numpy as np

from ancf.common.params import InputError
from ancf.scenes.spec import (DYNAMIC_KNOBS, PHYSICS, REFERENCE_VERSION, STATIC_KNOBS, Reference,
                              ReferenceFailed, SceneSpec, bending_frequencies, cache_root,
                              computed_self_reference, knob_text, self_reference, stable_hash)

__all__ = ["DYNAMIC_KNOBS", "ELEMENT_PHYSICS", "FREQUENCY_SPECS", "PHYSICS", "QUANTITIES",
           "REFERENCE_VERSION", "Reference", "ReferenceFailed", "SPECS", "STATIC_KNOBS",
           "SceneSpec", "bending_frequencies", "cache_root", "check_quantity",
           "computed_self_reference", "model_physics", "rescore", "runner", "self_reference",
           "spec", "specs", "stable_hash"]




def _element_physics() -> dict:
    """What each element provides (the elements' ``physics``, registry order): every
    element of the registry, the thesis's and Chrono's (a scene's ``element`` choices are
    its own; the 3-node ancf3333 is no ``models.beam3d.BUILDERS`` entry but the 3D beam
    scenes take it)."""
    from ancf.elements.registry import ELEMENTS
    return {n: e.physics for n, e in ELEMENTS.items()}


#: What each element family provides (derived from the element registry).
ELEMENT_PHYSICS = _element_physics()


#: what a sweep computes: the scene's own results, or its natural frequencies
QUANTITIES = ("results", "frequency")


def __getattr__(name):
    """``SPECS`` / ``FREQUENCY_SPECS``: scene name -> the spec factory it declares (its
    ``study`` / ``frequency_study``), built from ``SCENES`` on first use; the frequency
    ones in the order their modules declare (``FREQUENCY_ORDER``)."""
    if name not in ("SPECS", "FREQUENCY_SPECS"):
        raise AttributeError(name)
    from ancf.scenes import FOLDER, SCENES
    from ancf.common.paths import declared
    if name == "SPECS":
        value = {n: s.study for n, s in SCENES.items() if s.study is not None}
    else:
        value = {m.replace("_", "-"): SCENES[m.replace("_", "-")].frequency_study
                 for m in declared(FOLDER, "FREQUENCY_ORDER")}
    globals()[name] = value
    return value


def _derived(name: str) -> dict:
    """``SPECS`` or ``FREQUENCY_SPECS``, built once."""
    return globals()[name] if name in globals() else __getattr__(name)


def runner(scene: str, quantity: str = "results"):
    """The :class:`~ancf.scenes.base.Scene` a sweep runs: the scene itself, or for
    ``quantity = "frequency"`` its ``ancf modes`` about the reference
    (:func:`ancf.scenes.modes.frequency_scene`)."""
    check_quantity(scene, quantity)
    if quantity == "frequency":
        from ancf.scenes.modes import frequency_scene
        return frequency_scene(scene)
    from ancf.scenes import SCENES
    return SCENES[scene]


def check_quantity(scene: str, quantity: str) -> None:
    """InputError unless ``quantity`` is one of :data:`QUANTITIES` that ``scene`` has."""
    if quantity not in QUANTITIES:
        raise InputError(f"quantity: {quantity!r} is not valid; allowed: "
                         f"{', '.join(QUANTITIES)}")
    if quantity == "frequency" and scene not in _derived("FREQUENCY_SPECS"):
        raise InputError(f"quantity frequency: scene {scene!r} has no frequency reference; "
                         f"allowed: the scenes {', '.join(_derived('FREQUENCY_SPECS'))}")


@lru_cache(maxsize=None)
def spec(scene: str, quantity: str = "results") -> SceneSpec:
    """The spec of a scene of ``SCENES``: the one its ``study`` declares (for ``quantity =
    "frequency"``: its ``frequency_study``), else one built from the scene's optional
    ``knobs`` / ``needs`` fields with a self-reference at 8x the default element count."""
    from ancf.scenes import SCENES
    if scene not in SCENES:
        raise InputError(f"scene: unknown name {scene!r}; allowed: {', '.join(SCENES)}")
    check_quantity(scene, quantity)
    sc = SCENES[scene]
    if quantity == "frequency":
        return sc.frequency_study()
    if sc.study is not None:
        return sc.study()
    names = [p.name for p in sc.params]
    knobs = tuple(getattr(sc, "knobs", ()) or [k for k in DYNAMIC_KNOBS + STATIC_KNOBS
                                               if k in names])
    defaults = sc.resolve({})
    fine = {"n_elements": 8 * defaults["n_elements"]} if "n_elements" in names else {}
    quantities = tuple(k for k, v in sc.execute({})[0]["results"].items()
                       if isinstance(v, float))

    def err(res, ref, p):
        return max(abs(res[q] - ref[q]) / max(abs(ref[q]), 1e-300) for q in quantities)
    refs = {"self": self_reference(scene, fine, quantities, err,
                                   f"self-reference at {knob_text(fine)}; error = max relative "
                                   "difference of the scalar results", knobs=knobs,
                                   measure="largest relative error of the results")}
    return SceneSpec(scene, knobs, frozenset(getattr(sc, "needs", ()) or ()), refs, "self",
                     report_grids=({"n_elements": [1, 2, 4, 8]},) if fine else ({},),
                     recommend_grids=({"n_elements": [1, 2, 4, 8]},) if fine else ({},))


def specs() -> dict:
    """Specs of every swept scene of ``SCENES`` (declaration order of the registry)."""
    from ancf.scenes import SCENES
    return {name: spec(name) for name, s in SCENES.items() if s.swept}


def model_physics(scene: str, params: dict) -> frozenset:
    """The physics a configuration provides."""
    s = spec(scene)
    if s.provides is not None:
        return s.provides
    got = set(ELEMENT_PHYSICS.get(params.get("element", "linear"), frozenset()))
    if not s.dynamic:
        got.discard("inertia")
    return frozenset(got)


def rescore(df, scene: str, reference: str, quantity: str = "results"):
    """Errors of sweep rows (a DataFrame from :mod:`ancf.study.sweep`) against another reference,
    from the stored scalar results (``res_*`` columns); NaN where not converged."""
    s = spec(scene, quantity)
    ref = s.reference(reference)
    names = [p.name for p in runner(scene, quantity).params]
    cache = {}
    out = []
    for _, row in df.iterrows():
        if row.get("status") != "ok":
            out.append(float("nan"))
            continue
        p = {k: _py(row[k]) for k in names}
        pk = stable_hash(s.physical(p))
        if pk not in cache:
            try:
                cache[pk] = ref.values(p)
            except ReferenceFailed:
                cache[pk] = None
        res = {c[4:]: _py(row[c]) for c in row.index if c.startswith("res_")}
        out.append(float("nan") if cache[pk] is None else float(ref.error(res, cache[pk], p)))
    return np.array(out)


def _py(v):
    if isinstance(v, np.generic):
        return v.item()
    return v
