"""FASTSIM contact evaluation from Python: the command line's units, names and ranges, and a numpy
traction field consistent with the totals."""

import csv
import io
import math
import subprocess

import numpy as np
import pytest

import ballscrew

# CONTACT's FASTSIM example (docs/reference/saturation_and_fastsim.csv, rows fastsim_lateral_spin):
# a = 8 mm, b = 4 mm, G = 82000 MPa, nu = 0.28, mu = 0.3, Fn = 82 kN, eta = -6.25e-4,
# phi = 6.25e-4 1/mm; parabolic bound: Fy/(mu Fn) = -0.6118 on CONTACT's 44x44 grid, -0.6359 on
# its 220x220 grid (the grid-converged value, which Kalker's strip grid approaches faster).
G_GPA = 82.0
NU = 0.28
EXAMPLE = dict(
    semi_axis_rolling_mm=8.0,
    semi_axis_lateral_mm=4.0,
    normal_load_n=82e3,
    eta=-6.25e-4,
    phi_per_mm=6.25e-4,
    friction=0.3,
    youngs_modulus_gpa=2.0 * G_GPA * (1.0 + NU),
    poisson_ratio=NU,
)


def test_traction_field_adds_up_to_the_forces_and_respects_the_bound():
    r = ballscrew.contact(**EXAMPLE, grid=44)
    for key in ("x_mm", "y_mm", "area_mm2", "traction_x_mpa", "traction_y_mpa", "bound_mpa", "sliding"):
        assert r[key].shape == (44, 44)
    # MPa times mm^2 is N.
    fx = float(np.sum(r["traction_x_mpa"] * r["area_mm2"]))
    fy = float(np.sum(r["traction_y_mpa"] * r["area_mm2"]))
    assert fx == pytest.approx(r["force_e_n"], rel=1e-9, abs=1e-9)
    assert fy == pytest.approx(r["force_f_n"], rel=1e-9)
    # The ellipse in mm: every element inside a = 8 mm, b = 4 mm; the area pi a b in mm^2.
    assert np.all(np.abs(r["x_mm"]) < 8.0) and np.all(np.abs(r["y_mm"]) < 4.0)
    assert float(np.sum(r["area_mm2"])) == pytest.approx(math.pi * 8.0 * 4.0, rel=0.02)
    magnitude = np.hypot(r["traction_x_mpa"], r["traction_y_mpa"])
    assert np.all(magnitude <= r["bound_mpa"] * (1 + 1e-12) + 1e-15)
    assert int(np.sum(r["sliding"])) == r["slip_elements"]
    assert 0.0 < r["adhesion_share"] < 1.0
    # Strip grid and the project's Kalker table (flexibilities about 1 % off CONTACT's): within 3 %
    # of CONTACT's grid-converged value.
    assert r["force_f_n"] / (0.3 * 82e3) == pytest.approx(-0.6359, rel=0.03)


def test_large_creepage_saturates_and_zero_creepage_gives_no_force():
    full = ballscrew.contact(**{**EXAMPLE, "eta": -0.05, "phi_per_mm": 0.0})
    assert math.hypot(full["force_e_n"], full["force_f_n"]) == pytest.approx(0.3 * 82e3, rel=1e-6)
    assert full["adhesion_share"] < 0.05
    none = ballscrew.contact(8.0, 4.0, 82e3)
    assert none["force_e_n"] == 0.0 and none["force_f_n"] == 0.0 and none["adhesion_share"] == 1.0


