"""Room scores for room names the summariser does not know, compared on seen-split houses.

    .venv/bin/python experiments/room_scores.py --out DIR [--scenes 24] [--seed 12345] [--check-unseen SEED ...]

For every house, room type t and category held in two or more rooms one of which is a t room: is the t room the
best-scoring of the rooms holding that category (the verifier's choice, `Verifier.rooms_match`), and over all rooms
(house top-1)? A tie of k rooms counts 1/k. Each object is perceived `--looks` times by the captioner, standing for
the memory's names (as `fitting.training_rows`). Two protocols on seen houses: `loo` leaves only t out of the types
the score knows (as `ragnav fit-verifier` does), `house` leaves out every type of the house, as in an unseen house,
where no room's type is known. `--check-unseen` adds unseen-split houses of those seeds (a check only: nothing is
chosen on them). Writes room_scores.json and room_scores.md under --out.
"""

from __future__ import annotations

import argparse
import dataclasses
import json
from pathlib import Path

import numpy as np

from ragnav_jax.config import load_config
from ragnav_jax.evaluation.verify import Verifier, VerifierParams, _summariser
from ragnav_jax.io import write_text
from ragnav_jax.memory.encoder import make_embedder
from ragnav_jax.world.generator import generate_scene


def scores(v: Verifier) -> dict:
    """Name -> f(room phrase, {room id: names}, known types) -> {room id: score}."""

    def vecs(names):
        return {r: v.vectors(list(ns)) for r, ns in names.items() if ns}

    def plain(t, names, known):
        return {r: float(np.sort(v.cos([t], list(ns))[0])[::-1][:3].mean()) for r, ns in names.items() if ns}

    def centroid(t, names, known):
        out, q, k = {}, v.vectors([t])[0], v.vectors(known)
        for r, x in vecs(names).items():
            c = x.mean(0) / np.linalg.norm(x.mean(0))
            out[r] = float(c @ q - (k @ c).mean())
        return out

    def sentence(t, names, known):
        rs = [r for r, ns in names.items() if ns]
        txt = ["a room with " + ", ".join(names[r]) for r in rs]
        c = v.cos([f"a {t}"], txt)[0] - v.cos([f"a {k}" for k in known], txt).mean(0)
        return dict(zip(rs, map(float, c)))

    def soft_type(t, names, known, temp=0.05):  # log p(t | room) over t and the known types, from distinct-style fits
        out = {}
        for r, ns in names.items():
            if ns:
                s = np.sort(v.cos([t, *known], list(ns)), axis=1)[:, ::-1][:, :3].mean(1) / temp
                out[r] = float(s[0] - s.max() - np.log(np.exp(s - s.max()).sum()))
        return out

    return {"distinctiveness (verifier)": v.room_scores, "plain cosine": plain, "name centroid": centroid,
            "whole-room sentence": sentence, "soft type assignment": soft_type}


def _share(sc: dict, among, rooms: dict, t: str) -> float:
    """The share of the best-scoring rooms of `among` that are t rooms (a tie of k rooms counts 1/k each)."""
    top = max(sc[r] for r in among)
    best = [r for r in among if sc[r] == top]
    return sum(rooms[r].type == t for r in best) / len(best)


def evaluate(v: Verifier, houses: list, protocol: str, looks: int, tag: str) -> dict:
    protos = sorted(_summariser().rooms)
    fns = scores(v)
    hits = {k: [0, 0, 0, 0] for k in fns}  # among-category hits, rows, house top-1 hits, rows
    for h, scene in enumerate(houses):
        seen = [[p for (p,) in v.perceptions_of(scene, f"rooms-{tag}-{h}-{k}")] for k in range(looks)]
        rec = {k: [seen[m][k].name for m in range(looks)] for k in range(len(scene.objects))}
        view = v.scene_view(scene, list(rec), rec)
        rooms = {r.id: r for r in scene.rooms}
        types = sorted({r.type for r in scene.rooms})
        for t in types:
            known = sorted(set(protos) - ({t} if protocol == "loo" else set(types)))
            for name, f in fns.items():
                sc = f(t, view.room_names, known)
                hits[name][2] += _share(sc, sc, rooms, t)
                hits[name][3] += 1
                for c in sorted({o.category for o in scene.objects}):
                    among = {o.room for o in scene.objects if o.category == c and o.room in sc}
                    if len(among) >= 2 and any(rooms[r].type == t for r in among):
                        hits[name][0] += _share(sc, among, rooms, t)
                        hits[name][1] += 1
    return {k: {"among_category": round(a / max(n, 1), 3), "rows": n, "house_top1": round(b / max(m, 1), 3),
                "room_types": m} for k, (a, n, b, m) in hits.items()}


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--out", required=True)
    ap.add_argument("--scenes", type=int, default=24)
    ap.add_argument("--seed", type=int, default=12345)
    ap.add_argument("--looks", type=int, default=8)
    ap.add_argument("--check-unseen", type=int, nargs="*", default=[], metavar="SEED")
    args = ap.parse_args()
    cfg = load_config(None, [])
    v = Verifier.build(make_embedder("minilm"), cfg, VerifierParams())
    v.looks = 1
    seen = [generate_scene(cfg.world, args.seed, i) for i in range(args.scenes)]
    res = {f"seen {args.seed} x{args.scenes}, {p}": evaluate(v, seen, p, args.looks, f"seen-{args.seed}")
           for p in ("loo", "house")}
    unseen_world = dataclasses.replace(cfg.world, split="unseen", name_prefix="unseen")
    for s in args.check_unseen:
        houses = [generate_scene(unseen_world, s, i) for i in range(12)]
        res[f"unseen {s} x12 (check only)"] = evaluate(v, houses, "loo", args.looks, f"unseen-{s}")
    out = Path(args.out)
    write_text(out / "room_scores.json", json.dumps(res, indent=1) + "\n")
    cols = list(res)
    lines = ["| score | " + " | ".join(cols) + " |", "|---|" + "---:|" * len(cols)]
    for k in next(iter(res.values())):
        lines.append(f"| {k} | " + " | ".join(f"{res[c][k]['among_category']:.3f} / {res[c][k]['house_top1']:.3f}"
                                               for c in cols) + " |")
    md = ("# Room scores: the true room among the rooms holding one category / house top-1\n\n"
          + "\n".join(lines) + "\n\nrows: " + ", ".join(f"{c}: {next(iter(res[c].values()))['rows']}" for c in cols)
          + "\n")
    write_text(out / "room_scores.md", md)
    print(md)


if __name__ == "__main__":
    main()
