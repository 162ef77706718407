"""Shared fixtures of the whole suite.

``workdir``: a per-module scratch folder that is also the reference cache.  ``cli``: runs
``ancf ARGV`` in-process and gives (exit code, stdout, stderr), whether the command
returns its code or exits.  ``examples``: the repository's ``examples/`` folder.

Tiers: ``make test-fast`` runs every test not marked ``slow`` (``pytest -m "not slow"``),
``make test`` all of them; a test that takes more than a few seconds on an idle machine is
marked ``@pytest.mark.slow`` in its own file.
"""
import os

import pytest

from ancf.common.paths import REPO


@pytest.fixture(scope="module")
def workdir(tmp_path_factory, request):
    """A per-module scratch folder that is also the reference cache (ANCF_CACHE), so
    sweeps in tests never read or write reports/.cache."""
    d = tmp_path_factory.mktemp(request.module.__name__.rsplit(".", 1)[-1])
    old = os.environ.get("ANCF_CACHE")
    os.environ["ANCF_CACHE"] = str(d / "cache")
    yield d
    if old is None:
        os.environ.pop("ANCF_CACHE", None)
    else:
        os.environ["ANCF_CACHE"] = old


@pytest.fixture
def cli(capsys):
    """``cli(*argv) -> (exit code, stdout, stderr)`` of ``ancf ARGV`` run in this process."""
    from ancf.cli import main

    def run(*argv):
        try:
            rc = main(list(argv))
        except SystemExit as exc:
            rc = exc.code
        out, err = capsys.readouterr()
        return rc, out, err
    return run


@pytest.fixture(scope="session")
def examples():
    """The repository's examples/ folder (drive files)."""
    return REPO / "examples"
