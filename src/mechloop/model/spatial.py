"""Structure of a model with spatial contours (issue 17): roles, modules, solving order.

A contour with ``spatial: true`` closes in 3-D, ``Σ ±r_i (cos α_i cos β_i, sin α_i,
cos α_i sin β_i) = 0`` (seed 000 eq. 1.1, DESIGN §1): each of its vectors has ``r``,
``a`` (α, the elevation above the XZ plane) and ``b`` (β, the rotation about Y; 0 when
absent), each a constant, an argument, a link (with ratio) or ``function``; a negative
number in its ``vectors`` list subtracts that vector.  Exactly three of its parameters are
functions, and which three names the module of seed 000 table 2.1
(:func:`mechloop.spatial.contour.classify`); ``variant`` picks the module's branch
(1..its count) or ``auto`` (branch 1 at position 0, then continuity).

The other contours of such a model are planar (their vectors have no ``b``; in the XY
plane, or in the contour's ``plane``, :mod:`mechloop.model.plane`) and are solved by the
planar modules Pl1–Pl4 in their plane's axes; every parameter may
link to any other of its kind (α to α or to a planar angle, β to β), so planar and spatial
contours are chained freely.  Contours are solved one after another in dependency order;
contours that need each other's functions, or a contour linking to one of its own, form a
coupled block solved by Newton's method (:mod:`mechloop.spatial.blocks`,
:mod:`mechloop.spatial.block`).  Bodies, forces, moments and gravity are read by the
spatial dynamics (:mod:`mechloop.spatial.dynamics`), joints by its force analysis
(:mod:`mechloop.spatial.joints`); the sections nothing reads for a spatial model yet
(:data:`UNSUPPORTED`: gears, springs, machine motion, synthesis, ...) are refused.

:func:`analyze_spatial` (called by :func:`mechloop.model.check.check_model` for a model
with a spatial contour, in place of :func:`mechloop.model.structure.analyze`) returns the
same :class:`~mechloop.model.structure.Structure` as the planar analysis (module names
``Pr1``–``Pr19`` beside ``Pl1``–``Pl4``, three functions for a spatial contour) and every
problem, located, with its fix.
"""

from __future__ import annotations

from mechloop.errors import Problem
from mechloop.model.plane import Plane, normal_of
from mechloop.model.roles import is_function
from mechloop.model.schema import ArgumentRole, LinkRole, Model
from mechloop.model.structure import (
    MODULE_SOLUTIONS,
    ContourInfo,
    Structure,
    _module_of,
    param_role,
    vector_links,
)
from mechloop.model.units import UnitProblem, to_si
from mechloop.spatial.blocks import coupled_blocks
from mechloop.spatial.contour import classify

#: Sections of a model file that the spatial solver does not read yet.
UNSUPPORTED = ("gears", "springs", "dampers",
               "machine", "envelopes", "simulate", "synthesis", "project")
LETTERS = "rab"


def is_spatial(model: Model) -> bool:
    """Whether the model has a spatial contour."""
    return any(c.spatial for c in model.contours)


def plane_normal(model: Model, plane: Plane | None) -> tuple[float, float, float]:
    """The normal of a planar contour's ``plane`` (Z, the XY plane, when None)."""
    if plane is None:
        return (0.0, 0.0, 1.0)
    if plane.normal is not None:
        return plane.normal
    unit = model.units.angle
    return normal_of(to_si(plane.a, "angle", unit), to_si(plane.b, "angle", unit))


def contour_signs(model: Model, index: int) -> list[tuple[int, float]]:
    """(vector number, ±1) of contour ``index`` (0-based): a negative entry of a spatial
    contour subtracts the vector."""
    contour = model.contours[index]
    return [(abs(n), -1.0 if n < 0 and contour.spatial else 1.0) for n in contour.vectors]


