"""The CLI fuzz cases marked ``"slow": true`` (a run of 2 s or more), replayed as
test_fuzz_cli.py replays the others (same checks, :func:`check_case`): in a file of
their own so that ``--dist loadfile`` runs them beside the fast cases.
"""
import pytest

from tests.interface.test_fuzz_cli import CASES, _id, check_case

SLOW = [c for c in CASES if c.get("slow")]


def test_the_two_files_replay_every_case_once():
    """Every case is in exactly one of the two files."""
    fast = [c for c in CASES if not c.get("slow")]
    assert len(SLOW) > 0 and len(fast) + len(SLOW) == len(CASES)


@pytest.mark.slow
@pytest.mark.parametrize("case", SLOW, ids=_id)
def test_slow_fuzz_case(case, capsys, tmp_path):
    check_case(case, capsys, tmp_path)
