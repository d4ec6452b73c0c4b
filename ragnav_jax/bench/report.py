"""RUN/bench.md and its plots from the bench.json document."""

from __future__ import annotations

from pathlib import Path

from ragnav_jax.io import save_figure, write_text


def _t(s: float) -> str:
    """Seconds as a short human figure."""
    if s is None:
        return "-"
    if s >= 1:
        return f"{s:.2f} s"
    if s >= 1e-3:
        return f"{1e3 * s:.2f} ms"
    if s >= 1e-6:
        return f"{1e6 * s:.2f} us"
    return f"{1e9 * s:.1f} ns"


def _x(r: float) -> str:
    return f"{r:.3g}x" if r is not None else "-"


def comparison_table(comps: list[dict]) -> list[str]:
    lines = ["| section | comparison | ours per unit, median [min-max] | peer per unit | ratio peer/ours [range] | compile |",
             "|---|---|---|---|---|---:|"]
    for c in comps:
        o, p = c["ours"], c["peer"]
        lines.append(
            f"| {c['section']} | {c['name']} | {_t(o['median_s'])} [{_t(o['min_s'])}-{_t(o['max_s'])}] / {c['unit']} | "
            f"{_t(p['median_s'])} ({p['name']}) | **{_x(c['ratio'])}** [{_x(c['ratio_range'][0])}-{_x(c['ratio_range'][1])}]"
            f" | {_t(c.get('compile_s')) if c.get('compile_s') is not None else '-'} |")
    return lines


def _ok_rows(section: dict) -> list[dict]:
    """The rows of a section that were measured (a size that failed carries an 'error' instead)."""
    return [r for r in section.get("rows", []) if "error" not in r]


def readme_table(doc: dict) -> list[str]:
    """The compact table of the README's Performance section (one CPU column; a GPU column can be added)."""
    col = f"{doc['machine']['device_kind'] or doc['machine']['jax_backend']} ({doc['profile']})"
    lines = [f"| figure | {col} |", "|---|---:|"]
    secs = doc["sections"]
    for r in _ok_rows(secs.get("retrieval", {})):
        lines.append(f"| retrieval, {r['nodes']} nodes: single query / batched | {r['single_ms']:.2f} ms / "
                     f"{r['batched_queries_per_s']:.0f} q/s |")
    for c in doc["comparisons"]:
        lines.append(f"| {c['name']} | {_x(c['ratio'])} |")
    e2e = secs.get("end_to_end", {})
    for rec in e2e.get("by_scenes", []):
        st = rec["stages"]
        tot = sum(v.get("wall_s", 0) for v in st.values())
        lines.append(f"| end to end, {rec['scenes']} scenes: total (compile) | {tot:.1f} s "
                     f"({sum(v.get('compile_s', 0) for v in st.values()):.1f} s) |")
    sw = secs.get("sweep", {})
    if sw.get("status") == "ok":
        lines.append(f"| sweep {sw['grid']}, {sw['grid_points']} points | {sw['points_per_s']:.0f} points/s |")
    return lines


