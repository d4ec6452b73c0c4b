"""Grounding parsed goals in what the memory knows: repair misread heads, drop remarks read as goals.

    subgoals, dropped = ground_subgoals(verifier, subgoals, vocab)   # vocab: every name the memory recorded

The rule parser is written beside the sentences it has met; a new author's phrasing makes it misread in
two typical ways: words around a goal end up in its head ("the chest freezer a visit" from "pay the chest
freezer a visit", "condition of the shelf unit" from "verify the condition of the shelf unit", "up" from
"finish up by tracking down the bonsai tree"), and a remark becomes a goal of its own ("suits you" from
"in whatever order suits you", "s fine" from "any order's fine"). Both are visible before the robot moves,
against the memory of the house:

- a head that contains a closed-class word (`lexicon.CLOSED_CLASS`: articles, pronouns, prepositions,
  auxiliaries, number words; names hold none but 'of' and 'and') is a misreading: it is replaced by the run
  of content words, taken from the head and then from the subgoal's source span (less its anchors' and
  room's words), that fits a recorded name best (a name itself scores 1) when that fit reaches
  `tau_ground` (fitted on the seen split: a goal's head against the other words of seen-template
  instructions, `fitting.ground_rows`) and beats the head's own; a head no recorded name reaches
  (cosine below the verifier's `tau_head`) is replaced likewise by a run of its own words.
  A misread head's name is looked for in its first run of words first: a noun phrase's head comes before
  what modifies it ("the cello close of the shelving unit" is the cello);
- a misread head below `tau_head` with no such run names nothing the memory knows (a remark, an aside).
  Where it is placed against an object the memory knows ("thy trial awaits at the spider plant", "on my
  way to the shelf unit"; not "in", what holds it), that object is the goal; otherwise the goal is dropped
  and reported (`ungrounded` in the episode rows);
- a head of content words is a remark ("Applicant: Household Services Unit", "Psst, treasure hunter!", "back
  to the studio") when the goal has nothing but its name and that name fits the recorded ones worse than 99%
  of the seen goals' and anchors' heads do (`tau_bare`, fitted on the seen split: 0.56 with MiniLM, 0.2 with
  the hashing embedder, for which a plural is as far from a name as a remark is); with a room, relations,
  readings or a coordinate hint it need only pass the name check (`tau_head`). Such a head is first repaired
  to its first words when they ground ("freezer flush" from "the freezer flush next to ..."), never to its
  last ("unit" of "Household Services Unit"). A goal measured by a sensor keeps such a head: a word the house
  never uses for what it names ("the appliance in the pantry at about 21 °C"), which the verifier checks by
  the names that fit it best. The price: a goal the memory never recorded under any near name
  is dropped too (an object the exploration missed, or one added since); `tau_bare=0` in a fitted file turns
  the rule off (tests/test_eval.py does so for a synthetic memory that never saw the sofa);
- a goal that is only words the memory describes things with and names nothing by ("the amp, retro" read
  as a goal "retro") gives them to the goal before it as attributes, and its room if that goal has none
  ("the bean bag, turquoise by the look of it, in the games room"), and a goal dropped as a remark gives the
  goal before it such words it holds ("the chaise longue, answering the description lilac"); one that is only
  a room name the memory's names do not reach ("... (open) in the nursery" read as a goal "nursery") gives it
  to the goal before it as its room;
- a goal takes the words its span says of it after its name that the house's captions describe things by
  (`after_name`, `eval.ground_described`): "the work light described as teal", "the fruit bowl in an empty
  state", "the sofa (the teal wool variety)", "the snake plant described as glazed" (a caption's "in a glazed
  planter"), and, where it has no room, the room named there ("whose berth is the laundry room"), up to the
  next run of words that names a recorded object, whose modifiers are its own ("sharing quarters with the
  turquoise shelving unit"); a relation "in" a frame no name reaches ("in a closed state") gives its words to
  the goal and goes;
- an attribute is dropped when it is only closed-class words, or when it is no descriptive word the
  lexicon knows (`lexicon.is_modifier`: colours, materials, conditions) and no caption of the house's
  memory ever said it ('required' from "no further action is required", 'noted', 'requested');
- an anchor must name something (`ground_relations`): one with a number in it is a coordinate ("at easting 4.5")
  and goes, one with a closed-class word ("by the look of it") is repaired to the recorded name in it or goes;
  inside something the memory never named is a room ("in the bakehouse"), the room word it starts with where
  words follow ("in the sunroom whose NDVI is the lowest going"), and no room where it is an adverb ("walk it
  in exactly").

A head the memory used itself, or one that reaches `tau_head` and holds no closed-class word, is left as
parsed: the step changes nothing that the parser read correctly. Nothing here reads the scene's true
categories: only the parse and the names the memory's captioner used.
"""

