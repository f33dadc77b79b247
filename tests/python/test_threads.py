"""Stages run with the GIL released: while one thread is inside voxgi, Python code runs in
another (with the GIL held it could not run at all until the call returned); two threads running
stages at once each get what they get alone."""
import threading
import time

import voxgi


def test_python_runs_while_a_stage_runs(repo):
    scene = voxgi.load_scene(repo / "scenes" / "cornell_box.json", resolution=32, image=256)
    window = []

    def work():
        start = time.perf_counter()
        voxgi.render(scene, threads=1)
        window.extend([start, time.perf_counter()])

    worker = threading.Thread(target=work)
    ticks = []
    worker.start()
    while worker.is_alive():
        ticks.append(time.perf_counter())
    worker.join()
    start, end = window
    assert end - start > 0.05
    # The middle fifth of the call: the worker is inside voxgi's C++ there, and the main thread
    # must have run Python in it.
    lo, hi = start + 0.4 * (end - start), start + 0.6 * (end - start)
    assert any(lo <= t <= hi for t in ticks), f"no Python ran during the call ({start}, {end})"


def test_two_threads_running_stages_get_what_each_gets_alone(repo):
    scene = voxgi.load_scene(repo / "scenes" / "cornell_box.json", resolution=32, image=128)
    lpv = voxgi.load_scene(repo / "scenes" / "cornell_box_lpv.json", resolution=16, image=64)
    alone = [voxgi.render(scene, threads=1), voxgi.render(lpv, "lpv", threads=1)]
    images = [None, None]

    def work(i):
        images[i] = voxgi.render(scene, threads=1) if i == 0 else voxgi.render(lpv, "lpv",
                                                                              threads=1)

    threads = [threading.Thread(target=work, args=(i,)) for i in range(2)]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    for image, own in zip(images, alone):
        assert image.tobytes() == own.tobytes()
