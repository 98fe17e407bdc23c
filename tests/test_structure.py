"""Structural analysis (seed 002, part 1): Chebyshev's mobility, Assur groups, the
structure formula and the identification table, each checked against a hand analysis.

Hand analysis (W = 3n − 2p5 − p4, p4 = 0):

* slider-crank: crank 1, rod 2, slider 3; pairs O, A, B (R) and the slide S (P):
  W = 3·3 − 2·4 = 1; L0(1) → L2(2,3), the slider being ``i`` (external P on the ground);
* four-bar: W = 3·3 − 2·4 = 1; L0(1) → L1(2,3);
* Watt six-bar (examples/six_bar.yaml): crank 1, coupler 2, bell crank 3, link 4,
  rocker 5, seven pins: W = 3·5 − 2·7 = 1; L0(1) → L1(2,3) → L1(4,5), the second dyad on
  the bell crank 3;
* V-twin: crank 1, rods 2 and 4, pistons 3 and 5, five pins and two slides:
  W = 3·5 − 2·7 = 1; L0(1) → L2(2,3) → L2(4,5), both dyads on the crank;
* the mechanism of the seed's fig. 1.25 (11 links, 16 lower pairs, W = 1): its groups and
  the link columns of its table 1.6;
* a triad (a base link hinged to three binary links) is one class-III group; a closed
  four-link contour with two external pairs is class IV;
* W ≠ inputs: a five-bar with one crank (an input missing), a double parallelogram (a
  passive link), a four-bar with two drives (a redundant input), a link hanging on one pin.
"""

from __future__ import annotations

import doctest
import importlib

import pytest
from oracles.dynamic_models import example, landing_gear, quick_return

import mechloop
from mechloop.dynamics.mechanism import BodyFrame, Drive, Mechanism, Pair
from mechloop.model.dynamic import TailPoint
from mechloop.structure import (
    Decomposition,
    analyze,
    decompose,
    identification_table,
    mobility,
)

SIX_BAR_BODIES = {1: {"name": "crank", "vectors": [1]}, 2: {"name": "coupler", "vectors": [2]},
                  3: {"name": "bell crank", "vectors": [3, 5]},
                  4: {"name": "link", "vectors": [6]}, 5: {"name": "rocker", "vectors": [7]}}
V_TWIN_BODIES = {1: {"vectors": [1, 4]}, 2: {"vectors": [2]}, 3: {"vectors": [3]},
                 4: {"vectors": [5]}, 5: {"vectors": [6]}}


# --- mechanisms built directly from the dataclasses ---------------------------------------

def pin(a: int, b: int) -> Pair:
    return Pair(f"J{a}_{b}", "revolute", (a, b), TailPoint(tail=1), None, 0.0, 0.0, 0.0,
                False)


def slide(a: int, b: int, along: int | None = None) -> Pair:
    return Pair(f"S{a}_{b}", "prismatic", (a, b), TailPoint(tail=1), along, 0.0, 0.0, 0.0,
                False)


def crank(body: int = 1, argument: int = 1) -> Drive:
    return Drive(argument, "angle", body, (0, body))


def mechanism(*pairs: Pair, drives: tuple[Drive, ...] = (crank(),),
              bodies: dict[int, tuple[int, ...]] | None = None) -> Mechanism:
    frames = {k: BodyFrame(k, f"link {k}", vs, vs[0], ()) for k, vs in (bodies or {}).items()}
    return Mechanism(frames, (), pairs, drives, 0.0)


def solved(data: dict) -> tuple[mechloop.structure.Mobility, Decomposition]:
    return analyze(mechloop.Model.from_dict(data))


# --- the bundled examples -------------------------------------------------------------------

@pytest.mark.parametrize("joints", ["named", "inferred"])
def test_slider_crank_is_a_crank_and_an_rrp_dyad(joints):
    data = example("crank_slider_dynamics.yaml")
    if joints == "inferred":
        data.pop("joints")
    mob, dec = solved(data)
    assert (mob.n, mob.p5, mob.p4, mob.W, mob.inputs) == (3, 4, 0, 1, 1)
    assert mob.ok and mob.explanation == "W = 1 equals the number of inputs."
    assert dec.formula == "L0(1) → L2(2,3)"
    assert dec.mechanism_class == 2
    l0, rrp = dec.groups
    assert (l0.kind, l0.assur_class, l0.links, l0.drives) == ("L0", 1, (1,), (1,))
    assert [(p.kind, p.link, p.to) for p in l0.external] == [("R", 1, 0)]
    # i = slider 3 (its external pair is the slide on the ground), j = rod 2 (on the crank)
    assert (rrp.kind, rrp.links, rrp.pairs) == ("L2", (3, 2), "RRP")
    assert sorted((p.kind, p.link, p.to) for p in rrp.external) == [("P", 3, 0), ("R", 2, 1)]
    assert [(p.kind, {p.link, p.to}) for p in rrp.internal] == [("R", {2, 3})]
    assert (rrp.variant, rrp.contour) == (1, 1)  # contour 1, Pl3, variant: 1


