"""The course-project models of ``examples/course/`` (seed 000 sec. 3), their catalogue
(``mechloop examples``) and ``mechloop new``.

Every course model, whoever adds it: named ``NN_stem.yaml`` with a unique task number, an
English ``name`` and the seed's Russian title as ``description``; it loads, its chain never
breaks over its working range — at the positions and between them, decided by the exact
existence check of ``mechloop solve`` — its force analysis is finite and regular at every
position, the works of its loads add up to the change of its kinetic energy, the balancing
load by kinetostatics equals the one by virtual power (an independent route: the analogs
and the loads' power, no reactions), and its mobility by Chebyshev equals its number of
inputs; each header's stated range of motion is what the solve gives.  One course model's
report is rendered in both languages (the report is slow: the others are rendered by hand).
"""

from __future__ import annotations

import fnmatch
import re
import time
import tomllib
import warnings
from pathlib import Path

import numpy as np
import pypdf
import pytest
import yaml
from typer.testing import CliRunner

import mechloop
from mechloop import cli
from mechloop.bundled import examples, examples_dir, find_example
from mechloop.cli import app
from mechloop.errors import HintedError
from mechloop.report.words import TEXT
from mechloop.structure.analysis import analyze
from mechloop.views.report import write_report

ROOT = Path(__file__).resolve().parents[1]
COURSE_DIR = ROOT / "examples" / "course"
COURSE = sorted(COURSE_DIR.glob("*.yaml"))
CYRILLIC = re.compile(r"[А-Яа-яЁё]")


def _id(path: Path) -> str:
    return path.stem


class _Course:
    """The course models of this module, each loaded, solved and analysed at most once
    (read only: the tests share them)."""

    def __init__(self) -> None:
        self._models: dict[Path, mechloop.Model] = {}
        self._solved: dict[Path, mechloop.Results] = {}
        self._dynamics: dict[Path, mechloop.DynamicResults] = {}

    def model(self, path: Path) -> mechloop.Model:
        if path not in self._models:
            self._models[path] = mechloop.load_model(path)
        return self._models[path]

    def solved(self, path: Path) -> mechloop.Results:
        if path not in self._solved:
            self._solved[path] = mechloop.solve(self.model(path))
        return self._solved[path]

    def dynamics(self, path: Path) -> mechloop.DynamicResults:
        if path not in self._dynamics:
            self._dynamics[path] = mechloop.solve_dynamics(self.model(path))
        return self._dynamics[path]


@pytest.fixture(scope="module")
def course() -> _Course:
    return _Course()


def test_course_files_are_numbered_and_titled_in_both_languages():
    numbers = []
    for path in COURSE:
        match = re.match(r"^(\d\d)_[a-z0-9_]+\.yaml$", path.name)
        assert match, f"{path.name}: name it NN_stem.yaml (NN: the task number)"
        numbers.append(int(match.group(1)))
        model = mechloop.load_model(path)
        assert model.name and not CYRILLIC.search(model.name), f"{path.name}: English name"
        assert CYRILLIC.search(model.description), f"{path.name}: the Russian title in " \
            "description:"
        header = path.read_text(encoding="utf-8").split("\nname:")[0]
        assert f"task No. {int(match.group(1))} " in header, f"{path.name}: header"
    assert len(numbers) == len(set(numbers)) and all(1 <= n <= 20 for n in numbers)
    assert len(COURSE) >= 10


@pytest.mark.parametrize("path", COURSE, ids=_id)
def test_course_model_never_breaks_over_its_working_range(course: _Course, path: Path):
    model = course.model(path)
    results = course.solved(path)  # the first solve of a process also compiles kernels
    assert not results.broken.any(), [b.describe() for b in results.breaks]
    assert results.breaks_between == (), [g.describe() for g in results.breaks_between]
    started = time.perf_counter()
    mechloop.solve(model)
    elapsed = time.perf_counter() - started
    assert elapsed < 2.0, f"solve took {elapsed:.1f} s (keep a course model fast)"
    for name, values in results.values.items():
        assert np.all(np.isfinite(values)), name


