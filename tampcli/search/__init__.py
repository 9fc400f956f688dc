"""Search over a grounded Task: heuristics, searches, top-k, plan validation."""
