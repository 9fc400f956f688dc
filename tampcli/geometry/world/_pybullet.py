"""The PyBullet modules, imported once for the World package.

PyBullet writes "pybullet build time: ..." on the process's stderr (fd 2, from
C) when imported: that line is kept off what users read.
"""

from __future__ import annotations


def _import_pybullet():
    import os
    import sys

    sys.stderr.flush()
    try:
        saved = os.dup(2)
    except OSError:  # no fd 2 to silence
        import pybullet as pb
        import pybullet_data as data
        return pb, data
    try:
        quiet = os.open(os.devnull, os.O_WRONLY)
        os.dup2(quiet, 2)
        os.close(quiet)
        import pybullet as pb
        import pybullet_data as data
    finally:
        os.dup2(saved, 2)
        os.close(saved)
    return pb, data


pybullet, pybullet_data = _import_pybullet()
