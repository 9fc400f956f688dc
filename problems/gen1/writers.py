"""Text of the generated files: scene.toml, problem.pddl, and the domains
(copies of the repository's public domain files, embedded so that the
generator stands alone)."""

import math

CLUTTER_DOMAIN = """\
; gen1 arm-clutter: arm-pick-place's pick and place (docs: domains/arm-pick-place),
; without stack/unstack: the generated clutter is never stacked.
(define (domain gen1-arm-clutter)
  (:requirements :strips :typing)
  (:types block region)
  (:predicates (at ?b - block ?r - region)
               (holding ?b - block)
               (handempty))

  (:action pick
    :parameters (?b - block ?from - region)
    :precondition (and (at ?b ?from) (handempty))
    :effect (and (not (at ?b ?from)) (not (handempty)) (holding ?b)))

  (:action place
    :parameters (?b - block ?to - region)
    :precondition (holding ?b)
    :effect (and (not (holding ?b)) (handempty) (at ?b ?to))))
"""

CLUTTER_MODES = """\
# What each action of gen1-arm-clutter does to the world (docs/formats.md, "modes.toml").

[pick]
mode = "grasp"
object = "?b"

[place]
mode = "place"
object = "?b"
on = "?to"
"""

STACK_DOMAIN = """\
; gen1 arm-stack: a copy of domains/arm-kuka (= arm-xarm, arm-pick-place):
; pick/place take a block from/to a region, unstack/stack from/onto a block.
(define (domain gen1-arm-stack)
  (:requirements :strips :typing)
  (:types block region)
  (:predicates (at ?b - block ?r - region)
               (on ?b - block ?c - block)
               (clear ?b - block)
               (holding ?b - block)
               (handempty))

  (:action pick
    :parameters (?b - block ?from - region)
    :precondition (and (at ?b ?from) (clear ?b) (handempty))
    :effect (and (not (at ?b ?from)) (not (clear ?b)) (not (handempty))
                 (holding ?b)))

  (:action place
    :parameters (?b - block ?to - region)
    :precondition (holding ?b)
    :effect (and (not (holding ?b)) (handempty) (clear ?b) (at ?b ?to)))

  (:action unstack
    :parameters (?b - block ?from - block)
    :precondition (and (on ?b ?from) (clear ?b) (handempty))
    :effect (and (not (on ?b ?from)) (not (clear ?b)) (not (handempty))
                 (holding ?b) (clear ?from)))

  (:action stack
    :parameters (?b - block ?to - block)
    :precondition (and (holding ?b) (clear ?to))
    :effect (and (not (holding ?b)) (not (clear ?to)) (handempty) (clear ?b)
                 (on ?b ?to))))
"""

STACK_MODES = """\
# A copy of domains/arm-kuka/modes.toml (docs/formats.md, "modes.toml").

[pick]
mode = "grasp"
object = "?b"

[place]
mode = "place"
object = "?b"
on = "?to"

[unstack]
mode = "grasp"
object = "?b"

[stack]
mode = "place"
object = "?b"
on = "?to"
"""

PLANAR_DOMAIN = """\
; gen1 planar: a copy of domains/planar-push: a planar disk pushes an item
; over one surface, or picks (liftable items only) and places it.
(define (domain gen1-planar)
  (:requirements :strips :typing :action-costs)
  (:types item region surface)
  (:predicates (at ?o - item ?r - region)
               (holding ?o - item)
               (handempty)
               (liftable ?o - item)
               (region-on ?r - region ?s - surface))
  (:functions (total-cost) - number)

  (:action push
    :parameters (?o - item ?from - region ?to - region ?s - surface)
    :precondition (and (at ?o ?from) (handempty)
                       (region-on ?from ?s) (region-on ?to ?s))
    :effect (and (not (at ?o ?from)) (at ?o ?to)
                 (increase (total-cost) 2)))

  (:action pick
    :parameters (?o - item ?from - region)
    :precondition (and (at ?o ?from) (handempty) (liftable ?o))
    :effect (and (not (at ?o ?from)) (not (handempty)) (holding ?o)
                 (increase (total-cost) 2)))

  (:action place
    :parameters (?o - item ?to - region)
    :precondition (holding ?o)
    :effect (and (not (holding ?o)) (handempty) (at ?o ?to)
                 (increase (total-cost) 2))))
"""

PLANAR_MODES = """\
# A copy of domains/planar-push/modes.toml (docs/formats.md, "modes.toml").

[push]
mode = "push"
object = "?o"
to = "?to"

[pick]
mode = "grasp"
object = "?o"

[place]
mode = "place"
object = "?o"
on = "?to"
"""


def _num(x):
    text = f"{float(x):.5f}".rstrip("0").rstrip(".")
    return text if abs(x) >= 5e-6 else "0.0"


def _vec(v):
    return "[" + ", ".join(_num(x) if not isinstance(x, str) else x for x in v) + "]"


def body_toml(b):
    """One [[objects]] table from a body dict (name, shape, size, pose, fixed, color)."""
    lines = ["[[objects]]", f'name = "{b["name"]}"', f'shape = "{b["shape"]}"',
             f"size = {_vec(b['size'])}", f"pose = {_vec(b['pose'])}"]
    if b.get("fixed"):
        lines.append("fixed = true")
    color = b.get("color", "gray")
    lines.append(f'color = "{color}"' if isinstance(color, str) else f"color = {_vec(color)}")
    return "\n".join(lines) + "\n"


def region_toml(r):
    return "\n".join(["[[regions]]", f'name = "{r["name"]}"', f'on = "{r["on"]}"',
                      f"center = {_vec(r['center'])}", f"size = {_vec(r['size'])}"]) + "\n"


def scene_toml(header, robot, bodies, regions, camera):
    out = [f"# {line}" for line in header] + ["", "[robot]"]
    for key, value in robot.items():
        out.append(f'{key} = "{value}"' if isinstance(value, str) else f"{key} = {_vec(value) if isinstance(value, (list, tuple)) else _num(value)}")
    out.append("")
    out += [body_toml(b) for b in bodies]
    out += [region_toml(r) for r in regions]
    out += ["[camera]", f"eye = {_vec(camera[0])}", f"target = {_vec(camera[1])}", ""]
    return "\n".join(out)


def problem_pddl(name, domain, comment, objects, init, goal, metric=False):
    """objects: {type: [names]}; init, goal: lists of fact strings."""
    objs = "\n            ".join(" ".join(names) + f" - {t}" for t, names in objects.items() if names)
    lines = [f"; {line}" for line in comment]
    lines += [f"(define (problem {name})", f"  (:domain {domain})", f"  (:objects {objs})",
              "  (:init " + "\n         ".join(init) + ")",
              "  (:goal (and " + "\n              ".join(goal) + "))"]
    if metric:
        lines.append("  (:metric minimize (total-cost))")
    return "\n".join(lines) + ")\n"


def yaw_deg(yaw):
    return f"{math.degrees(yaw):.0f} deg"
