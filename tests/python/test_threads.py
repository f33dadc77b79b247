"""Stages run with the GIL released: while one thread is inside voxgi, Python code runs in
another (with the GIL held it could not run at all until the call returned); two threads running
stages at once each get what they get alone."""
import sys
import threading

import voxgi


def test_python_runs_while_a_stage_runs(repo):
    """With the interpreter's switch interval out of reach, a thread gives up the GIL only where it
    blocks or where C++ releases it. The worker sets out to run the stages (voxgi.run, the call
    that computes, and nothing else); the main thread, woken, runs a fixed piece of Python work.
    Released, the GIL passes to the main thread while the stages run, and the worker, back from
    C++, waits for the main thread to block: the main thread's work ends first. Held, the main
    thread runs only once the worker is done. An order of events, not a window of time."""
    scene = voxgi.load_scene(repo / "scenes" / "cornell_box.json", resolution=16, image=64)
    setting_out = threading.Event()
    order = []

    def work():
        setting_out.set()
        voxgi.run(scene, threads=1)
        order.append("run returned")

    interval = sys.getswitchinterval()
    sys.setswitchinterval(1000.0)
    try:
        worker = threading.Thread(target=work)
        worker.start()
        setting_out.wait()
        total = sum(i * i for i in range(20000))
        order.append("main thread's work done")
        worker.join()
    finally:
        sys.setswitchinterval(interval)
    assert total == 2666466670000
    assert order == ["main thread's work done", "run returned"], order


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
