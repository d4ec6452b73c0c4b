"""Seen/unseen world splits: the seen split is the original generator byte for byte; the unseen split uses
only its own room types, categories and attribute kinds, with things standing on others."""

import hashlib
import re
from collections import Counter

import pytest

from ragnav_jax.config import ROOM_TYPES, WorldConfig, load_config
from ragnav_jax.errors import UserError
from ragnav_jax.memory.captioner import ADJECTIVE_KEYS, SYNONYMS, CaptionNoise, find_words, template_caption
from ragnav_jax.memory.keyposes import NodeObservation
from ragnav_jax.world.generator import generate_scene
from ragnav_jax.world.geometry import reachability
from ragnav_jax.world.scene import scene_to_json
from ragnav_jax.world.vocabulary import (
    CATALOG,
    PLANTS,
    ROOM_GROUPS,
    ROOM_TYPES_UNSEEN,
    UNSEEN_CATALOG,
    UNSEEN_HYPERNYMS,
    UNSEEN_SYNONYMS,
    catalog_for,
    plants_for,
    room_groups_for,
)

UNSEEN = WorldConfig(split="unseen", num_scenes=3)
STATES = {"switched on", "switched off", "open", "closed", "empty", "full"}


def _sha(scene) -> str:
    return hashlib.sha256(scene_to_json(scene).encode()).hexdigest()


@pytest.fixture(scope="module")
def unseen_scenes():
    return [generate_scene(UNSEEN, 3, i) for i in range(3)]


def test_seen_split_unchanged():
    """Hashes computed with the generator before the split existed (the paper preset depends on them)."""
    small = WorldConfig(min_rooms=4, max_rooms=4, min_objects=10, max_objects=20)
    assert small.split == "seen"
    assert _sha(generate_scene(small, 7, 0)) == "8a1a5d6b16a3629d54af1faea60b14522cdd260034bc4bed2f8a6f661d25e3ef"
    paper = load_config("configs/paper.yaml").world
    assert _sha(generate_scene(paper, 2024, 0)) == "c47b5fb549b78829301bd0ac3fc8b922926f72f27f0d6d48cb16153aa385ae38"


def test_split_config():
    assert WorldConfig().room_types == ROOM_TYPES
    assert UNSEEN.room_types == ROOM_TYPES_UNSEEN  # the seen default follows the split
    assert WorldConfig(split="unseen", room_types=("garage",)).room_types == ("garage",)  # still overridable
    assert load_config(None, ["world.split=unseen"]).world.room_types == ROOM_TYPES_UNSEEN
    with pytest.raises(UserError, match=r"world\.split"):
        load_config(None, ["world.split=bogus"])


def test_vocabularies_disjoint():
    assert catalog_for("seen") is CATALOG and room_groups_for("seen") is ROOM_GROUPS and plants_for("seen") == PLANTS
    assert not set(UNSEEN_CATALOG) & set(CATALOG) and not set(ROOM_TYPES_UNSEEN) & set(ROOM_TYPES)

    def words_in(a: str, b: str) -> bool:  # a occurs in b as whole words (hyphens join words)
        return re.search(r"(?<![\w-])" + re.escape(a) + r"(?![\w-])", b) is not None

    for u in UNSEEN_CATALOG:
        assert not any(words_in(c, u) or words_in(u, c) for c in CATALOG), u
        assert not any(words_in(v, u) for v in UNSEEN_CATALOG if v != u), u
    seen_kinds = {k for e in CATALOG.values() for k, _ in e.attrs}
    seen_values = {v for e in CATALOG.values() for _, vs in e.attrs for v in vs}
    for e in UNSEEN_CATALOG.values():
        assert not {k for k, _ in e.attrs} & seen_kinds
        assert not {v for _, vs in e.attrs for v in vs} & seen_values
    assert set(UNSEEN_SYNONYMS) <= set(UNSEEN_CATALOG)
    assert all(cats <= set(UNSEEN_CATALOG) for cats in UNSEEN_HYPERNYMS.values())


def test_unseen_deterministic():
    assert scene_to_json(generate_scene(UNSEEN, 3, 1)) == scene_to_json(generate_scene(UNSEEN, 3, 1))
    assert scene_to_json(generate_scene(UNSEEN, 3, 1)) != scene_to_json(generate_scene(UNSEEN, 4, 1))


def test_unseen_scenes(unseen_scenes):
    kinds: Counter = Counter()
    for s in unseen_scenes:
        assert {r.type for r in s.rooms} <= set(ROOM_TYPES_UNSEEN)
        assert {o.category for o in s.objects} <= set(UNSEEN_CATALOG)
        r = reachability(s)
        assert all(r.rooms_reachable.values()) and all(r.objects_reachable.values())
        counts = Counter(o.category for o in s.objects)
        assert sum(k >= 2 for k in counts.values()) >= UNSEEN.min_distractor_categories
        assert any(k >= 2 and UNSEEN_CATALOG[c].sensors for c, k in counts.items())  # sensor superlatives
        kinds.update(k for o in s.objects for k, _ in o.attributes)
        assert {v for o in s.objects for k, v in o.attributes if k == "state"} <= STATES
        # things on others: the bottom on a supporting object's top, the footprint inside its top
        raised = [o for o in s.objects if o.position[2] - o.size[2] / 2 > 0.05]
        assert 0.1 <= len(raised) / len(s.objects) <= 0.4
        for o in raised:
            bottom = o.position[2] - o.size[2] / 2
            assert any(
                abs(b.position[2] + b.size[2] / 2 - bottom) < 0.011  # positions and sizes are rounded to 1 cm
                and all(abs(o.position[k] - b.position[k]) <= (b.size[k] - o.size[k]) / 2 + 0.011 for k in (0, 1))
                for b in s.objects
                if b is not o
            ), o.id
    assert {"state", "finish", "shade", "fabric"} <= set(kinds)


def test_unseen_captions(unseen_scenes):
    s = unseen_scenes[0]
    noise = CaptionNoise(
        detect_near=1.0, detect_falloff=1e6, small_penalty=1.0, attribute_keep=1.0, max_objects=len(s.objects)
    )
    obs = NodeObservation(
        0, (0.0, 0.0, 0.0), 0.0, tuple(range(len(s.objects))), (1.0,) * len(s.objects), (0.0,) * len(s.objects)
    )
    cap = template_caption(s, obs, 0, 0, noise)
    assert len(cap.phrases) == len(s.objects)
    states = 0
    for oi, label, phrase in zip(cap.objects, cap.labels, cap.phrases):
        o = s.objects[oi]
        assert o.category in UNSEEN_CATALOG and label in SYNONYMS.get(o.category, (o.category,)), phrase
        m = find_words(label, phrase)
        pre, post = phrase[: m.start()], phrase[m.end():]
        if "state" in o.attrs:
            assert post.startswith(f" that is {o.attrs['state']}"), phrase
            states += 1
        for k in ADJECTIVE_KEYS:
            if k in o.attrs and k != "condition":
                assert re.search(rf"\b{re.escape(o.attrs[k])}\b", pre), (k, phrase)
    assert states > 0
    rooms = {r.type for r in s.rooms} | {r.id for r in s.rooms}
    assert not any(t in cap.text.lower() for t in rooms)
