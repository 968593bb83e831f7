"""Screw.replace: a spec with changed values, as editing its TOML text and loading it gives it."""

import pickle

import numpy as np
import pytest

import ballscrew


@pytest.fixture(scope="module")
def screw():
    return ballscrew.Screw.dkfzd4012()


def test_replace_equals_loading_the_edited_toml(screw):
    text = screw.to_toml()
    assert "coefficient = 0.03\n" in text and "lead_mm = 12.0\n" in text and "preload_n = 2000.0\n" in text
    edited = text.replace("coefficient = 0.03\n", "coefficient = 0.05\n").replace(
        "lead_mm = 12.0\n", "lead_mm = 10.0\n").replace("preload_n = 2000.0\n", "preload_n = 2500.0\n")
    loaded = ballscrew.Screw.from_toml_str(edited)
    replaced = screw.replace(friction_coefficient=0.05, lead_mm=10, preload_n=2500.0)
    assert replaced.to_toml() == loaded.to_toml()
    p = np.array([800.0, 1600.0, 3200.0])
    assert np.array_equal(replaced.torque(p), loaded.torque(p))
    a, b = replaced.summary(), loaded.summary()
    assert list(a) == list(b) and all(a[k] == b[k] or (a[k] != a[k] and b[k] != b[k]) for k in a)
    assert (replaced.friction_coefficient, replaced.lead_m, replaced.default_preload_n) == (0.05, 0.01, 2500.0)
    # The original is unchanged.
    assert screw.friction_coefficient == 0.03 and screw.lead_m == 0.012


@pytest.mark.parametrize("name", ["friction.coefficient", "friction_coefficient", "coefficient"])
def test_every_form_of_a_name_reaches_the_same_key(screw, name):
    assert screw.replace({name: 0.05}).friction_coefficient == 0.05
    assert screw.replace(**{name: 0.05}).to_toml() == screw.replace(friction_coefficient=0.05).to_toml()


def test_strings_bools_and_nested_tables(screw):
    dry = screw.replace(lubrication="dry", heathcote=False)
    assert (dry.lubrication, dry.heathcote) == ("dry", False)
    sealed = screw.replace({"extensions.seal_drag.torque_nm": 0.02})
    assert sealed.torque(2000.0) == pytest.approx(screw.torque(2000.0) + 0.02, abs=1e-12)
    # And back: None removes an optional table's key (an empty table is no extension).
    assert "seal_drag" in sealed.to_toml()
    unsealed = sealed.replace({"extensions.seal_drag.torque_nm": 0.0})
    assert unsealed.torque(2000.0) == pytest.approx(screw.torque(2000.0), abs=1e-12)


def test_unknown_names_list_the_closest_ones(screw):
    with pytest.raises(ValueError, match=r'unknown spec key: "frction_coeficient" \(did you mean friction_coefficient'):
        screw.replace(frction_coeficient=0.05)
    with pytest.raises(ValueError, match=r'unknown spec key: "zzz" \(see Screw.to_toml\(\) for the keys\)'):
        screw.replace(zzz=1.0)
    # A dotted key under a table the spec has goes to the loader, which lists the table's keys.
    with pytest.raises(ValueError, match=r"unknown field `bogus` in \[lubricant\], expected one of `iso_vg`"):
        screw.replace({"lubricant.bogus": 1.0})


def test_values_are_checked_as_a_toml_file_checks_them(screw):
    edited = screw.to_toml().replace("coefficient = 0.03\n", "coefficient = 5.0\n")
    with pytest.raises(ValueError) as loading:
        ballscrew.Screw.from_toml_str(edited, origin=screw.origin)
    with pytest.raises(ValueError) as replacing:
        screw.replace(friction_coefficient=5.0)
    assert str(replacing.value) == str(loading.value)
    assert "invalid friction.coefficient: 5 (valid: [0.005, 1])" in str(replacing.value)
    with pytest.raises(ValueError, match="nuts"):
        screw.replace(nuts=1.5)
    with pytest.raises(ValueError, match="invalid pitch_diameter_mm: 'forty'|pitch_diameter_mm"):
        screw.replace(pitch_diameter_mm="forty")
    with pytest.raises(ValueError, match="given twice"):
        screw.replace({"friction.coefficient": 0.04}, friction_coefficient=0.05)


def test_values_not_changed_keep_their_exact_si_values(screw):
    # A lead in SI that its mm text does not give back bit for bit (a pickle carries it as is).
    lead_m = 0.012000000000000047
    exact = ballscrew.Screw._from_state(screw.to_toml(), "exact", {"geometry.lead_m": lead_m})
    assert ballscrew.Screw.from_toml_str(exact.to_toml()).lead_m != lead_m
    assert exact.replace().lead_m == lead_m
    changed = exact.replace(friction_coefficient=0.05)
    assert changed.lead_m == lead_m
    assert exact.replace().torque(2000.0) == exact.torque(2000.0)
    assert pickle.loads(pickle.dumps(changed)).lead_m == lead_m
    # Changing the lead itself takes the new value.
    assert exact.replace(lead_mm=10.0).lead_m == 0.01


def test_a_grade_replaces_the_viscosities_and_one_viscosity_alone_is_named_missing(screw):
    # A screw's text carries the two viscosities where its file had a grade: a new grade stands
    # for both (it was refused as "not both"), as a file with that grade reads.
    graded = screw.replace({"lubricant.iso_vg": 100})
    from_file = ballscrew.Screw.from_toml_str(screw.to_toml().replace(
        "viscosity_40c_mm2_s = ", "iso_vg = 100.0\n# ").replace("viscosity_100c_mm2_s = ", "# "))
    assert graded.to_toml() == from_file.to_toml()
    assert graded.torque(2000.0) == from_file.torque(2000.0) != screw.torque(2000.0)
    # A grade with viscosities given too is the loader's refusal of the three.
    with pytest.raises(ValueError, match="not both"):
        screw.replace({"lubricant.iso_vg": 100, "lubricant.viscosity_40c_mm2_s": 90.0})
    # One viscosity dropped: the other is named missing, not reported as NaN.
    with pytest.raises(ValueError, match=r"missing lubricant\.viscosity_40c_mm2_s \(valid: both viscosities") as e:
        screw.replace({"lubricant.viscosity_40c_mm2_s": None})
    assert "NaN" not in str(e.value)
