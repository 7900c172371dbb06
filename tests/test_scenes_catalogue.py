"""The scene catalogue: every scene declared in full, a user's parameters checked in one line, `harness scenes`
printing what the catalogue declares."""
import json
import math
import subprocess
import sys

import pytest

from harness.infra.errors import UserError
from harness.scenes import closed_forms
from harness.scenes.catalogue import EFFECT_WORDS, EFFECTS_CHOSEN, SCENES, scene_kind

ISSUE_43_SCENES = {"impact", "free-fall", "bounce", "slide-to-roll", "rest", "stack"}
RUNNING = ISSUE_43_SCENES    # what `harness run --scene` runs


def harness(*args):
    return subprocess.run([sys.executable, "-m", "harness", *args], capture_output=True, text=True, timeout=300)


def test_the_catalogue_holds_the_scenes_of_issue_43():
    assert set(SCENES) == ISSUE_43_SCENES
    assert all(name == kind.NAME for name, kind in SCENES.items())


@pytest.mark.parametrize("name", sorted(ISSUE_43_SCENES))
def test_every_scene_is_declared_in_full(name):
    """A summary of one line, effects from the vocabulary, every parameter with a unit and a meaning and a default
    it accepts, every check with a closed form whose docstring names its source."""
    kind = SCENES[name]
    assert kind.SUMMARY and "\n" not in kind.SUMMARY
    assert kind.EFFECTS and kind.EFFECTS <= set(EFFECT_WORDS), kind.EFFECTS
    assert kind.PARAMETERS
    for p in kind.PARAMETERS:
        assert p.unit and p.meaning, p
        assert kind.values({p.name: p.default})[p.name] == p.default
    for check in kind.CHECKS:
        assert check.closed_form is getattr(closed_forms, check.closed_form.__name__)
        assert check.source and check.source in check.closed_form.__doc__, (check.name, check.source)
        assert 0.0 < check.tolerance < 0.1 and check.quantity and "=" in check.equation


def test_each_scene_needs_the_effects_the_issue_names():
    """Issue 43: gravity for every scene but impact, several contacts for the stack, long contact where a contact
    lasts (slide-to-roll, rest, stack), a wall or a pair for impact as its target says."""
    assert SCENES["free-fall"].EFFECTS == {"gravity"}
    assert SCENES["bounce"].EFFECTS == {"gravity", "wall"}
    assert SCENES["slide-to-roll"].EFFECTS == SCENES["rest"].EFFECTS == {"gravity", "wall", "long-contact"}
    assert SCENES["stack"].EFFECTS == set(EFFECT_WORDS)
    impact = SCENES["impact"]
    assert impact.effects(impact.values()) == {"wall"}
    assert impact.effects(impact.values({"target": "sphere"})) == {"pair"}
    assert SCENES["bounce"].effects(SCENES["bounce"].values()) == SCENES["bounce"].EFFECTS


def test_a_scenes_checks_are_those_of_issue_43():
    names = {name: {c.closed_form.__name__ for c in kind.CHECKS} for name, kind in SCENES.items()}
    assert names == {"impact": set(), "free-fall": {"free_fall_height"},
                     "bounce": {"linear_bounce_restitution", "linear_bounce_apex"},
                     "slide-to-roll": {"slip_end_time", "rolling_speed"},
                     "rest": {"hertz_static_overlap", "linear_static_overlap"}, "stack": {"stack_contact_force"}}


def test_parameters_given_replace_the_defaults():
    assert SCENES["stack"].values({"spheres": 5, "walls": 2, "preload": 3}) == \
        {"spheres": 5, "walls": 2, "preload": 3, "g": 9.81}
    assert SCENES["bounce"].values() == {"height": 0.1, "bounces": 3, "g": 9.81}


