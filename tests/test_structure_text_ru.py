"""The structure texts in Russian (issues 15, 16): ``mechloop info``'s description of the
vector model and ``mechloop structure``'s analysis, with ``lang='ru'``, ``--lang ru``,
``MECHLOOP_LANG=ru`` and the web's ``X-Mechloop-Lang: ru``.

English stays as it was byte for byte (literal texts below; every bundled example was
compared with the output before the change when it was made).  The Russian text of every
bundled example holds no Latin word but symbols, units and the model's own names, and the
same numbers as the English one, read back with the decimal comma.
"""

from __future__ import annotations

import re
from functools import cache
from pathlib import Path

import pytest
from helpers.latin import latin_words, model_names
from starlette.testclient import TestClient
from typer.testing import CliRunner

from mechloop.cli import app
from mechloop.errors import ModelError
from mechloop.model.formula import describe_structure
from mechloop.model.formula_words import RUSSIAN_LAWS
from mechloop.model.load import load_model
from mechloop.structure import analyze
from mechloop.structure.text import mobility_text, structure_lines, table_text
from mechloop.structure.words_ru import russian
from mechloop.web.app import create_app

ROOT = Path(__file__).resolve().parents[1]
EXAMPLES = sorted([*ROOT.glob("examples/*.yaml"), *ROOT.glob("examples/course/*.yaml")])
_SUPER = str.maketrans("⁰¹²³⁴⁵⁶⁷⁸⁹⁻", "0123456789-")
_NUMBER = re.compile(r"(?<![\w.,])-?\d+(?:[.,]\d+)?(?:e[-+]?\d+)?")


@cache
def _model(path: Path):
    try:
        return load_model(path)
    except Exception:  # not a vector model (a cam design, groups file): no description
        return None


def _vector_models() -> list[Path]:
    return [p for p in EXAMPLES if (m := _model(p)) is not None and m.contours]


def numbers(text: str) -> list[float]:
    """The numbers of ``text`` (English, or Russian with the decimal comma and ·10⁻⁵), in
    order; the Russian names of the laws are put back (``полином 3-4-5`` is poly345)."""
    for law, said in RUSSIAN_LAWS.items():
        text = text.replace(f"«{said}»", law)
    text = re.sub(r"·10([⁰¹²³⁴⁵⁶⁷⁸⁹⁻]+)", lambda m: "e" + m[1].translate(_SUPER), text)
    return sorted(float(n.replace(",", ".")) for n in _NUMBER.findall(text))


def _check_russian(english: str, russian_text: str, model) -> None:
    assert latin_words(russian_text, model_names(model)) == []
    assert numbers(russian_text) == numbers(english)


@pytest.mark.parametrize("path", _vector_models(), ids=lambda p: p.name)
def test_description_in_russian(path):
    model = _model(path)
    english, russian_text = describe_structure(model), describe_structure(model, "ru")
    assert english == describe_structure(model, "en")
    assert russian_text.count("\n") == english.count("\n")
    _check_russian(english, russian_text, model)


@cache
def _analysis(path: Path):
    model = _model(path)
    if model is None or not model.bodies:
        return None
    try:
        return model, *analyze(model)
    except ModelError:
        return None


def _mechanisms() -> list[Path]:
    return [p for p in EXAMPLES if _analysis(p) is not None]


@pytest.mark.parametrize("path", _mechanisms(), ids=lambda p: p.name)
def test_structure_in_russian(path):
    model, mob, dec = _analysis(path)
    assert mobility_text(mob) == str(mob)
    english = "\n".join(t for _, t in structure_lines(mob, dec)) + table_text(dec)
    said = "\n".join(t for _, t in structure_lines(mob, dec, "ru")) + table_text(dec, "ru")
    _check_russian(english, said, model)


def test_english_structure_as_before():
    """``mechloop structure`` of the gear pair (a higher pair and a note) as it printed
    before the languages, byte for byte."""
    result = CliRunner().invoke(app, ["structure", str(ROOT / "examples/gear_pair_dynamics.yaml")],
                                env={"MECHLOOP_LANG": "en", "COLUMNS": "300"})
    assert result.exit_code == 0, result.output
    assert result.output.splitlines()[:6] == [
        "n = 2, p5 = 2, p4 = 1 (gear mesh (ratio link) between bodies 1 and 2, ratio -0.4 "
        "(a3 = -0.4·a1 + Δ): a higher pair p4): W = 3·2 − 2·2 − 1 = 1; inputs: 1. W = 1 "
        "equals the number of inputs.",
        "structure formula: L0(1) → L1(2,3)",
        "class of the mechanism: II",
        "  L0(1): external J0_1 R 1→0; internal —",
        "  L1(2,3): external J0_2 R 2→0, N1_3 R 3→1; internal N3_2 R 3–2",
        "note: the gear mesh between bodies 1 and 2 is replaced by its equivalent, link 3 "
        "with revolute pairs N1_3 and N3_2 (at the centres of curvature of the teeth in "
        "contact)"]


def test_english_description_as_before():
    text = describe_structure(load_model(ROOT / "examples/course/01_an10_landing_gear.yaml"))
    assert text.splitlines()[4:9] == [
        "",
        "contour 1 — cylinder and leg: vectors 1, 2, 3",
        "  structure formula:  n=2, m=3",
        "  parametric formula: r2 (arg 1) → α1, α2 · Pl4, V=2 (2 solution(s))",
        "  constants:          r1=400 mm, r3=1612.45 mm, α3=-29.745 deg"]
    assert describe_structure(load_model(ROOT / "examples/course/01_an10_landing_gear.yaml"),
                              "ru").splitlines()[8] == \
        "  постоянные:              r1=400 мм, r3=1612,45 мм, α3=-29,745°"


