"""Every registered buffer of every technique as a NumPy array: its dtype and shape from the
registry, no copy of the run's memory, read-only, alive as long as an array needs it; the same
words on any thread count."""
import gc

import numpy as np
import pytest

import voxgi

# Runs that between them produce every declared buffer: the planner's full mode, and the settings
# whose buffers it still leaves out (isotropic mips, a bounce, the RSM's blockers).
RUNS = [
    ("vct", "cornell_box.json", {"plan.mode": "full", "bounce.count": 1}),
    ("vct", "cornell_box.json", {"plan.mode": "full", "mip.mode": "isotropic", "bounce.count": 1}),
    ("lpv", "cornell_box_lpv.json", {"plan.mode": "full"}),
    ("lpv", "cornell_box_lpv.json", {"plan.mode": "full", "inject_geometry.blockers": "rsm"}),
    ("holpv", "cornell_box_lpv.json", {"plan.mode": "full"}),
    ("svo", "cornell_box.json", {"plan.mode": "full"}),
]
N, WIDTH = 16, 64


def setting(run, key):
    return next(s.split("=", 1)[1] for s in run.settings if s.startswith(key + "="))


def expected_shape(spec, run, array):
    """The shape docs/python.md gives for the buffer, from the scene and settings alone."""
    c = spec["components"]
    shape = spec["shape"]
    if shape == "volume":
        return (N, N, N, c)
    if shape == "image":
        return (WIDTH, WIDTH, c)  # the box's camera is square
    if shape in ("mips", "mips6"):
        faces = 6 if shape == "mips6" else 1
        return (sum(faces * (N >> l) ** 3 for l in range(1, 5)), c)
    if shape == "series":
        # one volume per propagation step and the injected one before the first
        return (int(setting(run, "propagate.steps")) + 1, N, N, N, c)
    if shape == "maps":
        r = int(setting(run, "rsm.resolution"))
        return (array.shape[0], r, r, c)
    assert shape == "sparse"
    return (array.shape[0], c)


@pytest.fixture(scope="module")
def runs(repo):
    out = []
    for technique, scene, settings in RUNS:
        s = voxgi.load_scene(repo / "scenes" / scene, resolution=N, image=WIDTH)
        out.append(voxgi.run(s, technique, settings=settings, threads=2))
    return out


def test_every_declared_buffer_has_its_dtype_and_shape(runs):
    specs = {b["name"]: b for b in voxgi.buffers()}
    seen = set()
    for run in runs:
        declared = {b["name"] for b in voxgi.buffers(run.technique)}
        for name in run.names:
            assert name in declared, f"{run.technique} produced {name}, not one of its buffers"
            a = run[name]
            assert a.dtype == specs[name]["dtype"], name
            assert a.shape == expected_shape(specs[name], run, a), name
            assert a.size > 0, name
            seen.add(name)
    assert set(specs) - seen == set(), "no run produced these buffers"


def test_arrays_are_views_of_the_run(box):
    run = voxgi.run(box, stage="vct/light_voxels", threads=2)
    a = run["vct/light_voxels.radiance"]
    b = run["vct/light_voxels.radiance"]
    # Two arrays of one buffer are the same memory: neither is a copy.
    assert a.__array_interface__["data"][0] == b.__array_interface__["data"][0]
    assert np.shares_memory(a, b)
    assert not a.flags.writeable and not a.flags.owndata
    with pytest.raises(ValueError):
        a[0, 0, 0, 0] = 1.0
    # The array keeps the run's buffers alive after the run itself is gone.
    copy = a.copy()
    del run, b
    gc.collect()
    np.testing.assert_array_equal(a, copy)
    assert copy.any()


def test_buffers_are_the_same_on_any_thread_count(box):
    one = voxgi.run(box, threads=1)
    two = voxgi.run(box, threads=2)
    assert one.names == two.names
    for name in one.names:
        assert one[name].tobytes() == two[name].tobytes(), name


def test_mip_levels_are_views(box):
    run = voxgi.run(box, stage="vct/mip", threads=2)
    mips = run["vct/mip.radiance_mips6"]
    levels = voxgi.mip_levels(mips, N, faces=6)
    assert [l.shape for l in levels] == [(8, 8, 48, 4), (4, 4, 24, 4), (2, 2, 12, 4),
                                         (1, 1, 6, 4)]
    assert all(np.shares_memory(l, mips) for l in levels)
    assert levels[-1].flatten().tolist() == mips[-6:].flatten().tolist()


def test_render_is_the_techniques_image(box):
    image = voxgi.render(box, threads=2)
    assert image.shape == (64, 64, 3) and image.dtype == np.float32
    assert np.isfinite(image).all() and image.mean() > 0.0
