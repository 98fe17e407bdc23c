"""The model's ``report:`` section: what the title page of the course-project report says
(``mechloop report``; the command line's ``--student``, ``--group``, … override it).

.. code-block:: yaml

    report:
      university: Samara University
      department: Department of machine design
      student: I. Ivanov
      group: 2305-240502D
      supervisor: A. Petrov
      city: Samara

Every field is optional; the title page leaves out the lines not given and takes the
kind of work, the course and the title in the report's language, the model's name as
its subject and this year as its year.
"""

from __future__ import annotations

from pydantic import Field

from mechloop.model.signals import _Frozen


def _text(what: str) -> object:
    return Field(None, max_length=200, description=what)


class ReportInfo(_Frozen):
    """The title page of the report: who made it, where and when."""

    university: str | None = _text("the university (top line of the title page)")
    department: str | None = _text("the department")
    course: str | None = _text("the discipline (default: Theory of machines and "
                               "mechanisms, in the report's language)")
    title: str | None = _text("the work's title (default: Kinematic and dynamic analysis "
                              "of the mechanism, in the report's language)")
    student: str | None = _text("the student's name")
    group: str | None = _text("the student's group")
    supervisor: str | None = _text("the supervisor's name")
    city: str | None = _text("the city (bottom line, with the year)")
    year: int | None = Field(None, ge=1900, le=2999, description="the year (default: "
                             "this year)")

    def merged(self, **override: str | int | None) -> ReportInfo:
        """These fields with those of ``override`` that are not None in their place (the
        command line's options)."""
        given = {k: v for k, v in override.items() if v is not None}
        return self.model_copy(update=given)
