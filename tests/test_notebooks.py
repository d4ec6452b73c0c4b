"""Notebooks: each runs top to bottom on the tiny run folder (nbclient), and the committed files hold no outputs."""

from pathlib import Path

import nbformat
import pytest
import sweep_fixtures
from sweep_fixtures import SMALL

tiny_run = sweep_fixtures.tiny_run  # the session fixture

NOTEBOOKS = sorted((Path(__file__).resolve().parents[1] / "notebooks").glob("*.ipynb"))


def test_notebooks_exist_and_are_stripped():
    assert {p.stem for p in NOTEBOOKS} >= {"memory_explorer", "sweeps", "ablations", "navigation", "generalisation"}
    for p in NOTEBOOKS:
        nb = nbformat.read(p, as_version=4)
        for cell in nb.cells:
            if cell.cell_type == "code":
                assert not cell.outputs and cell.execution_count is None, f"{p.name}: outputs not stripped"


@pytest.mark.parametrize("path", NOTEBOOKS, ids=[p.stem for p in NOTEBOOKS])
def test_notebook_runs_top_to_bottom(path, tiny_run, monkeypatch, tmp_path):
    from nbclient import NotebookClient

    run, episodes, _, _, _ = tiny_run
    monkeypatch.setenv("RAGNAV_RUN", str(run))
    monkeypatch.setenv("RAGNAV_EPISODES", str(episodes))
    monkeypatch.setenv("RAGNAV_CONFIG", "")
    monkeypatch.setenv("RAGNAV_OVERRIDES", " ".join(SMALL))
    monkeypatch.setenv("RAGNAV_NAV_EPISODES", "3")  # the navigation notebook: every cell, on fewer episodes
    monkeypatch.setenv("JAX_PLATFORMS", "cpu")
    monkeypatch.setenv("MPLBACKEND", "Agg")
    nb = nbformat.read(path, as_version=4)
    NotebookClient(nb, timeout=300, kernel_name="python3", resources={"metadata": {"path": str(path.parent)}}).execute()
    errors = [o for c in nb.cells if c.cell_type == "code" for o in c.outputs if o.output_type == "error"]
    assert not errors
