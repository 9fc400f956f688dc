"""Physics replay of every library problem: how far each object ends from its plan.

Each problem with a scene (problems/*/pNN.scene.toml) is solved with `tampcli
solve` (default options), then its solution replayed as `validate --physics`
does (tampcli/render/physics.py). The table gives, per problem, the largest
final position and rotation drift over its objects, the object they belong
to, the verdict at the default tolerances (1 cm, 5 degrees), the first phase
beyond them, and the replay's simulated and wall time.
Run: .venv/bin/python bench/physics.py; writes bench/results/physics.md.
"""

from __future__ import annotations

import json
import os
import platform
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))

from tampcli.render.inputs import load_inputs, mode_kind_of  # noqa: E402
from tampcli.render.physics import replay_physics  # noqa: E402
from tampcli.render.physics_values import drift_violations  # noqa: E402

OUT = ROOT / "bench" / "results" / "physics.md"
MAX_DRIFT, MAX_TURN = 0.01, 5.0


def solve(scene: Path, out: Path) -> float:
    domain = ROOT / "domains" / scene.parent.name / "domain.pddl"
    problem = scene.parent / (scene.name.split(".")[0] + ".pddl")
    start = time.perf_counter()
    subprocess.run([sys.executable, "-m", "tampcli", "solve", "--quiet", "--out", str(out),
                    str(domain), str(problem)], cwd=ROOT, check=True, capture_output=True)
    return time.perf_counter() - start


def row(scene: Path, folder: Path) -> str:
    key = f"{scene.parent.name}/{scene.name.split('.')[0]}"
    out = folder / f"{key.replace('/', '-')}.json"
    solve_seconds = solve(scene, out)
    if json.loads(out.read_text())["status"] != "solved":
        return f"| {key} | not solved | | | | | | {solve_seconds:.1f} |"
    inputs = load_inputs(out)
    start = time.perf_counter()
    replay = replay_physics(inputs, mode_kind_of(inputs.modes))
    wall = time.perf_counter() - start
    far = max(replay.objects, key=lambda o: o.distance)
    turned = max(replay.objects, key=lambda o: o.angle_deg)
    bad = drift_violations(replay, MAX_DRIFT, MAX_TURN)
    verdict = "valid" if not bad else "invalid: " + ", ".join(v.drift.name for v in bad)
    first = min((v.first.phase for v in bad if v.first is not None), default=None)
    where = "-" if not bad else ("after the last" if first is None else
                                 next(f"{v.first.phase}: {v.first.label}" for v in bad
                                      if v.first is not None and v.first.phase == first))
    return (f"| {key} | {far.distance * 1000:.1f} ({far.name}) | "
            f"{turned.angle_deg:.1f} ({turned.name}) | {verdict} | {where} | "
            f"{replay.seconds:.1f} | {wall:.1f} | {solve_seconds:.1f} |")


def main() -> None:
    os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")
    # The library's scenes; the blind robustness sets are bench/robustness.py's.
    scenes = sorted(s for s in ROOT.glob("problems/*/*.scene.toml")
                    if not s.parent.name.startswith("robust-"))
    load = [os.getloadavg()[0]]
    rows = []
    with tempfile.TemporaryDirectory() as folder:
        for scene in scenes:
            rows.append(row(scene, Path(folder)))
            print(rows[-1], flush=True)
            load.append(os.getloadavg()[0])
    lines = [
        "# Physics replay benchmark",
        "",
        f"`bench/physics.py` on {platform.machine()}, {os.cpu_count()} cores, load average "
        f"(1 min) {min(load):.1f} .. {max(load):.1f} over the runs (a shared machine: wall "
        "times are inflated by other jobs).",
        "Each library problem with a scene is solved (`tampcli solve`, default options) and "
        "its solution replayed with dynamics as `validate --physics` does "
        "(docs/physics.md). Drift = final simulated pose against the planned one; the "
        f"verdict uses the default tolerances, {MAX_DRIFT * 100:g} cm and {MAX_TURN:g} "
        "degrees; \"first beyond\" is the first phase (index: action) at whose end an "
        "object was beyond them.",
        "",
        "| problem | largest drift (mm, object) | largest turn (deg, object) | verdict | "
        "first beyond | simulated (s) | replay wall (s) | solve wall (s) |",
        "| --- | ---: | ---: | --- | --- | ---: | ---: | ---: |",
        *rows,
        "",
        "An invalid row is a plan that physics refuses; "
        "tests/render/test_physics_validate.py expects none.",
        "",
    ]
    OUT.write_text("\n".join(lines))
    print(f"wrote {OUT}")


if __name__ == "__main__":
    main()