@pytest.mark.parametrize("path", COURSE, ids=_id)
def test_course_model_dynamics_finite_and_balanced_by_virtual_power(course: _Course,
                                                                     path: Path):
    model = course.model(path)
    assert model.bodies and model.time is not None, "masses and a time: kinetostatics"
    dyn = course.dynamics(path)
    frame = dyn.to_frame()
    assert not dyn.forces.singular.any() and not frame["chain_break"].any()
    numeric = frame.drop(columns=["chain_break"]).to_numpy(float)
    assert np.isfinite(numeric).all()
    reactions = [c for c in frame.columns  # the magnitudes |R| of every pair's reaction
                 if re.fullmatch(r"R.+ \[N\]", c) and not re.search(r"_[xyntr] \[N\]$", c)]
    assert reactions and all(frame[c].abs().max() > 0 for c in reactions)
    for kinetostatic in [c for c in frame.columns if re.match(r"[FM]_bal\d* ", c)]:
        virtual = kinetostatic.replace("_bal", "_bal_vp", 1).replace("_vp ", "_vp ", 1)
        a, b = frame[kinetostatic].to_numpy(), frame[virtual].to_numpy()
        assert np.abs(a - b).max() <= 1e-7 * max(np.abs(b).max(), 1.0), kinetostatic
    # the works of the loads over the range add up to the change of the kinetic energy.
    # The works are quadratures of the powers over the positions, the change is exact: 06
    # (40 positions) is off by 1.4e-4 of its largest work, 80 positions 4e-9, 160 2e-11;
    # the others by at most 1e-6.  A load left out or of the wrong sign is far above 1e-3.
    s = dyn.summary
    residual = sum(r.positive_work + r.negative_work for r in s.rows) - s.kinetic_energy_change
    largest = max(r.positive_work - r.negative_work for r in s.rows)
    assert abs(residual) < 1e-3 * largest


@pytest.mark.parametrize("path", COURSE, ids=_id)
def test_course_model_mobility_equals_its_inputs(course: _Course, path: Path):
    model = course.model(path)
    mob, dec = analyze(model)
    assert mob.W == 3 * mob.n - 2 * mob.p5 - mob.p4
    assert mob.W == mob.inputs == len(model.arguments) >= 1, mob.describe() \
        if hasattr(mob, "describe") else mob
    assert dec.formula.startswith("L0(")


@pytest.fixture(scope="module", params=["en", "ru"])
def course_report(request, tmp_path_factory) -> tuple[str, Path]:
    path = tmp_path_factory.mktemp("course") / f"report_{request.param}.pdf"
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        write_report(mechloop.load_model(COURSE_DIR / "01_an10_landing_gear.yaml"), path,
                     lang=request.param)
    return request.param, path


def test_course_report_renders_every_section_in_both_languages(course_report):
    lang, path = course_report
    text = "\n".join(page.extract_text() for page in pypdf.PdfReader(path).pages)
    text = " ".join(text.split())
    for key in ("s_parameters", "s_formula", "s_increment", "s_angles", "s_dependence",
                "s_masses", "s_reduced", "s_reactions", "s_centres", "s_conclusion",
                "s_appendix"):
        assert TEXT[lang][key].split("{")[0].strip() in text, (lang, key)
    assert "An-10 aircraft landing gear" in text and "Шасси самолета Ан-10" in text


# ------------------------------------------------------------------ catalogue and `new`
def test_catalogue_lists_every_course_model_and_every_example():
    listed = examples()
    course = [e for e in listed if e.course]
    assert [e.path.name for e in course] == [p.name for p in COURSE]
    assert [e.number for e in course] == sorted(e.number for e in course)
    others = {e.path.name for e in listed if not e.course}
    assert others == {p.name for p in (ROOT / "examples").glob("*.yaml")} | {
        p.name for p in (ROOT / "examples").glob("*.py")}
    assert all(e.title for e in listed)
    assert examples(course_only=True) == course


def test_examples_command_prints_numbers_and_both_titles(monkeypatch):
    # the console's width is fixed when it was made if COLUMNS was set then (by another
    # test in the same process): set it for this test
    monkeypatch.setattr(cli.out, "width", 250)
    result = CliRunner().invoke(app, ["examples", "--course"], env={"COLUMNS": "250"})
    assert result.exit_code == 0, result.output
    for e in examples(course_only=True):
        row = next(line for line in result.output.splitlines()
                   if re.match(rf"\W*{e.number}\W", line))
        assert e.path.name in row and e.title in row and e.title_ru in row
    assert "crank_slider.yaml" not in result.output
    full = CliRunner().invoke(app, ["examples"], env={"COLUMNS": "250"})
    assert "crank_slider.yaml" in full.output and "Offset slider-crank" in full.output


