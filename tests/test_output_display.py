"""Results in the user's units and precision (issue 15: KDAM's units and tolerances panels).

Every converted column must equal the SI column converted by pint on its own (not through
mechloop's factors), headers must carry the unit, the tables must read back to the SI
values, unknown or wrong-kind units must be refused with their place, and a model without
``display:`` must write exactly what it wrote before.
"""

from __future__ import annotations

import io
import math
from pathlib import Path

import hypothesis
import numpy as np
import pandas as pd
import pint
import pytest
import yaml
from hypothesis import given, settings
from hypothesis import strategies as st
from oracles.dynamic_models import dynamics, example
from typer.testing import CliRunner

import mechloop
from mechloop.cli import app
from mechloop.errors import ModelError
from mechloop.output.display import (
    TableDisplay,
    apply_display,
    parse_units,
    plot_display,
    resolve,
    round_significant,
)
from mechloop.output.paths import OutputError
from mechloop.output.tables import write_frame

ROOT = Path(__file__).resolve().parents[1]
DYNAMICS = ROOT / "examples/crank_slider_dynamics.yaml"
UREG = pint.UnitRegistry()  # a registry of its own: independent of mechloop's

#: Units of every kind that can be named, and a column header of that kind.
CHOICES = {
    "length": ["m", "mm", "cm", "in", "km"],
    "angle": ["deg", "rad", "grad", "turn"],
    "time": ["s", "ms", "min"],
    "force": ["N", "kN", "kgf", "lbf"],
    "moment": ["N*m", "kN*m", "kgf*m"],
    "energy": ["J", "kJ", "kgf*m", "Wh"],
    "power": ["W", "kW", "hp"],
    "mass": ["kg", "g", "t", "lb"],
    "inertia": ["kg*m^2", "kg*cm^2", "g*cm^2"],
    "velocity": ["m/s", "mm/s", "km/h"],
    "acceleration": ["m/s^2", "mm/s^2", "g0"],
    "angular_velocity": ["rad/s", "rpm", "deg/s"],
    "angular_acceleration": ["rad/s^2", "deg/s^2"],
}
#: (header, its SI unit as pint reads it): one column of each unit the tables write.
HEADERS = ["r3 [m]", "a2 [deg]", "time [s]", "RA [N]", "M_bal [N*m]", "T [J]",
           "friction_loss [W]", "dr3 [m/s]", "ddr3 [m/s^2]", "da2 [rad/s]",
           "dda2 [rad/s^2]", "J_red [kg*m^2]", "m_red [kg]", "dJ_red [kg*m^2/rad]",
           "dr3 [m/rad]", "ddr3 [m/rad^2]", "da2 [rad/rad]", "N per kg [W/kg]"]


def _expected_unit(header_unit: str, units: dict[str, str]) -> str:
    """The unit a column should be written in, said independently of the module: the
    named unit of its own kind, else each named base unit in place of the header's;
    angular velocity/acceleration stay rad/s, rad/s^2 unless named."""
    own = {"m/s": "velocity", "m/s^2": "acceleration", "rad/s": "angular_velocity",
           "rad/s^2": "angular_acceleration"}
    if header_unit in own:
        if own[header_unit] in units:
            return units[own[header_unit]]
        if header_unit.startswith("rad"):
            return header_unit
    base = {"m": "length", "rad": "angle", "deg": "angle", "s": "time", "kg": "mass",
            "kg*m^2": "inertia", "N": "force", "N*m": "moment", "J": "energy", "W": "power"}
    top, _, bottom = header_unit.partition("/")
    power = ""
    if "^" in bottom:
        bottom, power = bottom.split("^")
    new_top = units.get(base[top], top)
    if not bottom:
        return new_top
    new_bottom = units.get(base[bottom], bottom)
    if power:
        new_bottom = f"({new_bottom})^{power}" if any(c in new_bottom for c in "*/^") \
            else f"{new_bottom}^{power}"
    if any(c in new_bottom for c in "*/") and not new_bottom.startswith("("):
        new_bottom = f"({new_bottom})"
    return f"{new_top}/{new_bottom}"


@settings(deadline=None, max_examples=60)
@given(st.fixed_dictionaries({}, optional={k: st.sampled_from(v) for k, v in CHOICES.items()}),
       st.lists(st.floats(-1e6, 1e6, allow_nan=False), min_size=3, max_size=3))
