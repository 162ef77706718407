"""The tutorials (docs/tutorials/*.md) run as they are written and print what they say.

Each page's ```python blocks are joined, in order, into one script in a fresh folder and run
there in a child process (``sys.executable``, ``MPLBACKEND=Agg``), as a reader running the
blocks one after another in one session would; the test then checks the key lines of what
it printed, against references computed here independently where that is cheap (Euler-
Bernoulli's roots, Navier's double series, the thesis's transcribed table, the steady
reference of the page's own drive file).  Each page takes a few seconds with numba's
kernels cached (the belt drive's first run compiles them: minutes), so none is marked
slow.  A last test holds the list of pages to the folder and to mkdocs.yml's nav.
"""
import math
import os
import re
import subprocess
import sys

import numpy as np
import pandas as pd
import pytest
import yaml

from ancf.common.paths import REPO

TUTORIALS = REPO / "docs" / "tutorials"
FENCE = re.compile(r"^```python\n(.*?)^```", re.S | re.M)
NUM = r"([-+]?\d+(?:\.\d+)?(?:e[-+]?\d+)?)"


def script(page: str) -> str:
    """The page's Python blocks, in order, as one script."""
    blocks = FENCE.findall((TUTORIALS / page).read_text(encoding="utf-8"))
    assert blocks, f"{page} has no ```python block"
    return "\n".join(blocks)


def run_page(page: str, folder) -> str:
    """Run the page's script in ``folder``; its stdout (the test fails on a non-zero exit)."""
    (folder / "tutorial.py").write_text(script(page), encoding="utf-8")
    env = {**os.environ, "MPLBACKEND": "Agg"}
    p = subprocess.run([sys.executable, "tutorial.py"], cwd=folder, env=env,
                       capture_output=True, text=True, timeout=900)
    assert p.returncode == 0, f"{page} exited {p.returncode}:\n{p.stdout}\n{p.stderr}"
    return p.stdout


def rows(pattern: str, out: str) -> list[tuple]:
    """Every match of ``pattern`` (anchored at a line's start) in ``out``."""
    return re.findall(rf"^{pattern}", out, re.M)


def tip_error(run, rod) -> float:
    """The cantilever's tip miss over the rod's tip deflection."""
    dx = run.results["tip_x"] - rod.results["tip_x"]
    dy = run.results["tip_y"] - rod.results["tip_y"]
    return math.hypot(dx, dy) / math.hypot(rod.results["tip_x"] - run.params["L"],
                                           rod.results["tip_y"])


# --- the checks per page ------------------------------------------------------------------

def check_thesis_table(out: str, folder) -> None:
    """Every printed cell: the published value is thesis Table 2.3's (as transcribed in
    ancf/reports/published.py), ours is a run made here (to the 5 printed decimals), and
    the relative error is below the table's rounding, 1e-5."""
    import ancf
    from ancf.reports.published import CANTILEVER_COLUMNS, THESIS_2_3, THESIS_OS
    cells = rows(rf"(linear|omar-shabana)\s+(\d+)\s+{NUM}\s+{NUM}\s+{NUM}\s+{NUM}\s+{NUM}$", out)
    assert len(cells) == 8, out
    settings = {"linear": {}, "omar-shabana": {k.removeprefix("os_"): v
                                               for k, v in THESIS_OS.items()}}
    for element, n, x, px, y, py, err in cells:
        pub = THESIS_2_3["rows"][int(n)][CANTILEVER_COLUMNS.index(element)]
        assert (float(px), float(py)) == pub
        run = ancf.run("cantilever", element=element, n_elements=int(n), **settings[element])
        assert abs(float(x) - run.results["tip_x"]) <= 5e-6
        assert abs(float(y) - run.results["tip_y"]) <= 5e-6
        assert float(err) < 1e-5
    rod = ancf.analytic("reissner").results
    assert f"Reissner rod: tip = ({rod['tip_x']:.5f}, {rod['tip_y']:.5f}) m" in out
    assert re.search(r"--set n_elements=8: tip_y = -0\.67691 m", out)


def check_own_drive(out: str, folder) -> None:
    """The steady reference printed is that of the page's drive file (computed here, to
    the printed digits), the run is within the page's 'about 5 %' of it (tolerance 0.1),
    and the GIF was written."""
    from ancf.scenes.belt_drive import SCENE, steady_reference
    ref = steady_reference(SCENE.resolve({"file": str(folder / "my_drive.toml")}))
    speeds = {name: float(steady) for name, _, steady in
              rows(rf"  (\w+)\s+omega: march\s+{NUM}\s+steady\s+{NUM}", out)}
    free = [p for p in ref["pulleys"] if p["law"] not in ("prescribed", "fixed")]
    assert set(speeds) == {p["name"] for p in free}, out
    for p in free:
        assert abs(speeds[p["name"]] - p["omega"]) <= 5e-5
    tensions = [float(t) for _, t in rows(rf"  span \w+-\w+: march\s+{NUM}\s+steady\s+{NUM}",
                                          out)]
    assert np.allclose(tensions, [s["tension_N"] for s in ref["spans"]], rtol=0, atol=5e-4)
    error = float(rows(rf"error against the steady reference: {NUM}", out)[0])
    assert 0 < error < 0.1
    assert "warnings: none" in out
    assert re.search(r"wrote my_drive\.gif \(\d+ kB\)", out)
    assert (folder / "my_drive.gif").read_bytes()[:4] == b"GIF8"


