"""Error messages in Russian (issue 15: "CLI messages … contain no English words except
symbols, unit names and the user's own names"): a corpus of bad inputs — the mistakes of
tests/test_cli_errors.py, tests/test_solve_errors_located.py and tests/test_loading_limits.py,
the plot and report commands' refusals, and a fixed sample of tests/test_fuzz_models.py's
mutations — run through the command line with ``MECHLOOP_LANG=ru`` (or ``--lang ru``) print
no English word; the same inputs in English print exactly what they printed before."""

from __future__ import annotations

import re
import string
import textwrap
from pathlib import Path

import pytest
from fuzz.mutations import BILLION_LAUGHS, mutated
from helpers.latin import latin_words
from hypothesis import HealthCheck, Phase, given, settings
from hypothesis import strategies as st
from test_cli_errors import CASES, GOOD
from test_solve_errors_located import SOLVE_CASES
from typer.testing import CliRunner

from mechloop.cli import app
from mechloop.errors import HintedError, ModelError, Problem
from mechloop.messages import message_language, render_error
from mechloop.messages.catalogue_ru import _COMPILED, ENTRIES, has_russian, translate

EXAMPLES = Path(__file__).resolve().parents[1] / "examples"
CRANK = (EXAMPLES / "crank_slider.yaml").read_text()
DYN = str(EXAMPLES / "crank_slider_dynamics.yaml")
SLIDER = str(EXAMPLES / "crank_slider.yaml")
DYN_TEXT = (EXAMPLES / "crank_slider_dynamics.yaml").read_text()
ROCKER = (EXAMPLES / "cams" / "rocker.yaml").read_text()
CAM_BAD = """\
cam:
  follower: {type: oscillating_roller, roller_radius: -1, arm: 0}
  base_radius: -3
  segments:
    - {rise: -20, angle: 0, law: cycloidal}
    - {dwell: 0}
    - {table: [[0, 1], [10, 0]]}
    - {table: [[0, 0], [10, 3], [5, 4]]}
    - {table: [[0, 0], [10, 0]]}
"""

#: The user's own text in a message: quoted values and names, key paths and YAML keys
#: (before a colon), file paths, command-line options, and the names of file formats.
QUOTED = re.compile(r"'[^'\n]*'")
KEYS = re.compile(r"[\w.\[\]]+(?=:)")
PATHS = re.compile(r"\S*/\S*|\S+\.(?:ya?ml|json|csv|png|svg|pdf|docx|txt|xlsx|parquet)\b")
OPTIONS = re.compile(r"--\w+(?: \w+)?")
SUFFIXES = re.compile(r"(?<![\w.])\.\w+")
FORMATS = ["YAML", "JSON", "CSV", "UTF-8"]
#: The unit names a fix lists ("используйте единицу угла: deg, rad, grad").
UNIT_LIST = re.compile(r"единиц[уы] [ а-яё]+: ([^\n]*)")


def user_names(text: str) -> list[str]:
    """The parts of a printed message that are the user's (or the file's) own words."""
    return [*QUOTED.findall(text), *KEYS.findall(text), *PATHS.findall(text),
            *OPTIONS.findall(text), *SUFFIXES.findall(text), *UNIT_LIST.findall(text), *FORMATS]


def english_left(text: str) -> list[str]:
    return latin_words(text, user_names(text))


def _files(tmp_path: Path, text: str | bytes) -> Path:
    path = tmp_path / "model.yaml"
    if isinstance(text, bytes):
        path.write_bytes(text)
    else:
        path.write_text(textwrap.dedent(text), encoding="utf-8")
    return path


def _run(args: list[str], lang: str | None) -> tuple[int, str]:
    env = {"MECHLOOP_LANG": lang} if lang else {"MECHLOOP_LANG": ""}
    result = CliRunner().invoke(app, args, env=env)
    return result.exit_code, result.output


