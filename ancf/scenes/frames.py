"""The geometry of a finished run, step by step: what ``--vtk`` writes and what the Python
API (``ancf.run``) returns as arrays.

A scene's :class:`~ancf.scenes.base.SceneResult` keeps its model in ``extra`` (the beams'
mesh and coordinates, the dynamic scenes' sampled states, the belt drives' model and
march); this module turns it into

* :func:`states`: the output times (``None`` for a static scene), the global coordinate
  vectors at those times (static: the one final state) and the reference coordinates;
* :func:`node_positions`: the nodal positions ``r`` (n_nodes, dim) of a coordinate vector;
* :func:`frames`: one :class:`Frame` per output step, the deformed mesh with its cells and
  point data: beams as their centreline (each element sampled at ``per_element`` points
  with its own shape functions, ``line`` cells), plates as ``quad`` cells on their nodes,
  the 2D belt as its sampled centreline with the axial force, speed and contact pressure,
  the 3D belt as quads over its mid surface with the membrane's axial force, the speed
  along the belt and the contact pressure.

A scene without a mesh (the analytic references) has no states: :func:`has_geometry` is
False and :func:`frames` raises ``InputError``.
"""
from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from ancf.common.params import InputError

#: (dim, nodal slots) -> generated shape-function family of the planar and spatial beams
FAMILIES = {(2, ("r", "r_y")): "linear2d", (2, ("r", "r_x", "r_y")): "cubic2d",
            (3, ("r", "r_y", "r_z")): "linear3d", (3, ("r", "r_x", "r_y", "r_z")): "cubic3d"}

BELTS = ("belt2d", "belt3d")


@dataclass
class Frame:
    """One output step: ``points`` (n, 3), m; ``cells`` [(meshio cell type, (m, k) node
    indices)]; ``point_data`` {name: (n,) or (n, 3)}."""

    time: float
    points: np.ndarray
    cells: list
    point_data: dict = field(default_factory=dict)


def has_geometry(extra: dict) -> bool:
    """Whether a result's ``extra`` holds a mesh to show."""
    return "drive" in extra or "mesh" in extra


def _mesh_dim(mesh) -> int:
    return getattr(mesh, "dim", 3 if hasattr(mesh, "element_nodes") else 2)


def states(extra: dict):
    """(times or None, [coordinate vectors], reference coordinates) of a finished run; the
    belt drives' vectors are the belt's global coordinates (the pulley angle dropped)."""
    if not has_geometry(extra):
        raise InputError("this result has no mesh (an analytic reference): nothing to show")
    res = extra.get("result")
    if "drive" in extra:
        drive = extra["drive"]
        return (np.asarray(res.t, float), [drive.belt(x) for x in res.q],
                np.asarray(drive.q0, float))
    mesh = extra["mesh"]
    if res is not None:  # a dynamic beam: the sampled states
        return np.asarray(res.t, float), list(res.q), mesh.reference()
    q0 = extra.get("q0")
    return None, [extra["q"]], mesh.reference() if q0 is None else q0


def velocities(extra: dict):
    """[velocity vectors] at the output times of a dynamic run (None for a static one)."""
    res = extra.get("result")
    if res is None or getattr(res, "v", None) is None:
        return None
    if "drive" in extra:
        return [extra["drive"].belt(v) for v in res.v]
    return list(res.v)


def node_positions(extra: dict, q) -> np.ndarray:
    """Positions ``r`` (n_nodes, dim) of the nodes in coordinates ``q``, m."""
    q = np.asarray(q, float)
    if "drive" in extra:
        drive = extra["drive"]
        if hasattr(drive, "mesh"):  # the 2D belt: a closed beam mesh
            return node_positions({"mesh": drive.mesh}, q)
        return q.reshape(-1, 9)[:, :3]  # the 3D belt: 9 coordinates per node, r first
    mesh = extra["mesh"]
    dim = _mesh_dim(mesh)
    idx = [[mesh.dof(k, "r", c) for c in range(dim)] for k in range(mesh.n_nodes)]
    return q[np.asarray(idx)]


def _pad3(a: np.ndarray) -> np.ndarray:
    a = np.asarray(a, float)
    return a if a.shape[-1] == 3 else np.concatenate([a, np.zeros(a.shape[:-1] + (1,))], -1)


# --- beams: the centreline -------------------------------------------------------------

def beam_sampler(mesh, per_element: int):
    """(function q -> points (m, dim), line cells) of a beam mesh's centreline."""
    from ancf.elements.basis import family_shapes
    dim = _mesh_dim(mesh)
    family = FAMILIES[(dim, tuple(mesh.slots))]
    S = family_shapes(family)["S"]
    closed = mesh.n_nodes == mesh.n_elements
    k = per_element
    xi = np.arange(k) / k
    l = mesh.lengths
    X = xi[None, :] * l[:, None]
    L = np.broadcast_to(l[:, None], X.shape)
    zeros = [np.zeros_like(X)] * (dim - 1)
    shp = np.asarray(S(X, *zeros, L)).reshape(l.size, k, -1)  # (nel, k, nshape)
    end = None
    if not closed:  # the last node: x = l of the last element
        Xe = np.array([[l[-1]]])
        end = np.asarray(S(Xe, *[np.zeros_like(Xe)] * (dim - 1), Xe)).reshape(-1)
    n_pts = l.size * k + (0 if closed else 1)
    seg = np.arange(n_pts - (0 if closed else 1))
    cells = [("line", np.stack([seg, (seg + 1) % n_pts], 1))]
    nshape = shp.shape[-1]

    def points(q):
        E = np.asarray(q, float)[mesh.dofmap].reshape(l.size, nshape, dim)
        pts = np.einsum("eqk,ekd->eqd", shp, E).reshape(-1, dim)
        if end is not None:
            pts = np.vstack([pts, end @ E[-1]])
        return pts

    return points, cells


