"""RRT-Connect's edge checks asked in batches, against OMPL's own validator (one
configuration a call), on the scenes of problems whose motions fall back on sampling.

Per scene: PAIRS pairs of collision-free configurations drawn uniformly (seeded), a
`sampled_path` query between each (budget CHECKS validity checks, seeded), once with
the batched edge check (`tampcli.geometry.sampled_path`, the default) and once with
OMPL's DiscreteMotionValidator, alternating, ROUNDS times. Both must find the same
paths (the batched check asks what OMPL would and counts as it does); the table gives
the median time of each and their ratio.

    .venv/bin/python bench/sampling.py [--rounds N]

writes bench/results/sampling.md.
"""

from __future__ import annotations

import argparse
import os
import platform
import statistics
import sys
import time
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))

from tampcli.geometry import sampled_path as sp  # noqa: E402
from tampcli.geometry.collision import CollisionChecker  # noqa: E402
from tampcli.geometry.scene import load_scene  # noqa: E402
from tampcli.geometry.world import World  # noqa: E402

OUT = Path(__file__).parent / "results" / "sampling.md"
SCENES = ("problems/blind29/p01/p01.scene.toml",   # a Panda reaching into a booth
          "problems/arm-kitchen/p01.scene.toml",   # the library's kitchen (Panda)
          "problems/blind13/p04/p04.scene.toml",   # KUKA, a can between tall walls
          "problems/blind3/p03/p03.scene.toml",    # a doorway
          "problems/blind7/p03/p03.scene.toml")    # a maze (planar)
PAIRS, CHECKS = 6, 4000


def free_pairs(world, checker, rng) -> list[tuple[np.ndarray, np.ndarray]]:
    found = []
    while len(found) < 2 * PAIRS:
        q = rng.uniform(world.lower, world.upper)
        if all(c.distance > 0.01 for c in checker.distances(q, None, None, frozenset(), 0.02)):
            found.append(q)
    return list(zip(found[0::2], found[1::2], strict=True))


def queries(world, checker, pairs, own: bool) -> tuple[float, list]:
    batched = sp._batched_edges
    if own:
        sp._batched_edges = lambda *args: None  # OMPL's own validator
    try:
        start = time.perf_counter()
        paths = [sp.sampled_path(checker, a, b, world.lower, world.upper,
                                 options=sp.SamplingOptions(checks=CHECKS, seed=k + 1,
                                                            clearance=0.005))
                 for k, (a, b) in enumerate(pairs)]
        return time.perf_counter() - start, paths
    finally:
        sp._batched_edges = batched


def same(first: list, second: list) -> bool:
    return all((a is None and b is None) or (a is not None and b is not None
                                             and a.shape == b.shape and np.array_equal(a, b))
               for a, b in zip(first, second, strict=True))


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--rounds", type=int, default=3)
    args = parser.parse_args()
    started, load = time.time(), os.getloadavg()
    rows = []
    for scene in SCENES:
        with World(load_scene(ROOT / scene), visuals=False) as world:
            checker = CollisionChecker(world)
            pairs = free_pairs(world, checker, np.random.default_rng(1))
            times = {False: [], True: []}
            agree, found = True, 0
            for _ in range(args.rounds):
                t_batched, batched = queries(world, checker, pairs, own=False)
                t_own, own = queries(world, checker, pairs, own=True)
                times[False].append(t_batched)
                times[True].append(t_own)
                agree &= same(batched, own)
                found = sum(p is not None for p in batched)
            own_s, batched_s = statistics.median(times[True]), statistics.median(times[False])
            rows.append((scene, found, agree, own_s, batched_s))
            print(f"{scene}: found {found}/{PAIRS}, same {agree}, own {own_s:.2f} s, "
                  f"batched {batched_s:.2f} s, {own_s / batched_s:.2f}x", flush=True)
    lines = ["# Sampling: edge checks in batches against OMPL's own validator", "",
             f"`bench/sampling.py --rounds {args.rounds}` on {platform.machine()}, "
             f"{os.cpu_count()} cores, Python {platform.python_version()}; load average "
             f"{load[0]:.2f} at the start, {os.getloadavg()[0]:.2f} at the end; "
             f"{time.time() - started:.0f} s in all. Per scene {PAIRS} queries between "
             f"random collision-free configurations, {CHECKS} validity checks each, "
             "clearance 5 mm; median of the rounds, run alternately. *same paths*: every "
             "query's path identical under both (as they must be).", "",
             "| scene | paths found | same paths | OMPL's own s | batched s | speed-up |",
             "| --- | ---: | --- | ---: | ---: | ---: |"]
    for scene, found, agree, own_s, batched_s in rows:
        lines.append(f"| {scene} | {found}/{PAIRS} | {'yes' if agree else '**no**'} | "
                     f"{own_s:.2f} | {batched_s:.2f} | {own_s / batched_s:.2f}x |")
    OUT.write_text("\n".join(lines) + "\n")
    print(f"wrote {OUT}")
    return 0 if all(r[2] for r in rows) else 1


if __name__ == "__main__":
    sys.exit(main())
