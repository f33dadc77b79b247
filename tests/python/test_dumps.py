"""voxgi.read_dump reads every grid voxgi writes, the octree's integer grids included (which
python3-openvdb refuses), back into the arrays the run held, with the grid's transform."""
import subprocess

import numpy as np
import pytest

import voxgi


def dump(voxgi_bin, scene, out, *args):
    subprocess.run([voxgi_bin, "dump", str(scene), "--resolution", "16", "--image", "64",
                    "--backend", "cpu", "--out", str(out), *args], check=True,
                   capture_output=True)


def test_a_volume_dump_reads_back_as_the_runs_buffer(repo, voxgi_bin, box, tmp_path):
    dump(voxgi_bin, repo / "scenes" / "cornell_box.json", tmp_path, "--stage", "vct/light_voxels")
    grids = voxgi.read_dump(tmp_path / "light_voxels.vdb")
    radiance = voxgi.run(box, stage="vct/light_voxels", threads=2)["vct/light_voxels.radiance"]
    # A 4-component buffer is an RGB grid and its alpha grid (docs/architecture.md, "Buffers").
    assert grids["radiance"]["array"].tobytes() == np.ascontiguousarray(radiance[..., :3]).tobytes()
    assert grids["radiance_alpha"]["array"].tobytes() == np.ascontiguousarray(
        radiance[..., 3]).tobytes()
    meta = grids["radiance"]["metadata"]
    assert meta["voxgi_stage"] == "vct/light_voxels" and meta["voxgi_resolution"] == 16
    # Voxel (i, j, k)'s centre is at grid_min + (i + 0.5) h in world space.
    h = box.grid_size / 16
    centre = grids["radiance"]["transform"] @ np.array([3, 5, 7, 1.0])
    np.testing.assert_allclose(centre[:3], np.array(box.grid_min) + (np.array([3, 5, 7]) + 0.5) * h)


def test_the_octrees_integer_grids_read(repo, voxgi_bin, tmp_path):
    dump(voxgi_bin, repo / "scenes" / "cornell_box.json", tmp_path, "--technique", "svo",
         "--stage", "svo/build")
    grids = voxgi.read_dump(tmp_path / "build.vdb")
    assert grids["nodes_child"]["array"].dtype == np.uint32
    assert grids["leaf_sums_albedo"]["array"].dtype == np.int32
    assert grids["leaf_sums_albedo"]["array"].shape[-1] == 3
    for name, grid in grids.items():
        level = grid["metadata"]["voxgi_level"]
        assert grid["array"].shape[:3] == (16 >> level,) * 3, name
    # Every leaf holds some surface: its summed opacity weight is positive wherever it has albedo.
    opacity = grids["leaf_sums_opacity"]["array"]
    albedo = grids["leaf_sums_albedo"]["array"]
    assert (opacity > 0).sum() > 0
    assert ((albedo.sum(axis=-1) > 0) <= (opacity > 0)).all()


def test_an_image_dump_reads_back_as_the_runs_image(repo, voxgi_bin, box, tmp_path):
    dump(voxgi_bin, repo / "scenes" / "cornell_box.json", tmp_path, "--stage", "vct/compose")
    image = voxgi.read_dump(tmp_path / "compose.color.exr")
    assert image.tobytes() == voxgi.render(box, threads=2).tobytes()


def test_a_file_that_is_not_a_dump_is_refused(tmp_path):
    bad = tmp_path / "x.vdb"
    bad.write_bytes(b"not a vdb")
    with pytest.raises(voxgi.InputError, match="x.vdb"):
        voxgi.read_dump(bad)


def test_dump_from_python_writes_what_voxgi_dump_writes(repo, voxgi_bin, box, tmp_path):
    dump(voxgi_bin, repo / "scenes" / "cornell_box.json", tmp_path / "cli", "--stage", "vct/mip")
    paths = voxgi.dump(box, tmp_path / "py", stage="vct/mip", threads=2)
    assert [p.split("/")[-1] for p in paths] == ["mip.vdb"]
    cli = voxgi.read_dump(tmp_path / "cli" / "mip.vdb")
    py = voxgi.read_dump(paths[0])
    # rgb and alpha per face (6) and level (16^3: 4 above the base)
    assert sorted(cli) == sorted(py) and len(cli) == 2 * 6 * 4
    for name in cli:
        assert cli[name]["array"].tobytes() == py[name]["array"].tobytes(), name


def test_inspect_keeps_what_a_render_drops(repo):
    scene = voxgi.load_scene(repo / "scenes" / "cornell_box_lpv.json", resolution=16, image=64)
    assert "lpv/propagate.steps_sh4" not in voxgi.run(scene, "lpv", threads=2).names
    kept = voxgi.run(scene, "lpv", threads=2, inspect=True)
    assert kept["lpv/propagate.steps_sh4"].shape[1:] == (16, 16, 16, 12)
    assert voxgi.stages("lpv") == kept.stages
    with pytest.raises(voxgi.InputError, match="technique"):
        voxgi.stages("nope")
