"""mksub.py BASE NEW OUT: the episodes whose rule-parser reading changed, one file, ids prefixed by their set."""
import sys, json
a, b = json.load(open(sys.argv[1])), json.load(open(sys.argv[2]))
rows = []
for k in a:
    if a[k][1] != b[k][1] and not k.startswith('paper'):
        s, eid = k.split('/')
        split = s.removeprefix('episodes-')
        for l in open(f'/work/main/runs/unseen2/{s}/episodes.jsonl'):
            d = json.loads(l)
            if d['id'] == eid:
                d['id'] = f'{split}--{eid}'
                rows.append(json.dumps(d))
open(sys.argv[3], 'w').write('\n'.join(rows) + '\n')
print(len(rows))
