"""planar: the planar disk robot on a bench with 3-8 fixed walls and posts,
2-4 objects to bring to goal regions by pick + place, and in some instances
a crate that may not be lifted, to push along a face's normal."""

import math

import numpy as np
import writers
from gen_clutter import Reject, q
from geom2d import Foot, distance, inside, rect

R, H, Z = 0.05, 0.05, 0.035  # the disk: radius, height, centre (hovering 1 cm, as the library does)
OBST_H = 0.1
ROBOT_CLEAR = 2 * R + 0.02  # room kept between objects/goals and obstacles: the disk passes
GRID = 0.01
COLORS = ["red", "green", "blue", "orange"]


def draw_obstacles(rng, bench):
    n = int(rng.integers(3, 9))
    n_walls = int(rng.integers(1, n))
    bx, by = bench.half
    out = []
    for i in range(n):
        if i < n_walls:
            t = q(rng.uniform(0.02, 0.03))
            if rng.random() < 0.4:  # a partition from an edge of the bench: a passage at its far end
                along_x = rng.random() < 0.5
                span = 2 * (by if along_x else bx)
                length = q(rng.uniform(0.4, 0.7) * span)
                end = rng.choice([-1, 1]) * (span / 2 - length / 2)
                off = rng.uniform(-0.6, 0.6) * (bx if along_x else by)
                yaw = math.pi / 2 if along_x else 0.0
                center = (off, end) if along_x else (end, off)
            else:
                length = q(rng.uniform(0.25, 0.7))
                yaw = float(rng.choice([0.0, math.pi / 2, rng.uniform(-math.pi, math.pi)], p=[0.4, 0.4, 0.2]))
                center = (rng.uniform(-bx + 0.1, bx - 0.1), rng.uniform(-by + 0.1, by - 0.1))
            foot = Foot("box", center, (length / 2, t / 2), yaw)
            body = {"name": f"wall{i + 1}", "shape": "box", "size": [length, t, OBST_H], "yaw": yaw}
        else:
            r = q(rng.uniform(0.03, 0.07))
            foot = Foot("disc", (rng.uniform(-bx + 0.1, bx - 0.1), rng.uniform(-by + 0.1, by - 0.1)), (r, r))
            body = {"name": f"post{i - n_walls + 1}", "shape": "cylinder", "size": [r, OBST_H], "yaw": 0.0}
        if not inside(foot, bench):
            raise Reject("obstacle off the bench")
        body.update(foot=foot, fixed=True, color=[0.3, 0.3, 0.3, 1.0],
                    pose=[foot.center[0], foot.center[1], OBST_H / 2, body["yaw"]])
        out.append(body)
    return out


def clearance_map(bench, obstacles):
    """Grid over the bench: each point's distance to the nearest obstacle footprint."""
    x0, y0, x1, y1 = bench.aabb()
    xs, ys = np.arange(x0, x1 + 1e-9, GRID), np.arange(y0, y1 + 1e-9, GRID)
    px, py = np.meshgrid(xs, ys, indexing="ij")
    clear = np.full(px.shape, np.inf)
    for o in obstacles:
        f = o["foot"]
        dx, dy = px - f.center[0], py - f.center[1]
        if f.kind == "disc":
            d = np.hypot(dx, dy) - f.half[0]
        else:
            c, s = math.cos(f.yaw), math.sin(f.yaw)
            lx, ly = np.abs(c * dx + s * dy) - f.half[0], np.abs(-s * dx + c * dy) - f.half[1]
            d = np.hypot(np.maximum(lx, 0), np.maximum(ly, 0)) + np.minimum(np.maximum(lx, ly), 0)
        clear = np.minimum(clear, d)
    return xs, ys, clear


def components(free):
    """Connected components (4-neighbour) of a boolean grid."""
    label = np.full(free.shape, -1)
    k = 0
    for start in zip(*np.nonzero(free), strict=False):
        if label[start] >= 0:
            continue
        stack = [start]
        label[start] = k
        while stack:
            i, j = stack.pop()
            for a, b in ((i + 1, j), (i - 1, j), (i, j + 1), (i, j - 1)):
                if 0 <= a < free.shape[0] and 0 <= b < free.shape[1] and free[a, b] and label[a, b] < 0:
                    label[a, b] = k
                    stack.append((a, b))
        k += 1
    return label


