"""The order in which ``make test`` hands the test files to its two xdist workers
(``tests/conftest.py``): the long files of ``LONG`` first, in its order, then the others
by test count as xdist would; only under xdist without a marker selection."""
from types import SimpleNamespace

from ancf.common.paths import REPO
from tests.conftest import LONG, file_order, pytest_configure


def test_every_long_file_exists():
    assert LONG and all((REPO / path).is_file() for path in LONG)


def test_long_files_go_first_in_order_then_by_test_count():
    first, second = LONG[:2]
    ids = ["tests/a/test_few.py::t", *(f"tests/b/test_many.py::t{k}" for k in range(3)),
           f"{second}::x", f"{second}::y", f"{first}::z", "tests/a/test_few.py::u"]
    items = [SimpleNamespace(nodeid=i) for i in ids]
    got = [i.nodeid for i in file_order(items)]
    assert got == [f"{first}::z", f"{second}::x", f"{second}::y",
                   *(f"tests/b/test_many.py::t{k}" for k in range(3)),
                   "tests/a/test_few.py::t", "tests/a/test_few.py::u"]


def test_only_make_test_leaves_xdist_its_reordering_off():
    """``-n`` without ``-m``: off (the collection's order); ``-m`` or no xdist: xdist's."""
    for numprocesses, markexpr, reorder in ((2, "", False), (2, "not slow", True),
                                            (None, "", True)):
        option = SimpleNamespace(numprocesses=numprocesses, markexpr=markexpr,
                                 loadscopereorder=True)
        pytest_configure(SimpleNamespace(option=option))
        assert option.loadscopereorder is reorder, (numprocesses, markexpr)
