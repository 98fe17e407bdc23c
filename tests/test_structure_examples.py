"""The structure of every bundled example, against a hand analysis written out here.

For each example with bodies: moving links n, lower pairs p5, higher pairs p4, Chebyshev's
W = 3n − 2p5 − p4, the structure formula and the class.  Examples without bodies are pure
kinematic models: ``mechloop structure`` must refuse them with the located "no bodies"
error (the structure of their mechanisms is tested with bodies in tests/test_structure.py:
the four-bar, the Watt six-bar, the V-twin, the hydraulic rocker).  A new example must be
added to one of the two lists, so none is left unchecked.
"""

from __future__ import annotations

from pathlib import Path

import pytest

import mechloop
from mechloop.errors import ModelError
from mechloop.structure.analysis import analyze

EXAMPLES = Path(__file__).resolve().parents[1] / "examples"

# file: (n, p5, p4, W, formula, class), by hand:
HAND = {
    # crank 1 pinned to the frame (R), rod 2 pinned to the crank and the slider 3 (R, R),
    # slider 3 on the guide (P): n = 3, p5 = 4, W = 9 − 8 = 1.  The crank is the input
    # group; rod + slider with two pins and a slide is an RRP dyad (L2).
    "crank_slider_dynamics.yaml": (3, 4, 0, 1, "L0(1) → L2(2,3)", 2),
    "crank_slider_friction.yaml": (3, 4, 0, 1, "L0(1) → L2(2,3)", 2),
    "course_project_sheets.yaml": (3, 4, 0, 1, "L0(1) → L2(2,3)", 2),  # + project: cam
    "crank_slider_groups.yaml": (3, 4, 0, 1, "L0(1) → L2(2,3)", 2),
    "single_cylinder_engine.yaml": (3, 4, 0, 1, "L0(1) → L2(2,3)", 2),
    "engine_indicator.yaml": (3, 4, 0, 1, "L0(1) → L2(2,3)", 2),
    "engine_startup.yaml": (3, 4, 0, 1, "L0(1) → L2(2,3)", 2),
    "compressor_indicator.yaml": (3, 4, 0, 1, "L0(1) → L2(2,3)", 2),
    "compressor_startup.yaml": (3, 4, 0, 1, "L0(1) → L2(2,3)", 2),
    "spring_release.yaml": (3, 4, 0, 1, "L0(1) → L2(2,3)", 2),
    # five-bar: cranks 1 and 4 each pinned to the frame (two input groups), links 2 and 3
    # pinned to the cranks and to each other: n = 4, p5 = 5, W = 12 − 10 = 2 (two
    # inputs); links 2 + 3 are an RRR dyad (L1).
    "two_input_five_bar.yaml": (4, 5, 0, 2, "L0(1) → L0(4) → L1(2,3)", 2),
    # shaper: crank 1 (R to the frame), block 2 (R on the crank pin, P along the lever),
    # lever 3 (R to the frame), rod 4 (R to the lever and to the ram), ram 5 (P on the
    # guide): n = 5, p5 = 7, W = 15 − 14 = 1.  Block + lever with pins at both ends and the
    # slide between them is an RPR dyad (L3); rod + ram an RRP dyad (L2).
    "shaper_cutting_stroke.yaml": (5, 7, 0, 1, "L0(1) → L3(2,3) → L2(4,5)", 2),
    # crank 1, coupler 2, rocker 3, four pins: W = 9 − 8 = 1; coupler + rocker is an
    # RRR dyad (L1).
    "four_bar_groups.yaml": (3, 4, 0, 1, "L0(1) → L1(2,3)", 2),
    "four_bar_groups_synthesis.yaml": (3, 4, 0, 1, "L0(1) → L1(2,3)", 2),
    # crank 1, coupler 2, rocker 3 (RRR dyad), then link 4 and slider 5 (R, R, P: RRP)
    # hung on the rocker: n = 5, p5 = 7, W = 15 − 14 = 1.
    "six_bar_groups.yaml": (5, 7, 0, 1, "L0(1) → L1(2,3) → L2(4,5)", 2),
    # crank 1, then rod 2, lever 3, rocker 4 each pinned to the plate 5 and to the crank
    # pin, C and D: n = 5, p5 = 7, W = 15 − 14 = 1.  Two links of 2..5 never have the three
    # pairs of a dyad to placed links; all four with their six pairs are a triad (class
    # III: no closed contour inside, the plate holds three pairs).
    "class3_six_bar_groups.yaml": (5, 7, 0, 1, "L0(1) → III(2,3,4,5)", 3),
    # shield 1, front link 2, rear link 3, pins O2, B, O1, A: n = 3, p5 = 4, W = 1.  The
    # massless leg is the drive and pushes on the shield at B: the shield alone keeps
    # 3 − 1 = 2 freedoms, with the front link 6 − 4 − 1 = 1, with the rear link too
    # 9 − 8 − 1 = 0 — the input group holds all three links (a closed contour of three
    # links with the drive: class III by the seed's rule).
    "roof_support.yaml": (3, 4, 0, 1, "L0(1,2,3)", 3),
    "roof_support_synthesis.yaml": (3, 4, 0, 1, "L0(1,2,3)", 3),
    # the same with the leg pinned to the shield at C (its own pin): the same pairs, the
    # drive between the ground and the shield, so again one group of all three links
    "roof_support_real.yaml": (3, 4, 0, 1, "L0(1,2,3)", 3),
    # the same three links with the leg pinned to the shield at its own point K: the leg
    # is a drive (not a link), pins O1, O2, A, B: n = 3, p5 = 4, W = 1; the shield held
    # by three binary members (two links and the driven leg) — the input group, class III.
    "roof_support_groups.yaml": (3, 4, 0, 1, "L0(1,2,3)", 3),
    # pinion 1 and wheel 2 pinned to the frame, their mesh a higher pair: n = 2, p5 = 2,
    # p4 = 1, W = 6 − 4 − 1 = 1; the mesh replaced by a link 3 with two pins, an RRR dyad
    "gear_pair_dynamics.yaml": (2, 2, 1, 1, "L0(1) → L1(2,3)", 2),
    # crank 1, coupler 2, rocker 3, four pins: W = 9 − 8 = 1; an RRR dyad (L1)
    "four_bar_break_ahead.yaml": (3, 4, 0, 1, "L0(1) → L1(2,3)", 2),
}

