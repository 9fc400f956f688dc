"""Plans held to a user's choice of actions (`solve --force`, `--forbid`).

A forbidden ground action is taken out of the task. A forced one is made
necessary: it also adds a fact of its own, `(forced <action>)`, that no other
action adds, and the goal asks for that fact. Every plan of the restricted
task is a plan of the original one containing each forced action, and its
cost is the same; the search, its heuristics and the skeleton ranking need
nothing else.
"""

from __future__ import annotations

import dataclasses

from tampcli.errors import InputError
from tampcli.task.task import Task


def action_key(text: str) -> str:
    """A ground action as the task names it: `( pick  A b )` -> `(pick a b)`."""
    return "(" + " ".join(text.replace("(", " ").replace(")", " ").lower().split()) + ")"


def op_indices(task: Task, names, flag: str) -> frozenset[int]:
    """Indices in task.operators of the ground actions `names`; InputError (key
    `flag`) naming one that the task does not have."""
    index = {op.name: i for i, op in enumerate(task.operators)}
    out = set()
    for name in names:
        key = action_key(name)
        if key not in index:
            raise InputError(f"{name!r} is not a ground action of the task (no such action, "
                             "or none of its preconditions can ever hold)", key=flag)
        out.add(index[key])
    return frozenset(out)


def restrict(task: Task, forced=(), forbidden=()) -> Task:
    """The task whose plans are `task`'s plans that contain every action of `forced`
    and none of `forbidden` (ground action names)."""
    if not forced and not forbidden:
        return task
    must, never = op_indices(task, forced, "--force"), op_indices(task, forbidden, "--forbid")
    both = must & never
    if both:
        name = task.operators[min(both)].name
        raise InputError(f"{name} is both forced and forbidden", key="--force")
    facts = list(task.facts)
    marks = {}
    for i in sorted(must):
        marks[i] = len(facts)
        facts.append(f"(forced {task.operators[i].name[1:]}")
    operators = tuple(dataclasses.replace(op, add=op.add | {marks[i]}) if i in marks else op
                      for i, op in enumerate(task.operators) if i not in never)
    goal = dataclasses.replace(task.goal, pos=task.goal.pos | frozenset(marks.values()))
    return dataclasses.replace(task, facts=tuple(facts), operators=operators, goal=goal)
