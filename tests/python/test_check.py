"""voxgi.check: a buffer made outside voxgi against the CPU oracle, with its registered
comparison. voxgi's own GPU backend stands in for another engine: its buffers pass; a perturbed
one fails naming the buffer and the worst element; an array of the wrong shape or dtype is
refused before anything runs."""
import numpy as np
import pytest

import voxgi

# Stages whose GPU buffers match the oracle run from the GPU's own earlier stages too (the
# comparisons of later stages assume the oracle's inputs, as voxgi diff gives them: check an
# engine stage by stage, first to last).
CHECKED = ["voxelize.opacity", "voxelize.albedo", "vct/light_voxels.radiance",
           "vct/mip.radiance_mips6"]


@pytest.fixture(scope="module")
def gpu_run(box):
    return voxgi.run(box, stage="vct/mip", backend="gpu", threads=2)


@pytest.mark.parametrize("name", CHECKED)
def test_the_gpu_backends_buffers_pass(box, gpu_run, name):
    report = voxgi.check(box, name, gpu_run[name])
    assert report["pass"], report
    (stage,) = report["stages"]
    assert stage["stage"] == name.split(".")[0]
    (buffer,) = stage["buffers"]
    assert buffer["buffer"] == name.split(".")[1] and buffer["status"] == "compared"


def test_a_perturbed_buffer_fails_at_its_worst_element(box, gpu_run):
    radiance = np.array(gpu_run["vct/light_voxels.radiance"])
    k, j, i = np.argwhere(radiance[..., 0] > 0)[0]  # a lit voxel
    radiance[k, j, i, 0] *= 1.01
    report = voxgi.check(box, "vct/light_voxels.radiance", radiance)
    assert not report["pass"]
    (buffer,) = report["stages"][0]["buffers"]
    assert buffer["buffer"] == "radiance" and not buffer["pass"]
    assert buffer["differing"] == 1
    # worst_element indexes voxels as the arrays do: i + N * (j + N * k)
    assert buffer["worst_element"] == i + 16 * (j + 16 * k)
    original = gpu_run["vct/light_voxels.radiance"][k, j, i, 0]
    assert buffer["max_abs_diff"] == float(radiance[k, j, i, 0]) - float(original)


def test_several_buffers_of_one_stage_at_once(box, gpu_run):
    names = ["voxelize.opacity", "voxelize.normal"]
    report = voxgi.check(box, {n: gpu_run[n] for n in names})
    assert report["pass"]
    assert [b["buffer"] for b in report["stages"][0]["buffers"]] == ["opacity", "normal"]
    with pytest.raises(voxgi.InputError, match="buffers of one stage at a time"):
        voxgi.check(box, {"voxelize.opacity": gpu_run["voxelize.opacity"],
                          "vct/light_voxels.radiance": gpu_run["vct/light_voxels.radiance"]})


def test_an_array_of_another_layout_is_refused(box, gpu_run):
    radiance = gpu_run["vct/light_voxels.radiance"]
    for wrong in [radiance.astype(np.float64), radiance[..., :3], radiance.reshape(-1, 4),
                  np.ascontiguousarray(radiance.transpose(2, 1, 0, 3))[:, :, :8]]:
        with pytest.raises(voxgi.InputError, match=r"the buffer \(16, 16, 16, 4\) float32"):
            voxgi.check(box, "vct/light_voxels.radiance", wrong)
    # A transposed layout of the right shape is not refused, but it fails: a cube's axes are
    # indistinguishable by shape, which is why docs/python.md states the order.
    swapped = np.ascontiguousarray(radiance.transpose(2, 1, 0, 3))
    assert not voxgi.check(box, "vct/light_voxels.radiance", swapped)["pass"]


def test_the_octrees_gpu_build_passes_in_canonical_order(box):
    gpu = voxgi.run(box, "svo", stage="svo/build", backend="gpu", threads=2)
    names = [n for n in gpu.names if n.startswith("svo/build.")]
    report = voxgi.check(box, {n: gpu[n] for n in names})
    assert report["pass"], report
    assert len(report["stages"][0]["buffers"]) == len(names) == 5
    # The pools are compared in the canonical order (common/svo/canonical.h): the same nodes
    # allocated in another order are another buffer.
    nodes = np.array(gpu["svo/build.nodes"])
    nodes[[1, 2]] = nodes[[2, 1]]
    assert not voxgi.check(box, "svo/build.nodes", nodes)["pass"]


def test_voxgi_diff_against_a_dump_folder(repo, voxgi_bin, tmp_path):
    import subprocess

    scene = str(repo / "scenes" / "cornell_box.json")
    size = ["--resolution", "16", "--image", "64"]

    def run(*args):
        return subprocess.run([voxgi_bin, *args], capture_output=True, text=True)

    gpu, other = tmp_path / "gpu", tmp_path / "antialiased"
    assert run("dump", scene, *size, "--stage", "vct/light_voxels", "--backend", "gpu", "--out",
               str(gpu)).returncode == 0
    assert run("dump", scene, *size, "--stage", "voxelize", "--mode", "antialiased", "--backend",
               "cpu", "--out", str(other)).returncode == 0
    passed = run("diff", scene, *size, "--stage", "vct/light_voxels", "--against", str(gpu))
    assert passed.returncode == 0, passed.stdout + passed.stderr
    assert "stage vct/light_voxels: PASS" in passed.stdout
    # Another engine's voxelization (antialiased coverage where the oracle is conservative).
    failed = run("diff", scene, *size, "--stage", "voxelize", "--against", str(other))
    assert failed.returncode == 1 and "stage voxelize: FAIL" in failed.stdout
    assert "opacity" in failed.stdout
    wrong = run("diff", scene, "--resolution", "32", "--stage", "voxelize", "--against",
                str(other))
    assert wrong.returncode == 2 and "voxgi_resolution" in wrong.stderr
    empty = run("diff", scene, *size, "--stage", "vct/mip", "--against", str(gpu))
    assert empty.returncode == 2 and "no dump of the stages" in empty.stderr
