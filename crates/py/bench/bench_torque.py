"""Time of screw.torque(array) over a study grid and random points (a benchmark script, not a test).

    python crates/py/bench/bench_torque.py [--points N] [--random-points N] [--drive-points N]
                                           [--repeat R] [--seed S]

DKFZD4012. Two batches:
- a study grid of N points (default 27,000): 30 preloads (500-3000 N) x 30 axial loads
  (-500..500 N) x 30 speeds (10-3000 rpm, 15 forward and 15 reverse), broadcast from three
  axes, the shape of a parameter study. With the lubricated default every point is a balance
  of its own (the torque depends on the speed), solved cold over the cores (`ballscrew_batch`);
- random points (default 10,000): preloads, speeds and axial loads uniform over the same ranges,
  in random order.
Each batch is timed on a fresh Screw twice: canonical (the default: every point's cold solve)
and with start="warm" (the control-loop evaluator band by band of speed, its table built in the
call); their ratio is the cost of the canonical rule.
Then a drive cycle of N points (default 10,000) through `ballscrew.Evaluator` (the control-loop
evaluator), in f64 and f32: 2000 N preload, the speed a sine of 300 rpm amplitude (ten periods,
through standstill and reversals), the axial load a sine of 400 N amplitude (seven periods);
timed per call as a loop of `ev.torque(...)` in Python (what a Python control loop pays) and as
one `ev.series(...)` (the same points in order, without Python in the loop); and for comparison
the same loop of scalar `screw.torque(...)` calls (the analysis model, each call cold).
Then the band of the drag torque (the spec's default `[uncertainty]`, 128 samples): `screw.band`
at one point (2000 N, 100 rpm) and a 26-point `screw.sweep(band=True)` (the default preloads).
Prints the best wall time of R runs and the time per point.
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
    ap.add_argument("--points", type=int, default=27_000, help="points of the study grid (a cube)")
    ap.add_argument("--random-points", type=int, default=10_000)
    ap.add_argument("--drive-points", type=int, default=10_000, help="points of the evaluator's drive cycle")
    ap.add_argument("--repeat", type=int, default=1)
    ap.add_argument("--seed", type=int, default=2015)
    args = ap.parse_args()
    screw = ballscrew.Screw.dkfzd4012()
    dry_toml = screw.to_toml().replace('lubrication = "ehl"', 'lubrication = "dry"')
    print(f"ballscrew torque benchmark: DKFZD4012, {os.cpu_count()} CPUs")

    k = max(2, round(args.points ** (1 / 3)))
    preload = np.linspace(500.0, 3000.0, k)[:, None, None]
    axial = np.linspace(-500.0, 500.0, k)[None, :, None]
    half = np.linspace(10.0, 3000.0, k // 2)
    speed = np.concatenate([-half[::-1], half])[None, None, :]
    n = preload.size * axial.size * speed.size
    rng = np.random.default_rng(args.seed)
    m = args.random_points
    p = rng.uniform(500.0, 3000.0, m)
    s = rng.uniform(10.0, 3000.0, m) * rng.choice([-1.0, 1.0], m)
    a = rng.uniform(-500.0, 500.0, m)
    for label, fresh in [
        ("lubricated", ballscrew.Screw.dkfzd4012),
        ("dry", lambda: ballscrew.Screw.from_toml_str(dry_toml)),
    ]:
        # Each batch canonical (the default) and warm (start="warm": the evaluator band by band
        # of speed, its table built in the call); their ratio is the canonical rule's cost.
        for what, size, args3 in [
            (f"study grid {k} x {k} x {speed.size}", n, (preload, speed, axial)),
            ("random points", m, (p, s, a)),
        ]:
            t = best_time(lambda: fresh().torque(args3[0], speed_rpm=args3[1], axial_load_n=args3[2]), args.repeat)
            w = best_time(
                lambda: fresh().torque(args3[0], speed_rpm=args3[1], axial_load_n=args3[2], start="warm"), args.repeat
            )
            print(f"  {label}: {what} = {size} points: canonical {t:.3f} s ({t / size * 1e6:.1f} us per point), "
                  f"warm {w:.3f} s ({w / size * 1e6:.1f} us per point); canonical / warm {t / w:.1f}")

    drive_cycle(screw, args.drive_points, args.repeat)

    t = best_time(lambda: screw.band(2000.0, speed_rpm=100.0), args.repeat)
    print(f"  band at one point, 128 samples: {t:.3f} s")
    t = best_time(lambda: screw.sweep(band=True, frame=False), args.repeat)
    print(f"  sweep(band=True), 26 preloads x 128 samples: {t:.3f} s ({t / 26 * 1e3:.1f} ms per point)")


def drive_cycle(screw, n, repeat):
    """The evaluator over a drive cycle of `n` points (see the module docs)."""
    phase = np.linspace(0.0, 2.0 * np.pi, n, endpoint=False)
    speed = 300.0 * np.sin(10.0 * phase)
    axial = 400.0 * np.sin(7.0 * phase)
    points = [(2000.0, float(s), float(a)) for s, a in zip(speed, axial)]

    def loop(torque):
        for p, s, a in points:
            torque(p, s, a)

    for precision in ("f64", "f32"):
        ev = ballscrew.Evaluator(screw, precision)

        def calls(ev=ev):
            ev.reset()
            loop(ev.torque)

        t = best_time(calls, repeat)
        print(f"  Evaluator({precision!r}) drive cycle, {n} torque() calls: {t:.3f} s ({t / n * 1e6:.2f} us per call)")
        t = best_time(lambda ev=ev: (ev.reset(), ev.series(2000.0, speed_rpm=speed, axial_load_n=axial)), repeat)
        print(f"  Evaluator({precision!r}) drive cycle, one series() of {n} points: {t:.3f} s ({t / n * 1e6:.2f} us per point)")
    t = best_time(lambda: loop(screw.torque), repeat)
    print(f"  Screw drive cycle, {n} scalar torque() calls: {t:.3f} s ({t / n * 1e6:.2f} us per call)")


if __name__ == "__main__":
    main()
