"""verdict_diff.py SPLIT|EPISODES.jsonl... (as run: /tmp/dbg/vdiff35.py): per grounded sensor subgoal, the target's
verdict and the number of other objects passing, with round 34's verifier (old_verdicts) and the checkout's; RUN
(a folder under /work/main/runs) and CFG (a config) select the houses."""
import sys, os, json
from pathlib import Path
import numpy as np
from ragnav_jax.config import load_config
from ragnav_jax.evaluation import verify as V
from ragnav_jax.evaluation.verify import Verifier, memory_views
from ragnav_jax.evaluation.methods import method_spec
from ragnav_jax.evaluation.ranking import grounder
from ragnav_jax.retrieval.evaluate import goal_items
from ragnav_jax.language.episodes import load_episodes
from ragnav_jax.memory.checkpoint import load_bank
from ragnav_jax.memory.encoder import make_embedder
from ragnav_jax.world.scene import load_scene_set
run = Path('/work/main/runs/' + os.environ.get('RUN', 'unseen2'))
cfg = load_config(os.environ.get('CFG', '/work/main/configs/unseen.yaml'), [])
scenes = load_scene_set(run / 'scenes'); bank = load_bank(run / 'memory' / 'bank', scenes)
ver = Verifier.build(make_embedder(cfg.memory.embedder), cfg)
views = memory_views(ver, bank, scenes)
orig = Verifier.verdicts
def old_verdicts(self, view, sg, ps, names=None):  # round 34 (da299c1)
    objs = view.scene.objects
    names = names if names is not None else [view.names_of(i, ps[i]) for i in range(len(objs))]
    named = self.target_fits(sg.target, ps, view.vocab, names, view.classes)
    ok = self._constrained(view, sg, ps, named)
    pool = list(view.known)
    if sg.sensors and sg.target.head not in view.vocab and not ok[pool].any():
        rest = self._constrained(view, sg, ps, V.attributes_seen(sg.target, ps), rank=False)
        if not any(c.is_superlative for c in sg.sensors):
            rest &= self.best_named(sg.target.head, names, rest, pool)
        ok = self._constrained(view, sg, ps, rest)
    return ok
tot = {'changed': 0, 'target_gain': 0, 'target_loss': 0, 'wrong_more': 0, 'wrong_less': 0}
for split in sys.argv[1:]:
    eps = load_episodes(split if split.endswith('.jsonl') else f'{run}/episodes-{split}/episodes.jsonl', scenes)
    g = grounder(method_spec('ragnav'), bank, scenes, eps, cfg, ver)
    for ep, k, goal, sg in goal_items(eps, g, every_subgoal=True):
        if sg is None or goal is None or not sg.sensors:
            continue
        view = views[ep.scene]; ps = ver.perceptions_of(view.scene, ep.id)
        ids = [o.id for o in view.scene.objects]; t = ids.index(goal)
        a = old_verdicts(ver, view, sg, ps); b = orig(ver, view, sg, ps)
        if (a != b).any():
            tot['changed'] += 1
            tot['target_gain'] += bool(b[t] and not a[t]); tot['target_loss'] += bool(a[t] and not b[t])
            wa = int(a.sum() - a[t]); wb = int(b.sum() - b[t])
            tot['wrong_more'] += wb > wa; tot['wrong_less'] += wb < wa
            print(split, ep.id, k, goal, repr(sg.text[:70]), 'target', bool(a[t]), '->', bool(b[t]), 'others', wa, '->', wb,
                  [view.scene.objects[i].id for i in np.flatnonzero(b) if i != t][:4])
print(tot)
