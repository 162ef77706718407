"""The speed-accuracy Pareto plots (issue 23): redrawn from the committed rows
(``reports/data/speed_accuracy_SCENE.csv``) without a sweep; the y axis names the error;
the front's runs are labelled by their element count; a one-run front is drawn (circled)
and its legend entry says so; element-count axes are labelled plainly."""
from __future__ import annotations

import shutil

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import pandas as pd  # noqa: E402
import pytest  # noqa: E402

from ancf.common.paths import REPORTS  # noqa: E402
from ancf.reports import output  # noqa: E402
from ancf.reports.speed_accuracy import figures_from_data, pareto, plot  # noqa: E402
from ancf.study.references import spec  # noqa: E402


def _rows(scene: str) -> pd.DataFrame:
    return pd.read_csv(REPORTS / "data" / f"speed_accuracy_{scene.replace('-', '_')}.csv")


def test_redrawn_from_the_committed_rows(tmp_path):
    (tmp_path / "data").mkdir()
    for name in ("plate_square", "belt3d"):  # plate-square's CSV has no ng column
        shutil.copy(REPORTS / "data" / f"speed_accuracy_{name}.csv", tmp_path / "data")
    before = output.settings()
    try:
        output.configure(tmp_path)
        assert figures_from_data() == ["plate-square", "belt3d"]
    finally:
        output.configure(before.root, before.quick)
    assert (tmp_path / "figures" / "pareto_plate_square.png").stat().st_size > 0


@pytest.mark.parametrize("scene", ["belt3d", "cantilever"])
def test_axis_legend_and_labels(scene):
    df, s = _rows(scene), spec(scene)
    fig, ax = plt.subplots()
    plot(df, scene, s.dynamic, ax, ylabel=s.reference().measure)
    front = pareto(df[df["status"] == "ok"])
    entries = [t.get_text() for t in ax.get_legend().get_texts()]
    fronts = [e for e in entries if e.startswith("Pareto front")]
    assert fronts == ["Pareto front (one run)" if len(front) == 1 else "Pareto front"]
    line = [ln for ln in ax.get_lines() if ln.get_label() == fronts[0]][0]
    assert line.get_marker() == "o" and len(line.get_xdata()) == len(front)
    assert ax.get_ylabel() == s.reference().measure != "error"
    labels = {t.get_text() for t in ax.texts}
    assert str(int(front["n_elements"].iloc[0])) in labels
    assert len(labels) <= len(front) + 1  # at most one per front run, and the key
    plt.close(fig)


def test_count_axis_reads_plainly():
    fig, ax = plt.subplots()
    ax.loglog([2, 4, 8, 16], [1, 0.5, 0.2, 0.1])
    output.count_axis(ax, [2, 4, 8, 16])
    fig.canvas.draw()
    assert [t.get_text() for t in ax.get_xticklabels()] == ["2", "4", "8", "16"]
    assert all(t.get_text() == "" for t in ax.xaxis.get_minorticklabels())
    plt.close(fig)
