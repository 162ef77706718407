"""The memory a solve will need, estimated before anything is built (issue 33 item 4).

A model of ``elements`` elements with ``element_dofs`` coordinates each and ``unknowns``
reduced unknowns in a band of half-width ``kl`` needs, at its peak:

* the pattern's index arrays (:class:`ancf.core.pattern.ReducedPattern`): about
  :data:`PATTERN_ARRAYS` int64 arrays of ``elements x element_dofs^2`` entries;
* the band matrices (rows of 3 kl + 1: the tangent, the mass, K - sigma M and its LU):
  :data:`BAND_MATRICES` of them.

Above :data:`MEMORY_SHARE` of the memory the machine has available (``MemAvailable`` of
/proc/meminfo, else the physical pages), the run is refused before it starts
(:func:`affordable`), the estimate stated, instead of swapping for minutes with no answer.
"""
from __future__ import annotations

import os

#: int64 index arrays of elements x element_dofs^2 entries the pattern holds at its peak
PATTERN_ARRAYS = 8
#: band matrices held at once (tangent, mass, K - sigma M, its LU)
BAND_MATRICES = 4
#: share of the available memory a run may plan to use (the rest: the interpreter, the
#: solver's work arrays, other processes)
MEMORY_SHARE = 0.5


def available_bytes() -> float:
    """Memory available to a new process, bytes: MemAvailable of /proc/meminfo, else all
    physical pages."""
    try:
        with open("/proc/meminfo") as fh:
            for line in fh:
                if line.startswith("MemAvailable:"):
                    return 1024.0 * float(line.split()[1])
    except OSError:
        pass
    return float(os.sysconf("SC_PAGE_SIZE") * os.sysconf("SC_PHYS_PAGES"))


def band_bytes(unknowns: int, kl: int, elements: int, element_dofs: int) -> float:
    """Estimated peak bytes of a band solve (see the module's list)."""
    pattern = PATTERN_ARRAYS * 8.0 * elements * element_dofs**2
    return pattern + BAND_MATRICES * 8.0 * unknowns * (3 * kl + 1)


def affordable(need: float, what: str, allowed: str, available: float | None = None) -> str | None:
    """None when ``need`` bytes fit in :data:`MEMORY_SHARE` of the available memory, else
    the one-line refusal ``what: ... allowed: ...`` naming the estimate."""
    have = available_bytes() if available is None else available
    if need <= MEMORY_SHARE * have:
        return None
    return (f"{what} would need about {need / 1e9:.3g} GB, above {MEMORY_SHARE:g} of the "
            f"{have / 1e9:.3g} GB available; allowed: {allowed}")


def grid_bytes(nx: int, ny: int, per_node: int, nodes_per_element: int = 4) -> float:
    """:func:`band_bytes` of an nx x ny grid of quadrilateral elements with ``per_node``
    coordinates per node, its band as wide as the shorter side (reverse Cuthill-McKee)."""
    unknowns = per_node * (nx + 1) * (ny + 1)
    kl = per_node * (min(nx, ny) + 2)
    return band_bytes(unknowns, kl, nx * ny, per_node * nodes_per_element)
