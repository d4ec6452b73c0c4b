"""The reflection's search (evaluation/search.py): where it looks for a goal the memory missed, and a closed
loop in which it finds what the memory never recorded."""

import dataclasses

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from hypothesis.extra import numpy as hnp
from test_memory_streams import synthetic_stream

from ragnav_jax.config import load_config
from ragnav_jax.evaluation.execute import make_executor
from ragnav_jax.evaluation.navigate import evaluate_navigation
from ragnav_jax.evaluation.search import search_nodes, spread
from ragnav_jax.evaluation.verify import Verifier, memory_views
from ragnav_jax.language.episodes import Episode
from ragnav_jax.language.parser import parse_instruction
from ragnav_jax.memory.build import build_bank
from ragnav_jax.memory.encoder import HashingEmbedder
from ragnav_jax.world.scene import room_of


@pytest.fixture(scope="module")
def hidden(apartment):
    """A memory of the apartment in which the living room's potted plant was never seen."""
    cfg = load_config(None, ["memory.embedder=hashing", "eval.batch_size=8", "eval.record_legs=true"])
    stream = synthetic_stream(apartment)
    vis = stream.visible.copy()
    vis[:, [o.id for o in apartment.objects].index("plant_1")] = False
    emb = HashingEmbedder(dim=cfg.memory.hashing_dim)
    bank, _ = build_bank([apartment], [dataclasses.replace(stream, visible=vis)], cfg, embedder=emb)
    return cfg, bank, emb


@settings(max_examples=40, deadline=None)
@given(hnp.arrays(np.float64, st.tuples(st.integers(1, 9), st.just(2)), elements=st.floats(-5, 5)), st.data())
def test_spread_is_farthest_point_sampling(pos, data):
    first = data.draw(st.integers(0, len(pos) - 1))
    k = data.draw(st.integers(1, 10))
    got = spread(pos, first, k)
    assert got[0] == first and len(got) == min(k, len(pos))
    for t in range(1, len(got)):  # each pick is as far from the earlier ones as any point is
        d = np.min(np.linalg.norm(pos[:, None] - pos[got[:t]][None], axis=-1), axis=1)
        assert d[got[t]] == pytest.approx(d.max())


def test_search_nodes_lie_where_the_instruction_puts_the_goal(hidden, apartment):
    cfg, bank, emb = hidden
    v = Verifier.build(emb, cfg)
    view = memory_views(v, bank, [apartment])[apartment.name]
    pos, live = np.asarray(bank.memory.position)[0, :, :2], np.asarray(bank.memory.node_mask)[0]
    sgs = parse_instruction("Go to the potted plant in the kitchen, then the lamp around x=5.4, y=4.2, "
                            "then the sofa.").subgoals
    room, hint, plain = (search_nodes(v, view, sg, pos, live, 3) for sg in sgs)
    assert 1 <= len(room) <= 3 and {room_of(apartment.rooms, *pos[n]) for n in room} == {"kitchen"}
    d = np.linalg.norm(pos[list(hint)] - [5.4, 4.2], axis=1)
    assert 1 <= len(hint) <= 3 and np.all(np.diff(d) >= 0)  # nearest the hint first
    assert all(x <= v.radius or room_of(apartment.rooms, *pos[n]) == "living" for n, x in zip(hint, d))
    assert plain == ()  # no room, no coordinates: nowhere to search
    assert search_nodes(v, view, sgs[0], pos, live, 0) == ()


def test_search_finds_what_the_memory_never_recorded(hidden, apartment):
    """The memory never saw the living room's plant; its candidates are all rejected. Searching the living
    room's key poses finds it; without the search (and the fallback, which would declare the study's plant)
    the goal fails."""
    cfg, bank, emb = hidden
    ex = make_executor([apartment], cfg)
    ep = Episode(id="search", scene=apartment.name, instruction="Go to the potted plant in the living room, then the fridge.",
                 modality="text", goals=("plant_1", "fridge_1"), order="strict")
    off = dataclasses.replace(cfg, eval=dataclasses.replace(cfg.eval, search_nodes=0, fallback=False))
    rows, _ = evaluate_navigation(bank, [apartment], [ep], emb, off, "ragnav", executor=ex)
    assert not rows[0]["success"] and rows[0]["goal_status"][0] == "failed:not_confirmed"
    rows, _ = evaluate_navigation(bank, [apartment], [ep], emb, cfg, "ragnav", executor=ex)
    r = rows[0]
    assert r["success"] and r["goal_status"] == ["found", "found"]
    legs = [leg for leg in r["legs"] if leg["goal"] == 0]
    kinds = [leg["kind"] for leg in legs]
    assert "search" in kinds and kinds[-1] == "approach" and kinds.index("search") > kinds.index("nav")
    assert all(room_of(apartment.rooms, *leg["end"]) == "living" for leg in legs if leg["kind"] == "search")


def test_a_shared_verifier_reuses_its_views_and_checks(hidden, apartment):
    """Methods evaluated together share one verifier (`ragnav eval`): the second method's memory views and
    verdicts are the first's objects, equal to those of a verifier of its own; another bank gets its own."""
    from ragnav_jax.evaluation.verify import verdict_table

    cfg, bank, emb = hidden
    texts = ["go to the potted plant in the living room", "find the sofa, then the bed"]
    eps = [Episode(f"e{i}", apartment.name, t, ("x",)) for i, t in enumerate(texts)]
    subgoals = [parse_instruction(t).subgoals for t in texts]
    shared = Verifier.build(emb, cfg)
    views = memory_views(shared, bank, [apartment])
    first = verdict_table(shared, views, eps, subgoals)
    assert memory_views(shared, bank, [apartment]) is views
    again = verdict_table(shared, memory_views(shared, bank, [apartment]), eps, subgoals)
    assert all(a is b for ra, rb in zip(first, again) for a, b in zip(ra, rb))
    own = Verifier.build(emb, cfg)
    fresh = verdict_table(own, memory_views(own, bank, [apartment]), eps, subgoals)
    assert all(np.array_equal(a, b) for ra, rb in zip(first, fresh) for a, b in zip(ra, rb))
    other = dataclasses.replace(bank)
    assert memory_views(shared, other, [apartment]) is not views
