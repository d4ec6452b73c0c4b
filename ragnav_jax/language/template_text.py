"""Small text helpers the sentence-template sets share (`phrasings_*.py`): none draws a random number but
`listed`, which draws from the generator passed in. Each set's wording stays its own; these only lay words out."""

from __future__ import annotations

from ragnav_jax.language.types import Target

ONES = ("zero", "one", "two", "three", "four", "five", "six", "seven", "eight", "nine", "ten", "eleven", "twelve",
        "thirteen", "fourteen", "fifteen", "sixteen", "seventeen", "eighteen", "nineteen")
TENS = ("", "", "twenty", "thirty", "forty", "fifty", "sixty", "seventy", "eighty", "ninety")


def attributes_and_states(t: Target) -> tuple[list[str], list[str]]:
    """(attributes the target's phrase writes before the noun, in order; every other attribute, a state such as
    'switched on', 'open' or 'empty')."""
    if not t.phrase.endswith(t.head):
        return list(t.attributes), []
    rest = t.phrase[: len(t.phrase) - len(t.head)].strip()
    pre, states = [], []
    for a in t.attributes:
        if rest and (rest == a or rest.startswith(a + " ")):
            pre.append(a)
            rest = rest[len(a):].strip()
        else:
            states.append(a)
    return pre, states


def tidy(s: str) -> str:
    """Runs of spaces as one, no doubled or dangling commas ('a ,, b,' -> 'a, b')."""
    s = " ".join(s.split())
    for a, b in ((",,", ","), (", ,", ","), (", (", " ("), (",)", ")")):
        s = s.replace(a, b)
    while s.endswith(","):
        s = s[:-1].rstrip()
    return s


def number_words(n: int) -> str:
    """A whole number in words: 'minus eighteen', 'forty-two', 'three hundred and five'."""
    if n < 0:
        return "minus " + number_words(-n)
    if n < 20:
        return ONES[n]
    if n < 100:
        return TENS[n // 10] + ("-" + ONES[n % 10] if n % 10 else "")
    if n < 1000:
        rest = n % 100
        return ONES[n // 100] + " hundred" + (" and " + number_words(rest) if rest else "")
    return str(n)


def listed(rng, res: list[str]) -> str:
    """Goals in a running sentence: commas, or semicolons where a goal has commas of its own (two goals: 'and')."""
    from ragnav_jax.language.episodes import _pick

    if len(res) == 2:
        return f"{res[0]} and {res[1]}"
    if any("," in r for r in res):
        return "; ".join(res[:-1]) + "; and " + res[-1]
    return ", ".join(res[:-1]) + _pick(rng, (" and ", ", and ")) + res[-1]


def hyphenated(states: list[str]) -> str:
    """States as one modifier before a noun: ['switched on', 'open'] -> 'switched-on open'."""
    return " ".join(s.replace(" ", "-") for s in states)


def both(words: list[str]) -> str:
    """Words joined by 'and': ['teal', 'wool'] -> 'teal and wool'."""
    return " and ".join(words)


def plural(head: str) -> bool:
    """'drums', 'shelves' are plural; 'cactus', 'glass', 'lamp' are not."""
    last = head.split()[-1]
    return last.endswith("s") and not last.endswith(("ss", "us", "is"))


def is_are(head: str) -> str:
    """The verb 'to be' agreeing with a head noun ('are' for 'drums', 'is' for 'lamp')."""
    return "are" if plural(head) else "is"
