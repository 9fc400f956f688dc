"""Many problems -> results.jsonl: discovery, one process per problem, resume.

    discover.py      PATH... -> Jobs (problem + its domain, found the IPC ways)
    child.py         the child's entry point: memory limit, test hooks, then exec of the CLI
    runner.py        one Job -> one child process -> one Result (limits enforced here)
    outcome.py       a finished child (exit status, stdout, stderr) -> Result fields
    results.py       Result and the append-only, fsynced, resumable results file
    local.py         a thread pool over runner (one machine)
    dask_backend.py  the same jobs on a Dask cluster (optional extra)
    summary.py       results -> counts and times per status and per domain, CSV
"""
