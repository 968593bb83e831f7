"""FASTSIM contact evaluation from Python: numpy traction field consistent with the totals."""

import math

import numpy as np
import pytest

import ballscrew

# CONTACT's FASTSIM example (docs/reference/saturation_and_fastsim.csv, rows fastsim_lateral_spin):
# a = 8 mm, b = 4 mm, G = 82000 MPa, nu = 0.28, mu = 0.3, Fn = 82 kN, eta = -6.25e-4,
# phi = 6.25e-4 1/mm; parabolic bound: Fy/(mu Fn) = -0.6118 on CONTACT's 44x44 grid, -0.6359 on
# its 220x220 grid (the grid-converged value, which Kalker's strip grid approaches faster).
G = 82.0e9
NU = 0.28
EXAMPLE = dict(
    semi_axis_rolling_m=8e-3,
    semi_axis_lateral_m=4e-3,
    normal_load_n=82e3,
    eta=-6.25e-4,
    phi_per_m=0.625,
    friction_coefficient=0.3,
    youngs_modulus_pa=2.0 * G * (1.0 + NU),
    poisson_ratio=NU,
)


def test_traction_field_adds_up_to_the_forces_and_respects_the_bound():
    r = ballscrew.contact(**EXAMPLE, grid=44)
    for key in ("x_m", "y_m", "traction_x_pa", "traction_y_pa", "bound_pa", "sliding"):
        assert r[key].shape == (44, 44)
    fx = float(np.sum(r["traction_x_pa"] * r["area_m2"]))
    fy = float(np.sum(r["traction_y_pa"] * r["area_m2"]))
    assert fx == pytest.approx(r["force_e_n"], rel=1e-9, abs=1e-9)
    assert fy == pytest.approx(r["force_f_n"], rel=1e-9)
    magnitude = np.hypot(r["traction_x_pa"], r["traction_y_pa"])
    assert np.all(magnitude <= r["bound_pa"] * (1 + 1e-12) + 1e-9)
    assert int(np.sum(r["sliding"])) == r["slip_elements"]
    assert 0.0 < r["adhesion_share"] < 1.0
    # Strip grid and the project's Kalker table (flexibilities about 1 % off CONTACT's): within 3 %
    # of CONTACT's grid-converged value.
    assert r["force_f_n"] / (0.3 * 82e3) == pytest.approx(-0.6359, rel=0.03)


def test_large_creepage_saturates_and_zero_creepage_gives_no_force():
    full = ballscrew.contact(**{**EXAMPLE, "eta": -0.05, "phi_per_m": 0.0})
    assert math.hypot(full["force_e_n"], full["force_f_n"]) == pytest.approx(0.3 * 82e3, rel=1e-6)
    assert full["adhesion_share"] < 0.05
    none = ballscrew.contact(8e-3, 4e-3, 82e3)
    assert none["force_e_n"] == 0.0 and none["force_f_n"] == 0.0 and none["adhesion_share"] == 1.0


@pytest.mark.parametrize(
    "kwargs, field",
    [
        (dict(grid=0), "grid"),
        (dict(grid=100000), "grid"),
        (dict(bound="round"), "bound"),
        (dict(xi=math.nan), "xi"),
        (dict(youngs_modulus_pa=-1.0), "youngs_modulus_pa"),
    ],
)
def test_invalid_input_raises_value_error_naming_the_field(kwargs, field):
    with pytest.raises(ValueError, match=field):
        ballscrew.contact(8e-3, 4e-3, 82e3, **kwargs)
