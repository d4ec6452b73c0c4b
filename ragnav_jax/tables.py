"""Result tables: every table is written as CSV and markdown side by side."""

from __future__ import annotations

from pathlib import Path

from ragnav_jax.io import write_text


def write_table(rows: list[dict], stem: str | Path, markdown: list[dict] | None = None) -> tuple[Path, Path]:
    """Writes `stem`.csv from `rows` and `stem`.md from `markdown` (default: the same rows; pass rows that
    read differently, e.g. with combined cells); returns both paths. Missing figures (None, NaN) are empty
    cells in both files, never 'nan'."""
    import pandas as pd

    stem = Path(stem)
    stem.parent.mkdir(parents=True, exist_ok=True)
    df = pd.DataFrame(rows)
    csv, md = stem.with_suffix(".csv"), stem.with_suffix(".md")
    write_text(csv, df.to_csv(index=False))
    shown = df if markdown is None else pd.DataFrame(markdown)
    shown = shown.astype(object).where(shown.notna(), None)
    # given markdown cells are formatted already ("1.000" stays so, not re-read as the number 1)
    write_text(md, shown.to_markdown(index=False, missingval="", disable_numparse=markdown is not None) + "\n")
    return csv, md
