"""The eval tables on tiny summaries: a compact main table with Wilson intervals, the per-modality table,
every figure kept in table_full, and no 'nan' cell in any markdown."""

import csv

import pytest
from scipy.stats import binomtest

from ragnav_jax.evaluation.eval_commands import TABLE_KEYS, figures, save_bar_plot, write_eval_tables
from ragnav_jax.evaluation.metrics import summarise
from ragnav_jax.tables import write_table

MODALITIES = ("text", "text+location", "text+location+sensor")


def rows_of(successes: list[bool], retrieval: bool = True) -> list[dict]:
    """Episode rows as `episode_row` writes them (the fields the summary reads), modalities in turn."""
    return [{"success": ok, "retrieval_top1": [ok, True] if retrieval else [None, None], "spl": 0.8 * ok,
             "progress": 1.0 if ok else 0.5, "ppl": 0.8 if ok else 0.4, "travel_distance_m": 20.0 + i,
             "oracle_m": 18.0, "planned_rule1_m": 19.0 if retrieval else None,
             "planned_rule2_m": 18.5 if retrieval else None, "sim_time_s": 40.0, "wrong_declarations": 0,
             "modality": MODALITIES[i % 3], "reason": "success" if ok else "budget"}
            for i, ok in enumerate(successes)]


def read_csv(path) -> list[dict]:
    with open(path) as f:
        return list(csv.DictReader(f))


@pytest.mark.parametrize("n", [1, 2, 7, 12])
def test_summary_interval_is_wilson_and_brackets_the_rate(n):
    for k in {0, n // 2, n}:
        s = summarise(rows_of([i < k for i in range(n)]), {}, 0.1, "m")
        lo, hi = s["success_ci95"]
        ref = binomtest(k, n).proportion_ci(0.95, method="wilson")
        assert (lo, hi) == pytest.approx((ref.low, ref.high), abs=1e-4)
        assert lo <= s["success_rate"] <= hi
        for blk in s["by_modality"].values():
            assert blk["success_ci95"][0] <= blk["success_rate"] <= blk["success_ci95"][1]


def test_eval_tables_compact_by_modality_and_full(tmp_path):
    summaries = {"ragnav": summarise(rows_of([True] * 11 + [False]), {}, 0.1, "ragnav"),
                 "etpnav": summarise(rows_of([True, False] * 6, retrieval=False), {}, 0.01, "etpnav")}
    paths = write_eval_tables(summaries, tmp_path)
    assert [p.name for p in paths] == ["table.md", "table_by_modality.md", "table_full.md"]
    for p in paths:
        assert "nan" not in p.read_text().lower() and "nan" not in p.with_suffix(".csv").read_text().lower()

    main = read_csv(tmp_path / "table.csv")
    assert list(main[0]) == ["method", "episodes", "success", "ci_low", "ci_high", "spl", "top1", "travel_m", "time_s"]
    assert [r["method"] for r in main] == ["ragnav", "etpnav"] and main[0]["episodes"] == "12"
    for r in main:
        assert float(r["ci_low"]) <= float(r["success"]) <= float(r["ci_high"])
    assert main[1]["top1"] == ""  # no retrieval: an empty cell, not nan or 0
    md = (tmp_path / "table.md").read_text()
    assert "success [95% CI]" in md and "0.917 [0.65, 0.99]" in md and "0.500 [0.25, 0.75]" in md

    by_mod = read_csv(tmp_path / "table_by_modality.csv")
    assert [(r["method"], r["modality"]) for r in by_mod] == [(m, x) for m in summaries for x in MODALITIES]
    assert all(r["episodes"] == "4" and float(r["ci_low"]) <= float(r["success"]) <= float(r["ci_high"]) for r in by_mod)

    full = read_csv(tmp_path / "table_full.csv")
    assert list(full[0]) == ["method", *TABLE_KEYS] and len(full) == 2 * (1 + len(MODALITIES))
    assert full[0]["success_rate"] == main[0]["success"] and full[1]["method"] == "ragnav [text]"

    png = save_bar_plot([{"method": m, **figures(s)} for m, s in summaries.items()], tmp_path / "methods.png")
    assert png.stat().st_size > 1000


@pytest.mark.parametrize("rows", [[{"a": "x", "b": None}], [{"a": "x", "b": float("nan")}, {"a": "y", "b": 1.5}]])
def test_write_table_leaves_missing_figures_empty(tmp_path, rows):
    csv_path, md = write_table(rows, tmp_path / "t")
    assert "nan" not in md.read_text().lower() and "nan" not in csv_path.read_text().lower()
    cells = [[c.strip() for c in line.strip("|").split("|")] for line in md.read_text().splitlines()[2:]]
    assert cells[0] == ["x", ""]
    assert read_csv(csv_path)[0] == {"a": "x", "b": ""}


def test_generalisation_table_pools_folders_and_reads_kept_rows(tmp_path):
    """experiments/table_generalisation.py: several folders in one split are pooled (every episode counted, each
    paired with RAGNav's row of its own folder, though ids repeat across folders); kept rows (gzipped, no eval/
    level) read like an eval folder's; a split with no rows is a one-line error, exit 2."""
    import gzip
    import json
    import subprocess
    import sys
    from pathlib import Path

    script = Path(__file__).resolve().parents[1] / "experiments" / "table_generalisation.py"
    wins = {"a": [True, True, False, True], "b": [True, False, False, True]}  # RAGNav, then the baseline's below
    other = {"a": [False, True, True, False], "b": [False, False, False, False]}
    for f in ("a", "b"):
        for m, ok in (("ragnav", wins[f]), ("naive_rag", other[f])):
            rows = [dict(r, episode=f"ep-{i}", declarations=[]) for i, r in enumerate(rows_of(ok))]
            d = tmp_path / f / m
            d.mkdir(parents=True)
            if f == "a":  # kept rows
                (d / "episodes.jsonl.gz").write_bytes(gzip.compress("\n".join(map(json.dumps, rows)).encode()))
            else:  # an eval run folder
                d = tmp_path / f / "eval" / m
                d.mkdir(parents=True)
                (d / "episodes.jsonl").write_text("\n".join(map(json.dumps, rows)))
    out = tmp_path / "t"
    run = subprocess.run([sys.executable, str(script), "--split", f"both={tmp_path / 'a'},{tmp_path / 'b'}",
                          "--out", str(out)], capture_output=True, text=True)
    assert run.returncode == 0, run.stderr
    res = json.loads((out / "table_generalisation.json").read_text())["results"]["both"]
    assert res["ragnav"]["episodes"] == 8 and res["ragnav"]["success"] == 5 / 8
    c = res["naive_rag"]["vs_ragnav"]
    assert (c["episodes"], c["success_wins"], c["success_losses"]) == (8, 4, 1)  # a: 2 / 1, b: 2 / 0
    assert c["success_p"] == pytest.approx(binomtest(4, 5).pvalue)
    bad = subprocess.run([sys.executable, str(script), "--split", f"x={tmp_path / 'none'}", "--out", str(out)],
                         capture_output=True, text=True)
    assert bad.returncode == 2 and len(bad.stderr.strip().splitlines()) == 1 and "none" in bad.stderr
