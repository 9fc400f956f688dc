"""arm-stack: a KUKA iiwa (even seeds) or an xArm6 (odd seeds) stacks 3-4
blocks of unequal sizes, largest at the bottom, on a base region; some start
stacked (always smaller on larger), in towers that are not the goal's."""

import math
from collections import deque

import writers
from gen_clutter import TABLE, Reject, q
from geom2d import Foot, bearing_range, distance, inside, radial_range, rect

ARMS = {  # docs/robots.md: reach, widest object gripped (opening less 5 mm), ready pose
    "kuka_iiwa": {"reach": (0.40, 0.75), "zone": ((0.15, 0.20), (0.20, 0.26)), "grip": 0.075, "start": [0.0, 0.6, 0.0, -1.3, 0.0, 1.24, 0.0]},
    "xarm6": {"reach": (0.25, 0.50), "zone": ((0.11, 0.14), (0.17, 0.22)), "grip": 0.082, "start": [0.0, -0.6, -0.9, 0.0, 1.5, 0.0]},
}
KEEP = 0.02
BEARING = math.radians(70)
NAMES = ["a", "b", "c", "d"]
COLORS = ["blue", "green", "red", "yellow"]


def in_reach(foot, reach):
    lo, hi = radial_range(foot)
    b0, b1 = bearing_range(foot)
    return lo >= reach[0] + KEEP and hi <= reach[1] - KEEP and -BEARING <= b0 and b1 <= BEARING


def draw_sizes(rng, n):
    """Sizes bottom first: each block's longer side below the narrower side of the one under it."""
    sizes = []
    hi = rng.uniform(0.056, 0.068)
    for _ in range(n):
        w = q(rng.uniform(hi - 0.006, hi))
        length = q(rng.uniform(w, max(w, hi)))
        h = q(rng.uniform(0.03, 0.05))
        sizes.append([length, w, h])
        hi = w - rng.uniform(0.005, 0.011)
    if hi < 0.022:
        raise Reject("blocks too small")
    return sizes


def draw_chains(rng, n):
    """Partition of block indices (0 = largest) into towers, each listed bottom first."""
    while True:
        order = list(rng.permutation(n))
        cuts = sorted(set(int(c) for c in rng.integers(1, n, size=int(rng.integers(1, n)))))
        chains = [sorted(order[i:j]) for i, j in zip([0] + cuts, cuts + [n], strict=False)]
        if any(len(c) >= 2 for c in chains) and chains != [list(range(n))]:
            return chains


def min_actions(n, chains, bottom_in_base):
    """Breadth-first search of pick/place moves; a block goes only on a larger block,
    the base region holds one block. State: each block's support (-1 zone, -2 base)."""
    start = [-1] * n
    for c in chains:
        for lower, upper in zip(c, c[1:], strict=False):
            start[upper] = lower
    if bottom_in_base is not None:
        start[bottom_in_base] = -2
    goal = tuple([-2] + list(range(n - 1)))
    seen = {tuple(start): 0}
    queue = deque([tuple(start)])
    while queue:
        s = queue.popleft()
        if s == goal:
            return seen[s]
        clear = [i for i in range(n) if i not in s]
        for b in clear:
            for to in [-1, -2] + [c for c in clear if c < b]:
                if to == s[b] or (to == -2 and -2 in s):
                    continue
                t = list(s)
                t[b] = to
                t = tuple(t)
                if t not in seen:
                    seen[t] = seen[s] + 2
                    queue.append(t)
    raise Reject("goal unreachable")


