import json,glob,sys,collections
a,b=json.load(open(sys.argv[1])),json.load(open(sys.argv[2]))
truth={}
for f in glob.glob('/work/main/runs/unseen2/episodes-*/episodes.jsonl')+['/work/main/experiments/results/paper-episodes.jsonl']:
    for l in open(f):
        d=json.loads(l); n=len(d.get('goals') or d.get('goal_ids') or d.get('subgoals') or [])
        truth[f.split('/')[-2]+'/'+d['id']]=n
c=collections.Counter()
for k in a:
    if a[k][1]==b[k][1]: continue
    na=len(a[k][1]) if not isinstance(a[k][1],str) else -1; nb=len(b[k][1]) if not isinstance(b[k][1],str) else -1
    t=truth.get(k)
    c[(na==t, nb==t)]+=1
    if na==t and nb!=t: print('LOST', k, t, na, nb)
print(c)
