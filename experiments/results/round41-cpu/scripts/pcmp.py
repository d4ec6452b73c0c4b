"""pcmp.py BASE NEW [SHOW_SET...]: changed readings per set; examples for the sets named."""
import sys, json, collections
a, b = json.load(open(sys.argv[1])), json.load(open(sys.argv[2]))
show = sys.argv[3:]
cnt = collections.Counter()
for k in a:
    if a[k][1] != b.get(k, [None, None])[1]:
        s = k.split('/')[0]
        cnt[s] += 1
        if any(x in s for x in show):
            print('==', k, a[k][0][:300]); print('  -', a[k][1]); print('  +', b[k][1])
print(dict(cnt))