def _plots(doc: dict, out: Path) -> list[str]:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    made = []
    secs = doc["sections"]
    rows = _ok_rows(secs.get("retrieval", {}))
    if rows:
        fig, ax = plt.subplots(figsize=(5.5, 3.8))
        n = [r["nodes"] for r in rows]
        ax.loglog(n, [r["single_ms"] for r in rows], "o-", label="RAGNav score, single query (JAX)")
        ax.loglog(n, [1e3 * r["batched"]["median_s"] / r["batch_queries"] for r in rows], "s-",
                  label="RAGNav score, batched (per query)")
        ax.loglog(n, [1e3 * r["sim_jax"]["median_s"] / r["batch_queries"] for r in rows], "^-",
                  label="similarity only, JAX (per query)")
        fr = [r for r in rows if r.get("sim_faiss")]
        if fr:
            ax.loglog([r["nodes"] for r in fr], [1e3 * r["sim_faiss"]["median_s"] / r["sim_faiss_queries"] for r in fr],
                      "v--", label="similarity only, faiss IndexFlatIP")
        ax.axhspan(185, 195, color="0.8", label="paper, 185-195 ms")
        ax.set(xlabel="memory nodes", ylabel="ms per query", title="Retrieval latency")
        ax.legend(fontsize=7)
        fig.tight_layout()
        save_figure(fig, out / "retrieval.png", dpi=110)
        plt.close(fig)
        made.append("retrieval.png")
    sim = secs.get("simulation", {})
    if sim.get("rows"):
        fig, ax = plt.subplots(figsize=(5.5, 3.8))
        b = [r["batch"] for r in sim["rows"]]
        ax.loglog(b, [r["env_steps_per_s"] for r in sim["rows"]], "o-", label="MJX NavEnv (vmap x scan)")
        ax.axhline(sim["c_engine"]["env_steps_per_s"], ls="--", color="k", label="MuJoCo C, 1 thread")
        ax.set(xlabel="parallel environments", ylabel="env-steps / s", title="Simulation (physics + lidar + visibility)")
        ax.legend(fontsize=8)
        fig.tight_layout()
        save_figure(fig, out / "simulation.png", dpi=110)
        plt.close(fig)
        made.append("simulation.png")
    e2e = secs.get("end_to_end", {})
    for key, xkey, xlabel, fname in (("by_scenes", "scenes", "scenes", "end_to_end_scenes.png"),
                                     ("by_nodes", "mean_nodes", "mean nodes per scene", "end_to_end_nodes.png")):
        recs = e2e.get(key, [])
        if not recs:
            continue
        fig, (a1, a2) = plt.subplots(1, 2, figsize=(9, 3.8))
        xs = [r[xkey] for r in recs]
        stages = [s for s in recs[-1]["stages"] if "wall_s" in recs[-1]["stages"][s]]
        for s in stages:
            ys = [r["stages"].get(s, {}).get("wall_s") for r in recs]
            pts = [(x, y) for x, y in zip(xs, ys) if y is not None]
            a1.plot(*zip(*pts), "o-", label=s)
            zs = [r["stages"].get(s, {}).get("peak_rss_mb") for r in recs]
            pts = [(x, z) for x, z in zip(xs, zs) if z is not None]
            a2.plot(*zip(*pts), "o-", label=s)
        a1.set(xlabel=xlabel, ylabel="wall s (incl. compile)", title="Stage time", yscale="log")
        a2.set(xlabel=xlabel, ylabel="peak RSS during stage (MB)", title="Peak memory")
        if key == "by_scenes":
            a1.set_xscale("log")
            a2.set_xscale("log")
        a1.legend(fontsize=7)
        fig.tight_layout()
        save_figure(fig, out / fname, dpi=110)
        plt.close(fig)
        made.append(fname)
    return made


