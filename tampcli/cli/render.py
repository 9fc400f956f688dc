"""`tampcli render SOLUTION.json`: replay a solution headlessly; export a video,
a keyframe strip, and (with --physics) how far dynamics drift from the plan."""

from __future__ import annotations

from pathlib import Path

from rich.table import Table

from tampcli.errors import ExitCode
from tampcli.render.camera import parse_camera
from tampcli.render.options import RenderOptions


def add_parser(p) -> None:
    p.add_argument("solution", help="solution.json written by `tampcli solve`")
    p.add_argument("--video", metavar="FILE",
                   help="output video, .mp4 (H.264) or .gif (default: SOLUTION.mp4 beside it, "
                        "unless only --keyframes or --physics is asked)")
    p.add_argument("--keyframes", metavar="FILE",
                   help="also write one image (.png/.jpg) with a panel per geometric action")
    p.add_argument("--width", type=int, default=_default("width"),
                   help="frame width in pixels (default %(default)s)")
    p.add_argument("--height", type=int, default=_default("height"),
                   help="frame height in pixels (default %(default)s)")
    p.add_argument("--fps", type=float, default=_default("fps"),
                   help="frames per second (default %(default)g)")
    # One value per flag, so the solution path may come after it.
    p.add_argument("--camera", action="append", metavar="'FIELD=VALUE ...'",
                   help="quoted: --camera 'eye=x,y,z target=x,y,z [up=x,y,z] [fov=degrees]', "
                        "or one field per flag: --camera eye=x,y,z --camera target=x,y,z; "
                        "fields left out come from the scene's [camera], else the scene is "
                        "framed automatically")
    p.add_argument("--workers", type=int, default=_default("workers"),
                   help="render processes (default %(default)s: one per core)")
    p.add_argument("--duration", type=float, default=_default("duration"),
                   help="seconds of robot motion, pauses excluded (default: from the speed)")
    p.add_argument("--speed", type=float, default=_default("speed"),
                   help="joint-space speed, rad/s (m/s for the planar robot)")
    p.add_argument("--pause", type=float, default=_default("pause"),
                   help="seconds held at each instantaneous action (default %(default)g)")
    p.add_argument("--no-caption", action="store_true", help="frames without the caption bar")
    p.add_argument("--physics", action="store_true",
                   help="also replay with PyBullet dynamics and report object drift")


def _default(field: str):
    """RenderOptions' default of `field` (a dataclass keeps it as a class attribute)."""
    return getattr(RenderOptions, field)


def options_from_args(args) -> RenderOptions:
    """The RenderOptions of the parsed flags of `tampcli render`."""
    return RenderOptions(
        width=args.width, height=args.height, fps=args.fps,
        camera=parse_camera(args.camera) if args.camera else None, workers=args.workers,
        duration=args.duration, speed=args.speed, pause=args.pause, physics=args.physics,
        caption=not args.no_caption)


def run(args, ui) -> int:
    from tampcli.render.video import render_solution

    options = options_from_args(args)
    video = args.video
    if video is None and args.keyframes is None and not options.physics:
        video = str(Path(args.solution).with_suffix(".mp4"))
    report = render_solution(args.solution, video, options, ui, keyframes=args.keyframes)
    if ui.json:
        ui.emit_json({"status": "ok", **report})
        return ExitCode.OK
    if report.get("path"):
        ui.print(f"wrote {report['path']}: {report['frames']} frames, {report['width']}x"
                 f"{report['height']} at {report['fps']:g} fps ({report['seconds']:.1f} s of "
                 f"video) in {report['render_seconds']:.1f} s with {report['workers']} "
                 f"worker{'s' if report['workers'] != 1 else ''}")
    if report.get("keyframes"):
        ui.print(f"wrote {report['keyframes']}: {report['panels']} keyframe panels")
    if "physics" in report:
        _print_physics(ui, report["physics"])
    return ExitCode.OK


def _print_physics(ui, physics: dict) -> None:
    table = Table(title=f"physics replay ({physics['seconds']:.1f} s simulated, "
                        f"{physics['steps']} steps)")
    for column in ("object", "drift (m)", "rotation (deg)", "planned xyz", "simulated xyz"):
        table.add_column(column, justify="left" if column == "object" else "right")
    for name, row in physics["objects"].items():
        table.add_row(name, f"{row['distance']:.4f}", f"{row['angle_deg']:.1f}",
                      _xyz(row["planned"]), _xyz(row["simulated"]))
    ui.print(table)
    ui.print(f"largest drift {physics['max_distance']:.4f} m; the robot tracked its "
             f"trajectory within {physics['tracking_error']:.3f} (rad or m) per joint")


def _xyz(values) -> str:
    return " ".join(f"{v:.3f}" for v in values[:3])