from __future__ import annotations

import dataclasses
import re
from collections.abc import Collection, Sequence

import numpy as np

from ragnav_jax.evaluation.verify import Perceived, descriptors, recorded, said, vocabulary
from ragnav_jax.language.episodes import NEAR_TYPES
from ragnav_jax.language.lexicon import (
    CLOSED_CLASS,
    RELATION_PHRASES,
    ROOM_RELATION_WORDS,
    SAME_STATES,
    is_modifier,
    is_room_phrase,
)
from ragnav_jax.language.types import Subgoal, Target

MAX_SPAN = 4  # longest run of words tried as a head
NAME_LINKS = frozenset({"of", "and"})
_WORD = re.compile(r"[a-z0-9]+(?:[-'][a-z0-9]+)*")
_NUMBER = re.compile(r"^\d+(?:[.,]\d+)?$")
_NUMBER_IN = re.compile(r"\d")


def _closed(word: str) -> bool:
    return word in CLOSED_CLASS or bool(_NUMBER.match(word))


def content_runs(text: str) -> list[tuple[str, ...]]:
    """The maximal runs of content words of a text, in order ('pay the chest freezer a visit' ->
    [('pay',), ('chest', 'freezer'), ('visit',)])."""
    runs, cur = [], []
    for w in _WORD.findall(text.lower().replace("\u2019", "'")):
        if _closed(w):
            if cur:
                runs.append(tuple(cur))
            cur = []
        else:
            cur.append(w)
    if cur:
        runs.append(tuple(cur))
    return runs


def candidate_heads(text: str, max_len: int = MAX_SPAN) -> list[str]:
    """Every contiguous piece of at most max_len words of each content run, in order of appearance."""
    out = []
    for run in content_runs(text):
        for i in range(len(run)):
            for j in range(i + 1, min(len(run), i + max_len) + 1):
                out.append(" ".join(run[i:j]))
    return list(dict.fromkeys(out))


def _closed_in(head: str) -> bool:
    """The head holds a closed-class word that no object's name holds ('of' and 'and' join the nouns of
    names: 'chest of drawers', 'salt and pepper mill')."""
    return any(_closed(w) and w not in NAME_LINKS for w in _WORD.findall(head))


def name_fit(verifier, pieces: Sequence[str], vocab: Sequence[str]) -> np.ndarray:
    """(len(pieces),) how well each piece fits the best recorded name: 1 for a name itself, else the cosine."""
    if not len(pieces):
        return np.zeros(0)
    vset = set(vocab)
    return np.where([p in vset for p in pieces], 1.0, verifier.cos(list(pieces), list(vocab)).max(1))


def _best(verifier, pieces: Sequence[str], vocab: Sequence[str]) -> tuple[str | None, float]:
    """The piece that fits a recorded name best (ties: the longer, then the earlier), with its score."""
    if not pieces:
        return None, -1.0
    fit = name_fit(verifier, pieces, vocab)
    i = max(range(len(pieces)), key=lambda k: (round(float(fit[k]), 6), len(pieces[k].split()), -k))
    return pieces[i], float(fit[i])


def ground_relations(verifier, rels: Sequence, vocab: Sequence[str]) -> tuple:
    """Relations whose anchors name something: an anchor head with a number in it is a coordinate read as an
    object ("at easting 4.5, northing 0.4") and goes; one with a closed-class word is a misreading ("by the look
    of it", "within arm's length of the easel") and is repaired to its run of content words that fits a recorded
    name best (`tau_ground`, as heads are), or goes."""
    out = []
    for r in rels:
        a = r.anchor
        if _NUMBER_IN.search(a.head):
            continue
        if _closed_in(a.head):
            best, score = _best(verifier, candidate_heads(a.phrase), vocab)
            if score < verifier.p.tau_ground:
                continue
            r = dataclasses.replace(r, anchor=dataclasses.replace(a, head=best, phrase=best))
        out.append(r)
    return tuple(out)