# name, command, file text (None: the arguments name existing files), extra arguments
CORPUS: list[tuple[str, str, str | bytes | None, list[str]]] = [
    *((name, "check", text, []) for name, text, *_ in CASES),
    *((name, "solve", text, []) for name, text, *_ in SOLVE_CASES),
    ("non_utf8", "check", CRANK.encode().replace(b"connecting rod", b"connecting \xff rod"),
     []),
    ("list_as_key", "check", CRANK.replace("positions: 72", "positions: 72\n? [1, 2]\n: 3"),
     []),
    ("alias_bomb", "check", BILLION_LAUGHS + CRANK, []),
    ("deep_nesting", "check", "a: " + "[" * 1000 + "]" * 1000 + "\n", []),
    ("long_value", "check", CRANK.replace("positions: 72", "positions: " + "9" * 20000), []),
    ("unknown_output_format", "solve", GOOD, ["-o", "{tmp}/r.txt"]),
    ("missing_file", "check", None, ["{tmp}/nope.yaml"]),
    ("plot_unknown_view", "plot", None, [SLIDER, "spline", "-o", "{tmp}/a.png"]),
    ("plot_unknown_quantity", "plot", None, [SLIDER, "parameters", "-n", "zz9", "-o",
                                             "{tmp}/a.png"]),
    ("plot_seven_curves", "plot", None, [SLIDER, "parameters", "-n",
                                         "r3,dr3,ddr3,a2,a3,da2,da3", "-o", "{tmp}/a.png"]),
    ("plot_position", "plot", None, [SLIDER, "plan", "-p", "999", "-o", "{tmp}/a.png"]),
    ("plot_format", "plot", None, [SLIDER, "plan", "-o", "{tmp}/a.txt"]),
    ("plot_no_vector", "plot", None, [SLIDER, "angle", "-n", "2,9", "-o", "{tmp}/a.png"]),
    ("plot_needs_bodies", "plot", None, [SLIDER, "hodograph", "--joint", "Q", "-o",
                                         "{tmp}/a.png"]),
    ("plot_varying_power", "plot", None, [SLIDER, "combination", "-n", "r3,a2", "--op",
                                          "power", "-o", "{tmp}/a.png"]),
    ("plot_no_joint", "plot", None, [DYN, "hodograph", "--joint", "Z", "-o", "{tmp}/h.png"]),
    ("units_unknown", "solve", None, [DYN, "--units", "force=kgx", "-o", "{tmp}/x.csv"]),
    ("units_wrong_kind", "solve", None, [DYN, "--units", "omega=mm", "-o", "{tmp}/x.csv"]),
    ("units_unknown_kind", "solve", None, [DYN, "--units", "colour=red", "-o",
                                           "{tmp}/x.csv"]),
    ("units_not_a_pair", "solve", None, [DYN, "--units", "force", "-o", "{tmp}/x.csv"]),
    ("digits_out_of_range", "solve", None, [DYN, "--digits", "40", "-o", "{tmp}/x.csv"]),
    ("report_format", "report", None, [DYN, "-o", "{tmp}/r.txt"]),
    ("report_parameter", "report", None, [DYN, "-o", "{tmp}/r.pdf", "--parameter", "q7"]),
    ("report_position", "report", None, [DYN, "-o", "{tmp}/r.pdf", "--position", "999"]),
    ("new_unknown_example", "new", None, ["nosuch_example_zz"]),
    ("new_missing_folder", "new", None, ["crank_slider", "{tmp}/no/such/x.yaml"]),
    ("sweep_bad_range", "sweep", None, [SLIDER, "--vary", "time.rpm=1000:4000", "--collect",
                                        "r3:max"]),
    # the force analysis's model (mechloop.dynamics): bodies, joints, friction
    ("joint_one_body", "solve", DYN_TEXT.replace("bodies: [0, 3], along", "bodies: [3, 3], along"),
     []),
    ("body_unknown_vector", "solve", DYN_TEXT.replace(
        "center: {tail: 3}}", "center: {tail: 3}}\n  4: {vectors: [9], mass: 1}"), []),
    ("friction_no_radius", "solve", DYN_TEXT.replace("at: {tail: 1}}",
                                                     "at: {tail: 1}, friction: 0.1}"), []),
    # the model's area: a group file, its synthesis task, a vector model's synthesis task
    ("groups_unit_and_order", "check", (EXAMPLES / "four_bar_groups.yaml").read_text()
     .replace("at: [A, C]", "at: [A, P]").replace("length: 100,", "length: 100 kg,"), []),
    ("groups_unknown_dimension", "check", (EXAMPLES / "four_bar_groups_synthesis.yaml")
     .read_text().replace("points.P.distance:", "points.P.distanse:"), []),
    ("synthesis_vary", "check", (EXAMPLES / "four_bar_path_synthesis.yaml").read_text()
     .replace("r1: [50, 150]", "r1: [150, 50]\n    q7: [1, 2]\n    r2.ratio: [1, 2]")
     .replace("r4: [200, 400]", "r4: periodic").replace("{head: 6}", "{head: 9}"), []),
    # views, output files and the command line (mechloop.messages.ru.views, .web)
    ("plot_combination_one_name", "plot", None, [SLIDER, "combination", "-n", "r3", "-o",
                                                 "{tmp}/a.png"]),
    ("plot_hodograph_no_joint", "plot", None, [DYN, "hodograph", "-o", "{tmp}/h.png"]),
    ("plot_trace_no_vector", "plot", None, [SLIDER, "trajectories", "--points", "head:99",
                                            "-o", "{tmp}/a.png"]),
    ("output_no_folder", "plot", None, [SLIDER, "plan", "-o", "{tmp}/no folder/a.png"]),
    ("output_no_suffix", "solve", None, [SLIDER, "-o", "{tmp}/a"]),
    ("energy_no_bodies", "energy", None, [SLIDER]),
    ("serve_port", "serve", None, [SLIDER, "--port", "70000"]),
    ("cam_document", "cam", CAM_BAD, []),
    ("cam_segment_kinds", "cam", CAM_BAD.replace("{dwell: 0}", "{dwell: 60, law: harmonic}")
     .replace("{rise: -20, angle: 0, law: cycloidal}", "{rise: 20, return: 3}"), []),
    ("cam_span", "cam", ROCKER.replace("pressure_angle: 40", "pressure_angle: 100")
     .replace("{dwell: 60}", "{dwell: 50}"), []),
    ("cam_rocker_no_base_radius", "cam", ROCKER.replace("pressure_angle: 40",
                                                        "pressure_angle: 2"), []),
    ("gear_centre_distance", "gear", None, ["pair", "-m", "2", "-z", "10", "20", "-a", "20"]),
    ("gear_file_and_options", "gear", None, ["pair", str(EXAMPLES / "gears" / "gear_pair.yaml"),
                                             "-m", "2"]),
    ("gear_wolfrom_model", "gear", None, ["planetary", str(EXAMPLES / "gears" / "wolfrom.yaml"),
                                          "--model", "{tmp}/m.yaml"]),
]


