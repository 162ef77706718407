"""Shared fixtures."""
import os

import pytest


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
