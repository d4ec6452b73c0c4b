"""A learned reader of what a goal's words ask of a sensor: which reading, and which way.

    reader = SensorReader.load()                                   # ragnav_jax/data/sensor_reader.npz
    p_reading, p_way = reader.probs(["the toastiest tool in the workshop"])   # (n, 3), (n, len(WAYS))
    sg = revise(sg, p_reading[0], p_way[0], conf=0.9)              # the parse's sensor constraint, read again

Each new author words a comparison in their own way ("never dips under 20 degrees", "capped at 40 per cent",
"that leads every other on NDVI", "the toastiest", "the most withered"), and a rule parser knows only the phrases
written beside it: it reads "dips under" as below, "toastiest tool" as a name, and nothing at all in "leads every
other on NDVI". The direction of a comparison is the hard part: the sentence encoder puts antonyms together
("toastiest" is nearest "frostiest"), so nearest-phrase matching cannot give it, and a linear probe of MiniLM's
sentence vectors reads only half of the held-out template sets' comparisons right. Fine-tuned with low-rank
adapters on goal phrases of many authors, the encoder learns which words carry the direction.

The classifier reads a goal's text (`Subgoal.text`, the span the parse gave it) and gives a distribution over the
generator's three readings and over WAYS (no comparison, above, below, about, the most, the least). `revise`
then changes the parse only where the classifier is sure (`conf`): a comparison the parse read the other way
turns, one the parse missed is added (a superlative, or a bound with the goal's one number), and a superlative
word the parse took as part of the name leaves the name. Values are still read by the parser's number rules.

Training data (`training_examples`): goal phrases of episodes written with every template set but the held-out
one (`HELD_OUT`) over seen-split houses drawn with their own seed, labelled from the generator's truth, plus the
same goals written again with a random comparison by their set's own sensor template. The confidence is fitted
on other seen-split houses like the tagger's (`fit_conf`): the smallest at which `revise` changes at most
CONF_CHANGES (`adapters.py`) of the parses that read the truth's sensor constraints.
"""

from __future__ import annotations

import dataclasses
import functools
import re
from collections.abc import Collection, Sequence
from pathlib import Path

import jax
import jax.numpy as jnp
import numpy as np
from flax import linen as nn

from ragnav_jax.errors import UserError
from ragnav_jax.language.adapters import (
    data_path,
    encoder_params,
    fitted_conf,
    join,
    load_adapters,
    save_adapters,
    split_init,
    train,
)
from ragnav_jax.language.types import SensorConstraint, Subgoal
from ragnav_jax.memory.encoder import BertShape, MiniLM, MiniLMEmbedder, _bucket

READINGS = ("temperature_c", "humidity_pct", "ndvi")  # the generator's readings, the ones the classifier knows
WAYS = ("none", "above", "below", "approx", "max", "min")
NONE, ABOVE, BELOW, APPROX, MAX, MIN = range(len(WAYS))
WAY_OF = {"gt": ABOVE, "ge": ABOVE, "lt": BELOW, "le": BELOW, "approx": APPROX, "max": MAX, "min": MIN}
READER_FORMAT = "ragnav-sensor-reader/1"
MAX_TOKENS = 96
LENGTHS = (32, 64, MAX_TOKENS)
# the template sets the reader may not learn from: AA (`unseen_aa`), the fresh set of round 24 (round 24 taught
# the reader Z and W, the fresh sets of rounds 22 and 23), AB (`unseen_ab`), that of round 25, AC (`unseen_ac`),
# that of round 26, AD (`unseen_ad`), that of round 27, AE (`unseen_ae`), measured fresh with round 27's design,
# AF (`unseen_af`), that of round 28, AG (`unseen_ag`), that of round 29, AH (`unseen_ah`), that of round 30, AI
# (`unseen_ai`), that of round 31, AJ (`unseen_aj`), that of round 32, AK (`unseen_ak`), that of round 33, AL
# (`unseen_al`), that of round 34, AM (`unseen_am`), that of round 35, AN (`unseen_an`), that of round 36, AO
# (`unseen_ao`), that of round 37, AP (`unseen_ap`), a second fresh measure of round 37's design, AQ
# (`unseen_aq`), that of round 38, AR (`unseen_ar`) and AS (`unseen_as`), those of round 39, AT (`unseen_at`),
# that of round 40, and AU (`unseen_au`), a second fresh measure of round 40's design. The next change of the
# readers adds a new fresh set here before it is measured.
HELD_OUT = ("unseen_aa", "unseen_ab", "unseen_ac", "unseen_ad", "unseen_ae", "unseen_af", "unseen_ag",
            "unseen_ah", "unseen_ai", "unseen_aj", "unseen_ak", "unseen_al",
            "unseen_am", "unseen_an", "unseen_ao", "unseen_ap", "unseen_aq",
            "unseen_ar", "unseen_as", "unseen_at", "unseen_au", "unseen_av")
