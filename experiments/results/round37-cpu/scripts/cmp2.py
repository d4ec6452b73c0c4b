"""cmp2.py A B: paired won/lost of eval run folders A -> B (ragnav)."""
import json,sys
from math import comb
def load(p): return {json.loads(l)['episode']:json.loads(l) for l in open(p + '/eval/ragnav/episodes.jsonl')}
a=load(sys.argv[1]); b=load(sys.argv[2])
w=[k for k in a if b[k]['success'] and not a[k]['success']]; l=[k for k in a if a[k]['success'] and not b[k]['success']]
n=len(w)+len(l); p=min(1,2*sum(comb(n,i) for i in range(0,min(len(w),len(l))+1))/2**n) if n else 1
sa=sum(r['success'] for r in a.values())/len(a); sb=sum(r['success'] for r in b.values())/len(b)
print(f'{sys.argv[2].split("/")[-1]}: {sa:.3f} -> {sb:.3f}  won {len(w)} lost {len(l)} p={p:.2g}  lost: {l}')
