"""The sparsity of a reduced system, computed once, and compiled scatters into it.

Constraints eliminated as ``q = T z + g`` with ``T`` a 0/1 selection (fixed and
prescribed coordinates dropped, tied ones sharing a column) turn the reduced
tangent ``T^T K T`` into a plain scatter: element entry (a, b) of element e goes to
(z(a), z(b)) or nowhere.  :class:`ReducedPattern` numbers the independent
coordinates ``z`` (reverse Cuthill-McKee when that narrows the band, e.g. for a
closed loop), picks the storage from the pattern (band rows of width 3 kl + 1,
see :mod:`ancf.solvers.banded`, or CSR) and keeps, per element group, the target
index of every element vector and matrix entry (-1: eliminated).  The scatter then
writes straight into the solver's storage: no COO, no CSR rebuild, no ``T^T K T``.
scipy loads only where a CSR matrix is made: ``T`` given as a
:class:`~ancf.core.constraints.Selection` and band storage need none.
"""
from __future__ import annotations

import weakref
from typing import TYPE_CHECKING

import numpy as np

from ancf.common.leaf import leaf
from ancf.core.constraints import Selection

if TYPE_CHECKING:
    import scipy.sparse as sp


#: band storage is used while it holds at most this many times the nonzeros
BAND_FILL_LIMIT = 8.0


def width(kl: int) -> int:
    """Row width of band storage with half-bandwidth kl (``ancf.solvers.banded``)."""
    return 3 * kl + 1


@leaf
def scatter(ge, Ke, vidx, midx, vec, mat, want_K):
    """vec[vidx] += ge and, if want_K, mat.flat[midx] += Ke (negative index: dropped)."""
    nel, nd = ge.shape
    flat = mat.reshape(-1)
    for e in range(nel):
        for a in range(nd):
            i = vidx[e, a]
            if i >= 0:
                vec[i] += ge[e, a]
            if want_K:
                for b in range(nd):
                    j = midx[e, a, b]
                    if j >= 0:
                        flat[j] += Ke[e, a, b]


def assemble_group(group, z, gq, want_K, grad, K):
    """grad = T^T dU/dq at q = T z + gq and, if want_K, K = T^T (d2U/dq2) T, for a compiled
    element group (:meth:`ReducedPattern.compiled`), in one call from compiled code.
    Implemented per group type by the element layer (:mod:`ancf.common.dispatch`;
    the planar Green strains: :func:`ancf.elements.green2d.assemble_band`)."""
    raise NotImplementedError("resolved at compile time by the type of group")


def _selection_columns(T, n_dofs: int) -> np.ndarray:
    """Column of each global coordinate in T (a 0/1 selection), -1 where none."""
    if isinstance(T, Selection):
        return T.column
    import scipy.sparse as sp
    T = sp.csr_matrix(T)
    counts = np.diff(T.indptr)
    if counts.max(initial=0) > 1 or not np.all(T.data == 1.0):
        raise ValueError("the elimination matrix T must be a 0/1 selection (one entry per row)")
    col = np.full(n_dofs, -1, dtype=np.int64)
    col[counts == 1] = T.indices
    return col


def _bandwidth(r, c, order) -> int:
    return int(np.abs(order[r] - order[c]).max(initial=0))