def ground_subgoal(verifier, sg: Subgoal, vocab: Sequence[str], captions: str | None = None) -> Subgoal | None:
    """The subgoal with its head repaired against the memory's names (module docstring), or None when
    nothing in it names anything the memory knows. vocab: every name the memory recorded (lower case);
    captions: everything the memory's captions said, lower case (None: attributes are not checked)."""
    t, p = sg.target, verifier.p
    attrs = tuple(a for a in t.attributes if not all(_closed(w) for w in _WORD.findall(a))
                  and (captions is None or said(a, captions) or all(is_modifier(w) for w in a.split())))
    head = t.head
    fit, misread = float(name_fit(verifier, [head], vocab)[0]), _closed_in(head)
    # a misread head must pass the name check (tau_head); one of content words with nothing else to it must name a
    # recorded object as 99% of the seen goals' names do (tau_bare), with a room, relations, readings or a
    # coordinate hint it need only pass the name check (and never more than tau_bare)
    bare = not (t.relations or sg.room or sg.location or sg.sensors)
    floor = p.tau_head if misread else p.tau_bare if bare else min(p.tau_head, p.tau_bare)
    if fit < 1.0 and (fit < floor or misread):
        # a head of content words is repaired only to its first words: the parser's misreading runs on past the
        # name ("the freezer flush next to ..." -> "freezer flush"), and a title's last word is no name of its own
        # ("Household Services Unit" is no shelf unit)
        words = head.split()
        best, score = _best(verifier, candidate_heads(head) if misread else
                            [" ".join(words[:k]) for k in range(1, len(words))], vocab)
        runs = content_runs(head)
        if misread and len(runs) > 1:  # a noun phrase's head comes before what modifies it ("the cello close of
            # the shelving unit", "the tool chest from the garage"): a name in the first run of words wins
            first, fs = _best(verifier, candidate_heads(" ".join(runs[0])), vocab)
            if fs >= p.tau_ground:
                best, score = first, fs
        if score < p.tau_ground and misread:  # nothing in the head: the words around it in its span, less
            # those of its anchors and room (another object's name there is not this goal's)
            taken = set(_WORD.findall(" ".join([sg.room or "", *_anchor_phrases(t)])))
            best, score = _best(verifier, [x for x in candidate_heads(sg.text) if not set(x.split()) & taken], vocab)
        if score >= p.tau_ground and score > fit:
            head = best
        elif fit < floor:
            # names nothing the memory knows: a remark, a title, a heading or a term of address; where it is
            # placed against something the memory knows ("thy trial awaits at the spider plant", "on my way
            # to the shelf unit"), that is the goal (not what holds it: "the relics hidden in this house")
            for r in (r for r in t.relations if r.type not in ("in", "in_room_with")):
                g = ground_subgoal(verifier, dataclasses.replace(sg, target=r.anchor), vocab, captions)
                if g is not None:
                    return g
            if misread or not sg.sensors:
                return None
            # a goal measured by a sensor keeps a head of content words no recorded name reaches, a word the house
            # never uses for what it names ("the appliance in the pantry at about 21 °C"): the verifier checks it
            # by the names that fit it best (`Verifier.verdicts`)
    rels, room = ground_relations(verifier, t.relations, vocab), sg.room
    inside = [r for r in rels if r.type == "in" and not r.anchor.relations and not r.anchor.attributes]
    if room is None and inside and float(name_fit(verifier, [inside[0].anchor.head], vocab)[0]) < p.tau_head:
        # "in the bakehouse": inside something the memory never named is a room whose name the parser lacks; a room
        # name and words after it are the room ("in the sunroom whose NDVI is the lowest going"), an adverb or words
        # no name holds are none ("walk it in exactly")
        words = inside[0].anchor.phrase.split()
        lead = next((words[:k] for k in range(len(words), 0, -1) if is_room_phrase(words[:k]) and words[:k] != ["room"]),
                    None)  # ("room" alone names none: "in the room occupied by the rack")
        if lead is not None or not (_closed_in(inside[0].anchor.phrase) or words[-1].endswith("ly")):
            room = " ".join(lead) if lead is not None else inside[0].anchor.phrase
        rels = tuple(r for r in rels if r is not inside[0])
    if head == t.head and attrs == t.attributes and room == sg.room and rels == t.relations:
        return sg
    pre = t.phrase[: -len(t.head)] if t.phrase.endswith(t.head) else " ".join(attrs)
    gone = {w for a in t.attributes if a not in attrs for w in a.split()}
    phrase = " ".join([w for w in pre.split() if not _closed(w) and w not in gone] + [head])
    return dataclasses.replace(sg, room=room, target=dataclasses.replace(t, phrase=phrase, head=head, attributes=attrs,
                                                                         relations=rels))


