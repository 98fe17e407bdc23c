"""Every figure the report draws, put into Russian by ``views.russian.translate``, holds no
English word: only symbols (r3, φ1, F_bal, S2), unit names and the user's own names from
the model (issue 15: "Russian throughout")."""

from __future__ import annotations

from pathlib import Path

import matplotlib.pyplot as plt
import pytest
from helpers.latin import latin_words

import mechloop
from mechloop.cams import load_cam
from mechloop.views import curves, dynamics, formula, plan
from mechloop.views.cam_sheet import cam_sheet
from mechloop.views.gear_sheet import gear_sheet, load_gears
from mechloop.views.russian import figure_texts, russian, translate

ROOT = Path(__file__).resolve().parents[1]
EXAMPLES = ["crank_slider_dynamics.yaml", "course/05_compressor.yaml",
            "course/01_an10_landing_gear.yaml", "single_cylinder_engine.yaml",
            "four_bar_break_ahead.yaml"]


def user_names(model: mechloop.Model) -> list[str]:
    """The names the user gave in the model: its name, vectors, contours, bodies, joints,
    loads (drawn as given, so they may be English)."""
    names = [model.name]
    names += [v.name or "" for v in model.vectors.values()]
    names += [c.name or "" for c in model.contours]
    names += [getattr(b, "name", None) or "" for b in model.bodies.values()]
    names += [*(model.joints or {}), *model.gears]
    for load in [*model.forces, *model.moments, *model.springs, *model.dampers]:
        names.append(getattr(load, "name", None) or "")
    return [n for n in names if n]


def english(figure, names) -> list[tuple[str, str]]:
    """(word, text) of every English word in the figure's texts after translation."""
    translate(figure, "ru")
    found = [(word, text.get_text()) for text in figure_texts(figure)
             for word in latin_words(text.get_text(), names)]
    plt.close(figure)
    return found


