"""Smoke tests of the Python module skeleton: it loads, computes the same model, rejects bad input."""

import math

import pytest

import ballscrew


def test_torque_rises_with_preload_and_is_below_the_catalog_estimate():
    t500 = ballscrew.dkfzd4012_torque_nm(500.0)
    t3000 = ballscrew.dkfzd4012_torque_nm(3000.0)
    assert 0.0 < t500 < t3000
    # docs/reference/catalog_drag_torque.csv: 0.9271 N m at 3000 N; the model stands below (docs/prediction.md).
    assert t3000 < 0.9271


def test_reverse_rotation_reverses_the_torque():
    assert ballscrew.dkfzd4012_torque_nm(2000.0, -100.0) == pytest.approx(
        -ballscrew.dkfzd4012_torque_nm(2000.0, 100.0), rel=0.05
    )


@pytest.mark.parametrize("bad", [math.nan, math.inf, -1.0])
def test_invalid_preload_raises_value_error_naming_the_field(bad):
    with pytest.raises(ValueError, match="preload_n"):
        ballscrew.dkfzd4012_torque_nm(bad)
