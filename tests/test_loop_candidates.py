"""loop/candidates.py against the host code it replaces (ranking.py: candidate_order, distinct_instances, the
pre-check's keep-all rule, view_nodes), on random small slots and on every subgoal slot of the apartment."""

import dataclasses
import functools

import jax
import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from hypothesis.extra.numpy import arrays
from test_memory_streams import synthetic_stream

from ragnav_jax.config import load_config
from ragnav_jax.evaluation import ranking
from ragnav_jax.evaluation.loop.candidates import rank_all, rank_candidates
from ragnav_jax.evaluation.methods import method_spec
from ragnav_jax.evaluation.ranking import (
    CANDIDATE_DEPTH,
    _kernel_ranked,
    _ranked_terms,
    candidate_order,
    distinct_instances,
    view_nodes,
)
from ragnav_jax.language.episodes import load_episodes
from ragnav_jax.memory.build import build_bank
from ragnav_jax.memory.encoder import HashingEmbedder
from ragnav_jax.retrieval import kernels as K
from ragnav_jax.retrieval.evaluate import prepare_batch
from ragnav_jax.retrieval.params import ablation_params, params_from_config
from ragnav_jax.world.scene import example_scene_path

STATIC = ("k", "depth", "widen", "closest_view")
one_slot = jax.jit(rank_candidates, static_argnames=STATIC)
all_slots = jax.jit(rank_all, static_argnames=STATIC)
SCORES = (K.NEG, -0.5, -0.0, 0.0, 0.25, 1.0)  # few values: ties in every tier; K.NEG: dropped by the retrieval
POOLS = (SCORES, (K.NEG, K.NEG, K.NEG, 0.0, 1.0), (K.NEG,))


def reference(score, relaxed, category, slot_best, node_live, slot_inst, inst_pos, node_pos, ruled, k, depth, widen,
              closest_view):
    """`_kernel_ranked`'s loop body for one slot on the host functions; the pre-check is the `ruled` lookup."""
    ranked = [int(n) for n in candidate_order(score, relaxed, category, node_live, widen)[: k * depth]]
    inst = [int(slot_inst[n, slot_best[n]]) for n in ranked]
    pick = distinct_instances(inst, len(inst))
    pick = [j for j in pick if inst[j] < 0 or not ruled[inst[j]]] or pick
    pick = pick[:k]
    nodes = [ranked[j] for j in pick]
    if closest_view:
        nodes = view_nodes(nodes, [inst[j] for j in pick], slot_inst, node_pos, node_live, inst_pos)
    return nodes, [inst[j] for j in pick], ranked[0] if ranked else -1


def assert_same(r, ref, inst_pos, k):
    nodes, inst, top = ref
    n = len(nodes)
    assert int(r.n) == n and int(r.top) == top
    np.testing.assert_array_equal(r.nodes, nodes + [-1] * (k - n))
    np.testing.assert_array_equal(r.inst, inst + [-1] * (k - n))
    np.testing.assert_array_equal(r.has_est, np.array(inst + [-1] * (k - n)) >= 0)
    for c, i in enumerate(inst):
        np.testing.assert_array_equal(r.est[c], inst_pos[i] if i >= 0 else 0.0)


@st.composite
def terms(draw, N, S):
    """One subgoal's kernel terms over N nodes, full of ties; at times (nearly) every score K.NEG."""
    f32 = functools.partial(arrays, np.float32, N)
    return dict(score=draw(f32(elements=st.sampled_from(draw(st.sampled_from(POOLS))))),
                relaxed=draw(f32(elements=st.sampled_from(draw(st.sampled_from((SCORES, SCORES[1:])))))),
                category=draw(arrays(bool, N)),
                slot_best=draw(arrays(np.int32, N, elements=st.integers(0, S - 1))))


def scene(N, S, I):
    """One scene's nodes (N, S slots) and instances (I), positions on a grid (ties in distance); many slots without
    an instance (-1) and many of a few instances."""
    grid = functools.partial(arrays, np.float32, elements=st.integers(-2, 2).map(float))
    inst = st.integers(-1, min(I, 2) - 1) | st.integers(-1, I - 1)
    return st.fixed_dictionaries(dict(node_live=arrays(bool, N, elements=st.sampled_from((True, True, False))),
                                      slot_inst=arrays(np.int32, (N, S), elements=inst),
                                      inst_pos=grid((I, 2)), node_pos=grid((N, 2))))


