"""Drag torque and load torque reported apart, the catalog comparison of the drag, and the
efficiency under an axial load."""

import json
import math

import pytest

import ballscrew

LEAD_M = 0.012  # the built-in DKFZD4012


@pytest.fixture(scope="module")
def screw():
    return ballscrew.Screw.dkfzd4012()


def test_drag_and_load_add_up_to_the_torque(screw):
    row = screw.summary(2000.0, axial_load_n=300.0)
    assert row["drag_torque_nm"] + row["load_torque_nm"] == pytest.approx(row["torque_nm"], rel=1e-12)
    assert row["load_torque_nm"] == pytest.approx(300.0 * LEAD_M / (2 * math.pi), rel=1e-9)
    # The catalog compares the drag alone.
    assert row["ratio"] == row["drag_torque_nm"] / row["catalog_nm"]
    assert "axial_term_nm" not in row


def test_efficiency_under_an_axial_load(screw):
    row = screw.summary(500.0, axial_load_n=3000.0)
    eta, eta_back = row["forward_efficiency"], row["backdrive_efficiency"]
    assert 0.9 < eta < 1.0 and 0.9 < eta_back < 1.0
    # Forward: the load torque over the drive torque at this point (positive speed, positive load).
    assert eta == pytest.approx(row["load_torque_nm"] / row["torque_nm"], rel=1e-12)
    assert row["backdrive_torque_nm"] == pytest.approx(eta_back * row["load_torque_nm"], rel=1e-12)
    # A large preload drag against a small load: self-locking, backdrive efficiency 0.
    locked = screw.summary(3000.0, axial_load_n=10.0)
    assert locked["backdrive_efficiency"] == 0.0 and locked["backdrive_torque_nm"] <= 0.0


def test_no_efficiency_without_a_load_or_a_speed(screw):
    for kwargs in (dict(preload_n=2000.0), dict(preload_n=2000.0, speed_rpm=0.0, axial_load_n=300.0)):
        row = screw.summary(**kwargs)
        for key in ("forward_efficiency", "backdrive_efficiency", "backdrive_torque_nm"):
            assert math.isnan(row[key]), (kwargs, key)


def test_sweep_columns_and_numbers_are_the_command_lines_under_a_load(cli):
    doc = json.loads(cli("sweep", "--preload", "500..3000", "--step", "500", "--axial-load-n", "300", "--format", "json"))
    table = ballscrew.Screw.dkfzd4012().sweep([500.0, 1000.0, 1500.0, 2000.0, 2500.0, 3000.0], axial_load_n=300.0, frame=False)
    keys = list(doc["rows"][0])
    assert list(table) == keys
    for i, expected in enumerate(doc["rows"]):
        for k in keys:
            assert float(table[k][i]) == pytest.approx(expected[k], rel=1e-12, abs=0), (i, k)
    drag = table["drag_torque_nm"]
    assert list(table["ratio"]) == list(drag / table["catalog_nm"])
