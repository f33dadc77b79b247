"""A study's runs spread over a Dask cluster (a LocalCluster of 2 worker processes) and over the
shards of a batch job array (voxgi study --shard I/N, then --merge N) give the serial study's CSV:
every column but the times and what depends on them, bit for bit; so do a reference sequence's
frames (voxgi.path_trace_frames on the cluster, voxgi render --frames --shard I/N)."""
import csv
import subprocess

import pytest

import voxgi

# Columns that hold times, or depend on them (error per time, the Pareto fronts).
TIMED = {"seconds", "efficiency", "pareto", "pareto_technique"}


def untimed(rows):
    return [{k: v for k, v in row.items() if k not in TIMED and not k.endswith("_seconds")}
            for row in rows]


@pytest.fixture(scope="module")
def study(repo, voxgi_bin, tmp_path_factory):
    folder = tmp_path_factory.mktemp("study")
    reference = folder / "reference.exr"
    scene = repo / "scenes" / "cornell_box.json"
    subprocess.run([voxgi_bin, "render", str(scene), "--technique", "path", "--spp", "8",
                    "--image", "64", "--out", str(reference)], check=True, capture_output=True)
    args = dict(scene=scene, reference=reference, techniques=("vct", "path"),
                sweeps={"resolution": [16, 32], "spp": [1, 2]}, image=64, repeats=1)
    serial = voxgi.study(csv=folder / "serial.csv", **args)
    return folder, args, serial


def test_the_serial_study_has_every_job_and_the_baselines(study):
    _, _, serial = study
    assert [row["technique"] for row in serial] == ["vct", "vct", "path", "path",
                                                    "baseline_black", "baseline_constant"]
    assert all(float(row["rel_mse"]) > 0 for row in serial)


@pytest.fixture(scope="module")
def client():
    # scripts/setup installs python3-distributed: its absence fails, never skips, the test.
    import distributed
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True,
                                  dashboard_address=None) as cluster, \
            distributed.Client(cluster) as c:
        yield c


def test_a_dask_cluster_gives_the_serial_study(study, client):
    folder, args, serial = study
    spread = voxgi.study(csv=folder / "dask.csv", client=client, **args)
    assert untimed(spread) == untimed(serial)


def test_shards_merged_give_the_serial_study(study, voxgi_bin):
    folder, args, serial = study
    command = [voxgi_bin, "study", str(args["scene"]), "--technique", "vct,path",
               "--sweep", "resolution=16,32", "--sweep", "spp=1,2", "--image", "64",
               "--repeat", "1", "--reference", str(args["reference"]),
               "--csv", str(folder / "merged.csv")]
    for shard in ["0/3", "1/3", "2/3"]:
        subprocess.run(command + ["--shard", shard], check=True, capture_output=True)
    subprocess.run(command + ["--merge", "3"], check=True, capture_output=True)
    with open(folder / "merged.csv", newline="") as f:
        assert untimed(list(csv.DictReader(f))) == untimed(serial)
    # A merge with the shards of another command line, or one missing, is refused.
    other = subprocess.run(command[:4] + ["vct"] + command[5:] + ["--merge", "3"],
                           capture_output=True, text=True)
    assert other.returncode == 2 and "other options" in other.stderr
    (folder / "merged.csv.shard-1-of-3.json").unlink()
    missing = subprocess.run(command + ["--merge", "3"], capture_output=True, text=True)
    assert missing.returncode == 2 and "shard-1-of-3.json" in missing.stderr


def test_reference_frames_anywhere_are_the_serial_ones(repo, voxgi_bin, client, tmp_path):
    scene = repo / "scenes" / "bunny_turning.json"
    frames = [0, 6, 12]
    options = dict(spp=2, image=32)
    serial = voxgi.path_trace_frames(scene, frames, tmp_path / "serial_%04d.exr", **options)
    spread = voxgi.path_trace_frames(scene, frames, tmp_path / "dask_%04d.exr", client=client,
                                     **options)
    for shard in ["0/2", "1/2"]:
        subprocess.run([voxgi_bin, "render", str(scene), "--technique", "path", "--spp", "2",
                        "--image", "32", "--frames", "0:12:6", "--shard", shard, "--out",
                        str(tmp_path / "shard_%04d.exr")], check=True, capture_output=True)
    images = [voxgi.read_dump(path).tobytes() for path in serial]
    assert len(set(images)) == len(frames)  # the bunny turns
    for f, image in zip(frames, images):
        assert voxgi.read_dump(tmp_path / f"dask_{f:04d}.exr").tobytes() == image
        assert voxgi.read_dump(tmp_path / f"shard_{f:04d}.exr").tobytes() == image
