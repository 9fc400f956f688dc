"""Grounding: lifted PDDL -> Task with integer facts and frozenset states."""