class ReducedPattern:
    """Reduced numbering and storage of ``T^T K T`` for element groups with DOF maps
    ``dofmaps`` (each (nel, nd)) over ``n_dofs`` global coordinates."""

    def __init__(self, n_dofs: int, dofmaps, T):
        self.n_dofs = n_dofs
        col = _selection_columns(T, n_dofs)
        self.n = int(T.shape[1])
        pairs = [(col[d][:, :, None], col[d][:, None, :]) for d in map(np.asarray, dofmaps)]
        r = np.concatenate([np.broadcast_to(a, (a.shape[0], a.shape[1], b.shape[2])).ravel() for a, b in pairs])
        c = np.concatenate([np.broadcast_to(b, (a.shape[0], a.shape[1], b.shape[2])).ravel() for a, b in pairs])
        keep = (r >= 0) & (c >= 0)
        r, c = r[keep], c[keep]
        self.order = self._numbering(r, c)
        ro, co = self.order[r], self.order[c]
        self.nnz = int(np.unique(ro * self.n + co).size)
        self.kl = _bandwidth(r, c, self.order)
        self.band = width(self.kl) * self.n <= BAND_FILL_LIMIT * max(self.nnz, 1)
        sel = np.flatnonzero(col >= 0)
        self.qsel, self.zsel = sel, self.order[col[sel]]
        self.z_of = np.full(n_dofs, -1, dtype=np.int64)  # global coordinate -> position
        self.z_of[sel] = self.zsel
        self._csr = None if self.band else self._csr_pattern(ro, co)
        self.groups = [self._targets(col[np.asarray(d)]) for d in dofmaps]

    def _numbering(self, r, c) -> np.ndarray:
        """order[z] = position; natural unless RCM narrows the band."""
        natural = np.arange(self.n)
        if self.n == 0 or _bandwidth(r, c, natural) * 3 < 64:
            return natural
        import scipy.sparse as sp
        from scipy.sparse.csgraph import reverse_cuthill_mckee  # loads scipy.linalg: ~0.1 s
        g = sp.csr_matrix((np.ones(r.size), (r, c)), shape=(self.n, self.n))
        perm = reverse_cuthill_mckee(g, symmetric_mode=True)
        order = np.empty(self.n, dtype=np.int64)
        order[perm] = natural
        return order if _bandwidth(r, c, order) < _bandwidth(r, c, natural) else natural

    def _csr_pattern(self, ro, co):
        self._keys = np.unique(ro * self.n + co)  # row-major order = CSR data order
        rows, cols = self._keys // self.n, self._keys % self.n
        import scipy.sparse as sp
        return sp.csr_matrix((np.ones(self._keys.size), (rows, cols)), shape=(self.n, self.n))

    def _targets(self, zc):
        """(vidx, midx) of one group from its reduced columns zc (nel, nd), -1 = dropped."""
        z = np.where(zc >= 0, self.order[np.maximum(zc, 0)], -1)
        a, b = z[:, :, None], z[:, None, :]
        ok = (a >= 0) & (b >= 0)
        if self.band:
            target = a * width(self.kl) + (b - a + self.kl)
        else:
            target = self._csr_slot(np.maximum(a, 0), np.maximum(b, 0))
        return np.ascontiguousarray(z), np.ascontiguousarray(np.where(ok, target, -1))

    def _csr_slot(self, a, b):
        return np.searchsorted(self._keys, a * self.n + b)

    def compiled(self, assembly):
        """The compiled element group of :func:`assemble_group` for a single group on band
        storage, built by its strain model's ``band_group`` (the planar Green strains,
        :mod:`ancf.elements.green2d`), or None (then :meth:`assemble` serves)."""
        grps = assembly.groups
        strain = getattr(grps[0].element, "strain", None) if len(grps) == 1 else None
        build = getattr(strain, "band_group", None)
        return build(self, grps[0]) if self.band and build is not None else None

    # --- storage -----------------------------------------------------------------------
    def zeros_matrix(self) -> np.ndarray:
        """Empty storage: band rows (n, 3 kl + 1) or CSR data (nnz,)."""
        return np.zeros((self.n, width(self.kl)) if self.band else (self.nnz,))

    def as_csr(self, data) -> sp.csr_matrix:
        """The stored matrix as CSR in the reduced (possibly reordered) numbering."""
        import scipy.sparse as sp
        if not self.band:
            A = self._csr
            return sp.csr_matrix((data, A.indices, A.indptr), shape=A.shape)
        kl = self.kl
        i, off = np.nonzero(data[:, : 2 * kl + 1])
        j = i + off - kl
        ok = (j >= 0) & (j < self.n)
        return sp.csr_matrix((data[i[ok], off[ok]], (i[ok], j[ok])), shape=(self.n, self.n))

    def inf_norm(self, data) -> float:
        """Largest absolute row sum of the stored matrix."""
        if self.band:
            return float(np.abs(data).sum(axis=1).max(initial=0.0))
        return float(np.asarray(abs(self.as_csr(data)).sum(axis=1)).max(initial=0.0))

    # --- vectors -----------------------------------------------------------------------
    def expand(self, z, g) -> np.ndarray:
        """q = T z + g."""
        q = np.array(g, dtype=float)
        q[self.qsel] += z[self.zsel]
        return q

    def restrict(self, q) -> np.ndarray:
        """z from a global q that satisfies the ties."""
        z = np.zeros(self.n)
        z[self.zsel] = np.asarray(q)[self.qsel]
        return z

    def reduce(self, Q) -> np.ndarray:
        """T^T Q (a global force vector in the reduced numbering)."""
        out = np.zeros(self.n)
        np.add.at(out, self.zsel, np.asarray(Q)[self.qsel])
        return out

    def add_global(self, mat, A, scale=1.0) -> None:
        """mat += scale T^T A T for a global sparse matrix A whose couplings lie in the
        pattern (declared through a force term's ``dofmap``)."""
        import scipy.sparse as sp
        A = sp.coo_matrix(A)
        r, c = self.z_of[A.row], self.z_of[A.col]
        ok = (r >= 0) & (c >= 0)
        r, c, v = r[ok], c[ok], scale * A.data[ok]
        if self.band:
            if np.any(np.abs(r - c) > self.kl):
                raise ValueError("a force term couples coordinates outside the sparsity pattern; "
                                 "declare them through the term's dofmap")
            np.add.at(mat, (r, c - r + self.kl), v)
        else:
            np.add.at(mat, self._csr_slot(r, c), v)

    def mass(self, assembly) -> np.ndarray:
        """T^T M T from the element mass matrices, in this pattern's storage."""
        mat, dummy = self.zeros_matrix(), np.zeros(self.n)
        for grp, (vidx, midx) in zip(assembly.groups, self.groups):
            el = grp.element
            scatter(np.zeros((el.nel, el.ndof)), el.mass(), vidx, midx, dummy, mat, True)
        return mat

    def assemble(self, assembly, q, want_K=True, vec=None, mat=None):
        """T^T dU/dq and T^T K T at q, scattered into ``vec``/``mat`` (fresh if None)."""
        vec = np.zeros(self.n) if vec is None else vec
        mat = (self.zeros_matrix() if want_K else np.zeros((1, 1))) if mat is None else mat
        for grp, (vidx, midx) in zip(assembly.groups, self.groups):
            ge, Ke = grp.element.gradient(q[grp.dofmap], tangent=want_K)
            scatter(ge, Ke if want_K else _EMPTY3, vidx, midx, vec, mat, want_K)
        return vec, mat


_EMPTY3 = np.zeros((0, 0, 0))


_SHARED = weakref.WeakKeyDictionary()  # assembly -> {(n_free, columns): ReducedPattern}


def shared(assembly, T) -> ReducedPattern:
    """The :class:`ReducedPattern` of ``assembly``'s element groups under the selection T,
    built once per assembly and T's columns and shared by the runs of a sweep or a table
    that reuse the assembly (``ancf.scenes.beam_static.build``)."""
    col = _selection_columns(T, assembly.n_dofs)
    per = _SHARED.setdefault(assembly, {})
    key = (int(T.shape[1]), col.tobytes())
    if key not in per:
        per[key] = ReducedPattern(assembly.n_dofs, [g.dofmap for g in assembly.groups], T)
    return per[key]