def test_readme_table_names_every_course_model_with_its_title():
    readme = (ROOT / "docs" / "examples.md").read_text(encoding="utf-8")
    section = readme.split("\n## Course project\n")[1].split("\n## ")[0]
    rows = re.findall(r"^\| (\d+) \| (.+?) \| `([^`]+)` \| .+ \|$", section, flags=re.M)
    course = examples(course_only=True)
    assert [(int(n), f) for n, _, f in rows] == [(e.number, e.path.name) for e in course]
    for (_, title, _), e in zip(rows, course, strict=True):
        assert title.startswith(e.title_ru.split(" (")[0]), (title, e.title_ru)


@pytest.mark.parametrize("name", ["1", "01", "01_an10_landing_gear",
                                  "01_an10_landing_gear.yaml", "01_an10"])
def test_new_finds_by_number_stem_file_or_prefix(name):
    assert find_example(name).path.name == "01_an10_landing_gear.yaml"


def test_new_copies_and_never_overwrites(tmp_path):
    runner = CliRunner()
    result = runner.invoke(app, ["new", "1", str(tmp_path)])
    assert result.exit_code == 0, result.output
    copy = tmp_path / "01_an10_landing_gear.yaml"
    assert copy.read_bytes() == (COURSE_DIR / copy.name).read_bytes()
    assert mechloop.load_model(copy).name == "An-10 aircraft landing gear"
    again = runner.invoke(app, ["new", "1", str(tmp_path)])
    assert again.exit_code == 2 and "does not overwrite" in again.output
    assert "Traceback" not in again.output
    named = runner.invoke(app, ["new", "crank_slider", str(tmp_path / "mine.yaml")])
    assert named.exit_code == 0 and (tmp_path / "mine.yaml").read_text(
        encoding="utf-8") == (ROOT / "examples/crank_slider.yaml").read_text(encoding="utf-8")


@pytest.mark.parametrize(("args", "message", "fix"), [
    (["new", "99"], "no bundled example is called '99'", "mechloop examples"),
    (["new", "four_bar_"], "matches", "give more of the name"),
    (["new", "1", "missing/dir/x.yaml"], "does not exist", "create it first"),
    (["new", "1", "x.txt"], "does not end in .yaml", "name the copy"),
])
def test_new_errors_are_located_with_the_fix(tmp_path, monkeypatch, args, message, fix):
    monkeypatch.chdir(tmp_path)
    result = CliRunner().invoke(app, args)
    assert result.exit_code == 2 and message in result.output and fix in result.output
    assert "Traceback" not in result.output and not list(tmp_path.iterdir())


def test_ambiguous_prefix_names_the_candidates():
    with pytest.raises(HintedError) as info:
        find_example("six_points")
    assert "six_points_line_synthesis" in str(info.value)


def test_examples_ship_as_package_data():
    """The installed package holds the examples: ``mechloop/examples_data`` links to
    ``examples/`` and pyproject's package data covers every example file (a wheel built
    from this tree carries them; checked by hand with ``pip wheel``)."""
    assert examples_dir().resolve() == (ROOT / "examples").resolve()
    link = ROOT / "src/mechloop/examples_data"
    assert link.is_symlink() and link.resolve() == (ROOT / "examples").resolve()
    config = tomllib.loads((ROOT / "pyproject.toml").read_text(encoding="utf-8"))
    patterns = config["tool"]["setuptools"]["package-data"]["mechloop"]
    for e in examples():
        relative = "examples_data/" + e.path.relative_to(examples_dir()).as_posix()
        assert any(fnmatch.fnmatch(relative, p) and p.count("/") == relative.count("/")
                   for p in patterns), relative


# ------------------------------------------------------- the headers' claims, by the solve
def _deg(results, name: str) -> np.ndarray:
    return np.degrees(results.value(name))


def _group_points(name: str, *points: str) -> list[tuple[np.ndarray, np.ndarray]]:
    from mechloop.model.groups import build, mechanism_of

    built = build(mechanism_of(COURSE_DIR / name))
    results = mechloop.solve(built.model)
    return [built.points[p].xy(results) for p in points]


def _wrap(angle_deg: np.ndarray) -> np.ndarray:
    return (np.asarray(angle_deg) + 180.0) % 360.0 - 180.0


