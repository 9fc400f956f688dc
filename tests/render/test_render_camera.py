"""Camera parsing, validation and automatic framing; options validation; captions."""

import math

import numpy as np
import pytest

from tampcli.errors import UsageError
from tampcli.render.camera import Camera, auto_camera, box_corners, choose_camera, parse_camera
from tampcli.render.captions import Captioner
from tampcli.render.encode import keyframe_strip, strip_geometry
from tampcli.render.options import RenderOptions, video_format


def test_parse_camera():
    assert parse_camera(["eye=1,2,3", "target=0,0,0.5", "fov=40"]) == {
        "eye": (1.0, 2.0, 3.0), "target": (0.0, 0.0, 0.5), "fov": 40.0}
    assert parse_camera("up=0,1,0") == {"up": (0.0, 1.0, 0.0)}
    # one string with the fields apart by blanks, ";" or a comma before a name
    for spec in ("eye=1,2,3 target=0,0,0.5", "eye=1,2,3,target=0,0,0.5",
                 " eye=1, 2, 3;target=0,0,.5"):
        assert parse_camera(spec) == {"eye": (1.0, 2.0, 3.0), "target": (0.0, 0.0, 0.5)}, spec
    assert parse_camera(["eye=1,1,1 fov=30", "eye=2,2,2"]) == {"eye": (2.0, 2.0, 2.0),
                                                               "fov": 30.0}  # the later wins


@pytest.mark.parametrize("spec", ["eye=1,2", "look=1,2,3", "eye", "fov=1,2", "target=x,1,2",
                                  "fov=0", "fov=nan", "eye=1,1,1,look=0,0,0"])
def test_parse_camera_refuses(spec):
    with pytest.raises(UsageError) as err:
        parse_camera(spec)
    assert err.value.key == "--camera"


@pytest.mark.parametrize("fields", [
    {"eye": (1, 1, 1), "target": (1, 1, 1)},
    {"eye": (0, 0, 1), "target": (0, 0, 0)},  # looking straight down with up = z
    {"eye": (1, 0, 0), "target": (0, 0, 0), "fov": 0.5},
    {"eye": (1, 0, math.nan), "target": (0, 0, 0)},
])
def test_camera_refuses(fields):
    with pytest.raises(UsageError):
        Camera(**fields)


def _project(camera: Camera, points, aspect):
    eye, target = np.array(camera.eye), np.array(camera.target)
    forward = (target - eye) / np.linalg.norm(target - eye)
    right = np.cross(forward, camera.up)
    right /= np.linalg.norm(right)
    up = np.cross(right, forward)
    rel = points - eye
    depth = rel @ forward
    tan_v = math.tan(math.radians(camera.fov) / 2)
    return (rel @ right) / depth / (tan_v * aspect), (rel @ up) / depth / tan_v


@pytest.mark.parametrize("lo,hi", [((-0.3, -0.6, -0.04), (0.9, 0.6, 0.8)),
                                   ((0, 0, 0), (2, 0.1, 0.1)), ((-5, -5, 0), (5, 5, 0.2))])
@pytest.mark.parametrize("aspect", [4 / 3, 0.5])
def test_auto_camera_fits_and_fills_the_frame(lo, hi, aspect):
    points = box_corners(lo, hi)
    x, y = _project(auto_camera(points, aspect=aspect), points, aspect)
    assert max(np.abs(x).max(), np.abs(y).max()) <= 1.0  # all inside
    assert max(np.abs(x).max(), np.abs(y).max()) > 0.9  # and no wider than needed
    assert abs(x.max() + x.min()) < 0.05 or abs(y.max() + y.min()) < 0.05  # centred


@pytest.mark.parametrize("reserve", [0.1, 0.3])
def test_auto_camera_keeps_the_caption_band_free(reserve):
    points = box_corners((-0.3, -0.6, -0.04), (0.9, 0.6, 0.8))
    _, y = _project(auto_camera(points, reserve_bottom=reserve), points, 4 / 3)
    bottom = -(1 - 2 * reserve)  # the band's top edge, in the same units as y
    assert y.min() >= bottom - 1e-9 and y.max() <= 1.0
    assert y.min() - bottom < 0.06 or 1.0 - y.max() < 0.06  # still fills the rest


def test_choose_camera_precedence():
    points = box_corners((0, 0, 0), (1, 1, 1))
    scene = Camera((3.0, 0.0, 1.0), (0.0, 0.0, 0.0))
    assert choose_camera(None, scene, points, 1.0) == scene
    assert choose_camera({"fov": 30.0}, scene, points, 1.0).fov == 30.0
    auto = choose_camera({"eye": (0.0, 4.0, 2.0)}, None, points, 1.0)
    assert auto.eye == (0.0, 4.0, 2.0) and auto.target != (0.0, 0.0, 0.0)


def test_options_validate():
    assert RenderOptions().worker_count >= 1
    for bad in ({"width": 8}, {"height": 10_000}, {"fps": 0}, {"workers": -1},
                {"duration": 0.0}, {"speed": -1.0}, {"pause": 60.0}):
        with pytest.raises(UsageError):
            RenderOptions(**bad)
    assert video_format("a.GIF", 161, 121) == "gif"  # a GIF may have odd sizes
    with pytest.raises(UsageError, match="even"):
        video_format("a.mp4", 161, 120)


def test_caption_draws_in_the_bar_only():
    frame = np.full((120, 160, 3), 255, dtype=np.uint8)
    captioner = Captioner(160, 120)
    out = captioner.draw(frame, "(pick a very long action name that cannot fit) x y z",
                         "step 1/2   p01")
    assert out.shape == frame.shape
    assert (out[: 120 - captioner.bar] == 255).all()
    bar = out[120 - captioner.bar:]
    assert bar.mean() < 150 and (bar.max(axis=2) > 200).any()  # dark bar, light text


def test_caption_without_truetype_fonts():
    from tampcli.render.captions import load_font

    font = load_font(14, names=("no-such-font.ttf",))
    assert font.getbbox("step 1/2")[2] > 0


def test_keyframe_strip_layout():
    panels = [np.full((10, 20, 3), i * 40, dtype=np.uint8) for i in range(6)]
    strip = keyframe_strip(panels)
    assert strip.shape[:2][::-1] == strip_geometry(6, 20, 10)
    assert strip.shape == (24, 92, 3)  # two rows of four, 4-pixel gaps
    assert (strip[14:, 48:] == 255).all()  # empty slots of the last row stay white
