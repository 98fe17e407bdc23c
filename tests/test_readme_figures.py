"""Every number in README.md, the pages of docs/ and the examples' headers is accounted for.

The text (outside code blocks; inline code only where a figure entry covers it) is split
into paragraphs, and every number in it must be one of:

* a **figure** of FIGURES: a result, with how it is reproduced — a test that pins it (its
  source holds the number to the precision printed in the docs), a value computed here
  (cheap: a solve, a closed form), or a benchmark the docs name in the same section (a
  machine-dependent figure must be said to be, in its section);
* an **input or a reference** of INPUTS (a phrase, with why it is not a result);
* a small count (an integer up to 12 without a unit of time or a percent sign), or a
  number that appears in the data of an example or in a code block of the README (the
  example's own inputs, as its header describes them).

A number that is none of these — a new figure nobody checks — fails
`test_every_number_is_accounted_for`; an entry that no longer matches anything fails
`test_no_entry_is_stale`.
"""

from __future__ import annotations

import ast
import functools
import math
import re
from collections.abc import Callable
from pathlib import Path

import numpy as np
import pytest
from helpers.docs import PAGES, all_text, page_text

import mechloop

ROOT = Path(__file__).resolve().parents[1]
EXAMPLES = ROOT / "examples"
EXAMPLE_FILES = sorted(p for p in EXAMPLES.rglob("*")  # examples/course, cams, gears too
                       if p.is_file() and "__pycache__" not in p.parts)
SUPERSCRIPT = str.maketrans("⁻⁰¹²³⁴⁵⁶⁷⁸⁹", "-0123456789")
NUMBER = re.compile(r"(?<![\w.\-/])(\d+(?:,\d{3})*(?:\.\d+)?(?:e[-+]?\d+|·10[⁻⁰-⁹¹²³]+)?)"
                    r"(?![a-zA-Z_\d])")
TIMEY = re.compile(r"\s?(s\b|ms\b|%|GB\b|designs/s)")


# ------------------------------------------------------------------------------ the text
def _paragraphs_of_readme() -> list[tuple[str, str, str]]:
    """(document, section, paragraph) of the README and of each page of docs/ outside fenced
    code blocks; a table row is a paragraph of its own."""
    out: list[tuple[str, str, str]] = []
    for page in PAGES:
        readme = page_text(page)
        for block in re.findall(r"```bash\n(.*?)```", readme, flags=re.S):
            out += [(page, readme, line.split(" #", 1)[1].strip())
                    for line in block.splitlines() if " #" in line]
        text = re.sub(r"```.*?```", "\n\n", readme, flags=re.S)
        for section in re.split(r"\n(?=#{1,4} )", text):
            for block in re.split(r"\n\s*\n", section):
                rows = block.splitlines()
                if rows and all(r.startswith("|") for r in rows):
                    out += [(page, section, r) for r in rows]
                elif block.strip():
                    out.append((page, section, " ".join(r.strip() for r in rows)))
    return out


def _header(path: Path) -> str:
    text = path.read_text(encoding="utf-8")
    if path.suffix == ".py":
        found = re.match(r'\s*"""(.*?)"""', text, flags=re.S)
        return found.group(1) if found else ""
    lines = []
    for line in text.splitlines():
        if not line.startswith("#"):
            break
        lines.append(line[1:].strip() if line.strip() != "#" else "")
    return "\n".join(lines)


def _paragraphs_of_headers() -> list[tuple[str, str, str]]:
    out = []
    for path in EXAMPLE_FILES:
        header = _header(path)
        for block in re.split(r"\n\s*\n", header):
            if block.strip():
                out.append((path.name, header, " ".join(block.split())))
    return out


PARAGRAPHS = _paragraphs_of_readme() + _paragraphs_of_headers()


def _pool() -> set[float]:
    """Numbers of the examples' data (outside comments) and of the documentation's code
    blocks."""
    texts = [line.split("#")[0] for p in EXAMPLE_FILES
             for line in p.read_text(encoding="utf-8").splitlines()]
    readme = all_text()
    texts += [line.split("#")[0] for block in re.findall(r"```(?:yaml|python|bash)\n(.*?)```",
                                                         readme, flags=re.S)
              for line in block.splitlines()]
    return {float(m) for t in texts for m in re.findall(r"\d+(?:\.\d+)?(?:e[-+]?\d+)?", t)}


POOL = _pool()


def _value(token: str) -> float:
    token = token.replace(",", "")
    if "·10" in token:
        mantissa, exponent = token.split("·10")
        return float(mantissa) * 10.0 ** int(exponent.translate(SUPERSCRIPT))
    return float(token)


def _digits(token: str) -> int:
    """Significant digits as printed: '1.83e-6' -> 3, '0.0012' -> 2, '1.40000' -> 6."""
    mantissa = re.split(r"e|·10", token.replace(",", ""))[0]
    return max(len(mantissa.replace(".", "").lstrip("0")), 1)


def _same(value: float, token: str) -> bool:
    """``value`` printed to the precision of ``token`` reads as ``token``."""
    return math.isclose(float(f"{value:.{_digits(token)}g}"), _value(token), rel_tol=1e-12)


# ---------------------------------------------------------------- figures computed here
@functools.cache
def _roof() -> dict[str, float]:
    model = mechloop.load_model(EXAMPLES / "roof_support.yaml")
    dyn = mechloop.solve_dynamics(model)
    k = dyn.kinematics
    force = dyn.to_frame()["F_bal [N]"].to_numpy()
    least = int(np.argmin(force))
    ox, oy = k.point([1, 2])  # O2 from D; D is 0.15 m above the floor
    ex = ox - k.values["r12"] * np.cos(k.values["a12"])
    ey = oy - k.values["r12"] * np.sin(k.values["a12"]) + 0.15
    return {"F low MN": force[0] / 1e6, "F least MN": force[least] / 1e6,
            "leg at least": k.value("r7")[least], "F top MN": force[-1] / 1e6,
            "F low kN": force[0] / 1e3, "E low": ey[0], "E high": ey[-1],
            "band mm": np.ptp(ex) * 1e3, "rise": np.ptp(ey)}


@functools.cache
def _roof_real() -> dict[str, float]:
    """The real leg's force (examples/roof_support_real.yaml) at its lowest and top
    positions, and the simplification's at the same shield angles (interpolated)."""
    real = mechloop.solve_dynamics(mechloop.load_model(EXAMPLES / "roof_support_real.yaml"))
    simple = mechloop.solve_dynamics(mechloop.load_model(EXAMPLES / "roof_support.yaml"))
    fr = real.to_frame()["F_bal [N]"].to_numpy()
    fs = simple.to_frame()["F_bal [N]"].to_numpy()
    at = np.interp(real.kinematics.value("a8"), simple.kinematics.value("a8"), fs)
    return {"real low MN": fr[0] / 1e6, "real top MN": fr[-1] / 1e6,
            "simple at real low MN": at[0] / 1e6, "simple at real top MN": at[-1] / 1e6}