def draw(rng, arm, seed):
    reach = ARMS[arm]["reach"]
    n = 3 + (seed // 2) % 2  # 3 or 4 blocks, both with each arm over consecutive seeds
    sizes = draw_sizes(rng, n)
    chains = draw_chains(rng, n)
    side = 1 if rng.random() < 0.5 else -1
    mid = (reach[0] + reach[1]) / 2
    zone = base = None
    for _ in range(300):
        (w0, w1), (h0, h1) = ARMS[arm]["zone"]
        zw, zh = rng.uniform(w0, w1), rng.uniform(h0, h1)
        b = side * rng.uniform(0.35, 0.75)
        zc = (mid * math.cos(b), mid * math.sin(b))
        zone = rect(zc[0] - zw / 2, zc[1] - zh / 2, zc[0] + zw / 2, zc[1] + zh / 2)
        s = max(sizes[0][:2]) * math.sqrt(2) * 0.85 + rng.uniform(0.015, 0.04)
        bb = -side * rng.uniform(0.2, 0.7)
        d = rng.uniform(reach[0] + 0.08, reach[1] - 0.08)
        bc = (d * math.cos(bb), d * math.sin(bb))
        base = rect(bc[0] - s / 2, bc[1] - s / 2, bc[0] + s / 2, bc[1] + s / 2)
        if in_reach(zone, reach) and in_reach(base, reach) and distance(zone, base) >= 0.06:
            break
    else:
        raise Reject("no room for the regions")
    bottom_in_base = None
    feet = {}
    for chain in chains:
        low = chain[0]
        foot0 = Foot("box", (0, 0), (sizes[low][0] / 2, sizes[low][1] / 2))
        in_base = low == 0 and rng.random() < 0.4
        for _ in range(300):
            if in_base:
                f = foot0.moved(base.center, rng.uniform(-0.25, 0.25))
                ok = inside(f, base, 0.004)
            else:
                c = (rng.uniform(zone.aabb()[0], zone.aabb()[2]), rng.uniform(zone.aabb()[1], zone.aabb()[3]))
                f = foot0.moved(c, rng.uniform(-math.pi, math.pi))
                ok = inside(f, zone, 0.004) and all(distance(f, g) >= 0.025 for g in feet.values())
            if ok:
                break
        else:
            raise Reject("no room for a tower")
        feet[low] = f
        if in_base:
            bottom_in_base = low
        for lower, upper in zip(chain, chain[1:], strict=False):
            top = feet[lower]
            fu = Foot("box", (0, 0), (sizes[upper][0] / 2, sizes[upper][1] / 2))
            for _ in range(300):
                c = (top.center[0] + rng.uniform(-0.006, 0.006), top.center[1] + rng.uniform(-0.006, 0.006))
                g = fu.moved(c, top.yaw + rng.uniform(-0.15, 0.15))
                if inside(g, top, 0.002):
                    break
            else:
                raise Reject("a block does not fit on the one below")
            feet[upper] = g
    return n, sizes, chains, feet, zone, base, bottom_in_base


def build(rng, seed):
    arm = "kuka_iiwa" if seed % 2 == 0 else "xarm6"
    for attempt in range(5000):
        try:
            n, sizes, chains, feet, zone, base, bib = draw(rng, arm, seed)
            if max(min(s[:2]) for s in sizes) > ARMS[arm]["grip"]:
                raise Reject("too wide")
            if min_actions(n, chains, bib) < 4:
                raise Reject("too easy: one move finishes the tower")
            return emit(seed, arm, n, sizes, chains, feet, zone, base, bib, attempt, rng)
        except Reject:
            continue
    raise RuntimeError("arm-stack: no valid draw in 5000 attempts")


def emit(seed, arm, n, sizes, chains, feet, zone, base, bib, attempt, rng):
    names = [NAMES[i] for i in rng.permutation(n)]  # names not in size order
    below, z0 = {}, {}
    for chain in chains:
        z = 0.0
        for i, b in enumerate(chain):
            below[b] = chain[i - 1] if i else None
            z0[b] = z
            z += sizes[b][2]
    bodies = [{"name": names[i], "shape": "box", "size": sizes[i], "color": COLORS[i],
               "pose": [feet[i].center[0], feet[i].center[1], z0[i] + sizes[i][2] / 2, feet[i].yaw]} for i in range(n)]
    init = []
    for i in range(n):
        if below[i] is None:
            init.append(f"(at {names[i]} {'base' if i == bib else 'zone'})")
        else:
            init.append(f"(on {names[i]} {names[below[i]]})")
        if i not in below.values():
            init.append(f"(clear {names[i]})")
    init.append("(handempty)")
    goal = [f"(at {names[0]} base)"] + [f"(on {names[i]} {names[i - 1]})" for i in range(1, n)]
    towers = "; ".join("-".join(names[b] for b in reversed(c)) for c in chains)
    header = [f"gen1 arm-stack seed {seed} (generated by problems/gen1/generate.py, draw {attempt + 1}).",
              f"A {arm} stacks {'-'.join(names[i] for i in reversed(range(n)))} (top first) on region base.",
              f"Start towers (top first): {towers}."]
    regions = [{"name": "zone", "on": "table", "center": list(zone.center), "size": [2 * zone.half[0], 2 * zone.half[1]]},
               {"name": "base", "on": "table", "center": list(base.center), "size": [2 * base.half[0], 2 * base.half[1]]}]
    robot = {"model": arm, "base": [0.0, 0.0, 0.0], "start": ARMS[arm]["start"]}
    scene = writers.scene_toml(header, robot, [TABLE] + bodies, regions, ([1.5, 1.0, 1.1], [0.4, 0.0, 0.1]))
    pddl = writers.problem_pddl(f"gen1-arm-stack-s{seed:02d}", "gen1-arm-stack", header,
                                {"block": sorted(names), "region": ["zone", "base"]}, init, goal)
    meta = {"family": "arm-stack", "seed": seed, "robot": arm, "objects": n,
            "expected_min_actions": min_actions(n, chains, bib), "start_towers": towers}
    return writers.STACK_DOMAIN, writers.STACK_MODES, pddl, scene, meta
