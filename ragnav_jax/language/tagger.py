"""A learned reader of where an instruction's goals are: MiniLM with low-rank adapters, tagging each word.

    tagger = InstructionTagger.load()                  # the fitted adapter of ragnav_jax/data/tagger.npz
    probs = tagger.word_probs(["first the sofa, then the fridge"])   # [(n_words, 8)]: TAGS, then AXES

The rule parser is written beside the sentences it has met, and each new author's phrasing breaks it in
the same two ways: a remark is read as a goal, or two goals run into one. Which words name a goal is a
matter of syntax more than of the words themselves, and a pretrained encoder carries syntax. The tagger
labels every word O, B-T/I-T (a goal's noun phrase: attributes and head) or B-A/I-A (an anchor's), and, with a
second head, tells the numbers of a coordinate hint from the rest (AXES: none, x, y). Coordinate hints come in
as many forms as authors ("at x=14.7 & y=8.5", "the spot whose x is 5.1 and whose y is 0.3", "posn 3.5E 2.0N");
which number is a coordinate, and which a reading's value or a count, is a matter of the words around it.

Training data (`training_examples`): houses of the seen split drawn with their own seed (never an
evaluation house), episodes written with every template set but the held-out one (`HELD_OUT`), labelled
from the generator's truth (a coordinate hint's numbers found as written, `label_axes`). Half the examples
have every goal and anchor phrase replaced by random words of the encoder's vocabulary (the same
replacement for the same phrase), so the tagger learns where goals sit in a sentence, not which nouns the
seen catalogue holds. Only the adapters (rank `lora` on every layer's query and value) and the two heads
are trained; the encoder's weights stay those of all-MiniLM-L6-v2, so the fitted file holds a few hundred
kilobytes.
"""

from __future__ import annotations

import dataclasses
import functools
import re
from collections.abc import Callable, Collection, Sequence
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
from ragnav_jax.memory.encoder import BertShape, MiniLM, MiniLMEmbedder, _bucket

TAGS = ("O", "B-T", "I-T", "B-A", "I-A")
O, BT, IT, BA, IA = range(len(TAGS))
AXES = ("none", "x", "y")  # what a word is to a coordinate hint: none of its numbers, its x or its y
AX_X, AX_Y = len(TAGS) + 1, len(TAGS) + 2  # their columns in `word_probs`, after the tags
TAGGER_FORMAT = "ragnav-tagger/1"
MAX_TOKENS = 128
_WORD = re.compile(r"[A-Za-z0-9]+(?:['\-.][A-Za-z0-9]+)*|\n+|\S")
ADD_CONF = 0.5  # a tagged phrase the parse missed is added when its every word is likelier a goal's than not
# a number is a coordinate hint's x (or y) when the coordinate head finds it likelier so than not. Not the fitted
# confidence of the goal tags (0.995-0.999), which right hints often do not reach: on seen-split houses of the
# confidence seed, hints are read right alike at every threshold from 0.5 to 0.98 (320 of 322) and less often above
# (0.99: 317; 0.999: 311; experiments/axis_conf_seen.py); 0.5 is the least of those, as ADD_CONF
AXIS_CONF = 0.5
LINE_BREAK = "|"  # the word a line break is read as: lists and headings are laid out in lines
# the template sets a tagger may learn from: every set of the generator but the held-out AA (`unseen_aa`), the
# fresh set of round 24, AB (`unseen_ab`), that of round 25, AC (`unseen_ac`), that of round 26, AD (`unseen_ad`),
# that of round 27, AE (`unseen_ae`), measured fresh with round 27's design, AF (`unseen_af`), that of round 28,
# AG (`unseen_ag`), that of round 29, AH (`unseen_ah`), that of round 30, AI (`unseen_ai`), that of round 31, AJ
# (`unseen_aj`), that of round 32, AK (`unseen_ak`), that of round 33, AL (`unseen_al`), that of round 34, AM
# (`unseen_am`), that of round 35, AN (`unseen_an`), that of round 36, AO (`unseen_ao`), that of round 37, AP
# (`unseen_ap`), a second fresh measure of round 37's design, AQ (`unseen_aq`), that of round 38, AR (`unseen_ar`)
# and AS (`unseen_as`), those of round 39, AT (`unseen_at`), that of round 40, and AU (`unseen_au`), a second
# fresh measure of round 40's design. Up to round 22 the tagger learnt from the seen templates and the twelve
# development sets alone; round 23 added the sets measured fresh in earlier rounds (P to Z) and the four training
# sets, as the sensor reader did, and round 24 W, round 23's fresh set
HELD_OUT = ("unseen_aa", "unseen_ab", "unseen_ac", "unseen_ad", "unseen_ae", "unseen_af", "unseen_ag",
            "unseen_ah", "unseen_ai", "unseen_aj", "unseen_ak", "unseen_al",
            "unseen_am", "unseen_an", "unseen_ao", "unseen_ap", "unseen_aq",
            "unseen_ar", "unseen_as", "unseen_at", "unseen_au", "unseen_av")
TRAIN_SPLITS = ("seen", "unseen_dev", "unseen_dev2", "unseen_dev3", "unseen_dev4", "unseen_dev5", "unseen_dev6",
                "unseen_dev7", "unseen_dev8", "unseen_dev9", "unseen_dev10", "unseen_dev11", "unseen_dev12",
                "unseen_train1", "unseen_train2", "unseen_train3", "unseen_train4", "unseen", "unseen_q", "unseen_r",
                "unseen_s", "unseen_t", "unseen_u", "unseen_v", "unseen_x", "unseen_y", "unseen_z", "unseen_w")


def words(text: str) -> list[str]:
    """The tagger's words: runs of letters and digits (with inner ' - .), single other characters, and
    LINE_BREAK for each run of line breaks."""
    return [LINE_BREAK if w[0] == "\n" else w for w in _WORD.findall(text)]


