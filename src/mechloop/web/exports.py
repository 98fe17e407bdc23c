"""The files the page downloads, made by the same writers as the CLI, each from the
editor's text (run in a child process, :mod:`mechloop.web.worker`):

* the results table (``mechloop solve -o``): CSV, XLSX or JSON in the model's display
  units (:func:`mechloop.output.tables.write_frame` after
  :func:`mechloop.output.display.apply_display`);
* a plot of up to six parameters (``mechloop plot ... parameters``): PNG or SVG
  (:func:`mechloop.views.curves.plot_parameters`, its texts in English or Russian);
* the report (``mechloop report``): PDF or DOCX (:func:`mechloop.report.write.write_report`);
* the structure (``mechloop structure``): mobility, formula, class, Assur groups, as JSON.
"""

from __future__ import annotations

import tempfile
from collections.abc import Callable, Sequence
from pathlib import Path
from typing import Any

from mechloop.errors import ModelError
from mechloop.web.documents import Document, read_model
from mechloop.web.payload import solve_model
from mechloop.web.safety import WebError

#: Content types of the downloads, by format.
TABLE_TYPES = {"csv": "text/csv; charset=utf-8", "json": "application/json",
               "xlsx": "application/vnd.openxmlformats-officedocument.spreadsheetml.sheet"}
FIGURE_TYPES = {"png": "image/png", "svg": "image/svg+xml"}
REPORT_TYPES = {"pdf": "application/pdf",
                "docx": "application/vnd.openxmlformats-officedocument."
                        "wordprocessingml.document"}
#: The most curves on one plot (as :func:`mechloop.views.curves.plot_parameters`).
MAX_CURVES = 6


def pick(kind: str, value: Any, types: dict[str, str]) -> str:
    """``value`` checked as one of the formats of ``types`` (a :class:`WebError`
    naming them otherwise)."""
    if value not in types:
        raise WebError(f"no {kind} format {value!r}", f"use one of {', '.join(types)}")
    return str(value)


def language(value: Any) -> str:
    """``value`` checked as a language of the reports and figures."""
    if value not in ("en", "ru"):
        raise WebError(f"no language {value!r}", "use 'en' or 'ru'")
    return str(value)


def curve_names(value: Any) -> list[str]:
    """The parameters asked for one plot: 1 to :data:`MAX_CURVES` names."""
    if (not isinstance(value, list) or not value
            or not all(isinstance(n, str) and n for n in value)):
        raise WebError("'names' is not a list of parameter names",
                       'send e.g. {"names": ["r3", "dr3"]}')
    if len(value) > MAX_CURVES:
        raise WebError(f"{len(value)} curves asked for one plot; at most {MAX_CURVES} fit",
                       "choose fewer parameters")
    return list(value)


def _in_file(document: Document, suffix: str, write: Callable[[Path], Any]) -> bytes:
    """The bytes ``write(path)`` puts in a temporary file of ``suffix``; a model error
    it raises is located by line in the text."""
    with tempfile.TemporaryDirectory(prefix="mechloop-web-") as folder:
        target = Path(folder) / f"download{suffix}"
        try:
            write(target)
        except ModelError as exc:
            raise document.locate(exc) from None
        return target.read_bytes()


def table_file(text: str, path: Path, root: Path, fmt: str) -> bytes:
    """The results table of the model in ``text`` as a ``fmt`` file (csv, xlsx, json),
    in its display units, as ``mechloop solve -o`` writes it."""
    from mechloop.output.display import apply_display, resolve
    from mechloop.output.tables import check_table_size, write_frame

    document = read_model(text, path, root)

    def write(target: Path) -> None:
        frame = solve_model(document.model).to_frame()
        check_table_size(len(frame), len(frame.columns), target)
        write_frame(apply_display(frame, resolve(document.model.display), target.suffix),
                    target)

    return _in_file(document, f".{fmt}", write)


def figure_file(text: str, path: Path, root: Path, names: Sequence[str], fmt: str,
                lang: str) -> bytes:
    """The plot of the parameters ``names`` over the positions (one y-axis per unit) as a
    ``fmt`` image (png, svg), as ``mechloop plot MODEL parameters -n ...`` draws it."""
    from mechloop.output.display import plot_display, resolve
    from mechloop.views.curves import plot_parameters
    from mechloop.views.display import DEFAULT_DISPLAY
    from mechloop.views.figure import save_figure
    from mechloop.views.russian import translate

    document = read_model(text, path, root)
    display = plot_display(resolve(document.model.display)) or DEFAULT_DISPLAY

    def write(target: Path) -> None:
        figure = plot_parameters(solve_model(document.model), list(names), display=display)
        save_figure(translate(figure, lang), target)

    return _in_file(document, f".{fmt}", write)


