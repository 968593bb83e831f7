"""A drive cycle through the real-time evaluator: the DKFZD4012 at 2000 N preload driven over a
trapezoidal speed profile sampled at 1 kHz (accelerate to 1500 rpm, run, brake, reverse, run
back, stop), its drive torque from ``Evaluator.series`` (each point warm-started from the one
before, as a drive simulation steps it), and what the cycle comes to: the peak and RMS torque
and the energy the friction takes.

    python crates/py/examples/drive_cycle.py
"""

import numpy as np

import ballscrew

DT_S = 1e-3  # the drive's sample time, s
PRELOAD_N = 2000.0
PEAK_RPM = 1500.0


def profile_rpm():
    """The speed profile, rpm, one sample per DT_S: 0.2 s ramps, 0.5 s runs, 0.1 s stops."""
    ramp = np.linspace(0.0, PEAK_RPM, 201)[1:]
    run = np.full(500, PEAK_RPM)
    stop = np.zeros(100)
    forward = np.concatenate([ramp, run, ramp[::-1], stop])
    return np.concatenate([stop, forward, -forward])


speed_rpm = profile_rpm()
screw = ballscrew.Screw.dkfzd4012()
evaluator = ballscrew.Evaluator(screw, precision="f64")
torque_nm = evaluator.series(PRELOAD_N, speed_rpm=speed_rpm)

speed_rad_s = speed_rpm * 2.0 * np.pi / 60.0
peak_torque_nm = float(np.max(np.abs(torque_nm)))
rms_torque_nm = float(np.sqrt(np.mean(torque_nm**2)))
# The friction's power is torque times speed (>= 0: the torque opposes the motion).
friction_energy_j = float(np.sum(torque_nm * speed_rad_s) * DT_S)

print(f"DKFZD4012, preload {PRELOAD_N:.0f} N, {len(speed_rpm)} samples of {DT_S * 1e3:.0f} ms, peak {PEAK_RPM:.0f} rpm")
print(f"peak torque: {peak_torque_nm:.4f} N m")
print(f"rms torque: {rms_torque_nm:.4f} N m")
print(f"friction energy over the cycle: {friction_energy_j:.2f} J")
