"""The GIL is released during long calls (other Python threads run meanwhile), concurrent
calls from several threads give the same answers, and a million calls do not leak."""

import os
import sys
import threading
import time

import numpy as np

import lac

GOOD = [(-1.0, 0.0), (-0.2, 0.8), (1.0, 0.0)]


def big_batch(n: int) -> np.ndarray:
    rng = np.random.default_rng(7)
    middle = np.stack([rng.uniform(-0.3, 0.3, n), rng.uniform(0.2, 1.0, n)], axis=1)
    points = np.zeros((n, 3, 2))
    points[:, 0] = (-1.0, 0.0)
    points[:, 1] = middle
    points[:, 2] = (1.0, 0.0)
    return points


def main_thread_steps_during(call) -> int:
    """How many steps the main thread takes while another thread is inside `call`.

    The switch interval is made longer than the test, so no thread is ever asked to drop
    the GIL: the main thread hands it over only in `time.sleep(0)` between its steps, and
    the worker keeps it from its first timestamp to its second unless the call itself
    releases it. So steps stamped between the worker's two timestamps exist exactly when
    the call releases the GIL."""
    window = []
    steps = []
    done = threading.Event()

    def worker() -> None:
        t0 = time.perf_counter()
        call()
        window.extend([t0, time.perf_counter()])
        done.set()

    interval = sys.getswitchinterval()
    sys.setswitchinterval(1000.0)
    try:
        thread = threading.Thread(target=worker)
        thread.start()
        while not done.is_set():
            time.sleep(0)
            steps.append(time.perf_counter())
        thread.join()
    finally:
        sys.setswitchinterval(interval)
    t0, t1 = window
    return sum(1 for t in steps if t0 < t < t1)


def test_the_gil_test_can_fail():
    """A C call that holds the GIL (sorting a list) lets the main thread take no step."""
    data = np.random.default_rng(1).random(1_000_000).tolist()  # Python floats
    assert main_thread_steps_during(lambda: sorted(data)) == 0


def test_gil_is_released_during_solve_segments():
    points = big_batch(200_000)
    assert main_thread_steps_during(lambda: lac.solve_segments(points, 0.5, samples=4)) > 100


def test_gil_is_released_during_sampling_and_regions():
    seg = lac.Segment(GOOD, 0.5)
    assert main_thread_steps_during(lambda: seg.sample(3_000_000)) > 100
    assert main_thread_steps_during(lambda: lac.drawable_region(-1.0, 700)) > 100


def test_threads_agree():
    points = big_batch(2_000)
    expected = lac.solve_segments(points, -1.0).arc_length
    answers: list = [None] * 4

    def worker(i: int) -> None:
        singles = np.array([lac.Segment(p, -1.0).arc_length if ok else np.nan
                            for p, ok in zip(points[i::4], ~np.isnan(expected[i::4]))])
        answers[i] = (lac.solve_segments(points, -1.0).arc_length, singles)

    threads = [threading.Thread(target=worker, args=(i,)) for i in range(4)]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    for i, (batch, singles) in enumerate(answers):
        assert np.array_equal(batch, expected, equal_nan=True)
        assert np.array_equal(singles, expected[i::4], equal_nan=True)


def rss_bytes() -> int:
    with open("/proc/self/statm") as f:
        return int(f.read().split()[1]) * os.sysconf("SC_PAGE_SIZE")


def test_a_million_calls_do_not_leak():
    """A million constructions, property reads, samplings and raised errors: the resident
    size after them is within 8 MB of what it was after the first hundred thousand (a leak
    of one 24-byte object per call would add 24 MB)."""
    bad = [(0.0, 0.0), (1.0, 0.0), (2.0, 0.0)]
    points = np.array(GOOD)

    def calls(n: int) -> None:
        for i in range(n):
            seg = lac.Segment(points if i % 2 else GOOD, 0.5)
            seg.arc_length
            if i % 10 == 0:
                seg.sample(4).points
                try:
                    lac.Segment(bad, 0.5)
                except lac.InvalidInput:
                    pass
            if i % 1000 == 0:
                lac.solve_segments(points[None], 0.5, samples=3)

    calls(100_000)
    before = rss_bytes()
    calls(900_000)
    grown = rss_bytes() - before
    assert grown < 8 * 2**20, f"resident size grew by {grown / 2**20:.1f} MB"