sizes = st.tuples(st.integers(0, 12), st.integers(1, 3), st.integers(0, 6))  # N, S, I
# One compilation each: (N, S, I) and the static (k, depth, widen, closest_view): sizes 0 and 1, no instances,
# k * depth below and above N.
SHAPES = ((0, 1, 0, 2, 2, True, True), (1, 2, 0, 3, 1, False, True), (4, 1, 2, 4, 3, True, True),
          (5, 3, 4, 4, 1, True, True), (7, 3, 6, 2, 2, True, False), (12, 3, 6, 3, 1, False, True),
          (12, 1, 1, 4, 3, False, False))


@settings(max_examples=40, deadline=None)
@given(st.sampled_from(SHAPES).flatmap(lambda c: st.tuples(terms(*c[:2]), scene(*c[:3]), arrays(bool, c[2]),
                                                           st.just(dict(zip(STATIC, c[3:]))))))
def test_one_slot_matches_host(case):
    """rank_candidates under jit on exact shapes equals the host."""
    t, sc, ruled, kw = case
    a = {**t, **sc, "ruled": ruled}
    assert_same(one_slot(**a, **kw), reference(**a, **kw), a["inst_pos"], kw["k"])


@settings(max_examples=40, deadline=None)
@given(st.lists(sizes.flatmap(lambda s: st.tuples(st.lists(terms(*s[:2]), min_size=3, max_size=3), scene(*s))),
                min_size=2, max_size=2),
       st.lists(st.tuples(st.integers(0, 1), st.integers(0, 2)), min_size=5, max_size=5),
       st.sampled_from([(1, 1, True, True), (3, 2, True, True), (2, 3, False, False)]), st.data())
def test_all_slots_match_host_on_padded_scenes(scenes, slots, statics, data):
    """rank_all (vmap, jit) over 5 slots of 2 scenes of 3 subgoal slots, padded to 12 nodes, 3 slots, 6 instances
    with garbage in the padding (dead nodes, unused instances): each slot equals the host on its scene's unpadded
    arrays (N 0..12, S 1..3, I 0..6)."""
    N, S, I = 12, 3, 6
    pad = {**data.draw(terms(N, S)), **data.draw(scene(N, S, I))}
    arr = {f: np.stack([x] * 2) for f, x in pad.items()}  # garbage everywhere, (B, ...)
    for f in ("score", "relaxed", "category", "slot_best"):
        arr[f] = np.stack([arr[f]] * 3, 1)  # (B, Q, N)
    arr["node_live"][:] = False
    for b, (ts, sc) in enumerate(scenes):
        n, si = sc["slot_inst"].shape
        arr["slot_inst"][b, :n] = -1
        arr["slot_inst"][b, :n, :si] = sc["slot_inst"]
        for f in ("node_live", "node_pos", "inst_pos"):
            arr[f][b, : len(sc[f])] = sc[f]
        for q, t in enumerate(ts):
            for f, x in t.items():
                arr[f][b, q, :n] = x
    ruled = data.draw(arrays(bool, (len(slots), I)))
    kw = dict(zip(STATIC, statics))
    r = jax.tree.map(np.asarray, all_slots(**arr, ruled=ruled, b=np.array([b for b, _ in slots], np.int32),
                                           q=np.array([q for _, q in slots], np.int32), **kw))
    for m, (b, q) in enumerate(slots):
        ts, sc = scenes[b]
        one = {**ts[q], **sc, "ruled": ruled[m, : len(sc["inst_pos"])]}
        assert_same(jax.tree.map(lambda x, m=m: x[m], r), reference(**one, **kw), sc["inst_pos"], kw["k"])


def test_everything_ruled_out_keeps_all():
    """The pre-check rules out every instance: the ranking's candidates stay (`pick = kept or pick`)."""
    a = dict(score=np.array([1.0, 0.5, 0.2], np.float32), relaxed=np.full(3, K.NEG, np.float32),
             category=np.ones(3, bool), slot_best=np.zeros(3, np.int32), node_live=np.ones(3, bool),
             slot_inst=np.array([[0], [1], [0]], np.int32), inst_pos=np.zeros((2, 2), np.float32),
             node_pos=np.zeros((3, 2), np.float32))
    kw = dict(k=2, depth=2, widen=False, closest_view=False)
    assert list(one_slot(**a, ruled=np.array([True, True]), **kw).nodes) == [0, 1]
    assert list(one_slot(**a, ruled=np.array([True, False]), **kw).nodes) == [1, -1]


