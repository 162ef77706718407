"""The catalogue of elements: the one place that lists them.

Scenes, references, selection, recommend, extremes, benchmarks and reports take
their (beam) element names, classes, schemes and the knobs each element
understands from :data:`CATALOGUE`; the element contract tests take every element
that satisfies the contract from :data:`CONTRACT_ELEMENTS`.
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


def _contract_elements() -> dict:
    """Every element that satisfies ancf.elements.contract, each with the constructor
    variants its contract tests run (name -> (class, keyword arguments)): the beam
    catalogue with one variant per integration scheme, and Dufva's belt elements
    (thesis 3.1 planar, 4.4 spatial), kept out of CATALOGUE so that the beam scenes,
    studies and references do not pick them up."""
    from ancf.elements.belt3d import DufvaBelt3D
    from ancf.elements.dufva2d import DufvaBelt2D
    return {
        **{f"{c.__name__}-{s}": (c, {"integration": s}) for c in ELEMENTS.values() for s in c.schemes},
        "DufvaBelt2D": (DufvaBelt2D, {}),
        "DufvaBelt2D-alpha": (DufvaBelt2D, {"alpha1": 0.6, "alpha2": 0.05, "nx": 3}),
        "DufvaBelt3D": (DufvaBelt3D, {}),
        "DufvaBelt3D-alpha": (DufvaBelt3D, {"alpha1": 0.6, "alpha2": 0.05, "nx": 3}),
    }


def __getattr__(name):
    """``CONTRACT_ELEMENTS`` (see :func:`_contract_elements`) is built on first use: the beam
    scenes then import no belt element (their generated kernels take a tenth of a second
    to load)."""
    if name != "CONTRACT_ELEMENTS":
        raise AttributeError(name)
    globals()["CONTRACT_ELEMENTS"] = value = _contract_elements()
    return value


SCHEMES = tuple(dict.fromkeys(s for e in CATALOGUE.values() for s in e.cls.schemes))


def coordinates_per_node(name: str) -> int:
    cls = ELEMENTS[name]
    return len(cls.slots) * cls.strain.dim


def element_kwargs(name: str, p: dict) -> dict:
    """The element-specific keyword arguments of ``name`` taken from parameters ``p``."""
    return {k: p[k] for k in CATALOGUE[name].knobs if k in p}
