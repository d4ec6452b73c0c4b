"""Why each goal of an evaluation failed: one cause per failed goal of one method's eval run.

    .venv/bin/python experiments/failure_causes.py RUN [--method ragnav] [--out DIR]

RUN is a `ragnav eval --out` folder (run from the folder the eval ran in: its summary records the scene
set and episodes file as given). For every goal that is not `found`, the first cause that applies:
- `unparsed`: the instruction did not parse, or fewer subgoals were read than it has goals (the k-th true goal
  is compared with the k-th subgoal read, as retrieval is scored; the loop itself runs every subgoal read);
- `not_in_memory`: the memory never recorded the target object (no caption names it);
- `check_rejects_target`: the reflection's check fails on the target itself (the failing parts named:
  name, attributes, relations, location, sensors, room);
- `retrieval_misses_target`: no candidate of the goal is the target's memory instance;
- `precheck_rules_out_target`: the target is a candidate without RAGNav's pre-check and not with it;
- `check_passes_wrong_object`: a wrong object was declared although the check holds on the target;
- `executor`: the target was a candidate and passes the check, but the drive, look or approach failed
  (the goal's status says which: blocked, stuck, not_confirmed).
Writes failure_causes-<method>.{csv,md} (one row per failed goal) and a count table in the markdown.
Reads the run; writes only under --out (default RUN/analysis).
"""

from __future__ import annotations

import argparse
import dataclasses
import math
from collections import Counter
from pathlib import Path

import numpy as np

from ragnav_jax.evaluation.clearance import SAME_INSTANCE_M, box_distance
from ragnav_jax.evaluation.methods import method_spec
from ragnav_jax.evaluation.ranking import retrieve_candidates
from ragnav_jax.evaluation.replay import load_eval_run
from ragnav_jax.evaluation.verify import Verifier, recorded, said
from ragnav_jax.io import write_text
from ragnav_jax.memory.encoder import make_embedder
from ragnav_jax.tables import write_table


def check_parts(v: Verifier, view, sg, ps, k: int) -> list[str]:
    """The parts of the check that fail on scene object k (its looks ps[k])."""
    t, o = sg.target, view.scene.objects[k]
    bad = []
    if not v.names_match(t.head, [{p.name for p in ps[k]} | view.names_of(k, ps[k])], view.vocab, view.classes)[0]:
        bad.append("name")
    if not all(any(said(a, p.text) for p in ps[k]) for a in t.attributes):
        bad.append("attributes")
    if not v.relations_hold(t, view, ps)[k]:
        bad.append("relations")
    if sg.location is not None and math.dist(o.position[:2], (sg.location.x, sg.location.y)) > v.radius:
        bad.append("location")
    if any(c.reading not in o.readings for c in sg.sensors):
        bad.append("sensors")
    if sg.room is not None and o.room not in v.rooms_match(sg.room, view):
        bad.append("room")
    return bad or ["superlative"]  # every part holds alone: the target lost the ranking among its rivals


def target_among(cands, e: int, g: int, obj) -> bool:
    """One of goal g's candidates (episode e) is the target's memory instance (its estimated position)."""
    return any(x is not None and box_distance(obj, x) <= SAME_INSTANCE_M for x in cands.est[e][g])


def causes(run: Path, method: str) -> list[dict]:
    ev = load_eval_run(run, method)
    cfg = ev.cfg
    spec = method_spec(method)
    bank = ev.bank
    embedder = make_embedder(bank.metas[0].embedder if bank.metas else cfg.memory.embedder, dim=cfg.memory.hashing_dim)
    verifier = Verifier.build(embedder, cfg)
    failed = [e for e in ev.episodes if not all(s == "found" for s in ev.rows[e.id]["goal_status"])]
    with_check = retrieve_candidates(spec, bank, ev.scenes, failed, embedder, cfg, verifier)
    no_pre = dataclasses.replace(cfg, eval=dataclasses.replace(cfg.eval, precheck=False))
    without_check = retrieve_candidates(spec, bank, ev.scenes, failed, embedder, no_pre, verifier)
    by_scene = {s.name: s for s in ev.scenes}
    obs, mask = np.asarray(bank.memory.obs_object), np.asarray(bank.memory.node_mask)
    views = {}
    for b, meta in enumerate(bank.metas):
        if meta.scene in by_scene:
            known = sorted({int(x) for x in obs[b][mask[b]].ravel() if x >= 0})
            views[meta.scene] = verifier.scene_view(by_scene[meta.scene], known, recorded(meta, by_scene[meta.scene])[0])
    out = []
    for e, ep in enumerate(failed):
        row, sgs = ev.rows[ep.id], with_check.subgoals[e]
        view = views[ep.scene]
        ids = [o.id for o in view.scene.objects]
        ps = verifier.perceptions_of(view.scene, ep.id)
        for g, (status, goal) in enumerate(zip(row["goal_status"], row["goal_ids"])):
            if status == "found":
                continue
            k = ids.index(goal)
            obj = view.scene.objects[k]
            detail = ""
            if not sgs or g >= len(sgs):  # no instruction read, or fewer subgoals read than goals
                cause, detail = "unparsed", "" if not sgs else "no subgoal read in its place"
            elif k not in view.aliases:
                cause = "not_in_memory"
            elif not verifier.verdicts(view, sgs[g], ps)[k]:
                cause, detail = "check_rejects_target", "+".join(check_parts(verifier, view, sgs[g], ps, k))
            elif spec.reads and not target_among(without_check, e, g, obj):
                cause = "retrieval_misses_target"
            elif spec.reads and not target_among(with_check, e, g, obj):
                cause = "precheck_rules_out_target"
            elif status == "wrong":
                cause = "check_passes_wrong_object"
                detail = next((d["object"] for d in row["declarations"] if d["goal"] == g), "")
            else:
                cause, detail = "executor", status.split(":")[-1]
            out.append({"episode": ep.id, "modality": ep.modality, "goal": g, "target": goal, "status": status,
                        "cause": cause, "detail": detail,
                        "subgoal": sgs[g].text if sgs and g < len(sgs) else ep.instruction})
    return out


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("run", help="a `ragnav eval --out` folder")
    ap.add_argument("--method", default="ragnav")
    ap.add_argument("--out", help="output folder (default RUN/analysis)")
    args = ap.parse_args()
    run = Path(args.run)
    out = Path(args.out) if args.out else run / "analysis"
    rows = causes(run, args.method)
    stem = out / f"failure_causes-{args.method.replace(':', '_')}"
    write_table(rows or [{"episode": "", "cause": ""}], stem)
    n = Counter(r["cause"] for r in rows)
    lines = [f"# Failed goals of {args.method} in {run}: {len(rows)} goals", "", "| cause | goals |", "|---|---:|"]
    lines += [f"| {c} | {k} |" for c, k in n.most_common()]
    md = stem.with_suffix(".md")
    write_text(md, "\n".join(lines) + "\n\n" + md.read_text())
    print("\n".join(lines))
    print(f"-> {md}")


if __name__ == "__main__":
    main()
