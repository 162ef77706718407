"""Project Chrono's stored ANCF reference data for the ``test_chrono_*`` files: the
parameters, the loader and the elements live in :mod:`ancf.checks.chrono_matrices` (shared
with the report chapter ``chrono_elements``); here the test-only comparisons.

Data: ``tests/data/chrono/`` (see its README: source path, commit, licence, layout).
"""
from __future__ import annotations

import numpy as np
import pytest

from ancf.checks.chrono_matrices import (  # noqa: F401 (re-exported to the tests)
    ALPHA, BY_NAME, E, ELEMENTS, FORCE_CASES, G, JACOBIAN_CASES, K_TIMOSHENKO, NU, RHO,
    RTOL_FORCE, RTOL_JAC, RTOL_MASS, load)


def close(actual, expected, rtol: float, scale=None):
    """assert_allclose with rtol and an atol of rtol times the largest |expected| entry;
    with ``scale`` (per coordinate) also on the scaled d a (vector) or d a d (matrix),
    so that small gradient entries are held to rtol of the largest entry too."""
    pairs = [(np.asarray(actual), np.asarray(expected))]
    if scale is not None:
        d = np.asarray(scale, dtype=float)
        d = d if np.ndim(expected) == 1 else np.outer(d, d)
        pairs.append((d * actual, d * expected))
    for a, b in pairs:
        np.testing.assert_allclose(a, b, rtol=rtol, atol=rtol * np.abs(b).max())


def check_mass_and_weight(M, q, positions, mass, g=G):
    """M symmetric positive definite; a rigid unit translation along each axis (1 on
    that component of every node position, compact indices ``positions``) carries
    u^T M u = mass (kg); the gravity entries of the node positions add up to mass g (N)."""
    n = M.shape[0]
    assert M.shape == (n, n) and q.shape == (n,)
    np.testing.assert_allclose(M, M.T, rtol=0, atol=1e-14 * np.abs(M).max())
    np.linalg.cholesky(M)  # raises unless positive definite
    assert np.linalg.eigvalsh(M).min() > 0
    rows = 3 * np.asarray(positions)
    for k in range(3):
        u = np.zeros(n)
        u[rows + k] = 1.0
        assert u @ M @ u == pytest.approx(mass, rel=1e-12)
    np.testing.assert_allclose(q.reshape(-1, 3)[positions].sum(axis=0), mass * np.asarray(g),
                               rtol=1e-12, atol=0)


def rotation(axis, angle) -> np.ndarray:
    """Rodrigues rotation matrix (3, 3) about the unit ``axis`` by ``angle`` (rad)."""
    a = np.asarray(axis, dtype=float) / np.linalg.norm(axis)
    A = np.array([[0, -a[2], a[1]], [a[2], 0, -a[0]], [-a[1], a[0], 0]])
    return np.eye(3) + np.sin(angle) * A + (1 - np.cos(angle)) * A @ A