def analyze_spatial(model: Model) -> tuple[Structure, list[Problem]]:
    """Resolve roles, name every contour's module and order the contours; collect every
    problem found."""
    problems: list[Problem] = []
    vectors = model.vectors
    for key in UNSUPPORTED:
        value = getattr(model, key)
        if value:
            problems.append(Problem((key,), f"'{key}' is not solved for a model with spatial "
                                    "contours yet (their dynamics reads bodies, joints, forces, "
                                    "moments and gravity only)",
                                    f"remove '{key}', or solve the planar part as a "
                                    "separate model"))
    if model.joints is not None and not model.bodies:  # reactions need bodies
        problems.append(Problem(("joints",), "the joints' reactions need the bodies they "
                                "connect, and the model has no bodies",
                                "list the moving bodies under bodies:, or remove joints"))
    spatial_vectors: set[int] = set()
    holder: dict[int, int] = {}
    for ci, contour in enumerate(model.contours):
        if contour.convention != 1 and not contour.spatial:
            problems.append(Problem(("contours", ci, "convention"), f"contour {ci + 1} is "
                                    "planar; a convention of parameter ranges applies to a "
                                    "spatial contour", "remove 'convention'"))
        if contour.plane is not None and contour.spatial:
            problems.append(Problem(("contours", ci, "plane"), f"contour {ci + 1} is "
                                    "spatial; a plane applies to a planar contour",
                                    "remove 'plane', or 'spatial: true'"))
        elif contour.plane is not None:
            try:
                plane_normal(model, contour.plane)
            except UnitProblem as exc:
                problems.append(Problem(("contours", ci, "plane"), exc.message, exc.hint))
        seen: set[int] = set()
        for vi, entry in enumerate(contour.vectors):
            number = abs(entry) if contour.spatial else entry
            path = ("contours", ci, "vectors", vi)
            if number not in vectors:
                hint = (f"add vector {number} under 'vectors:' or remove it from the contour"
                        if number > 0 else "a planar contour lists vector numbers "
                        "(a minus sign subtracts a vector only in a spatial contour)")
                problems.append(Problem(path, f"contour {ci + 1} lists vector {entry}, "
                                        "which is not defined", hint))
            elif number in seen:
                problems.append(Problem(path, f"contour {ci + 1} lists vector {number} twice",
                                        "list each vector once"))
            elif number in holder:
                problems.append(Problem(path, f"vector {number} is in contours "
                                        f"{holder[number]} and {ci + 1}; a vector belongs "
                                        "to one contour",
                                        f"in contour {ci + 1} use a new vector linked to it: "
                                        f"r: {{link: r{number}}}, a: {{link: a{number}}}, "
                                        f"b: {{link: b{number}}}"))
            else:
                holder[number] = ci + 1
                if contour.spatial:
                    spatial_vectors.add(number)
            seen.add(number)
    for number, vector in vectors.items():
        if number not in holder:
            problems.append(Problem(("vectors", number), f"vector {number} is in no contour",
                                    "add it to the 'vectors' list of a contour, or remove it"))
        elif vector.b is not None and number not in spatial_vectors:
            problems.append(Problem(("vectors", number, "b"), f"vector {number} has a "
                                    f"rotation β (b) but its contour {holder[number]} is "
                                    "planar (the XY plane, β = 0)",
                                    "add 'spatial: true' to that contour, or remove 'b'"))

    links = vector_links(model, LETTERS, problems)

    owner: dict[str, int] = {}
    infos: list[ContourInfo] = []
    closed_only: dict[int, list[Problem]] = {}  # problems of a contour solved alone
    for ci, contour in enumerate(model.contours):
        numbers = [abs(n) if contour.spatial else n for n in contour.vectors]
        numbers = [n for n in numbers if n in vectors]
        letters = LETTERS if contour.spatial else "ra"
        found = [(n, letter) for n in numbers for letter in letters
                 if is_function(param_role(model, f"{letter}{n}"))]
        names = [f"{letter}{n}" for n, letter in found]
        for f in names:
            owner[f] = ci + 1
        info, more = _classify(ci, contour, found, names)
        alone = [p for p in more if p.path[2:3] or "(module Pr20)" in p.message]
        problems += [p for p in more if p not in alone]
        closed_only[ci + 1] = alone
        needs: set[int] = set()
        arguments, link_names = [], []
        for n in numbers:
            for letter in letters:
                name = f"{letter}{n}"
                role = param_role(model, name)
                if isinstance(role, ArgumentRole):
                    arguments.append(name)
                if isinstance(role, LinkRole) and name in links:
                    link_names.append(name)
        infos.append(ContourInfo(number=ci + 1, vectors=tuple(numbers),
                                 functions=info[1], module=info[0],
                                 variant=contour.variant, needs=(),
                                 arguments=tuple(arguments), links=tuple(link_names)))
    for ci, info in enumerate(infos):
        needs = set()
        for name in info.links:
            root = links[name].root
            if root in owner:
                needs.add(owner[root])
            elif is_function(param_role(model, root)):
                problems.append(Problem(("vectors", int(name[1:]), name[0]),
                                        f"{name} links to {root}, a function that no "
                                        "contour solves", f"add vector {root[1:]} to a "
                                        "contour"))
        infos[ci] = _with(info, needs=tuple(sorted(needs)))
    final, blocks = coupled_blocks(model, infos, closed_only, problems)
    order = tuple(n for b in blocks for n in b.contours)
    return Structure(contours=final, order=order, links=links, owner=owner,
                     blocks=blocks), problems