def test_every_column_is_its_si_value_converted_by_pint(units, values):
    frame = pd.DataFrame({h: np.array(values) * (i + 1) for i, h in enumerate(HEADERS)})
    frame["chain_break"] = False
    shown = apply_display(frame, TableDisplay(units))
    assert list(shown.columns)[-1] == "chain_break"
    for header, new in zip(HEADERS, shown.columns[:-1], strict=True):
        stem, unit = header[:-1].split(" [")
        target = _expected_unit(unit, units)
        assert new == f"{stem} [{target}]"
        si = frame[header].to_numpy()
        expected = UREG.Quantity(si, unit.replace("^", "**")).to(
            target.replace("^", "**")).magnitude
        np.testing.assert_allclose(shown[new].to_numpy(), expected, rtol=1e-12, atol=0)
        if target == unit:  # not converted: the very numbers
            assert np.array_equal(shown[new].to_numpy(), si)


@settings(deadline=None)
@given(st.floats(allow_nan=False, allow_infinity=False).filter(lambda v: v != 0),
       st.integers(1, 15))
@hypothesis.example(6.477010904600146e16, 15)  # the scaled value lands on a half by rounding error
@hypothesis.example(7.275836812150525e81, 15)
def test_significant_digits_are_the_nearest_decimal_of_that_many_digits(value, digits):
    rounded = float(round_significant(np.array([value]), digits)[0])
    if not math.isfinite(float(f"{value:.{digits}g}")):  # would pass the largest double
        assert rounded == value
        return
    assert float(f"{rounded:.{digits}g}") == rounded  # at most `digits` digits
    step = 10.0 ** (math.floor(math.log10(abs(value))) - digits + 1)
    # within half the last digit, but for the error of holding the decimal as a double
    # (the doubles near 1e81 are 1e65 apart: 7.275836812150525e81 to 15 digits)
    assert abs(rounded - value) <= 0.5 * step * (1 + 1e-9) + 2 * math.ulp(value)


def test_significant_digits_equal_pythons_exact_rounding_in_bulk():
    rng = np.random.default_rng(11)
    values = rng.uniform(1, 10, 200_000) * 10.0 ** rng.integers(-30, 30, 200_000)
    for digits in (3, 9, 15):
        exact = np.array([float(f"{v:.{digits}g}") for v in values])
        assert np.array_equal(round_significant(values, digits), exact)


def test_nan_inf_and_zero_stay():
    values = np.array([np.nan, np.inf, -np.inf, 0.0, -0.0, 123.456])
    out = round_significant(values, 3)
    assert np.isnan(out[0]) and out[1] == np.inf and out[2] == -np.inf
    assert out[3] == 0.0 and list(out[5:]) == [123.0]


@pytest.mark.parametrize("suffix", [".csv", ".json", ".parquet", ".xlsx"])
def test_tables_read_back_to_the_si_values(tmp_path, suffix):
    dyn = dynamics(example("crank_slider_dynamics.yaml"))
    frame = dyn.to_frame()
    td = resolve(None, "omega=rpm,force=kN,length=mm,moment=kN*m,energy=kJ,power=kW")
    path = tmp_path / f"t{suffix}"
    write_frame(apply_display(frame, td, suffix), path)
    back = {".csv": pd.read_csv, ".json": pd.read_json, ".parquet": pd.read_parquet,
            ".xlsx": pd.read_excel}[suffix](path)
    assert {"RA [kN]", "da1 [rpm]", "r3 [mm]", "M_bal [kN*m]", "T [kJ]",
            "friction_loss [kW]", "dr3 [mm/s]", "dda1 [rad/s^2]"} <= set(back.columns)
    for header in frame.columns:
        if "[" not in header:
            continue
        new = next(c for c in back.columns if c.split(" [")[0] == header.split(" [")[0])
        unit, target = header[:-1].split(" [")[1], new[:-1].split(" [")[1]
        si = UREG.Quantity(back[new].to_numpy(dtype=float), target.replace("^", "**")
                           ).to(unit.replace("^", "**")).magnitude
        np.testing.assert_allclose(si, frame[header].to_numpy(dtype=float), rtol=1e-12,
                                   atol=1e-9 * np.nanmax(np.abs(frame[header])) + 1e-300)


def test_parquet_keeps_every_digit_unless_asked_on_the_command_line():
    section = mechloop.Model.from_dict(example(
        "crank_slider_dynamics.yaml", display={"force": "kN", "digits": 3})).display
    from_file = resolve(section)
    assert from_file.rounds(".csv") and from_file.rounds(".xlsx")
    assert not from_file.rounds(".parquet")
    assert resolve(section, digits=3).rounds(".parquet")
    frame = pd.DataFrame({"F [N]": [1234.5678]})
    assert apply_display(frame, from_file, ".parquet")["F [kN]"].iloc[0] == 1.2345678
    assert apply_display(frame, from_file, ".csv")["F [kN]"].iloc[0] == 1.23


