"""Geometry: scene and modes files, the PyBullet world, kinematics and collision distances.

scene.py / modes.py read the files; world.py owns the simulator and the
robot's kinematics (chain.py, ik.py); collision.py answers signed-distance
queries with joint gradients (parts.py, shapes.py, narrow.py, gjk.py);
report.py summarizes a scene for `tampcli check`.
"""
