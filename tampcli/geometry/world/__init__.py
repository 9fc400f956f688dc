"""The World: the one owner of the PyBullet simulator.

PyBullet is imported nowhere else in tampcli. The modules beside this one are
the World's own parts and are used by it alone:

    _world.py     World: loads a Scene, answers kinematic and geometric queries
    _pybullet.py  the pybullet and pybullet_data modules (imported quietly)
    _load.py      scene bodies and the planar robot into a client
    _measure.py   a loaded body read into numpy: its Chain, collision shapes, boxes
    _dynamics.py  Dynamics: gravity, joint motors and a grasp (the physics replay)
"""

from tampcli.geometry.world._world import PANDA_FINGERS, World

__all__ = ["PANDA_FINGERS", "World"]