def _anchor_phrases(t: Target) -> list[str]:
    return [x for r in t.relations for x in (r.anchor.phrase, *_anchor_phrases(r.anchor))]


def _described(phrase: str, descriptors: Collection[str]) -> bool:
    """The phrase is a word or state the house's captions describe things by, or a state said the same way
    (`lexicon.SAME_STATES`: "powered off" where the captions say "switched off")."""
    return phrase in descriptors or any(x in descriptors for x in SAME_STATES.get(phrase, ()))


def after_name(verifier, sg: Subgoal, vocab: Sequence[str], descriptors: Collection[str]) -> tuple[tuple[str, ...], str | None]:
    """What a goal's span says of it after its name and the parse did not read: (describing words, room or None).

    Read from the words after the head up to the next run of words that names a recorded object (what follows
    is that object's: "sharing quarters with the turquoise shelving unit"): the `descriptors` (words and states
    the house's captions describe things by) and, where the goal has no room, the first room name
    (`lexicon.is_room_phrase`: "whose berth is the laundry room", "somewhere in the garage"). A describing word
    followed by a run of content words is that run's when the run names a recorded object (`tau_ground`, as a
    misread head's words must) and the goal's own otherwise, a frame noun ("described as teal", "in a closed
    state", "of the ivory kind", "(the teal wool variety)"). Words of the head, its attributes, its anchors (but
    frames: `_frames`) and its room are never taken; nothing before the head is (the parser reads modifiers
    there)."""
    t = sg.target
    ws = [w.strip("'") for w in _WORD.findall(sg.text.lower().replace("\u2019", "'"))]
    head = _WORD.findall(t.head.lower())
    at = next((i + len(head) for i in range(len(ws) - len(head), -1, -1)
               if head and ws[i : i + len(head)] == head), None)  # the head's last mention: the name itself
    if at is None:
        return (), None
    frames = _frames(verifier, t, vocab)
    anchors = [x for r in t.relations if r not in frames for x in (r.anchor.phrase, *_anchor_phrases(r.anchor))]
    have = {w for x in (t.head, *t.attributes, *anchors, sg.room or "") for w in _WORD.findall(x)}
    have |= {w for a in t.attributes for x in SAME_STATES.get(a, ()) for w in x.split()}

    def names_something(run: Sequence[str]) -> bool:
        return bool(run) and _best(verifier, candidate_heads(" ".join(run)), vocab)[1] >= verifier.p.tau_ground

    out, room, i = [], None, at
    while i < len(ws):
        pair = " ".join(ws[i : i + 2]).replace("-", " ") if i + 1 < len(ws) else ""
        one = ws[i].replace("-", " ")
        phrase = pair if pair and _described(pair, descriptors) else one if _described(one, descriptors) else None
        if phrase is None:
            run = _run_from(ws, i)
            named = _room_name(run)
            if named and sg.room is None and room is None and not set(named) & have:
                room, i = " ".join(named), i + len(named)
                continue
            if run and names_something(run):
                break  # another object's name: what follows is its
            i += 1
            continue
        j = i + len(phrase.split())
        while j < len(ws) and (_closed(ws[j]) or _described(ws[j].replace("-", " "), descriptors)):
            j += 1  # past the other describing words ("the teal wool variety")
        if names_something(_run_from(ws, j)):
            break  # a modifier of the object named next
        if not set(phrase.split()) <= have:
            out.append(phrase)
            have |= set(phrase.split())
        i += len(phrase.split())
    return tuple(out), room


def _frames(verifier, t: Target, vocab: Sequence[str]) -> tuple:
    """t's relations "in" something no recorded name reaches (`tau_ground`): a frame read as a container ("in a
    closed state", "in an empty state"), whose describing words are the goal's."""
    return tuple(r for r in t.relations if r.type == "in" and not r.anchor.relations
                 and float(name_fit(verifier, [r.anchor.head], vocab)[0]) < verifier.p.tau_ground)