def cell(xs, ys, p):
    return int(round((p[0] - xs[0]) / GRID)), int(round((p[1] - ys[0]) / GRID))


def draw_object(rng, crate):
    if crate:
        w, length = q(rng.uniform(0.07, 0.10)), q(rng.uniform(0.07, 0.11))
        return "box", [length, w, 0.05], Foot("box", (0, 0), (length / 2, w / 2))
    if rng.random() < 0.7:
        w, length = q(rng.uniform(0.04, 0.08)), q(rng.uniform(0.04, 0.09))
        return "box", [length, w, q(rng.uniform(0.04, 0.06))], Foot("box", (0, 0), (length / 2, w / 2))
    r = q(rng.uniform(0.025, 0.045))
    return "cylinder", [r, 0.05], Foot("disc", (0, 0), (r, r))


def draw(rng, push):
    bw, bd = q(rng.uniform(1.4, 1.8)), q(rng.uniform(1.0, 1.3))
    bench = rect(-bw / 2, -bd / 2, bw / 2, bd / 2)
    obstacles = draw_obstacles(rng, bench)
    xs, ys, clear = clearance_map(bench, obstacles)
    n_obj = int(rng.integers(2, 5))
    objects, goals, lanes = [], [], []
    taken = [o["foot"] for o in obstacles]

    def free_spot(foot, keep, others, gap):
        for _ in range(300):
            f = foot.moved((rng.uniform(-bw / 2 + 0.12, bw / 2 - 0.12), rng.uniform(-bd / 2 + 0.12, bd / 2 - 0.12)), foot.yaw)
            if all(distance(f, t) >= keep for t in taken) and all(distance(f, o) >= gap for o in others):
                return f
        raise Reject("no free spot")

    for i in range(n_obj):
        crate = push and i == 0
        shape, size, foot = draw_object(rng, crate)
        foot = foot.moved((0, 0), rng.uniform(-math.pi, math.pi) if shape == "box" else 0.0)
        f = free_spot(foot, ROBOT_CLEAR, [o["foot"] for o in objects] + [g["area"] for g in goals] + lanes, 0.10)
        name = ("crate" if crate else ("box" if shape == "box" else "cyl")) + str(i + 1)
        obj = {"name": name, "shape": shape, "size": size, "foot": f, "color": COLORS[i], "liftable": not crate,
               "pose": [f.center[0], f.center[1], size[-1] / 2, f.yaw]}
        nx, ny = (2 * size[0],) * 2 if shape == "cylinder" else (2 * f.radius(),) * 2
        if crate:  # pushed along its first face's normal (+x of its frame, either way)
            u = np.array([math.cos(f.yaw), math.sin(f.yaw)]) * rng.choice([-1, 1])
            dist = rng.uniform(0.2, 0.4)
            gc = np.array(f.center) + dist * u
            s = 2 * f.radius() + rng.uniform(0.05, 0.08)
            area = rect(gc[0] - s / 2, gc[1] - s / 2, gc[0] + s / 2, gc[1] + s / 2)
            back = np.array(f.center) - (f.half[0] + R + 0.01) * u
            for t in np.linspace(0, 1, 30):  # the corridor of the push, the disk behind the crate
                p = back + t * (gc - back)
                i_, j_ = cell(xs, ys, p)
                if not (0 <= i_ < len(xs) and 0 <= j_ < len(ys)) or clear[i_, j_] < max(R, f.radius()) + 0.03:
                    raise Reject("push corridor blocked")
            lanes += [Foot("disc", tuple(back + t * (gc - back)), (max(R, f.radius()),) * 2) for t in np.linspace(0, 1, 8)]
        else:
            s = max(nx, ny) + rng.uniform(0.03, 0.07)
            area = free_spot(rect(-s / 2, -s / 2, s / 2, s / 2), ROBOT_CLEAR, [o["foot"] for o in objects] + [f] + [g["area"] for g in goals] + lanes, 0.08)
        if not inside(area, bench, 0.02) or any(distance(area, t) < ROBOT_CLEAR for t in taken):
            raise Reject("goal region off the bench or too near an obstacle")
        obj["goal"] = f"goal{i + 1}"
        objects.append(obj)
        goals.append({"name": obj["goal"], "area": area})
    for g in goals:
        for o in objects:
            if distance(g["area"], o["foot"]) < 0.03:
                raise Reject("goal region occupied")
    for a, g in enumerate(goals):
        for h in goals[a + 1:]:
            if distance(g["area"], h["area"]) < 0.03:
                raise Reject("goal regions overlap")
    start = None
    for _ in range(300):
        p = (rng.uniform(-bw / 2 + 0.1, bw / 2 - 0.1), rng.uniform(-bd / 2 + 0.1, bd / 2 - 0.1))
        disk = Foot("disc", p, (R, R))
        if all(distance(disk, t) >= 0.03 for t in taken + [o["foot"] for o in objects] + [g["area"] for g in goals]):
            start = p
            break
    if start is None:
        raise Reject("no room for the robot")
    carry = max(max(R, o["foot"].radius()) for o in objects) + 0.015
    label = components(clear >= carry)
    keys = [start] + [o["foot"].center for o in objects] + [g["area"].center for g in goals]
    comps = {label[cell(xs, ys, k)] for k in keys}
    if len(comps) != 1 or -1 in comps:
        raise Reject("no passage: start, objects and goals not connected")
    return bench, obstacles, objects, goals, start, push


