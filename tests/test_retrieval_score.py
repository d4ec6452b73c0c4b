"""The composed retrieval kernel on a tiny hand-made memory: each term does what it claims."""

import jax
import jax.numpy as jnp
import numpy as np
import pytest

from ragnav_jax.retrieval.kernels import NEG, OP_APPROX, OP_MAX, OP_MIN, OP_NONE
from ragnav_jax.retrieval.params import ABLATIONS, RetrievalParams, ablation_params, stack_params
from ragnav_jax.retrieval.query import QueryArrays
from ragnav_jax.retrieval.score import RetrievalIndex, score_subgoal

D = 8
SOFA, RED, BLUE, PLANT, RADIATOR, REMOTE, TV, LAMP = np.eye(D, dtype=np.float32)


def unit(v):
    return (v / np.linalg.norm(v)).astype(np.float32)


# Eight object instances; six key poses in a row, 1.5 m apart, a chain graph, each describing up to two.
INSTANCES = [  # (phrase embeddings, position, temperature or None)
    ([unit(SOFA + 0.5 * RED)], (0.3, 0.5), None),  # 0 red sofa
    ([unit(REMOTE)], (0.4, 0.6), None),  # 1 remote next to the sofa
    ([unit(PLANT)], (1.8, 0.5), None),  # 2 plant A
    ([unit(LAMP)], (1.9, 0.6), None),  # 3 lamp
    ([unit(RADIATOR)], (3.3, 0.5), 40.0),  # 4 radiator 40 C
    ([unit(REMOTE)], (4.8, 0.5), None),  # 5 a remote far from any sofa
    ([unit(TV)], (4.9, 0.6), None),  # 6 TV
    ([unit(SOFA + 0.5 * BLUE)], (6.3, 0.5), None),  # 7 blue sofa
    ([unit(PLANT)], (7.8, 0.5), None),  # 8 plant B
    ([unit(RADIATOR), unit(RADIATOR + 0.2 * BLUE)], (7.9, 0.6), 60.0),  # 9 radiator 60 C, seen twice
]
SLOTS = [[0, 1], [2, 3], [4], [5, 6], [7], [8, 9]]


def make_index():
    n, m, I, P = 6, 2, len(INSTANCES), 2
    inst_emb = np.zeros((I, P, D), np.float32)
    inst_pmask = np.zeros((I, P), bool)
    inst_pos = np.zeros((I, 3), np.float32)
    sensors = np.zeros((I, 1), np.float32)
    smask = np.zeros((I, 1), bool)
    for c, (phr, xy, temp) in enumerate(INSTANCES):
        for k, e in enumerate(phr):
            inst_emb[c, k], inst_pmask[c, k] = e, True
        inst_pos[c, :2] = xy
        if temp is not None:
            sensors[c, 0], smask[c, 0] = temp, True
    slot_inst = np.full((n, m), -1, np.int32)
    for i, row in enumerate(SLOTS):
        slot_inst[i, : len(row)] = row
    # Node i is exploration record 10 * i; the key poses saw each instance once, so first == last.
    first = np.array([10.0 * next(i for i, row in enumerate(SLOTS) if c in row) for c in range(I)])
    last = first
    node_emb = np.stack([unit(sum(inst_emb[c, 0] for c in row)) for row in SLOTS])
    pos = np.stack([np.array([1.5 * i, 0.0, 0.0]) for i in range(n)]).astype(np.float32)
    nbr = np.full((n, 2), -1, np.int32)
    for i in range(n):
        nb = [k for k in (i - 1, i + 1) if 0 <= k < n]
        nbr[i, : len(nb)] = nb
    return RetrievalIndex(
        node_emb=jnp.asarray(node_emb), node_pos=jnp.asarray(pos), node_mask=jnp.ones(n, bool),
        nbr=jnp.asarray(nbr), nbr_mask=jnp.asarray(nbr >= 0), inst_emb=jnp.asarray(inst_emb),
        inst_phrase_mask=jnp.asarray(inst_pmask), inst_name_emb=jnp.asarray(inst_emb),
        inst_name_mask=jnp.asarray(inst_pmask), inst_pos=jnp.asarray(inst_pos), inst_sensors=jnp.asarray(sensors),
        inst_sensor_mask=jnp.asarray(smask), inst_mask=jnp.ones(I, bool), inst_first=jnp.asarray(first, jnp.float32),
        inst_last=jnp.asarray(last, jnp.float32), slot_inst=jnp.asarray(slot_inst),
        slot_mask=jnp.asarray(slot_inst >= 0), cluster_emb=jnp.ones((1, 1, D)), cluster_label_emb=jnp.ones((1, 1, D)),
        cluster_mask=jnp.ones((1, 1), bool), cluster_parent=-jnp.ones((1, 1), jnp.int32),
        leaf_cluster=jnp.zeros((n, 1), jnp.int32),
    )