def test_course_headers_state_what_the_models_do(course: _Course):
    """Each header's range of motion (the leg "from hanging down to 5 deg below
    horizontal", the mast "from vertical to 25 deg", ...) is what the solve gives."""
    def solved(name):
        return course.solved(COURSE_DIR / name)

    leg = _wrap(_deg(solved("01_an10_landing_gear.yaml"), "a8"))  # forward: towards -180
    assert abs(leg[0] + 90) < 3 and abs(leg[-1] + 180) < 12
    leg = _wrap(_deg(solved("02_landing_gear.yaml"), "a8"))       # aft: towards 0
    assert abs(leg[0] + 90) < 3 and round(leg[-1]) == -5
    leg = _wrap(_deg(solved("03_tu154_landing_gear.yaml"), "a8"))
    assert abs(leg[0] + 90) < 3 and round(leg[-1]) == -9
    leg = _wrap(_deg(solved("04_an10_landing_gear_b.yaml"), "a8"))
    assert abs(leg[0] + 90) < 3 and abs(leg[-1] + 180) < 12
    leg = _wrap(_deg(solved("07_landing_gear_jack_on_brace.yaml"), "a9"))
    assert abs(leg[0] + 90) < 3 and abs(leg[-1] + 180) < 12
    door = solved("08_nose_gear_door.yaml")
    leg, panel = _wrap(_deg(door, "a11")), _wrap(_deg(door, "a9"))
    assert abs(leg[-1] + 180) < 12 and abs(panel[0] + 90) < 3 and abs(panel[-1] + 180) < 12
    assert abs(_wrap(panel - leg)).max() < 3  # nearly a parallelogram: turns with the leg
    mast = _deg(solved("10_cable_mast.yaml"), "a8") % 360
    assert abs(mast[0] - 90) < 0.1 and round(mast[-1] - 90) == 25
    lever = _deg(solved("10_cable_mast.yaml"), "a1")
    assert round(np.ptp(lever) / np.ptp(mast)) == 3  # "about three times as far"
    boom = _wrap(_deg(solved("11_erector.yaml"), "a4"))
    assert abs(boom[0]) < 0.2 and abs(boom[-1] - 90) < 0.2
    (_, wy), = _group_points("06_landing_gear_four_bar.yaml", "W")
    assert wy[-1] - wy[0] > 1.0  # m: "rises by more than a metre"
    (ox, oy), (kx, ky) = _group_points("09_lunar_lander_gear.yaml", "O", "K")
    off_body = 90 + np.degrees(np.arctan2(ky - oy, kx - ox))  # from the body's -Y
    assert round(off_body[0]) == 2 and round(off_body[-1]) == 35


def test_course_headers_12_to_20_state_what_they_do(course: _Course):
    """The same for tasks 12-20: the strokes, dead centres and swings the headers state."""
    def solved(name):
        return course.solved(COURSE_DIR / name)

    def deg(res: mechloop.Results, name: str) -> np.ndarray:
        return np.degrees(res.value(name))

    # 12: the articulated piston's dead centres fall a little off those of a central
    # slider-crank at 60 deg (60 and 240 deg of the crank): found on a dense copy
    data = yaml.safe_load((COURSE_DIR / "12_v_engine_articulated.yaml").read_text(
        encoding="utf-8"))
    for key in ("bodies", "forces", "gravity", "machine"):
        data.pop(key)
    data["positions"], data["arguments"][1] = 7200, {"table": {0: 0, 7200: 720}}
    dense = mechloop.solve(mechloop.Model.from_dict(data))
    s, crank = dense.value("r7"), np.degrees(dense.arguments[1])
    top, bottom = crank[np.argmax(s)], crank[np.argmin(s)]
    assert 60.5 < top < 63 and 235 < bottom < 239.5
    assert np.ptp(dense.value("r3")) * 1e3 == pytest.approx(170, abs=1e-9)
    # 14: the flap turns from 25 deg inwards to about in line with the axis
    door = deg(solved("14_nozzle_ring.yaml"), "a6") - 360
    assert door[0] == pytest.approx(-25, abs=0.05) and -1 < door[-1] < 0
    # 15: the primary flap from 30 to 12 deg inwards, the divergent one out from 5 to 9 deg
    res = solved("15_nozzle_flaps.yaml")
    primary, divergent = deg(res, "a5") - 360, deg(res, "a6")
    assert primary[[0, -1]] == pytest.approx([-30, -12], abs=0.05)
    assert np.round(divergent[[0, -1]]).tolist() == [5, 9]
    # 19: the ram moves down (r7 grows) over more of the crank's turn than up: quick return
    rate = solved("19_gear_shaper.yaml").rate("r7")
    assert (rate > 0).sum() > (rate < 0).sum() + 4
    # 20: the doors open from flat to 119 deg, mirror images of each other
    res = solved("20_solar_panel_doors.yaml")
    left, right = deg(res, "a9"), 180 - (deg(res, "a11") % 360)
    assert round(left[0]) == 0 and round(left[-1]) == 119 and np.all(np.diff(left) > 0)
    assert np.allclose(left, right, atol=1e-9)