def test_four_bar_is_a_crank_and_an_rrr_dyad():
    data = example("four_bar.yaml", bodies={1: {"vectors": [1, 5]}, 2: {"vectors": [2, 6]},
                                            3: {"vectors": [3]}})
    mob, dec = solved(data)
    assert (mob.n, mob.p5, mob.W, mob.inputs) == (3, 4, 1, 1)
    assert dec.formula == "L0(1) → L1(2,3)"
    # j = rocker 3, the link hinged to the ground (seed: "её будем обозначать буквой j")
    assert dec.groups[1].links == (2, 3)
    assert (dec.groups[1].variant, dec.groups[1].contour) == (1, 1)


def test_rrr_dyad_names_the_grounded_link_j_whatever_the_numbering():
    # crank 1, rocker 2 on the ground, coupler 3 between them
    dec = decompose(mechanism(pin(0, 1), pin(1, 3), pin(2, 3), pin(0, 2)))
    assert dec.formula == "L0(1) → L1(2,3)"
    assert dec.groups[1].links == (3, 2)
    row = identification_table(dec).loc[2]
    assert (row["i-1"], row["j-1"], row["i"], row["j"]) == (1, 0, 3, 2)


def test_watt_six_bar_is_two_rrr_dyads_in_order():
    mob, dec = solved(example("six_bar.yaml", bodies=SIX_BAR_BODIES))
    assert (mob.n, mob.p5, mob.p4, mob.W, mob.inputs) == (5, 7, 0, 1, 1)
    assert dec.formula == "L0(1) → L1(2,3) → L1(4,5)"
    assert dec.mechanism_class == 2
    first, second = dec.groups[1:]
    assert sorted((p.link, p.to) for p in first.external) == [(2, 1), (3, 0)]
    assert sorted((p.link, p.to) for p in second.external) == [(4, 3), (5, 0)]
    assert [(g.variant, g.contour) for g in dec.groups] == [(None, None), (1, 1), (1, 2)]


def test_assembly_variant_comes_from_the_contour_that_solves_the_group():
    data = example("six_bar.yaml", bodies=SIX_BAR_BODIES)
    data["contours"][1]["variant"] = 2
    _, dec = solved(data)
    assert [g.variant for g in dec.groups] == [None, 1, 2]


def test_six_bar_identification_table():
    _, dec = solved(example("six_bar.yaml", bodies=SIX_BAR_BODIES))
    table = identification_table(dec)
    assert list(table.columns) == ["L", "pairs", "i-1", "j-1", "i", "j", "i+1", "j+1",
                                   "variant"]
    assert table.index.name == "group"
    rows = [list(row) for row in table.itertuples(index=True)]
    # group, L, pairs, i-1, j-1, i, j, i+1, j+1, variant: the crank carries the coupler's
    # pin (i+1 = 2), the bell crank 3 carries link 4's pin (j+1 = 4)
    assert rows == [[1, 0, "R", 0, "-", 1, "-", 2, "-", "-"],
                    [2, 1, "RRR", 1, 0, 2, 3, "-", 4, 1],
                    [3, 1, "RRR", 3, 0, 4, 5, "-", "-", 1]]


def test_v_twin_is_two_rrp_dyads_on_the_crank():
    mob, dec = solved(example("v_engine.yaml", bodies=V_TWIN_BODIES))
    assert (mob.n, mob.p5, mob.W, mob.inputs) == (5, 7, 1, 1)
    assert dec.formula == "L0(1) → L2(2,3) → L2(4,5)"
    for group, (rod, piston) in zip(dec.groups[1:], [(2, 3), (4, 5)], strict=True):
        assert (group.kind, group.links, group.variant) == ("L2", (piston, rod), 1)
        assert sorted((p.kind, p.link, p.to) for p in group.external) == [
            ("P", piston, 0), ("R", rod, 1)]
    assert identification_table(dec).loc[1, "i+1"] == "2,4"


