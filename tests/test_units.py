"""Tests for crane_sym.units: quantity parsing, dimension checks, safety."""
import math

import pytest
from sympy.physics.units import Dimension, force, length, mass, time

from crane_sym.units import (
    UNITS,
    Quantity,
    UnitError,
    convert,
    format_dimension,
    parse_quantity,
    parse_unit,
    same_dimension,
)

ONE = Dimension(1)
TORQUE = force * length

# --- a canary: if any test string were evaluated, this flag would be set ----
CANARY = {"called": False}


def _canary() -> int:
    CANARY["called"] = True
    return 1


# A payload that really calls _canary() when evaluated from any namespace
# (checked in test_canary_payload_is_live), so rejecting it is meaningful.
LIVE_PAYLOAD = f"__import__('sys').modules[{__name__!r}]._canary()"


# ----------------------------------------------------------------- conversions
@pytest.mark.parametrize(
    "text, value, dim",
    [
        ("50 t", 50000.0, mass),
        ("1450 kg", 1450.0, mass),
        ("250 g", 0.25, mass),
        ("500 mm", 0.5, length),
        ("2.5 km", 2500.0, length),
        ("30 cm", 0.3, length),
        ("4 um", 4e-6, length),
        ("4 µm", 4e-6, length),
        ("-2.5e-3 m", -2.5e-3, length),
        ("0.5 s", 0.5, time),
        ("250 ms", 0.25, time),
        ("2 min", 120.0, time),
        ("1.5 h", 5400.0, time),
        ("12 kN", 12000.0, force),
        ("3 MN", 3e6, force),
        ("2 kgf", 2 * 9.80665, force),
        ("1 tf", 9806.65, force),
        ("5e6 N/m", 5e6, force / length),
        ("3 m/s^2", 3.0, length / time**2),
        ("3 m/s**2", 3.0, length / time**2),
        ("3 m/s²", 3.0, length / time**2),
        ("13 kg*m^2", 13.0, mass * length**2),
        ("13 kg·m²", 13.0, mass * length**2),
        ("13 kg.m^2", 13.0, mass * length**2),
        ("7 m^-1", 7.0, 1 / length),
    ],
)
def test_parse_quantity_values(text, value, dim):
    q = parse_quantity(text)
    assert isinstance(q, Quantity)
    assert q.value == pytest.approx(value, rel=1e-15)
    assert same_dimension(q.dimension, dim)
    assert q.text == text


def test_tonne():
    q = parse_quantity("50 t")
    assert q.value == 50000.0
    assert same_dimension(q.dimension, mass)


def test_metres_per_minute_exact():
    q = parse_quantity("80 m/min")
    assert q.value == pytest.approx(1.3333333333333333, rel=1e-15)
    assert same_dimension(q.dimension, length / time)


@pytest.mark.parametrize("text", ["20 kN*m/rad", "20 kN·m/rad", "20 kN.m/rad", "20 kN * m / rad"])
def test_rotational_stiffness_is_torque(text):
    q = parse_quantity(text)
    assert q.value == 20000.0
    assert same_dimension(q.dimension, TORQUE)
    assert same_dimension(q.dimension, mass * length**2 / time**2)
    assert not same_dimension(q.dimension, force / length)


def test_rpm_is_angular_velocity():
    q = parse_quantity("1450 rpm")
    assert q.value == pytest.approx(1450 * 2 * math.pi / 60, rel=1e-15)
    assert q.value == pytest.approx(151.84364492350667, rel=1e-15)
    assert same_dimension(q.dimension, 1 / time)


def test_angles_dimensionless():
    assert parse_quantity("90 deg").value == pytest.approx(math.pi / 2, rel=1e-15)
    assert parse_quantity("1 rev").value == pytest.approx(2 * math.pi, rel=1e-15)
    assert same_dimension(parse_quantity("90 deg").dimension, ONE)
    assert same_dimension(parse_quantity("3 rad").dimension, ONE)


