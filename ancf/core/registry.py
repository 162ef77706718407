"""The coordinate registry: who owns which global coordinates.

Global coordinates are allocated in named blocks: the nodal coordinates of a mesh
(``kind="nodes"``), rigid-body coordinates such as a pulley's rotation angle
(``kind="rigid"``), Lagrange multipliers (``kind="multiplier"``).  A block is a
contiguous range; meshes, force terms and constraints look their coordinates up
by name, so adding a body never renumbers another's.
"""
from __future__ import annotations

from dataclasses import dataclass

KINDS = ("nodes", "rigid", "multiplier")


@dataclass(frozen=True)
class Block:
    name: str
    start: int
    size: int
    kind: str

    @property
    def indices(self) -> range:
        return range(self.start, self.start + self.size)


class Registry:
    def __init__(self):
        self.blocks: dict[str, Block] = {}
        self.n = 0

    def add(self, name: str, size: int, kind: str = "nodes") -> Block:
        """Allocate ``size`` coordinates under ``name``."""
        if name in self.blocks:
            raise ValueError(f"coordinate block {name!r} is already registered")
        if kind not in KINDS:
            raise ValueError(f"coordinate kind {kind!r} must be one of {', '.join(KINDS)}")
        if int(size) < 0:
            raise ValueError(f"block {name!r}: size must be >= 0 (got {size})")
        block = Block(name, self.n, int(size), kind)
        self.blocks[name] = block
        self.n += block.size
        return block

    def __getitem__(self, name: str) -> Block:
        return self.blocks[name]

    def index(self, name: str, k: int = 0) -> int:
        """Global index of the k-th coordinate of block ``name``."""
        b = self.blocks[name]
        if not 0 <= k < b.size:
            raise IndexError(f"block {name!r} has {b.size} coordinates (asked for {k})")
        return b.start + k

    def of_kind(self, kind: str) -> list[Block]:
        return [b for b in self.blocks.values() if b.kind == kind]
