"""Where the checkout's folders are: one place, so that moving a module cannot move them."""
from __future__ import annotations

from pathlib import Path

#: the repository root (the folder holding ``ancf/``, ``analytic/`` and ``reports/``)
REPO = Path(__file__).resolve().parents[2]
#: the generated report pages
REPORTS = REPO / "reports"
