"""arm-clutter: a Panda at a table, 3-6 boxes and cylinders, 1-3 of them to
goal regions (rectangles on the table, or squares on round mats), the others
in the way: a blocker inside a goal region, neighbours 1.5-4 cm from a target."""

import math

import numpy as np
import writers
from geom2d import Foot, bearing_range, distance, gap_along, inside, radial_range, rect

REACH = (0.30, 0.70)  # docs/robots.md: the Panda handles objects 0.3-0.7 m from its base
KEEP = 0.02  # kept inside that annulus, for margin
BEARING = math.radians(70)
TABLE = {"name": "table", "shape": "box", "size": [1.2, 1.4, 0.04], "pose": [0.3, 0.0, -0.02],
         "fixed": True, "color": [0.55, 0.4, 0.3, 1.0]}
TABLE_TOP = rect(-0.3, -0.7, 0.9, 0.7)
GRIP = 0.073  # widest the Panda takes across the gripped faces (opening 7.8 cm less 5 mm)
MAT_H = 0.01
TIGHT = (0.015, 0.04)
GOAL_COLORS = ["red", "green", "blue"]
OTHER_COLORS = ["yellow", "gray", "orange", "purple", "cyan", "brown"]


def q(x):
    """Sizes to 0.1 mm, so that a resting pose's z (half a height) is exact in the file."""
    return round(float(x), 4)


class Reject(Exception):
    """A draw broke one of the generator's sanity checks."""


def in_reach(foot):
    lo, hi = radial_range(foot)
    b0, b1 = bearing_range(foot)
    return lo >= REACH[0] + KEEP and hi <= REACH[1] - KEEP and -BEARING <= b0 and b1 <= BEARING


def draw_shape(rng, kind=None):
    """(shape, size, Foot at the origin, height, narrowest width)."""
    kind = kind or ("box" if rng.random() < 0.6 else "cylinder")
    if kind == "box":
        w = q(rng.uniform(0.03, GRIP - 0.005))
        length = q(rng.uniform(w, min(1.8 * w, 0.10)))
        h = q(rng.uniform(0.04, min(0.12, 2.5 * w)))
        return "box", [length, w, h], Foot("box", (0, 0), (length / 2, w / 2), rng.uniform(-math.pi, math.pi)), h, w
    r = q(rng.uniform(0.018, 0.033))
    h = q(rng.uniform(0.05, min(0.13, 5 * r)))
    return "cylinder", [r, h], Foot("disc", (0, 0), (r, r)), h, 2 * r


def random_center(rng, lo=0.36, hi=0.64):
    d, b = rng.uniform(lo, hi), rng.uniform(-BEARING + 0.15, BEARING - 0.15)
    return (d * math.cos(b), d * math.sin(b))


def footprint_need(shape, size):
    """The rectangle extents (x, y) the object needs in a region, one orientation."""
    if shape == "cylinder":
        return 2 * size[0], 2 * size[0]
    return size[0], size[1]


def draw_goal_region(rng, idx, shape, size, width, blocked):
    """A goal region for an object: (region dict, the area it takes: Foot, mat body or None, blocked side)."""
    nx, ny = footprint_need(shape, size)
    if rng.random() < 0.5:
        nx, ny = ny, nx
    if blocked:
        side = max(nx, ny) + rng.uniform(0.01, 0.025)
        sx = sy = side
    else:
        sx, sy = nx + rng.uniform(0.015, 0.05), ny + rng.uniform(0.015, 0.05)
    disc = rng.random() < 0.35
    if disc:
        side = max(sx, sy)
        sx = sy = side
    return {"name": f"goal{idx}", "size": [sx, sy], "disc": disc, "mat_r": max(sx, sy) / math.sqrt(2) + rng.uniform(0.006, 0.02)}


def place_region(rng, reg, taken):
    for _ in range(200):
        c = random_center(rng, 0.38, 0.62)
        area = Foot("disc", c, (reg["mat_r"],) * 2) if reg["disc"] else rect(c[0] - reg["size"][0] / 2, c[1] - reg["size"][1] / 2, c[0] + reg["size"][0] / 2, c[1] + reg["size"][1] / 2)
        if in_reach(area) and inside(area, TABLE_TOP) and all(distance(area, t) >= 0.04 for t in taken):
            reg["center"] = list(c)
            reg["area"] = area
            reg["rect"] = rect(c[0] - reg["size"][0] / 2, c[1] - reg["size"][1] / 2, c[0] + reg["size"][0] / 2, c[1] + reg["size"][1] / 2)
            return
    raise Reject("no room for a goal region")