def test_command_line_wins_over_the_file_kind_by_kind():
    section = mechloop.Model.from_dict(example(
        "crank_slider_dynamics.yaml",
        display={"force": "kN", "length": "mm", "decimals": 2})).display
    td = resolve(section, "force=kgf", digits=5)
    assert td.units == {"force": "kgf", "length": "mm"}
    assert (td.digits, td.decimals) == (5, None)
    assert resolve(None) is None and resolve(section).decimals == 2


def test_decimals():
    frame = pd.DataFrame({"a2 [deg]": [12.34567, -0.004]})
    out = apply_display(frame, TableDisplay({}, decimals=2))
    assert out["a2 [deg]"].tolist() == [12.35, -0.0]


def test_units_errors_name_the_pair_and_what_works():
    with pytest.raises(OutputError, match="force='rpm' is not a unit of force") as exc:
        parse_units("omega=rpm, force=rpm")
    assert "kN" in exc.value.hint
    with pytest.raises(OutputError, match="unknown kind of quantity 'speeed'"):
        parse_units("speeed=m/s")
    with pytest.raises(OutputError, match="'kN' is not KIND=UNIT"):
        parse_units("kN")
    with pytest.raises(OutputError, match="unknown display unit length='parsec_x'"):
        parse_units("length=parsec_x")
    with pytest.raises(OutputError, match="angular_velocity='m/s' is not a unit"):
        parse_units("omega=m/s")
    with pytest.raises(OutputError, match="--digits 0 is out of range"):
        resolve(None, digits=0)
    with pytest.raises(OutputError, match="both given"):
        resolve(None, digits=3, decimals=2)
    with pytest.raises(OutputError, match="small powers"):
        parse_units("length=m**9**9**9")  # refused before pint would compute it
    assert parse_units("omega=rpm,epsilon=deg/s^2,work=kJ") == {
        "angular_velocity": "rpm", "angular_acceleration": "deg/s^2", "energy": "kJ"}


def test_a_wrong_unit_in_the_file_is_located(tmp_path):
    text = DYNAMICS.read_text() + "display:\n  force: kN\n  moment: rpm\n  digits: 4\n"
    path = tmp_path / "m.yaml"
    path.write_text(text)
    with pytest.raises(ModelError) as exc:
        mechloop.load_model(path)
    line = text.splitlines().index("  moment: rpm") + 1
    rendered = str(exc.value)
    assert f"m.yaml:{line}, display.moment" in rendered
    assert "'rpm' is not a unit of moment" in rendered
    result = CliRunner().invoke(app, ["solve", str(path)])
    assert result.exit_code == 2 and "Traceback" not in result.output


def test_old_models_write_exactly_what_they_wrote(tmp_path):
    """No display: section, no options: the bytes of the plain table writer."""
    dyn = dynamics(example("crank_slider_dynamics.yaml"))
    for suffix in (".csv", ".json"):
        direct, via_cli = tmp_path / f"d{suffix}", tmp_path / f"c{suffix}"
        write_frame(dyn.to_frame(), direct)
        result = CliRunner().invoke(app, ["solve", str(DYNAMICS), "-o", str(via_cli)])
        assert result.exit_code == 0, result.output
        assert via_cli.read_bytes() == direct.read_bytes()


def test_a_model_in_kn_writes_kn(tmp_path):
    """The CLI with the model's display: section and --units/--digits on top."""
    data = yaml.safe_load(DYNAMICS.read_text())
    data["display"] = {"force": "kN", "angular_velocity": "rpm"}
    model = tmp_path / "kn.yaml"
    model.write_text(yaml.safe_dump(data))
    out = tmp_path / "kn.csv"
    result = CliRunner().invoke(app, ["solve", str(model), "-o", str(out),
                                      "--units", "length=mm", "--digits", "6"])
    assert result.exit_code == 0, result.output
    table = pd.read_csv(out)
    si = dynamics(example("crank_slider_dynamics.yaml")).to_frame()
    expected = round_significant(si["RA [N]"].to_numpy() / 1000.0, 6)
    assert np.array_equal(table["RA [kN]"].to_numpy(), expected)
    assert np.array_equal(table["da1 [rpm]"].to_numpy(), np.full(73, 3000.0))
    assert np.array_equal(table["r3 [mm]"].to_numpy(),
                          round_significant(si["r3 [m]"].to_numpy() * 1000.0, 6))
    assert "M_bal [N*m]" in table.columns  # moment not named: as before
    assert "dda1 [rad/s^2]" in table.columns


