"""Geometry: scene and modes files, the PyBullet world, kinematics and collision distances.

scene.py / modes.py read the files (locate.py finds them); world/ owns the
simulator and the robot's kinematics (chain.py, ik.py); collision.py answers
signed-distance queries with joint gradients, one configuration or a batch
(parts.py, shapes.py; broad.py and obb.py screen the pairs of a batch,
pairs.py answers them and certify.py checks FCL's answers for all of them at
once; narrow.py, prism.py, gjk.py answer one pair); report.py summarizes a
scene for `tampcli check`.
"""