def test_every_sentence_of_the_analysis_in_russian():
    """The notes no bundled example reaches, written as the analysis writes them."""
    sentences = [
        "W = 2 > 1 input(s): 1 input(s) missing — the mechanism needs 1 more drive(s), or a "
        "link has a local mobility",
        "W = 0 ≤ 0 and no inputs: a structure (a truss), not a mechanism",
        "W = -1 ≤ 0 and no inputs: a structure (a truss), not a mechanism, with redundant "
        "constraints",
        "W = 0 < 1 input(s): redundant constraints (an over-constrained chain, a passive "
        "link) or more drives than the chain can take; W ≤ 0: the chain cannot move at all "
        "unless its geometry is special",
        "link 4 is held by J3_4, J0_4, argument 2 to links already placed: 5 conditions on "
        "its 3 freedoms — a passive link, its extra constraint redundant",
        "link 4 is held only by J3_4: it keeps 1 degree(s) of freedom of its own — a local "
        "mobility",
        "link 5 is joined to nothing: it keeps 3 degree(s) of freedom of its own — a local "
        "mobility",
        "links 2, 3 keep 1 degree(s) of freedom: an input is missing (or they have a local "
        "mobility)",
        "links 2, 3 have 1 constraint(s) more than their freedoms: a redundant constraint "
        "(an over-constrained chain)",
        "links 2, 3, 4 have as many constraints as freedoms but form no rigid group: one part "
        "is over-constrained while another moves (or a chain of prismatic pairs slides "
        "freely)",
        "the drive of argument 2 acts between links 1 and 3, which are placed without it: a "
        "redundant input"]
    names = ["J3_4", "J0_4"]
    for sentence in sentences:
        said = russian(sentence)
        assert said != sentence and latin_words(said, names) == [], said
        assert numbers(said) == numbers(sentence), said


def test_cli_and_environment():
    runner = CliRunner()
    path = str(ROOT / "examples/crank_slider_dynamics.yaml")
    model = load_model(path)
    by_option = runner.invoke(app, ["info", path, "--lang", "ru"], env={"COLUMNS": "300"})
    by_env = runner.invoke(app, ["info", path], env={"MECHLOOP_LANG": "ru", "COLUMNS": "300"})
    assert by_option.exit_code == by_env.exit_code == 0
    assert by_option.output == by_env.output == describe_structure(model, "ru") + "\n"
    text = runner.invoke(app, ["structure", path], env={"MECHLOOP_LANG": "ru",
                                                        "COLUMNS": "300"}).output
    assert "класс механизма: II" in text and "число входов: 1" in text
    assert latin_words(text, model_names(model)) == []
    bad = runner.invoke(app, ["structure", path, "--lang", "de"], env={"MECHLOOP_LANG": "ru"})
    assert bad.exit_code == 2 and "нет языка текста 'de'" in bad.output


def test_web_structure_in_russian(tmp_path):
    client = TestClient(create_app(tmp_path))
    text = (ROOT / "examples/gear_pair_dynamics.yaml").read_text(encoding="utf-8")
    source = {"example": "gear_pair_dynamics", "text": text}
    english = client.post("/api/structure", json=source).json()
    said = client.post("/api/structure", json=source,
                       headers={"X-Mechloop-Lang": "ru"}).json()
    model = load_model(ROOT / "examples/gear_pair_dynamics.yaml")
    mob, dec = analyze(model)
    assert english["mechanism"]["explanation"] == mob.explanation
    assert english["mechanism"]["notes"] == list(dec.notes)
    assert said["description"] == describe_structure(model, "ru")
    assert said["mechanism"]["explanation"] == "W = 1 равно числу входов."
    assert said["mechanism"]["notes"][0].startswith("зубчатое зацепление звеньев 1 и 2")
    assert said["mechanism"]["formula"] == english["mechanism"]["formula"]


def test_simulation_events_in_russian():
    """Every kind of event: English as it always was (the literal text), Russian without
    Latin words and with the same numbers."""
    import math

    from mechloop.dynamics.motors import RPM
    from mechloop.dynamics.simulate import Event
    from mechloop.dynamics.simulate_words import RUSSIAN_KINDS

    at = math.radians(123.456789)
    for kind in RUSSIAN_KINDS:
        event = Event(kind, 1.25, math.radians(90.5), 1450.5 * RPM,
                      at if kind == "chain break ahead" else None)
        english, said = event.describe(), event.describe("ru")
        assert english.startswith(f"{kind}: t = 1.25 s, angle 90.5 deg, speed 1450.5 rpm")
        assert said.startswith(f"{RUSSIAN_KINDS[kind]}: t = 1,25 с, угол 90,5°, скорость "
                               "1450,5 об/мин")
        assert latin_words(said) == [] and numbers(said) == numbers(english)
    assert Event("chain break ahead", 1.25, math.radians(90.5), 0.0, at).describe() \
        .endswith(" — the run stops at the last position before the break; the chain "
                  "breaks at angle 123.45679 deg, 32.96 deg further on")
