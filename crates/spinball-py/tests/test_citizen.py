"""Good citizenship: the GIL is released while Rust computes, and Ctrl-C
(SIGINT) stops a long run promptly with KeyboardInterrupt."""

import os
import signal
import threading
import time

import pytest

import spinball as sb


def test_other_python_threads_run_during_a_computation():
    started, done = threading.Event(), threading.Event()
    out = {}

    def work():
        started.set()
        # ~1e8 collisions on one thread: a few tenths of a second or more.
        out["r"] = sb.lyapunov("stadium:a=1", 0.5, ics=10_000, collisions=10_000,
                               method="tangent", threads=1)
        done.set()

    worker = threading.Thread(target=work)
    worker.start()
    started.wait()
    ticks = 0
    t0 = time.perf_counter()
    while not done.is_set():
        ticks += 1
    elapsed = time.perf_counter() - t0
    worker.join()
    assert out["r"].n_ics == 10_000
    # Were the GIL held for the whole run, this loop could not have turned
    # while it lasted; released, it turns millions of times per second.
    assert elapsed > 0.05, elapsed
    assert ticks > 10_000, (ticks, elapsed)


@pytest.mark.skipif(not hasattr(signal, "pthread_kill"), reason="needs POSIX signals")
def test_ctrl_c_stops_a_long_run():
    main = threading.get_ident()
    # Python raises KeyboardInterrupt on SIGINT only if it found SIGINT at
    # its default when it started; a shell starting a command in the
    # background (`.ci/run &`) hands it SIGINT ignored, and the run below
    # would then go on for hours. Install Python's handler for this test.
    previous = signal.signal(signal.SIGINT, signal.default_int_handler)
    # A run of ~1e11 collisions (hours) in batches of 64 ICs; SIGINT after 0.3 s.
    timer = threading.Timer(0.3, lambda: signal.pthread_kill(main, signal.SIGINT))
    t0 = time.perf_counter()
    timer.start()
    try:
        with pytest.raises(KeyboardInterrupt):
            sb.lyapunov("stadium:a=1", 0.5, ics=10_000_000, collisions=10_000,
                        target_rel_sem=0.0, batch=64)
    finally:
        timer.cancel()
        signal.signal(signal.SIGINT, previous)
    assert time.perf_counter() - t0 < 10.0
    # The module still works afterwards.
    assert sb.lyapunov("stadium:a=1", 0.5, ics=8, collisions=100).n_ics == 8
    assert os.getpid() > 0
