"""Where the checkout's folders are: one place, so that moving a module cannot move them."""
from __future__ import annotations

import re
from pathlib import Path

#: the repository root (the folder holding ``ancf/``, ``analytic/`` and ``reports/``)
REPO = Path(__file__).resolve().parents[2]
#: the generated report pages
REPORTS = REPO / "reports"


def declared(folder: Path, constant: str = "ORDER") -> dict[str, int]:
    """{module: place} of the modules in ``folder`` that declare their place in a list
    (``ORDER = <int>``, or another ``constant``, at the start of a line), in that order;
    read, not imported."""
    found = {}
    for path in folder.glob("*.py"):
        m = re.search(rf"^{constant} = (\d+)", path.read_text(), flags=re.M)
        if m:
            found[path.stem] = int(m.group(1))
    return dict(sorted(found.items(), key=lambda item: item[1]))