def report_file(text: str, path: Path, root: Path, lang: str, fmt: str = "pdf") -> bytes:
    """The report of the model in ``text`` as a ``fmt`` file (pdf, docx), with the course
    project's gear and cam sheets when its ``project:`` section names them."""
    from mechloop.model.project import project_documents
    from mechloop.report.write import write_report

    document = read_model(text, path, root)  # its project: files lie inside root

    def write(target: Path) -> None:
        project = project_documents(document.model, path)
        write_report(document.model, target, lang=lang, project=project)

    return _in_file(document, f".{fmt}", write)


def structure(text: str, path: Path, root: Path, lang: str = "en") -> dict[str, Any]:
    """The structure of the model in ``text`` in ``lang`` (see :func:`structure_of`)."""
    return structure_of(read_model(text, path, root), lang)


def structures(document: Document, results: Any) -> dict[str, dict[str, Any]]:
    """The structure of a solved model in English and Russian, ``{"en": ..., "ru": ...}``
    (the page shows it in its language, and a change of language asks nothing), from its
    kinematic ``results`` (nothing solved again); a problem of the structure is
    ``{"error", "hint"}`` in each language (the solution itself stays good)."""
    from mechloop.errors import MechloopError
    from mechloop.structure.analysis import analyze
    from mechloop.web.documents import problems
    from mechloop.web.language import problems_in

    try:
        spatial = any(c.spatial for c in document.model.contours)
        analyzed = analyze(document.model, results) if document.model.bodies and not \
            spatial else None
        return {lang: structure_of(document, lang, analyzed=analyzed) for lang in ("en", "ru")}
    except MechloopError as exc:
        located = document.locate(exc) if isinstance(exc, ModelError) else exc
        said = {lang: problems_in(problems(located), lang)[0] for lang in ("en", "ru")}
        return {lang: {"error": item["message"], "hint": item["hint"]}
                for lang, item in said.items()}


def structure_of(document: Document, lang: str = "en",
                 analyzed: tuple[Any, Any] | None = None) -> dict[str, Any]:
    """The structure of the model in ``text`` as ``mechloop structure`` prints it:
    Chebyshev's count (``n``, ``p5``, ``p4``, ``W``, ``inputs``, ``ok``, ``explanation``),
    the ``formula``, the ``class`` of the mechanism (Roman, None when not determined),
    the ``groups`` (label, kind, class, links, pair letters, external and internal pairs,
    assembly variant, contour), the ``notes``, and the contour-by-contour ``description``
    of the vector model (:func:`mechloop.model.formula.describe_structure`).  A model
    without bodies has only the description (``mechanism`` None); a model with spatial
    contours the printed Somov–Malyshev structure as its description (``spatial`` true),
    without bodies too when its vectors define its links.  The texts (explanation,
    notes, class, description) are in ``lang`` ('en' or 'ru').  ``analyzed``: the
    model's :func:`~mechloop.structure.analysis.analyze` when already made."""
    from mechloop.model.formula import describe_structure
    from mechloop.structure.analysis import analyze
    from mechloop.structure.text import class_text, explanation, note_text

    model = document.model
    try:
        description = describe_structure(model, lang)
        if any(c.spatial for c in model.contours):  # issue 17: Somov–Malyshev as text
            from mechloop.structure.spatial import spatial_structure
            from mechloop.structure.spatial_text import spatial_structure_lines

            try:  # without bodies: the links from the vectors, when they define them
                lines = spatial_structure_lines(spatial_structure(model), model, lang)
            except ModelError:
                if model.bodies:
                    raise
                return {"mechanism": None, "description": description}
            return {"mechanism": None, "spatial": True, "description": "\n".join(lines)}
        if not model.bodies:
            return {"mechanism": None, "description": description}
        mob, dec = analyze(model) if analyzed is None else analyzed
    except ModelError as exc:
        raise document.locate(exc) from None
    cls = dec.mechanism_class

    def pairs(items: Sequence[Any]) -> list[dict[str, Any]]:
        return [{"name": p.name, "kind": p.kind, "link": p.link, "to": p.to}
                for p in items]

    groups = [{"label": g.label, "kind": g.kind, "class": g.assur_class,
               "links": list(g.links), "pairs": g.pairs,
               "external": pairs(g.external), "internal": pairs(g.internal),
               "variant": g.variant, "contour": g.contour} for g in dec.groups]
    return {"mechanism": {"n": mob.n, "p5": mob.p5, "p4": mob.p4, "W": mob.W,
                          "inputs": mob.inputs, "ok": mob.ok,
                          "explanation": explanation(mob, lang),
                          "formula": dec.formula,
                          "class": None if cls is None else class_text(dec, lang),
                          "groups": groups,
                          "notes": [note_text(note, lang) for note in dec.notes]},
            "description": description}
