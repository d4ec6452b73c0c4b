"""Fuzz the rule parser with many random strings (beyond the test suite's hypothesis runs).

    .venv/bin/python experiments/fuzz_parser.py --n 100000

Three generators: printable unicode, instruction-like word soup, and mutated generated instructions.
Anything other than a TaskChain (valid against the schema) or a ParseError is reported and fails.
"""

from __future__ import annotations

import argparse
import random
import time
import traceback

from ragnav_jax.language.parser import parse_instruction
from ragnav_jax.language.types import ParseError, validate_chain_dict

WORDS = (
    "go to the a sofa red near next by on in with then and first finally any order ndvi temperature humidity "
    "above below about under over degrees % ( ) , . x= y= 3.5 -2 0.6 1e5 nan inf 12,5 of it one room kitchen "
    "warmest lowest highest least most healthy please start continue finish at after before that is which "
    "° °c f percent sixty point ⟪a⟫ 1.2.3 [ ] : ; ! ? ' \" - x y between than hotter whose coordinates"
).split()
SEEDS = [
    "First go to the sink next to the table with the monitor, then the fern near (3.5, 2.0) with an NDVI above 0.6.",
    "Visit the warmest appliance in the kitchen, the couch and the lamp at x=1, y=2 in any order.",
    "Start at the bed, continue to the desk, and finish at the plant with humidity between 40 and 60%.",
]


def main() -> None:
    ap = argparse.ArgumentParser()
    ap.add_argument("--n", type=int, default=100_000)
    ap.add_argument("--seed", type=int, default=0)
    args = ap.parse_args()
    rng = random.Random(args.seed)
    ok = err = 0
    t0 = time.perf_counter()
    for i in range(args.n):
        kind = i % 3
        if kind == 0:
            s = "".join(chr(rng.randint(32, 0x2FFF)) for _ in range(rng.randint(0, 80)))
        elif kind == 1:
            s = " ".join(rng.choice(WORDS) for _ in range(rng.randint(0, 30)))
        else:
            s = list(rng.choice(SEEDS))
            for _ in range(rng.randint(1, 6)):
                k = rng.randrange(len(s))
                op = rng.random()
                if op < 0.4:
                    del s[k]
                elif op < 0.8:
                    s.insert(k, rng.choice(" ,.()0123456789xy=-"))
                else:
                    s[k] = rng.choice("abcdefghijklmnopqrstuvwxyz")
            s = "".join(s)
        try:
            validate_chain_dict(parse_instruction(s).to_dict())
            ok += 1
        except ParseError:
            err += 1
        except Exception:  # noqa: BLE001 - the point of the script
            print(f"UNEXPECTED on {s!r}")
            traceback.print_exc()
            raise SystemExit(1) from None
    dt = time.perf_counter() - t0
    print(f"{args.n} strings: {ok} chains, {err} ParseErrors, 0 other exceptions ({1000 * dt / args.n:.2f} ms each)")


if __name__ == "__main__":
    main()
