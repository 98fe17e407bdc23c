"""The content of the course-project report as a :class:`~mechloop.report.document.Document`
(seed 000 sec. 2.1 item 9), apart from any typesetter.

Sections in the seed's order: 1 model parameters (tables and the vector scheme in an
intermediate position), 2 calculation formula, 3 increment of the output parameter and
its 1st and 2nd derivatives, 4 angle differences of the links, 5 dependence of the driven
link on the driving one; for a model with bodies 6 mass characteristics, forces and
moments, 7 reduced loads and inertia (reduced characteristics, balancing load, summary,
machine motion), 8 reactions in the kinematic pairs (with a hodograph per joint), 9
centres of mass; then the course project's gear and cam sheets when given, the
conclusion, and an appendix with the values at every position.  Every number is in the
model's display units and precision (its ``display:`` section); every text in the
report's language.  A model with spatial contours gets the same document with its 3-D
parts (:mod:`mechloop.report.spatial`).
"""

from __future__ import annotations

import itertools
from collections.abc import Callable

import numpy as np

from mechloop.dynamics.analysis import DynamicResults, solve_dynamics
from mechloop.dynamics.cycle_validity import cycle_breaks
from mechloop.errors import HintedError
from mechloop.model.project import ProjectDocuments
from mechloop.model.report_info import ReportInfo
from mechloop.model.schema import Model
from mechloop.output.display import TableDisplay, plot_display, resolve
from mechloop.report.appendix import appendix_tables
from mechloop.report.breaks import break_lines
from mechloop.report.conclusion import conclusion_blocks
from mechloop.report.document import Document, FigureItem, Paragraph, Section, Table
from mechloop.report.dynamic_parameters import masses_section
from mechloop.report.formula import formula_section
from mechloop.report.numbers import Shown
from mechloop.report.parameters import parameters_section
from mechloop.report.sheets import project_sheets, sheet_section
from mechloop.report.summary import summary_tables
from mechloop.report.title import title_info, title_page
from mechloop.report.values import symbol
from mechloop.report.words import words
from mechloop.solve.kinematics import solve
from mechloop.solve.results import Results, compress_positions
from mechloop.views.display import DEFAULT_DISPLAY, Display
from mechloop.views.russian import translate

#: Angle-difference figures at most (section 4).
MAX_ANGLE_FIGURES = 6


def output_parameter(results: Results) -> str:
    """The parameter of the output link used by the report: in the first contour solved,
    a function length (a slider) if there is one, else its last function angle (the
    rocker of a four-bar)."""
    first = results.structure.ordered()[0]
    lengths = [f for f in first.functions if f[0] == "r"]
    return lengths[0] if lengths else first.functions[-1]


def intermediate(results: Results) -> int:
    """A position near the first third of the cycle where the chain does not break."""
    good = np.flatnonzero(~results.broken)
    if not good.size:
        return 0
    middle = results.broken.size // 3
    return int(good[np.argmin(np.abs(good - middle))])


def check_position(results: Results, position: int | None, w: dict[str, str]) -> int:
    """The scheme's position: ``position`` when it is a calculation position where the
    chain assembles, else a HintedError naming the unbroken positions; None: the
    :func:`intermediate` one."""
    if position is None:
        return intermediate(results)
    good = compress_positions(np.flatnonzero(~results.broken))
    count = results.broken.size
    hint = w["e_position_hint"].format(good=good) if good else w["e_all_broken"]
    if not isinstance(position, int | np.integer) or not 0 <= position < count:
        raise HintedError(w["e_position_range"].format(position=position, last=count - 1),
                          hint)
    if results.broken[position]:
        raise HintedError(w["e_position_broken"].format(position=position), hint)
    return int(position)


def angle_pairs(results: Results) -> list[tuple[int, int]]:
    """Adjacent vectors in each contour whose angle difference varies (link angles,
    transmission and pressure angles)."""
    pairs = []
    for contour in results.model.contours:
        for a, b in itertools.pairwise(contour.vectors):
            if f"a{a}" in results.constant and f"a{b}" in results.constant:
                continue
            diff = results.value(f"a{b}") - results.value(f"a{a}")
            finite = diff[np.isfinite(diff)]
            if finite.size and np.ptp(finite) > 1e-9:
                pairs.append((a, b))
    return pairs