class RelationWords:
    """The relation a run of words says where the parser does not know them ("cheek by jowl with", "in the same
    quarters as", "bunking with"): the type of the lexicon's relation phrase (`lexicon.RELATION_PHRASES`, the
    seen words) nearest them through the encoder, among the types the check tells apart (`CHECKED`); near where
    there are no words. Called with the words between a goal and an anchor the tagger found for it
    (`tagger.reconcile`). Nothing is fitted: on the relations of thirteen development sets (Q to AC; 2,269, the
    words between each goal and its anchor as written) the nearest phrase's type is the check's for 92% (near
    97%, the same room 98%, with 67%; on, 29 of them, it never reads)."""

    CHECKED = (*NEAR_TYPES, "with", "in_room_with")  # not "on": one thing on another is near it, and a "with" read as
    # "on" turns the relation round ("the workbench carrying the soldering station")

    def __init__(self, verifier):
        self.verifier = verifier
        self.phrases = sorted(p for p, t in RELATION_PHRASES.items() if t in self.CHECKED)

    def __call__(self, words: Sequence[str]) -> str:
        text = " ".join(words).strip()
        if not text:
            return "near"
        return RELATION_PHRASES[self.phrases[int(np.argmax(self.verifier.cos([text], self.phrases)[0]))]]


def _room_name(run: Sequence[str]) -> tuple[str, ...] | None:
    """The longest start of a run of words that names a room ("laundry room" of "laundry room today"), or None:
    "room" alone names none, nor does a relation's "same room" or "next room"."""
    return next((tuple(run[:k]) for k in range(len(run), 0, -1) if is_room_phrase(run[:k]) and tuple(run[:k]) != ("room",)
                 and not set(run[: k - 1]) & ROOM_RELATION_WORDS), None)


def _run_from(ws: Sequence[str], i: int) -> tuple[str, ...]:
    """The run of content words starting at ws[i] (empty when ws[i] is closed-class or past the end)."""
    run = []
    while i < len(ws) and not _closed(ws[i]):
        run.append(ws[i])
        i += 1
    return tuple(run)


def ground_subgoals(verifier, subgoals: Sequence[Subgoal], vocab: Sequence[str], captions: str | None = None,
                    descriptors: Collection[str] = (), described: bool = False) -> tuple[tuple[Subgoal, ...], tuple[str, ...]]:
    """Every subgoal grounded (`ground_subgoal`); returns (kept subgoals, phrases of the dropped ones).
    descriptors: the words the house's captions describe things by (`caption_descriptors`), which a remark
    dropped gives the goal before it, and (described) each kept goal those its span says of it after its name,
    and the room it names there where it has none (`after_name`)."""
    if not vocab:
        return tuple(subgoals), ()
    kept, dropped = [], []
    names = {w for n in vocab for w in _WORD.findall(n)}
    for sg in subgoals:
        t = sg.target
        if (captions is not None and not (sg.location or sg.sensors) and t.head not in vocab
                and all(said(w, captions) and w not in names for w in _WORD.findall(t.head))
                and not ground_relations(verifier, t.relations, vocab)):
            # "the amp, retro": words the memory describes things with but names nothing by describe the goal
            # before, and so does the room said with them ("the bean bag, turquoise by the look of it, in the
            # games room") unless that goal has another
            if kept and (sg.room is None or kept[-1].room in (None, sg.room)):
                prev = kept[-1].target
                attrs = prev.attributes + tuple(a for a in (*t.attributes, t.head) if a not in prev.attributes)
                kept[-1] = dataclasses.replace(kept[-1], target=dataclasses.replace(prev, attributes=attrs),
                                               room=kept[-1].room or sg.room)
            else:
                dropped.append(t.phrase)
            continue
        if (is_room_phrase(t.head.split()) and not (t.relations or sg.location or sg.sensors)
                and float(name_fit(verifier, [t.head], vocab)[0]) < verifier.p.tau_head):
            # "the toy chest (open) in the nursery" read as a goal called "nursery": a room is where the goal
            # before it is, not an object to find
            if kept and kept[-1].room is None:
                kept[-1] = dataclasses.replace(kept[-1], room=t.head)
            else:
                dropped.append(t.phrase)
            continue
        g = ground_subgoal(verifier, sg, vocab, captions)
        if g is None:
            dropped.append(sg.target.phrase)
            if kept:  # a remark's describing words describe the goal before it ("the chaise longue, answering the
                # description lilac": the remark "description lilac" goes, lilac stays)
                prev = kept[-1].target
                said_here = [w for x in (*t.attributes, t.head) for w in _WORD.findall(x)
                             if w in descriptors and w not in names and w not in prev.attributes]
                if said_here:
                    kept[-1] = dataclasses.replace(kept[-1], target=dataclasses.replace(
                        prev, attributes=prev.attributes + tuple(dict.fromkeys(said_here))))
        else:
            more, room = after_name(verifier, g, vocab, descriptors) if described else ((), None)
            if more:  # and a frame whose words they were is no relation ("in a full state")
                t = g.target
                gone = [r for r in _frames(verifier, t, vocab) if set(r.anchor.attributes) <= set(t.attributes + more)]
                g = dataclasses.replace(g, target=dataclasses.replace(
                    t, attributes=t.attributes + more, phrase=" ".join([*more, t.phrase]),
                    relations=tuple(r for r in t.relations if r not in gone)))
            if room is not None:
                g = dataclasses.replace(g, room=room)
            kept.append(g)
    return tuple(kept), tuple(dropped)