def test_bare_number_text_is_dimensionless():
    q = parse_quantity("1.2")
    assert q.value == 1.2
    assert same_dimension(q.dimension, ONE)


@pytest.mark.parametrize("text", ["1 m/s/s", "1 m/s^2", "1 m*s^-2", "1 m·s⁻²"])
def test_slash_binds_to_next_unit_only(text):
    q = parse_quantity(text)
    assert q.value == 1.0
    assert same_dimension(q.dimension, length / time**2)


def test_slash_then_multiply():
    # "kg/m*s" is kg*s/m, not kg/(m*s)
    q = parse_quantity("2 kg/m*s")
    assert same_dimension(q.dimension, mass * time / length)
    assert not same_dimension(q.dimension, mass / (length * time))


@pytest.mark.parametrize("text", ["50t", " 50  t ", "50 t", "\t50\tt\n"])
def test_whitespace_tolerance(text):
    assert parse_quantity(text).value == 50000.0


def test_parse_unit():
    factor, dim = parse_unit("kN*m/rad")
    assert factor == 1000.0
    assert same_dimension(dim, TORQUE)
    assert parse_unit("")[0] == 1.0 and same_dimension(parse_unit("")[1], ONE)
    assert parse_unit("1")[0] == 1.0 and same_dimension(parse_unit("1")[1], ONE)
    assert parse_unit("mm^2")[0] == pytest.approx(1e-6, rel=1e-15)
    assert same_dimension(parse_unit("MPa")[1], force / length**2)
    assert same_dimension(parse_unit("kW")[1], mass * length**2 / time**3)
    assert same_dimension(parse_unit("kJ")[1], TORQUE)
    assert same_dimension(parse_unit("Hz")[1], 1 / time)


def test_every_table_entry_parses():
    for name, (factor, dim) in UNITS.items():
        got_factor, got_dim = parse_unit(name)
        assert got_factor == factor
        assert same_dimension(got_dim, dim)


# ---------------------------------------------------------------- dimensions
def test_same_dimension_reduces_to_base():
    assert same_dimension(force, mass * length / time**2)
    assert same_dimension(ONE, length / length)
    assert not same_dimension(force, mass)


def test_format_dimension_deterministic():
    assert format_dimension(force) == "mass*length/time**2"
    assert format_dimension(mass * length / time**2) == "mass*length/time**2"
    assert format_dimension(force / length) == "mass/time**2"
    assert format_dimension(1 / time) == "1/time"
    assert format_dimension(ONE) == "dimensionless"
    assert format_dimension(force / length**2) == "mass/(length*time**2)"


# ------------------------------------------------------------------- convert
def test_convert_string_and_dict():
    assert convert("m2", "50 t", mass) == 50000.0
    assert convert("m2", {"value": 50, "unit": "t"}, mass) == 50000.0
    assert convert("v", {"value": 80, "unit": "m/min"}, length / time) == pytest.approx(
        4 / 3, rel=1e-15)
    assert convert("k", "20 kN·m/rad", TORQUE) == 20000.0
    assert convert("k", "20 kN·m/rad", mass * length**2 / time**2) == 20000.0


def test_convert_dimension_mismatch_names_parameter():
    with pytest.raises(UnitError) as exc:
        convert("c", "20 kN*m/rad", force / length)
    msg = str(exc.value)
    assert "'c'" in msg
    assert "force/length" in msg
    assert "20 kN*m/rad" in msg
    assert "force*length" in msg


def test_convert_dict_dimension_mismatch():
    with pytest.raises(UnitError, match="'m_load'"):
        convert("m_load", {"value": 5, "unit": "kN"}, mass)


def test_unknown_unit_suggests_close_names():
    with pytest.raises(UnitError) as exc:
        convert("F", "12 kn", force)
    msg = str(exc.value)
    assert "'F'" in msg and "'kn'" in msg and "kN" in msg
    with pytest.raises(UnitError, match="did you mean.*'rpm'"):
        parse_quantity("1450 rmp")


