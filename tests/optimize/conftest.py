import os

import pytest

from tampcli.geometry.world import World

from .helpers import load_modes, load_scene

os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")


@pytest.fixture(scope="module")
def wall():
    scene = load_scene("wall")
    with World(scene) as world:
        yield scene, load_modes("arm-pick-place"), world


@pytest.fixture(scope="module")
def planar():
    scene = load_scene("planar")
    with World(scene) as world:
        yield scene, load_modes("planar-push"), world
