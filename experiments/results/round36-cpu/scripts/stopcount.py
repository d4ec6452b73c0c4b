"""Goals counted right on instructions with a telegram STOP: subgoals vs goals, rule parser alone and with tagger."""
import sys, json
from ragnav_jax.language.parser import parse_instruction
from ragnav_jax.language.types import ParseError
n = ok = 0
for split in sys.argv[1:]:
    for l in open(f'/work/main/runs/unseen2/episodes-{split}/episodes.jsonl'):
        e = json.loads(l)
        if 'STOP' not in e['instruction']:
            continue
        n += 1
        try:
            c = parse_instruction(e['instruction'])
            k = len(c.subgoals)
            heads = [s.target.head for s in c.subgoals]
        except ParseError:
            k, heads = -1, []
        ok += k == len(e['goals'])
        if k != len(e['goals']) and len(sys.argv) > 0:
            print(split, e['id'], len(e['goals']), k, heads[:6])
print('instructions with STOP', n, 'goal count right', ok)
