"""ballscrew: friction (drag) torque of preloaded ball screws (Python bindings of the Rust core)."""

from ballscrew._ballscrew import contact, dkfzd4012_torque_nm
from ballscrew._ballscrew import diagnose, predict

__all__ = ["contact", "dkfzd4012_torque_nm"]
