"""The analytic references (:mod:`analytic`) exposed like scenes: ``ancf analytic NAME``.

One module per reference: it declares ``REFERENCE = Scene(...)`` (parameters, run, result
keys) and its place in the list, ``ORDER = <int>``; ``DYNAMIC = True`` marks the ones the
dynamic scenes are measured against.  :data:`REFERENCES` (every one, in that order) and
:data:`DYNAMIC_REFERENCES` are collected from this folder; adding a reference is adding
its file.
"""
from __future__ import annotations

import importlib
from pathlib import Path

from ancf.common.paths import declared

_MODULES = [importlib.import_module(f"{__name__}.{m}") for m in declared(Path(__file__).parent)]

#: name -> the reference's Scene, in the declared order
REFERENCES = {m.REFERENCE.name: m.REFERENCE for m in _MODULES}
#: the references of the dynamic scenes (a part of REFERENCES)
DYNAMIC_REFERENCES = {m.REFERENCE.name: m.REFERENCE for m in _MODULES
                      if getattr(m, "DYNAMIC", False)}
