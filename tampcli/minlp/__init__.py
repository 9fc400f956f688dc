"""The lesson's time-indexed MINLP (§2-§4) for the planar robot, solved globally by SCIP.

    solve_minlp(domain_path, problem_path, scene_path, modes_path, MinlpOptions()) -> Solution

Modules: footprint (bodies as polygons), bigm (implications with M from bounds),
symbolic (facts and actions as 0/1 variables), events (carry state), collide
(separation valid between waypoints), model (the whole program), extract
(SCIP's solution -> Solution), warm (a solution.json as SCIP's start), solve.
"""

from tampcli.minlp.options import MinlpOptions


def solve_minlp(domain_path, problem_path, scene_path=None, modes_path=None,
                options: MinlpOptions | None = None):
    """Imported lazily: pyscipopt is an optional extra (`pip install tampcli[minlp]`)."""
    from tampcli.minlp.solve import solve_minlp as run

    return run(domain_path, problem_path, scene_path, modes_path, options)


__all__ = ["MinlpOptions", "solve_minlp"]