def check_cheapest_model(out: str, folder) -> None:
    """The printed front is the Pareto front of the page's sweep file (computed here), the
    recommendation is recommend's answer from that file, and its rerun meets the 1e-2."""
    import ancf
    from ancf.reports.speed_accuracy import pareto
    df = pd.read_parquet(folder / "sweep.parquet")
    assert (df["status"] == "ok").all() and len(df) == df["element"].nunique() * df[
        "n_elements"].nunique()
    front = pareto(df)
    printed = [(e, int(n)) for e, n in rows(r"  (\S+)\s+n =\s+(\d+)  work", out)]
    assert printed == list(zip(front["element"], front["n_elements"].astype(int)))
    rec = ancf.recommend("cantilever", 1e-2, data=str(folder / "sweep.parquet"))
    assert f"model: {rec['model']}" in out
    rerun = float(rows(rf"rerun: error {NUM}", out)[0])
    assert rerun <= 1e-2 and math.isclose(rerun, rec["error"], rel_tol=1e-2)
    assert (folder / "pareto.png").read_bytes()[:4] == b"\x89PNG"


def euler_bernoulli_hz(k: int, E=2.07e11, L=2.0, h=0.1, b=0.1, rho=7850.0) -> float:
    """The k-th clamped-free Euler-Bernoulli frequency: beta L the k-th root of
    cos x cosh x = -1 (bisection near (2k - 1) pi / 2)."""
    from scipy.optimize import brentq
    x = brentq(lambda x: math.cos(x) * math.cosh(x) + 1, (k - 1) * math.pi + 0.1,
               k * math.pi)
    return x ** 2 / (2 * math.pi * L ** 2) * math.sqrt(E * b * h ** 3 / 12 / (rho * b * h))


def check_frequencies(out: str, folder) -> None:
    """Euler-Bernoulli's column against the roots computed here (printed to 1e-3 Hz), the
    axial mode found, and f1 converging (its error falling with every doubling, below
    1e-4 at 64 elements)."""
    kinds = rows(r"  mode (\d): \s*\S+ Hz  (\w+)", out)
    assert [k for _, k in kinds].count("axial") == 1 and kinds[3][1] == "axial"
    table = rows(rf"\s+(\d)\s+{NUM}\s+{NUM}\s+\S+%\s+{NUM}\s+\S+%$", out)
    assert len(table) == 5, out
    for k, _, _, eb in table:
        assert abs(float(eb) - euler_bernoulli_hz(int(k))) <= 1e-3
    conv = rows(rf"  n =\s*(\d+): f1 =\s*{NUM} Hz \({NUM}\)", out)
    errors = [abs(float(e)) for _, _, e in conv]
    assert len(errors) == 5 and all(a > b for a, b in zip(errors, errors[1:]))
    assert errors[-1] < 1e-4


def navier_centre_deflection(a=1.0, h=0.01, E=2.1e11, nu=0.3, p=1000.0, terms=801) -> float:
    """Navier's double series for the simply supported square plate's centre deflection,
    summed directly over odd m, n < ``terms`` (tail below 1e-9 relative)."""
    D = E * h ** 3 / (12 * (1 - nu ** 2))
    m = np.arange(1, terms, 2, dtype=float)
    M, N = np.meshgrid(m, m)
    signs = np.sin(M * np.pi / 2) * np.sin(N * np.pi / 2)
    return float(16 * p / (np.pi ** 6 * D) * np.sum(signs / (M * N * (M ** 2 + N ** 2) ** 2))
                 * a ** 4)


