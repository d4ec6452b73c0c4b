import json,re,collections,sys
d=json.load(open(sys.argv[1]))
MARK=re.compile(r'^\s*(?:[•·*▪►‣–—-]|\(?\d{1,2}[.)]|\(?[a-h]\)|\[[ x]?\])\s*')
cnt=collections.Counter(); tot=collections.Counter()
for k,(ins,r) in d.items():
    lines=ins.split('\n')
    idx=[i for i,l in enumerate(lines) if MARK.match(l)]
    if len(idx)<2 or idx[0]==0: continue
    pre=' '.join(lines[:idx[0]]).lower()
    tot[k.split('/')[0]]+=1
    if isinstance(r,str): continue
    first=r[0]
    if first[0] and first[0].lower()[:20] in pre:
        cnt[k.split('/')[0]]+=1
        if len(sys.argv)>2: print(k, '|', pre[:150], '|', first[:2])
print(dict(tot)); print(dict(cnt))