def draw_blocker(rng, reg, goal_width):
    """A body centred in the blocked region that leaves no strip the goal object fits in."""
    side = reg["size"][0]
    need = side - 2 * (goal_width - 0.006)  # the blocker's least extent along both axes
    for _ in range(200):
        shape, size, foot, h, _ = draw_shape(rng)
        if shape == "box":
            foot = foot.moved((0, 0), rng.uniform(-0.3, 0.3))
        foot = foot.moved(np.add(reg["center"], rng.uniform(-0.004, 0.004, 2)))
        x0, y0, x1, y1 = foot.aabb()
        if min(x1 - x0, y1 - y0) > need and inside(foot, reg["rect"], 0.004):
            return shape, size, foot, h
    raise Reject("no blocker fits the blocked region")


def _body(name, shape, size, foot, h, base_z, color):
    return {"name": name, "shape": shape, "size": size, "color": color, "foot": foot, "h": h,
            "pose": [foot.center[0], foot.center[1], base_z + h / 2, foot.yaw if shape == "box" else 0.0]}


def _clear_of(foot, bodies, areas, gap=TIGHT[0]):
    home = rect(*foot.aabb())
    return (all(distance(foot, b["foot"]) >= gap for b in bodies)
            and all(distance(home, a) >= 0.008 for a in areas))


def draw(rng):
    n_obj = int(rng.integers(3, 7))
    n_goal = int(rng.integers(1, min(3, n_obj) + 1))
    blocked = n_obj - n_goal >= 1 and rng.random() < 0.5
    goals = [draw_shape(rng) for _ in range(n_goal)]
    regions, areas = [], []
    for i, (shape, size, _, _, width) in enumerate(goals):
        reg = draw_goal_region(rng, i + 1, shape, size, width, blocked and i == 0)
        place_region(rng, reg, areas)
        regions.append(reg)
        areas.append(reg["area"])
    bodies = []
    if blocked:
        shape, size, foot, h = draw_blocker(rng, regions[0], goals[0][4])
        bodies.append(_body(f"{'box' if shape == 'box' else 'cyl'}{len(goals) + 1}", shape, size, foot, h,
                            MAT_H if regions[0]["disc"] else 0.0, OTHER_COLORS[0]))
        bodies[-1]["at"] = "goal1"
    placed = []
    for i, (shape, size, foot, h, _) in enumerate(goals):
        for _ in range(300):
            f = foot.moved(random_center(rng), rng.uniform(-math.pi, math.pi))
            if placed and rng.random() < 0.4:
                f = gap_along(placed[int(rng.integers(len(placed)))]["foot"], f, rng.normal(size=2), rng.uniform(*TIGHT))
            if in_reach(f) and _clear_of(f, bodies, areas):
                break
        else:
            raise Reject("no room for a goal object")
        name = f"{'box' if shape == 'box' else 'cyl'}{i + 1}"
        body = _body(name, shape, size, f, h, 0.0, GOAL_COLORS[i])
        body["goal"] = f"goal{i + 1}"
        bodies.append(body)
        placed.append(body)
    for k in range(n_obj - n_goal - int(blocked)):
        shape, size, foot, h, _ = draw_shape(rng)
        around = rng.random() < 0.75
        for _ in range(300):
            if around:  # a neighbour: tightly beside a target
                target = placed[int(rng.integers(len(placed)))]["foot"]
                f = gap_along(target, foot.moved(target.center, rng.uniform(-math.pi, math.pi)), rng.normal(size=2), rng.uniform(*TIGHT))
            else:  # in the way of a region: beside it
                reg = regions[int(rng.integers(len(regions)))]
                f = gap_along(reg["area"], foot.moved(reg["center"], rng.uniform(-math.pi, math.pi)), rng.normal(size=2), rng.uniform(0.015, 0.05))
            if in_reach(f) and _clear_of(f, bodies, areas):
                break
        else:
            raise Reject("no room for a neighbour")
        idx = len(goals) + int(blocked) + k + 1
        bodies.append(_body(f"{'box' if shape == 'box' else 'cyl'}{idx}", shape, size, f, h, 0.0, OTHER_COLORS[(k + 1) % len(OTHER_COLORS)]))
        placed.append(bodies[-1])
    spare = None
    for _ in range(300):
        s = rng.uniform(0.12, 0.16)
        c = random_center(rng, 0.4, 0.6)
        area = rect(c[0] - s / 2, c[1] - s / 2, c[0] + s / 2, c[1] + s / 2)
        if in_reach(area) and all(distance(area, a) >= 0.03 for a in areas) and all(distance(area, rect(*b["foot"].aabb())) >= 0.03 for b in bodies):
            spare = {"name": "spare", "center": list(c), "size": [s, s], "disc": False, "area": area, "rect": area}
            break
    if spare is None:
        raise Reject("no room for the spare region")
    return bodies, regions, spare