@pytest.mark.parametrize("inst,expect", [
    ([-1] * 5, [0, 3, 2, 1, 4]),  # top-1, then: category kept, category dropped, other kept, the rest
    ([0, 0, -1, -1, 1], [0, 3, 2, 4, 1]),  # distinct instances first, no instance (-1) always distinct
])
def test_tiers_and_nodes_without_instance(inst, expect):
    """candidate_order's widen tiers and distinct_instances' rule for -1 on a hand-made slot of 5 nodes."""
    a = dict(score=np.array([1.0, 0.9, K.NEG, 0.1, K.NEG], np.float32),
             relaxed=np.array([K.NEG, K.NEG, 0.8, K.NEG, 0.95], np.float32),
             category=np.array([True, False, True, True, False]), slot_best=np.zeros(5, np.int32),
             node_live=np.ones(5, bool), slot_inst=np.array(inst, np.int32)[:, None], inst_pos=np.zeros((2, 2), np.float32),
             node_pos=np.zeros((5, 2), np.float32), ruled=np.zeros(2, bool))
    kw = dict(k=5, depth=1, widen=True, closest_view=False)
    assert reference(**a, **kw)[0] == expect
    assert list(one_slot(**a, **kw).nodes) == expect


@pytest.fixture(scope="module")
def apartment_setup(apartment):
    cfg = load_config(None, ["memory.embedder=hashing", "eval.precheck=false"])
    emb = HashingEmbedder(dim=cfg.memory.hashing_dim)
    bank, _ = build_bank([apartment], [synthetic_stream(apartment)], cfg, embedder=emb)
    episodes = load_episodes(example_scene_path().parent / "episodes.jsonl", [apartment])
    # the batch as _kernel_ranked builds it
    batch, meta = prepare_batch(bank, [apartment], episodes, emb, every_subgoal=True, bucket_slots=True)
    return cfg, bank, episodes, emb, batch, meta


@pytest.mark.parametrize("method,widen,view,k", [("ragnav", True, True, 4), ("ragnav", False, False, 4),
                                                 ("ragnav", True, True, 16), ("ragnav:no_forest", True, True, 4)])
def test_apartment_slots_match_kernel_ranked(apartment_setup, apartment, method, widen, view, k, monkeypatch):
    """Every subgoal slot of the apartment's episodes: rank_all's nodes, estimates and top-1 are _kernel_ranked's
    (k 16: the ranking's every node, repeated instances)."""
    cfg, bank, episodes, emb, batch, meta = apartment_setup
    # only times one slot's scoring (a compilation of its own); the ranking never reads it
    monkeypatch.setattr(ranking, "_score_single", lambda *a: None, raising=False)
    cfg = dataclasses.replace(cfg, eval=dataclasses.replace(cfg.eval, widen=widen, closest_view=view, candidates=k))
    spec = method_spec(method)
    host = _kernel_ranked(spec, bank, [apartment], episodes, emb, cfg, None, None)
    terms = _ranked_terms(batch.index, batch.queries, ablation_params(params_from_config(cfg.retrieval), spec.variant))
    live = [((ep.id, kk), sl) for (ep, kk, _, _), sl in zip(meta.items, meta.slots) if sl is not None]
    b, q = (np.array([sl[j] for _, sl in live], np.int32) for j in (0, 1))
    ix = batch.index
    r = all_slots(*terms, ix.node_mask, ix.slot_inst, ix.inst_pos[..., :2], ix.node_pos[..., :2],
                  np.zeros((len(live), ix.inst_pos.shape[1]), bool), b, q, k=cfg.eval.candidates,
                  depth=CANDIDATE_DEPTH, widen=cfg.eval.widen, closest_view=cfg.eval.closest_view)
    r = jax.tree.map(np.asarray, r)
    assert len(live) > 10 and set(host.nodes) == {key for key, _ in live}
    for m, (key, _) in enumerate(live):
        n = int(r.n[m])
        assert list(r.nodes[m, :n]) == host.nodes[key] and (r.nodes[m, n:] == -1).all(), key
        assert int(r.top[m]) == (-1 if host.top[key] is None else host.top[key]), key
        assert [e is not None for e in host.est[key]] == list(r.has_est[m, :n]), key
        for c, e in enumerate(host.est[key]):
            if e is not None:
                np.testing.assert_array_equal(r.est[m, c], e)
