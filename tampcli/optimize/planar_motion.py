"""The planar robot's grid routes of one motion (geometry/planar_route.py), kept per
stage solve in `Run.routes`: the start its path NLP is solved from, whether a body at
rest is in the way, whether what it holds is, and the grid's proof that no path
exists (`Run.separated`)."""

from __future__ import annotations

import dataclasses

from tampcli.geometry.planar_route import RouteOptions, planar_route
from tampcli.optimize import relocate
from tampcli.optimize.collide import held_spec
from tampcli.optimize.path import allowed_contacts

ROUTE_ROOM = 0.03  # m: beyond the margin, the clearance a planar route pays nothing for


def route(run, ctx, left_out: frozenset[str] = frozenset()):
    """The planar robot's grid route (geometry/planar_route.py) of this motion, clear
    by the options' margin where it can be, or None; the bodies `left_out` ignored.
    Each asked once per stage solve (`motion.passable` asks before the motion's
    solve does)."""
    problem = run.problem
    key = _key(ctx, left_out)
    if key not in run.routes:
        opts = problem.options
        m = problem.motions[ctx.index]
        options = RouteOptions(clearance=opts.tight_margin, comfort=opts.margin + ROUTE_ROOM)
        report: dict = {}
        run.routes[key] = planar_route(
            run.checker, ctx.q_a, ctx.q_b, problem.world.lower, problem.world.upper,
            body_poses=ctx.moved, held=held_spec(ctx.held),
            ignore=allowed_contacts(m) | left_out, options=options, report=report)
        if report.get("separated"):
            run.separated.add(key)
    return run.routes[key]


def separated(run, ctx) -> bool:
    """Whether the planar motion `ctx`'s grid proves no path joins its ends, the
    bodies where they are (planar_route._separated): no sampling can find one."""
    if not run.problem.planar or route(run, ctx) is not None:
        return False
    return _key(ctx) in run.separated


def _key(ctx, left_out: frozenset[str] = frozenset()) -> tuple:
    return (ctx.index, ctx.q_a.tobytes(), ctx.q_b.tobytes(),
            None if ctx.held is None else (ctx.held.name, ctx.held.t),
            tuple(sorted((n, p.tobytes()) for n, p in ctx.moved.items())), left_out)


def route_around(run, ctx):
    """The grid route of the planar motion `ctx` with the bodies at rest left out
    (relocate.resting), where it has none with them; else None."""
    bodies = relocate.resting(run.problem, ctx)
    if not bodies or route(run, ctx) is not None:
        return None
    return route(run, ctx, bodies)


def held_blocks(run, ctx) -> bool:
    """Whether what the planar robot holds in the motion `ctx` is what leaves it no
    grid route: the robot alone has one. Only then may another grip pass (robust-planar
    pen-k4: the disk alone between two rails, where no face of the box makes room)."""
    return route(run, dataclasses.replace(ctx, held=None, grasp=None)) is not None
