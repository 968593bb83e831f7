"""``ballscrew.diagnose`` on the XJTU ball-screw data (tests/data/xjtu-ball-screw: the friction
torque of a 32 x 8 screw measured over its running time) against its spec
(configs/xjtu-32x8.toml): what the diagnosis finds (a loss of preload), its fitted rate, and
how much the finding cuts the held-out error of the model.

    python crates/py/examples/xjtu_diagnosis.py
"""

import pathlib

import ballscrew

ROOT = pathlib.Path(__file__).resolve().parents[3]
DATA = ROOT / "tests" / "data" / "xjtu-ball-screw" / "friction_torque.csv"
SPEC = ROOT / "configs" / "xjtu-32x8.toml"

# The data's own column names: the running time in hours, the upper screw's torque in N m.
report = ballscrew.diagnose(DATA, spec=SPEC, columns={"time_h": "hours", "torque_nm": "upper_screw_torque_Nm"})
effects = [f["effect"] for f in report["findings"]]
loss_per_1000_h = report["findings"][0]["parameters"]["loss_per_1000_h"] if effects else float("nan")
heldout_rmse_cut = report["gain"]["heldout_rmse_cut"]

print(f"rows: {len(report['row_torques']['measured_torque_nm'])}")
print(f"findings: {', '.join(effects) or 'none'}")
print(f"preload loss: {100.0 * loss_per_1000_h:.2f} % of the preload per 1000 h")
print(f"held-out RMSE cut by the finding: {100.0 * heldout_rmse_cut:.1f} %")
print(f"extended model RMSE: {report['extended']['metrics']['rmse_nm']:.4f} N m")