@pytest.mark.parametrize("scene, given, says", [
    ("bounce", {"heigth": 0.2}, "scene bounce has no parameter heigth (it takes height, bounces, g)"),
    ("bounce", {"height": "0.2"}, "scene bounce: height = '0.2' is not a number > 0"),
    ("bounce", {"height": -0.1}, "scene bounce: height = -0.1 is not a number > 0"),
    ("bounce", {"height": math.nan}, "scene bounce: height = nan is not a number > 0"),
    ("bounce", {"bounces": 2.0}, "scene bounce: bounces = 2.0 is not an integer >= 1 and <= 1000"),
    ("bounce", {"bounces": 0}, "scene bounce: bounces = 0 is not an integer >= 1 and <= 1000"),
    ("bounce", {"bounces": True}, "scene bounce: bounces = True is not an integer >= 1 and <= 1000"),
    ("rest", {"steps": 10 ** 10}, "scene rest: steps = 10000000000 is not an integer >= 1 and <= 1000000000"),
    ("slide-to-roll", {"g": 0.0}, "scene slide-to-roll: g = 0.0 is not a number > 0"),
    ("slide-to-roll", {"v0": math.inf}, "scene slide-to-roll: v0 = inf is not a number"),
    ("stack", {"walls": 3}, "scene stack: walls = 3 is not one of 1, 2"),
    ("stack", {"spheres": 1}, "scene stack: spheres = 1 is not an integer >= 2 and <= 100"),
    ("stack", {"preload": 2.0}, "scene stack: preload = 2.0 needs walls = 2 (a top wall to press with)"),
    ("impact", {"target": "plane"}, "scene impact: target = 'plane' is not one of wall, sphere"),
])
def test_a_bad_parameter_is_refused_in_one_line(scene, given, says):
    with pytest.raises(UserError) as refused:
        SCENES[scene].values(given)
    assert str(refused.value) == says


def test_an_unknown_scene_is_refused_naming_the_scenes():
    with pytest.raises(UserError, match=r"^unknown scene 'bounse' \(scenes: impact, free-fall, bounce, "
                                        r"slide-to-roll, rest, stack\)$"):
        scene_kind("bounse")
    assert scene_kind("rest") is SCENES["rest"]


def test_scenes_json_is_the_catalogue():
    """Every scene, every parameter (name, default, unit, meaning), its effects and every check, as declared."""
    done = harness("scenes", "--json")
    assert done.returncode == 0 and not done.stderr, done.stderr
    listed = {scene["name"]: scene for scene in json.loads(done.stdout)}
    assert list(listed) == list(SCENES)
    for name, kind in SCENES.items():
        scene = listed[name]
        assert scene["summary"] == kind.SUMMARY and scene["runs"] == kind.RUNS
        assert [(p["name"], p["default"], p["unit"], p["meaning"]) for p in scene["parameters"]] == \
            [(p.name, p.default, p.unit, p.meaning) for p in kind.PARAMETERS]
        assert set(scene["effects"]) == kind.EFFECTS
        assert [(c["name"], c["tolerance"], c["tolerance_is"], c["source"]) for c in scene["checks"]] == \
            [(c.name, c.tolerance, "relative" if c.relative else "absolute", c.source) for c in kind.CHECKS]
    assert listed["impact"]["effects_chosen_by"] == {"parameter": "target",
                                                     "effects": {"wall": ["wall"], "sphere": ["pair"]}}
    assert listed["slide-to-roll"]["checks"][0]["equation"] == "t_s = 2 |v0 - R w0|/(7 mu g)"
    assert {n for n in ISSUE_43_SCENES if listed[n]["runs"]} == RUNNING


def test_scenes_text_lists_every_scene_parameter_unit_and_check():
    done = harness("scenes")
    assert done.returncode == 0 and not done.stderr, done.stderr
    lines = done.stdout.splitlines()
    for name, kind in SCENES.items():
        start = next(i for i, line in enumerate(lines) if line.startswith(f"{name}: {kind.SUMMARY}"))
        block = lines[start + 1:start + 2 + len(kind.PARAMETERS) + len(kind.CHECKS)]
        assert block[0].startswith("  effects: ")
        for p in kind.PARAMETERS:
            assert any(line.startswith(f"  {p.name} = {p.default} [{p.unit}]  {p.meaning}") for line in block), p
        for c in kind.CHECKS:
            assert any(line.startswith(f"  check {c.name}: ") and line.endswith(c.source) for line in block), c
        assert ("no command runs it yet" in lines[start]) != kind.RUNS
    assert "  effects: wall (target = wall) or pair (target = sphere)" in lines
    assert set(EFFECTS_CHOSEN) <= set(SCENES)