def spans(tags: Sequence[int], begin: int = BT) -> list[tuple[int, int]]:
    """[start, end) word ranges of the phrases tagged `begin` (B-T or B-A) and continued by the I tag after it."""
    out, i = [], 0
    while i < len(tags):
        if tags[i] == begin:
            j = i + 1
            while j < len(tags) and tags[j] == begin + 1:
                j += 1
            out.append((i, j))
            i = j
        else:
            i += 1
    return out


# ----------------------------------------------------------------------------------------------------
# Labels from the generator's truth


def _find(ws: list[str], seq: list[str], lo: int, hi: int, used: set) -> int:
    n = len(seq)
    for i in range(lo, hi - n + 1):
        if all(ws[i + j] == seq[j] for j in range(n)) and not used & set(range(i, i + n)):
            return i
    return -1


def _anchors(t):
    for r in t.relations:
        yield r.anchor
        yield from _anchors(r.anchor)


def label_words(instruction: str, truth) -> tuple[list[str], list[int]] | None:
    """(words, tags) of a generated instruction from its truth TaskChain; None where a goal's words cannot
    be found in order (the example is left out). A phrase is found as written (attributes and head) or,
    failing that, by its head alone; anchors are placed first so a goal's name used as another goal's
    anchor is not taken twice."""
    ws = [w.lower() for w in words(instruction)]
    tags, used, pos = [O] * len(ws), set(), 0
    for sg in truth.subgoals:
        found = []
        for t, kind in [*((a, BA) for a in _anchors(sg.target)), (sg.target, BT)]:
            for text in (t.phrase, t.head):
                i = _find(ws, words(text.lower()), pos if kind == BT else 0, len(ws), used)
                if i >= 0:
                    n = len(words(text.lower()))
                    used |= set(range(i, i + n))
                    found.append((i, n, kind))
                    break
            else:
                if kind == BT:
                    return None
        for i, n, kind in found:
            tags[i : i + n] = [kind] + [kind + 1] * (n - 1)
        pos = max(i + n for i, n, k in found if k == BT)
    return ws, tags


_VALUE = re.compile(r"(\d+(?:\.\d+)?)[a-z]{0,2}")  # digits, and at most two letters glued on ("3.5m", "11.9e")


def word_value(ws: Sequence[str], i: int) -> float | None:
    """The number word i writes in digits ("3.5", "14", or with a unit or compass letter glued on: "3.5m", "11.9e";
    negative after a lone "-" that follows no number), or None. ws: lower-case `words`."""
    m = _VALUE.fullmatch(ws[i])
    if m is None:
        return None
    minus = i > 0 and ws[i - 1] == "-" and (i < 2 or _VALUE.fullmatch(ws[i - 2]) is None)
    return -float(m.group(1)) if minus else float(m.group(1))


def label_axes(ws: Sequence[str], tags: Sequence[int], truth) -> list[int] | None:
    """AXES index per word of a labelled instruction (`label_words`): the number words that write a goal's
    coordinate hint, x then y, between the goal phrases before and after it; None where a hint's numbers are not
    found there once each in digits (spelt out, "three point five", or written "3,5": the example then teaches
    the goal tags alone)."""
    axes = [0] * len(ws)
    goals = spans(tags, BT)
    for k, sg in enumerate(truth.subgoals):
        if sg.location is None:
            continue
        lo = goals[k - 1][1] if k > 0 else 0
        hi = goals[k + 1][0] if k + 1 < len(goals) else len(ws)
        for axis, v in ((1, sg.location.x), (2, sg.location.y)):
            at = [i for i in range(lo, hi) if axes[i] == 0 and (w := word_value(ws, i)) is not None and abs(w - v) < 1e-6]
            if not at:
                return None
            axes[at[0]] = axis
    return axes


@dataclasses.dataclass(frozen=True)
class Fillers:
    """What a goal or anchor phrase is replaced by in augmented examples (`filler_words`)."""

    words: tuple[str, ...]  # whole words of the encoder's vocabulary
    starts: tuple[str, ...] = ()  # word-initial pieces ("cr", "le"); empty: whole words only
    tails: tuple[str, ...] = ()  # continuation pieces, without '##' ("ede", "nza")


def filler_word(rng: np.random.Generator, f: Fillers) -> str:
    """One stand-in name word: a whole vocabulary word, a rare word the encoder splits into two or three pieces
    ("credenza": cr ##ede ##nza), or a hyphenated pair ("night-light"), a third each (whole words only when
    `f` has no pieces). Names of houses nobody fitted on are often rare or hyphenated words; a tagger that met
    only whole-vocabulary stand-ins learns that a word in pieces is never a name."""
    kind = int(rng.integers(0, 3)) if f.starts and f.tails else 0
    if kind == 1:
        return f.starts[rng.integers(len(f.starts))] + "".join(f.tails[k] for k in rng.integers(0, len(f.tails),
                                                                                                  rng.integers(1, 3)))
    pair = kind == 2
    return "-".join(f.words[k] for k in rng.integers(0, len(f.words), 1 + pair))


def augment(ws: list[str], tags: list[int], rng: np.random.Generator, fillers: Fillers) -> list[str]:
    """The words with every tagged phrase replaced by random stand-in words (`filler_word`; one replacement
    per phrase)."""
    out, sub = list(ws), {}
    for begin in (BT, BA):
        for i, j in spans(tags, begin):
            key = " ".join(ws[i:j])
            if key not in sub:
                sub[key] = [filler_word(rng, fillers) for _ in range(j - i)]
            out[i:j] = sub[key]
    return out


def filler_words(tokenizer, pieces: bool = True) -> Fillers:
    """Whole lower-case words of 3-12 letters in the encoder's vocabulary that are not closed-class words and,
    with `pieces`, its word-initial pieces of 2-6 letters and continuation pieces of 2-5 letters."""
    from ragnav_jax.language.lexicon import CLOSED_CLASS

    vocab = tokenizer.get_vocab()
    words = tuple(sorted(w for w in vocab if re.fullmatch("[a-z]{3,12}", w) and w not in CLOSED_CLASS))
    if not pieces:
        return Fillers(words)
    return Fillers(words, tuple(sorted(w for w in vocab if re.fullmatch("[a-z]{2,6}", w))),
                   tuple(sorted(w[2:] for w in vocab if re.fullmatch("##[a-z]{2,5}", w))))


