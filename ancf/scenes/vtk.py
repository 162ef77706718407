"""ParaView output (``ancf run SCENE --vtk DIR``, ``ancf.run(..., vtk=DIR)``): the deformed
mesh of every output step (:func:`ancf.scenes.frames.frames`) as one ``.vtu`` file each,
written by ``meshio``, and ``DIR/SCENE.pvd``, the time series ParaView opens.

``meshio`` is imported only when something is written, so a run without ``--vtk`` does
not load it.  :func:`check_directory` refuses a directory that cannot be written before
the run starts (one ``InputError`` line naming the path).
"""
from __future__ import annotations

import os
from pathlib import Path
from xml.sax.saxutils import quoteattr

from ancf.common.params import InputError


def check_directory(directory, option: str = "--vtk") -> Path:
    """``directory`` as a Path, created if missing; InputError (naming ``option``, the
    command-line option that gave it) when it is a file, lies under a file or cannot be
    written."""
    path = Path(directory).expanduser()
    if str(directory).strip() == "":
        raise InputError(f"{option} '': expected a directory")
    for parent in [path, *path.parents]:
        if parent.exists() and not parent.is_dir():
            what = "is a file" if parent == path else f"lies under the file {str(parent)!r}"
            raise InputError(f"{option} {str(directory)!r}: {what}; allowed: a directory that "
                             "exists or can be created")
    try:
        path.mkdir(parents=True, exist_ok=True)
    except OSError as exc:
        raise InputError(f"{option} {str(directory)!r}: cannot create the directory "
                         f"({exc.strerror or exc})") from None
    if not os.access(path, os.W_OK | os.X_OK):
        raise InputError(f"{option} {str(directory)!r}: the directory is not writable")
    return path


#: the scenes whose runs ``--gif`` animates (``ancf.reports.animations``)
GIF_SCENES = ("belt2d", "belt3d", "belt-drive")


def check_gif(scene: str, path) -> Path:
    """``--gif PATH`` checked before the run: a belt drive's run (:data:`GIF_SCENES`), a
    ``.gif`` file name, and a folder that exists or can be created and written."""
    if scene not in GIF_SCENES:
        raise InputError(f"--gif: {scene} has no animation; allowed: the belt drives "
                         f"({', '.join(GIF_SCENES)})")
    gif = Path(path).expanduser()
    if gif.suffix.lower() != ".gif" or not gif.stem:
        raise InputError(f"--gif {str(path)!r}: expected a file name ending in .gif")
    if gif.is_dir():
        raise InputError(f"--gif {str(path)!r}: is a directory; allowed: a .gif file name")
    check_directory(gif.parent, f"--gif {str(path)!r}: its folder")
    return gif


def pvd_text(entries) -> str:
    """The ``.pvd`` collection of (time, file name) entries."""
    rows = "\n".join(f'    <DataSet timestep="{t!r}" group="" part="0" file={quoteattr(f)}/>'
                     for t, f in entries)
    return ('<?xml version="1.0"?>\n'
            '<VTKFile type="Collection" version="0.1" byte_order="LittleEndian">\n'
            f"  <Collection>\n{rows}\n  </Collection>\n</VTKFile>\n")


def write(frames, directory, name: str) -> Path:
    """Write ``frames`` as ``directory/name_NNNNN.vtu`` and ``directory/name.pvd``;
    returns the path of the ``.pvd``."""
    import meshio

    path = check_directory(directory)
    width = max(5, len(str(len(frames) - 1)))
    entries = []
    pvd = path / f"{name}.pvd"
    try:
        for i, fr in enumerate(frames):
            fname = f"{name}_{i:0{width}d}.vtu"
            mesh = meshio.Mesh(fr.points, fr.cells, point_data=fr.point_data)
            meshio.write(path / fname, mesh, file_format="vtu")
            entries.append((float(fr.time), fname))
        pvd.write_text(pvd_text(entries))
    except OSError as exc:  # a full disk, a directory removed under the run
        raise InputError(f"--vtk {str(directory)!r}: cannot write "
                         f"({exc.strerror or exc})") from None
    return pvd


def write_run(scene: str, extra: dict, directory, per_element: int = 8) -> tuple[Path, int]:
    """Write a finished run of ``scene`` (its ``SceneResult.extra``); returns (the ``.pvd``
    path, the number of steps)."""
    from ancf.scenes.frames import frames as frames_of
    frames = frames_of(scene, extra, per_element)
    return write(frames, directory, scene), len(frames)
