"""The report of a model with spatial contours (issue 17) as a
:class:`~mechloop.report.document.Document`, in the planar report's order
(:mod:`mechloop.report.content`) with what is spatial added:

1 model parameters (general data, the vectors with β, the arguments, the contours, the
3-D vector scheme at the intermediate position with its projections on XY, ZY and XZ,
and the coordinates of the vector ends there), 2 calculation formula (n = 3 for a
spatial contour), 3 increment of the output parameter and its derivatives, 4 the angles
between adjacent vectors in space, 5 dependence of the driven link on the driving one,
6 trajectories of the moving vector ends; for a model with bodies 7 mass
characteristics and loads (inertia tensors, 3-D directions), 8 reduced loads and inertia
by virtual power (the reduced characteristics, the balancing load, the works of the loads
and the kinetic energy), with ``joints:`` 9 the reactions in the kinematic pairs by the
Newton–Euler equations (:mod:`mechloop.report.spatial_reactions`: the joints, the
reactions at positions, their magnitudes and 3-D hodographs), 10 trajectories of the
centres of mass; then the course project's sheets when given, the conclusion and the
appendix with the values at every position (β, the vectors' x/y/z, the centres of mass,
the bodies' angular velocities, the reactions).

Without ``joints:`` there are no reactions, and the reduced section says that they need
the joints; the machine motion is not computed for spatial models yet, so it has no
section (the reduced section says so).
"""

from __future__ import annotations

from collections.abc import Callable

from mechloop.model.project import ProjectDocuments
from mechloop.model.report_info import ReportInfo
from mechloop.model.schema import Model
from mechloop.output.display import TableDisplay, plot_display, resolve
from mechloop.report.appendix import appendix_tables
from mechloop.report.breaks import break_lines
from mechloop.report.document import Document, Paragraph, Section
from mechloop.report.formula import formula_section
from mechloop.report.numbers import Shown
from mechloop.report.parameters import argument_table, contour_table, general_table
from mechloop.report.sheets import project_sheets, sheet_section
from mechloop.report.spatial_dynamics import (
    centres_section3,
    conclusion3,
    masses_section3,
    reduced_section3,
)
from mechloop.report.spatial_kinematics import (
    angles_section,
    joints_table,
    scheme_figure,
    trajectories_section,
    vector_table3,
)
from mechloop.report.spatial_reactions import reactions_section3
from mechloop.report.spatial_words import spatial_words
from mechloop.report.title import title_info, title_page
from mechloop.views.display import DEFAULT_DISPLAY


def spatial_document(model: Model, *, lang: str, output: str | None = None,
                     position: int | None = None,
                     title: ReportInfo | dict | None = None,
                     project: ProjectDocuments | None = None,
                     warn: Callable[[str], None] | None = None) -> Document:
    """The report of the spatial ``model``; the arguments as
    :func:`mechloop.report.content.build_document`'s."""
    from mechloop.errors import HintedError
    from mechloop.report import content
    from mechloop.solve.kinematics import solve
    from mechloop.spatial.dynamics import solve_spatial_dynamics

    w = spatial_words(lang)
    dyn = solve_spatial_dynamics(model) if model.bodies else None
    results = dyn.kinematics if dyn is not None else solve(model)
    name = output or content.output_parameter(results)
    if name not in results.values or name in results.constant:
        raise HintedError(f"{name!r} is not a varying parameter of the model",
                          f"use one of {', '.join(results.varying())}")
    position = content.check_position(results, position, w)
    td = resolve(model.display)
    shown = Shown(td, lang)
    display = plot_display(td or TableDisplay({})) or DEFAULT_DISPLAY
    length_unit = None if td is None else td.units.get("length")
    lines = break_lines(results, shown, w)
    if warn is not None and lines:
        warn(" ".join([w["breaks_intro"], *lines]))
    first: list = [general_table(model, results, shown, w),
                   vector_table3(model, results, shown, w)]
    if model.arguments:
        first.append(argument_table(model, results, shown, w))
    first += [contour_table(model, results, w),
              scheme_figure(results, position, length_unit, lang, w),
              joints_table(results, position, shown, w)]
    if lines:
        first.append(Paragraph(" ".join([w["breaks_intro"], *lines]), "warning"))
    sections = [Section(w["s_parameters"], first), formula_section(model, results, shown, w),
                content.increment_section(results, results, name, display, lang, w),
                angles_section(results, display, lang, w),
                content.dependence_section(results, results, name, display, lang, w),
                trajectories_section(results, position, length_unit, lang, w)]
    if dyn is not None:
        sections += [masses_section3(dyn, model, shown, w),
                     reduced_section3(dyn, display, shown, lang, w)]
        reactions = reactions_section3(dyn, model, position, display, shown, lang, w)
        if reactions is not None:
            sections.append(reactions)
        centres = centres_section3(dyn, position, length_unit, lang, w)
        if centres is not None:
            sections.append(centres)
    if project is not None:
        sections += [sheet_section(s) for s in project_sheets(project, lang)]
    sections.append(Section(w["s_conclusion"], list(conclusion3(dyn, results, name, shown,
                                                                 w))))
    frame = dyn.to_frame() if dyn is not None else results.to_frame()
    joints = tuple(dyn.reactions.joints) if dyn is not None and dyn.reactions else ()
    appendix = Section(w["s_appendix"], list(appendix_tables(frame, shown, w, joints)))
    return Document(lang=lang, name=model.name or w["title"],
                    title=title_page(model, title_info(model, title), w),
                    sections=content.compact(sections), appendices=[appendix])

