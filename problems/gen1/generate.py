"""Random tampcli problem instances from a seed (numpy and the standard library only).

    python problems/gen1/generate.py --family arm-clutter --seed 3 --out DIR
    python problems/gen1/generate.py --all            # the committed set, beside this file

Each instance is a self-contained folder: domain.pddl, modes.toml,
problem.pddl, problem.scene.toml (found by tampcli as the problem's name with
.pddl replaced by .scene.toml) and instance.json (what the generator drew:
counts, the expected least number of actions). The same family and seed
always give the same files.
"""

import argparse
import json
import sys
import zlib
from pathlib import Path

import gen_clutter
import gen_planar
import gen_stack
import numpy as np

FAMILIES = {"arm-clutter": gen_clutter.build, "arm-stack": gen_stack.build, "planar": gen_planar.build}
COMMITTED = {"arm-clutter": range(1, 7), "arm-stack": range(1, 6), "planar": range(1, 6)}


def generate(family, seed, out):
    # the family's name in the seed keeps the families' draws independent
    rng = np.random.default_rng([zlib.crc32(family.encode()), seed])
    domain, modes, problem, scene, meta = FAMILIES[family](rng, seed)
    out = Path(out)
    out.mkdir(parents=True, exist_ok=True)
    (out / "domain.pddl").write_text(domain)
    (out / "modes.toml").write_text(modes)
    (out / "problem.pddl").write_text(problem)
    (out / "problem.scene.toml").write_text(scene)
    (out / "instance.json").write_text(json.dumps(meta, indent=1) + "\n")
    return meta


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--family", choices=sorted(FAMILIES))
    ap.add_argument("--seed", type=int)
    ap.add_argument("--out")
    ap.add_argument("--all", action="store_true", help="write the committed set beside this script")
    args = ap.parse_args(argv)
    if args.all:
        here = Path(__file__).resolve().parent
        for family, seeds in COMMITTED.items():
            for seed in seeds:
                meta = generate(family, seed, here / f"{family}-s{seed:02d}")
                print(json.dumps(meta))
        return 0
    if args.family is None or args.seed is None or args.out is None:
        ap.error("give --family, --seed and --out, or --all")
    print(json.dumps(generate(args.family, args.seed, args.out)))
    return 0


if __name__ == "__main__":
    sys.exit(main())
