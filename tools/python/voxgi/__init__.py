"""voxgi from Python: scenes, plans, stages on the CPU or GPU backend, every buffer as a NumPy
array without a copy, the path tracer, image metrics, and your own engine's buffers checked
against voxgi's CPU oracle. docs/python.md has a worked example.

Names are the CLI's: techniques ("vct", "lpv", "holpv", "svo"), stages ("voxelize",
"vct/trace_cones"), buffers ("vct/light_voxels.radiance") and settings keys ("cones.set").
Bad input raises voxgi.InputError (a ValueError) with the one-line message the CLI prints.
Every call that computes releases the GIL, and takes `threads` (None: every core).
"""

import csv as _csv
import json
import os

from . import _voxgi
from ._voxgi import InputError, Run, Scene

__all__ = [
    "InputError", "Run", "Scene", "load_scene", "techniques", "stages", "buffers", "settings",
    "presets", "plan", "run", "dump", "render", "diff", "check", "path_trace", "compare",
    "read_dump", "mip_levels", "study", "path_trace_frames",
]


def load_scene(source, *, base_dir=".", camera="", resolution=None, image=None):
    """Loads a scene: a path (a scene .json, or a bare OBJ, glTF or PLY file) or a dict in the
    scene format (docs/scene-format.md), whose file names are relative to `base_dir`.
    `resolution` overrides the grid's (a power of two), `image` the image width (the height keeps
    the camera's aspect), `camera` picks a glTF camera by name."""
    if isinstance(source, dict):
        text = json.dumps(source)
        path = os.path.join(base_dir, "<dict>.json")
    else:
        text = None
        path = os.fspath(source)
    return _voxgi.load_scene(path, text, camera, resolution, image)


def _scene(scene):
    return scene if isinstance(scene, Scene) else load_scene(scene)


def _assignments(settings):
    """{"cones.set": "equal7"} or ["cones.set=equal7"] as the CLI's --set assignments."""
    if settings is None:
        return []
    if isinstance(settings, dict):
        out = []
        for key, value in settings.items():
            if isinstance(value, bool):
                value = "true" if value else "false"
            out.append(f"{key}={value}")
        return out
    return list(settings)


def techniques():
    """The techniques: name, summary, stages (in graph order), image (the buffer it renders)."""
    return _voxgi.techniques()


def stages(technique):
    """The stages `technique` runs, in graph order ("voxelize", "vct/light_voxels", ...)."""
    for t in techniques():
        if t["name"] == technique:
            return t["stages"]
    _voxgi.presets(technique)  # raises the registry's InputError, naming the techniques


def buffers(technique=None):
    """The declared buffers (of `technique`'s stages, or all): name, stage, dtype, components,
    shape (volume, mips, mips6, image, series, maps, sparse), needs (the plan's effect) and
    meaning. docs/python.md, "Arrays", gives each shape's array."""
    return _voxgi.buffers(technique or "")


def settings(technique):
    """The settings keys `technique` reads: key, default, range and meaning."""
    return _voxgi.settings(technique)


def presets(technique):
    """The technique's presets: name -> its "key=value" assignments."""
    return _voxgi.presets(technique)


def plan(scene, technique="vct", *, preset="default", settings=None):
    """What the technique's planner decides for the scene: items (each stage, buffer and effect,
    in or out, and why), the stages it runs, and every setting's value."""
    return _voxgi.plan(_scene(scene), technique, preset, _assignments(settings))


def run(scene, technique="vct", *, stage=None, backend="cpu", gl="egl", preset="default",
        settings=None, threads=None, inspect=False):
    """Runs the planned stages up to `stage` (all when None) on the CPU or GPU backend ("auto": a
    hardware GPU through EGL if there is one, else the CPU). Returns a voxgi.Run: run.names lists
    the buffers it holds, run[name] is one as a read-only NumPy array sharing the run's memory,
    run.dump(folder) writes them as `voxgi dump` does. `inspect` keeps the intermediate volumes a
    render drops (lpv: every propagation step), as voxgi diff and dump do."""
    return _voxgi.run(_scene(scene), technique, stage or "", backend, gl, preset,
                      _assignments(settings), threads or 0, inspect)


