"""Bad input raises voxgi.InputError (a ValueError) carrying the one line the CLI prints for the
same input (after its "voxgi: "), and leaves the interpreter usable."""
import subprocess

import numpy as np
import pytest

import voxgi


def cli_error(voxgi_bin, *args):
    done = subprocess.run([voxgi_bin, *map(str, args)], capture_output=True, text=True)
    assert done.returncode == 2, done.stderr
    line = done.stderr.strip().splitlines()[-1]
    assert line.startswith("voxgi: ")
    return line[len("voxgi: "):]


@pytest.mark.parametrize("name", ["grid_size_huge.json", "light_without_intensity.json",
                                  "missing_meshes.json", "number_beyond_double.json",
                                  "face_index_7_of_3.ply", "no_such_file.json"])
def test_a_bad_scene_raises_the_clis_message(repo, voxgi_bin, name):
    path = repo / "tests" / "data" / "bad" / name
    with pytest.raises(voxgi.InputError) as error:
        voxgi.load_scene(path)
    assert str(error.value) == cli_error(voxgi_bin, "plan", path)
    assert isinstance(error.value, ValueError)


def test_a_bad_setting_raises_the_clis_message(repo, voxgi_bin, box):
    scene = repo / "scenes" / "cornell_box.json"
    for assignment in ["cones.set=nine", "propagate.steps=3", "no.such=1", "cones.aperture=-1"]:
        key, value = assignment.split("=")
        with pytest.raises(voxgi.InputError) as error:
            voxgi.plan(box, settings={key: value})
        assert str(error.value) == cli_error(voxgi_bin, "plan", scene, "--set", assignment)


def test_bad_arguments_name_what_is_wrong(box):
    cases = [
        (lambda: voxgi.run(box, "nope"), "technique"),
        (lambda: voxgi.run(box, stage="vct/propagate"), "stage"),
        (lambda: voxgi.run(box, backend="tpu"), "backend"),
        (lambda: voxgi.run(box, threads=-3), "threads"),
        (lambda: voxgi.load_scene({"meshes": [{"file": "missing.obj"}]}), "meshes[0].file"),
        (lambda: voxgi.load_scene(box.file, resolution=100), "resolution"),
        (lambda: voxgi.load_scene(box.file, resolution=0), "resolution"),
        (lambda: voxgi.load_scene(box.file, image=0), "image"),
        (lambda: voxgi.check(box, "vct/nothing", np.zeros(3)), "vct/nothing"),
        (lambda: voxgi.path_trace(box, spp=0), "spp"),
        (lambda: voxgi.compare(np.zeros((4, 4, 3)), np.zeros((4, 5, 3))), "differ in size"),
        (lambda: voxgi.read_dump(box.file), "a dump is a .vdb or .exr file"),
    ]
    for call, named in cases:
        with pytest.raises(voxgi.InputError) as error:
            call()
        assert named in str(error.value)
        assert "\n" not in str(error.value)


def test_a_scene_from_a_dict_reads_its_files_beside_base_dir(repo):
    scene = voxgi.load_scene({"meshes": [{"file": "cornell_box.obj"}], "grid": {"resolution": 16}},
                             base_dir=repo / "scenes")
    assert scene.triangles == voxgi.load_scene(repo / "scenes" / "cornell_box.obj").triangles
    assert scene.resolution == 16