@functools.cache
def _swings() -> dict[str, float]:
    def solved(name):
        return mechloop.solve(mechloop.load_model(EXAMPLES / name))

    six = solved("six_bar.yaml")
    rocker = np.degrees(np.ptp(np.unwrap(six.value("a3"))))
    output = np.degrees(np.ptp(np.unwrap(six.value("a7"))))
    from mechloop.model.groups import build, mechanism_of

    built = build(mechanism_of(EXAMPLES / "six_bar_groups.yaml"))
    res = mechloop.solve(built.model)
    x, _ = built.points["E"].xy(res)
    bell = np.degrees(np.ptp(np.unwrap(res.value(_bell_crank_angle(built)))))
    leg = solved("hydraulic_rocker.yaml")
    return {"six rocker": rocker, "six output": output, "ram mm": np.ptp(x) * 1e3,
            "bell": bell, "leg swing": np.degrees(np.ptp(np.unwrap(leg.value("a1"))))}


def _bell_crank_angle(built) -> str:
    """The parameter carrying the bell crank C-B's direction in the generated model."""
    return str(built.dimensions["groups[0].lengths[1]"][0]).replace("r", "a", 1)


@functools.cache
def _published() -> dict[str, float]:
    from test_benchmark_problems import (
        PUBLISHED_DESIGNS,
        SIX,
        SIX_POINT_DESIGNS,
        papers_objective,
    )

    from mechloop.synthesis.problem import SynthesisProblem

    out = {f"five {k}": papers_objective(v) for k, v in PUBLISHED_DESIGNS.items()}
    problem = SynthesisProblem(mechloop.load_model(ROOT / SIX))
    for name, (r1, r2, r3, r4, rcx, rcy, x0, y0, theta0) in SIX_POINT_DESIGNS.items():
        values = {"r1": r2, "r2": r3, "r3": r4, "r4": r1,
                  "a4": np.degrees(theta0) % 360 + 180, "r6": np.hypot(rcx, rcy),
                  "a6": np.degrees(np.arctan2(rcy, rcx)), "start1.x": x0, "start1.y": y0}
        row = np.array([values[n] * (np.pi / 180 if n[0] == "a" else 1e-3)
                        for n in problem.variables.names])
        out[f"six {name}"] = float(problem.evaluate(row[None, :]).q[0])
    return out


@functools.cache
def _slider_crank() -> dict[str, float]:
    from scipy.optimize import minimize_scalar

    from mechloop.synthesis.classical import slider_crank_from_stroke

    start = slider_crank_from_stroke(200.0, 1.4, offset=100.0)

    def pressure(e: float) -> float:  # the largest pressure angle of the family's member, deg
        member = slider_crank_from_stroke(200.0, 1.4, offset=e)
        return float(np.degrees(np.arcsin((member.crank + e) / member.rod)))

    best = minimize_scalar(pressure, bounds=(1e-3, 200.0 / math.tan(math.radians(30.0))),
                           method="bounded", options={"xatol": 1e-10}).x
    member = slider_crank_from_stroke(200.0, 1.4, offset=best)
    return {"start crank": float(start.crank), "start rod": float(start.rod),
            "start far": abs(float(np.degrees(start.crank_angle_far))),
            "best e": best, "best crank": float(member.crank), "best rod": float(member.rod)}


def _sparse(position: int) -> Callable[[], float]:
    def value() -> float:
        res = mechloop.solve(mechloop.load_model(EXAMPLES / "sparse_argument.yaml"))
        return float(res.to_frame()["arg1 [m]"].iloc[position])
    return value


COMPUTED: dict[str, Callable[[], float]] = {
    **{key: (lambda key=key: _roof()[key]) for key in (
        "F low MN", "F least MN", "leg at least", "F top MN", "F low kN", "E low", "E high",
        "band mm", "rise")},
    **{key: (lambda key=key: _roof_real()[key]) for key in (
        "real low MN", "real top MN", "simple at real low MN", "simple at real top MN")},
    **{key: (lambda key=key: _swings()[key]) for key in (
        "six rocker", "six output", "ram mm", "bell", "leg swing")},
    **{key: (lambda key=key: _published()[key]) for key in (
        "five Cabrera", "five MUMSA", "five IOA", "five HCDJ", "six Cabrera", "six column 7",
        "six column 8")},
    **{key: (lambda key=key: _slider_crank()[key]) for key in (
        "start crank", "start rod", "start far", "best e", "best crank", "best rod")},
    "sparse 4": _sparse(4), "sparse 5": _sparse(5), "sparse 7": _sparse(7),
}

