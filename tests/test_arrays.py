import jax
import jax.numpy as jnp
import numpy as np
import pytest
from conftest import tree_allclose

from ragnav_jax.config import WorldConfig
from ragnav_jax.world.arrays import PadSizes, pad_sizes, scene_arrays, stack_scenes
from ragnav_jax.world.generator import generate_scenes


@pytest.fixture(scope="module")
def batch(request):
    from ragnav_jax.world.scene import example_scene_path, load_scene

    scenes = [load_scene(example_scene_path())] + generate_scenes(WorldConfig(num_scenes=2), seed=3)
    return scenes, *stack_scenes(scenes)


def test_shapes_and_masks(batch):
    scenes, arr, idx = batch
    B = len(scenes)
    R, W, O, S = idx.sizes
    assert arr.room_min.shape == (B, R, 2) and arr.wall_a.shape == (B, W, 2)
    assert arr.obj_pos.shape == (B, O, 3) and arr.obj_sensors.shape == (B, O, S)
    np.testing.assert_array_equal(arr.room_mask.sum(1), [len(s.rooms) for s in scenes])
    np.testing.assert_array_equal(arr.wall_mask.sum(1), [len(s.walls) for s in scenes])
    np.testing.assert_array_equal(arr.obj_mask.sum(1), [len(s.objects) for s in scenes])
    # Padding is zero / -1 outside the mask.
    assert not np.any(np.asarray(arr.obj_pos)[~np.asarray(arr.obj_mask)])
    assert np.all(np.asarray(arr.obj_category)[~np.asarray(arr.obj_mask)] == -1)


def test_values_round_trip(batch):
    scenes, arr, idx = batch
    for b, s in enumerate(scenes):
        for i, o in enumerate(s.objects):
            np.testing.assert_allclose(arr.obj_pos[b, i], o.position, atol=1e-6)
            assert idx.categories[int(arr.obj_category[b, i])] == o.category
            assert idx.room_ids[b][int(arr.obj_room[b, i])] == o.room
            for k, v in o.sensors:
                j = idx.sensor_names.index(k)
                assert bool(arr.obj_sensor_mask[b, i, j]) and abs(float(arr.obj_sensors[b, i, j]) - v) < 1e-4
        np.testing.assert_allclose(arr.start[b], [*s.start.position, s.start.yaw], atol=1e-6)


def _total_wall_length(a):
    """A masked per-scene reduction, as later kernels do."""
    lengths = jnp.linalg.norm(a.wall_b - a.wall_a, axis=-1)
    return jnp.sum(jnp.where(a.wall_mask, lengths, 0.0))


def test_jit_vmap_over_padded_batch_matches_each_alone(batch):
    scenes, arr, idx = batch
    batched = jax.jit(jax.vmap(_total_wall_length))(arr)
    for b, s in enumerate(scenes):
        alone, _ = scene_arrays(s)  # padded only to its own size
        assert abs(float(_total_wall_length(alone)) - float(batched[b])) < 1e-4
        assert abs(float(batched[b]) - sum(w.length for w in s.walls)) < 1e-3


@pytest.mark.parametrize("n", [1, 2])
def test_extra_padding_does_not_change_results(batch, n):
    scenes, arr, idx = batch
    bigger = PadSizes(idx.sizes.rooms + n, idx.sizes.walls + n, idx.sizes.objects + n, idx.sizes.sensors)
    arr2, _ = stack_scenes(scenes, bigger)
    assert tree_allclose(jax.vmap(_total_wall_length)(arr), jax.vmap(_total_wall_length)(arr2), atol=1e-4)


def test_scene_too_big_for_pad_sizes(batch):
    scenes, _, _ = batch
    with pytest.raises(ValueError, match="does not fit"):
        stack_scenes(scenes, PadSizes(1, 1, 1, 1))


def test_pad_sizes_never_zero():
    from ragnav_jax.world.scene import Room, Scene, Start

    empty = Scene("e", (Room("r", "hall", (0, 0), (2, 2)),), (), (), Start((1, 1)))
    assert pad_sizes([empty]) == PadSizes(1, 1, 1, 1)
    arr, _ = scene_arrays(empty)
    assert arr.wall_a.shape == (1, 2) and not bool(arr.wall_mask.any())