def _args(tmp_path: Path, command: str, text, extra: list[str]) -> list[str]:
    extra = [a.replace("{tmp}", str(tmp_path)) for a in extra]
    if text is None:
        return [command, *extra]
    return [command, str(_files(tmp_path, text)), *extra]


def _places(output: str) -> list[str]:
    """The located places of a printed error (``file:line`` and key path)."""
    return re.findall(r"(\S+\.\w+:\d+)", output)


@pytest.mark.parametrize(("command", "text", "extra"),
                         [pytest.param(c, t, e, id=n) for n, c, t, e in CORPUS])
def test_errors_in_russian_have_no_english_words(tmp_path, command, text, extra):
    args = _args(tmp_path, command, text, extra)
    code_en, english = _run(args, None)
    code_ru, russian = _run(args, "ru")
    assert code_en == code_ru == 2, (english, russian)
    assert english.startswith("error: ") and not re.search("[А-Яа-яЁё]", english), english
    assert russian.startswith("ошибка: "), russian
    assert "error:" not in russian and "fix:" not in russian and "Traceback" not in russian
    assert english_left(russian) == [], russian
    assert _places(russian) == _places(english)  # the same places, in the same order
    assert russian.count("как исправить:") == english.count("fix:")


@pytest.mark.parametrize("command", ["report", "plot"])
def test_a_commands_lang_ru_reaches_its_errors(tmp_path, command):
    args = ([command, DYN, "-o", str(tmp_path / "r.txt")] if command == "report" else
            [command, SLIDER, "spline", "-o", str(tmp_path / "a.png")])
    _, english = _run(args, None)
    _, russian = _run([*args, "--lang", "ru"], None)
    assert english.startswith("error: ") and russian.startswith("ошибка: ")
    assert english_left(russian) == []


@pytest.mark.parametrize("command", ["report", "plot"])
def test_a_commands_lang_overrides_the_environment(tmp_path, command):
    """``--lang en`` under ``MECHLOOP_LANG=ru`` prints English; with no ``--lang`` the
    environment's language is the command's (its messages and, for plot, its figure)."""
    args = ([command, DYN, "-o", str(tmp_path / "r.txt")] if command == "report" else
            [command, SLIDER, "spline", "-o", str(tmp_path / "a.png")])
    _, english = _run([*args, "--lang", "en"], "ru")
    _, russian = _run(args, "ru")
    assert english.startswith("error: ") and russian.startswith("ошибка: ")
    if command == "plot":
        code, text = _run([command, SLIDER, "plan", "-o", str(tmp_path / "p.svg")], "ru")
        assert code == 0 and "записан файл" in text
        assert "Положение" in (tmp_path / "p.svg").read_text() or \
            "положение" in (tmp_path / "p.svg").read_text()


