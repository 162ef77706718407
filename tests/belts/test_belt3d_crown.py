"""Crowned pulleys of the plate belt (issue 36 item 4; ancf.belts.contact3d_state, crowned
rims): the drive-file keys ``crown_m`` and ``face_offset_m`` with their bad input, the
crowned kernel's exact derivatives against central differences, and ``crown_m = 0`` bit for
bit the drive without the key."""
import json

import numpy as np
import pytest

from ancf.belts import friction
from ancf.belts.contact3d import contact_points3d
from ancf.belts.contact3d_state import contact_forces3d_crown
from ancf.cli import main
from ancf.common.paths import REPO
from ancf.scenes import SCENES

THREE3D = REPO / "examples" / "three_pulleys_3d.toml"
THREE2D, SERPENTINE3D = REPO / "examples" / "three_pulleys.toml", REPO / "examples" / \
    "serpentine_3d.toml"


def _one_error_line(args, capsys) -> str:
    """The CLI's stderr for ``args``: exactly one ``error:`` line and exit 2."""
    assert main(args) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and err[0].startswith("error: "), err
    return err[0]


@pytest.mark.parametrize("path, item, words", [
    (THREE2D, "pulleys.0.crown_m=0.001", "pulleys.0.crown_m = 0.001 is out of range for "
     "belt.element = 'dufva2d'; allowed: 0.0"),
    (THREE3D, "pulleys.driven.crown_m=-0.001", "pulleys.2.crown_m = -0.001 is out of range; "
     "allowed: a number in [0, 1]"),
    (THREE3D, "pulleys.driven.crown_m=0.05", "pulleys.2.crown_m = 0.05 is out of range: not "
     "below the pulley's radius 0.05 m; allowed: a number in [0, 0.05) m"),
    (THREE3D, "pulleys.driven.crown_m=0.2", "pulleys.2.crown_m = 0.2 is out of range: not "
     "below the pulley's radius 0.05 m; allowed: a number in [0, 0.05) m"),
    (SERPENTINE3D, "pulleys.tensioner.crown_m=0.001", "pulleys.1.crown_m = 0.001 is out of "
     "range for law = 'tensioner'; allowed: 0"),
])
def test_bad_crowns_are_one_error_line(path, item, words, capsys):
    """A crown on the 2D belt, negative, not below the radius, or on a tensioner: one
    ``error:`` line naming the key and its allowed range, exit 2."""
    line = _one_error_line(["run", "belt-drive", "--file", str(path), "--set", item], capsys)
    assert words in line, line
