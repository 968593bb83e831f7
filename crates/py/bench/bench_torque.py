"""Time of screw.torque(array) over 1e6 operating points (a benchmark script, not a test).

    python crates/py/bench/bench_torque.py [--points N] [--repeat R] [--seed S]

Operating points: DKFZD4012, preloads uniform in 500-3000 N, speeds uniform in 10-3000 rpm,
axial loads uniform in -500..500 N, in random order; also the same points sorted by preload
(a sweep-like batch). Prints the best wall time of R runs and the time per point.
"""

import argparse
import os
import time

import numpy as np

import ballscrew


def best_time(f, repeat):
    times = []
    for _ in range(repeat):
        start = time.perf_counter()
        f()
        times.append(time.perf_counter() - start)
    return min(times)


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--points", type=int, default=1_000_000)
    ap.add_argument("--repeat", type=int, default=1)
    ap.add_argument("--seed", type=int, default=2015)
    args = ap.parse_args()
    rng = np.random.default_rng(args.seed)
    n = args.points
    preload = rng.uniform(500.0, 3000.0, n)
    speed = rng.uniform(10.0, 3000.0, n)
    axial = rng.uniform(-500.0, 500.0, n)
    screw = ballscrew.Screw.dkfzd4012()
    print(f"ballscrew torque benchmark: {n} operating points, {os.cpu_count()} CPUs")
    for label, p, s, a in [
        ("random order", preload, speed, axial),
        ("sorted by preload, speed and axial load fixed", np.sort(preload), np.full(n, 100.0), np.zeros(n)),
    ]:
        t = best_time(lambda: screw.torque(p, speed_rpm=s, axial_load_n=a), args.repeat)
        print(f"  {label}: {t:.3f} s ({t / n * 1e6:.2f} us per point)")


if __name__ == "__main__":
    main()