def dump(scene, out, technique="vct", *, stage=None, **options):
    """voxgi dump: runs the stages up to `stage` (all when None) with inspect=True and writes
    their buffers (of `stage` alone when given) to the folder `out` as <stage>.vdb and
    <stage>.<buffer>.exr; options as run()'s. Returns the paths written."""
    r = run(scene, technique, stage=stage, inspect=True, **options)
    return r.dump(os.fspath(out), stage or "")


def _run_getitem(self, name):
    return self.array(name)


def _run_buffers(self):
    return {name: self.array(name) for name in self.names}


Run.__getitem__ = _run_getitem
Run.buffers = property(_run_buffers, doc="every buffer of the run, name -> array (no copies)")


def render(scene, technique="vct", **options):
    """The technique's image, (height, width, 3) float32 linear RGB; options as run()'s."""
    r = run(scene, technique, **options)
    image = next(t["image"] for t in techniques() if t["name"] == technique)
    return r[image]


def diff(scene, technique="vct", *, stage="all", gl="egl", preset="default", settings=None,
         threads=None):
    """voxgi diff: the stages on both backends, every buffer through its registered comparison.
    Returns the report `voxgi diff --json` writes ({"pass", "stages": [...]})."""
    return _voxgi.diff(_scene(scene), technique, stage, gl, preset, _assignments(settings),
                       threads or 0)


def check(scene, buffer, array=None, *, technique=None, preset="default", settings=None,
          threads=None):
    """Checks a buffer made outside voxgi against the CPU oracle's, with the buffer's registered
    comparison (tolerance, ties, the octree's canonical order). `buffer` names it and `array`
    holds it, or `buffer` is a dict of name -> array, all of one stage. The array must have the
    dtype and shape voxgi's own has (docs/python.md, "Arrays"). Returns the report voxgi diff
    gives; report["pass"] says whether it matched, and each buffer's worst_element where not.
    `technique` defaults to the buffer's owner (vct for the shared stages' buffers)."""
    arrays = buffer if isinstance(buffer, dict) else {buffer: array}
    if technique is None:
        first = next(iter(arrays))
        technique = first.split("/")[0] if "/" in first else "vct"
    return _voxgi.check(_scene(scene), technique, preset, _assignments(settings), threads or 0,
                        arrays)


def path_trace(scene, *, spp=64, seed=0, bounces=-1, replicas=2, sampler="sobol", threads=None):
    """The Embree reference path tracer (docs/path-tracer.md): image and variance, each
    (height, width, 3) float32, with the rays traced and the seconds taken."""
    return _voxgi.path_trace(_scene(scene), spp, seed, bounces, replicas, sampler, threads or 0)


def compare(test, reference, *, mask=None, units="mean"):
    """voxgi compare's metrics of an image against a reference (both (height, width, 3)), beside
    what a black and a constant image score on the same reference (docs/accuracy.md)."""
    return _voxgi.compare(test, reference, mask, units)


def read_dump(path):
    """A dump voxgi wrote: a .vdb as name -> {array, origin, transform, metadata} for every grid
    (int32 ones included), the array dense over the grid's level ([0, N >> level)^3 from origin),
    indexed [k, j, i(, c)], transform the 4x4 index-to-world matrix for column vectors, u32
    buffers' grids as uint32; an .exr as its (height, width, 3) float32 image."""
    grids = _voxgi.read_dump(os.fspath(path))
    if isinstance(grids, dict):
        # OpenVDB has no unsigned grids: voxgi writes its u32 buffers' words as int32 grids
        for grid in grids.values():
            if grid["metadata"].get("voxgi_type") == "u32":
                grid["array"] = grid["array"].view("uint32")
    return grids