def build(rng, seed):
    for attempt in range(20000):
        try:
            return emit(seed, *draw(rng, seed % 2 == 0), attempt)  # even seeds push a crate
        except Reject:
            continue
    raise RuntimeError("planar: no valid draw in 20000 attempts")


def emit(seed, bench, obstacles, objects, goals, start, push, attempt):
    bench_body = {"name": "bench", "shape": "box", "size": [2 * bench.half[0], 2 * bench.half[1], 0.04],
                  "pose": [0.0, 0.0, -0.02], "fixed": True, "color": [0.55, 0.4, 0.3, 1.0]}
    regions = []
    for o in objects:
        x0, y0, x1, y1 = o["foot"].aabb()
        regions.append({"name": f"home{o['name'][-1]}", "on": "bench", "center": [(x0 + x1) / 2, (y0 + y1) / 2],
                        "size": [x1 - x0 + 0.02, y1 - y0 + 0.02]})
        o["home"] = regions[-1]["name"]
    for g in goals:
        x0, y0, x1, y1 = g["area"].aabb()
        regions.append({"name": g["name"], "on": "bench", "center": [(x0 + x1) / 2, (y0 + y1) / 2], "size": [x1 - x0, y1 - y0]})
    header = [f"gen1 planar seed {seed} (generated by problems/gen1/generate.py, draw {attempt + 1}).",
              f"A planar disk, {len(obstacles)} obstacles; " + ", ".join(
                  f"{o['name']} -> {o['goal']}{' (push only)' if not o['liftable'] else ''}" for o in objects) + "."]
    robot = {"model": "planar", "base": [start[0], start[1], Z], "start": list(start), "radius": R, "height": H}
    scene = writers.scene_toml(header, robot, [bench_body] + obstacles + objects, regions, ([0.0, -1.3, 1.9], [0.0, 0.0, 0.0]))
    init = [f"(at {o['name']} {o['home']})" for o in objects] + [f"(liftable {o['name']})" for o in objects if o["liftable"]]
    init += [f"(region-on {r['name']} bench)" for r in regions] + ["(handempty)", "(= (total-cost) 0)"]
    goal = [f"(at {o['name']} {o['goal']})" for o in objects]
    pddl = writers.problem_pddl(f"gen1-planar-s{seed:02d}", "gen1-planar", header,
                                {"item": [o["name"] for o in objects], "region": [r["name"] for r in regions], "surface": ["bench"]},
                                init, goal, metric=True)
    meta = {"family": "planar", "seed": seed, "robot": "planar", "objects": len(objects), "obstacles": len(obstacles),
            "push": push, "expected_min_actions": sum(2 if o["liftable"] else 1 for o in objects)}
    return writers.PLANAR_DOMAIN, writers.PLANAR_MODES, pddl, scene, meta