# ------------------------------------------------------------------------ the figures
# (document, pattern with the figure in group "fig", how): how is ("test", "file::name"),
# ("computed", key of COMPUTED) or ("bench", "benchmarks/x.py", machine-dependent?).
# The document is an example's file name, a page ("docs/synthesis.md") or R: the
# documentation, README.md or any page of docs/ (the README's reference moved there).
R = "README.md"
SCRIPTS = "tests/test_docs_and_cli.py::test_example_scripts_run"
SLIDER = "tests/test_classical_start.py::test_slider_crank_example_has_its_stroke_and_time_ratio"
BEATS = "tests/test_benchmark_problems.py::test_the_example_beats_every_published_design"
KHK = "tests/test_gears_pair.py::test_the_khk_worked_example_of_a_profile_shifted_pair"
TWO_ROW = "tests/test_gears_planetary.py::test_a_two_row_choice_meets_every_condition"
WOLFROM = "tests/test_gears_james_wolfrom.py::test_the_wolfrom_example_train"
FIGURES: list[tuple[str, str, tuple]] = [
    # energy example (the compressor)
    (R, r"efficiency \((?P<fig>28) %\)",
     ("test", "tests/test_readme_commands.py::test_energy_example_prints_a_meaningful_efficiency")),
    # indicator diagrams
    (R, r"diagram does (?P<fig>332\.5) J", ("test", "tests/test_indicator_load.py::"
     "test_the_indicator_examples_figures")),
    (R, r"positions read (?P<fig>331\.3) J", ("test", "tests/test_indicator_load.py::"
     "test_the_indicator_examples_figures")),
    (R, r"takes (?P<fig>147\.5) J a turn", ("test", "tests/test_indicator_load.py::"
     "test_the_indicator_examples_figures")),
    (R, r"volumetric efficiency\s+(?P<fig>0\.840)", ("test", "tests/test_indicator_load.py::"
     "test_the_indicator_examples_figures")),
    (R, r"steady state after (?P<fig>7\.77) s", ("test", "tests/test_engine_startup.py::"
     "test_the_starter_brings_the_engine_to_its_steady_state")),
    (R, r"at a\s+mean (?P<fig>1498) rpm", ("test", "tests/test_engine_startup.py::"
     "test_the_starter_brings_the_engine_to_its_steady_state")),
    # a coupled block's break between two positions
    (R, r"lost for about (?P<fig>1\.2)° of the", ("test", "tests/test_coupled_existence.py::"
     "test_a_triad_break_between_two_samples_is_found_where_the_oracle_loses_it")),
    # the real roof support against the simplification
    (R, r"(?P<fig>4\.30) MN at the lowest", ("computed", "real low MN")),
    (R, r"(?P<fig>3\.32) MN at the top", ("computed", "real top MN")),
    (R, r"needs (?P<fig>4\.54) MN", ("computed", "simple at real low MN")),
    (R, r"4\.54 MN and (?P<fig>3\.66) MN", ("computed", "simple at real top MN")),
    # motion in time: the compressor's start-up
    (R, r"after (?P<fig>2\.72) s", ("test", "tests/test_simulate.py::"
                                    "test_compressor_start_up_figures")),
    (R, r"2\.72 s \((?P<fig>14) turns", ("test", "tests/test_simulate.py::"
                                          "test_compressor_start_up_figures")),
    (R, r"mean (?P<fig>488\.1) rpm", ("test", "tests/test_simulate.py::"
                                      "test_compressor_start_up_figures")),
    (R, r"δ = (?P<fig>0\.0192)", ("test", "tests/test_simulate.py::"
                                  "test_compressor_start_up_figures")),
    (R, r"then\s(?P<fig>2799) J", ("test", "tests/test_simulate.py::"
                                   "test_compressor_start_up_figures")),
    (R, r"closes to (?P<fig>0\.02) J", ("test", "tests/test_simulate.py::"
                                        "test_compressor_start_up_figures")),
    # roof support table and text
    (R, r"41, exact \| (?P<fig>9\.4) mm \| 4658 kN", ("computed", "band mm")),
    (R, r"9\.4 mm \| (?P<fig>4658) kN", ("computed", "F low kN")),
    (R, r"\| 1 \| (?P<fig>17) found", ("bench", "benchmarks/bench_roof_support.py", False)),
    (R, r"(?P<fig>10\.5) mm \(E off", ("bench", "benchmarks/bench_roof_support.py", False)),
    (R, r"up to (?P<fig>3\.1) mm\)", ("bench", "benchmarks/bench_roof_support.py", False)),
    (R, r"(?P<fig>0\.5) ms in NumPy", ("bench", "benchmarks/bench_roof_support.py", True)),
    (R, r"(?P<fig>4096) \| 41", ("bench", "benchmarks/bench_roof_support.py", False)),
    (R, r"(?P<fig>13\.9) mm \| 4180", ("bench", "benchmarks/bench_roof_support.py", False)),
    (R, r"13\.9 mm \| (?P<fig>4180) kN", ("bench", "benchmarks/bench_roof_support.py", False)),
    (R, r"4180 kN \| (?P<fig>1\.3) s", ("bench", "benchmarks/bench_roof_support.py", True)),
    (R, r"(?P<fig>15625) \| 41", ("bench", "benchmarks/bench_roof_support.py", False)),
    (R, r"(?P<fig>11\.9) mm \| 3743", ("bench", "benchmarks/bench_roof_support.py", False)),
    (R, r"11\.9 mm \| (?P<fig>3743) kN", ("bench", "benchmarks/bench_roof_support.py", False)),
    (R, r"3743 kN \| (?P<fig>8\.9) s", ("bench", "benchmarks/bench_roof_support.py", True)),
    (R, r"\| (?P<fig>5948) \| 41", ("bench", "benchmarks/bench_roof_support.py", False)),
    (R, r"\*\*(?P<fig>3\.39) mm\*\*", ("bench", "benchmarks/bench_roof_support.py", False)),
    (R, r"4300 kN \| (?P<fig>8\.9) s", ("bench", "benchmarks/bench_roof_support.py", True)),
    (R, r"\((?P<fig>17) of the 41 positions", ("bench", "benchmarks/bench_roof_support.py",
                                               False)),
    (R, r"here, (?P<fig>8) for the synthesized", ("bench", "benchmarks/bench_roof_support.py",
                                                   False)),
    (R, r"synthesis took (?P<fig>20) s", ("bench", "benchmarks/bench_roof_support.py", True)),
    (R, r"5-level grid (?P<fig>17) s", ("bench", "benchmarks/bench_roof_support.py", True)),
    # classical starts
    (R, r"own Q \((?P<fig>0\.754)°", ("test", SCRIPTS)),
    (R, r"from it \(Q = (?P<fig>0\.598)°", ("test", SCRIPTS)),
    (R, r"without it \(Q = (?P<fig>0\.584)°", ("test", SCRIPTS)),
    # bench_synthesis_problems.py: published designs recomputed, mechloop's best (timed)
    (R, r"\| (?P<fig>4\.067e-12) \|", ("bench", "benchmarks/bench_synthesis_problems.py", False)),
    (R, r"\| (?P<fig>1\.376e-27) \|", ("bench", "benchmarks/bench_synthesis_problems.py", True)),
    (R, r"\| (?P<fig>1\.284e-06) \|", ("bench", "benchmarks/bench_synthesis_problems.py", False)),
    (R, r"\| (?P<fig>7\.416e-07) \|", ("bench", "benchmarks/bench_synthesis_problems.py", True)),
    (R, r"\| (?P<fig>1\.216) \|", ("bench", "benchmarks/bench_synthesis_problems.py", False)),
    (R, r"\| (?P<fig>1\.22) \|", ("bench", "benchmarks/bench_synthesis_problems.py", True)),
    (R, r"that turns \((?P<fig>1\.216)\)",
     ("bench", "benchmarks/bench_synthesis_problems.py", False)),
    (R, r"K = 1\.4 to (?P<fig>1e-5)", ("test", SLIDER)),
    (R, r"H = 200 mm to (?P<fig>1e-3) mm", ("test", SLIDER)),
    (R, r"within (?P<fig>0\.01)° of the best member", ("test", SLIDER)),
    (R, r"family \((?P<fig>57\.368)°", ("test", SLIDER)),
    # published benchmark problems
    (R, r"Cabrera GA (?P<fig>1\.83e-6)", ("computed", "five Cabrera")),
    (R, r"MUMSA (?P<fig>1\.28e-6)", ("computed", "five MUMSA")),
    (R, r"IOA (?P<fig>4\.27e-6)", ("computed", "five IOA")),
    (R, r"HCDJ (?P<fig>1\.92e-6)", ("computed", "five HCDJ")),
    (R, r"\*\*(?P<fig>7\.42e-7)\*\*", ("test", BEATS)),
    (R, r"Cabrera GA (?P<fig>0\.0258)", ("computed", "six Cabrera")),
    (R, r"uncertain\) (?P<fig>1\.5e-10)", ("computed", "six column 7")),
    (R, r"uncertain\) 1\.5e-10 and (?P<fig>3\.1e-11)", ("computed", "six column 8")),
    (R, r"score (?P<fig>1\.5e-10)", ("computed", "six column 7")),
    (R, r"score 1\.5e-10 and (?P<fig>3\.1e-11)", ("computed", "six column 8")),
    (R, r"\| (?P<fig>1\.42e-7) \(CMA-ES", ("bench", "benchmarks/bench_synthesis_examples.py",
                                         True)),
    # performance
    (R, r"speedup vs pylinkage: (?P<fig>3\.6)", ("bench", "benchmarks/bench_fourbar.py", True)),
    (R, r"\((?P<fig>3\.5) to 3\.6 over", ("bench", "benchmarks/bench_fourbar.py", True)),
    (R, r"3\.5 to (?P<fig>3\.6) over", ("bench", "benchmarks/bench_fourbar.py", True)),
    (R, r"elsewhere (?P<fig>3\.0)", ("bench", "benchmarks/bench_fourbar.py", True)),
    (R, r"coupled vs closed form: (?P<fig>7\.4)", ("bench", "benchmarks/bench_coupled.py",
                                                  True)),
    (R, r"\((?P<fig>6\.5) to 8\.3 over", ("bench", "benchmarks/bench_coupled.py", True)),
    (R, r"6\.5 to (?P<fig>8\.3) over", ("bench", "benchmarks/bench_coupled.py", True)),
    (R, r"the triad (?P<fig>381) to", ("bench", "benchmarks/bench_coupled.py", True)),
    (R, r"381 to (?P<fig>436) ms", ("bench", "benchmarks/bench_coupled.py", True)),
    (R, r"(?P<fig>9\.5) to\s10\.4 times", ("bench", "benchmarks/bench_coupled.py", True)),
    (R, r"9\.5 to\s(?P<fig>10\.4) times", ("bench", "benchmarks/bench_coupled.py", True)),
    (R, r"printed (?P<fig>12\.7)–17\.3", ("bench", "benchmarks/bench_synthesis.py", True)),
    (R, r"12\.7–(?P<fig>17\.3)", ("bench", "benchmarks/bench_synthesis.py", True)),
    (R, r"mechloop\s(?P<fig>122,700)–", ("bench", "benchmarks/bench_synthesis.py", True)),
    (R, r"122,700–(?P<fig>196,800) designs/s", ("bench", "benchmarks/bench_synthesis.py", True)),
    (R, r"printed\s(?P<fig>112,600)–", ("bench", "benchmarks/bench_synthesis.py", True)),
    (R, r"112,600–(?P<fig>147,400)", ("bench", "benchmarks/bench_synthesis.py", True)),
    (R, r"printed (?P<fig>243,800)–", ("bench", "benchmarks/bench_synthesis.py", True)),
    (R, r"243,800–(?P<fig>317,800) designs/s", ("bench", "benchmarks/bench_synthesis.py", True)),
    (R, r"against (?P<fig>153,000)–", ("bench", "benchmarks/bench_synthesis.py", True)),
    (R, r"153,000–(?P<fig>196,900) on one", ("bench", "benchmarks/bench_synthesis.py", True)),
    (R, r"speedup (?P<fig>34\.2)–", ("bench", "benchmarks/bench_synthesis.py", True)),
    (R, r"speedup 34\.2–(?P<fig>34\.7)", ("bench", "benchmarks/bench_synthesis.py", True)),
    (R, r"it printed (?P<fig>0\.26) s", ("bench", "benchmarks/bench_startup.py", True)),
    (R, r"load average (?P<fig>0\.6)\sand", ("bench", "benchmarks/bench_output.py", True)),
    (R, r"0\.6\sand\s(?P<fig>1\.2), two", ("bench", "benchmarks/bench_output.py", True)),
    (R, r"CSV (?P<fig>553) and", ("bench", "benchmarks/bench_output.py", True)),
    (R, r"553 and\s(?P<fig>510) MB/s", ("bench", "benchmarks/bench_output.py", True)),
    (R, r"disk's\s(?P<fig>608)\sand", ("bench", "benchmarks/bench_output.py", True)),
    (R, r"608\sand\s(?P<fig>534)", ("bench", "benchmarks/bench_output.py", True)),
    (R, r"ratios\s(?P<fig>0\.91) and", ("bench", "benchmarks/bench_output.py", True)),
    (R, r"0\.91 and\s(?P<fig>0\.96)\)", ("bench", "benchmarks/bench_output.py", True)),
    (R, r"JSON\s(?P<fig>675) and", ("bench", "benchmarks/bench_output.py", True)),
    (R, r"675 and\s(?P<fig>658) MB/s", ("bench", "benchmarks/bench_output.py", True)),
    (R, r"against\s(?P<fig>641) and", ("bench", "benchmarks/bench_output.py", True)),
    (R, r"641 and\s(?P<fig>605)", ("bench", "benchmarks/bench_output.py", True)),
    (R, r"\((?P<fig>1\.05) and\s1\.09", ("bench", "benchmarks/bench_output.py", True)),
    (R, r"1\.05 and\s(?P<fig>1\.09)\)", ("bench", "benchmarks/bench_output.py", True)),
    (R, r"Parquet\s(?P<fig>1172) and", ("bench", "benchmarks/bench_output.py", True)),
    (R, r"1172 and\s(?P<fig>1069) MB/s", ("bench", "benchmarks/bench_output.py", True)),
    (R, r"against\s(?P<fig>1189) and", ("bench", "benchmarks/bench_output.py", True)),
    (R, r"1189 and\s(?P<fig>1561)", ("bench", "benchmarks/bench_output.py", True)),
    (R, r"\((?P<fig>0\.99) and\s0\.69", ("bench", "benchmarks/bench_output.py", True)),
    (R, r"0\.99 and\s(?P<fig>0\.69)\)", ("bench", "benchmarks/bench_output.py", True)),
    (R, r"at\s(?P<fig>296)/277", ("bench", "benchmarks/bench_output.py", True)),
    (R, r"296/(?P<fig>277),", ("bench", "benchmarks/bench_output.py", True)),
    (R, r"(?P<fig>394)/379", ("bench", "benchmarks/bench_output.py", True)),
    (R, r"394/(?P<fig>379) and", ("bench", "benchmarks/bench_output.py", True)),
    (R, r"and\s(?P<fig>1186)/1134", ("bench", "benchmarks/bench_output.py", True)),
    (R, r"1186/(?P<fig>1134) MB", ("bench", "benchmarks/bench_output.py", True)),
    (R, r"with\s(?P<fig>72), 73", ("bench", "benchmarks/bench_output.py", True)),
    (R, r"72,\s(?P<fig>73) and 34", ("bench", "benchmarks/bench_output.py", True)),
    (R, r"73 and\s(?P<fig>34) MB\sabove", ("bench", "benchmarks/bench_output.py", True)),
    (R, r"load average (?P<fig>1\.4)–1\.7", ("bench", "benchmarks/bench_output.py", True)),
    (R, r"load average 1\.4–(?P<fig>1\.7)", ("bench", "benchmarks/bench_output.py", True)),
    (R, r"printed\s(?P<fig>1201), 1061", ("bench", "benchmarks/bench_output.py", True)),
    (R, r"1201, (?P<fig>1061) and", ("bench", "benchmarks/bench_output.py", True)),
    (R, r"1061 and (?P<fig>1195) MB/s", ("bench", "benchmarks/bench_output.py", True)),
    (R, r"disk's (?P<fig>1587), 1116", ("bench", "benchmarks/bench_output.py", True)),
    (R, r"1587, (?P<fig>1116) and", ("bench", "benchmarks/bench_output.py", True)),
    (R, r"1116 and (?P<fig>1226) \(", ("bench", "benchmarks/bench_output.py", True)),
    (R, r"ratios (?P<fig>0\.76), 0\.95", ("bench", "benchmarks/bench_output.py", True)),
    (R, r"0\.76, (?P<fig>0\.95)\sand", ("bench", "benchmarks/bench_output.py", True)),
    (R, r"0\.95\sand (?P<fig>0\.97)\)", ("bench", "benchmarks/bench_output.py", True)),
    (R, r"`--contours (?P<fig>50)` \(458", ("bench", "benchmarks/bench_output.py", True)),
    (R, r"\((?P<fig>458) columns", ("bench", "benchmarks/bench_output.py", True)),
    (R, r"columns, (?P<fig>3\.5) GB", ("bench", "benchmarks/bench_output.py", True)),
    (R, r"GB\) (?P<fig>1506) MB/s", ("bench", "benchmarks/bench_output.py", True)),
    (R, r"1506 MB/s against (?P<fig>877)", ("bench", "benchmarks/bench_output.py", True)),
    (R, r"877 \((?P<fig>1\.72)\)", ("bench", "benchmarks/bench_output.py", True)),
    (R, r"printed CSV (?P<fig>0\.38), JSON", ("bench", "benchmarks/bench_output.py", True)),
    (R, r"JSON (?P<fig>0\.35) and Parquet", ("bench", "benchmarks/bench_output.py", True)),
    (R, r"Parquet (?P<fig>0\.41) of the", ("bench", "benchmarks/bench_output.py", True)),
    # example headers
    ("roof_support.yaml", r"E from (?P<fig>1\.434) m", ("computed", "E low")),
    ("roof_support.yaml", r"to (?P<fig>2\.557) m", ("computed", "E high")),
    ("roof_support.yaml", r"wanders (?P<fig>9\.4) mm", ("computed", "band mm")),
    ("roof_support.yaml", r"F_bal = (?P<fig>4\.66) MN", ("computed", "F low MN")),
    ("roof_support.yaml", r"(?P<fig>3\.55) MN at its least", ("computed", "F least MN")),
    ("roof_support.yaml", r"\(leg (?P<fig>1\.45) m\)", ("computed", "leg at least")),
    ("roof_support.yaml", r"(?P<fig>3\.72) MN at the top", ("computed", "F top MN")),
    ("roof_support_synthesis.yaml", r"design has (?P<fig>1\.12) m", ("computed", "rise")),
    ("roof_support_synthesis.yaml", r"needs (?P<fig>4658) kN", ("computed", "F low kN")),
    ("roof_support_synthesis.yaml", r"(?P<fig>5948) designs",
     ("bench", "benchmarks/bench_roof_support.py", False)),
    *[("roof_support_synthesis.yaml", p, ("bench", "benchmarks/bench_roof_support.py", False))
      for p in (r"Q = (?P<fig>1\.69) mm", r"within a (?P<fig>3\.39) mm", r"rises (?P<fig>1\.128)",
                r"r9 = (?P<fig>0\.915)", r"\((?P<fig>1\.763), 0\.608\)",
                r"1\.763, (?P<fig>0\.608)\)", r"\((?P<fig>0\.166), 0\.157\)",
                r"0\.166, (?P<fig>0\.157)\)")],
    ("roof_support_synthesis.yaml", r"starting design: (?P<fig>9\.4) mm", ("computed", "band mm")),
    *[("four_bar_shape_synthesis.yaml", p, ("test", "tests/test_synthesis_formulations.py::"
       "test_the_shape_example_places_the_known_design_on_its_circuit"))
      for p in (r"turned by (?P<fig>130) deg", r"scaled by (?P<fig>0\.4) and")],
    ("six_points_free_timing_synthesis.yaml", r"below (?P<fig>2e-11)",
     ("test", "tests/test_free_timing.py::test_published_designs_score_as_in_the_papers")),
    ("slider_crank_stroke_synthesis.yaml", r"crank (?P<fig>85\.5600)", ("computed", "start crank")),
    ("slider_crank_stroke_synthesis.yaml", r"rod (?P<fig>217\.5328)", ("computed", "start rod")),
    ("slider_crank_stroke_synthesis.yaml", r"angle (?P<fig>19\.2646)°", ("computed", "start far")),
    ("slider_crank_stroke_synthesis.yaml", r"20° − (?P<fig>19\.2646)°", ("computed", "start far")),
    ("slider_crank_stroke_synthesis.yaml", r"Q below (?P<fig>1e-4)°",
     ("test", SLIDER)),
    ("slider_crank_stroke_synthesis.yaml", r"200 mm to (?P<fig>1e-3) mm",
     ("test", SLIDER)),
    ("slider_crank_stroke_synthesis.yaml", r"K = 1\.4 to (?P<fig>1e-5)",
     ("test", SLIDER)),
    ("slider_crank_stroke_synthesis.yaml", r"offset to (?P<fig>1e-3) mm",
     ("test", SLIDER)),
    ("slider_crank_stroke_synthesis.yaml", r"within (?P<fig>0\.01)° of the family",
     ("test", SLIDER)),
    ("slider_crank_stroke_synthesis.yaml", r"smallest, (?P<fig>57\.368)°",
     ("test", SLIDER)),
    ("slider_crank_stroke_synthesis.yaml", r"e = (?P<fig>64\.199)", ("computed", "best e")),
    ("slider_crank_stroke_synthesis.yaml", r"crank (?P<fig>90\.993)", ("computed", "best crank")),
    ("slider_crank_stroke_synthesis.yaml", r"rod (?P<fig>184\.280)", ("computed", "best rod")),
    ("slider_crank_stroke_synthesis.yaml", r"within (?P<fig>0\.01)° of that",
     ("test", SLIDER)),
    ("six_bar.yaml", r"(?P<fig>47) deg swing of the first", ("computed", "six rocker")),
    ("six_bar.yaml", r"a (?P<fig>62) deg swing", ("computed", "six output")),
    ("six_bar_groups.yaml", r"the (?P<fig>47) deg swing of the bell", ("computed", "bell")),
    ("six_bar_groups.yaml", r"a (?P<fig>155) mm stroke", ("computed", "ram mm")),
    ("hydraulic_rocker.yaml", r"about (?P<fig>81) deg", ("computed", "leg swing")),
    ("four_bar_break_ahead.yaml", r"θ = (?P<fig>150\.266) deg",
     ("test", "tests/test_simulate_breaks.py::test_the_example_runs_up_to_the_break")),
    ("four_bar_break_ahead.yaml", r"positions (?P<fig>31) to 41",
     ("test", "tests/test_simulate_breaks.py::test_the_example_runs_up_to_the_break")),
    ("four_bar_break_ahead.yaml", r"positions 31 to (?P<fig>41)",
     ("test", "tests/test_simulate_breaks.py::test_the_example_runs_up_to_the_break")),
    ("sparse_argument.yaml", r"(?P<fig>0\.1667) 0\.2133", ("computed", "sparse 4")),
    ("sparse_argument.yaml", r"0\.1667 (?P<fig>0\.2133)", ("computed", "sparse 5")),
    ("sparse_argument.yaml", r"0\.26 (?P<fig>0\.24) 0\.22", ("computed", "sparse 7")),
    ("20_solar_panel_doors.yaml", r"to (?P<fig>119) deg open",
     ("test", "tests/test_course_models.py::test_course_headers_12_to_20_state_what_they_do")),
    ("sparse_argument.yaml", r"at (?P<fig>81\.6) deg",
     ("test", "tests/test_examples.py::test_sparse_argument_positions_by_law_of_cosines")),
    ("sparse_argument.yaml", r"to (?P<fig>120\.4) deg",
     ("test", "tests/test_examples.py::test_sparse_argument_positions_by_law_of_cosines")),
    # gears: the KHK worked example and the two-row choice
    (R, r"`a = (?P<fig>56\.4999)`", ("test", KHK)),
    (R, r"`α_w = (?P<fig>26\.0886)°`", ("test", KHK)),
    (R, r"`ε_α = (?P<fig>1\.202)`", ("test", KHK)),
    (R, r"`z = (?P<fig>18)/54/27/99`", ("test", TWO_ROW)),
    (R, r"`z = 18/(?P<fig>54)/27/99`", ("test", TWO_ROW)),
    (R, r"`z = 18/54/(?P<fig>27)/99`", ("test", TWO_ROW)),
    (R, r"`z = 18/54/27/(?P<fig>99)`", ("test", TWO_ROW)),
    # gears: the Wolfrom example (examples/gears/wolfrom.yaml and the README)
    ("wolfrom.yaml", r"i_ae = (?P<fig>5\.2)/", ("test", WOLFROM)),
    ("wolfrom.yaml", r"5\.2/\((?P<fig>117)/", ("test", WOLFROM)),
    ("wolfrom.yaml", r"/3 = (?P<fig>26),", ("test", WOLFROM)),
    ("wolfrom.yaml", r"/\(3·3\) = (?P<fig>13)\)", ("test", WOLFROM)),
    (R, r"`i_ae = (?P<fig>64)`", ("test", WOLFROM)),
    (R, r"`i_bh = (?P<fig>1\.25)`", ("test", "tests/test_gears_james_wolfrom.py::"
                                      "test_the_james_train_textbook_ratios")),
    (R, r"`a = (?P<fig>56\.8)` mm", ("test", "tests/test_gears_published.py::"
                                     "test_the_sun_planet_pair_from_its_printed_shifts")),
    (R, r"the planar results to (?P<fig>1e-12)", ("test", "tests/test_spatial_models.py::"
     "test_planar_four_bar_written_as_spatial_gives_the_planar_results")),
    (R, r"planar coupled results to (?P<fig>1e-10)", ("test", "tests/test_spatial_coupled.py::"
     "test_planar_triad_written_as_spatial_gives_the_planar_coupled_results")),
    (R, r"Newton–Euler equations hold to (?P<fig>1e-9)", ("test", "tests/"
     "test_spatial_reactions.py::test_the_rssr_example_balances_every_body_with_its_reactions")),
    (R, r"give the planar reactions to (?P<fig>1e-9)", ("test", "tests/"
     "test_spatial_reactions.py::test_a_planar_four_bar_written_as_spatial_gives_the_planar_"
     "reactions")),
]
# the peak coefficients of the cam laws (README's cam section: law | C_v | C_a | C_j)
_CELL = r"[^|]*\|"  # one cell of a table row
FIGURES += [(R, f"`{law}` \\|" + _CELL * column + r" (?P<fig>[\d.]+) \|",
             ("test", "tests/test_cam_design.py::test_peak_coefficients_match_the_textbook"))
            for law in ("harmonic", "cycloidal", "poly345", "poly4567", "modified_trapezoidal",
                        "modified_sine") for column in range(3)]

