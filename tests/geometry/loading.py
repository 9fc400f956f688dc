"""Load a scene as a solve (and `check`) does: read it, build its one World and
CollisionChecker, and check the start state with them."""

from tampcli.geometry.collision import CollisionChecker
from tampcli.geometry.scene import read_scene
from tampcli.geometry.startcheck import check_start_state
from tampcli.geometry.world import World


def load_checked(path, domain=None, problem=None, modes=None):
    scene, source = read_scene(path, domain, problem, modes)
    with World(scene) as world:
        check_start_state(world, CollisionChecker(world), source)
    return scene
