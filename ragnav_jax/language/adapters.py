"""What the learned readers share: MiniLM with low-rank adapters, fitted and stored the same way.

The instruction tagger (`tagger.py`) and the sensor reader (`sensor_reader.py`) each put small heads on the
installed all-MiniLM-L6-v2 and train only those heads and the adapters (`is_trained`); their fitted files hold
those arrays and the metadata (a few hundred kilobytes), never the encoder's own weights.

    trained, frozen = split_init(model, base, key, is_trained)     # flat dicts
    trained, losses = train(loss_fn, trained, frozen, batches, steps, lr, key, desc="fit-x", progress=True)
    save_adapters(trained, meta, path); trained, meta = load_adapters(path, FORMAT, "sensor reader")
"""

from __future__ import annotations

import json
from collections.abc import Callable, Iterator
from pathlib import Path

import jax
import jax.numpy as jnp
import numpy as np
from flax import traverse_util

from ragnav_jax.errors import UserError

CONF_GRID = (0.5, 0.6, 0.7, 0.8, 0.9, 0.95, 0.98, 0.99, 0.995, 0.999)
CONF_CHANGES = 0.005  # share of correct parses a reader's fitted confidence may change (set before any unseen-split
# measurement; a stricter 0 chosen after seeing unseen-house results was reverted)


def fitted_conf(changes_at: Callable[[float], int], n: int) -> tuple[float, dict[str, int]]:
    """(the smallest confidence of CONF_GRID at which a reader changes at most CONF_CHANGES of n correct parses,
    the changes at every grid value); changes_at(conf) counts them."""
    changes = {c: changes_at(c) for c in CONF_GRID}
    conf = next((c for c in CONF_GRID if changes[c] <= CONF_CHANGES * n), CONF_GRID[-1])
    return conf, {str(c): k for c, k in changes.items()}


def data_path(filename: str) -> Path:
    """A fitted file shipped in ragnav_jax/data."""
    from importlib import resources

    return Path(str(resources.files("ragnav_jax").joinpath("data").joinpath(filename)))


def encoder_params(base) -> dict:
    """The installed MiniLM's weights as a flat dict under the model's 'enc' scope."""
    return {("enc", *k): v for k, v in traverse_util.flatten_dict(base.params["params"]).items()}


def join(trained: dict, frozen: dict) -> dict:
    """The {'params': ...} tree of flat trained and frozen dicts."""
    return {"params": traverse_util.unflatten_dict({**frozen, **trained})}


def split_init(model, base, key, is_trained: Callable[[tuple[str, ...]], bool], ids=None) -> tuple[dict, dict]:
    """(initial trained params, frozen encoder params) as flat dicts: the model's fresh heads and adapters, and
    the installed encoder's weights for everything else."""
    # one compiled program, not one per initialiser (the encoder's part is thrown away: the installed weights)
    ids = jnp.zeros((1, 8), jnp.int32) if ids is None else ids
    init = traverse_util.flatten_dict(jax.jit(model.init)(key, ids)["params"])
    pre = encoder_params(base)
    return ({k: v for k, v in init.items() if is_trained(k)}, {k: pre[k] for k in init if not is_trained(k)})


def train(loss_fn, trained: dict, frozen: dict, batches: Callable[[], Iterator[tuple[np.ndarray, np.ndarray]]],
          steps: int, lr: float, key, desc: str = "fit", progress: bool = False) -> tuple[dict, list[float]]:
    """AdamW (warm-up and cosine decay, weight decay 0.01) on loss_fn(trained, frozen, x, t, dropout key) over the
    (x, t) batches of `batches()` (one pass an epoch, `steps` in all); returns (trained, losses). The frozen
    weights are an argument of the compiled step, not constants in it, so a second fit of the same shapes finds
    the step in the compilation cache."""
    import optax

    schedule = optax.warmup_cosine_decay_schedule(0.0, lr, max(1, steps // 10), max(1, steps))
    opt = optax.adamw(schedule, weight_decay=0.01)
    state = opt.init(trained)
    frozen = jax.device_put(frozen)

    @jax.jit
    def step(tr, fr, st, x, t, k):
        loss, g = jax.value_and_grad(loss_fn)(tr, fr, x, t, k)
        upd, st = opt.update(g, st, tr)
        return optax.apply_updates(tr, upd), st, loss

    bar = None
    if progress:
        from tqdm.auto import tqdm

        bar = tqdm(total=steps, desc=desc, unit="step")
    losses: list[float] = []
    while len(losses) < steps:
        for x, t in batches():
            key, k = jax.random.split(key)
            trained, state, loss = step(trained, frozen, state, jnp.asarray(x), jnp.asarray(t), k)
            losses.append(float(loss))
            if bar is not None:
                bar.update(1)
                bar.set_postfix(loss=f"{losses[-1]:.4f}")
            if len(losses) >= steps:
                break
    if bar is not None:
        bar.close()
    return jax.device_get(trained), losses


def save_adapters(trained: dict, meta: dict, path: str | Path) -> Path:
    """The trained arrays as float32 named by their parameter path, with the metadata as JSON."""
    from ragnav_jax.io import atomic_path

    arrays = {"/".join(k): np.asarray(v, np.float32) for k, v in trained.items()}
    path = Path(path)
    with atomic_path(path) as tmp:
        with open(tmp, "wb") as f:
            np.savez(f, __meta__=np.frombuffer(json.dumps(meta, sort_keys=True).encode(), np.uint8), **arrays)
    return path


def load_adapters(path: str | Path, fmt: str, what: str) -> tuple[dict, dict]:
    """(trained arrays, metadata) of a file `save_adapters` wrote; UserError naming the file unless it is one of
    format `fmt` (`what`: the reader's name in the message)."""
    path = Path(path)
    try:
        with np.load(path) as z:
            meta = json.loads(bytes(z["__meta__"]).decode())
            trained = {tuple(k.split("/")): jnp.asarray(z[k]) for k in z.files if k != "__meta__"}
    except (OSError, ValueError, KeyError) as e:
        raise UserError(f"{path}: not a {what} file ({e.__class__.__name__}: {e})") from None
    if meta.get("format") != fmt:
        raise UserError(f"{path}: format {meta.get('format')!r} is not {fmt}")
    return trained, meta
