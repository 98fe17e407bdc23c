"""The summary of a simulation (``mechloop simulate``, the web's simulation job) in
Russian: the same lines and the same numbers as in English, no English word, the decimal
comma; ``--lang`` on the command line."""

from __future__ import annotations

import re
from pathlib import Path

import pytest
from helpers.latin import latin_words, model_names
from typer.testing import CliRunner

from mechloop.cli import app
from mechloop.dynamics.simulate import simulate
from mechloop.dynamics.simulate_summary import summary_lines
from mechloop.model.load import load_model

EXAMPLES = Path(__file__).parent.parent / "examples"
#: The bundled simulations (duration cut to keep the test cheap, s; None: the model's).
CASES = {"four_bar_break_ahead.yaml": None, "two_input_five_bar.yaml": 1.0,
         "spring_release.yaml": 0.5, "compressor_startup.yaml": 0.6}
NUMBER_EN = re.compile(r"-?\d+(?:\.\d+)?(?:e[-+]?\d+)?")
NUMBER_RU = re.compile(r"-?\d+(?:,\d+)?(?:·10[⁻⁰¹²³⁴⁵⁶⁷⁸⁹]+)?")
SUPERSCRIPT = str.maketrans("⁻⁰¹²³⁴⁵⁶⁷⁸⁹", "-0123456789")


def _numbers_en(text: str) -> list[float]:
    return [float(n) for n in NUMBER_EN.findall(re.sub(r"\^\d", "", text))]  # kg*m^2


def _numbers_ru(text: str) -> list[float]:
    out = []
    for n in NUMBER_RU.findall(text):
        mantissa, _, power = n.partition("·10")
        out.append(float(mantissa.replace(",", "."))
                   * (10.0 ** int(power.translate(SUPERSCRIPT)) if power else 1.0))
    return out


@pytest.mark.parametrize("name", sorted(CASES))
def test_the_russian_summary_says_what_the_english_one_says(name):
    model = load_model(EXAMPLES / name)
    settings = model.simulate
    if CASES[name] is not None:
        settings = settings.model_copy(update={"duration": CASES[name], "cycles": None})
    sim = simulate(model, settings)
    english, russian = summary_lines(sim, "en"), summary_lines(sim, "ru")
    assert [w for _, w in english] == [w for _, w in russian] and len(english) >= 2
    for (en, _), (ru, _) in zip(english, russian, strict=True):
        assert not latin_words(ru, model_names(model)), ru
        assert "." not in re.sub(r"…", "", ru).replace("кг·м", ""), ru  # decimal comma
        assert _numbers_ru(ru) == pytest.approx(_numbers_en(en), rel=1e-12), (en, ru)


def test_simulate_prints_its_summary_in_the_language_asked(monkeypatch):
    monkeypatch.delenv("MECHLOOP_LANG", raising=False)
    path = str(EXAMPLES / "spring_release.yaml")
    runner = CliRunner()
    ru = runner.invoke(app, ["simulate", path, "--duration", "0.5", "--lang", "ru"])
    en = runner.invoke(app, ["simulate", path, "--duration", "0.5"])
    assert ru.exit_code == 0 and en.exit_code == 0, (ru.output, en.output)
    assert "приведённый момент инерции" in ru.output and "энергия: " in ru.output
    assert "reduced inertia" in en.output and "приведённый" not in en.output
    monkeypatch.setenv("MECHLOOP_LANG", "ru")
    assert "энергия: " in runner.invoke(app, ["simulate", path, "--duration", "0.5"]).output
    bad = runner.invoke(app, ["simulate", path, "--lang", "de"])
    assert bad.exit_code == 2 and "--lang" in bad.output