def sanity(bodies, regions, spare):
    """The checks every instance passes; raises Reject."""
    for i, a in enumerate(bodies):
        if not in_reach(a["foot"]):
            raise Reject(f"{a['name']} out of reach")
        if a["shape"] == "box" and min(a["size"][:2]) > GRIP:
            raise Reject(f"{a['name']} too wide to grip")
        for b in bodies[i + 1:]:
            if distance(a["foot"], b["foot"]) < TIGHT[0] - 1e-4:
                raise Reject(f"{a['name']} and {b['name']} closer than 1.5 cm")
        for r in regions + [spare]:
            declared = a.get("at") == r["name"]
            if declared and not inside(a["foot"], r["rect"], 0.002):
                raise Reject(f"{a['name']} not inside its region {r['name']}")
            if not declared and distance(a["foot"], r["area"]) < 0.005:
                raise Reject(f"{a['name']} occupies region {r['name']} undeclared")
    gaps = [distance(a["foot"], b["foot"]) for i, a in enumerate(bodies) for b in bodies[i + 1:]]
    if not any(TIGHT[0] - 1e-4 <= g <= TIGHT[1] + 1e-4 for g in gaps):
        raise Reject("no tight pair")
    for r in regions + [spare]:
        if not inside(r["area"], TABLE_TOP, 0.01) or not in_reach(r["area"]):
            raise Reject(f"region {r['name']} off the table or out of reach")


def build(rng, seed):
    for attempt in range(5000):
        try:
            bodies, regions, spare = draw(rng)
            sanity(bodies, regions, spare)
            return emit(seed, bodies, regions, spare, attempt)
        except Reject:
            continue
    raise RuntimeError("arm-clutter: no valid draw in 5000 attempts")


def emit(seed, bodies, regions, spare, attempt):
    mats, region_rows = [], []
    for r in regions:
        on = "table"
        if r["disc"]:
            on = f"mat{r['name'][4:]}"
            mats.append({"name": on, "shape": "cylinder", "size": [r["mat_r"], MAT_H],
                         "pose": [r["center"][0], r["center"][1], MAT_H / 2], "fixed": True, "color": "white"})
        region_rows.append({"name": r["name"], "on": on, "center": r["center"], "size": r["size"]})
    homes = []
    for b in bodies:
        if "at" not in b:
            x0, y0, x1, y1 = b["foot"].aabb()
            b["at"] = f"home-{b['name']}"
            homes.append({"name": b["at"], "on": "table", "center": [(x0 + x1) / 2, (y0 + y1) / 2], "size": [x1 - x0 + 0.006, y1 - y0 + 0.006]})
    region_rows += homes + [{"name": "spare", "on": "table", "center": spare["center"], "size": spare["size"]}]
    goal_objs = [b for b in bodies if "goal" in b]
    blocker = [b for b in bodies if b["at"].startswith("goal")]
    gaps = sorted((distance(a["foot"], b["foot"]), a["name"], b["name"]) for i, a in enumerate(bodies) for b in bodies[i + 1:])
    header = [f"gen1 arm-clutter seed {seed} (generated by problems/gen1/generate.py, draw {attempt + 1}).",
              "A Panda at a table; " + ", ".join(f"{b['name']} -> {b['goal']}" for b in goal_objs)
              + (f"; {blocker[0]['name']} blocks goal1" if blocker else "") + ".",
              "Tightest gaps: " + ", ".join(f"{a}-{b} {g * 100:.1f} cm" for g, a, b in gaps[:3]) + "."]
    robot = {"model": "panda", "base": [0.0, 0.0, 0.0], "start": [0.0, -0.785, 0.0, -2.356, 0.0, 1.571, 0.785]}
    scene = writers.scene_toml(header, robot, [TABLE] + mats + bodies, region_rows, ([1.5, 1.0, 1.1], [0.45, 0.0, 0.05]))
    init = [f"(at {b['name']} {b['at']})" for b in bodies] + ["(handempty)"]
    goal = [f"(at {b['name']} {b['goal']})" for b in goal_objs]
    pddl = writers.problem_pddl(f"gen1-arm-clutter-s{seed:02d}", "gen1-arm-clutter", header,
                                {"block": [b["name"] for b in bodies], "region": [r["name"] for r in region_rows]}, init, goal)
    meta = {"family": "arm-clutter", "seed": seed, "robot": "panda", "objects": len(bodies),
            "goals": len(goal_objs), "blocker": blocker[0]["name"] if blocker else None,
            "disc_goals": sum(r["disc"] for r in regions), "min_gap_cm": round(gaps[0][0] * 100, 2),
            "expected_min_actions": 2 * len(goal_objs) + 2 * len(blocker)}
    return writers.CLUTTER_DOMAIN, writers.CLUTTER_MODES, pddl, scene, meta
