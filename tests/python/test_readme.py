"""README.md's commands run as written, at small sizes, so that a README that drifts from the tool
fails CI: every command of its indented blocks, in order, in a scratch copy of scenes/ (the
repository's tests/ beside it), the `voxgi` of the build for `voxgi` and `build/tools/voxgi`.

Sizes are lowered by rewriting options only (16^3 grids, 32-pixel images, a few samples, a few
frames: `small`); the files the README leaves to its reader (a model of one's own, another
engine's dumps, a mask, path-traced references) are made first (`readers_files`). A command of the
README that is neither run nor listed in NOT_RUN with its reason fails the test, and so does a
NOT_RUN entry the README no longer holds."""
import os
import pathlib
import re
import shlex
import shutil
import subprocess

import numpy as np
import pytest

# Commands the test does not run, each with why; each must still be in README.md, and a script's
# file must exist and be executable.
NOT_RUN = {
    "scripts/setup": "installs Debian packages and builds: CI's first step",
    "scripts/test": "this suite",
    "scripts/output_hashes": "every scene, technique, preset and backend: 20 minutes",
    "scripts/lpv_study": "docs/lpv.md's study: 25 minutes",
    "scripts/references": "1024-spp references of every shipped scene",
    "scripts/convergence": "docs/path-tracer.md's study: minutes",
    "scripts/accuracy": "docs/accuracy.md's study: minutes",
    "scripts/fuzz": "scripts/test runs every fuzz target",
    "voxgi study ... --shard": "the job array's pattern (`...`: the study's own arguments); "
                               "Cli.StudyShards* run shards and their merge",
    "voxgi study ... --merge": "as above",
}

# Small sizes for the benches, by bench.
BENCH = {
    "voxelize": ["--resolutions", "16", "--triangles", "2000", "--repeat", "1"],
    "vct": ["--resolutions", "16", "--images", "32", "--threads-list", "1", "--mip-resolution", "0",
            "--repeat", "1"],
    "lpv": ["--resolutions", "16", "--steps", "2", "--threads-list", "1", "--repeat", "1"],
    "svo": ["--points", "20000", "--depths", "4", "--stage-depths", "4", "--threads-list", "1",
            "--repeat", "1"],
    "path": ["--image", "32", "--spp", "2", "--reference-spp", "16", "--repeat", "1"],
}
SCENE_COMMANDS = {"render", "dump", "diff", "plan", "ledger"}


def readme_commands(text):
    """(command, the README's line) for each shell command of the indented blocks: continuation
    lines joined, comments dropped, `;`-separated commands split; the Python example as one."""
    commands, python = [], []
    lines = [line[4:] for line in text.splitlines() if line.startswith("    ")]
    i = 0
    while i < len(lines):
        line = lines[i]
        while line.rstrip().endswith("\\") and i + 1 < len(lines):
            i += 1
            line = line.rstrip()[:-1] + " " + lines[i].strip()
        i += 1
        code = re.sub(r"\s+#.*$", "", line).strip()
        if not code or code.startswith("#"):
            continue
        if code.startswith(("import ", "run = ", "radiance = ", "print(")):
            python.append(code)
            continue
        commands += [(part.strip(), code) for part in code.split(";") if part.strip()]
    return commands, "\n".join(python)


def option(args, name, value):
    """`args` with option `name` set to `value` (replaced where given, else appended)."""
    if name in args:
        args[args.index(name) + 1] = value
    else:
        args += [name, value]
    return args


def small(args):
    """The command at small sizes (see the module's docstring)."""
    sub = args[0]
    if sub in SCENE_COMMANDS and "--help" not in args:
        option(args, "--resolution", "16")
        option(args, "--image", "32")
    if sub == "voxelize":
        option(args, "--resolution", "16")
    if "--spp" in args:
        option(args, "--spp", "2")
    if "--points" in args:
        option(args, "--points", "20000")
    if "--frames" in args:  # 0:48 -> 0:4; 0:48:8 -> 0:16:8 (two frames, as the references)
        parts = args[args.index("--frames") + 1].split(":")
        parts[1] = str(int(parts[0]) + (16 if len(parts) > 2 else 4))
        option(args, "--frames", ":".join(parts))
    if sub == "study":
        args = [re.sub(r"^resolution=.*", "resolution=16", re.sub(r"^spp=.*", "spp=1", a))
                for a in args]
        option(args, "--image", "32")
        if "--frames" in args:
            option(args, "--resolution", "16")
    if sub == "bench":
        args += BENCH[args[1]]
    return args


def readers_files(voxgi, work):
    """What the README leaves to its reader, made in `work`."""
    shutil.copy(work / "tests/data/scenes/blender_room.glb", work / "model.glb")  # camera Cam
    run = lambda *a: subprocess.run([voxgi, *a], cwd=work, check=True, capture_output=True)
    # Another engine's dumps: here the CPU's own.
    run("dump", "scenes/bunny.json", "--stage", "all", "--resolution", "16", "--image", "32",
        "--out", "theirs")
    (work / "references").mkdir()
    # As scripts/references makes them: with their light terms.
    run("render", "scenes/cornell_box.json", "--technique", "path", "--spp", "4", "--image", "32",
        "--terms", "--out", "references/cornell_box.exr")
    run("render", "scenes/cornell_box_moving_block.json", "--technique", "path", "--spp", "4",
        "--image", "32", "--frames", "0:16:8", "--out",
        "references/cornell_box_moving_block_%04d.exr")
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    mask = np.ones((32, 32, 3))
    mask[:, :8] = 0.0  # a mask that leaves pixels out
    plt.imsave(work / "mask.png", mask)


def test_the_readmes_commands_run(repo, voxgi_bin, tmp_path):
    commands, python = readme_commands((repo / "README.md").read_text())
    assert len(commands) > 40, "the README's commands were not found"
    work = tmp_path
    shutil.copytree(repo / "scenes", work / "scenes",
                    ignore=shutil.ignore_patterns("cornell_box_cloud.ply"))
    os.symlink(repo / "tests", work / "tests")
    readers_files(voxgi_bin, work)
    seen = set()
    for command, line in commands:
        skip = next((key for key in NOT_RUN if command.startswith(key)), None)
        if skip:
            seen.add(skip)
            if command.startswith("scripts/"):
                script = repo / command.split()[0]
                assert script.is_file() and os.access(script, os.X_OK), f"{line}: no {script}"
            continue
        args = shlex.split(command)
        assert args[0] in ("voxgi", "build/tools/voxgi"), f"README command not run: {line}"
        done = subprocess.run([voxgi_bin, *small(args[1:])], cwd=work, capture_output=True,
                              text=True)
        assert done.returncode == 0, f"{line}\n{done.stdout[-2000:]}{done.stderr[-2000:]}"
    assert seen == set(NOT_RUN), f"NOT_RUN entries the README no longer has: {set(NOT_RUN) - seen}"
    assert "import voxgi" in python
    cwd = os.getcwd()
    os.chdir(work)
    try:
        exec(compile(python, "README.md", "exec"), {})
    finally:
        os.chdir(cwd)
