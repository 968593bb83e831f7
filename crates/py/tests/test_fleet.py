"""A fleet diagnosis (one CSV file per machine) run in parallel gives the serial loop's reports:
with multiprocessing in processes started by 'spawn' (the screw and the calls reach the workers
only by pickling), with concurrent.futures, and with Dask when it is installed (docs/fleet.md)."""

import concurrent.futures
import functools
import multiprocessing
import sys
import time

import numpy as np
import pytest

import ballscrew

MACHINES = 4


def write_fleet(directory, screw):
    """One CSV file per machine: the screw's torque at four preloads and two speeds, repeated
    over the running time, with a wear loss of its own per machine and measurement noise."""
    rng = np.random.default_rng(7)
    paths = []
    preload = np.tile(np.repeat([1000.0, 1600.0, 2200.0, 2800.0], 2), 4)
    speed = np.tile([200.0, -200.0], preload.size // 2)
    hours = np.repeat(np.linspace(0.0, 2000.0, 4), preload.size // 4)
    model = screw.torque(preload, speed_rpm=speed)
    for m in range(MACHINES):
        loss = 0.02 * (m + 1)  # per 1000 h
        torque = model * (1.0 - loss * hours / 1000.0) + rng.normal(0.0, 2e-4, preload.size)
        path = directory / f"machine-{m:02d}.csv"
        rows = "\n".join(f"{p!r},{s!r},{h!r},{t!r}" for p, s, h, t in zip(*(a.tolist() for a in (preload, speed, hours, torque))))
        path.write_text("preload_n,speed_rpm,time_h,torque_nm\n" + rows + "\n")
        paths.append(str(path))
    return paths


@pytest.fixture(scope="module")
def fleet(tmp_path_factory):
    screw = ballscrew.Screw.dkfzd4012()
    paths = write_fleet(tmp_path_factory.mktemp("fleet"), screw)
    start = time.perf_counter()
    serial = [ballscrew.diagnose(p, spec=screw) for p in paths]
    print(f"serial diagnosis of {len(paths)} machines: {time.perf_counter() - start:.2f} s")
    # The data shows each machine's wear, so the reports differ from machine to machine.
    losses = [r["findings"][0]["parameters"]["loss_per_1000_h"] for r in serial if r["findings"]]
    assert len(losses) == MACHINES and losses == sorted(losses), losses
    return screw, paths, serial


def same_reports(got, want):
    # As printed: the reports hold NaN where a value is undefined (NaN != NaN); their numpy arrays
    # printed whole, to the last digit.
    with np.printoptions(threshold=sys.maxsize, floatmode="unique"):
        assert [repr(r) for r in got] == [repr(r) for r in want]


def test_multiprocessing_spawn_gives_the_serial_reports(fleet):
    screw, paths, serial = fleet
    start = time.perf_counter()
    with multiprocessing.get_context("spawn").Pool(2) as pool:
        reports = pool.map(functools.partial(ballscrew.diagnose, spec=screw), paths)
    print(f"multiprocessing (spawn, 2 processes): {time.perf_counter() - start:.2f} s")
    same_reports(reports, serial)


def test_concurrent_futures_processes_give_the_serial_reports(fleet):
    screw, paths, serial = fleet
    context = multiprocessing.get_context("spawn")
    with concurrent.futures.ProcessPoolExecutor(max_workers=2, mp_context=context) as pool:
        reports = list(pool.map(ballscrew.diagnose, paths, [screw] * len(paths)))
    same_reports(reports, serial)


def test_dask_gives_the_serial_reports(fleet):
    dask = pytest.importorskip("dask")
    screw, paths, serial = fleet
    tasks = [dask.delayed(ballscrew.diagnose)(p, spec=screw) for p in paths]
    # Processes: everything a task holds is pickled to its worker.
    (reports,) = dask.compute(tasks, scheduler="processes", num_workers=2)
    same_reports(reports, serial)