def _with(info: ContourInfo, **changes: object) -> ContourInfo:
    fields = {k: getattr(info, k) for k in ("number", "vectors", "functions", "module",
                                            "variant", "needs", "arguments", "links",
                                            "block")}
    fields.update(changes)
    return ContourInfo(**fields)  # type: ignore[arg-type]


def _classify(ci: int, contour, found: list[tuple[int, str]], names: list[str]
              ) -> tuple[tuple[str, tuple[str, ...]], list[Problem]]:
    """(module, functions in module order) of contour ``ci`` and its problems."""
    path = ("contours", ci)
    listed = ", ".join(names) if names else "none"
    want = 3 if contour.spatial else 2
    kind = "spatial" if contour.spatial else "planar"
    if len(found) != want:
        fix = (f"mark {want} of its parameters 'function' (the unknowns of this loop)"
               if len(found) < want else
               f"make all but {want} of them constants, arguments or links to earlier "
               "contours")
        return ("?", tuple(names)), [Problem(
            path, f"contour {ci + 1} has {len(found)} function parameter(s) ({listed}); a "
            f"{kind} contour needs exactly {want}", fix)]
    if not contour.spatial:
        module, ordered = _module_of(names)
        count = MODULE_SOLUTIONS[module]
    else:
        choice = classify(found)
        assert choice is not None  # three distinct parameters
        module = choice.module
        ordered = tuple(f"{letter}{n}" for n, letter in choice.unknowns)
        count = choice.branches
        if module == "Pr20":
            return (module, ordered), [Problem(
                path, f"contour {ci + 1} has the three rotations {listed} unknown (module "
                "Pr20): it has infinitely many solutions (a one-parameter family)",
                "give one of these β a value (a constant, an argument or a link): the "
                "other two are then module Pr18/Pr19 or the planar Pl4 in the XZ plane")]
    problems: list[Problem] = []
    if contour.variant != "auto" and contour.variant > count:
        problems.append(Problem((*path, "variant"), f"contour {ci + 1} is module {module}, "
                                f"which has {count} solution(s); variant "
                                f"{contour.variant!r} does not apply",
                                f"set 'variant' to 1..{count} or 'auto'"
                                if count > 1 else "remove 'variant' or set it to 1"))
    if contour.guess:
        problems.append(Problem((*path, "guess"), f"contour {ci + 1} is solved in closed "
                                f"form (module {module}); a guess applies only to a coupled "
                                "block", "remove 'guess' and choose the branch with "
                                "'variant'"))
    return (module, ordered), problems


def refuse_spatial(model: Model, what: str) -> None:
    """Raise :class:`~mechloop.errors.SolveError` when ``model`` has a spatial contour:
    ``what`` (e.g. "solving many designs at once") is not built for spatial models yet."""
    if is_spatial(model):
        from mechloop.errors import SolveError

        raise SolveError(f"{what} is not built for a model with spatial contours yet",
                         "solve it with mechloop.solve (mechloop solve), or vary its "
                         "dimensions with mechloop sweep")
