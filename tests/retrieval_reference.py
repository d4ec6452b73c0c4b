"""Plain NumPy / Python reference implementations of the retrieval kernels (loops, obviously right)."""

import math

import networkx as nx
import numpy as np
from scipy.special import expit

NEG = -1e9


def cosine(q, emb, mask):
    out = np.full(len(emb), NEG)
    for i in range(len(emb)):
        if mask[i]:
            out[i] = float(np.dot(q, emb[i]) / (max(np.linalg.norm(q), 1e-12) * max(np.linalg.norm(emb[i]), 1e-12)))
    return out


def graph(nbr, nbr_mask):
    g = nx.Graph()
    g.add_nodes_from(range(len(nbr)))
    for i in range(len(nbr)):
        for d in range(nbr.shape[1]):
            if nbr_mask[i, d] and nbr[i, d] >= 0:
                g.add_edge(int(nbr[i, d]), i)  # the kernels read row i as "who feeds node i"
    return g


def within_hops(g, i, hops):
    return set(nx.single_source_shortest_path_length(g, i, cutoff=int(hops)))


def anchor_guided(sem_a, sem_b, pos, nbr, nbr_mask, top_k, hops, thr, sigma, pos_b=None):
    n = len(sem_a)
    pos_b = pos if pos_b is None else pos_b
    g = graph(nbr, nbr_mask)
    order = sorted(range(n), key=lambda i: -sem_a[i])[: int(top_k)]
    scores, anchor = np.full(n, NEG), np.full(n, -1)
    for i in order:
        if sem_a[i] <= NEG / 2:
            continue
        best, best_j = -np.inf, -1
        for j in sorted(within_hops(g, i, hops)):
            if sem_b[j] >= thr:
                v = sem_b[j] / (1 + np.linalg.norm(pos[i] - pos_b[j]))
                if v > best:
                    best, best_j = v, j
        if best_j >= 0:
            d2 = float(np.sum((pos[i] - pos_b[best_j]) ** 2))
            scores[i] = sem_a[i] * math.exp(-d2 / (2 * sigma**2))
            anchor[i] = best_j
    return scores, anchor


def boost(sem, ctx, nbr, nbr_mask, node_mask, eta, thr, hops):
    n = len(sem)
    g = graph(nbr, nbr_mask)
    out, means = np.full(n, NEG), np.zeros(n)
    for i in range(n):
        if not node_mask[i]:
            continue
        nb = [j for j in within_hops(g, i, hops) if j != i and node_mask[j] and ctx[j] >= thr]
        m = float(np.mean([ctx[j] for j in nb])) if nb else 0.0
        means[i] = m
        out[i] = sem[i] * (1 + eta * m)
    return out, means


def sensor(readings, present, match, channel, op, value, scale, missing=0.1):
    x, has = readings[:, channel], present[:, channel]
    cands = [x[m] for m in range(len(x)) if match[m] and has[m]]
    out = []
    for m in range(len(x)):
        if op == 0:
            out.append(1.0)
        elif not has[m]:
            out.append(missing)
        elif op == 1:
            out.append(expit((x[m] - value) / scale))
        elif op == 2:
            out.append(expit((value - x[m]) / scale))
        elif op == 3:
            out.append(math.exp(-((x[m] - value) ** 2) / (2 * scale**2)))
        elif op == 4:
            out.append(math.exp(-max(max(cands) - x[m], 0) / scale) if cands else 1.0)  # nothing to rank against
        elif op == 5:
            out.append(math.exp(-max(x[m] - min(cands), 0) / scale) if cands else 1.0)
    return np.array(out)


def beam(q, cluster_emb, cluster_mask, cluster_parent, leaf_cluster, width):
    L, C, _ = cluster_emb.shape
    kept = np.zeros((L, C), bool)
    parent_kept = np.ones(C, bool)
    for level in range(L - 1, -1, -1):
        cand = [c for c in range(C) if cluster_mask[level, c]
                and (level == L - 1 or (cluster_parent[level, c] >= 0 and parent_kept[cluster_parent[level, c]]))]
        s = cosine(q, cluster_emb[level], np.ones(C, bool))
        for c in sorted(cand, key=lambda c: -s[c])[: int(width)]:
            kept[level, c] = True
        parent_kept = kept[level]
    allowed = np.array([lc[0] >= 0 and kept[0, lc[0]] for lc in leaf_cluster])
    return allowed, kept