def query(target, head=None, anchor=None, hint=None, op=OP_NONE, value=0.0, scale=3.0, room=None, near=True,
          time_order=0, time_rank=1):
    z = np.zeros(D, np.float32)
    return QueryArrays(
        target=jnp.asarray(target), head=jnp.asarray(head if head is not None else target),
        anchor=jnp.asarray(anchor if anchor is not None else z), has_anchor=jnp.asarray(anchor is not None),
        anchor_near=jnp.asarray(anchor is not None and near),
        room=jnp.asarray(room if room is not None else z), has_room=jnp.asarray(room is not None),
        hint=jnp.asarray(hint if hint is not None else [0.0, 0.0], jnp.float32), has_hint=jnp.asarray(hint is not None),
        sensor_channel=jnp.int32(0), sensor_op=jnp.int32(op), sensor_value=jnp.float32(value),
        sensor_scale=jnp.float32(scale), time_order=jnp.int32(time_order), time_rank=jnp.int32(time_rank),
    )


IDX = make_index()
P = RetrievalParams.create(w_slot=0.8, match_threshold=0.6, anchor_threshold=0.8, boost_threshold=0.8)
score = jax.jit(score_subgoal)


def best(q, p=P):
    s, expl = score(IDX, q, p)
    return int(jnp.argmax(s)), s, expl


def test_attributes_pick_the_instance():
    assert best(query(unit(SOFA + 0.5 * RED), SOFA))[0] == 0
    assert best(query(unit(SOFA + 0.5 * BLUE), SOFA))[0] == 4


def test_location_hint_disambiguates_identical_instances():
    # Plant A at x = 1.8, plant B at x = 7.8 (both at y = 0.5).
    assert best(query(unit(PLANT), hint=[1.8, 0.5]))[0] == 1
    i, _, expl = best(query(unit(PLANT), hint=[7.8, 0.5]))
    assert i == 5 and float(expl["loc"][5]) > 0.99


@pytest.mark.parametrize("op, value, expect", [(OP_APPROX, 60.0, 5), (OP_APPROX, 40.0, 2), (OP_MAX, 0.0, 5), (OP_MIN, 0.0, 2)])
def test_sensor_constraints(op, value, expect):
    assert best(query(unit(RADIATOR), op=op, value=value))[0] == expect


def test_anchor_guided_prefers_remote_near_sofa():
    q = query(unit(REMOTE), anchor=unit(SOFA))
    i, s, expl = best(q)
    assert i == 0 and int(expl["anchor"][0]) == 0  # the sofa is seen from the same key pose
    # Without the spatial term the two remotes tie on semantics; boosting by the anchor still helps node 0.
    i2, s2, e2 = best(q, ablation_params(P, "no_spatial"))
    assert int(e2["anchor"][0]) == -1


def test_masked_nodes_never_win():
    idx = IDX.replace(node_mask=IDX.node_mask.at[0].set(False))
    s, _ = score(idx, query(unit(SOFA + 0.5 * RED), SOFA), P)
    assert float(s[0]) <= NEG / 2 and int(jnp.argmax(s)) == 4


def test_ablation_grid_in_one_call_traces_once():
    traces = []

    def f(p):
        traces.append(1)
        return score_subgoal(IDX, query(unit(REMOTE), anchor=unit(SOFA)), p)[0]

    grid = stack_params([ablation_params(P, v) for v in ABLATIONS])
    out = jax.jit(jax.vmap(f))(grid)
    assert out.shape == (len(ABLATIONS), 6) and len(traces) == 1
    for k, v in enumerate(ABLATIONS):
        np.testing.assert_allclose(out[k], score_subgoal(IDX, query(unit(REMOTE), anchor=unit(SOFA)), ablation_params(P, v))[0], atol=1e-6)


def test_sigma_grid_without_recompiling():
    # A function object of its own: jax.jit wrappers of the same function share one executable cache,
    # so other tests' calls of jit(score_subgoal) would show up in its cache size.
    traces = []

    def scored(idx, q, p):
        traces.append(1)
        return score_subgoal(idx, q, p)

    f = jax.jit(scored)
    q = query(unit(REMOTE), anchor=unit(SOFA))
    for sigma in (0.5, 1.0, 3.0):
        f(IDX, q, P.replace(sigma=jnp.float32(sigma)))
    assert len(traces) == 1 and f._cache_size() == 1


def two_regions():
    """IDX with two forest clusters: nodes 0-2 labelled room_a, nodes 3-5 room_b."""
    room_a, room_b = unit(RED + BLUE), unit(TV + LAMP)
    idx = IDX.replace(
        cluster_emb=jnp.stack([jnp.asarray(room_a), jnp.asarray(room_b)])[None],
        cluster_label_emb=jnp.stack([jnp.asarray(room_a), jnp.asarray(room_b)])[None],
        cluster_mask=jnp.ones((1, 2), bool), cluster_parent=-jnp.ones((1, 2), jnp.int32),
        leaf_cluster=jnp.array([[0], [0], [0], [1], [1], [1]], jnp.int32),
    )
    return idx, room_a, room_b