def _beam_frames(extra, per_element):
    times, qs, q0 = states(extra)
    vs = velocities(extra)
    points, cells = beam_sampler(extra["mesh"], per_element)
    ref = _pad3(points(q0))
    out = []
    for i, q in enumerate(qs):
        pts = _pad3(points(q))
        data = {"displacement": pts - ref}
        if vs is not None:
            data["velocity"] = _pad3(points(vs[i]))  # the shape functions map q' as q
        out.append(Frame(0.0 if times is None else float(times[i]), pts, cells, data))
    return out


# --- plates: quads on the nodes -------------------------------------------------------

def _plate_frames(extra):
    mesh = extra["mesh"]
    _, qs, q0 = states(extra)
    ref = node_positions(extra, q0)
    cells = [("quad", np.asarray(mesh.element_nodes))]
    return [Frame(0.0, pts, cells, {"displacement": pts - ref})
            for pts in (node_positions(extra, q) for q in qs)]


# --- the 2D belt ----------------------------------------------------------------------

def _belt2d_frames(extra, per_element):
    from ancf.belts.post2d import sample
    drive, res = extra["drive"], extra["result"]
    out, cells = [], None
    for x, v, t in zip(res.q, res.v, res.t):
        smp = sample(drive, x, v, float(t), npts=per_element)
        n = smp.s.size
        if cells is None:
            seg = np.arange(n)
            cells = [("line", np.stack([seg, (seg + 1) % n], 1))]
        out.append(Frame(float(t), _pad3(smp.r), cells, {
            "axial_force_N": np.asarray(smp.N, float),
            "speed_m_s": np.asarray(smp.speed, float),
            "contact_pressure_N_m": np.asarray(smp.Fn, float).sum(axis=1),
            "penetration_m": np.asarray(smp.d, float).max(axis=1),
            "velocity": _pad3(smp.v), "arc_length_m": np.asarray(smp.s, float)}))
    return out


# --- the 3D belt ----------------------------------------------------------------------

def _belt3d_frames(extra, per_element):
    from ancf.belts.contact3d import contact_state3d
    from ancf.belts.post3d import _contact_args, membrane_force
    from ancf.elements.basis import plate36_S, plate36_x, plate36_y
    drive, res = extra["drive"], extra["result"]
    s, L = drive.spec, drive.lengths
    nel, k = L.size, per_element
    xi = np.arange(k) / k
    X = np.repeat(xi[None, :] * L[:, None], 2, axis=1).reshape(nel, k, 2)
    Y = np.broadcast_to(np.array([0.0, s.width]), X.shape)
    A, B = np.broadcast_to(L[:, None, None], X.shape), np.full(X.shape, s.width)
    S, Sx, Sy = (np.ascontiguousarray(np.asarray(f(X, Y, A, B)).reshape(nel, 2 * k, 12))
                 for f in (plate36_S, plate36_x, plate36_y))
    m = nel * k  # stations along the belt; point (station, edge) = 2 station + edge
    st = np.arange(m)
    nxt = (st + 1) % m
    cells = [("quad", np.stack([2 * st, 2 * nxt, 2 * nxt + 1, 2 * st + 1], 1))]
    out = []
    for x, v, t in zip(res.q, res.v, res.t):
        E, V, o, om, odot = _contact_args(drive, x, v, float(t))
        r, d, Fn = contact_state3d(E, V, S, o, drive.axes, drive.radii, om, odot, drive.prm)[:3]
        rx, ry = (np.einsum("eqk,ekd->eqd", Bm, E) for Bm in (Sx, Sy))
        vel = np.einsum("eqk,ekd->eqd", S, V)
        tang = rx / np.linalg.norm(rx, axis=-1, keepdims=True)
        flat = lambda a: np.asarray(a).reshape(2 * m, *np.shape(a)[2:])  # noqa: E731
        out.append(Frame(float(t), flat(r), cells, {
            "axial_force_N": flat(membrane_force(rx, ry, s.E, s.nu, s.h, s.width)),
            "speed_m_s": flat(np.einsum("eqd,eqd->eq", tang, vel)),
            "contact_pressure_N_m2": flat(Fn.sum(axis=-1)),
            "penetration_m": flat(d.max(axis=-1)), "velocity": flat(vel)}))
    return out


def frames(scene: str, extra: dict, per_element: int = 8) -> list[Frame]:
    """One :class:`Frame` per output step of a finished run of ``scene`` (module doc)."""
    if not has_geometry(extra):
        raise InputError(f"{scene}: this result has no mesh (an analytic reference): "
                         "nothing to write")
    if "drive" in extra:  # belt2d, belt-drive (planar) and belt3d
        if hasattr(extra["drive"], "axes"):
            return _belt3d_frames(extra, max(per_element // 2, 1))
        return _belt2d_frames(extra, per_element)
    if hasattr(extra["mesh"], "element_nodes"):
        return _plate_frames(extra)
    return _beam_frames(extra, per_element)
