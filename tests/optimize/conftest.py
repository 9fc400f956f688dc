import pytest

from tampcli.geometry.world import World

from .helpers import load


def _world(name):
    _, _, scene, modes = load(name)
    with World(scene) as world:
        yield scene, modes, world


@pytest.fixture(scope="module")
def wall():
    yield from _world("wall")


@pytest.fixture(scope="module")
def planar():
    yield from _world("planar")
