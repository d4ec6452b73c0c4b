"""Episodes of the unseen splits: unseen houses described with unseen names and sentence structures."""

import pytest

from ragnav_jax.config import load_config
from ragnav_jax.language.episodes import HYPERNYMS, SYNONYMS, category_matches, generate_episodes, names
from ragnav_jax.world.generator import generate_scene
from ragnav_jax.world.vocabulary import CATALOG

SMALL = ["world.split=unseen", "world.num_scenes=1", "world.min_rooms=4", "world.max_rooms=5",
         "world.min_objects=25", "world.max_objects=40", "episodes.text=4", "episodes.text_location=3",
         "episodes.text_location_sensor=3", "episodes.max_goals=3"]


@pytest.fixture(scope="module")
def unseen_scene():
    cfg = load_config(None, SMALL)
    return generate_scene(cfg.world, 5, 0)


@pytest.mark.parametrize("split", ["unseen_dev", "unseen_dev2", "unseen_dev3", "unseen_dev4", "unseen_dev5",
                                   "unseen_dev6", "unseen_dev7", "unseen_dev8", "unseen_dev9",
                                   "unseen_dev10", "unseen_dev11", "unseen_dev12", "unseen"])
def test_unseen_episodes_are_deterministic_and_resolve(unseen_scene, split):
    cfg = load_config(None, [*SMALL, f"episodes.split={split}"])
    a = generate_episodes([unseen_scene], cfg.episodes, seed=3)
    b = generate_episodes([unseen_scene], cfg.episodes, seed=3)
    assert [p.episode.instruction for p in a] == [p.episode.instruction for p in b] and len(a) >= 6
    seen_words = generate_episodes([unseen_scene], load_config(None, SMALL).episodes, seed=3)
    assert {p.episode.instruction for p in a}.isdisjoint({p.episode.instruction for p in seen_words})
    for p in a:  # every goal's description is about an unseen-catalogue object (checked by the generator too)
        low = p.episode.instruction.lower()
        # sets M, N, O and P drop determiners and punctuation from the goals as rendered
        assert all((sg.target.head if split in ("unseen_dev10", "unseen_dev11", "unseen_dev12", "unseen")
                    else sg.text.lower()) in low
                   for sg in p.truth.subgoals)
        for sg, gid in zip(p.truth.subgoals, p.episode.goals):
            o = unseen_scene.object_by_id(gid)
            assert o.category not in CATALOG and category_matches(o.category, sg.target.head)


def test_split_names_are_disjoint():
    from ragnav_jax.world.vocabulary import UNSEEN_HYPERNYMS, UNSEEN_SYNONYMS

    assert not set(UNSEEN_SYNONYMS) & set(SYNONYMS) and not set(UNSEEN_SYNONYMS) & set(CATALOG)
    assert all(not (cats & set(CATALOG)) for cats in UNSEEN_HYPERNYMS.values())
    syn, hyp = names()  # the union: a seen house's categories see exactly the seen names
    assert all(hyp[k] & set(CATALOG) == HYPERNYMS.get(k, frozenset()) for k in hyp)
    assert all(syn[c] == SYNONYMS[c] for c in SYNONYMS)


def test_episodes_split_is_checked():
    from ragnav_jax.errors import UserError

    with pytest.raises(UserError, match="episodes.split"):
        load_config(None, ["episodes.split=bogus"])