COURSE_DIAGRAM = "the assumed indicator diagram behind the gas-force tables (checked in " \
    "tests/test_course_models_loads.py)"
# (document or None for any, pattern, why it is not a result)
INPUTS: list[tuple[str | None, str, str]] = [
    (None, r"ISO 21771|ISO 53|DIN 3960|GOST 16532-70|GOST 2\.105|"
           r"KHK Gear Technical Reference \(sec\. 4\.3", "a cited standard or reference"),
    ("planetary_choice.yaml", r"within 1 %", "the example's search.tolerance (0.01)"),
    (R, r"z 21/43 with\s+shifts 0\.4380/0\.0426", "the printed inputs of the Kos example "
        "(tests/test_gears_published.py)"),
    (None, r"(seed|Seed) 00[012](,? (App\. A [\d.]+|sec\. [\d.]+( item \d+)?|Fig\. [\d.]+"
           r"|part \d|table [\d.]+))*", "a section of the course's seed documents"),
    (None, r"sec\. 1\.2\.2|eq\. 1\.1|table 3\.2", "a section of a cited document"),
    (R, r"no ±180° jumps|\(−180°, 180°\], so a transmission", "the range the plots place an "
        "angle difference in (a convention of views.curves.continuous_angle)"),
    (R, r"seed 000 sec\. 2\.3–2\.6", "the seed's sections on cams"),
    (None, r"(Theory|Symmetry) \d+(,? \(?(19|20)\d\d\)?)( \d+)?|(19|20)\d\d", "a citation"),
    (R, r"\d+ positions per design", "the benchmark's setting"),
    (R, r"position, over 16\)", "the error ratio of a fourth-order spline at half the step"),
    (R, r"`rtol` \(default 1e-8\), `atol` \(1e-9,", "simulate:'s default tolerances"),
    (R, r"to 1e-11 of the mean speed", "a rule of the code (its constant, "
        "mechloop.dynamics.machine.SETTLE_RTOL)"),
    (R, r"2,000 random designs|relative 1e-9[);]", "the synthesis benchmark's settings"),
    (R, r"evaluates 2,000 designs|`--designs 20000`", "the synthesis benchmark's settings"),
    (R, r"from 65,536 designs × positions", "a rule of the code (its constant, "
        "mechloop.synthesis.cores.PARALLEL_ELEMENTS)"),
    (R, r"1,000,000 rows × 202 columns \(200\s+of them floats", "bench_output.py's table "
        "at --contours 22 --positions 1000000 (position, time, argument 1, 9 per four-bar, "
        "chain_break)"),
    (R, r"(at least|more than about) \d+ (ms|s)\b", "a rule of the code (its constant)"),
    (R, r"port 8786", "dask's default port"),
    (R, r"Jacobian columns\) falls to 1e-6", "a rule of the code (its constant, "
        "mechloop.dynamics.simulate_inputs.NEAR_BREAK)"),
    (R, r"a spring\) over 2 s", "the run's duration in tests/test_simulate_inputs.py::"
        "test_a_conservative_five_bar_keeps_its_energy_for_many_seconds"),
    (R, r"2\.5243549e-29|1\.9239227e-06|1\.2162122e\+00|best design\s+\(1\.2162122\)",
     "the source's recorded best (Records_HCDJ_Case*.txt, quoted in benchmarks/README.md)"),
    (R, r"<= (1e-10|7\.5e-07|1\.21621)\)", "the success bars: issue 11's acceptance "
        "thresholds and the source's record"),
    (R, r"budgets are 60 s, 30 s and 30 s", "the benchmark's settings (Case.budget)"),
    (R, r"within 5 s a command", "the fuzz harness's default limit: MECHLOOP_FUZZ_TIME in "
        "tests/fuzz/harness.py"),
    (R, r"at most 64 MiB|at most 64 levels|longer than 10,000 characters|"
        r"at most 1,000,000 items|at most 1e12 in size|below 1e-100",
     "the loading limits, constants of the code (test_readme_states_the_loading_limits)"),
    (R, r"0666 less the umask|1,048,575 rows|16,384 columns",
     "the POSIX default file mode and Excel's sheet limits (constants of mechloop.output)"),
    (R, r"blocks \(8192", "the block size in mechloop.solve"),
    (R, r"pages of 256 KiB", "the page size of mechloop.output.parquet "
        "(PARQUET_PAGE_BYTES)"),
    (R, r"100,001\s+positions|within 1e-12 of their size", "bench_coupled.py's settings "
        "(--n 100000) and its check"),
    (R, r"\d+ unknowns, \d+ equations", "counts of the source's formulation"),
    (R, r"41, exact|of the 41 positions", "the example's positions 0..40"),
    (R, r"\d+ × \d+ lever angles at \d°, kept where 0\.72 ≤ L² ≤ 0\.73 m²|"
        r"\d+ levels × \d+ dimensions|8100 pairs", "the seed's tabulation and the grids"),
    (R, r"\d+ generations", "a search setting of the example"),
    (R, r"10⁶|1st|2nd", "an order of magnitude or an ordinal"),
    (R, r"\d+°\)|over 720°|in \[0°, 360°\)|at \d+°|over 60°", "an angle of a definition"),
    (R, r"K = 1\.4", "the task's time ratio"),
    ("crank_slider_friction.yaml", r"pins of 15 mm", "the friction radius, 0.015 m"),
    ("roof_support.yaml", r"leg 1\.30 m", "where the drawing is"),
    (R, r"0\.40 m from B", "the real leg's pin, examples/roof_support_real.yaml"),
    ("roof_support_real.yaml", r"0\.725\)", "O2's height: 0.15 + 0.575 m, the base vectors"),
    ("roof_support.yaml", r"0\.725\)", "O2's height: 0.15 + 0.575 m, the base vectors"),
    (None, r"0\.72 ?(<=|\.\.)( L\^2 <=)? ?0\.73 m\^2(, and 0\.85\^2 = 0\.7225)?",
     "the seed's tabulation window"),
    (None, r"8100 combinations|41 positions", "the seed's grid; the example's positions"),
    ("hydraulic_rocker.yaml", r"law in 4 s", "the argument's law ends at 4 s"),
    ("single_cylinder_engine.yaml", r"0\.09 MPa|n = 1\.35|5\.5 MPa at 370 deg|n = 1\.25|"
     r"0\.11 MPa from 540 deg", "the assumed indicator diagram behind the gas-force table"),
    ("compressor_indicator.yaml", r"clearance 5 %", "the input clearance: 0.05"),
    ("engine_startup.yaml", r"released at 1\.5 s", "the starter's input off_at: 1.5"),
    ("slider_crank_stroke_synthesis.yaml", r"\(200, 1\.4,|K = 1\.4|\b230°", "the task"),
    ("sparse_argument.yaml", r"0\.24 0\.22", "given values of the table"),
    ("four_bar_break_ahead.yaml", r"390 mm", "coupler + rocker, 140 + 250 mm"),
    ("eighteen_points_timing_synthesis.yaml", r"i = 1 \.\.\. 18", "the source's targets"),
    ("README.md", r"^\| (1[3-9]|20) \| ", "a course task's number (seed 000 sec. 3)"),
    (None, r"task No\. \d+ ", "a course task's number (seed 000 sec. 3)"),
    (R, r"tasks 5, 12, 13 and 16–19", "course task numbers (seed 000 sec. 3)"),
    # the course models of examples/course/: the drawing's points (the frame vectors are
    # computed from them), the time the argument's law takes, assumed air loads
    (None, r"\b[A-Z]\d? \(-?\d+, ?-?\d+\)", "a point of a course model's drawing, mm"),
    (None, r"in \d+ s \(3-4-5 polynomial law", "the time of the argument's law (its end "
     "position over the model's time table)"),
    (None, r"\d+(\.\d+)? kPa on \d+ m × 0\.8 m", "an assumed wind pressure on an area"),
    # the course models of examples/course/ (tasks 5, 12-20 of seed 000 sec. 3)
    (None, r"n = 1\.3\b", COURSE_DIAGRAM),
    ("12_v_engine_articulated.yaml", r"bore 148 mm|6\.5 MPa at 370 deg|n = 1\.27|"
     r"0\.11 MPa from 540 deg|(at|fires) 420 deg", COURSE_DIAGRAM),
    ("13_v_engine_fork_and_blade.yaml", r"bore 84 mm|0\.09 MPa|n = 1\.25|0\.11 MPa from 540 deg",
     COURSE_DIAGRAM),
    ("18_two_stage_compressor.yaml", r"0\.33( MPa)?", COURSE_DIAGRAM),
    ("17_oil_pump.yaml", r"area 706\.86 mm²", "the plunger's area, pi (30 mm)^2 / 4"),
    (None, r"law in 2 s|law in 20 s", "the argument's law ends at that time"),
    ("20_solar_panel_doors.yaml", r"turned 115 deg", "the lug's angle to its door, the "
     "delta of a9 (-65 deg) less 180 deg"),
]


