"""--force and --forbid, the flags of `plan` and `solve` (both methods) that hold
plans to a user's choice of ground actions (task/restrict.py)."""

from __future__ import annotations


def add_restriction(p) -> None:
    p.add_argument("--force", dest="forced", action="append", default=[], metavar="ACTION",
                   help="a ground action the plan must contain, e.g. \"(pick box start)\" "
                        "(repeat the flag for several)")
    p.add_argument("--forbid", dest="forbidden", action="append", default=[],
                   metavar="ACTION", help="a ground action the plan must not contain")