def check_splits(splits: Sequence[str]) -> None:
    """UserError unless every template set is one a tagger may learn from (never the held-out `unseen`)."""
    bad = [s for s in splits if s not in TRAIN_SPLITS]
    if bad:
        raise UserError(f"tagger splits: {bad[0]!r} is not a training template set ({', '.join(TRAIN_SPLITS)})")


def training_examples(cfg, scenes: int, seed: int, splits: Sequence[str] = TRAIN_SPLITS,
                      per_scene: tuple[int, int, int] = (10, 5, 5)) -> list[tuple[list[str], list[int], list[int] | None]]:
    """(words, tags, axes or None) of episodes written with each template set in `splits` over `scenes` seen-split
    houses (`label_words`, `label_axes`)."""
    from ragnav_jax.evaluation.fitting import _seen_scenes
    from ragnav_jax.language.episodes import generate_episodes

    check_splits(splits)
    houses = _seen_scenes(cfg, scenes, seed)
    out = []
    for split in splits:
        ecfg = dataclasses.replace(cfg.episodes, split=split, text=per_scene[0], text_location=per_scene[1],
                                   text_location_sensor=per_scene[2])
        for g in generate_episodes(houses, ecfg, seed):
            got = label_words(g.episode.instruction, g.truth)
            if got is not None:
                out.append((*got, label_axes(*got, g.truth)))
    return out


# ----------------------------------------------------------------------------------------------------
# The model


class Tagger(nn.Module):
    """MiniLM token states (with adapters) -> (B, L, len(TAGS)) tag logits, then (with `axes`) len(AXES) logits of
    the coordinate head: (B, L, len(TAGS) + len(AXES))."""

    shape: BertShape
    lora: int = 8
    axes: bool = True  # the coordinate head (files fitted before round 23 have none)

    @nn.compact
    def __call__(self, ids, train: bool = False):  # ids (B, L) int32, 0 = padding
        h = MiniLM(self.shape, pool=False, lora=self.lora, name="enc")(ids, (ids > 0).astype(jnp.int32))
        h = nn.Dropout(0.1, deterministic=not train)(h)
        out = nn.Dense(len(TAGS), name="tag")(h)
        return jnp.concatenate([out, nn.Dense(len(AXES), name="axis")(h)], -1) if self.axes else out


def head_probs(logits):
    """(..., len(TAGS) [+ len(AXES)]) logits -> the same shape of probabilities, a softmax per head."""
    n = len(TAGS)
    if logits.shape[-1] == n:
        return jax.nn.softmax(logits, -1)
    return jnp.concatenate([jax.nn.softmax(logits[..., :n], -1), jax.nn.softmax(logits[..., n:], -1)], -1)


def _is_trained(path: tuple[str, ...]) -> bool:
    return path[0] in ("tag", "axis") or "_lora_" in path[-2]


def encode_words(tokenizer, wordlists: Sequence[Sequence[str]]) -> tuple[np.ndarray, np.ndarray]:
    """(ids (n, MAX_TOKENS) int32, first (n, MAX_TOKENS) int32) of pre-split word lists: `first` holds, at
    the first token of each word, the word's index, and -1 at every other token."""
    encs = tokenizer.encode_batch([list(w) for w in wordlists], is_pretokenized=True)
    ids = np.zeros((len(encs), MAX_TOKENS), np.int32)
    first = np.full((len(encs), MAX_TOKENS), -1, np.int32)
    for i, e in enumerate(encs):
        n = min(len(e.ids), MAX_TOKENS)
        ids[i, :n] = e.ids[:n]
        prev = None
        for t, w in enumerate(e.word_ids[:n]):
            if w is not None and w != prev:
                first[i, t] = w
            prev = w
    return ids, first


LENGTHS = (32, 64, 96, MAX_TOKENS)  # token-length buckets of the jitted batches


def _length(ids: np.ndarray) -> int:
    return _bucket(int((ids > 0).sum(1).max()), LENGTHS)


@dataclasses.dataclass(frozen=True)
class FitSettings:
    """How the tagger is fitted (`ragnav fit-tagger`)."""

    scenes: int = 8  # seen-split houses drawn for the examples
    seed: int = 4242  # houses, episodes, augmentation, initialisation and batches
    lora: int = 8  # adapter rank
    epochs: int = 3
    batch: int = 16
    lr: float = 1e-3
    augment: float = 1.0  # augmented copies per example (0 = none)
    rare_fillers: bool = True  # stand-ins also rare words in pieces and hyphenated pairs (False: whole words only)


