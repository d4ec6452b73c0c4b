"""pdump.py OUT: rule-parser reading of every instruction in runs/unseen2 episode files + paper episodes -> json."""
import sys, json, glob
from ragnav_jax.language.parser import parse_instruction
out = {}
files = sorted(f for f in glob.glob('/work/main/runs/unseen2/episodes-*/episodes.jsonl') if not any(h in f for h in ('unseen_av',))) + ['/work/main/experiments/results/paper-episodes.jsonl']
for f in files:
    for l in open(f):
        d = json.loads(l)
        try:
            c = parse_instruction(d['instruction'])
            r = [(s.text, s.target.head, s.target.attributes, s.room, [(x.type, x.anchor.head) for x in s.target.relations],
                  [str(x) for x in s.sensors]) for s in c.subgoals]
        except Exception as e:
            r = repr(e)
        out[f.split('/')[-2] + '/' + d['id']] = [d['instruction'], r]
json.dump(out, open(sys.argv[1], 'w'))
