"""Headless replay of a solution.json and video export.

    solution.json + scene -> replay.py (a state per frame, even timing)
                          -> frames.py (PyBullet TinyRenderer in worker processes, captions)
                          -> video.py  (mp4 / gif / keyframe strip)

`video.render_solution` is the library entry point (`solve --video` calls it);
`tampcli.cli.render` is the command.
"""
