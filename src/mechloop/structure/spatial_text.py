"""The structure of a model with spatial contours as text, in English or Russian: what
``mechloop structure`` prints for it (:mod:`.spatial`) — the links, the pairs with their
classes, the Somov–Malyshev count, the idle degrees of freedom, the redundant constraints,
the common constraints of a spherical or planar family, then the contours with their
modules and numbers of solutions (as ``mechloop info``)."""

from __future__ import annotations

from mechloop.model.schema import Model
from mechloop.structure.spatial import SpatialStructure

KINDS = {
    "en": {"R": "revolute", "P": "prismatic", "C": "cylindrical", "U": "universal",
           "S": "spherical"},
    "ru": {"R": "вращательная", "P": "поступательная", "C": "цилиндрическая",
           "U": "карданная", "S": "сферическая"},
}

WORDS = {
    "en": {
        "links": "moving links n = {n}: {list}; the ground 0",
        "from_joints": "the pairs are the model's joints (joints:), each checked against "
                       "the motion of its links",
        "from_vectors": "the model has no bodies: its links are taken from its vectors ("
                        "{list}), the vectors of constant r, α and β are the ground; two "
                        "links of one vector each meet in a spherical pair (name bodies: "
                        "and joints: for other pairs)",
        "link": "link {n}: vector(s) {list}",
        "pair": "  {name}: {kind} pair (class {k}) of links {a} and {b} at ({x}; {y}; {z}) "
                "{unit}{axis}",
        "axis": ", axis ({x}; {y}; {z})",
        "count": "Somov–Malyshev: W = 6n − 5p5 − 4p4 − 3p3 − 2p2 − p1 = 6·{n} − 5·{p5} − "
                 "4·{p4} − 3·{p3} − 2·{p2} − {p1} = {w}; inputs: {inputs}",
        "idle": "idle (passive) degrees of freedom: {count} — the spin of link(s) {list} "
                "about its line between spherical (or cylindrical) pairs; working mobility "
                "W − {count} = {work}",
        "family": "all revolute axes meet at one point: a spherical mechanism with 3 common "
                  "constraints; Dobrovolsky's formula W = 3n − 2p5 = 3·{n} − 2·{p5} = {wf}",
        "family_planar": "all revolute axes are parallel: a planar mechanism with 3 common "
                         "constraints; W = 3n − 2p5 = 3·{n} − 2·{p5} = {wf}",
        "redundant": "overconstrained: {q} redundant constraint(s) (q = {real} − ({w}) = "
                     "{q}: the chain moves with {real} degree(s) of freedom only because "
                     "of its geometry)",
        "missing": "W − idle = {work} > {inputs} input(s): {m} input(s) missing or a local "
                   "mobility not found",
        "ok": "the working mobility equals the number of inputs",
        "assur": "the Assur groups, the structure formula and the class of the mechanism "
                 "are defined for planar chains; they are not given for a chain with "
                 "spatial contours",
        "contours": "contours:",
    },
    "ru": {
        "links": "подвижные звенья n = {n}: {list}; стойка 0",
        "from_joints": "пары взяты из модели (joints:), каждая проверена по движению своих "
                       "звеньев",
        "from_vectors": "в модели нет звеньев (bodies:): звенья взяты из её векторов ("
                        "{list}), векторы с постоянными r, α и β — стойка; два звена из "
                        "одного вектора каждое соединены сферической парой (задайте bodies: "
                        "и joints:, чтобы указать другие пары)",
        "link": "звено {n}: векторы {list}",
        "pair": "  {name}: {kind} пара (класс {k}) звеньев {a} и {b} в точке ({x}; {y}; "
                "{z}) {unit}{axis}",
        "axis": ", ось ({x}; {y}; {z})",
        "count": "формула Сомова–Малышева: W = 6n − 5p5 − 4p4 − 3p3 − 2p2 − p1 = 6·{n} − "
                 "5·{p5} − 4·{p4} − 3·{p3} − 2·{p2} − {p1} = {w}; число входов: {inputs}",
        "idle": "местные (пассивные) подвижности: {count} — вращение звеньев {list} вокруг "
                "своей оси между сферическими (или цилиндрическими) парами; рабочая подвижность "
                "W − {count} = {work}",
        "family": "все оси вращательных пар пересекаются в одной точке: сферический "
                  "механизм с 3 общими связями; формула Добровольского W = 3n − 2p5 = "
                  "3·{n} − 2·{p5} = {wf}",
        "family_planar": "все оси вращательных пар параллельны: плоский механизм с 3 "
                         "общими связями; W = 3n − 2p5 = 3·{n} − 2·{p5} = {wf}",
        "redundant": "избыточные связи: {q} (q = {real} − ({w}) = {q}: цепь движется с "
                     "числом степеней свободы {real} лишь благодаря своей геометрии)",
        "missing": "W − местные подвижности = {work} > {inputs} (число входов): не хватает "
                   "входов: {m}, или не найдена местная подвижность",
        "ok": "рабочая подвижность равна числу входов",
        "assur": "группы Ассура, формула строения и класс механизма определены для плоских "
                 "цепей; для цепи с пространственными контурами они не приводятся",
        "contours": "контуры:",
    },
}