def test_room_term_prefers_the_matching_region():
    idx, room_a, room_b = two_regions()
    s, expl = score(idx, query(unit(PLANT), room=room_b), P)
    assert int(jnp.argmax(s)) == 5 and float(expl["room"][5]) == 1.0 and float(expl["room"][1]) < 0.01
    s, _ = score(idx, query(unit(PLANT), room=room_a), P)
    assert int(jnp.argmax(s)) == 1
    # The labels belong to the forest: without it the room phrase cannot be used (a tie on semantics).
    _, expl = score(idx, query(unit(PLANT), room=room_a), ablation_params(P, "no_forest"))
    assert bool(jnp.all(expl["room"] == 1.0))


def test_room_phrase_does_not_hide_a_target_whose_region_is_labelled_otherwise():
    # The only TV (node 3) lies in the region labelled like room_b; the query names room_a (the summariser
    # labelled the TV's room differently, or the phrase is redundant). The room term is relative to the
    # regions that hold the target's category, and the forest does not lock a region without one.
    idx, room_a, room_b = two_regions()
    s, expl = score(idx, query(unit(TV), room=room_a), P)
    assert int(jnp.argmax(s)) == 3 and float(expl["room"][3]) == 1.0 and bool(expl["category"][3])
    locked = P.replace(forest_lock=jnp.float32(1.0), beam=jnp.int32(1))  # the paper's hard pruning, one region
    s, _ = score(idx, query(unit(TV), room=room_a), locked)
    assert int(jnp.argmax(s)) == 3 and bool(jnp.all(s > NEG / 2))  # region a holds no TV: no lock
    s, _ = score(idx, query(unit(PLANT), room=room_a), locked)
    assert float(s[5]) <= NEG / 2 and int(jnp.argmax(s)) == 1  # it holds a plant: region b is pruned
    # Two plants, one per region: the room phrase still picks between them.
    s, _ = score(idx, query(unit(PLANT), room=room_a), P)
    assert int(jnp.argmax(s)) == 1 and float(s[5]) < 0.01 * float(s[1])


def test_anchor_proximity_prefers_the_instance_next_to_the_anchor():
    from ragnav_jax.retrieval.score import anchor_proximity

    # "the radiator near the lamp": radiator 4 is 1.4 m from the lamp, radiator 9 six metres away.
    anc = jnp.asarray([float(e[0] @ LAMP) for e, _, _ in INSTANCES])
    p = P.replace(anchor_threshold=jnp.float32(0.8), sigma_rel=jnp.float32(3.0))
    prox = anchor_proximity(IDX, query(unit(RADIATOR), anchor=unit(LAMP)), p, anc)
    assert float(prox[4]) > 0.85 and float(prox[9]) < 0.2
    ref = np.exp(-((3.3 - 1.9) ** 2 + 0.1**2) / (2 * 3.0**2))  # NumPy reference of the Gaussian
    assert float(prox[4]) == pytest.approx(ref, rel=1e-5)
    # Off for a room-scale relation, without spatial enhancement, and without an anchor phrase.
    for q, pp in ((query(unit(RADIATOR), anchor=unit(LAMP), near=False), p),
                  (query(unit(RADIATOR), anchor=unit(LAMP)), ablation_params(p, "no_spatial")),
                  (query(unit(RADIATOR)), p)):
        assert bool(jnp.all(anchor_proximity(IDX, q, pp, anc) == 1.0))


def test_anchor_proximity_picks_between_two_instances_one_key_pose_sees():
    # Node 2 sees both radiators (one 1.4 m from the lamp, one 6 m away), the second one better worded.
    slot = np.asarray(IDX.slot_inst).copy()
    slot[2] = [9, 4]
    idx = IDX.replace(slot_inst=jnp.asarray(slot), slot_mask=jnp.asarray(slot >= 0))
    q_plain = query(unit(RADIATOR + 0.2 * BLUE), RADIATOR)
    _, expl = score(idx, q_plain, P)
    assert int(expl["instance"][2]) == 0  # the blueish radiator 9 (slot 0) wins on words alone
    _, expl = score(idx, query(unit(RADIATOR + 0.2 * BLUE), RADIATOR, anchor=unit(LAMP)), P)
    assert int(expl["instance"][2]) == 1  # near the lamp: radiator 4 (slot 1)


def test_pooled_phrases_recover_an_attribute_seen_once():
    # Radiator 9 was once described as a blueish radiator; the 40 C one never was.
    p = P.replace(w_slot=jnp.float32(1.0))  # instance evidence only (node 5's fingerprint also has a plant)
    assert best(query(unit(RADIATOR + 0.2 * BLUE), RADIATOR), p)[0] == 5
    assert best(query(unit(RADIATOR), RADIATOR), p)[0] == 2