def test_hydraulic_rocker_input_group_is_the_rocker_and_its_cylinder():
    # the cylinder is a driving pair between the ground and the rocker: W = 3·1 − 2·1 = 1
    mob, dec = solved(example("hydraulic_rocker.yaml", bodies={1: {"vectors": [1, 4]}}))
    assert (mob.n, mob.p5, mob.W, mob.inputs) == (1, 1, 1, 1)
    assert dec.formula == "L0(1)"
    (l0,) = dec.groups
    assert (l0.drives, l0.cylinders) == ((1,), ((1, 0),))
    # rocker + cylinder close a triangle (contour 1, Pl4): class II, with a variant
    assert (l0.assur_class, l0.variant, l0.contour) == (2, 1, 1)
    row = identification_table(dec).loc[1]
    assert (row["L"], row["i-1"], row["j-1"], row["i"], row["variant"]) == (0, 0, 0, 1, 1)


def test_cylinder_and_rod_modelled_as_bodies_give_the_same_mobility():
    # barrel 2 on the airframe, rod 3 on the lug, a slide between them driven by argument 1:
    # n = 3, p5 = 4, W = 9 − 8 = 1 (the same W as without them: 3·2 − 2·3 = 0)
    mob, dec = solved(landing_gear(40))
    assert (mob.n, mob.p5, mob.W, mob.inputs) == (3, 4, 1, 1)
    assert dec.formula == "L0(1,2,3)"
    assert (dec.groups[0].assur_class, dec.groups[0].variant) == (2, 1)


def test_crank_and_slotted_lever_is_an_rpr_dyad():
    mob, dec = solved(quick_return())
    assert mob.W == 1 and dec.formula == "L0(1) → L3(2,3)"
    assert dec.groups[1].pairs == "RPR"
    assert dec.groups[1].variant is None  # contour 1 is a Pl1: one solution


# --- the seed's own example ----------------------------------------------------------------

def seed_fig_1_25() -> Mechanism:
    """Fig. 1.25 of seed 002 from its group list: crank 1; L1 (2,3) on 1 and 0; L4 (4,5)
    guided by 3 and by the ground; L3 (6,7) on 2 and 0 with the kulisa 6; L2 (8,9) on 6 and
    guided by the ground; L5 (10,11) on 8 and guided by the ground."""
    pairs = (pin(0, 1),
             pin(1, 2), pin(2, 3), pin(0, 3),
             slide(3, 4), pin(4, 5), slide(0, 5),
             pin(2, 6), slide(6, 7, along=60), pin(0, 7),
             pin(6, 8), pin(8, 9), slide(0, 9),
             pin(8, 10), slide(10, 11), slide(0, 11))
    bodies = {k: (10 * k,) for k in range(1, 12)}
    return mechanism(*pairs, bodies=bodies)


def test_seed_mechanism_mobility_and_formula():
    mech = seed_fig_1_25()
    mob = mobility(mech)
    assert (mob.n, mob.p5, mob.W, mob.inputs) == (11, 16, 1, 1)  # seed: p5 = 16, W = 1
    dec = decompose(mech)
    assert dec.formula == "L0(1) → L1(2,3) → L4(4,5) → L3(6,7) → L2(8,9) → L5(10,11)"
    assert dec.mechanism_class == 2  # seed step 9: "второго класса"


def test_seed_identification_table_links_match_table_1_6():
    table = identification_table(decompose(seed_fig_1_25()))
    by_kind = table.sort_values("L", key=lambda s: s.astype(int))
    got = [[row["L"], row["i-1"], row["j-1"], row["i"], row["j"], row["i+1"], row["j+1"]]
           for _, row in by_kind.iterrows()]
    # seed 002, table 1.6: L, i-1, j-1, i, j, i+1, j+1
    assert got == [[0, 0, "-", 1, "-", 2, "-"],
                   [1, 1, 0, 2, 3, 6, "-"],
                   [2, 0, 6, 9, 8, "-", 10],
                   [3, 2, 0, 6, 7, 8, "-"],
                   [4, 3, 0, 4, 5, "-", "-"],
                   [5, 0, 8, 11, 10, "-", "-"]]


# --- groups of higher classes ---------------------------------------------------------------

def test_triad_is_one_class_iii_group_not_dyads():
    # base link 5 hinged to 2, 3, 4; 2 on the crank, 3 and 4 on the ground
    mech = mechanism(pin(0, 1), pin(1, 2), pin(2, 5), pin(3, 5), pin(4, 5), pin(0, 3),
                     pin(0, 4))
    mob = mobility(mech)
    assert (mob.n, mob.p5, mob.W) == (5, 7, 1) and mob.ok
    dec = decompose(mech)
    assert dec.formula == "L0(1) → III(2,3,4,5)"
    assert dec.mechanism_class == 3
    triad = dec.groups[1]
    assert (triad.kind, triad.assur_class, len(triad.external), len(triad.internal)) == (
        "III", 3, 3, 3)
    row = identification_table(dec).loc[2]
    assert (row["L"], row["i"]) == ("III", "2,3,4,5")


