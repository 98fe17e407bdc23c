"""The course project's sheets 3 and 4 of every course model: each model of
``examples/course/`` names its own cam document and gear document
(``examples/course/project/NN_cam.yaml``, ``NN_gears.yaml``) in its ``project:`` section;
each design is sound — the pressure angle within its limit over the continuous cam angle
(and at a dense sample, a second route), no undercut or pointed profile, every gear-pair
check met with a contact ratio of at least 1.2 (and the closed-form contact ratio agrees),
the planetary train coaxial, assembling, its planets clear of each other, its ratio by
Willis' formula (recomputed here) on target — and both sheets are built in English and
Russian with every verdict "met" (the figures are not drawn: the report tests draw them).
The documents ship with the package, and ``mechloop new`` copies them with the model.
"""

from __future__ import annotations

import fnmatch
import math
import tomllib
from pathlib import Path

import numpy as np
import pytest
from typer.testing import CliRunner

import mechloop
from mechloop.bundled import examples_dir
from mechloop.bundled.start import project_references
from mechloop.cams.checks import convex_curvature
from mechloop.cli import app
from mechloop.model.project import project_documents
from mechloop.views.cam_sheet import TEXT as CAM_TEXT
from mechloop.views.cam_sheet import cam_sheet
from mechloop.views.gear_sheet import TEXT as GEAR_TEXT
from mechloop.views.gear_sheet import gear_sheet

ROOT = Path(__file__).resolve().parents[1]
COURSE_DIR = ROOT / "examples" / "course"
COURSE = sorted(COURSE_DIR.glob("*.yaml"))
DENSE = 7200  # sample positions over the cam turn (the second route)


def _documents(path: Path):
    return project_documents(mechloop.load_model(path), path)


@pytest.mark.parametrize("path", COURSE, ids=lambda p: p.stem)
def test_each_course_model_names_its_own_project_documents(path: Path):
    number = path.name[:2]
    assert project_references(path) == [f"project/{number}_cam.yaml",
                                        f"project/{number}_gears.yaml"]
    assert path.read_text(encoding="utf-8").splitlines()[-1] == (
        f"project: {{cam: project/{number}_cam.yaml, gears: project/{number}_gears.yaml}}")
    for kind in ("cam", "gears"):
        header = (COURSE_DIR / "project" / f"{number}_{kind}.yaml").read_text(
            encoding="utf-8").splitlines()[0]
        assert header.startswith(f"# Course project, task No. {int(number)}, sheet "
                                 f"{4 if kind == 'cam' else 3}: ")


def _check_cam(design) -> None:
    summary = design.summary()
    follower = design.follower
    cam = design.cam
    g = cam.cycle(DENSE)
    if not follower.flat:
        assert design.allowed is not None
        limits = np.array([design.allowed_return if seg.kind == "return" and
                           design.allowed_return is not None else design.allowed
                           for seg in design.program.segments])
        dense = float(np.max(np.abs(g.pressure) / limits[g.motion.segment]))
        assert summary.pressure_ratio <= 1 + 1e-9, summary.pressure_ratio
        # the continuous maximum is at least the sampled one, and the sample comes close
        assert dense <= summary.pressure_ratio + 1e-12
        assert dense >= summary.pressure_ratio - 2e-3
        # no undercut: the roller fits inside every convex part of the pitch curve
        assert not summary.undercut and summary.rho.value > 0
        assert float(np.max(convex_curvature(g))) * follower.roller_radius < 1
        if design.minimum is not None and math.isclose(cam.base_radius, design.minimum):
            assert summary.pressure_ratio == pytest.approx(1.0, abs=1e-6)  # the smallest
        elif design.minimum is not None:
            assert cam.base_radius > design.minimum
    else:  # convex: the radius of curvature keeps the allowed over the turn
        assert design.min_curvature > 0
        assert not summary.undercut
        assert summary.rho.value >= design.min_curvature * (1 - 1e-9)
        assert float(np.min(g.rho)) >= summary.rho.value - 1e-12
        assert summary.face is not None and summary.face.width > 0


def _contact_ratio(pair) -> float:
    """ε_α in closed form: (√(r_a1² − r_b1²) + √(r_a2² − r_b2²) − a sin α_w)/p_b."""
    r_a, r_b = pair.d_a / 2, pair.d_b / 2
    path = float(np.sum(np.sqrt(r_a**2 - r_b**2))) - pair.a * math.sin(pair.alpha_w)
    return path / (math.pi * pair.m_n * math.cos(pair.alpha_n))


def _check_pair(pair) -> None:
    checks = pair.checks()
    assert {c.name for c in checks} == {"involute flank", "undercut", "pointed tooth",
                                        "interference", "contact ratio"}
    assert all(c.ok for c in checks), [c.text for c in checks if not c.ok]
    assert pair.eps_alpha >= 1.2
    assert _contact_ratio(pair) == pytest.approx(pair.eps_alpha, rel=1e-9)
    assert not pair.undercut.any()


