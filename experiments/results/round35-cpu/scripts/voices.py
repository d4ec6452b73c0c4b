"""voices.py ROWS.jsonl...: successes of a method on AM by voice, instructions told apart by their words."""
import json, sys
from collections import Counter
eps = {json.loads(l)['id']: json.loads(l) for l in open('runs/unseen2/episodes-unseen_am/episodes.jsonl')}
def voice(t):
    l = t.lower()
    if 'STOP' in t: return 'telegram'
    if 'dive' in l or 'buddy' in l or 'ascent' in l: return 'scuba'
    if 'tour' in l or 'band' in l or 'bus ' in l: return 'tour'
    return 'horoscope/other'
for run in sys.argv[1:]:
    rows = [json.loads(l) for l in open(run)]
    tot, suc = Counter(), Counter()
    for r in rows:
        v = voice(eps[r['episode']]['instruction']); tot[v] += 1; suc[v] += r['success']
    print(run, {v: f"{suc[v]}/{tot[v]}" for v in sorted(tot)})