# ------------------------------------------------------------------------------ checks
def _in_code(paragraph: str, start: int) -> bool:
    return paragraph[:start].count("`") % 2 == 1


def _applies(entry: tuple, document: str) -> bool:
    """An entry of FIGURES or INPUTS holds in ``document`` (R: in every page)."""
    return entry[0] is None or entry[0] == document or (entry[0] == R and document in PAGES)


def _entries(document: str, table: list) -> list:
    return [e for e in table if _applies(e, document)]


def _spans(document: str, paragraph: str) -> tuple[list, list]:
    figures = [(m.span("fig"), entry) for entry in _entries(document, FIGURES)
               for m in re.finditer(entry[1], paragraph)]
    inputs = [m.span() for entry in _entries(document, INPUTS)
              for m in re.finditer(entry[1], paragraph)]
    return figures, inputs


def test_every_number_is_accounted_for():
    unaccounted = []
    for document, _, paragraph in PARAGRAPHS:
        figures, inputs = _spans(document, paragraph)
        for m in NUMBER.finditer(paragraph):
            a, b = m.span(1)
            if any(fa <= a and b <= fb for (fa, fb), _ in figures):
                continue
            if _in_code(paragraph, a) or any(ia <= a and b <= ib for ia, ib in inputs):
                continue
            token, value = m.group(1), _value(m.group(1))
            timey = TIMEY.match(paragraph, b)
            if not timey and ((value == int(value) and value <= 12) or value in POOL):
                continue
            unaccounted.append(f"{document}: {token!r} in …{paragraph[max(0, a - 50):b + 20]}…")
    assert not unaccounted, "numbers nobody checks (add to FIGURES or INPUTS):\n" + \
        "\n".join(unaccounted)


