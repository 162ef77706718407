"""Compiled band LU with partial pivoting, solves and inertia (numba).

Storage: row ``i`` of an (n x n) matrix with half-bandwidth ``kl`` (equal lower and
upper) keeps columns ``i - kl ... i + 2 kl`` in ``AB[i, j - i + kl]``: width
``W = 3 kl + 1``, the extra ``kl`` columns hold the fill of row interchanges (as
LAPACK's gbtrf).  The factorisation is in place; the multipliers of column ``k``
stay where row ``k``'s elimination put them and ``piv[k]`` records the row swapped
with ``k``, so a solve replays swaps and eliminations in the same order.

Inertia (Sylvester's law): the pivots of a symmetric matrix's LU *without*
pivoting are the D of its LDL^T, so the number of negative pivots of ``A - s I``
is the number of eigenvalues below ``s``.
"""
from __future__ import annotations

import numpy as np
from numba import njit, uintp

from ancf.common.leaf import leaf


@leaf
def _last_nonzero(AB, kl, i, j):
    """The last column <= j of row i with a nonzero entry (i if none past the diagonal)."""
    while j > i and AB[i, j - i + kl] == 0.0:
        j -= 1
    return j


@njit(cache=True)
def lu(AB, kl, piv, pivoting):
    """Factor in place; returns 0, or k + 1 if the pivot of column k is zero.  The
    last nonzero column of each row is tracked (from the matrix's own, within the
    band), so the zeros past it, and the fill columns, are only worked on where
    eliminations or row interchanges put something there."""
    n, w = AB.shape
    flat = AB.reshape(-1)  # the row updates index it with unsigned offsets: no negative-
    #                        index test in the loop, which then runs on vector instructions
    last = np.empty(n, dtype=np.int64)
    for i in range(n):
        last[i] = _last_nonzero(AB, kl, i, min(n - 1, i + kl))
    for k in range(n):
        end = min(n - 1, k + kl)
        p = k
        if pivoting:
            big = abs(AB[k, kl])
            for r in range(k + 1, end + 1):
                v = abs(AB[r, k - r + kl])
                if v > big:
                    big, p = v, r
        piv[k] = p
        if AB[p, k - p + kl] == 0.0:
            return k + 1
        if p != k:
            cmax = max(last[k], last[p])
            for c in range(k, cmax + 1):
                a, b = c - k + kl, c - p + kl
                AB[k, a], AB[p, b] = AB[p, b], AB[k, a]
            last[k], last[p] = cmax, cmax
        d = AB[k, kl]
        cmax = last[k]
        ob = uintp(k * w + kl + 1)  # flat index of row k's entry in column k + 1
        for r in range(k + 1, end + 1):
            m = AB[r, k - r + kl] / d
            AB[r, k - r + kl] = m
            if m != 0.0:
                oa = uintp(r * w + k + 1 - r + kl)
                for t in range(uintp(cmax - k)):  # columns k + 1 ... cmax
                    flat[oa + t] -= m * flat[ob + t]
                if cmax > last[r]:
                    last[r] = cmax
    return 0


@leaf
def solve(AB, kl, piv, b):
    """Solve in place with the factors of :func:`lu`.  Each pass stops at the last
    nonzero of its column of L or row of U, leaving out only exact zeros; without row
    interchanges the fill columns are untouched (zero in storage assembled from zero),
    so the backward pass looks for it from column k + kl."""
    n, w = AB.shape
    flat, step = AB.reshape(-1), uintp(w - 1)  # unsigned offsets, as in lu
    swapped = False
    for k in range(n):
        p = piv[k]
        if p != k:
            b[k], b[p] = b[p], b[k]
            swapped = True
        bk = b[k]
        if bk != 0.0:
            o, r0 = uintp((k + 1) * w - 1 + kl), uintp(k + 1)  # AB[k + 1, kl - 1]
            m = min(n - 1, k + kl) - k
            while m > 0 and flat[o + uintp(m - 1) * step] == 0.0:
                m -= 1
            for t in range(uintp(m)):  # rows k + 1 ... k + m
                b[r0 + t] -= flat[o + t * step] * bk
    upper = 2 * kl if swapped else kl
    for k in range(n - 1, -1, -1):
        s = b[k]
        o, c0 = uintp(k * w + kl + 1), uintp(k + 1)  # AB[k, kl + 1]
        for t in range(uintp(_last_nonzero(AB, kl, k, min(n - 1, k + upper)) - k)):
            s -= flat[o + t] * b[c0 + t]
        b[k] = s / AB[k, kl]


@njit(cache=True)
def count_below(AB, kl, shift):
    """Number of eigenvalues of the symmetric band matrix below ``shift``
    (-1 if a pivot is exactly zero)."""
    A = AB.copy()
    n = A.shape[0]
    for i in range(n):
        A[i, kl] -= shift
    piv = np.empty(n, dtype=np.int64)
    if lu(A, kl, piv, bool(False)) != 0:  # not a literal: one compilation of lu
        return -1
    neg = 0
    for i in range(n):
        if A[i, kl] < 0.0:
            neg += 1
    return neg


@njit(cache=True)
def matvec(AB, kl, x):
    n, w = AB.shape
    flat = AB.reshape(-1)  # unsigned offsets, as in lu
    y = np.zeros(n)
    for i in range(n):
        s = 0.0
        j0 = max(0, i - kl)
        o, x0 = uintp(i * w + j0 - i + kl), uintp(j0)
        for t in range(uintp(min(n - 1, i + kl) + 1 - j0)):  # columns j0 ... i + kl
            s += flat[o + t] * x[x0 + t]
        y[i] = s
    return y


@njit(cache=True)
def largest_magnitude(AB, kl, iterations):
    """Estimate of max |eigenvalue| of a symmetric band matrix by power iteration:
    the largest |A x| over unit iterates x, a lower bound that converges whatever
    the signs of the extreme eigenvalues."""
    n = AB.shape[0]
    x = np.empty(n)
    for i in range(n):
        x[i] = 1.0 + 0.5 * np.sin(1.0 + 7.0 * i)
    lam = 0.0
    for _ in range(iterations):
        x /= np.sqrt(np.dot(x, x))
        y = matvec(AB, kl, x)
        lam = max(lam, np.sqrt(np.dot(y, y)))
        x = y
        if np.dot(x, x) == 0.0:
            return lam
    return lam