_STATE_CLAUSE = re.compile(r"\bthat is ([a-z]+(?: on| off)?)\b")


def caption_descriptors(name_of: dict[str, str]) -> frozenset[str]:
    """The words and states a house's captions describe its objects by: from each caption phrase and the name
    it gave ('lacquered ivory shelf unit' -> shelf unit), the words before the name, the state after "that
    is" ("a drying rack that is full", "switched on") and the words of what holds it ("in a glazed planter"),
    less closed-class words, numbers, readings and the words of the names. Only what the captioner said."""
    out, names = set(), {w for n in name_of.values() for w in _WORD.findall(n.lower())}
    for phrase, name in name_of.items():
        low = phrase.lower()
        at = low.find(name)
        if at > 0:
            out.update(w for w in _WORD.findall(low[:at]) if not _closed(w))
        out.update(m.group(1) for m in _STATE_CLAUSE.finditer(low[at + len(name):] if at >= 0 else low))
        chunks = descriptors(Perceived(name, low)) if at >= 0 else ()
        out.update(w for c in chunks if not _NUMBER_IN.search(c) and c not in SAME_STATES for w in _WORD.findall(c)
                   if w not in names)
    return frozenset(w for w in out if not _closed(w))


class MemoryGrounder:
    """`ground_subgoals` against each scene's memory, as the `ground` hook of goal_items / prepare_batch:
    grounder(episode, subgoals) -> subgoals, each (scene, parse) grounded once. `dropped[episode id]`
    keeps the phrases it dropped."""

    def __init__(self, verifier, bank, scenes, described: bool = True):
        by_name = {s.name: s for s in scenes}
        self.verifier, self.described, self.dropped, self._done = verifier, described, {}, {}
        rec = {m.scene: recorded(m, by_name[m.scene]) for m in bank.metas if m.scene in by_name}
        self.vocab = {k: vocabulary(names) for k, (names, _) in rec.items()}
        self.descriptors = {k: caption_descriptors(name_of) for k, (_, name_of) in rec.items()}
        self.captions = {m.scene: " | ".join(c.lower() for c in m.captions) for m in bank.metas}

    def __call__(self, ep, subgoals):
        key = (ep.scene, subgoals)
        if key not in self._done:
            self._done[key] = ground_subgoals(self.verifier, subgoals, self.vocab.get(ep.scene, ()),
                                              self.captions.get(ep.scene), self.descriptors.get(ep.scene, ()),
                                              self.described)
        kept, dropped = self._done[key]
        if dropped:
            self.dropped[ep.id] = dropped
        return kept


def _comparison(sg: Subgoal) -> str:
    """A goal's sensor constraints and name as the rows show them ("tool, temperature_c max")."""
    parts = [" ".join(str(x) for x in (c.reading, c.comparator, c.value) if x is not None) for c in sg.sensors]
    return ", ".join([sg.target.head, *parts])