def test_energy_prints_the_chosen_units():
    args = ["energy", str(ROOT / "examples/single_cylinder_engine.yaml")]
    plain = CliRunner().invoke(app, args)
    shown = CliRunner().invoke(app, [*args, "--units", "omega=rpm,power=kW,work=kJ,"
                                     "inertia=kg*cm^2", "--digits", "5"])
    assert plain.exit_code == shown.exit_code == 0, shown.output
    assert "A+ [kJ]" in shown.output and "max N [kW]" in shown.output
    assert "N per kg [kW/kg]" in shown.output and "A+ [J]" in plain.output
    dyn = dynamics(example("single_cylinder_engine.yaml"))
    cycle = dyn.cycle
    rpm = cycle.omega_mean * 60 / (2 * math.pi)
    assert f"mean speed {rpm:.5g} rpm" in shown.output
    assert f"mean speed {cycle.omega_mean:.6g} rad/s" in plain.output
    assert f"{cycle.flywheel * 1e4:.5g} kg*cm^2" in shown.output
    gas = next(r for r in dyn.summary.rows if r.name == "gas")
    assert f"{gas.positive_work / 1000:.5g}" in shown.output


def test_plots_agree_with_the_tables():
    td = resolve(None, "force=kN,omega=rpm,length=mm", digits=5)
    display = plot_display(td)
    frame = apply_display(pd.DataFrame({"RA [N]": [2000.0], "da1 [rad/s]": [math.pi],
                                        "dr3 [m/s]": [1.0], "dda1 [rad/s^2]": [1.0]}), td)
    assert list(frame.columns) == [f"RA [{display.label('force')}]",
                                   f"da1 [{display.label('angular_velocity')}]",
                                   f"dr3 [{display.label('velocity')}]",
                                   f"dda1 [{display.label('angular_acceleration')}]"]
    assert frame["RA [kN]"].iloc[0] == display.convert(2000.0, "force") == 2.0
    assert frame["da1 [rpm]"].iloc[0] == pytest.approx(
        float(display.convert(math.pi, "angular_velocity")), rel=1e-15)
    assert display.digits == 5 and plot_display(None) is None


def test_the_plot_command_takes_the_models_display(tmp_path):
    data = yaml.safe_load(DYNAMICS.read_text())
    data["display"] = {"force": "kN"}
    model = tmp_path / "kn.yaml"
    model.write_text(yaml.safe_dump(data))
    result = CliRunner().invoke(app, ["plot", str(model), "reactions", "-o",
                                      str(tmp_path / "r.svg")])
    assert result.exit_code == 0, result.output
    assert "reaction [kN]" in (tmp_path / "r.svg").read_text()
    bad = CliRunner().invoke(app, ["plot", str(model), "reactions", "-o",
                                   str(tmp_path / "r.svg"), "--units", "force=rpm"])
    assert bad.exit_code == 2 and "is not a unit of force" in bad.output


def test_json_with_digits_is_short(tmp_path):
    frame = pd.DataFrame({"F [N]": [1234.56789, np.nan]})
    path = tmp_path / "f.json"
    write_frame(apply_display(frame, TableDisplay({"force": "kN"}, digits=3), ".json"), path)
    assert path.read_text() == '[\n{"F [kN]":1.23},\n{"F [kN]":null}\n]\n'
    buffer = io.StringIO(path.read_text())
    assert pd.read_json(buffer)["F [kN]"].iloc[0] == 1.23


def test_the_reports_appendix_takes_the_models_display():
    from mechloop.report.content import build_document

    model = mechloop.Model.from_dict(example(
        "crank_slider_dynamics.yaml", display={"force": "kN", "angular_velocity": "rpm"}))
    dyn = mechloop.solve_dynamics(model)
    heads: dict[str, str] = {}  # header -> the cell of position 0
    for table in build_document(model, lang="en").appendices[0].blocks:
        heads |= dict(zip(table.header, table.rows[0], strict=True))
    si = dyn.to_frame()
    assert "RA, kN" in heads and "RA, N" not in heads
    assert float(heads["RA, kN"]) == pytest.approx(si["RA [N]"].iloc[0] / 1000, rel=1e-4)
    assert float(heads["dα1, rpm"]) == pytest.approx(3000.0, rel=1e-9)
    assert "M_bal, N·m" in heads  # moment not named