# values a random comparison is written with in augmented examples, per reading
_VALUES = {"temperature_c": (-20, -18, -4, 0, 4, 18, 21, 22, 25, 30, 38, 40, 45, 60, 90, 150, 180, 220),
           "humidity_pct": (15, 20, 25, 30, 35, 40, 45, 50, 55, 60, 65, 70, 75, 80, 85, 90),
           "ndvi": (0.1, 0.2, 0.25, 0.3, 0.35, 0.4, 0.45, 0.5, 0.55, 0.6, 0.65, 0.7, 0.75, 0.8, 0.85)}


def train_splits() -> tuple[str, ...]:
    """Every template set of the episode generator but the held-out ones."""
    from ragnav_jax.config import EPISODE_SPLITS

    return tuple(s for s in EPISODE_SPLITS if s not in HELD_OUT)


def check_splits(splits: Sequence[str]) -> None:
    """UserError unless every template set is one the reader may learn from."""
    ok = train_splits()
    bad = [s for s in splits if s not in ok]
    if bad:
        raise UserError(f"sensor reader splits: {bad[0]!r} is not a training template set ({', '.join(ok)})")


def label(sg: Subgoal) -> tuple[int, int]:
    """(reading index, way index) of a truth subgoal: its first sensor constraint, or (0, NONE)."""
    for c in sg.sensors:
        if c.reading in READINGS:
            return READINGS.index(c.reading), WAY_OF[c.comparator]
    return 0, NONE


def training_examples(cfg, scenes: int, seed: int, splits: Sequence[str] | None = None,
                      rewrite: float = 1.0) -> list[tuple[str, int, int]]:
    """(goal text, reading index, way index) of every goal of episodes written with each template set over
    `scenes` seen-split houses of `seed`; with `rewrite`, that share of the goals without a comparison written
    again with a random one (`_VALUES`) by the set's own goal and sensor templates."""
    splits = tuple(splits) if splits is not None else train_splits()
    check_splits(splits)
    return goal_examples(cfg, scenes, seed, splits, rewrite)


def goal_examples(cfg, scenes: int, seed: int, splits: Sequence[str], rewrite: float = 1.0) -> list[tuple[str, int, int]]:
    """`training_examples` of any template sets, held-out ones included (to measure a reader, never to fit one)."""
    from ragnav_jax.evaluation.fitting import _seen_scenes
    from ragnav_jax.language.episodes import _renderer, generate_episodes

    houses = _seen_scenes(cfg, scenes, seed)
    rng = np.random.default_rng(seed)
    out = []
    for split in splits:
        ecfg = dataclasses.replace(cfg.episodes, split=split)
        goal, sensor = _renderer(split, "goal"), _renderer(split, "sensor")
        for g in generate_episodes(houses, ecfg, seed):
            for sg in g.truth.subgoals:
                if not sg.text:
                    continue
                out.append((sg.text, *label(sg)))
                if not sg.sensors and sg.location is None and rng.uniform() < rewrite:
                    rd = READINGS[rng.integers(len(READINGS))]
                    cmp = ("gt", "ge", "lt", "le", "approx", "max", "min")[rng.integers(7)]
                    value = None if cmp in ("max", "min") else float(rng.choice(_VALUES[rd]))
                    prefix, tail, written = sensor(rng, SensorConstraint(rd, cmp, value))
                    text = goal(rng, dataclasses.replace(sg, sensors=(written,)), prefix=prefix, tail=tail)
                    out.append((text.strip(" ,"), READINGS.index(rd), WAY_OF[cmp]))
    return out