class SensorReading:
    """Each goal's sensor comparison read again by the learned reader (`language/sensor_reader.py: revise`) after
    `inner` (the tagger and the memory grounder, whichever are on) has read and grounded the goals, so a remark
    grounding drops is never given one ("the sampling points below may be visited" is no least-NDVI goal): a
    `ground` hook of goal_items / prepare_batch. What `inner` dropped, added and reads alone passes through;
    `revised[episode id]` names each goal it changed, "text: before -> after" (the rows' `revised`)."""

    def __init__(self, reader, conf: float, inner=None):
        self.reader, self.conf, self.inner, self.revised = reader, conf, inner, {}

    dropped = property(lambda self: getattr(self.inner, "dropped", {}))
    added = property(lambda self: getattr(self.inner, "added", {}))

    def _revise(self, ep, subgoals):
        from ragnav_jax.language.sensor_reader import revise

        if not subgoals:
            return subgoals
        pr, pw = self.reader.probs([sg.text for sg in subgoals])
        known = getattr(self.inner, "vocab", {}).get(ep.scene, ())
        out = tuple(revise(sg, a, b, self.conf, known) for sg, a, b in zip(subgoals, pr, pw))
        changed = tuple(f"{x.text}: {_comparison(x)} -> {_comparison(y)}" for x, y in zip(subgoals, out) if x != y)
        if changed:
            self.revised[ep.id] = changed
        return out

    def __call__(self, ep, subgoals):
        return self._revise(ep, self.inner(ep, subgoals) if self.inner is not None else subgoals)

    def read_unparsed(self, ep):
        """What `inner` reads of an instruction the parser cannot (None where it reads nothing), read again."""
        alone = getattr(self.inner, "read_unparsed", None)
        got = alone(ep) if alone is not None else None
        return self._revise(ep, got) if got else got


class TaggedReading:
    """The parse reconciled with the instruction tagger (`language/tagger.py: reconcile`), then handed to
    `then` (the memory grounder) if any: a `ground` hook of goal_items / prepare_batch. The tagger reads
    every instruction once, batched, when the hook is made; it also reads, alone, the instructions the parser
    cannot (`read_unparsed`), and, with `clauses`, those of which nothing read survives grounding (every
    instruction names a goal). `dropped[episode id]` keeps the phrases the tagger and the
    grounder dropped; `added[episode id]` the goal phrases the tagger added."""

    def __init__(self, tagger, episodes, conf: float, then=None, clauses: bool = False, anchors: bool = True,
                 relation_of=None, anchor_conf: float | None = None, regroup: bool = False):
        texts = sorted({ep.instruction for ep in episodes})
        self.probs = dict(zip(texts, tagger.word_probs(texts)))
        self.conf, self.then, self.clauses, self.anchors, self.added, self._dropped = conf, then, clauses, anchors, {}, {}
        self.relation_of, self.anchor_conf, self.regroup = relation_of, anchor_conf, regroup

    def __call__(self, ep, subgoals):
        from ragnav_jax.language.tagger import reconcile

        known = getattr(self.then, "vocab", {}).get(ep.scene, ())  # the names the house's memory recorded
        described = getattr(self.then, "descriptors", {}).get(ep.scene, ()) if self.clauses else ()
        subgoals, dropped, added = reconcile(ep.instruction, subgoals, self.probs[ep.instruction], self.conf,
                                            self.clauses, known, described, self.anchors, self.relation_of,
                                            self.anchor_conf, self.regroup)
        if dropped:
            self._dropped[ep.id] = dropped
        if added:
            self.added[ep.id] = added
        out = self.then(ep, subgoals) if self.then is not None else subgoals
        if not out and subgoals and self.clauses:  # nothing read survives: every instruction names a goal, so the goal
            # phrases the tagger reads alone, each from its own clause ("can the robot get itself to the appliance
            # whose temperature reading reads 90 or anything above it?")
            alone, _, added = reconcile(ep.instruction, (), self.probs[ep.instruction], self.conf, True, known,
                                        described, self.anchors, self.relation_of, self.anchor_conf,
                                        self.regroup)
            out = self.then(ep, alone) if self.then is not None else alone
            if out:
                self.added[ep.id] = added
        return out

    def read_unparsed(self, ep):
        """The subgoals of an instruction the rule parser cannot read: the goal phrases the tagger finds likelier
        goals than not (`tagger.ADD_CONF`), each read from its own clause with `clauses` (then grounded); None
        where there are none, and for no instruction at all (`parser.input_problem`: blank, too long)."""
        from ragnav_jax.language.parser import input_problem

        return None if input_problem(ep.instruction) else self(ep, ()) or None

    vocab = property(lambda self: getattr(self.then, "vocab", {}))

    @property
    def dropped(self) -> dict:
        inner = self.then.dropped if self.then is not None else {}
        return {k: self._dropped.get(k, ()) + tuple(inner.get(k, ())) for k in {*self._dropped, *inner}}