#: A pair's coordinate smaller than this share of the largest is printed as 0.
ZERO_RTOL = 1e-12


def _number(value: float, lang: str) -> str:
    text = f"{value:.6g}"
    text = "0" if text in ("-0", "0") else text
    return text.replace(".", ",") if lang == "ru" else text


def spatial_structure_lines(s: SpatialStructure, model: Model, lang: str = "en"
                            ) -> list[str]:
    """The printed structure of a spatial model, one line each (see the module)."""
    from mechloop.model.formula import describe_structure
    from mechloop.model.units import unit_factor
    from mechloop.views.unit_words import unit_text

    w, kinds = WORDS[lang], KINDS[lang]
    unit = model.units.length
    lines = [w["links"].format(n=s.n, list=", ".join(map(str, s.links)))]
    if s.source == "joints":
        lines.append(w["from_joints"])
    elif s.source == "vectors" and s.vector_links is not None:
        lines.append(w["from_vectors"].format(list="; ".join(
            w["link"].format(n=n, list=", ".join(map(str, vs)))
            for n, vs in s.vector_links.items())))
    # a coordinate below this is a solver's rounding of 0 (a point at the origin)
    tiny = ZERO_RTOL * max((float(abs(c)) for p in s.pairs for c in p.point), default=0.0)
    for pair in s.pairs:
        factor = unit_factor(unit, "length")
        x, y, z = (_number(float(c) / factor if abs(c) > tiny else 0.0, lang)
                   for c in pair.point)
        axis = "" if pair.axis is None else w["axis"].format(
            **dict(zip("xyz", (_number(round(float(c), 9), lang) for c in pair.axis),
                       strict=True)))
        lines.append(w["pair"].format(name=pair.name, kind=kinds[pair.kind], k=pair.klass,
                                      a=pair.links[0], b=pair.links[1], x=x, y=y, z=z,
                                      unit=unit_text(unit, lang), axis=axis))
    lines.append(w["count"].format(n=s.n, p5=s.p[5], p4=s.p[4], p3=s.p[3], p2=s.p[2],
                                   p1=s.p[1], w=s.W, inputs=s.inputs))
    work = s.W - len(s.idle)
    if s.idle:
        lines.append(w["idle"].format(count=len(s.idle), list=", ".join(map(str, s.idle)),
                                      work=work))
    if s.family is not None:
        key = "family" if s.family == "spherical" else "family_planar"
        lines.append(w[key].format(n=s.n, p5=s.p[5], wf=s.W_family))
    if s.q:
        lines.append(w["redundant"].format(q=s.q, real=s.inputs + len(s.idle), w=s.W))
    elif work > s.inputs:
        lines.append(w["missing"].format(work=work, inputs=s.inputs, m=work - s.inputs))
    else:
        lines.append(w["ok"])
    lines.append(w["assur"])
    lines.append(w["contours"])
    contours = describe_structure(model, lang).split("\n\n", 1)
    lines.append(contours[-1].rstrip())
    return lines
