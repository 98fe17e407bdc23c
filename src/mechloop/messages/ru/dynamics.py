"""Russian of the messages and fixes of dynamics (src/mechloop/dynamics/): the bodies,
kinematic pairs and gear meshes of the force analysis, the loads, springs and dampers, the
machine's steady motion and flywheel, and the motion in time (``simulate:``).

Each pattern is written as the English f-string of its raise site (:func:`_p`: literal text,
``{name}`` for a value, ``{{``/``}}`` for a brace), so an entry reads as the message it
translates."""

from __future__ import annotations

import re
import string

from mechloop.messages.ru.base import Entry

#: The regex of a value by its group name (the rest: ``.+?``, the value as written).
_VALUE = {"n": r"[-+\d.eE]+", "q": r"[^']*", "key": r"\w+", "name": r"\w+",
          "expr": r"'[^']*'|\"[^\"]*\"|.+?"}


def _p(template: str) -> str:
    """The pattern of an English f-string ``template``: its literal text escaped, each
    ``{name}`` a named group (``n…``: a number; ``q…``: text inside quotes; ``key``,
    ``name``: one word; ``expr``: a Python repr (or as written); else ``.+?``)."""
    out = []
    for literal, name, _spec, _conv in string.Formatter().parse(template):
        out.append(re.escape(literal))
        if name is not None:
            value = _VALUE.get(name.rstrip("0123456789"), r".+?")
            out.append(f"(?P<{name}>{value})")
    return "".join(out)


#: The ends of a vector and the kinds of kinematic pair, as the messages name them.
_WORDS = {"tail": "начало", "head": "конец", "revolute": "вращательная",
          "prismatic": "поступательная", "none": "нет", "bodies": "звенья",
          "named in the file": "заданы в файле", "inferred": "выведены из модели"}
_WORD = re.compile(r"\b(?:" + "|".join(sorted(map(re.escape, _WORDS), key=len, reverse=True))
                   + r")\b")


def _ru(text: str) -> str:
    """``text`` with the words of :data:`_WORDS` in Russian (a user's value stays)."""
    return _WORD.sub(lambda m: _WORDS[m[0]], text)


def _end_genitive(end: str) -> str:
    return {"tail": "начала", "head": "конца"}.get(end, end)


def _cases(where: str) -> str:
    """``_where`` of mechloop.dynamics.machine: " (case 3; 2 of 8 cases)" in Russian."""
    m = re.fullmatch(r" \(case (?P<c>[^;]+); (?P<k>\d+) of (?P<m>\d+) cases\)", where)
    if m is None:
        return where
    return f" (вариант {m['c']}; таких вариантов {m['k']} из {m['m']})"