# ----------------------------------------------------------------------------------------------------
# The model


class Classifier(nn.Module):
    """MiniLM (with adapters), mean-pooled -> (B, len(READINGS)) and (B, len(WAYS)) logits."""

    shape: BertShape
    lora: int = 8

    @nn.compact
    def __call__(self, ids, train: bool = False):  # ids (B, L) int32, 0 = padding
        h = MiniLM(self.shape, pool=False, lora=self.lora, name="enc")(ids, (ids > 0).astype(jnp.int32))
        m = (ids > 0)[..., None]
        p = (h * m).sum(1) / jnp.maximum(m.sum(1), 1)
        p = nn.Dropout(0.1, deterministic=not train)(p)
        return nn.Dense(len(READINGS), name="reading")(p), nn.Dense(len(WAYS), name="way")(p)


def _is_trained(path: tuple[str, ...]) -> bool:
    return path[0] in ("reading", "way") or "_lora_" in path[-2]


def encode(tokenizer, texts: Sequence[str]) -> np.ndarray:
    """(n, MAX_TOKENS) int32 token ids (0 = padding), lower-cased texts."""
    ids = np.zeros((len(texts), MAX_TOKENS), np.int32)
    for i, e in enumerate(tokenizer.encode_batch([t.lower() for t in texts])):
        n = min(len(e.ids), MAX_TOKENS)
        ids[i, :n] = e.ids[:n]
    return ids


@dataclasses.dataclass(frozen=True)
class FitSettings:
    """How the reader is fitted (`ragnav fit-sensor-reader`)."""

    scenes: int = 8  # seen-split houses drawn for the examples
    seed: int = 5151  # houses, episodes, rewrites, initialisation and batches
    lora: int = 8
    epochs: int = 3
    batch: int = 32
    lr: float = 1e-3
    rewrite: float = 1.0  # share of goals without a comparison also written with a random one


