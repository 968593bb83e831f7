"""ballscrew: friction (drag) torque of preloaded ball screws (Python bindings of the Rust core).

The creep-analysis model of Xu et al. (2015) with lubricated (EHL) contacts by default, as the
``ballscrew`` command line runs it::

    import ballscrew, numpy as np
    screw = ballscrew.Screw.dkfzd4012()                       # Table 1 of the paper
    screw.torque(2000.0)                                      # N m at 2000 N preload, 100 rpm
    screw.torque(np.linspace(500, 3000, 6), speed_rpm=300.0)  # arrays broadcast
    table = screw.sweep()                                     # the command line's sweep columns
    screw.sweep(oil_temperature_c=[20.0, 40.0, 60.0])         # over the oil temperature
    screw.sweep(speed_rpm=np.arange(100.0, 3001.0, 100.0))   # over the speed
    screw.with_oil_temperature(60.0).torque(2000.0)           # oil at 60 C at the contacts
    screw.band(2000.0)                                        # the drag torque's 5-95 % band
    screw.sensitivity(2000.0)                                 # what drives the band
    rev = ballscrew.Reversal(screw, preload_n=2000.0)         # friction through reversals
    rev.step(1e-4, 1e-3)                                      # N m after turning 1e-4 rad in 1 ms

Speeds are in rpm, loads in N, torques in N m, rotations in rad, time steps in s; every name
carries its unit. Invalid specs and inputs raise ``ValueError`` with the field, the value and the
valid range.
"""

from ballscrew import _ballscrew
from ballscrew._ballscrew import *  # noqa: F401,F403  (every public name of the native module)

# The package's version: the Rust crate's, which is the wheel's (a star import skips it).
__version__: str = _ballscrew.__version__

__all__ = sorted(name for name in dir(_ballscrew) if not name.startswith("_"))