WITHOUT_BODIES = {
    "cam_flat_follower.yaml", "cam_roller_follower.yaml",
    "crank_slider.yaml", "eighteen_points_timing_synthesis.yaml",
    "five_points_timing_synthesis.yaml", "four_bar.yaml",
    "gear_pair.yaml", "gear_train.yaml", "planetary_reducer.yaml",
    "four_bar_path_synthesis.yaml", "four_bar_shape_synthesis.yaml",
    "hydraulic_rocker.yaml", "log10_function_generator.yaml", "six_bar.yaml",
    "six_points_free_timing_synthesis.yaml", "six_points_line_synthesis.yaml",
    "six_points_timing_synthesis.yaml",
    "slider_crank_stroke_synthesis.yaml",
    "sparse_argument.yaml", "v_engine.yaml",
}


def test_every_example_is_in_one_list():
    files = {p.name for p in EXAMPLES.glob("*.yaml")}
    assert files - HAND.keys() - WITHOUT_BODIES == set(), "add the new example here"
    assert (HAND.keys() | WITHOUT_BODIES) - files == set(), "an example was removed"


@pytest.mark.parametrize("name", sorted(HAND))
def test_structure_matches_the_hand_analysis(name: str):
    mob, dec = analyze(mechloop.load_model(EXAMPLES / name))
    n, p5, p4, w, formula, klass = HAND[name]
    assert (mob.n, mob.p5, mob.p4, mob.W, mob.inputs) == (n, p5, p4, w, w)  # W inputs
    assert mob.W == 3 * mob.n - 2 * mob.p5 - mob.p4
    assert dec.formula == formula
    assert dec.mechanism_class == klass


@pytest.mark.parametrize("name", sorted(WITHOUT_BODIES))
def test_kinematic_only_examples_are_refused_with_the_fix(name: str):
    with pytest.raises(ModelError) as info:
        analyze(mechloop.load_model(EXAMPLES / name))
    assert "no bodies" in str(info.value)