def test_bare_number_only_when_dimensionless():
    assert convert("mu", 0.3, ONE) == 0.3
    assert convert("n", 4, ONE) == 4.0
    assert isinstance(convert("n", 4, ONE), float)
    with pytest.raises(UnitError) as exc:
        convert("m2", 50, mass)
    msg = str(exc.value)
    assert "'m2'" in msg and "mass" in msg and "bare number 50" in msg


@pytest.mark.parametrize(
    "value", ["nan", "inf", "-inf", "NaN m", "inf t", float("nan"), float("inf"),
              -float("inf"), {"value": float("nan"), "unit": "t"}, "1e308 t", 10**400],
)
def test_non_finite_rejected(value):
    with pytest.raises(UnitError) as exc:
        convert("m2", value, mass if not isinstance(value, (int, float)) else ONE)
    assert "'m2'" in str(exc.value)
    assert "finite" in str(exc.value)


@pytest.mark.parametrize("value", [True, False])
def test_bool_is_not_a_number(value):
    with pytest.raises(UnitError, match="'flag'"):
        convert("flag", value, ONE)
    with pytest.raises(UnitError, match="'flag'"):
        convert("flag", {"value": value, "unit": ""}, ONE)


@pytest.mark.parametrize("value", [None, [50, "t"], (50, "t"), b"50 t", object(), {"unit": "t"},
                                   {"value": 50, "unit": "t", "extra": 1},
                                   {"value": "50", "unit": "t"}, {"value": 50, "unit": 3}])
def test_bad_types_rejected(value):
    with pytest.raises(UnitError, match="'p'"):
        convert("p", value, mass)


@pytest.mark.parametrize("text", ["", "   ", "m", "t", "kg 50", "50 t t", "50 t*", "50 /s",
                                  "5 m^", "5 m^99", "5 (m)", "5 N m", "1..5 m", "5 m**"])
def test_malformed_rejected(text):
    with pytest.raises(UnitError):
        parse_quantity(text)
    with pytest.raises(UnitError, match="'p'"):
        convert("p", text, length)


# ----------------------------------------------------------------- security
MALICIOUS = [
    LIVE_PAYLOAD,
    "1 " + LIVE_PAYLOAD,
    "1 m*" + LIVE_PAYLOAD,
    "__import__('os')",
    "__import__('os').system('true')",
    "1+1",
    "2*3 m",
    "1 + 1 m",
    "(1) m",
    "1e3 m; import os",
    "1 m # comment",
    "1 __import__('os')",
    "1 m*__import__('os')",
    "_canary()",
    "1 _canary()",
    "1 m*_canary()",
    "1 m/_canary()",
    "tests.test_units._canary()",
    "lambda: _canary()",
    "1 m.__class__",
    "1 m.__class__.__mro__",
    "[x for x in ()]",
    "1 {}",
    "1 m\n_canary()",
]


@pytest.mark.parametrize("text", MALICIOUS)
def test_malicious_strings_rejected_and_not_evaluated(text):
    CANARY["called"] = False
    with pytest.raises(UnitError):
        parse_quantity(text)
    with pytest.raises(UnitError):
        convert("p", text, length)
    with pytest.raises(UnitError):
        parse_unit(text)
    with pytest.raises(UnitError):
        convert("p", {"value": 1, "unit": text}, length)
    assert CANARY["called"] is False


def test_canary_payload_is_live():
    # Sanity check of the detector itself (the test evaluates its own constant,
    # never user text): evaluating the payload does set the flag.
    CANARY["called"] = False
    assert eval(LIVE_PAYLOAD, {}) == 1  # noqa: S307
    assert CANARY["called"] is True
    CANARY["called"] = False


def test_overlong_text_rejected():
    with pytest.raises(UnitError):
        parse_quantity("1 " + "m*" * 200 + "m")


def test_unit_error_is_value_error():
    assert issubclass(UnitError, ValueError)
    with pytest.raises(ValueError):
        parse_quantity("abc")


def test_quantity_is_frozen():
    q = parse_quantity("1 m")
    with pytest.raises(Exception):
        q.value = 2.0  # type: ignore[misc]
