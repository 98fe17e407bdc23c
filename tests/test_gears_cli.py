"""`mechloop gear pair` and `mechloop gear planetary`: the bundled gear examples run, write
their figures, tables and models, and a wrong gear file is told by line and key."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pandas as pd
import pytest
from typer.testing import CliRunner

import mechloop
from mechloop.cli import app
from mechloop.gears.document import pair_of, read_gear_document
from mechloop.solve.kinematics import solve

ROOT = Path(__file__).resolve().parents[1]
GEARS = ROOT / "examples" / "gears"
runner = CliRunner()


def run(*args: str):
    return runner.invoke(app, list(args))


def test_every_gear_example_is_read_and_runs():
    files = sorted(GEARS.glob("*.yaml"))
    assert {p.name for p in files} == {"gear_pair.yaml", "planetary_choice.yaml",
                                       "planetary_reducer.yaml", "wolfrom.yaml",
                                       "james_sun_fixed.yaml"}
    for path in files:
        doc, _ = read_gear_document(path)
        command = "pair" if doc.gear_pair is not None else "planetary"
        result = run("gear", command, str(path))
        assert result.exit_code == 0, result.output
        assert "FAILS" not in result.output


def test_pair_writes_its_drawing_sliding_plot_and_table(tmp_path):
    mesh, sliding, table = tmp_path / "mesh.png", tmp_path / "sliding.svg", tmp_path / "t.csv"
    result = run("gear", "pair", str(GEARS / "gear_pair.yaml"), "--plot", str(mesh),
                 "--sliding", str(sliding), "-o", str(table))
    assert result.exit_code == 0, result.output
    assert mesh.stat().st_size > 10_000 and sliding.stat().st_size > 1_000
    frame = pd.read_csv(table).set_index("symbol")
    assert frame.loc["a", "pinion"] == pytest.approx(56.4999, abs=5e-5)
    assert frame.loc["d_a", "wheel"] == pytest.approx(79.400, abs=5e-4)


def test_pair_from_options_is_the_pair_of_the_file():
    by_options = run("gear", "pair", "-m", "3", "-z", "12", "24", "-x", "0.6", "0.36")
    by_file = run("gear", "pair", str(GEARS / "gear_pair.yaml"))
    assert by_options.exit_code == by_file.exit_code == 0
    numbers = [line.split("│")[2:5] for line in by_file.output.splitlines()
               if line.count("│") > 4]
    assert numbers == [line.split("│")[2:5] for line in by_options.output.splitlines()
                       if line.count("│") > 4]


def test_centre_distance_alone_gives_balanced_shifts():
    doc, _ = read_gear_document(GEARS / "gear_pair.yaml")
    spec = doc.gear_pair.model_copy(update={"shifts": None, "centre_distance": 56.5})
    pair = pair_of(spec)
    from mechloop.gears.sliding import extreme_sliding

    t1, t2 = extreme_sliding(pair)
    assert pair.a == pytest.approx(56.5, abs=1e-9) and abs(t1 - t2) < 1e-9


def test_planetary_writes_the_plan_the_designs_and_a_vector_model(tmp_path):
    plan, table = tmp_path / "plan.png", tmp_path / "designs.csv"
    result = run("gear", "planetary", str(GEARS / "planetary_choice.yaml"), "--plot",
                 str(plan), "-o", str(table))
    assert result.exit_code == 0, result.output
    assert plan.stat().st_size > 10_000
    designs = pd.read_csv(table)
    assert len(designs) == 8 and (designs["error [%]"] <= 1).all()
    model = tmp_path / "train.yaml"
    result = run("gear", "planetary", str(GEARS / "planetary_reducer.yaml"), "--model",
                 str(model))
    assert result.exit_code == 0, result.output
    frame = solve(mechloop.load_model(model)).to_frame()
    turn = frame["a1 [deg]"].to_numpy()
    assert np.allclose(frame["a2 [deg]"].to_numpy()[1:] / turn[1:], 1 / 5, rtol=1e-12)


@pytest.mark.parametrize("text, where, words", [
    ("gear_pair:\n  module: 3\n  teeth: [12, 24]\n  shifts: [0.6, 0.36]\n"
     "  centre_distance: 57\n", ":5, gear_pair.centre_distance", "give the centre distance"),
    ("gear_pair:\n  module: 3\n  teeth: [12, 24]\n  shifts: balanced\n", ":4, gear_pair.shifts",
     "need their sum"),
    ("gear_pair:\n  module: 3\n  teeth: [12, 24]\n  modul: 2\n", ":4, gear_pair.modul",
     "unknown key"),
    ("planetary:\n  scheme: double_planet\n  teeth: {a: 20, g: 30, b: 80}\n",
     ":3, planetary.teeth", "missing f"),
    ("planetary:\n  scheme: simple\n  planets: 3\n  target_ratio: 1.01\n",
     ":4, planetary.target_ratio", "no design"),
    ("planetary:\n  scheme: simple\n  teeth: {a: 20, g: 30, b: 80}\n  fixed: h\n"
     "  input: h\n", ":5, planetary.input", "held fixed"),
    ("planetary:\n  scheme: wolfrom\n  teeth: {a: 15, g: 24, f: 21, b: 63}\n",
     ":3, planetary.teeth", "missing e"),
    ("planetary:\n  scheme: wolfrom\n  teeth: {a: 15, g: 24, f: 21, b: 63, e: 60}\n"
     "  fixed: a\n  input: b\n", ":4, planetary.fixed", "holds ring b"),
    ("planetary:\n  scheme: simple\n  teeth: {a: 20, g: 30, b: 80, e: 60}\n",
     ":3, planetary.teeth", "wolfrom scheme only"),
])
def test_a_wrong_gear_file_is_told_by_line_and_key(tmp_path, text, where, words):
    path = tmp_path / "bad.yaml"
    path.write_text(text, encoding="utf-8")
    command = "pair" if text.startswith("gear_pair") else "planetary"
    result = run("gear", command, str(path))
    assert result.exit_code == 2
    assert f"{path}{where}" in result.output and words in result.output
    assert "Traceback" not in result.output


def test_thickness_on_a_circle_is_measured_on_the_generated_tooth():
    from mechloop.gears.generation import generate_tooth

    result = run("gear", "pair", str(GEARS / "gear_pair.yaml"), "--at-diameter", "40",
                 "--at-diameter", "70")
    assert result.exit_code == 0, result.output
    rows = {cells[0]: cells for line in result.output.splitlines()
            if len(cells := [c.strip() for c in line.split("│")[1:-1]]) == 6}
    doc, _ = read_gear_document(GEARS / "gear_pair.yaml")
    pair = pair_of(doc.gear_pair)
    for name, i, d_y in (("pinion", 0, 40.0), ("wheel", 1, 70.0)):
        assert float(rows[name][1]) == d_y
        tooth = generate_tooth(pair.m_n, pair.z[i], pair.alpha_n, pair.x[i],
                               d_a=float(pair.d_a[i]), radii=2000)
        assert float(rows[name][3]) == pytest.approx(float(tooth.thickness(d_y / 2)),
                                                     abs=1e-4)


def test_no_undercut_shifts_are_the_least_that_keep_the_generated_involute_whole(tmp_path):
    from mechloop.gears.generation import generate_tooth

    path = tmp_path / "pair.yaml"
    path.write_text("gear_pair:\n  module: 2\n  teeth: [11, 40]\n  shifts: no_undercut\n",
                    encoding="utf-8")
    doc, lines = read_gear_document(path)
    pair = pair_of(doc.gear_pair, file=str(path), lines=lines)
    assert pair.x[1] == 0.0 and pair.x[0] == pytest.approx(float(pair.x_min[0]))
    for x1, cut in ((pair.x[0], False), (pair.x[0] - 0.05, True)):
        tooth = generate_tooth(2.0, 11, pair.alpha_n, x1)
        start = np.hypot(*tooth.flank[0])
        assert (tooth.cut_top > start + 1e-4) == cut


def test_pinion_shift_with_a_centre_distance(tmp_path):
    path = tmp_path / "pair.yaml"
    path.write_text("gear_pair:\n  module: 3\n  teeth: [12, 24]\n  centre_distance: 56.5\n"
                    "  pinion_shift: 0.6\n", encoding="utf-8")
    doc, lines = read_gear_document(path)
    pair = pair_of(doc.gear_pair, file=str(path), lines=lines)
    assert pair.x[0] == 0.6 and pair.a == pytest.approx(56.5, abs=1e-9)
    assert pair.x[1] == pytest.approx(0.36, abs=2e-4)  # the KHK example's, a 56.4999 there


def test_james_and_wolfrom_examples_print_their_ratios_and_draw_their_plans(tmp_path):
    plan, table = tmp_path / "plan.png", tmp_path / "w.csv"
    result = run("gear", "planetary", str(GEARS / "wolfrom.yaml"), "--plot", str(plan),
                 "-o", str(table))
    assert result.exit_code == 0, result.output
    assert plan.stat().st_size > 10_000
    frame = pd.read_csv(table).set_index("quantity")
    assert frame.loc["ratio i_ae = ω_a/ω_e (b fixed)", "value"] == pytest.approx(64.0)
    assert frame.loc["speed of e", "value"] == pytest.approx(1500 / 64)
    result = run("gear", "planetary", str(GEARS / "wolfrom.yaml"), "--model",
                 str(tmp_path / "m.yaml"))
    assert result.exit_code == 2 and "wolfrom train is not written" in result.output
    table = tmp_path / "j.csv"
    result = run("gear", "planetary", str(GEARS / "james_sun_fixed.yaml"), "--plot",
                 str(tmp_path / "j.png"), "-o", str(table))
    assert result.exit_code == 0, result.output
    frame = pd.read_csv(table).set_index("quantity")
    assert frame.loc["ratio i_bh = ω_b/ω_h (a fixed)", "value"] == pytest.approx(1.25)
    assert frame.loc["speed of a", "value"] == 0.0
    assert frame.loc["speed of h", "value"] == pytest.approx(1200 / 1.25)
    model = tmp_path / "james.yaml"
    result = run("gear", "planetary", str(GEARS / "james_sun_fixed.yaml"), "--model",
                 str(model))
    assert result.exit_code == 0, result.output
    frame = solve(mechloop.load_model(model)).to_frame()
    turn = frame["a8 [deg]"].to_numpy()               # the ring b drives (argument 1)
    assert "a1 [deg]" not in frame                    # the sun is held: a constant angle
    assert np.allclose(frame["a2 [deg]"].to_numpy()[1:] / turn[1:], 1 / 1.25, rtol=1e-12)


def test_a_wolfrom_train_chosen_for_a_target_ratio(tmp_path):
    path, table = tmp_path / "w.yaml", tmp_path / "designs.csv"
    path.write_text("planetary:\n  scheme: wolfrom\n  planets: 3\n  target_ratio: 64\n"
                    "  search: {teeth_min: 12, teeth_max: 90, show: 4}\n", encoding="utf-8")
    result = run("gear", "planetary", str(path), "-o", str(table))
    assert result.exit_code == 0, result.output
    designs = pd.read_csv(table)
    assert list(designs.columns[:6]) == ["a", "g", "f", "b", "e", "i_ae"]
    assert designs.iloc[0, :5].tolist() == [15, 24, 21, 63, 60]
    assert len(designs) == 4 and (designs["error [%]"] <= 1).all()
    assert "ratio i_ae = ω_a/ω_e (b fixed)" in result.output