def report_figures(model: mechloop.Model):
    """The figures the report draws for ``model`` (one of each kind per model)."""
    dyn = mechloop.solve_dynamics(model) if model.bodies else None
    res = dyn.kinematics if dyn is not None else mechloop.solve(model)
    source = dyn if dyn is not None else res
    name = res.varying()[-1]
    whole = [int(k) for k in range(res.positions.size) if not res.broken[k]]
    middle = whole[len(whole) // 2]
    broken = [int(k) for k in range(res.positions.size) if res.broken[k]]
    yield "plan", plan.plot_plan(source, middle)
    if broken:
        yield "plan at a break", plan.plot_plan(source, broken[0])
    yield "structure", formula.plot_structure(model)
    yield "increment", curves.plot_increment(source, name, middle)
    vectors = model.contours[0].vectors
    yield "angle", curves.plot_angle_between(source, vectors[0], vectors[1])
    against = f"arg{min(res.arguments)}" if res.arguments else "position"
    yield "parameters", curves.plot_parameters(source, [name, f"d{name}", f"dd{name}"],
                                               against=against)
    yield "parameters/position", curves.plot_parameters(source, [name])
    yield "combination", curves.plot_combination(source, name, 2.0, "product")
    if dyn is None:
        return
    if dyn.reduced is not None:
        yield "reduced", dynamics.plot_reduced(dyn)
    yield "balancing", dynamics.plot_balancing(dyn)
    yield "reactions", dynamics.plot_reactions(dyn)
    joint = next(iter(dyn.forces.reactions))
    yield "hodograph", dynamics.plot_hodograph(dyn, joint)
    yield "hodograph/polar", dynamics.plot_hodograph(dyn, joint, polar=True)
    yield "summary", dynamics.plot_summary(dyn)
    if dyn.cycle is not None:
        yield "machine motion", dynamics.plot_machine_motion(dyn)
    centres = [f"S{b}" for b in dyn.centers]
    yield "trajectories", plan.plot_trajectories(dyn, centres[:6], position=middle)


@pytest.mark.parametrize("path", EXAMPLES)
def test_report_figures_in_russian_have_no_english_words(path):
    model = mechloop.load_model(ROOT / "examples" / path)
    names = user_names(model)
    found = {}
    for kind, figure in report_figures(model):
        words = english(figure, names)
        if words:
            found[kind] = words
    assert not found, f"English left in the Russian figures: {found}"


def test_motion_in_time_in_russian_has_no_english_words():
    from mechloop.views.motion import plot_simulation

    model = mechloop.load_model(ROOT / "examples/compressor_startup.yaml")
    sim = mechloop.simulate(model)  # ends steady: the steady time is marked and named
    assert sim.steady_time is not None
    assert not english(plot_simulation(sim), user_names(model))


@pytest.mark.parametrize("which", ["cam", "gears", "planetary"])
def test_sheet_figures_in_russian_have_no_english_words(which):
    if which == "cam":
        design = load_cam(ROOT / "examples/cams/roller.yaml")
        sheet, names = cam_sheet(design, "ru"), [design.name]
    else:
        file = "gear_pair.yaml" if which == "gears" else "planetary_choice.yaml"
        sheet, names = gear_sheet(load_gears(ROOT / "examples/gears" / file), "ru"), []
    assert sheet.figures
    for item in sheet.figures:
        assert not english(item.draw(), names), item.caption


def test_the_users_names_stay_as_written():
    # the model's name holds English words the figures use ("to", "break")
    model = mechloop.load_model(ROOT / "examples/four_bar_break_ahead.yaml")
    assert " to the break" in model.name
    res = mechloop.solve(model)
    broken = int(res.broken.nonzero()[0][0])
    for figure in (plan.plot_plan(res, broken), formula.plot_structure(model)):
        texts = [" ".join(t.get_text().split()) for t in figure_texts(translate(figure, "ru"))]
        assert any(model.name in t for t in texts)  # (the structure's header wraps it)
        assert any("разрыв цепи" in t or "контур" in t for t in texts)
        plt.close(figure)


def test_translation_takes_whole_words_and_leaves_symbols_and_names_units_in_russian():
    assert russian("positions 0..72; position 5") == "положения 0..72; положение 5"
    assert russian("time [s]") == "время [с]"  # GOST 8.417's designation
    assert russian("RA_to_a2 [deg]") == "RA_to_a2 [°]"  # a symbol: not 'to' in it
    assert russian("timer, ground4") == "timer, ground4"  # not a word of ours
    assert russian("reduced load") == "приведённая нагрузка"  # the phrase, not 'load' alone
    assert russian("dJ_red [kg*m^2/rad]") == "dJ_red [кг·м²/рад]"
    assert russian("x [px], y [a.u.]") == "x [px], y [a.u.]"  # not units mechloop prints


@pytest.mark.parametrize(("kind", "extra", "title"), [
    ("reactions", [], "реакции в шарнирах"), ("plan", ["-p", "20"], "положение 20 из 0..72"),
    ("angle", ["-n", "1,2"], "угол от вектора 1 к вектору 2")])
def test_plot_command_draws_in_russian_with_lang_ru(kind, extra, title, tmp_path,
                                                   monkeypatch):
    import matplotlib
    from typer.testing import CliRunner

    from mechloop.cli import app

    monkeypatch.setitem(matplotlib.rcParams, "svg.fonttype", "none")  # texts kept as text
    model = ROOT / "examples/crank_slider_dynamics.yaml"
    for lang in ("ru", "en"):
        out = tmp_path / f"{kind}_{lang}.svg"
        result = CliRunner().invoke(app, ["plot", str(model), kind, *extra, "--lang", lang,
                                          "-o", str(out)])
        assert result.exit_code == 0, result.output
        assert ("записан файл" in result.output) == (lang == "ru")
        svg = out.read_text(encoding="utf-8")
        assert (title in svg) == (lang == "ru")
    result = CliRunner().invoke(app, ["plot", str(model), kind, "--lang", "de", "-o",
                                      str(tmp_path / "x.svg")])
    assert result.exit_code == 2 and "no figure language 'de'" in result.output


def test_envelope_in_russian_has_no_english_words():
    from mechloop.views.envelope import plot_envelope

    model = mechloop.load_model(ROOT / "examples/cam_roller_follower.yaml")
    figure = plot_envelope(mechloop.solve_intermediate(model))
    assert not english(figure, [*user_names(model), *(e.name for e in model.envelopes)])
