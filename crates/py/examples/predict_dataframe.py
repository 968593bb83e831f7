"""``ballscrew.predict`` on a pandas DataFrame: one row per operating point (preload, speed and
axial load in the column names the command line's ``predict`` reads), the model's drive torque
back as a ``Series`` named ``torque_nm`` on the frame's index, joined to the frame.

    python crates/py/examples/predict_dataframe.py
"""

import pandas as pd

import ballscrew

frame = pd.DataFrame(
    {
        "preload_n": [1000.0, 2000.0, 2000.0, 3000.0, 2000.0],
        "speed_rpm": [100.0, 100.0, 1000.0, 100.0, -300.0],
        "axial_load_n": [0.0, 0.0, 0.0, 0.0, 500.0],
    },
    index=pd.Index(["light", "nominal", "fast", "heavy", "loaded back"], name="point"),
)
# The built-in DKFZD4012 spec when none is given; `spec=` takes a Screw or a TOML path.
frame["torque_nm"] = ballscrew.predict(frame)
print(frame.to_string(formatters={"torque_nm": "{:.4f}".format}))