ENTRIES: list[Entry] = [
    # the machine's motion over the cycle (mechloop.dynamics.analysis, cycle, machine)
    (_p("lower the coefficient of friction there (friction.coefficient, or a joint's "
        "friction) or check the pin radii and slider lengths"),
     "уменьшите там коэффициент трения ('friction.coefficient' или трение пары) либо "
     "проверьте радиусы цапф и длины ползунов"),
    (_p("lower the coefficients of friction or check the pin radii and slider lengths"),
     "уменьшите коэффициенты трения или проверьте радиусы цапф и длины ползунов"),
    (_p("machine motion needs the whole cycle, but the chain breaks between positions: "
        "{why_tr}"), "для движения машины нужен весь цикл, но цепь разрывается между "
     "положениями: {why_tr}"),
    (_p("check the loads, masses and speed of the machine (forces, moments, bodies, time)"),
     "проверьте нагрузки, массы и скорость машины ('forces', 'moments', 'bodies', 'time')"),
    (_p("machine motion needs one input and a model time (the model has {n} drive(s) and "
        "no time)"), "для движения машины нужны один вход и время модели (приводов в "
     "модели: {n}, времени нет)"),
    (_p("machine motion needs one input and a model time (the model has {n} drive(s) and "
        "a time)"), "для движения машины нужны один вход и время модели (приводов в "
     "модели: {n}, время задано)"),
    (_p("remove machine:, or drive the machine by one argument and give time: {{rpm: ...}}"),
     "удалите 'machine:' или задайте движение машины одним аргументом и время: "
     "{{rpm: ...}}"),
    (_p("remove the chain break (see the solve report) before sizing the flywheel"),
     "устраните разрыв цепи (см. отчёт 'mechloop solve'), прежде чем подбирать маховик"),
    (_p("make argument 1 increase from position 0 to N"),
     "сделайте аргумент 1 возрастающим от положения 0 до N"),
    (_p("the steady cycle with the loads that depend on the speed did not settle: after {n} "
        "iterations the speed over the cycle still changed by {d} of the mean speed "
        "(wanted {w})"), "установившийся цикл с нагрузками, зависящими от скорости, не "
     "сошёлся: после {n} итераций скорость за цикл всё ещё менялась на {d} средней скорости "
     "(требовалось {w})"),
    (_p("the dampers or one-way loads change too much with the speed over the cycle: raise "
        "the mean speed, add inertia (a flywheel: delta smaller), or simulate the machine in "
        "time instead"), "демпферы или односторонние нагрузки слишком сильно меняются со "
     "скоростью за цикл: повысьте среднюю скорость, добавьте инерции (маховик: 'delta' "
     "меньше) или рассчитайте движение машины во времени ('simulate:')"),
    # the fixes of mechloop.dynamics.analysis._MACHINE_FIXES (a table: the reader of the
    # coverage test does not follow it)
    (_p("check the loads over the cycle: positions 0..N must be one whole cycle of the "
        "input"), "проверьте нагрузки за цикл: положения 0..N должны составлять один полный "
     "цикл входного звена"),
    (_p("the dampers or one-way loads change too much with the speed over the cycle: raise "
        "the speed (time: {{rpm: ...}}), give a smaller delta (a larger flywheel), or "
        "simulate the machine in time (simulate:)"), "демпферы или односторонние нагрузки "
     "слишком сильно меняются со скоростью за цикл: повысьте скорость (time: {{rpm: ...}}), "
     "задайте меньший 'delta' (больший маховик) или рассчитайте движение машины во "
     "времени ('simulate:')"),
    (_p("no flywheel reaches delta = {n}"),
     "ни один маховик не даёт коэффициент неравномерности хода 'delta' = {n}"),
    (_p("check the reduced characteristics"),
     "проверьте приведённые характеристики (приведённые момент инерции и момент сил)"),
    (_p("the motion is not steady: the loads leave a net work of {n} J over one "
        "cycle{where}, so the speed does not repeat"),
     lambda m: (f"движение не установившееся: работа нагрузок за цикл равна {m['n']} J"
                f"{_cases(m['where'])}, поэтому скорость не повторяется")),
    (_p("the motion is not steady: the loads leave a net work of {n} J over one cycle, so "
        "the speed does not repeat"), "движение не установившееся: работа нагрузок за цикл "
     "равна {n} J, поэтому скорость не повторяется"),
    (_p("add the constant driving moment steady_driving_moment(q, m_red) = {n} N·m to m_red; "
        "it balances the net work"), "добавьте к 'm_red' постоянный движущий момент "
     "'steady_driving_moment(q, m_red)' = {n} N·m: он уравновешивает работу за цикл"),
    (_p("raise omega_mean or add a flywheel (flywheel_inertia gives its size for a delta)"),
     "увеличьте 'omega_mean' или добавьте маховик ('flywheel_inertia' даёт его момент "
     "инерции для заданного 'delta')"),
    (_p("check the masses"), "проверьте массы"),
    (_p("omega_mean must be positive, got {v}"),
     "'omega_mean' должна быть положительной, а получено {v}"),
    (_p("pass rad/s > 0"), "передайте значение в rad/s > 0"),
    (_p("delta must lie in (0, 2), got {v}"),
     "коэффициент неравномерности хода 'delta' должен лежать в (0, 2), а получено {v}"),
    (_p("typical values are 0.01 to 0.1"), "обычные значения — от 0.01 до 0.1"),
    (_p("q must be one cycle of at least 4 positions, shape (P,); got shape {s}"),
     "'q' должен быть одним циклом не менее чем из 4 положений, форма (P,); получена "
     "форма {s}"),
    (_p("pass the input coordinate as a 1-D array"),
     "передайте координату входного звена одномерным массивом"),
    (_p("q must be finite and strictly increasing"),
     "значения 'q' должны быть конечными и строго возрастающими"),
    (_p("sort q, drop repeats"), "отсортируйте 'q' и уберите повторы"),
    (_p("{name} must have shape (..., {n}) like q, got {s}"),
     "массив '{name}' должен иметь форму (..., {n}), как 'q', а получена {s}"),
    (r"check (?P<name>d?[jm]_red|m)", "проверьте '{name}'"),
    (_p("put the positions on the last axis"), "расположите положения по последней оси"),
    (_p("{name} has non-finite values"), "в '{name}' есть неконечные значения"),
    (_p("q, J and M must be one cycle of at least 4 positions of the same shape (P,); got "
        "{a}, {b}, {c}"), "'q', 'J' и 'M' должны быть одним циклом не менее чем из 4 "
     "положений одной формы (P,); получено {a}, {b}, {c}"),
    (_p("pass arrays over the positions"), "передайте массивы значений по положениям"),
    (_p("the input must advance at every position of the cycle"),
     "входное звено должно продвигаться вперёд в каждом положении цикла"),
    (_p("make the input's argument increase from position 0 to N"),
     "сделайте аргумент входного звена возрастающим от положения 0 до N"),
    (_p("J must be positive and J, M finite at every position"),
     "'J' должен быть положительным, а 'J' и 'M' — конечными в каждом положении"),
    (_p("give the moving bodies masses; remove chain breaks"),
     "задайте подвижным звеньям массы; устраните разрывы цепи"),
    # the start of a motion in time at a chain break (mechloop.dynamics.chain_span)
    (_p("the motion starts at a chain break (input {a}, position {p} to {p2})"),
     "движение начинается в разрыве цепи (вход {a}, положения от {p} до {p2})"),
    (_p("the motion starts at a chain break (input {a}, position {p})"),
     "движение начинается в разрыве цепи (вход {a}, положение {p})"),
    (_p("start where the chain assembles (mechloop solve lists the broken positions)"),
     "начните там, где цепь собирается ('mechloop solve' перечисляет положения разрыва)"),
    (_p("the chain assembles at only {n} position(s) around the start (input {a}) before it "
        "breaks: too few to read the machine between them"), "около начала (вход {a}) "
     "цепь собирается лишь в нескольких положениях (их {n}), а дальше разрывается: этого "
     "мало, чтобы рассчитать машину между ними"),
    (_p("give more positions (a finer step) or start elsewhere"),
     "задайте больше положений (мельче шаг) или начните в другом месте"),
    # springs and dampers (mechloop.dynamics.elements)
    (_p("bodies {b} are not two different bodies of the mechanism"),
     "звенья {b} — не два разных звена механизма"),
    (_p("use two of {b} (0: the ground)"), "укажите два из {b} (0 — стойка)"),
    (_p("add time: {{rpm: ...}}"), "добавьте 'time: {{rpm: ...}}'"),
    (_p("a damper needs the model's time (its force follows the speed)"),
     "демпферу нужно время модели (его сила зависит от скорости)"),
    (_p("this point is not fixed in body {b}: it moves relative to it"),
     "эта точка не закреплена на звене {b}: она движется относительно него"),
    (_p("give a point on a vector of that body (or the body that carries the point)"),
     "укажите точку на векторе этого звена (или звено, которому принадлежит точка)"),
    # the gas force of an indicator diagram (mechloop.dynamics.indicator)
    (_p("the gas force points towards the cylinder head (a positive value must push the "
        "piston away from it)"), "сила давления газов направлена к головке цилиндра "
     "(положительное значение должно отталкивать поршень от неё)"),
    (_p("turn the force by 180 deg (angle:), or set head: to the other end (max/min of the "
        "piston's parameter)"), "поверните силу на 180 deg ('angle:') или укажите в "
     "'head:' другой конец хода ('max'/'min' параметра поршня)"),
    (_p("the model has no indicator load"), "в модели нет индикаторной нагрузки"),
    (_p("give a force a value {{piston: rK, bore: ..., crankcase: ..., engine: {{...}}}} "
        "(examples/engine_indicator.yaml)"), "задайте силе значение {{piston: rK, bore: "
     "..., crankcase: ..., engine: {{...}}}} (examples/engine_indicator.yaml)"),
    (_p("the model has no drive to take the crank's angle from"),
     "в модели нет привода, от которого взять угол кривошипа"),
    (_p("give argument: K (the crank's argument)"),
     "задайте 'argument: K' (аргумент кривошипа)"),
    (_p("no vector's angle is driven by argument {k}"),
     "аргумент {k} не задаёт угол ни одного вектора"),
    (_p("give the argument that turns the crank"),
     "укажите аргумент, который поворачивает кривошип"),
    (_p("name the length rK of an existing vector K that places the piston"),
     "укажите длину rK существующего вектора K, задающего положение поршня"),
    (_p("argument {k} is not an angle"), "аргумент {k} — не угол"),
    # the force analysis (mechloop.dynamics.kinetostatics, mechanism)
    (_p("force analysis has {a} unknowns for {b} equations"),
     "в силовом расчёте неизвестных: {a}, а уравнений: {b}"),
    (_p("the model has no bodies"), "в модели нет звеньев ('bodies:')"),
    (_p("vector {v} is not a vector of body {b}"), "вектор {v} не принадлежит звену {b}"),
    (_p("list it in vectors, or remove it from ends"),
     "перечислите его в 'vectors' или удалите из 'ends'"),
    (_p("the force analysis is not determinate: {a} moving bodies give {b} equations, but "
        "{c} lower pairs, {d} gear meshes and {e} drives give {f} unknowns (joints {o}: "
        "{pairs})"), lambda m: (
         f"силовой расчёт статически неопределим: подвижных звеньев {m['a']}, уравнений "
         f"{m['b']}, а низших пар {m['c']}, зацеплений {m['d']} и приводов {m['e']} дают "
         f"неизвестных {m['f']} (пары {_ru(m['o'])}: {_ru(m['pairs'])})")),
    (_p("the force analysis is not determinate: {a} moving bodies give {b} equations, but "
        "{c} lower pairs and {e} drives give {f} unknowns (joints {o}: {pairs})"),
     lambda m: (
         f"силовой расчёт статически неопределим: подвижных звеньев {m['a']}, уравнений "
         f"{m['b']}, а низших пар {m['c']} и приводов {m['e']} дают неизвестных {m['f']} "
         f"(пары {_ru(m['o'])}: {_ru(m['pairs'])})")),
    (_p("name the kinematic pairs in joints: (revolute at a point, prismatic along a "
        "vector), or check that every moving link is a body and every driven vector belongs "
        "to one; name each gear mesh between bodies linked by a ratio in gears: (bodies, "
        "pitch point at, pressure_angle)"), "перечислите кинематические пары в 'joints:' "
     "(вращательная — в точке 'at', поступательная — вдоль вектора 'along') или проверьте, "
     "что каждое подвижное звено задано в 'bodies:' и каждый ведомый вектор принадлежит "
     "звену; каждое зацепление между звеньями, связанными передаточным отношением, "
     "перечислите в 'gears:' ('bodies', полюс зацепления 'at', 'pressure_angle')"),
    (_p("name the kinematic pairs in joints: (revolute at a point, prismatic along a "
        "vector), or check that every moving link is a body and every driven vector belongs "
        "to one"), "перечислите кинематические пары в 'joints:' (вращательная — в точке "
     "'at', поступательная — вдоль вектора 'along') или проверьте, что каждое подвижное "
     "звено задано в 'bodies:' и каждый ведомый вектор принадлежит звену"),
    (_p("add bodies: {{1: {{vectors: [1], mass: ..., center: ...}}}}"),
     "добавьте 'bodies: {{1: {{vectors: [1], mass: ..., center: ...}}}}'"),
    (_p("the ground (body 0) cannot have a mass"), "у стойки (звено 0) не может быть массы"),
    (_p("remove mass and parts from body 0"), "удалите 'mass' и 'parts' у звена 0"),
    (_p("vectors {a} and {b} of body {c} turn relative to each other (by up to {n} deg)"),
     "векторы {a} и {b} звена {c} поворачиваются друг относительно друга (до {n} deg)"),
    (_p("a body's vectors must move together: link their angles (a{a}: {{link: a{b}, "
        "delta: ...}}) or put them in different bodies"), "векторы одного звена должны "
     "двигаться вместе: свяжите их углы (a{a}: {{link: a{b}, delta: ...}}) или отнесите их "
     "к разным звеньям"),
    (_p("the {end} of vector {v} is not fixed in body {b}: it moves relative to the body's "
        "other points"), lambda m: (
         f"начало вектора {m['v']} не закреплено на звене {m['b']}: оно" if m["end"] == "tail"
         else f"конец вектора {m['v']} не закреплён на звене {m['b']}: он"
         if m["end"] == "head" else f"точка '{m['end']}' вектора {m['v']} не закреплена на "
         f"звене {m['b']}: она") + " движется относительно других точек звена"),
    (_p("a vector of varying length has only one end in a body: name it in ends (ends: "
        "{{{v}: tail}} or head)"), "у вектора переменной длины на звене лежит лишь один "
     "конец: укажите его в 'ends' ('ends: {{{v}: tail}}' или 'head')"),
    (_p("the body's vectors lie in different contours that are not placed where they are: "
        "give the later contour start: {{tail: K}} (a vector end it shares with an earlier "
        "contour) or fixed coordinates [x, y]"), "векторы звена лежат в разных контурах, "
     "положение которых не задано: дайте более позднему контуру 'start: {{tail: K}}' "
     "(конец вектора, общий с предыдущим контуром) или неподвижные координаты [x, y]"),
    (_p("the pin of joint {j} is not a point of body {b}: it moves relative to the body"),
     "ось шарнира {j} — не точка звена {b}: она движется относительно звена"),
    (_p("place the pin at a vector end that both bodies hold (the tail or head of one of "
        "their vectors)"), "поместите ось шарнира в конец вектора, общий для обоих звеньев "
     "(начало или конец одного из их векторов)"),
    (_p("vector {v} turns relative to body {b}, so joint {j} cannot slide along it"),
     "вектор {v} поворачивается относительно звена {b}, поэтому пара {j} не может "
     "скользить вдоль него"),
    (_p("slide along a vector whose direction is fixed in both bodies (the guide)"),
     "задайте скольжение вдоль вектора, направление которого неизменно в обоих звеньях "
     "(направляющей)"),
    (_p("the bodies of joint {j} do not slide along vector {v}: their relative motion has a "
        "component across it"), "звенья пары {j} не скользят вдоль вектора {v}: у их "
     "относительного движения есть составляющая поперёк него"),
    (_p("slide along the vector that runs along the guide"),
     "задайте скольжение вдоль вектора, идущего по направляющей"),
    (_p("friction needs the pin radius"), "для трения нужен радиус цапфы"),
    (_p("give radius: (here or in friction:)"),
     "задайте 'radius:' (здесь или в 'friction:')"),
    (_p("friction needs the slider length"), "для трения нужна длина ползуна"),
    (_p("give length: (here or in friction:)"),
     "задайте 'length:' (здесь или в 'friction:')"),
    (_p("body {b} does not exist"), "звена {b} нет"),
    (_p("use 0 (ground) or one of {b}"), "укажите 0 (стойка) или одно из {b}"),
    (_p("a joint needs two different bodies"), "кинематической паре нужны два разных звена"),
    (_p("name the two bodies it connects"), "укажите два звена, которые она соединяет"),
    (_p("a prismatic joint needs 'along'"), "поступательной паре нужен ключ 'along'"),
    (_p("give the vector along which the bodies slide"),
     "укажите вектор, вдоль которого скользят звенья"),
    (_p("a revolute joint needs 'at'"), "вращательной паре нужен ключ 'at'"),
    (_p("give the pin, e.g. at: {{head: 1}}"),
     "укажите ось шарнира, например 'at: {{head: 1}}'"),
    (_p("bodies {b} all hold the point where vector {v} ends and vector {w} starts: which "
        "pairs they form is ambiguous"), "звенья {b} все содержат точку, где кончается "
     "вектор {v} и начинается вектор {w}: какие пары они образуют, неоднозначно"),
    (_p("name the kinematic pairs in joints:"),
     "перечислите кинематические пары в 'joints:'"),
    (_p("bodies {a} and {b} meet at {n} different points (at the tail of vectors {v})"),
     "звенья {a} и {b} соприкасаются в разных точках (их {n}: в начале векторов {v})"),
    (_p("if these are one pin, a contour is not placed where it lies: give it start: "
        "{{tail: K}} (or [x, y]); otherwise name the pairs in joints:"), "если это один "
     "шарнир, то положение одного из контуров не задано: дайте ему 'start: {{tail: K}}' "
     "(или [x, y]); иначе перечислите пары в 'joints:'"),
    (_p("vector {v} changes length, but no body holds its {end}: the body it slides in is "
        "unknown"), lambda m: (
         f"вектор {m['v']} меняет длину, но ни одно звено не содержит его "
         f"{_end_genitive(m['end'])}: неизвестно, в каком звене он скользит")),
    (_p("list vector {v} in the body at its {end} too, with ends: {{{w}: {end2}}}, or name "
        "the pairs in joints:"), lambda m: (
         f"перечислите вектор {m['v']} и в звене у его {_end_genitive(m['end'])}, с "
         f"'ends: {{{m['w']}: {m['end2']}}}', или перечислите пары в 'joints:'")),
    (_p("argument {k} turns vector(s) {v} of no body"),
     "аргумент {k} поворачивает векторы {v}, не принадлежащие ни одному звену"),
    (_p("add the driven vector to the body it turns"),
     "добавьте ведомый вектор в звено, которое он поворачивает"),
    (_p("argument {k} turns vectors of several bodies ({b})"),
     "аргумент {k} поворачивает векторы нескольких звеньев ({b})"),
    (_p("drive one body per argument"), "задавайте движение одного звена одним аргументом"),
    (_p("argument {k} drives the length of vector {v}, but the bodies at its ends are not "
        "clear (tail: {t}, head: {h})"), lambda m: (
         f"аргумент {m['k']} задаёт длину вектора {m['v']}, но звенья на его концах не "
         f"определены (начало: {_ru(m['t'])}, конец: {_ru(m['h'])})")),
    (_p("make each end of the driven vector a point of exactly one body"),
     "сделайте каждый конец ведомого вектора точкой ровно одного звена"),
    # masses and moments of inertia of bodies
    (_p("add center: {{vector: K, share: 0.5}}"),
     "добавьте 'center: {{vector: K, share: 0.5}}'"),
    (_p("a mass cannot be negative"), "масса не может быть отрицательной"),
    (_p("give a mass ≥ 0"), "задайте массу ≥ 0"),
    (_p("body {b} has a mass but no centre of mass"),
     "у звена {b} задана масса, но не задан центр масс"),
    (_p("the centre of mass is on vector {v}, which is not in body {b}"),
     "центр масс лежит на векторе {v}, который не входит в звено {b}"),
    (_p("place it on one of {v}"), "поместите его на один из векторов {v}"),
    (_p("vector {v} changes length, so a share of it is not a fixed point of the body"),
     "вектор {v} меняет длину, поэтому точка на доле его длины не закреплена на звене"),
    (_p("place the centre with along/across from the tail"),
     "задайте центр ключами 'along'/'across' от начала вектора"),
    (_p("body {b} holds the head of vector {v}, which changes length, so a point placed from "
        "its tail moves in the body"), "звено {b} содержит конец вектора {v} переменной "
     "длины, поэтому точка, отложенная от его начала, движется относительно звена"),
    (_p("put the centre at {{head: {v}}}, or on a vector of constant length"),
     "поместите центр в 'at: {{head: {v}}}' или на вектор постоянной длины"),
    (_p("body {b} holds the tail of vector {v}, which changes length, so its head moves in "
        "the body"), "звено {b} содержит начало вектора {v} переменной длины, поэтому его "
     "конец движется относительно звена"),
    (_p("put the centre at {{tail: {v}}} or along/across from it"),
     "поместите центр в 'at: {{tail: {v}}}' или отложите ключами 'along'/'across' от "
     "начала"),
    (_p("'rod' needs a vector of constant length, and vector {v} changes length"),
     "для 'rod' нужен вектор постоянной длины, а вектор {v} меняет длину"),
    (_p("give the moment of inertia as a number"), "задайте момент инерции числом"),
    (_p("a moment of inertia cannot be negative"),
     "момент инерции не может быть отрицательным"),
    (_p("give a value ≥ 0"), "задайте значение ≥ 0"),
    # gear meshes (mechloop.dynamics.meshes)
    (_p("gear mesh {mesh} needs two different bodies of the model; {b} is not one"),
     "зацеплению {mesh} нужны два разных звена модели; {b} — не звено модели"),
    (_p("gear mesh {mesh} needs two different bodies of the model"),
     "зацеплению {mesh} нужны два разных звена модели"),
    (_p("use two of {b}"), "укажите два из {b}"),
    # the choices listed as a Python list (the common "use one of" reads words only)
    (r"use one of (?P<items>\[[^\]]*\])", "укажите одно из {items}"),
    (_p("ring {r} is not one of the mesh's bodies {b}"),
     "'ring' {r} не входит в звенья зацепления {b}"),
    (_p("name the body with internal teeth, or leave ring out"),
     "укажите звено с внутренними зубьями или уберите 'ring'"),
    (_p("the pressure angle must lie in [0°, 90°)"),
     "угол зацепления должен лежать в [0°, 90°)"),
    (_p("use the standard 20°"), "используйте стандартный угол 20°"),
    (_p("the gear of body {b} needs exactly one revolute pair, its axle, to tell the radial "
        "direction (it has {n})"), "зубчатому колесу звена {b} нужна ровно одна "
     "вращательная пара — его ось, чтобы задать радиальное направление (пар у него: {n})"),
    (_p("put the mesh's second gear on one pin (list the gear on a body of its own)"),
     "посадите второе колесо зацепления на одну ось (выделите колесо в отдельное звено)"),
    # where the contours start (mechloop.dynamics.points)
    (_p("the starts of contours refer to each other in a cycle"),
     "начала контуров ссылаются друг на друга по кругу"),
    (_p("start one of them at the origin or at fixed coordinates [x, y]"),
     "начните один из них в начале координат или в неподвижной точке [x, y]"),
    (_p("vector {v} is in this contour"), "вектор {v} входит в этот же контур"),
    (_p("start a contour at a point of another contour"),
     "начинайте контур в точке другого контура"),
    # loads (mechloop.dynamics.loads)
    (_p("the model has no parameter {name}"), "в модели нет параметра {name}"),
    (_p("name rK or aK of an existing vector K"),
     "укажите rK или aK существующего вектора K"),
    (_p("the values of {name} must increase down the table"),
     "значения {name} должны возрастать сверху вниз по таблице"),
    (_p("sort the [value, load] pairs"),
     "отсортируйте пары [значение, нагрузка] по значению"),
    (_p("use t (with model time), rK, aK, drK, daK of existing vectors K"),
     "используйте t (если у модели есть время), rK, aK, drK, daK существующих векторов K"),
    (_p("the model has no t (the model has no time)"),
     "в модели нет величины t (у модели нет времени)"),
    # a name an expression reads (or a key of the model: the sweep's message is the same)
    # that the model lacks; not a word of another area's message
    (r"the model has no (?!(?:bodies|envelopes|time)$)(?P<name>[A-Za-z_]\w*)",
     "в модели нет '{name}'"),
    (_p("cannot evaluate {expr}: {why}"), "не удаётся вычислить {expr}: {why}"),
    (_p("call functions as sin(x); use numbers and the state's names"),
     "вызывайте функции как sin(x); используйте числа и имена величин состояния"),
    (_p("{expr} is not finite at position {n}"),
     "значение {expr} не конечно в положении {n}"),
    (_p("keep divisions and logarithms away from zero"),
     "не допускайте деления на ноль и логарифма нуля"),
    (_p("an expression of the rates or time cannot also have when:"),
     "у выражения со скоростями или временем не может быть ещё и 'when:'"),
    (_p("write the condition into the expression: (drK > 0)*..."),
     "впишите условие в само выражение: (drK > 0)*..."),
    (_p("body {b} is not a moving body"), "звено {b} — не подвижное звено"),
    (_p("vector {v} does not exist"), "вектора {v} нет"),
    # the motion in time (mechloop.dynamics.simulate, simulate_inputs, state_kinematics)
    (_p("no cycle was completed"), "ни один цикл не завершён"),
    (_p("simulate longer"), "увеличьте время расчёта"),
    (_p("the run needs an end"), "у расчёта должен быть конец"),
    (_p("give a duration (s) or a number of cycles"),
     "задайте длительность ('duration', s) или число циклов ('cycles')"),
    (_p("the start speed must be zero or positive, got {n} rad/s"),
     "начальная скорость должна быть нулевой или положительной, а задано {n} rad/s"),
    (_p("start from rest or turning forwards"),
     "начинайте из покоя или с вращением в прямом направлении"),
    (_p("the start angle {a} deg is outside the modelled range {b} … {c} deg of a machine "
        "that is not periodic"), "начальный угол {a} deg вне рассчитанного диапазона "
     "{b} … {c} deg непериодической машины"),
    (_p("start inside the range of the input's argument"),
     "начинайте внутри диапазона аргумента входного звена"),
    (_p("stop_at ({a} deg) must lie ahead of the start ({b} deg)"),
     "угол остановки 'stop_at' ({a} deg) должен лежать впереди начала ({b} deg)"),
    (_p("give an angle beyond the start angle (it grows turn by turn)"),
     "задайте угол дальше начального (он растёт с каждым оборотом)"),
    (_p("the integrator failed at t = {t} s: {why}"),
     "интегрирование прервалось при t = {t} s: {why}"),
    (_p("loosen rtol/atol or try method: Radau"),
     "ослабьте допуски rtol/atol или попробуйте 'method: Radau'"),
    (_p("the cycle that starts at t = {t} s does not end"),
     "цикл, начавшийся при t = {t} s, не заканчивается"),
    (_p("give a duration (s)"), "задайте длительность ('duration', s)"),
    (_p("the model has no simulate: section"), "в модели нет раздела 'simulate:'"),
    (_p("add simulate: {{motor: ..., duration: 5}} or pass settings"),
     "добавьте 'simulate: {{motor: ..., duration: 5}}' или передайте настройки "
     "('settings')"),
    (_p("see the simulate: section of the model schema"),
     "см. раздел 'simulate:' в схеме модели"),
    (_p("motion in time needs one input that turns (the model has {n} drive(s))"),
     "для движения во времени нужно одно вращающееся входное звено (приводов в модели: {n})"),
    (_p("motion in time needs one input that turns (the model has {n} drive(s), driven by a "
        "length)"), "для движения во времени нужно одно вращающееся входное звено "
     "(приводов в модели: {n}, движение задано длиной)"),
    (_p("drive the machine by one angle argument"),
     "задайте движение машины одним аргументом-углом"),
    (_p("flywheel: machine takes the flywheel machine: sizes, and the model has no machine: "
        "{{delta: ...}}"), "'flywheel: machine' берёт маховик, подобранный в 'machine:', а "
     "в модели нет 'machine: {{delta: ...}}'"),
    (_p("add machine: {{delta: 0.0125}} or give the flywheel's moment of inertia"),
     "добавьте 'machine: {{delta: 0.0125}}' или задайте момент инерции маховика"),
    (_p("the chain does not assemble at the start (contour {c} breaks or is at a dead "
        "point)"), "в начале цепь не собирается (контур {c} разрывается или находится в "
     "мёртвой точке)"),
    (_p("start the inputs where the mechanism assembles"),
     "задайте входам начало там, где механизм собирается"),
    (_p("the mass matrix at the start is not positive definite: some input moves no mass"),
     "матрица масс в начале не положительно определена: какой-то вход не движет ни одной "
     "массы"),
    (_p("give the bodies each input moves a mass or a moment of inertia"),
     "задайте звеньям, которые движет каждый вход, массу или момент инерции"),
    (_p("stop_at is the start angle itself"),
     "угол остановки 'stop_at' совпадает с начальным углом"),
    (_p("give an angle the input moves to"), "задайте угол, к которому движется вход"),
    (_p("input {k} is a length: the motion of several inputs takes inputs that turn"),
     "вход {k} — длина: движение с несколькими входами рассчитывается только для "
     "вращающихся входов"),
    (_p("drive every input by an angle argument"),
     "задайте каждый вход аргументом-углом"),
    (_p("{key} applies to a machine with one input; this one has {n} ({k})"),
     "'{key}' применяется к машине с одним входом, а у этой входов {n} ({k})"),
    (_p("use motors: {{k: ...}}, duration and stop_at per input"),
     "используйте 'motors: {{k: ...}}', 'duration' и 'stop_at' для каждого входа"),
    (_p("give motors: {{argument: {{...}}}} with one motor per input"),
     "задайте 'motors: {{argument: {{...}}}}' с одним двигателем на каждый вход"),
    (_p("the run of several inputs needs a duration"),
     "расчёту с несколькими входами нужна длительность ('duration')"),
    (_p("give duration: seconds"), "задайте 'duration:' в секундах"),
    (_p("argument {k} is not an input"), "аргумент {k} — не один из входов"),
    (_p("{key} of several inputs is given per input"),
     "'{key}' при нескольких входах задаётся для каждого входа"),
    (_p("write {key}: {{{k}: ...}}"), "пишите '{key}: {{{k}: ...}}'"),
    (_p("write start: {{{k}: {{angle: ..., rpm: ...}}}}"),
     "пишите 'start: {{{k}: {{angle: ..., rpm: ...}}}}'"),
    (_p("the start of several inputs is given per input"),
     "начало ('start') при нескольких входах задаётся для каждого входа"),
    (_p("a load over the positions has no value at the states of several inputs"),
     "у нагрузки, заданной по положениям, нет значения в состояниях с несколькими "
     "входами"),
    (_p("give it as a constant, a table over a parameter (of: ...) or an expression of the "
        "state"), "задайте её постоянной, таблицей по параметру ('of: ...') или выражением "
     "от состояния"),
    (_p("joint friction is not part of the motion of several inputs (it needs the reactions "
        "at every state)"), "трение в парах не учитывается в движении с несколькими "
     "входами (для него нужны реакции в каждом состоянии)"),
    (_p("set friction: false to run without it"),
     "задайте 'friction: false', чтобы считать без него"),
    (_p("argument {k} is not the input"), "аргумент {k} — не вход машины"),
    (_p("the input is argument {k}"), "вход машины — аргумент {k}"),
    (_p("rest_rpm applies to several inputs; one input ends its run where its speed falls "
        "to zero"), "'rest_rpm' применяется к нескольким входам; с одним входом расчёт "
     "заканчивается там, где его скорость падает до нуля"),
    (_p("remove rest_rpm (reverse: false stops there)"),
     "удалите 'rest_rpm' (при 'reverse: false' расчёт там и останавливается)"),
    (_p("a coupled block (contours solved together by Newton's continuation) has no closed "
        "form at a free-standing state"), "у связанного блока (контуров, решаемых вместе "
     "продолжением по методу Ньютона) нет замкнутого решения в отдельно взятом состоянии"),
    (_p("the motion of several inputs needs contours that each close by an elementary "
        "module"), "для движения с несколькими входами каждый контур должен замыкаться "
     "элементарным модулем"),
    (_p("an angle scaled by a link ratio follows its whole turns from position to position"),
     "угол, умноженный на отношение ссылки ('ratio'), следит за целыми оборотами от "
     "положения к положению"),
    (_p("the motion of several inputs needs links of ratio 1"),
     "для движения с несколькими входами нужны ссылки с отношением 1"),
    # spatial contours (dynamics/points.py)
    (r"position plans, trajectories and animations of a model with spatial contours are not "
     r"built yet \(its points are in 3-D\)", "планы положений, траектории и анимация модели "
     "с пространственными контурами пока не реализованы (её точки лежат в пространстве)"),
    (r"plot its parameters against the position \(plot \.\.\. parameters -n b3\) or write "
     r"the table with mechloop solve", "постройте графики её параметров по положениям "
     "('plot ... parameters -n b3') или запишите таблицу командой 'mechloop solve'"),
    # what applies only in space, refused in a planar model (dynamics/loads.py, mechanism.py)
    (_p("a 3-D direction applies to a force in a model with spatial contours"),
     "направление в пространстве задаётся для силы в модели с пространственными контурами"),
    (_p("give the direction in the plane with 'angle'"),
     "задайте направление в плоскости углом 'angle'"),
    (_p("an axis applies to a moment in a model with spatial contours"),
     "ось задаётся для момента в модели с пространственными контурами"),
    (_p("remove 'axis' (a planar moment turns about Z, counter-clockwise)"),
     "удалите 'axis' (плоский момент действует вокруг Z, против часовой стрелки)"),
    (_p("an inertia tensor applies to a body of a model with spatial contours"),
     "тензор инерции задаётся для звена модели с пространственными контурами"),
    (_p("give one moment of inertia (about the axis normal to the plane)"),
     "задайте один момент инерции (относительно оси, перпендикулярной плоскости)"),
    (_p("the force analysis with reactions, the machine motion and the planar plots of the "
        "dynamics are not built for a model with spatial contours yet"),
     "силовой расчёт с реакциями, движение машины и плоские графики динамики пока не "
     "реализованы для модели с пространственными контурами"),
    (_p("write its dynamics by virtual power with mechloop solve"),
     "запишите её динамику по принципу возможных мощностей командой 'mechloop solve'"),
    # joints of a model with spatial contours (spatial/joints.py, spatial/reactions.py;
    # the planar refusal in dynamics/mechanism.py)
    (_p("a {t} joint applies to a model with spatial contours"),
     "пара '{t}' применяется в модели с пространственными контурами"),
    (_p("a planar model's joints are revolute or prismatic"),
     "пары плоской модели — вращательные ('revolute') или поступательные ('prismatic')"),
    (_p("a joint's axis applies to a model with spatial contours"),
     "ось пары задаётся в модели с пространственными контурами"),
    (_p("remove 'axis' (a planar pin turns about Z; a prismatic joint slides 'along' a "
        "vector)"), "удалите 'axis' (плоский шарнир поворачивается вокруг Z; "
     "поступательная пара скользит вдоль вектора 'along')"),
    (_p("friction in the joints of a model with spatial contours is not computed yet"),
     "трение в кинематических парах модели с пространственными контурами пока не "
     "рассчитывается"),
    (_p("remove it (the joints are ideal)"), "удалите его (пары считаются идеальными)"),
    (_p("body {b} is not a moving body of the model"),
     "звено {b} не является подвижным звеном модели"),
    (_p("use 0 (the ground) or one of {items}"), "укажите 0 (стойку) или одно из {items}"),
    (_p("in a model with spatial contours a joint's axis is given by 'axis'"),
     "в модели с пространственными контурами ось пары задаётся ключом 'axis'"),
    (_p("write axis: {a} in place of along: {b}"), "напишите axis: {a} вместо along: {b}"),
    (_p("a spherical joint has no axis (it turns about every axis)"),
     "у сферической пары нет оси (она допускает поворот вокруг любой оси)"),
    (_p("remove 'axis', or make it a revolute joint (type: revolute)"),
     "удалите 'axis' или сделайте пару вращательной ('type: revolute')"),
    (_p("a {t} joint of a model with spatial contours needs its axis"),
     "паре '{t}' в модели с пространственными контурами нужна ось ('axis')"),
    (_p("give axis: K (along vector K) or axis: [x, y, z]"),
     "задайте axis: K (вдоль вектора K) или axis: [x, y, z]"),
    (_p("a {t} joint needs 'at': its centre"), "паре '{t}' нужна точка 'at': её центр"),
    (_p("a {t} joint needs 'at': a point of its axis"),
     "паре '{t}' нужна точка 'at': точка её оси"),
    (_p("give the point, e.g. at: {{head: 1}}"),
     "задайте точку, например at: {{head: 1}}"),
    (_p("place the point on the vector (share or along)"),
     "поместите точку на вектор ('share' или 'along')"),
    (_p("body {b} is in no joint, so the force analysis has nothing to hold it"),
     "звено {b} не входит ни в одну пару, поэтому в силовом расчёте его ничто не "
     "удерживает"),
    (_p("name the joints of body {b} with the bodies it touches"),
     "задайте пары звена {b} со звеньями, с которыми оно соединено"),
    (_p("argument {k} drives {params} of bodies {items}; its balancing load needs one "
        "parameter of one body"), lambda m: f"аргумент {m['k']} задаёт {m['params']} "
     f"звеньев {_ru(m['items'])}; для его уравновешивающей нагрузки нужен один параметр "
     "одного звена"),
    (_p("argument {k} turns vector {v} of no body"),
     "аргумент {k} поворачивает вектор {v}, не входящий ни в одно звено"),
    (_p("list vector {v} in the body at its head with ends: {{{w}: head}}, or name the "
        "joint along it (prismatic, cylindrical)"), "укажите вектор {v} в звене у его "
     "конца с 'ends: {{{w}: head}}' или задайте пару вдоль него (поступательную или "
     "цилиндрическую)"),
    (_p("the balancing force of argument {k} does not move with the argument (its power "
        "is not that of the argument's rate)"), "уравновешивающая сила аргумента {k} не "
     "согласована с ним (её мощность не равна мощности на скорости аргумента)"),
    (_p("the balancing moment of argument {k} does not move with the argument (its power "
        "is not that of the argument's rate)"), "уравновешивающий момент аргумента {k} не "
     "согласован с ним (его мощность не равна мощности на скорости аргумента)"),
    (_p("drive a body that turns about the argument's axis (an elevation a: about (-sin b, "
        "0, cos b); a rotation b: about Y), or the bodies at the two ends of a driven "
        "length"), "приводите звено, поворачивающееся вокруг оси аргумента (угол "
     "возвышения a: вокруг (-sin b, 0, cos b); поворот b: вокруг Y), или звенья на двух "
     "концах изменяемой длины"),
    (_p("the bodies {a} and {b} of joint {j} move apart at its point (with argument {k}): "
        "its force would do work"), "звенья {a} и {b} пары {j} расходятся в её точке (по "
     "аргументу {k}): её сила совершала бы работу"),
    (_p("place 'at' on the joint (the ball's centre, a point of the axis) and check its "
        "type and axis"), "поместите 'at' в пару (центр шара, точку оси) и проверьте её "
     "тип и ось"),
    (_p("the bodies {a} and {b} of joint {j} turn relative to each other about an axis its "
        "moment holds (with argument {k})"), "звенья {a} и {b} пары {j} поворачиваются "
     "друг относительно друга вокруг оси, которую удерживает её момент (по аргументу {k})"),
    (_p("give the axis they turn about (axis: K along vector K, or [x, y, z]), or a type "
        "that lets them turn (spherical, cylindrical)"), "задайте ось их относительного "
     "поворота (axis: K вдоль вектора K или [x, y, z]) или тип пары, допускающий поворот "
     "('spherical', 'cylindrical')"),
    (_p("the force analysis is statically indeterminate: {n} reaction component(s) more "
        "than the equations of the bodies decide (joints {items} can hold reactions that "
        "balance each other whatever the loads)"), "силовой расчёт статически "
     "неопределим: составляющих реакций на {n} больше, чем определяют уравнения звеньев "
     "(пары {items} могут нести взаимно уравновешенные реакции при любых нагрузках)"),
    (_p("make it determinate with these joint types: {types}"),
     "сделайте его статически определимым с такими типами пар: {types}"),
    (_p("free some of the components of joints {items} (a spherical or cylindrical joint "
        "in place of a revolute one)"), "освободите часть составляющих реакций пар {items} "
     "(сферическая или цилиндрическая пара вместо вращательной)"),
    (r"body (?P<b>\S+) can (?:(?P<turn>turn about the axis)|slide along) \((?P<axis>[^)]*)\) "
     r"at position (?P<p>\S+)(?: through joints (?P<on>.+?))? with no joint holding it, but "
     r"its inertia and loads do not balance in that motion: a (?:moment|force) of "
     r"(?P<i>\S+) (?P<u>\S+) from its inertia and (?P<l>\S+) (?P=u) from the loads \(at "
     r"(?P<c>\S+) position\(s\)\)", lambda m: f"звено {m['b']} может "
     + ("поворачиваться вокруг оси" if m["turn"] else "скользить вдоль")
     + f" ({m['axis']}) в положении {m['p']}"
     + (f" через пары {m['on']}" if m["on"] else "")
     + ", и его не удерживает ни одна пара, но его силы инерции и нагрузки в этом движении "
     + ("не уравновешены: момент " if m["turn"] else "не уравновешены: сила ")
     + f"{m['i']} {m['u']} от сил инерции и {m['l']} {m['u']} от нагрузок (положений: "
     f"{m['c']})"),
    (_p("make body {b}'s inertia tensor symmetric about that axis with no load turning it "
        "about the axis (inertia: rod, or [J_axis, J, J]), or hold the motion with a joint "
        "(revolute instead of spherical)"), "сделайте тензор инерции звена {b} "
     "симметричным относительно этой оси и без нагрузок, поворачивающих его вокруг неё "
     "(inertia: rod или [J_axis, J, J]), или удержите это движение парой (вращательной "
     "вместо сферической)"),
]