def _check_train(task) -> None:
    train = task.train
    t = train.teeth
    z_a, z_g, z_b = t["a"], t["g"], t["b"]
    z_f = t.get("f", z_g)
    scheme = train.scheme.name
    if scheme == "two_suns":  # both meshes external
        assert z_a + z_g == z_b + z_f
        willis = z_g * z_b / (z_a * z_f)
    else:  # a sun a and a ring b
        assert scheme in ("simple", "double_planet")
        assert z_a + z_g == z_b - z_f
        willis = -z_g * z_b / (z_a * z_f)
        assert z_b - z_f >= 8  # the internal mesh without interference
    assert train.ratio == pytest.approx(1 - willis, rel=1e-12)
    assert train.coaxial and train.assembles
    assert train.assembly == pytest.approx(round(train.assembly), abs=1e-9)
    # neighbours: the planets' tip circles clear each other on the carrier's circle
    a_w = train.m_n * (z_a + z_g) / 2
    tips = train.m_n * (max(z_g, z_f) + 2 * train.ha)
    assert 2 * a_w * math.sin(math.pi / train.k) > tips
    assert train.neighbour_margin > 0
    if task.target is not None:
        assert abs(train.ratio - task.target) <= 0.02 * abs(task.target)


@pytest.mark.parametrize("path", COURSE, ids=lambda p: p.stem)
def test_course_project_designs_are_sound_and_their_sheets_say_so(path: Path):
    docs = _documents(path)
    assert docs.cam is not None and docs.gears is not None
    _check_cam(docs.cam)
    task = docs.gears
    assert task.pair is not None or task.train is not None
    if task.pair is not None:
        _check_pair(task.pair)
    if task.train is not None:
        _check_train(task)
    for lang in ("en", "ru"):
        sheet = cam_sheet(docs.cam, lang)
        text = CAM_TEXT[lang]
        assert sheet.number == 4 and sheet.title == text["title"]
        expected = [text["ok_flat" if docs.cam.follower.flat else "ok_roller"],
                    text["checked"]]
        assert sheet.paragraphs[-2:] == expected
        if not docs.cam.follower.flat:
            assert sheet.paragraphs[0].startswith(text["ok_pressure"].split("(")[0])
        gears = gear_sheet(task, lang)
        words = GEAR_TEXT[lang]
        assert gears.number == 3
        if task.pair is not None:
            assert words["all_met"] in gears.paragraphs
            assert {row[-1] for row in gears.tables[1].rows} == {words["ok"]}
        if task.train is not None:
            verdicts = [p for p in gears.paragraphs if p.endswith(
                f"{words['cond_ok']}.")]
            assert len(verdicts) == 3
        for table in (*sheet.tables, *gears.tables):
            assert all(str(cell).strip() for row in table.rows for cell in row[:1])


def test_project_documents_ship_as_package_data():
    config = tomllib.loads((ROOT / "pyproject.toml").read_text(encoding="utf-8"))
    patterns = config["tool"]["setuptools"]["package-data"]["mechloop"]
    documents = sorted((examples_dir() / "course" / "project").glob("*.yaml"))
    assert len(documents) == 2 * len(COURSE)
    for document in documents:
        relative = "examples_data/" + document.relative_to(examples_dir()).as_posix()
        assert any(fnmatch.fnmatch(relative, p) and p.count("/") == relative.count("/")
                   for p in patterns), relative


def test_new_copies_the_project_documents_so_the_copy_still_reports(tmp_path):
    runner = CliRunner()
    result = runner.invoke(app, ["new", "6", str(tmp_path)])
    assert result.exit_code == 0, result.output
    copy = tmp_path / "06_landing_gear_four_bar.yaml"
    for name in ("06_cam.yaml", "06_gears.yaml"):
        assert (tmp_path / "project" / name).read_bytes() == \
            (COURSE_DIR / "project" / name).read_bytes()
        assert f"project{Path('/')}{name}" in result.output.replace("\n", "")
    docs = _documents(copy)
    original = _documents(COURSE_DIR / copy.name)
    assert docs.cam.cam.base_radius == original.cam.cam.base_radius
    assert docs.gears.train.teeth == original.gears.train.teeth
    # a second copy beside the first shares the (identical) documents
    again = runner.invoke(app, ["new", "6", str(tmp_path / "mine.yaml")])
    assert again.exit_code == 0, again.output
    assert _documents(tmp_path / "mine.yaml").gears.train.teeth == \
        original.gears.train.teeth
    # a document of the same name with other content is never overwritten
    (tmp_path / "project" / "01_cam.yaml").write_text("cam: {}\n", encoding="utf-8")
    refused = runner.invoke(app, ["new", "1", str(tmp_path)])
    assert refused.exit_code == 2 and "does not overwrite" in refused.output
    assert "Traceback" not in refused.output
    assert not (tmp_path / "01_an10_landing_gear.yaml").exists()
    assert not (tmp_path / "project" / "01_gears.yaml").exists()
    assert (tmp_path / "project" / "01_cam.yaml").read_text(encoding="utf-8") == "cam: {}\n"


def test_a_group_files_bad_project_reference_is_located_in_it(tmp_path):
    """Group files (tasks 6 and 9) take ``project:`` as vector models do, errors
    located at its key and line."""
    from mechloop.errors import ModelError

    text = (COURSE_DIR / "06_landing_gear_four_bar.yaml").read_text(encoding="utf-8")
    broken = tmp_path / "gear.yaml"
    broken.write_text(text.replace("project/06_cam.yaml", "project/missing.yaml"),
                      encoding="utf-8")
    (tmp_path / "project").mkdir()
    (tmp_path / "project" / "06_gears.yaml").write_bytes(
        (COURSE_DIR / "project" / "06_gears.yaml").read_bytes())
    model = mechloop.load_model(broken)
    assert model.project.gears == "project/06_gears.yaml"
    with pytest.raises(ModelError) as info:
        project_documents(model, broken)
    problem, = info.value.problems
    assert problem.path == ("project", "cam") and "missing.yaml" in problem.message
    assert problem.line == len(text.splitlines())
