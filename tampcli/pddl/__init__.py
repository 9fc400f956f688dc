"""The PDDL front end: grammar, AST, parser, semantic checks, printer."""
