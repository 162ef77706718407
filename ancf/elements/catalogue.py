"""The catalogue of elements: the one place that lists them.

Scenes, references, selection, recommend, extremes, benchmarks, reports and the
element contract tests take their element names, classes, schemes and the knobs
each element understands from here.
"""
from __future__ import annotations

from dataclasses import dataclass

from ancf.elements.linear2d import LinearBeam2D
from ancf.elements.omar_shabana import OmarShabana2D


@dataclass(frozen=True)
class Entry:
    name: str       # the public name (``element=`` of the scenes)
    cls: type       # satisfies ancf.elements.contract.Element
    knobs: tuple    # element-specific parameters it accepts besides E, nu, rho, integration
    doc: str


CATALOGUE = {e.name: e for e in (
    Entry("linear", LinearBeam2D, ("ks",), "Kerkkänen's linear shear-deformable beam, 8 coordinates"),
    Entry("omar-shabana", OmarShabana2D, (), "Omar and Shabana's beam, 12 coordinates"),
)}

ELEMENTS = {name: e.cls for name, e in CATALOGUE.items()}
SCHEMES = tuple(dict.fromkeys(s for e in CATALOGUE.values() for s in e.cls.schemes))


def coordinates_per_node(name: str) -> int:
    cls = ELEMENTS[name]
    return len(cls.slots) * cls.strain.dim


def element_kwargs(name: str, p: dict) -> dict:
    """The element-specific keyword arguments of ``name`` taken from parameters ``p``."""
    return {k: p[k] for k in CATALOGUE[name].knobs if k in p}