def check_own_element(out: str, folder) -> None:
    """The derivative check passes, the registered linear element's errors are those
    computed here (3 printed digits: 1 %), the new element locks as the page says (over
    0.1 on the three nu = 0.3 benchmarks), and the printed Navier value is the series
    summed here (1e-6)."""
    import ancf
    assert float(rows(rf"gradient vs central differences: {NUM}", out)[0]) < 1e-6
    table = {e: [float(v) for v in vals] for e, *vals in
             rows(rf"(linear|omar-shabana|linear-lame)\s+{NUM}\s+{NUM}\s+{NUM}\s+{NUM}$", out)}
    assert set(table) == {"linear", "omar-shabana", "linear-lame"}, out
    m1 = tip_error(ancf.run("cantilever", n_elements=16), ancf.analytic("reissner"))
    m2 = tip_error(ancf.run("cantilever", n_elements=16, h=0.5, nu=0.0),
                   ancf.analytic("reissner", h=0.5, nu=0.0))
    w = ancf.run("simply-supported", n_elements=16, nu=0.3).results["mid_deflection_m"]
    w_ref = ancf.analytic("timoshenko", nu=0.3).results["mid_deflection_m"]
    f1 = ancf.modes("cantilever", n_elements=16, count=1).results["frequencies_hz"][0]
    f1_ref = ancf.analytic("beam-modes", count=1).results["frequencies_hz"][0]
    ours = [m1, m2, abs(w / w_ref - 1), abs(f1 / f1_ref - 1)]
    assert np.allclose(table["linear"], ours, rtol=1e-2, atol=0)
    lame = table["linear-lame"]
    assert min(lame[0], lame[2], lame[3]) > 0.1 and lame[1] < 0.02
    plates = rows(rf"  plate36\s+(\d+) x\s+\d+: w = {NUM} m  Navier {NUM} m  rel.err {NUM}", out)
    assert len(plates) == 3
    navier = navier_centre_deflection()
    for _, _, nav, err in plates:
        assert math.isclose(float(nav), navier, rel_tol=1e-6)
    assert float(plates[-1][3]) < 1e-2


def check_dask_sweep(out: str, folder) -> None:
    """The cluster was on 127.0.0.1 and closed, every run of the grid is a row of the
    file (the product of its values' counts), one row equals a local run (1e-9), the CLI
    sweep went through the same scheduler and the rerun ran nothing."""
    import ancf
    assert re.search(r"^cluster: tcp://127\.0\.0\.1:\d+ 2 workers$", out, re.M), out
    assert out.rstrip().endswith("cluster closed")
    df = pd.read_parquet(folder / "large.parquet")
    grid = [df[k].nunique() for k in ("element", "n_elements", "nu", "h")]
    assert len(df) == math.prod(grid) and (df["status"] == "ok").all()
    n_runs = int(rows(r"(\d+) runs on tcp://127\.0\.0\.1:\d+: \{'runs': (\d+)", out)[0][0])
    assert n_runs == len(df)
    row = df[(df["element"] == "linear") & (df["n_elements"] == 8) & (df["nu"] == 0.3)
             & (df["h"] == 0.1)].iloc[0]
    local = tip_error(ancf.run("cantilever", n_elements=8), ancf.analytic("reissner"))
    assert math.isclose(row["error"], local, rel_tol=1e-9)
    assert re.search(r"ancf sweep --scheduler: exit 0, \{.*\"rows\": 3", out)
    assert f"{len(df)} already in large.parquet, 0 to run" in out


PAGES = {"thesis-table.md": check_thesis_table,
         "own-drive.md": check_own_drive,
         "cheapest-model.md": check_cheapest_model,
         "frequencies.md": check_frequencies,
         "own-element.md": check_own_element,
         "dask-sweep.md": check_dask_sweep}


#: the pages whose run takes 5 s or more (own-drive 14 s, dask-sweep 11 s, cheapest-model 7 s
#: warm): in the full tier only
LONG_PAGES = ("own-drive.md", "cheapest-model.md", "dask-sweep.md")


@pytest.mark.parametrize("page", [pytest.param(p, marks=pytest.mark.slow) if p in LONG_PAGES
                                  else p for p in PAGES])
def test_tutorial_runs_and_prints_what_it_says(page, tmp_path):
    out = run_page(page, tmp_path)
    PAGES[page](out, tmp_path)


class _Loader(yaml.SafeLoader):
    """YAML's safe loader that reads any tag (``!!python/name:...``, ``!ENV``) as None."""


_Loader.add_multi_constructor("", lambda loader, suffix, node: None)


def _nav_pages(nav) -> list[str]:
    """Every page path under the nav's "Tutorials" section."""
    section = next(item["Tutorials"] for item in nav
                   if isinstance(item, dict) and "Tutorials" in item)
    return [v for item in section for v in (item.values() if isinstance(item, dict) else [item])]


def test_every_tutorial_is_tested_and_in_the_nav():
    pages = sorted(p.name for p in TUTORIALS.glob("*.md"))
    assert sorted(PAGES) == [p for p in pages if p != "index.md"]
    config = yaml.load((REPO / "mkdocs.yml").read_text(encoding="utf-8"), Loader=_Loader)
    assert sorted(_nav_pages(config["nav"])) == sorted(f"tutorials/{p}" for p in pages)