# The course-project models of examples/course/ (seed 000 sec. 3), by hand from each
# file's header sketch: file: (n, p5, p4, W, formula, class).
COURSE = EXAMPLES / "course"
COURSE_HAND = {
    # leg 1 (pinned at O, driven by the cylinder), lower brace 2 (pins C, K), upper brace 3
    # (pins K, B): four pins, W = 9 − 8 = 1; the braces are an RRR dyad on the leg.
    "01_an10_landing_gear.yaml": (3, 4, 0, 1, "L0(1) → L1(2,3)", 2),
    # upper brace 1 driven at its knee (pins B, K), lower brace 2 (K, C), leg 3 (C, O)
    "02_landing_gear.yaml": (3, 4, 0, 1, "L0(1) → L1(2,3)", 2),
    # No. 1's leg and braces, then the bogie 4 (pin W on the leg) and the tilting rod 5
    # (pins F, H): seven pins, W = 15 − 14 = 1; a second RRR dyad.
    "03_tu154_landing_gear.yaml": (5, 7, 0, 1, "L0(1) → L1(2,3) → L1(4,5)", 2),
    # the bell crank 1 (pin B) driven by the cylinder, lower brace 2 and leg 3 a dyad
    "04_an10_landing_gear_b.yaml": (3, 4, 0, 1, "L0(1) → L1(2,3)", 2),
    # crank 1, rod 2, crosshead with piston 3: RRP dyad
    "05_compressor.yaml": (3, 4, 0, 1, "L0(1) → L2(2,3)", 2),
    # the leg held by two links and the cylinder (its own pin C): pins O1, A, O2, B; the
    # drive between the ground and the leg keeps all three links in one group (class III)
    "06_landing_gear_four_bar.yaml": (3, 4, 0, 1, "L0(1,2,3)", 3),
    # the cylinder between the leg and the upper brace: the drive closes the contour
    # leg–lower brace–upper brace–cylinder of four sides, one group of all three links
    "07_landing_gear_jack_on_brace.yaml": (3, 4, 0, 1, "L0(1,2,3)", 4),
    # leg 1 (pin O) driven, rod 2 (pins R, Q), door 3 (pin H): an RRR dyad
    "08_nose_gear_door.yaml": (3, 4, 0, 1, "L0(1) → L1(2,3)", 2),
    # carriage 1 on the rail (slide), strut 2 (pins S, K), leg 3 (pin O): three pins and
    # the slide, W = 9 − 8 = 1
    "09_lunar_lander_gear.yaml": (3, 4, 0, 1, "L0(1) → L1(2,3)", 2),
    # lever 1 (pin L) driven, rod 2 (pins A, Q), mast 3 (pin M): an RRR dyad
    "10_cable_mast.yaml": (3, 4, 0, 1, "L0(1) → L1(2,3)", 2),
    # the boom alone, pinned at O and driven by the cylinder: W = 3 − 2 = 1
    "11_erector.yaml": (1, 1, 0, 1, "L0(1)", 2),
    # crank 1, master rod 2 + piston 4 (RRP), articulated rod 3 + piston 5 hung on the
    # master rod's knuckle pin (RRP): n = 5, p5 = 7 (O, A, C, B1, B2, two slides)
    "12_v_engine_articulated.yaml": (5, 7, 0, 1, "L0(1) → L2(2,4) → L2(3,5)", 2),
    # crank 1, fork rod 2 + piston 4 (RRP), blade rod 3 + piston 5 pinned to the fork's
    # big end (RRP): n = 5, p5 = 7 (O, A crank-fork, A fork-blade, B1, B2, two slides)
    "13_v_engine_fork_and_blade.yaml": (5, 7, 0, 1, "L0(1) → L2(2,4) → L2(3,5)", 2),
    # ring 1 driven along its slide, link 2 and flap 3 (RRR): n = 3, p5 = 4 (slide, R, L, P)
    "14_nozzle_ring.yaml": (3, 4, 0, 1, "L0(1) → L1(2,3)", 2),
    # primary flap 1 turned by the cylinder (a drive, not a link), divergent flap 2 and
    # strut 3 (RRR): n = 3, p5 = 4 (P, T, E, Q)
    "15_nozzle_flaps.yaml": (3, 4, 0, 1, "L0(1) → L1(2,3)", 2),
    # crankshaft 1 with two throws, each with a rod and a piston (RRP dyads)
    "16_two_cylinder_compressor.yaml": (5, 7, 0, 1, "L0(1) → L2(2,4) → L2(3,5)", 2),
    # crank 1; plunger 2 pinned to the crank pin, sliding in the cylinder 3 that swings on
    # its trunnion: an RPR dyad (pins A and C, the slide between): n = 3, p5 = 4
    "17_oil_pump.yaml": (3, 4, 0, 1, "L0(1) → L3(2,3)", 2),
    # as No. 16, the cylinders at right angles (L-type), both rods on one crank pin
    "18_two_stage_compressor.yaml": (5, 7, 0, 1, "L0(1) → L2(2,4) → L2(3,5)", 2),
    # crank 1, coupler 2, rocker with arm 3 (RRR), rod 4 and ram 5 (RRP): n = 5, p5 = 7
    "19_gear_shaper.yaml": (5, 7, 0, 1, "L0(1) → L1(2,3) → L2(4,5)", 2),
    # slider 1 driven along its guide; link 2 + left door 3, link 4 + right door 5 (RRR
    # each): n = 5, p5 = 7 (slide, P twice, BL, BR, HL, HR)
    "20_solar_panel_doors.yaml": (5, 7, 0, 1, "L0(1) → L1(2,3) → L1(4,5)", 2),
}


def test_every_course_model_has_its_hand_analysis():
    assert {p.name for p in COURSE.glob("*.yaml")} == COURSE_HAND.keys()


@pytest.mark.parametrize("name", sorted(COURSE_HAND))
def test_course_model_structure_matches_the_hand_analysis(name: str):
    mob, dec = analyze(mechloop.load_model(COURSE / name))
    n, p5, p4, w, formula, klass = COURSE_HAND[name]
    assert (mob.n, mob.p5, mob.p4, mob.W, mob.inputs) == (n, p5, p4, w, 1)
    assert dec.formula == formula
    assert dec.mechanism_class == klass