def test_triad_after_a_dyad_keeps_the_dyad():
    # a four-bar (1, 2, 3) with a triad on its coupler and rocker
    mech = mechanism(pin(0, 1), pin(1, 2), pin(2, 3), pin(0, 3),
                     pin(2, 4), pin(3, 5), pin(0, 6), pin(4, 7), pin(5, 7), pin(6, 7))
    assert mobility(mech).W == 1
    assert decompose(mech).formula == "L0(1) → L1(2,3) → III(4,5,6,7)"


def test_closed_four_link_contour_is_class_iv():
    # links 2-3-4-5 form a closed contour; 2 hinged to the crank, 4 to the ground
    mech = mechanism(pin(0, 1), pin(1, 2), pin(2, 3), pin(3, 4), pin(4, 5), pin(2, 5),
                     pin(0, 4))
    dec = decompose(mech)
    assert mobility(mech).W == 1
    assert dec.formula == "L0(1) → IV(2,3,4,5)"
    assert dec.mechanism_class == 4


def test_cylinder_on_a_four_bar_coupler_is_a_class_iii_input_group():
    # cylinder between the ground and the coupler 2: with the cylinder as a link, the
    # coupler is the base of a triad (1, 3, cylinder) — textbook class III
    mech = mechanism(pin(0, 1), pin(1, 2), pin(2, 3), pin(0, 3),
                     drives=(Drive(1, "length", 9, (0, 2)),))
    assert mobility(mech).ok
    dec = decompose(mech)
    assert dec.formula == "L0(1,2,3)"
    assert dec.mechanism_class == 3


# --- W ≠ inputs ---------------------------------------------------------------------------

def test_five_bar_with_one_crank_misses_an_input():
    mech = mechanism(pin(0, 1), pin(1, 2), pin(2, 3), pin(3, 4), pin(0, 4))
    mob = mobility(mech)
    assert (mob.n, mob.p5, mob.W, mob.inputs) == (4, 5, 2, 1) and not mob.ok
    assert "1 input(s) missing" in mob.explanation
    assert "links 2, 3, 4 keep 1 degree(s) of freedom" in mob.explanation
    dec = decompose(mech)
    assert (dec.formula, dec.rest, dec.mechanism_class) == ("L0(1) → ?(2,3,4)", (2, 3, 4),
                                                            None)
    assert identification_table(dec).loc[2, "L"] == "?"


def test_double_parallelogram_has_a_passive_link():
    # a parallelogram 0-1-2-3 and a third crank 4 between the ground and the coupler
    mech = mechanism(pin(0, 1), pin(1, 2), pin(2, 3), pin(0, 3), pin(0, 4), pin(2, 4))
    mob = mobility(mech)
    assert (mob.n, mob.p5, mob.W, mob.inputs) == (4, 6, 0, 1)
    assert "redundant constraints" in mob.explanation
    assert "link 4 is held by J0_4, J2_4" in mob.explanation
    assert "passive link" in mob.explanation
    dec = decompose(mech)
    assert (dec.formula, dec.passive, dec.rest) == ("L0(1) → L1(2,3)", (4,), ())


def test_two_drives_on_a_four_bar_are_one_too_many():
    mech = mechanism(pin(0, 1), pin(1, 2), pin(2, 3), pin(0, 3),
                     drives=(crank(1, 1), crank(3, 2)))
    mob = mobility(mech)
    assert (mob.W, mob.inputs) == (1, 2)
    assert "more drives than the chain can take" in mob.explanation
    # both cranks are input groups; the coupler between them is then over-constrained
    dec = decompose(mech)
    assert (dec.formula, dec.passive) == ("L0(1) → L0(3)", (2,))


def test_link_hanging_on_one_pin_has_a_local_mobility():
    mech = mechanism(pin(0, 1), pin(1, 2), pin(2, 3), pin(0, 3), pin(0, 4))
    mob = mobility(mech)
    assert (mob.W, mob.inputs) == (2, 1)
    assert "link 4 is held only by J0_4" in mob.explanation
    assert "local mobility" in mob.explanation
    assert decompose(mech).free == (4,)


def test_three_prismatic_pairs_are_not_taken_for_a_dyad():
    # two links, three slides: the count gives W = 0 for them, but they translate
    mech = mechanism(pin(0, 1), slide(1, 2), slide(2, 3), slide(0, 3))
    assert mobility(mech).W == 1
    dec = decompose(mech)
    assert dec.formula == "L0(1) → ?(2,3)"
    assert "form no rigid group" in dec.notes[0]


def test_docstring_examples_run():
    for name in ("assur", "mobility"):
        module = importlib.import_module(f"mechloop.structure.{name}")
        assert doctest.testmod(module, raise_on_error=True).attempted > 0
