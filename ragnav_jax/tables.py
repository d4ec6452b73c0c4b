"""Result tables: every table is written as CSV and markdown side by side."""

from __future__ import annotations

from pathlib import Path


def write_table(rows: list[dict], stem: str | Path) -> tuple[Path, Path]:
    """Writes `stem`.csv and `stem`.md from a list of row dicts; returns both paths."""
    import pandas as pd

    stem = Path(stem)
    stem.parent.mkdir(parents=True, exist_ok=True)
    df = pd.DataFrame(rows)
    csv, md = stem.with_suffix(".csv"), stem.with_suffix(".md")
    df.to_csv(csv, index=False)
    md.write_text(df.to_markdown(index=False) + "\n")
    return csv, md