USAGE = [["solve", "--nosuch", "x"], ["solve"], ["nosuchcmd"],
         ["solve", SLIDER, "--digits", "abc"], ["solve", SLIDER, "-o"],
         ["solve", SLIDER, "extra1", "extra2"], ["report", DYN],
         ["solve", SLIDER, "--force=3"], ["synthesize", SLIDER, "--method", "zz"],
         ["plot", SLIDER, "plan", "-p", "x", "-o", "a.png"]]


@pytest.mark.parametrize("args", USAGE, ids=lambda a: "-".join(a[:1] + a[2:3]))
def test_usage_errors_in_russian(args):
    """Click's own usage errors (printed by Typer before a command runs): Russian under
    ``MECHLOOP_LANG=ru``, as before without it."""
    code, english = _run(args, None)
    code_ru, russian = _run(args, "ru")
    assert code == code_ru == 2
    assert "Error" in english and ("Usage:" in english or "Option" in english)
    assert "Ошибка" in russian and "Error" not in russian
    panel = " ".join(line.strip("│ ") for line in russian.splitlines() if "│" in line)
    assert panel and english_left(panel) == [], panel


def test_english_is_the_errors_own_text_byte_for_byte():
    errors = [ModelError([Problem(("vectors", 2, "r"), "'20 kg' is not a length",
                                  "use a length unit: m, cm, mm", 7)], "m.yaml"),
              ModelError([Problem((), "file not found", "x"), Problem(("a",), "b")]),
              HintedError("unknown view 'spline'", "use one of plan, overlay")]
    for error in errors:
        assert render_error(error, "en") == str(error)
    assert render_error(errors[1], "ru") == ("проблем в модели: 2\n- файл не найден\n"
                                             "      как исправить: x\n- a: b")


def test_the_language_comes_from_the_option_then_the_environment(monkeypatch):
    monkeypatch.delenv("MECHLOOP_LANG", raising=False)
    assert message_language() == "en" and message_language("ru") == "ru"
    monkeypatch.setenv("MECHLOOP_LANG", " RU ")
    assert message_language() == "ru" and message_language("en") == "en"
    monkeypatch.setenv("MECHLOOP_LANG", "de")
    assert message_language() == "en"


def test_every_entry_fills_its_template_from_its_own_groups():
    """A template that names a group its pattern lacks would fail when printed."""
    assert len(_COMPILED) == len(ENTRIES)
    for pattern, template in _COMPILED:
        if callable(template):
            continue
        names = {f for _, f, _, _ in string.Formatter().parse(template) if f}
        assert names <= set(pattern.groupindex), (pattern.pattern, template)


def test_user_text_inside_a_message_is_kept_as_written():
    assert translate("unknown key 'colour'") == "неизвестный ключ 'colour'"
    assert translate("cannot read 'lots' as an angle") == "не удаётся прочитать 'lots' как угол"
    assert translate("cannot read '3 kgy' as a force") == \
        "не удаётся прочитать '3 kgy' как силу"
    assert translate("a message no entry knows") == "a message no entry knows"
    assert not has_russian("a message no entry knows; unknown key 'x'")
    assert translate("a message no entry knows; unknown key 'x'") == \
        "a message no entry knows; неизвестный ключ 'x'"


FUZZ_EXAMPLES = [EXAMPLES / "crank_slider.yaml", EXAMPLES / "crank_slider_dynamics.yaml",
                 EXAMPLES / "four_bar_groups.yaml"]


@settings(max_examples=20, derandomize=True, deadline=None, database=None,
          phases=[Phase.generate], suppress_health_check=list(HealthCheck))
@given(data=st.data())
def test_a_fixed_sample_of_mutated_models_keeps_its_places_in_russian(tmp_path_factory, data):
    """Mutated examples (tests/fuzz/mutations.py, a derandomized sample): the Russian
    error names the same places and fixes as the English one, in Russian."""
    example = data.draw(st.sampled_from(FUZZ_EXAMPLES))
    files = data.draw(mutated(example))
    folder = tmp_path_factory.mktemp("fuzz")
    for name, content in files.items():
        (folder / name).write_bytes(content)
    args = ["check", str(folder / "model.yaml")]
    code_en, english = _run(args, None)
    code_ru, russian = _run(args, "ru")
    assert code_en == code_ru
    if code_en != 2:
        return
    assert russian.startswith("ошибка: ") and "fix:" not in russian
    assert _places(russian) == _places(english)
    assert russian.count("как исправить:") == english.count("fix:")
    assert english_left(russian) == [], russian