def compact(blocks: list) -> list:
    """``blocks`` with every table's empty columns left out (a name column where no
    vector or contour is named), in the subsections too."""
    out = []
    for block in blocks:
        if isinstance(block, Section):
            block = Section(block.title, compact(block.blocks))
        elif isinstance(block, Table) and block.rows:
            keep = [k for k in range(len(block.header))
                    if any(row[k] for row in block.rows)]
            if len(keep) < len(block.header):
                block = Table(block.caption, tuple(block.header[k] for k in keep),
                              [tuple(row[k] for k in keep) for row in block.rows],
                              block.values)
        out.append(block)
    return out


def _figure(caption: str, draw: Callable, lang: str) -> FigureItem:
    return FigureItem(caption, lambda: translate(draw(), lang))


def increment_section(results: Results, source, name: str, display: Display, lang: str,
                      w: dict[str, str]) -> Section:
    """Section 3: the increment of the output parameter from the first position where
    the chain assembles, and its 1st and 2nd derivatives."""
    from mechloop.views import curves

    good = np.flatnonzero(~results.broken)
    reference = int(good[0]) if good.size else 0
    return Section(w["s_increment"].format(name=symbol(name)), [_figure(
        w["f_increment"].format(name=symbol(name), position=reference),
        lambda: curves.plot_increment(source, name, reference, display=display), lang)])


def dependence_section(results: Results, source, name: str, display: Display, lang: str,
                       w: dict[str, str]) -> Section:
    """Section 5: the output parameter and its 1st derivative against argument 1."""
    from mechloop.views import curves

    against = f"arg{min(results.arguments)}" if results.arguments else "position"
    shown_against = w["h_position"]
    if against.startswith("arg"):  # φ1 of an angle, s1 of a length (a cylinder)
        k = int(against[3:])
        shown_against = f"{'s' if results.argument_kinds[k] == 'length' else 'φ'}{k}"
    return Section(w["s_dependence"], [_figure(
        w["f_dependence"].format(names=f"{symbol(name)}, d{symbol(name)}",
                                 against=shown_against),
        lambda: curves.plot_parameters(source, [name, f"d{name}"], against=against,
                                       display=display), lang)])


def _kinematic_sections(results: Results, source, name: str, display: Display,
                        lang: str, w: dict[str, str]) -> list[Section]:
    """Sections 3, 4 and 5: the output parameter, the angle differences, the
    dependence of the driven link on the driving one."""
    from mechloop.views import curves

    angles = Section(w["s_angles"], [
        _figure(w["f_angle"].format(a=a, b=b),
                lambda a=a, b=b: curves.plot_angle_between(source, a, b, display=display),
                lang)
        for a, b in angle_pairs(results)[:MAX_ANGLE_FIGURES]])
    if not angles.blocks:
        angles.blocks.append(Paragraph(w["no_angles"]))
    return [increment_section(results, source, name, display, lang, w), angles,
            dependence_section(results, source, name, display, lang, w)]


def _dynamic_sections(dyn: DynamicResults, model: Model, results: Results, position: int,
                      shown: Shown, display: Display, length_unit: str | None,
                      w: dict[str, str]) -> list[Section]:
    """Sections 6 to 9: masses and loads, reduced loads, reactions, centres of mass."""
    from mechloop.views import dynamics, plan

    lang = shown.lang
    sections = [masses_section(dyn, model, shown, w)]
    reduced = []
    if dyn.reduced is not None:
        reduced.append(Section(w["s_reduced_sub"], [_figure(
            w["f_reduced"], lambda: dynamics.plot_reduced(dyn, display=display), lang)]))
    reduced.append(Section(w["s_balancing"], [_figure(
        w["f_balancing"], lambda: dynamics.plot_balancing(dyn, display=display), lang)]))
    summary: list = []
    broken = cycle_breaks(dyn)
    if broken is not None:
        summary.append(Paragraph(w["cycle_breaks"].format(where=broken.where(lang)),
                                 "warning"))
    summary += summary_tables(dyn, display, lang, w)
    reduced.append(Section(w["s_summary"], summary))
    if dyn.cycle is not None and broken is None:
        reduced.append(Section(w["s_motion"], [_figure(
            w["f_motion"], lambda: dynamics.plot_machine_motion(dyn, display=display),
            lang)]))
    sections.append(Section(w["s_reduced"], reduced))
    reactions: list = []
    if dyn.forces.reactions:
        reactions.append(_figure(w["f_reactions"], lambda: dynamics.plot_reactions(
            dyn, display=display), lang))
    for joint in dyn.forces.reactions:
        reactions.append(Section(w["s_hodograph"].format(name=joint), [_figure(
            w["f_hodograph"].format(name=joint),
            lambda joint=joint: dynamics.plot_hodograph(dyn, joint, display=display),
            lang)]))
    sections.append(Section(w["s_reactions"], reactions))
    centres = [f"S{b}" for b in dyn.centers][:6]
    if centres:
        sections.append(Section(w["s_centres"], [_figure(
            w["f_centres"], lambda: plan.plot_trajectories(
                dyn, centres, position=position, length_unit=length_unit), lang)]))
    return sections