def mip_levels(array, resolution, faces=1):
    """The levels 1..log2(N) of a mips (faces=1) or mips6 (faces=6) buffer's array as views,
    level l of shape (N>>l, N>>l, faces*(N>>l), C): the six faces side by side along x."""
    levels = []
    offset = 0
    side = resolution >> 1
    while side >= 1:
        count = faces * side ** 3
        levels.append(array[offset:offset + count].reshape(side, side, faces * side, -1))
        offset += count
        side >>= 1
    return levels


def _study_jobs(options, jobs):
    """A Dask task: some of a study's jobs, run where the task runs; their records."""
    from . import _voxgi as core  # imported on the worker
    return core.study_jobs(options, jobs)


def study(scene, reference, csv, *, techniques=("vct",), sweeps=None, preset="default",
          settings=None, mask="", plot="", metric="rel_mse", image=None, resolution=None,
          repeats=3, terms=False, skip_emitters=False, units="mean", gl="egl", client=None):
    """voxgi study: every combination of `sweeps` ({"resolution": [32, 64], "spp": [1, 16]}, or
    the command's "key=v1,v2" strings) for each of `techniques` (any of voxgi's, and "path"),
    timed and measured against the `reference` image (.exr), written to `csv` (and `plot`, a PNG)
    with the baselines and Pareto fronts. Returns the CSV's rows as dicts.

    With `client` (a dask.distributed Client), each job runs as a task on the cluster's workers
    (which must see the scene and reference at the same paths and import voxgi), and the caller
    writes the CSV from their records: every column but the times and what depends on them
    (efficiency, the Pareto fronts) equals the serial run's bit for bit."""
    if isinstance(sweeps, dict):
        sweeps = [f"{key}=" + ",".join(str(v) for v in values) for key, values in sweeps.items()]
    options = json.dumps({
        "scene": os.fspath(scene), "techniques": list(techniques), "sweeps": list(sweeps or []),
        "preset": preset, "settings": _assignments(settings), "reference": os.fspath(reference),
        "mask": os.fspath(mask), "csv": os.fspath(csv), "plot": os.fspath(plot), "metric": metric,
        "gl": gl, "image": image or 0, "resolution": resolution or 0, "repeats": repeats,
        "terms": terms, "skip_emitters": skip_emitters, "units": units})
    if client is None:
        _voxgi.study(options)
    else:
        count = _voxgi.study_job_count(options)
        futures = client.map(_study_jobs, [options] * count, [[k] for k in range(count)],
                             pure=False)
        records = [r for part in client.gather(futures) for r in part]
        _voxgi.study_merge(options, records)
    with open(csv, newline="") as f:
        return list(_csv.DictReader(f))


def _path_trace_frame(args, frame):
    """A Dask task: one frame of a reference sequence, written where the task runs."""
    from . import _voxgi as core  # imported on the worker
    return core.path_trace_frame(*args, frame)


def path_trace_frames(scene, frames, out, *, fps=24.0, spp=64, seed=0, bounces=-1, replicas=2,
                      sampler="sobol", image=None, camera="", client=None):
    """The path tracer's reference of `frames` (frame numbers) of a scene file, frame f at f / fps
    seconds, as `voxgi render --technique path --frames` writes them: `out` holds a frame field
    (%04d), each image's variance beside it. With `client` (a dask.distributed Client) each frame
    is a task on the cluster's workers, which must see the scene and the output folder at the same
    paths; each frame is the same wherever it runs. Returns the images' paths."""
    args = (os.fspath(scene), camera, image or 0, float(fps), os.fspath(out), spp, seed, bounces,
            replicas, sampler)
    frames = list(frames)
    if client is None:
        return [_voxgi.path_trace_frame(*args, f) for f in frames]
    futures = client.map(_path_trace_frame, [args] * len(frames), frames, pure=False)
    return client.gather(futures)