def test_no_entry_is_stale():
    for table in (FIGURES, INPUTS):
        for entry in table:
            assert any(re.search(entry[1], p) for d, _, p in PARAGRAPHS
                       if _applies(entry, d)), f"matches nothing: {entry[:2]}"


def _found_figures() -> list[tuple[str, str, str, tuple]]:
    out = []
    for document, section, paragraph in PARAGRAPHS:
        for entry in _entries(document, FIGURES):
            for m in re.finditer(entry[1], paragraph):
                out.append((document, section, m.group("fig"), entry[2]))
    return out


FOUND = _found_figures()


def _numbers_in_source(source: str) -> list[float]:
    numbers = []
    for node in ast.walk(ast.parse(source)):
        if isinstance(node, ast.Constant) and isinstance(node.value, int | float):
            numbers.append(float(node.value))
        elif isinstance(node, ast.Constant) and isinstance(node.value, str):
            numbers += [float(t) for t in re.findall(r"\d+\.\d+|\d+e-\d+", node.value)]
    return numbers


@pytest.mark.parametrize(("document", "section", "figure", "how"),
                         [f for f in FOUND if f[3][0] == "test"],
                         ids=lambda v: v if isinstance(v, str) and len(v) < 20 else "")
def test_figure_is_pinned_by_its_test(document, section, figure, how):
    path, name = how[1].split("::")
    tree = ast.parse((ROOT / path).read_text(encoding="utf-8"))
    func = next((n for n in ast.walk(tree) if isinstance(n, ast.FunctionDef)
                 and n.name == name), None)
    assert func is not None, f"{how[1]} does not exist"
    used = {n.id for n in ast.walk(func) if isinstance(n, ast.Name)}
    constants = [node for node in tree.body if isinstance(node, ast.Assign | ast.AnnAssign)
                 and any(isinstance(t, ast.Name) and t.id in used for t in (
                     node.targets if isinstance(node, ast.Assign) else [node.target]))]
    source = "\n".join(ast.unparse(n) for n in [func, *constants])  # with its module's tables
    assert any(_same(v, figure) for v in _numbers_in_source(source)), (
        f"{how[1]} does not pin {figure}")


@pytest.mark.parametrize(("document", "section", "figure", "how"),
                         [f for f in FOUND if f[3][0] == "computed"],
                         ids=lambda v: v if isinstance(v, str) and len(v) < 20 else "")
def test_figure_is_what_the_model_gives(document, section, figure, how):
    value = COMPUTED[how[1]]()
    assert _same(value, figure), f"{document}: {figure} is {value:.6g} ({how[1]})"


@pytest.mark.parametrize(("document", "section", "figure", "how"),
                         [f for f in FOUND if f[3][0] == "bench"],
                         ids=lambda v: v if isinstance(v, str) and len(v) < 20 else "")
def test_figure_is_printed_by_a_named_benchmark(document, section, figure, how):
    script = ROOT / how[1]
    assert script.exists()
    assert "print(" in script.read_text(encoding="utf-8")
    assert script.name in section, f"{document} does not name {script.name} with {figure}"
    if how[2]:
        assert "machine" in section, f"{document}: {figure} is machine-dependent; say so"
