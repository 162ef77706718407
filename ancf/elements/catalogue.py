"""Views of the element registry (:data:`ancf.elements.registry.ELEMENTS`) by use.

Scenes, references, selection, recommend, extremes, benchmarks and reports take
their planar beam element names, classes, schemes and the knobs each element
understands from :data:`CATALOGUE` (the registry's 2D beams; the belt elements stay
out of it so that the beam scenes, studies and references do not pick them up); the
element contract tests take the constructions of every element on a beam mesh from
:data:`CONTRACT_ELEMENTS`.
"""
from __future__ import annotations

from ancf.elements.registry import ELEMENTS as REGISTRY
from ancf.elements.registry import contract_variants

CATALOGUE = {name: t for name, t in REGISTRY.items() if t.kind == "beam" and t.dim == 2}

ELEMENTS = {name: t.cls for name, t in CATALOGUE.items()}


def __getattr__(name):
    """``CONTRACT_ELEMENTS`` (:func:`ancf.elements.registry.contract_variants`) is built on
    first use: the beam scenes then import no belt element (their generated kernels take a
    tenth of a second to load)."""
    if name != "CONTRACT_ELEMENTS":
        raise AttributeError(name)
    globals()["CONTRACT_ELEMENTS"] = value = contract_variants()
    return value


SCHEMES = tuple(dict.fromkeys(s for e in CATALOGUE.values() for s in e.cls.schemes))


def coordinates_per_node(name: str) -> int:
    return CATALOGUE[name].coordinates_per_node


def element_kwargs(name: str, p: dict) -> dict:
    """The element-specific keyword arguments of ``name`` taken from parameters ``p``."""
    return CATALOGUE[name].knob_values(p)
