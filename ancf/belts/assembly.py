"""Shared compiled pieces of the belt-drive force evaluations (:mod:`ancf.belts.forces`,
:mod:`ancf.belts.forces3d`): gathering element arrays from system vectors and
combining elastic and contact terms into the residual and the bordered iteration matrix.
"""
from __future__ import annotations

import numpy as np
from numba import njit

from ancf.core.pattern import scatter

DRIVEN = 1  # index of the driven pulley in the pulley arrays


@njit(cache=True)
def gather(x, vidx, E, V, v):
    """Element coordinates E and velocities V (nel, nshape, dim) from system vectors x, v."""
    nel, nd = vidx.shape
    dim = E.shape[2]
    for e in range(nel):
        for a in range(nd):
            E[e, a // dim, a % dim] = x[vidx[e, a]]
            V[e, a // dim, a % dim] = v[vidx[e, a]]


@njit(cache=True)
def _arrays(nel, nd, npul, want_J):
    """Zeroed contact outputs: Q, Kq, Cv, Qw, T, dTq, dTv, dTw."""
    nj = nel if want_J else 0
    return (np.zeros((nel, nd)), np.zeros((nj, nd, nd)), np.zeros((nj, nd, nd)),
            np.zeros((nj, npul, nd)), np.zeros(npul), np.zeros((npul, nj, nd)),
            np.zeros((npul, nj, nd)), np.zeros(npul))


@njit(cache=True)
def _combine(g, K, c, vidx, midx, bp, gp, want_J, Ta, fz, mat, col, row):
    """Elastic gradient g, K and contact outputs c into fz, mat, col, row; the corner."""
    Q, Kq, Cv, Qw, T, dTq, dTv, dTw = c
    nel, nd = g.shape
    n = fz.size - 1
    fz[:] = 0.0
    g -= Q
    if want_J:
        mat[:, :] = 0.0
        col[:] = 0.0
        row[:] = 0.0
        for e in range(nel):
            for a in range(nd):
                i = vidx[e, a]
                col[i] -= gp * Qw[e, DRIVEN, a]
                row[i] -= bp * dTq[DRIVEN, e, a] + gp * dTv[DRIVEN, e, a]
                for b in range(nd):
                    K[e, a, b] = bp * (K[e, a, b] - Kq[e, a, b]) - gp * Cv[e, a, b]
    scatter(g, K, vidx, midx, fz, mat, want_J)
    fz[n] = -T[DRIVEN] + Ta
    return -gp * dTw[DRIVEN]