def build_document(model: Model, *, lang: str, output: str | None = None,
                   position: int | None = None,
                   title: ReportInfo | dict | None = None,
                   project: ProjectDocuments | None = None,
                   warn: Callable[[str], None] | None = None) -> Document:
    """The report of ``model`` as a Document in ``lang`` ('en' or 'ru').

    ``output``: the output parameter ('r3', 'a3'; default :func:`output_parameter`);
    ``position``: the intermediate position of the vector scheme and the trajectories
    (default :func:`intermediate`; a broken or missing one is a HintedError naming the
    positions where the chain assembles); ``title``: the title page's fields over the
    model's ``report:`` section (a :class:`ReportInfo` or a dict, None values ignored);
    ``project``: the course project's gear and cam documents, which add their sheets
    before the conclusion; ``warn(text)`` is told, in ``lang``, when the chain breaks,
    so that the report's cycle figures are not valid (the report says so too).
    """
    if any(c.spatial for c in model.contours):  # issue 17: 3-D schemes, virtual power
        from mechloop.report.spatial import spatial_document

        return spatial_document(model, lang=lang, output=output, position=position,
                                title=title, project=project, warn=warn)
    w = words(lang)
    dyn = solve_dynamics(model) if model.bodies else None
    results = dyn.kinematics if dyn is not None else solve(model)
    source: Results | DynamicResults = dyn if dyn is not None else results
    name = output or output_parameter(results)
    if name not in results.values or name in results.constant:
        raise HintedError(f"{name!r} is not a varying parameter of the model",
                          f"use one of {', '.join(results.varying())}")
    position = check_position(results, position, w)
    td = resolve(model.display)
    shown = Shown(td, lang)
    # the plots in the units of the tables (angular velocities in rad/s unless named)
    display = plot_display(td or TableDisplay({})) or DEFAULT_DISPLAY
    length_unit = None if td is None else td.units.get("length")
    if warn is not None:
        broken = cycle_breaks(dyn) if dyn is not None else None
        if broken is not None:
            warn(w["cycle_breaks"].format(where=broken.where(lang)))
        elif results.broken.any() or results.breaks_between:
            warn(" ".join([w["breaks_intro"], *break_lines(results, shown, w)]))
    first = parameters_section(model, results, source, position, shown, w, length_unit)
    lines = break_lines(results, shown, w)
    if lines:
        first.blocks.append(Paragraph(" ".join([w["breaks_intro"], *lines]), "warning"))
    sections = [first, formula_section(model, results, shown, w),
                *_kinematic_sections(results, source, name, display, lang, w)]
    if dyn is not None:
        sections += _dynamic_sections(dyn, model, results, position, shown, display,
                                      length_unit, w)
    if project is not None:
        sections += [sheet_section(s) for s in project_sheets(project, lang)]
    sections.append(Section(w["s_conclusion"], list(conclusion_blocks(
        results, dyn, name, shown, w))))
    frame = dyn.to_frame() if dyn is not None else results.to_frame()
    names = () if dyn is None else (*dyn.forces.reactions, *dyn.forces.meshes)
    appendix = Section(w["s_appendix"], list(appendix_tables(frame, shown, w, names)))
    return Document(lang=lang, name=model.name or w["title"],
                    title=title_page(model, title_info(model, title), w),
                    sections=compact(sections), appendices=[appendix])
