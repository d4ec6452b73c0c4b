"""Memory pictures: the topological map on the floor plan coloured by forest cluster, and the dendrogram."""

from __future__ import annotations

from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

from ragnav_jax.io import save_figure  # noqa: E402
from ragnav_jax.memory.types import DualBasisMemory, MemoryMeta  # noqa: E402
from ragnav_jax.world.plot import draw_floor_plan  # noqa: E402
from ragnav_jax.world.scene import Scene  # noqa: E402


def save_memory_plot(scene: Scene, mem: DualBasisMemory, meta: MemoryMeta, out: str | Path, level: int = -1,
                     dpi: int = 130) -> Path:
    """One scene's memory (no batch axis): map + clusters of `level` (negative counts from the top), dendrogram."""
    from scipy.cluster.hierarchy import dendrogram

    out = Path(out)
    out.parent.mkdir(parents=True, exist_ok=True)
    n = meta.num_nodes
    N = mem.node_mask.shape[0]
    L = mem.tree_level.shape[0] // N
    level = level % L if L else 0
    level = max(level, 1) if L > 1 else 0
    pos = np.asarray(mem.position)[:n]
    adj = np.asarray(mem.adjacency)[:n, :n]
    members = np.asarray(mem.tree_members)
    tmask = np.asarray(mem.tree_mask)
    slots = [level * N + k for k in range(N) if tmask[level * N + k]]
    cluster = np.zeros(n, int)
    for c, s in enumerate(slots):
        cluster[members[s, :n]] = c
    cmap = plt.get_cmap("tab20")

    xmin, ymin, xmax, ymax = scene.bounds
    w = max(6.0, (xmax - xmin) * 0.7)
    fig, (ax, ax2) = plt.subplots(1, 2, figsize=(w * 2.1, max(5.0, (ymax - ymin) * 0.7)),
                                  gridspec_kw={"width_ratios": [1.0, 1.1]})
    draw_floor_plan(scene, ax=ax, labels=False)
    ii, jj = np.nonzero(np.triu(adj))
    for i, j in zip(ii, jj):
        ax.plot(pos[[i, j], 0], pos[[i, j], 1], color="0.35", lw=0.6, alpha=0.7, zorder=3)
    ax.scatter(pos[:, 0], pos[:, 1], c=[cmap(c % 20) for c in cluster], s=28, edgecolors="black", linewidths=0.4,
               zorder=4)
    tpos = np.asarray(mem.tree_position)
    for c, s in enumerate(slots):
        ax.text(tpos[s, 0], tpos[s, 1], meta.tree_labels[s].split(":")[0], fontsize=7, ha="center", va="center",
                color="black", zorder=5, bbox=dict(boxstyle="round,pad=0.15", fc=cmap(c % 20), ec="none", alpha=0.85))
    ax.set_title(f"{scene.name}: {n} nodes, {len(ii)} edges, {meta.num_components} component(s); "
                 f"level {level} clusters")

    if n >= 2:
        Z = np.column_stack([np.asarray(mem.merges)[: n - 1].astype(float), np.asarray(mem.merge_height)[: n - 1],
                             np.asarray(mem.merge_size)[: n - 1]])
        leaf_cluster = cluster
        labels = [f"{i}:{meta.tree_labels[i][:22]}" for i in range(n)]
        dendrogram(Z, ax=ax2, labels=labels, orientation="right", leaf_font_size=max(3.0, min(7.0, 400 / n)),
                   link_color_func=lambda k: "0.3")
        # colour leaf labels by cluster
        for t in ax2.get_ymajorticklabels():
            i = int(t.get_text().split(":")[0])
            t.set_color(cmap(leaf_cluster[i] % 20))
        # level cut heights: between the last merge kept and the next
        heights = np.asarray(mem.merge_height)[: n - 1]
        for lvl in range(1, L):
            c = int(tmask[lvl * N : (lvl + 1) * N].sum())
            s = n - c
            if 0 < s < n - 1:
                cut = 0.5 * (heights[s - 1] + heights[s])
                ax2.axvline(cut, ls="--", lw=0.8, color="tab:red" if lvl == level else "0.6")
                ax2.text(cut, 1.0, f" level {lvl}", transform=ax2.get_xaxis_transform(), fontsize=7, va="bottom")
        ax2.set_xlabel("merge distance")
    ax2.set_title("semantic forest dendrogram")
    fig.tight_layout()
    save_figure(fig, out, dpi=dpi)
    plt.close(fig)
    return out
