import json, dataclasses, numpy as np
from ragnav_jax.language.parser import parse_instruction, split_noun_phrase
from ragnav_jax.language.types import ParseError, TaskChain, Subgoal, Target
from ragnav_jax.language.tagger import load_tagger, reconcile, words, spans, BT, IT, O
data = json.load(open('/tmp/tg/seen4244.json'))
r8 = [None if l.strip() == 'null' else TaskChain.from_dict(json.loads(l)).subgoals for l in open('/tmp/tg/seen4244-dev8-r8.jsonl')]
tagger = load_tagger('runs/tagger/no-dev8/tagger.npz')

def reconcile_last(instruction, subgoals, probs, conf):
    """the first design: a span holds the head's last word; no 'accounted' guard, no stems"""
    ws = [w.lower() for w in words(instruction)]
    tags = probs.argmax(-1); goals = spans(tags, BT); held = [set(ws[i:j]) for i, j in goals]
    sure = [min([probs[i, BT]] + [probs[k, IT] for k in range(i + 1, j)]) > conf for i, j in goals]
    kept, where, taken, changed = [], [], set(), False
    for sg in subgoals:
        head = sg.target.head.split()
        ks = [k for k in range(len(goals)) if head and head[-1] in held[k]]
        if not ks:
            occ = [n for n, w in enumerate(ws) if w in head]
            if occ and all(probs[n, O] > conf for n in occ):
                changed = True; continue
            where.append(occ[0] if occ else 0)
        else:
            k = next((k for k in ks if k not in taken), ks[0]); taken.add(k); where.append(goals[k][0])
        kept.append(sg)
    for k, (i, j) in enumerate(goals):
        if k in taken or not sure[k]: continue
        a, h = split_noun_phrase(ws[i:j]); kept.append(Subgoal(0, Target(' '.join(ws[i:j]), h, tuple(a)))); where.append(i); changed = True
    return (tuple(kept[n] for n in sorted(range(len(kept)), key=lambda n: where[n])) if changed else tuple(subgoals)), changed

res = {}
for split, rows in data.items():
    texts = [r['instruction'] for r in rows]
    probs = tagger.word_probs(texts)
    for conf in (0.5, 0.99):
        for name in ('last', 'current'):
            n = c0 = c1 = fixed = broke = changed = 0
            for k, (r, p) in enumerate(zip(rows, probs)):
                truth = len(r['truth']['subgoals'])
                if split == 'unseen_dev8':
                    sg = r8[k]
                else:
                    try: sg = parse_instruction(r['instruction']).subgoals
                    except ParseError: sg = None
                n += 1
                if sg is None: continue
                if name == 'current':
                    out, d, a = reconcile(r['instruction'], sg, p, conf); ch = bool(d or a)
                else:
                    out, ch = reconcile_last(r['instruction'], sg, p, conf)
                ok0, ok1 = len(sg) == truth, len(out) == truth
                c0 += ok0; c1 += ok1; fixed += ok1 and not ok0; broke += ok0 and not ok1; changed += ch
            res[(split, conf, name)] = (n, c0, c1, fixed, broke, changed)
print('| set | conf | rule | n | count right: parse | + tagger | fixed | broke | changed |')
for (split, conf, name), v in res.items():
    print(f'| {split} | {conf} | {name} | ' + ' | '.join(map(str, v)) + ' |')
tot = {}
for (split, conf, name), v in res.items():
    if split != 'unseen_dev8':
        t = tot.setdefault((conf, name), [0, 0]); t[0] += v[4]; t[1] += v[0]
print('breaks on the known sets:', {k: f'{b}/{n}' for k, (b, n) in tot.items()})
print('D round-8 fixed-broke:', {(c, nm): res[('unseen_dev8', c, nm)][3] - res[('unseen_dev8', c, nm)][4] for c in (0.5, 0.99) for nm in ('last', 'current')})