def test_contact_gives_the_command_lines_fastsim_forces(cli):
    # The command line takes the material of its spec (DKFZD4012: 210 GPa, 0.3), Python's defaults.
    flags = ["--semi-axis-rolling-mm", "8", "--semi-axis-lateral-mm", "4", "--normal-load-n", "82000",
             "--eta", "-6.25e-4", "--phi-per-mm", "6.25e-4", "--heathcote-per-mm2", "1e-3", "--friction", "0.3",
             "--grid", "44", "--bound", "elliptical"]
    row = next(csv.DictReader(io.StringIO(cli("contact", *flags, "--format", "csv"))))
    r = ballscrew.contact(8.0, 4.0, 82000.0, eta=-6.25e-4, phi_per_mm=6.25e-4, heathcote_per_mm2=1e-3,
                          friction=0.3, grid=44, bound="elliptical")
    for key in ("force_e_n", "force_f_n", "spin_moment_nm", "dissipation_per_speed_n", "adhesion_share"):
        assert r[key] == pytest.approx(float(row["fastsim_" + key]), rel=1e-12, abs=1e-9), key
    assert r["adhesion_elements"] == int(row["fastsim_adhesion_elements"])


@pytest.mark.parametrize(
    "kwargs, message",
    [
        # A semi-axis given in metres by habit (0.06e-3 mm = 60 nm) is below the command line's range.
        (dict(semi_axis_rolling_mm=0.06e-3), r"invalid semi_axis_rolling_mm: 60 nm \(valid: finite, \[100 nm, 100 mm\]\)"),
        (dict(semi_axis_lateral_mm=101.0), r"invalid semi_axis_lateral_mm: 101 mm \(valid: finite, \[100 nm, 100 mm\]\)"),
        (dict(normal_load_n=2e7), r"invalid normal_load_n: 20 MN \(valid: finite, \[1 µN, 10 MN\]\)"),
        (dict(xi=1001.0), r"invalid xi: 1001 \(valid: finite, \|value\| <= 1000\)"),
        (dict(phi_per_mm=-2e3), r"invalid phi_per_mm: -2000 \(valid: finite, \|value\| <= 1000\)"),
        (dict(heathcote_per_mm2=math.nan), r"invalid heathcote_per_mm2: NaN"),
        (dict(friction=2.0), r"invalid friction: 2 \(valid: \[1e-4, 1\]\)"),
        (dict(youngs_modulus_gpa=0.5), r"invalid youngs_modulus_gpa: 500 MPa \(valid: \[1 GPa, 1 TPa\]\)"),
        (dict(poisson_ratio=0.6), r"invalid poisson_ratio: 0.6 \(valid: \[0, 0.5\]\)"),
        (dict(grid=0), r"invalid grid: 0 \(valid: integer in \[1, 400\]\)"),
        (dict(grid=401), r"invalid grid: 401 \(valid: integer in \[1, 400\]\)"),
        (dict(grid=40.0), r"invalid grid: 40.0"),
        (dict(grid=True), r"invalid grid: True"),
        (dict(bound="round"), r"invalid bound"),
        (dict(eta="0.1"), r"invalid eta: '0.1'"),
    ],
)
def test_invalid_input_raises_the_command_lines_value_error(kwargs, message):
    args = dict(semi_axis_rolling_mm=8.0, semi_axis_lateral_mm=4.0, normal_load_n=82e3, **{})
    args.update(kwargs)
    with pytest.raises(ValueError, match=message):
        ballscrew.contact(**args)


@pytest.mark.parametrize("flag, value", [("--semi-axis-rolling-mm", "6e-5"), ("--grid", "401"),
                                         ("--normal-load-n", "2e7"), ("--friction", "2")])
def test_the_command_line_refuses_the_same_values(cli, flag, value):
    flags = {"--semi-axis-rolling-mm": "8", "--semi-axis-lateral-mm": "4", "--normal-load-n": "82000", "--eta": "0"}
    flags[flag] = value
    with pytest.raises(subprocess.CalledProcessError) as e:
        cli("contact", *[x for kv in flags.items() for x in kv])
    assert "invalid " + flag in e.value.stderr


def test_the_range_ends_are_accepted():
    r = ballscrew.contact(100.0, 1e-4 * 1000, 1e7, friction=1.0, grid=400, xi=1000.0)
    assert r["x_mm"].shape == (400, 400)
    assert math.isfinite(r["force_e_n"])