def fit_tagger(cfg, settings: FitSettings = FitSettings(), splits: Sequence[str] = TRAIN_SPLITS,
               progress: bool = False) -> tuple[dict, dict]:
    """Trains the adapters and the head; returns (trained flat params, metadata for the fitted file)."""
    import optax

    base = MiniLMEmbedder()
    rng = np.random.default_rng(settings.seed)
    examples = training_examples(cfg, settings.scenes, settings.seed, splits)
    fillers = filler_words(base.tokenizer, settings.rare_fillers)
    ws = [w for w, _, _ in examples]
    tg = [t for _, t, _ in examples]
    ax = [a if a is not None else [-1] * len(t) for _, t, a in examples]  # -1: not learnt from
    for _ in range(int(settings.augment)):
        ws += [augment(w, t, rng, fillers) for w, t, _ in examples]
        tg += tg[: len(examples)]
        ax += ax[: len(examples)]
    ids, first = encode_words(base.tokenizer, ws)

    def per_token(labels):
        return np.where(first >= 0, np.take_along_axis(_pad_tags(labels), np.maximum(first, 0), 1), -1).astype(np.int32)

    y = np.stack([per_token(tg), per_token(ax)], -1)  # (n, MAX_TOKENS, 2): tag, axis (-1: no loss)
    model = Tagger(base.shape, settings.lora)
    key = jax.random.PRNGKey(settings.seed)
    key, k0 = jax.random.split(key)
    trained, frozen = split_init(model, base, k0, _is_trained, jnp.asarray(ids[:2, :32]))

    def loss_fn(tr, fr, x, t, k):  # the tags' cross-entropy plus the coordinate head's, each over its labelled tokens
        logits = model.apply(join(tr, fr), x, True, rngs={"dropout": k})
        loss = 0.0
        for head, (a, b) in enumerate(((0, len(TAGS)), (len(TAGS), len(TAGS) + len(AXES)))):
            m = t[..., head] >= 0
            ce = optax.softmax_cross_entropy_with_integer_labels(logits[..., a:b], jnp.maximum(t[..., head], 0))
            loss = loss + (ce * m).sum() / jnp.maximum(m.sum(), 1)
        return loss

    def batches():
        order = rng.permutation(len(ids))
        for s in range(0, len(order) - settings.batch + 1, settings.batch):
            b = order[s : s + settings.batch]
            L = _length(ids[b])
            yield ids[b, :L], y[b, :L]

    steps = settings.epochs * (len(ids) // settings.batch)
    trained, losses = train(loss_fn, trained, frozen, batches, steps, settings.lr, key, "fit-tagger", progress)
    meta = {"format": TAGGER_FORMAT, "lora": settings.lora, "tags": list(TAGS), "axes": list(AXES),
            "fitted_on": {"world_split": "seen", "template_sets": list(splits), "scenes": settings.scenes,
                          "seed": settings.seed, "examples": len(examples), "augmented": len(ids) - len(examples),
                          "with_hints": sum(a is not None and 0 < max(a) for _, _, a in examples)},
            "settings": dataclasses.asdict(settings), "final_loss": float(np.mean(losses[-50:])) if losses else None,
            "backend": jax.default_backend()}
    return trained, meta


def _pad_tags(tags: Sequence[Sequence[int]]) -> np.ndarray:
    n = max(len(t) for t in tags)
    out = np.zeros((len(tags), max(n, 1)), np.int32)
    for i, t in enumerate(tags):
        out[i, : len(t)] = t
    return out


# ----------------------------------------------------------------------------------------------------
# The fitted file and inference


def save_tagger(trained: dict, meta: dict, path: str | Path) -> Path:
    """The adapters and head as float32 arrays named by their parameter path, with the metadata as JSON."""
    return save_adapters(trained, meta, path)


def load_tagger_file(path: str | Path) -> tuple[dict, dict]:
    return load_adapters(path, TAGGER_FORMAT, "tagger")


@functools.lru_cache(maxsize=2)
def load_tagger(path: str = "") -> InstructionTagger:
    """The tagger of a fitted file ("" = ragnav_jax/data/tagger.npz), loaded once per process."""
    return InstructionTagger.load(path or None)


class InstructionTagger:
    """The fitted tagger over the installed MiniLM weights; `word_probs` runs fixed-shape jitted batches."""

    def __init__(self, trained: dict, meta: dict, batch_size: int = 32):
        self.base = MiniLMEmbedder()
        self.meta = meta
        self.axes = "axes" in meta
        self.model = Tagger(self.base.shape, int(meta["lora"]), self.axes)
        self.params = join(trained, encoder_params(self.base))
        self.batch_size = batch_size
        self._apply = jax.jit(lambda p, x: head_probs(self.model.apply(p, x)))

    @classmethod
    def load(cls, path: str | Path | None = None) -> InstructionTagger:
        return cls(*load_tagger_file(path or data_path("tagger.npz")))

    def word_probs(self, texts: Sequence[str]) -> list[np.ndarray]:
        """Per text, (n_words, len(TAGS) + len(AXES)) probabilities of `words(text)`: its tags', then the
        coordinate head's (`AXES`; a file without that head gives (n_words, len(TAGS))). Words past the token
        limit: O and none."""
        wl = [words(t) for t in texts]
        ids, first = encode_words(self.base.tokenizer, wl)
        row = np.eye(len(TAGS), dtype=np.float32)[O]
        row = np.concatenate([row, np.eye(len(AXES), dtype=np.float32)[0]]) if self.axes else row
        out = [np.tile(row, (len(w), 1)) for w in wl]
        for s in range(0, len(ids), self.batch_size):
            x = ids[s : s + self.batch_size]
            L = _length(x)
            pad = np.zeros((self.batch_size, L), np.int32)
            pad[: len(x)] = x[:, :L]
            p = np.asarray(self._apply(self.params, jnp.asarray(pad)))
            for r in range(len(x)):
                t = np.nonzero(first[s + r, :L] >= 0)[0]
                out[s + r][first[s + r, t]] = p[r, t]
        return out


# ----------------------------------------------------------------------------------------------------
# Reconciling the parse with the tagger

def fit_conf(tagger: InstructionTagger, cfg, scenes: int, seed: int, splits: Sequence[str] = TRAIN_SPLITS) -> dict:
    """The smallest confidence of adapters.CONF_GRID at which `reconcile` changes at most CONF_CHANGES of the parses
    that read the true goals, on `scenes` seen-split houses of `seed` (not the training houses), episodes of
    the template sets `splits`; with the changes at every grid value."""
    from ragnav_jax.evaluation.fitting import _seen_scenes
    from ragnav_jax.language.episodes import generate_episodes
    from ragnav_jax.language.parser import parse_instruction
    from ragnav_jax.language.types import ParseError

    houses = _seen_scenes(cfg, scenes, seed)
    texts, parses = [], []
    for split in splits:
        for g in generate_episodes(houses, dataclasses.replace(cfg.episodes, split=split), seed):
            try:
                sgs = parse_instruction(g.episode.instruction).subgoals
            except ParseError:
                continue
            if [x.target.head for x in sgs] == [x.target.head for x in g.truth.subgoals]:
                texts.append(g.episode.instruction)
                parses.append(sgs)
    probs = tagger.word_probs(texts)
    conf, changes = fitted_conf(
        lambda c: sum(reconcile(t, sg, p, c)[0] != tuple(sg) for t, sg, p in zip(texts, parses, probs)), len(texts))
    return {"conf": conf, "parses": len(texts), "changes": changes,
            "fitted_on": {"world_split": "seen", "scenes": scenes, "seed": seed, "template_sets": list(splits)}}



def _stem(word: str) -> str:
    """A word as phrases are compared: lower case, no possessive, singular ('sunroom's' -> 'sunroom')."""
    from ragnav_jax.language.parser import _singular

    w = word.lower().removesuffix("'s").removesuffix("\u2019s")
    return _singular(w) if len(w) > 3 else w


def _structure(t, anchors: bool = True) -> set[str]:
    """Every word a parsed target accounts for: head, attributes and (with `anchors`) its anchors', recursively."""
    out = {_stem(w) for x in (t.head, *t.attributes) for w in x.split()}
    for r in t.relations if anchors else ():
        out |= _structure(r.anchor)
    return out


def _without_anchor(t, held: set[str]):
    """The target less every relation, at any depth, whose anchor's head words are all among `held`."""
    rels = tuple(dataclasses.replace(r, anchor=_without_anchor(r.anchor, held)) for r in t.relations
                 if not {_stem(w) for w in r.anchor.head.split()} <= held)
    return t if rels == t.relations else dataclasses.replace(t, relations=rels)


def _without_misread_anchor(t, held: set[str], closed: Collection[str]):
    """The target less every relation, at any depth, whose anchor's head holds all of `held` and a `closed`-class
    word: a misread anchor that swallowed a goal ("the bonsai near 'last repair unto the easel'")."""
    def misread(a) -> bool:
        words = a.head.split()
        return {_stem(w) for w in words} >= held and bool(set(words) & set(closed))

    rels = tuple(dataclasses.replace(r, anchor=_without_misread_anchor(r.anchor, held, closed)) for r in t.relations
                 if not misread(r.anchor))
    return t if rels == t.relations else dataclasses.replace(t, relations=rels)


def _clause_subgoal(instruction: str, i: int, end: int | None, held: set[str]):
    """The subgoal the rule parser reads in the clause from word `i` up to word `end` (the next tagged goal
    phrase; None = the end of the instruction) whose head shares a word with the tagged phrase `held`, or
    None: a goal the tagger found keeps what its own clause says of it (attributes, room, relations,
    sensors, a coordinate hint)."""
    from ragnav_jax.language.parser import parse_instruction
    from ragnav_jax.language.types import ParseError

    at = [m.start() for m in _WORD.finditer(instruction)]
    clause = instruction[at[i] : at[end] if end is not None and end < len(at) else len(instruction)]
    try:
        sgs = parse_instruction(clause).subgoals
    except ParseError:
        return None
    return next((sg for sg in sgs if {_stem(w) for w in sg.target.head.split()} & held), None)


_NUMBER = re.compile(r"(?<![\w.:/])-?\d+(?:\.\d+)?(?![\w:]|\.\d)")
_UNIT = re.compile(r"\s*(?:°|%|deg\b|degrees?\b|celsius|fahrenheit|percent|per cent|ppm|db\b|dba\b|lux\b|kw\b|watts?\b|w\b"
                   r"|kg\b|hpa\b|[cf]\b)", re.IGNORECASE)


def loose_hint(clause: str, used: Sequence[float] = ()):
    """A coordinate hint (x then y) from a goal's clause, up to its first line break: its two numbers, when it
    holds exactly two that carry no unit of a reading and are no value a sensor constraint already reads
    (`used`), in whatever words they are framed ("waypoint 3.5 | 2", "plan position 7.6 E / 7.9 N"); else None."""
    from ragnav_jax.language.types import Location

    line = clause.split("\n", 1)[0]
    nums = [float(m.group()) for m in _NUMBER.finditer(line) if not _UNIT.match(line, m.end())]
    nums = [v for v in nums if all(abs(v - u) > 1e-9 for u in used)]
    return Location(nums[0], nums[1]) if len(nums) == 2 else None


def loose_reading(clause: str, used: Sequence[float] = ()):
    """A sensor constraint from a goal's clause, up to its first line break, that the parser could not read
    ("(the NDVI meter puts it at 0.60 tops)", "temperature-wise: already past 0 degrees"): a reading the lexicon
    names in it (`lexicon.READING_NAMES`; else the one its number's unit implies) and its one number that is no
    coordinate (`used`), compared by the lexicon's comparator phrase nearest that number (one said before a
    number before it, one said after a number after it), or "about" where the clause has none; None unless
    there is exactly one such number and a reading."""
    from ragnav_jax.language import lexicon as L
    from ragnav_jax.language.parser import _alt, _number_words, _sensor
    from ragnav_jax.language.types import ParseError

    line = _number_words(re.sub(r"(?<![\w.])\.(\d)", r"0.\1", clause.split("\n", 1)[0].lower()))
    nums = [m for m in _NUMBER.finditer(line) if all(abs(float(m.group()) - u) > 1e-9 for u in used)]
    if len(nums) != 1:
        return None
    num = nums[0]
    unit = _UNIT.match(line, num.end())
    name = re.search(rf"\b(?:{_alt(L.READING_NAMES)})\b", line)
    if name is None and unit is None:
        return None
    # a comparator phrase before the number ("under 40"), or one written after it ("40 or more")
    cmps = [(num.start() - m.end(), L.COMPARATOR_PHRASES[m.group()])
            for m in re.finditer(rf"\b(?:{_alt(L.COMPARATOR_PHRASES)})(?!\w)", line[: num.start()])]
    cmps += [(m.start(), L.COMPARATOR_POSTFIX[m.group()])
             for m in re.finditer(rf"\b(?:{_alt(L.COMPARATOR_POSTFIX)})(?!\w)", line[num.end():])]
    cmp = min(cmps)[1] if cmps else "approx"
    try:
        return _sensor(L.READING_NAMES[name.group()] if name else None, cmp, num.group(),
                       unit.group().strip() if unit else None, line)
    except ParseError:
        return None


def axis_hint(ws: Sequence[str], probs: np.ndarray, lo: int, hi: int, conf: float = AXIS_CONF):
    """The coordinate hint the tagger's coordinate head reads in words ws[lo:hi]: the number word likeliest
    the x and the one likeliest the y, each above `conf`; None without both (or without the head: probs with
    len(TAGS) columns). probs: (n_words, len(TAGS) + len(AXES)) of `word_probs`."""
    from ragnav_jax.language.types import Location

    if probs.shape[-1] <= AX_Y:
        return None
    best = []
    for col in (AX_X, AX_Y):
        got = [(probs[i, col], i) for i in range(lo, hi) if probs[i, col] > conf and word_value(ws, i) is not None]
        if not got:
            return None
        best.append(word_value(ws, max(got)[1]))
    return Location(*best)


def clause_descriptors(ws: Sequence[str], tags: Sequence[int], lo: int, hi: int, sg,
                       descriptors: Collection[str]) -> tuple[str, ...]:
    """What a goal's clause says of it after its phrase and the parse did not read: the `descriptors` (words
    and states the house's captions describe things by, `caption_descriptors`) among the words `ws[lo:hi]`
    the tagger left untagged, up to the first anchor or line break (a modifier after an anchor is the
    anchor's: "the bin near the freezer (as found: closed)"). ws: lower-case `words`; tags: argmax per word."""
    have = _structure(sg.target) | {_stem(w) for w in (sg.room or "").split()}
    out, i = [], lo
    while i < hi and tags[i] not in (BA, IA) and ws[i] != LINE_BREAK:
        pair = " ".join(ws[i : i + 2]) if i + 1 < hi and tags[i + 1] == O else ""
        for phrase, n in ((pair, 2), (ws[i].replace("-", " "), 1)):
            if phrase and tags[i] == O and phrase in descriptors and not {_stem(w) for w in phrase.split()} <= have:
                out.append(phrase)
                have |= {_stem(w) for w in phrase.split()}
                i += n - 1
                break
        i += 1
    return tuple(out)


_ARTICLES = frozenset({"the", "a", "an"})
_WORD_CHAR = re.compile(r"[a-z0-9]")  # a word, not punctuation


def _relation_words(ws: Sequence[str], lo: int, hi: int, most: int = 6) -> list[str]:
    """The words of ws[lo:hi] that say a relation: after the last punctuation or line break, at most `most` of
    them, less the articles at either end ("in the same quarters as" of ", vintage to look at, in the same
    quarters as the")."""
    run: list[str] = []
    for w in reversed(ws[lo:hi]):
        if not _WORD_CHAR.match(w) or w == LINE_BREAK or len(run) == most:
            break
        run.insert(0, w)
    while run and run[-1] in _ARTICLES:
        run.pop()
    while run and run[0] in _ARTICLES:
        run.pop(0)
    return run


def clause_anchor(ws: Sequence[str], probs: np.ndarray, lo: int, hi: int, named: Collection[str],
                  relation_of: Callable[[Sequence[str]], str]):
    """The relation a goal's clause ws[lo:hi] (after its tagged phrase, up to the next goal's) says of it, or None:
    the first phrase there the tagger finds likelier an anchor's than not, word by word (`ADD_CONF`), before any
    line break, whose last word is a name the house's memory recorded or a name's last word (`named`), with words
    between it and the goal; its relation is the one `relation_of` reads in those words (`_relation_words`)."""
    from ragnav_jax.language.parser import split_noun_phrase
    from ragnav_jax.language.types import Relation, Target

    anchor = probs[:, BA] + probs[:, IA] if len(probs) else np.zeros(0)
    i = lo
    while i < hi and ws[i] != LINE_BREAK and not (anchor[i] > ADD_CONF and probs[i, BA] >= probs[i, IA]):
        i += 1
    while i < hi and ws[i] in _ARTICLES:
        i += 1
    j = i
    while j < hi and anchor[j] > ADD_CONF and (j == i or probs[j, IA] > probs[j, BA]) and _WORD_CHAR.match(ws[j]):
        j += 1
    between = _relation_words(ws, lo, i)
    if j == i or ws[j - 1] not in named or not between:
        return None
    attrs, head = split_noun_phrase(ws[i:j])
    return Relation(relation_of(between), Target(" ".join(ws[i:j]), head, tuple(attrs)))


def reconcile(instruction: str, subgoals: Sequence, probs: np.ndarray, conf: float = 0.9, clauses: bool = False,
              known: Collection[str] = (), descriptors: Collection[str] = (), anchors: bool = True,
              relation_of: Callable[[Sequence[str]], str] | None = None, anchor_conf: float | None = None,
              regroup: bool = False):
    """The parsed subgoals, less the ones the tagger is sure name no goal, plus the goal phrases the tagger
    is sure of and the parse missed; returns (subgoals, dropped phrases, added phrases).

    probs: (n_words, len(TAGS)) of `words(instruction)`. Words are compared by `_stem`. A parsed subgoal
    is the tagger's when a tagged goal phrase shares a word with its head; one no phrase shares a word with
    is dropped when every occurrence of its head's words is O with probability above `conf` (a remark read
    as a goal), unless its head is one of the `known` names or a name's last word (what the house's memory
    calls its objects, "light" of "work light": the memory is evidence the tagger does not have), and when
    every occurrence is an anchor's (B-A or I-A) above `anchor_conf` (default `conf`), known or not (an anchor read
    as a goal of its own: "the bureau, right next door to the magazine rack", "the harp dawdling by the cello (that
    being the one a hop, skip and jump from the music stand)"), or some are above `conf` and the rest are O ("a stride or two
    from the switched-off hi-fi speaker": an anchor's clause). A dropped goal that is only `descriptors`
    gives them, and its room, to the goal before ("the magazine rack, lacquered by the look of it, in the
    library"); a dropped anchor is the anchor (near) of the goal before where the parse gave that one none
    (`anchors`: "the workbench immediately adjoining the work lamp"), its relation the one `relation_of` reads in
    the words between them (`grounding.RelationWords`; near without it). A tagged goal phrase that no kept subgoal
    shares a head word with, every word of it likelier a goal's than not (`ADD_CONF`), is added as a bare
    target (attributes and head split as the parser splits a noun phrase) at its place in the instruction (two
    goals read as one), unless its words are all words some kept subgoal accounts for (an anchor, an
    attribute, a room: "the sunroom's lily" is one goal); where they are only an anchor's and the tagger is
    sure of the phrase above `conf`, the anchor goes and the goal is added ("then the fruit bowl, and bring it
    home with the fish tank"); with `regroup`, likelier a goal's than not is enough where the anchor holding its
    words also holds closed-class words (a misread anchor: "go first unto the bonsai, and at the last repair unto the
    easel", the bonsai's anchor "last repair unto the easel"), and that anchor goes; and a dropped remark that carries
    a reading or a coordinate hint gives it to the goal before where that one has neither, and one that names a room
    its room where it has none ("the appliance (room: garage) with the highest temperature of the lot").

    With `clauses`, an added goal is what the rule parser reads in its own clause (`_clause_subgoal`), falling
    back to the bare target; a goal takes as its coordinate hint the numbers the tagger's coordinate head finds
    likelier a hint's x and y than not (`AXIS_CONF`), from its place (the first goal's: the instruction's start)
    to the next goal's, and a sensor constraint the parse read from them goes (`axis_hint`: "the speaker at
    x=14.7 & y=8.5" is no temperature of 14.7); a goal still without a coordinate hint takes the two numbers its clause (from its
    tagged phrase to the next goal's) leaves unplaced, if any (`loose_hint`); a goal tagged in place and read
    without a reading takes the one its clause says, if any (`loose_reading`); and a goal tagged in place takes
    the `descriptors` (what the house's captions describe things by) its clause says of it after its phrase
    and the parse missed ("the freezer (think lilac)", `clause_descriptors`); and, with `relation_of`, a goal tagged
    in place that the parse gave no relation takes the first anchor its clause names after its phrase, related as
    the words between say (`clause_anchor`: "the record player, vintage to look at, in the same quarters as the
    drum kit"). Everything else is left as parsed: where the two agree on the goals, nothing changes.
    """
    from ragnav_jax.language.lexicon import CLOSED_CLASS, is_room_phrase
    from ragnav_jax.language.parser import split_noun_phrase
    from ragnav_jax.language.types import Relation, Subgoal, Target

    ws = [w.lower() for w in words(instruction)]
    stems = [_stem(w) for w in ws]
    tags = probs[:, : len(TAGS)].argmax(-1) if len(probs) else np.zeros(0, int)
    goals = spans(tags, BT)
    held = [set(stems[i:j]) for i, j in goals]
    sure = [min([probs[i, BT]] + [probs[k, IT] for k in range(i + 1, j)]) > ADD_CONF for i, j in goals]
    kept, where, ends, dropped, added, taken = [], [], [], [], [], set()
    named = set(known) | {n.split()[-1] for n in known}  # a name the memory recorded, or its last word ("light")
    for sg in subgoals:
        head = {_stem(w) for w in sg.target.head.split()}
        ks = [k for k in range(len(goals)) if head & held[k]]
        if not ks:
            occ = [n for n, w in enumerate(stems) if w in head]
            anchor = [probs[n, BA] + probs[n, IA] > conf for n in occ]
            likely = [probs[n, BA] + probs[n, IA] > (conf if anchor_conf is None else anchor_conf) for n in occ]
            if occ and (all(probs[n, O] > conf for n in occ) and sg.target.head not in named or all(likely)
                        or any(anchor) and all(probs[n, O] + probs[n, BA] + probs[n, IA] > conf for n in occ)):
                dropped.append(sg.target.phrase)
                if (kept and set(sg.target.head.split()) <= set(descriptors) and not (sg.sensors or sg.location)
                        and (sg.room is None or kept[-1].room in (None, sg.room))):
                    # words the house's captions describe things by, and the room said with them, are the goal
                    # before's ("the magazine rack, lacquered by the look of it, in the library")
                    t = kept[-1].target
                    kept[-1] = dataclasses.replace(kept[-1], room=kept[-1].room or sg.room, target=dataclasses.replace(
                        t, attributes=t.attributes + (sg.target.head,), phrase=f"{sg.target.head} {t.phrase}"))
                elif anchors and kept and any(likely) and not kept[-1].target.relations:
                    # an anchor read as a goal of its own is the anchor of the goal before, which the parse left
                    # without one: the relation's words were new to it ("the workbench immediately adjoining the
                    # work lamp"): the relation is the one the words between say, read by `relation_of`, else near
                    t, lo = kept[-1].target, ends[-1] if ends[-1] is not None else where[-1] + 1
                    kind = relation_of(_relation_words(ws, lo, occ[0])) if relation_of is not None and occ else "near"
                    kept[-1] = dataclasses.replace(kept[-1], target=dataclasses.replace(
                        t, relations=(Relation(kind, sg.target),)))
                elif regroup and kept:
                    # a remark that carries a reading or a coordinate hint gives it to the goal before, and one that
                    # names a room its room, where that one has none ("the appliance (room: garage) with the highest
                    # temperature of the lot": the parse's goals "garage" and "lot")
                    before = kept[-1]
                    if (sg.sensors or sg.location) and not (before.sensors or before.location):
                        before = dataclasses.replace(before, sensors=sg.sensors, location=sg.location)
                    if before.room is None and is_room_phrase(sg.target.head.split()) and not sg.target.relations:
                        before = dataclasses.replace(before, room=sg.target.head)
                    kept[-1] = before
                continue
            where.append(occ[0] if occ else 0)
            ends.append(None)
        elif all(k in taken for k in ks):  # its words' tagged phrase is another goal's ("riddle sheet ...", then
            # "or the riddle won't work"): it stands where its words next occur, with no tagged phrase of its own
            after = max(where, default=0)
            where.append(next((n for n, w in enumerate(stems) if n > after and w in head), goals[ks[0]][0]))
            ends.append(None)
        else:
            k = next(k for k in ks if k not in taken)
            taken.add(k)
            (i, j), last = goals[k], _stem(sg.target.head.split()[-1])
            where.append(i)
            # the goal's phrase ends at its head's last word where the tagger cut it short ("recycling/B-T bin/I-A")
            ends.append(next((n + 1 for n in range(j, min(len(stems), j + 2)) if stems[n] == last), j))
        kept.append(sg)
    accounted = set().union(*(_structure(sg.target) | {_stem(w) for w in (sg.room or "").split()} for sg in kept))
    own = set().union(*(_structure(sg.target, anchors=False) | {_stem(w) for w in (sg.room or "").split()}
                        for sg in kept))
    for k, (i, j) in enumerate(goals):
        if k in taken or not sure[k]:
            continue
        if held[k] <= accounted:
            if held[k] <= own:
                continue
            # a phrase the parse made an anchor of and the tagger is sure is a goal is one ("... then the fruit
            # bowl, and bring it home with the fish tank"): the anchor goes, the goal is added; only where the
            # goal holding the anchor is one the tagger found too, and no misreading ("clients arrive could you
            # check on the tumble dryer", "coins are stashed at the harp"), which grounding replaces by its anchor.
            # With `regroup`, a phrase likelier a goal's than not (`sure`) inside an anchor that holds
            # closed-class words is one too, and that anchor goes ("go first unto the bonsai, and at the last
            # repair unto the easel": the bonsai's anchor "last repair unto the easel")
            less, misread = kept, False
            if min([probs[i, BT]] + [probs[n, IT] for n in range(i + 1, j)]) > conf:
                less = [dataclasses.replace(sg, target=_without_anchor(sg.target, held[k])) for sg in kept]
            if less == kept and regroup:
                less = [dataclasses.replace(sg, target=_without_misread_anchor(sg.target, held[k], CLOSED_CLASS))
                        for sg in kept]
                misread = True
            # the goals that lose their own anchor (a misread anchor: only a top-level one) must be no misreading
            lose = [len(a.target.relations) != len(b.target.relations) if misread else a != b for a, b in zip(less, kept)]
            if less == kept or any(x and (e is None or set(b.target.head.split()) & CLOSED_CLASS)
                                   for x, b, e in zip(lose, kept, ends)):
                continue
            kept = less
        phrase = " ".join(ws[i:j])
        added.append(phrase)
        nxt = goals[k + 1][0] if k + 1 < len(goals) else None
        sg = _clause_subgoal(instruction, i, nxt, held[k]) if clauses else None
        if sg is None:
            attrs, head = split_noun_phrase(ws[i:j])
            sg = Subgoal(0, Target(phrase, head, tuple(attrs)), text=phrase)
        kept.append(sg)
        where.append(i)
        ends.append(j)
    order = sorted(range(len(kept)), key=lambda n: (where[n], n))
    hinted = False
    if clauses:  # a goal read without a coordinate hint takes two numbers its own clause leaves unplaced
        at = [m.start() for m in _WORD.finditer(instruction)] + [len(instruction)]
        starts = [min(where[n], len(at) - 1) for n in order] + [len(at) - 1]
        for pos, n in enumerate(order):
            clause = instruction[at[starts[pos]] : at[max(starts[pos], starts[pos + 1])]]
            # the numbers the coordinate head reads as a hint's, from the goal's place (the first goal's: the
            # instruction's start) to the next goal's, are its hint, and no reading's value
            loc = axis_hint(ws, probs, 0 if pos == 0 else starts[pos], starts[pos + 1])
            if loc is not None:
                sensors = tuple(c for c in kept[n].sensors
                                if c.value is None or min(abs(c.value - loc.x), abs(c.value - loc.y)) > 1e-9)
                if (loc, sensors) != (kept[n].location, kept[n].sensors):
                    kept[n], hinted = dataclasses.replace(kept[n], location=loc, sensors=sensors), True
            if kept[n].location is None:
                used = [c.value for c in kept[n].sensors if c.value is not None]
                loc = loose_hint(clause, used)
                if loc is not None:
                    kept[n], hinted = dataclasses.replace(kept[n], location=loc), True
            if not kept[n].sensors and ends[n] is not None:  # and a reading the clause of a goal tagged in place says
                loc = kept[n].location
                reading = loose_reading(clause, (loc.x, loc.y) if loc is not None else ())
                if reading is not None:
                    kept[n], hinted = dataclasses.replace(kept[n], sensors=(reading,)), True
        for pos, n in enumerate(order):  # and the descriptors its clause says of it after its phrase
            if ends[n] is not None and descriptors:
                more = clause_descriptors(ws, tags, ends[n], max(ends[n], starts[pos + 1]), kept[n], descriptors)
                if more:
                    t = kept[n].target
                    kept[n], hinted = dataclasses.replace(kept[n], target=dataclasses.replace(
                        t, attributes=t.attributes + more, phrase=" ".join([*more, t.phrase]))), True
            if ends[n] is not None and relation_of is not None and not kept[n].target.relations:
                rel = clause_anchor(ws, probs, ends[n], max(ends[n], starts[pos + 1]), named, relation_of)
                if rel is not None:
                    kept[n], hinted = dataclasses.replace(kept[n], target=dataclasses.replace(
                        kept[n].target, relations=(rel,))), True
    if not dropped and not added and not hinted:
        return tuple(subgoals), (), ()
    out = tuple(dataclasses.replace(kept[n], index=m) for m, n in enumerate(order))
    return out, tuple(dropped), tuple(added)
