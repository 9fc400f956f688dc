"""Trajectory optimization for a fixed skeleton: the seed's V(d) (sections 2, 5).

For a fixed sequence of actions the continuous problem is an ordinary NLP,
solved with SLSQP and exact Jacobians, in three stages of growing cost:

    problem.lower(skeleton, scene, modes, world, options) -> TrajectoryProblem
    solve.solve(problem, "final" | "reach" | "keyframes" | "path", warm) -> TrajectoryResult
    verify.verify(problem, result) -> [violations in words]

Modules: options (OptimizeOptions), problem (lowering), skeleton (steps,
motion phases), kinds (what each mode kind means, through every stage),
layout (the NLPs' blocks of variables), values (keyframes, grip choices and
placements handed between stages), bodies (extents, supports), grips (tool
frame, held objects), expr (values with Jacobians over named variable
blocks), constraints (placement, grasp, reach rows), collide (collision
rows), stages (final / keyframe NLPs), path (per-phase path NLPs, via
points), init (IK keyframes), nlp (the SLSQP driver), backends (the path
stage's solvers: SLSQP, Ipopt in ipopt_backend), assemble (trajectory,
phases, object poses), verify, result; run (a stage solve's bookkeeping),
keyframe_stage and path_stage (the stages), relocate (objects moved out of a
later motion's way); relaxed (the planar skeleton's convex QP without
collisions in motion: a proved lower bound of its cost) on convex_qp (a QP
solved with a duality certificate) and relaxed_apart (boxes put down apart:
a disjunction branched on).
"""
