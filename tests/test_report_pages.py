"""Every page of the English and the Russian report of every bundled dynamics example and
of every course model (with its cam and gear sheets), typeset (issues 14 and 15): A4
portrait pages, every character inside the text area, the section headings in the
document's order, no table column without a value, no English word in the Russian report
(the figures' texts included: they are text in the PDF) and no Russian word in the English
one but the user's own names."""

from __future__ import annotations

import re
from pathlib import Path

import pypdfium2
import pytest
from helpers.latin import latin_words, model_names
from helpers.pdf_pages import A4, check_text_area, normal, page_texts

import mechloop
from mechloop.model.project import project_documents
from mechloop.report.content import build_document
from mechloop.report.document import (
    Section,
    Table,
    heading,
    numbered,
    texts,
    walk,
)
from mechloop.report.write import write_document

ROOT = Path(__file__).resolve().parents[1]


def _dynamic(path: Path) -> bool:
    try:
        return bool(mechloop.load_model(path).bodies)
    except mechloop.MechloopError:  # group files and other documents
        return False


DYNAMIC = [p for p in sorted((ROOT / "examples").glob("*.yaml")) if _dynamic(p)]
COURSE = sorted((ROOT / "examples" / "course").glob("[0-9][0-9]_*.yaml"))
#: One model with spatial contours, bodies and joints (issue 17: 3-D schemes, virtual
#: power, the joint reactions with their 3-D hodographs).
SPATIAL = [ROOT / "examples" / "spatial" / "rssr_reactions.yaml"]
#: A number with a decimal point (not a dotted run: a date, a section number, a name).
DECIMAL_POINT = re.compile(r"(?<![\w.])\d+\.\d+(?![\w.])")
CASES = [pytest.param(p, lang, id=f"{p.parent.name}/{p.stem}-{lang}")
         for p in [*DYNAMIC, *COURSE, *SPATIAL] for lang in ("en", "ru")]


def test_the_cases_cover_the_bundled_dynamics_examples_and_the_course():
    assert len(DYNAMIC) >= 10 and len(COURSE) == 20


@pytest.mark.parametrize(("path", "lang"), CASES)
def test_every_page_of_the_report(path, lang, tmp_path):
    model = mechloop.load_model(path)
    project = project_documents(model, path)
    document = build_document(model, lang=lang, project=project)
    pdf = write_document(document, tmp_path / "report.pdf")
    reader = pypdfium2.PdfDocument(pdf)
    sizes = [page.get_size() for page in reader]
    reader.close()
    assert all(size == pytest.approx(A4, abs=0.5) for size in sizes)
    check_text_area(pdf)
    pages = page_texts(pdf)
    body = normal(" ".join(pages[2:]))  # after the title page and the contents
    at = 0
    for item in numbered(document):
        if isinstance(item.block, Section):
            at = body.find(normal(heading(document, item)), at)
            assert at >= 0, heading(document, item)
    for block in walk([*document.sections, *document.appendices]):
        if isinstance(block, Table):
            for k, name in enumerate(block.header):
                assert any(row[k].strip() for row in block.rows), (block.caption, name)
    _check_language(" ".join(pages), lang, _names(model, project))
    if lang == "ru":  # the decimal comma (GOST 2.105) in every text but the user's names
        names = [n for n in _names(model, project) if n]
        spoken = [re.sub("|".join(map(re.escape, names)), "", t) for t in texts(document)]
        points = [t for t in spoken if DECIMAL_POINT.search(t)]
        assert not points, points[:3]


def _names(model, project) -> list[str]:
    return [*model_names(model), getattr(project.cam, "name", ""),
            getattr(project.gears, "pair_name", ""), getattr(project.gears, "train_name", "")]


def _check_language(text: str, lang: str, names: list[str]) -> None:
    if lang == "ru":
        assert latin_words(text, names) == []
    else:
        allowed = {w for n in names for w in re.findall(r"[А-Яа-яЁё]+", n)}
        assert {w for w in re.findall(r"[А-Яа-яЁё]+", text)} <= allowed