def write_report(doc: dict, out: Path) -> Path:
    out = Path(out)
    m = doc["machine"]
    L = [f"# ragnav bench ({doc['profile']})", "",
         f"{doc['time']}, commit {doc['git_commit']}; {m['cpu_model']}, {m['cpus_usable']} usable of {m['cpu_count']} "
         f"cores, {m['memory_gb']} GB; JAX {doc['packages'].get('jax')} on {', '.join(m['jax_devices'])}; "
         f"load average at start {m['load_average_1_5_15']}; total {doc.get('total_wall_s', 0):.0f} s.", "",
         doc["note"], ""]
    if doc.get("notes"):
        L += [doc["notes"], ""]
    secs = doc["sections"]
    L += ["| section | status | wall s | process CPU s | cores used (CPU / wall) |", "|---|---|---:|---:|---:|"]
    for name, s in secs.items():
        w, c = s.get("section_wall_s", 0.0), s.get("section_cpu_s", 0.0)
        L.append(f"| {name} | {s.get('status')} | {w:.1f} | {c:.1f} | {c / w if w else 0:.2f} |")
    L += ["", "## Comparisons", ""] + comparison_table(doc["comparisons"]) + [""]
    for name, s in secs.items():
        if s.get("status") == "partial":
            L += [f"**{name}: partial** - the run stopped inside this section; its figures so far are below.", ""]
        elif s.get("status") != "ok":
            L += [f"**{name}: {s.get('status')}** - {s.get('reason')}", ""]
    r = secs.get("retrieval", {})
    if r.get("rows"):
        L += ["## Retrieval", "", "| nodes | single query ms (median [min-max]) | compile s | batched queries/s | "
              "queries | faiss / JAX per query (similarity) | top-1 agreement | paper 185-195 ms / ours |",
              "|---:|---:|---:|---:|---:|---:|---:|---:|"]
        for x in r["rows"]:
            if "error" in x:
                L.append(f"| {x['nodes']} | failed: {x['error'][:120]} | | | {x['batch_queries']} | | | |")
                continue
            s1 = x["single"]
            faiss = "-" if x["sim_faiss"] is None else f"{x['sim_ratio_faiss_over_jax']:.2f}"
            agree = "-" if x["sim_top1_agreement"] is None else f"{x['sim_top1_agreement']:.3f}"
            L.append(f"| {x['nodes']} | {1e3 * s1['median_s']:.2f} [{1e3 * s1['min_s']:.2f}-{1e3 * s1['max_s']:.2f}] | "
                     f"{x['compile_single_s']:.1f} | {x['batched_queries_per_s']:.0f} | {x['batch_queries']} | "
                     f"{faiss} | {agree} | {x['speedup_vs_paper_single']:.0f}x |")
        L.append("")
    p = secs.get("paths", {})
    if p.get("rows"):
        L += ["## Shortest paths", "", "| graphs x nodes | JAX s (median [min-max]) | compile s | networkx s | agrees |",
              "|---|---:|---:|---:|---|"]
        for x in p["rows"]:
            j, n = x["jax"], x["networkx"]
            L.append(f"| {x['graphs']} x {x['nodes']} | {j['median_s']:.3f} [{j['min_s']:.3f}-{j['max_s']:.3f}] | "
                     f"{x['compile_s']:.1f} | {n['median_s']:.1f} (from {x['networkx_graphs_timed']}) | "
                     f"{x['agrees_with_networkx']} |")
        L.append("")
    pl = secs.get("planning", {})
    if pl.get("rows"):
        L += ["## Order planning", "", "| case | episodes | JAX s | compile s | Python s (extrapolated from) | agrees |",
              "|---|---:|---:|---:|---:|---|"]
        for x in pl["rows"]:
            L.append(f"| {x['case']} | {x['episodes']} | {x['run_s_median']:.3f} | {x['compile_s']:.1f} | "
                     f"{x['python_s_all_episodes']:.1f} ({x['python_episodes_timed']}) | {x['agrees_with_python']} |")
        L.append("")
    sim = secs.get("simulation", {})
    if sim.get("rows"):
        L += ["## Simulation", "", f"C engine, 1 thread: {sim['c_engine']['env_steps_per_s']:.0f} env-steps/s.", "",
              "| batch | env-steps/s | x C | compile s |", "|---:|---:|---:|---:|"]
        for x in sim["rows"]:
            L.append(f"| {x['batch']} | {x['env_steps_per_s']:.0f} | {x['ratio_vs_c'] if 'ratio_vs_c' in x else x['env_steps_per_s'] / sim['c_engine']['env_steps_per_s']:.2f} | {x['compile_s']:.1f} |")
        L += ["", "![simulation](simulation.png)", ""]
    e2e = secs.get("end_to_end", {})
    if e2e.get("by_scenes"):
        L += ["## End to end (paper preset)", "", e2e["note"], ""]
        for key, label in (("by_scenes", "scenes"), ("by_nodes", "keyframe spacing")):
            recs = e2e.get(key, [])
            if not recs:
                continue
            stages = [s for s in recs[0]["stages"]]
            L += [f"| {label} | nodes/scene | " + " | ".join(stages) + " |", "|---:|---:|" + "---|" * len(stages)]
            for rec in recs:
                cells = []
                for s in stages:
                    v = rec["stages"].get(s, {})
                    cells.append(f"{v['wall_s']:.2f} s (c {v['compile_s']:.1f}, {v['peak_rss_mb']:.0f} MB)"
                                 if "wall_s" in v else v.get("status", "-"))
                lab = rec["scenes"] if key == "by_scenes" else rec["keyframe_spacing"]
                L.append(f"| {lab} | {rec['mean_nodes']:.0f} | " + " | ".join(cells) + " |")
            L.append("")
        ex = e2e.get("execute", {})
        if ex.get("status"):
            L += [f"execute: {ex['status']} ({ex.get('reason', '')})", ""]
    sw = secs.get("sweep", {})
    if sw.get("status") == "ok":
        w = sw["warm"]
        L += ["## Sweep", "", f"{sw['grid']}: {sw['grid_points']} grid points over {sw['scenes']} scenes "
              f"({sw['subgoals']} subgoals): {w['median_s']:.2f} s warm [{w['min_s']:.2f}-{w['max_s']:.2f}], "
              f"{sw['points_per_s']:.0f} points/s; first call {sw['first_call']['wall_s']:.1f} s "
              f"(compile {sw['first_call']['compile_s']:.1f} s)." + (f" Note: {sw['note']}" if sw.get("note") else ""), ""]
    from ragnav_jax.bench.sections import closed_loop_markdown, memory_update_markdown

    L += closed_loop_markdown(secs.get("closed_loop", {}))
    L += memory_update_markdown(secs.get("memory_update", {}))
    made = _plots(doc, out)
    if made:
        L += ["## Plots", ""] + [f"![{f}]({f})" for f in made if f != "simulation.png"] + [""]
    L += ["## README table", ""] + readme_table(doc) + [""]
    path = out / "bench.md"
    write_text(path, "\n".join(L) + "\n")
    return path