def fit_reader(cfg, settings: FitSettings = FitSettings(), splits: Sequence[str] | None = None,
               progress: bool = False) -> tuple[dict, dict]:
    """Trains the adapters and the two heads; returns (trained flat params, metadata for the fitted file)."""
    import optax

    splits = tuple(splits) if splits is not None else train_splits()
    base = MiniLMEmbedder()
    examples = training_examples(cfg, settings.scenes, settings.seed, splits, settings.rewrite)
    ids = encode(base.tokenizer, [t for t, _, _ in examples])
    y = np.array([[r, w] for _, r, w in examples], np.int32)
    model = Classifier(base.shape, settings.lora)
    key = jax.random.PRNGKey(settings.seed)
    key, k0 = jax.random.split(key)
    trained, frozen = split_init(model, base, k0, _is_trained)

    def loss_fn(tr, fr, x, t, k):
        lr_, lw = model.apply(join(tr, fr), x, True, rngs={"dropout": k})
        has = (t[:, 1] != NONE).astype(jnp.float32)  # no reading is asked of a goal without a comparison
        ce_r = optax.softmax_cross_entropy_with_integer_labels(lr_, t[:, 0])
        ce_w = optax.softmax_cross_entropy_with_integer_labels(lw, t[:, 1])
        return (ce_w + has * ce_r).mean()

    rng = np.random.default_rng(settings.seed)

    def batches():
        order = rng.permutation(len(ids))
        for s in range(0, len(order) - settings.batch + 1, settings.batch):
            b = order[s : s + settings.batch]
            yield ids[b, : _bucket(int((ids[b] > 0).sum(1).max()), LENGTHS)], y[b]

    steps = settings.epochs * (len(ids) // settings.batch)
    trained, losses = train(loss_fn, trained, frozen, batches, steps, settings.lr, key, "fit-sensor-reader", progress)
    ways = np.bincount(y[:, 1], minlength=len(WAYS))
    meta = {"format": READER_FORMAT, "lora": settings.lora, "readings": list(READINGS), "ways": list(WAYS),
            "fitted_on": {"world_split": "seen", "template_sets": list(splits), "scenes": settings.scenes,
                          "seed": settings.seed, "examples": len(examples),
                          "per_way": {w: int(n) for w, n in zip(WAYS, ways)}},
            "settings": dataclasses.asdict(settings), "final_loss": float(np.mean(losses[-50:])) if losses else None,
            "backend": jax.default_backend()}
    return trained, meta


# ----------------------------------------------------------------------------------------------------
# The fitted file and inference


def save_reader(trained: dict, meta: dict, path: str | Path) -> Path:
    """The adapters and heads as float32 arrays named by their parameter path, with the metadata as JSON."""
    return save_adapters(trained, meta, path)


def load_reader_file(path: str | Path) -> tuple[dict, dict]:
    return load_adapters(path, READER_FORMAT, "sensor reader")


@functools.lru_cache(maxsize=2)
def load_reader(path: str = "") -> SensorReader:
    """The reader of a fitted file ("" = ragnav_jax/data/sensor_reader.npz), loaded once per process."""
    return SensorReader(*load_reader_file(path or data_path("sensor_reader.npz")))


class SensorReader:
    """The fitted classifier over the installed MiniLM weights; `probs` runs fixed-shape jitted batches."""

    def __init__(self, trained: dict, meta: dict, batch_size: int = 32):
        self.base, self.meta, self.batch_size = MiniLMEmbedder(), meta, batch_size
        self.model = Classifier(self.base.shape, int(meta["lora"]))
        self.params = join(trained, encoder_params(self.base))
        self._apply = jax.jit(lambda p, x: tuple(jax.nn.softmax(z, -1) for z in self.model.apply(p, x)))
        self._seen: dict[str, tuple[np.ndarray, np.ndarray]] = {}

    def probs(self, texts: Sequence[str]) -> tuple[np.ndarray, np.ndarray]:
        """((n, len(READINGS)), (n, len(WAYS))) probabilities of each text; each text is read once per reader."""
        new = list(dict.fromkeys(t for t in texts if t not in self._seen))
        ids = encode(self.base.tokenizer, new)
        for s in range(0, len(ids), self.batch_size):
            x = ids[s : s + self.batch_size]
            L = _bucket(int((x > 0).sum(1).max()), LENGTHS)
            pad = np.zeros((self.batch_size, L), np.int32)
            pad[: len(x)] = x[:, :L]
            a, b = (np.asarray(z, np.float32) for z in self._apply(self.params, jnp.asarray(pad)))
            for i, t in enumerate(new[s : s + len(x)]):
                self._seen[t] = (a[i], b[i])
        got = [self._seen[t] for t in texts]
        return (np.stack([g[0] for g in got]) if got else np.zeros((0, len(READINGS)), np.float32),
                np.stack([g[1] for g in got]) if got else np.zeros((0, len(WAYS)), np.float32))


# ----------------------------------------------------------------------------------------------------
# Reading the parse again

_SUPERLATIVE = re.compile(r"^(?:(?:most|least)\s+[a-z\-]+|[a-z]+iest|[a-z]{4,}est)\s+")


def _comparator(way: int, had: str | None) -> str:
    """The comparator of a way, keeping the parse's where it goes the same way ("ge" stays "ge")."""
    if had is not None and WAY_OF.get(had) == way:
        return had
    return {ABOVE: "gt", BELOW: "lt", APPROX: "approx", MAX: "max", MIN: "min"}[way]


def _without_superlative(sg: Subgoal, known: Collection[str] = ()) -> Subgoal:
    """The subgoal less a leading superlative word the parse took as part of the name ("toastiest tool" ->
    "tool", "most withered spider plant" -> "spider plant") or as an attribute; a word that begins a name the
    house uses (`known`) stays ("chest freezer")."""
    t = sg.target
    m = _SUPERLATIVE.match(t.head + " ")
    first = m.group().split()[0] if m else ""
    if m and (any(n.split()[0] == first for n in known if n) or not t.head[m.end():].strip()):
        m = None
    head = t.head[m.end():].strip() if m else t.head
    attrs = tuple(a for a in t.attributes if not _SUPERLATIVE.match(a + " "))
    if head == t.head and attrs == t.attributes:
        return sg
    return dataclasses.replace(sg, target=dataclasses.replace(t, head=head, attributes=attrs))


def revise(sg: Subgoal, p_reading: np.ndarray, p_way: np.ndarray, conf: float,
           known: Collection[str] = ()) -> Subgoal:
    """The subgoal with its sensor constraint read again where the classifier is at least `conf` sure of a way
    (p_reading (len(READINGS),), p_way (len(WAYS),) of `sg.text`; known: the names the house's memory uses):

    - a parsed constraint on one of READINGS takes the classifier's way (a bound keeps its value; a
      superlative becomes a bound only where the goal's text holds one number to bound by);
    - where the parse read none, a superlative is added on the classifier's reading and a superlative word
      leaves the name, and a bound is added with the goal's one number (`tagger.loose_reading`);
    - "none" and an unsure classifier leave the parse as it is (a reading it does not know is never touched).
    """
    from ragnav_jax.language.tagger import loose_reading

    way = int(np.argmax(p_way))
    if way == NONE or float(p_way[way]) < conf:
        return sg
    at = next((i for i, c in enumerate(sg.sensors) if c.reading in READINGS), None)
    if at is None and sg.sensors:
        return sg
    if at is not None:
        c = sg.sensors[at]
        if way in (MAX, MIN):
            new = SensorConstraint(c.reading, _comparator(way, c.comparator), None, c.unit)
        elif c.value is not None:
            new = dataclasses.replace(c, comparator=_comparator(way, c.comparator))
        else:
            got = loose_reading(sg.text)
            if got is None or got.reading != c.reading:
                return sg
            new = dataclasses.replace(got, comparator=_comparator(way, None))
        if new == c:
            return sg
        out = dataclasses.replace(sg, sensors=sg.sensors[:at] + (new,) + sg.sensors[at + 1:])
        return _without_superlative(out, known) if way in (MAX, MIN) else out
    if way in (MAX, MIN):
        reading = READINGS[int(np.argmax(p_reading))]
        return _without_superlative(dataclasses.replace(sg, sensors=(SensorConstraint(reading, _comparator(way, None)),)),
                                    known)
    got = loose_reading(sg.text, (sg.location.x, sg.location.y) if sg.location is not None else ())
    if got is None:
        return sg
    return dataclasses.replace(sg, sensors=(dataclasses.replace(got, comparator=_comparator(way, None)),))


def fit_conf(reader: SensorReader, cfg, scenes: int, seed: int, splits: Sequence[str] | None = None) -> dict:
    """The smallest confidence of adapters.CONF_GRID at which `revise` changes at most CONF_CHANGES of the parsed goals
    whose sensor constraints equal the truth's, on `scenes` seen-split houses of `seed` (not the training
    houses), episodes of the template sets `splits`; with the changes at every grid value."""
    from ragnav_jax.evaluation.fitting import _seen_scenes
    from ragnav_jax.language.episodes import generate_episodes
    from ragnav_jax.language.parser import parse_instruction
    from ragnav_jax.language.types import ParseError

    splits = tuple(splits) if splits is not None else train_splits()
    check_splits(splits)
    houses = _seen_scenes(cfg, scenes, seed)
    goals = []
    for split in splits:
        for g in generate_episodes(houses, dataclasses.replace(cfg.episodes, split=split), seed):
            try:
                sgs = parse_instruction(g.episode.instruction).subgoals
            except ParseError:
                continue
            if len(sgs) == len(g.truth.subgoals):
                goals += [sg for sg, t in zip(sgs, g.truth.subgoals) if _same_sensors(sg.sensors, t.sensors)]
    pr, pw = reader.probs([sg.text for sg in goals])
    conf, changes = fitted_conf(lambda c: sum(revise(sg, a, b, c) != sg for sg, a, b in zip(goals, pr, pw)), len(goals))
    return {"conf": conf, "goals": len(goals), "changes": changes,
            "fitted_on": {"world_split": "seen", "scenes": scenes, "seed": seed, "template_sets": list(splits)}}


def _same_sensors(a: Sequence[SensorConstraint], b: Sequence[SensorConstraint]) -> bool:
    return len(a) == len(b) and all(x.reading == y.reading and WAY_OF.get(x.comparator) == WAY_OF.get(y.comparator)
                                    and (x.value is None) == (y.value is None)
                                    and (x.value is None or abs(x.value - y.value) < 1e-6) for x, y in zip(a, b))
