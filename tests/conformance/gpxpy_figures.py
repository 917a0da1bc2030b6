#!/usr/bin/python3
"""Prints gpxpy's figures for each GPX file given, one JSON object per line:
{"path", "ok", "points", "duration_s", "length_2d_m", "error"}.
Used by the conformance test, which compares them with `trailray stats --json` in the same run.
Run with Debian's /usr/bin/python3 (python3-gpxpy)."""
import json
import sys

import gpxpy


def figures(path):
    try:
        with open(path, encoding="utf-8-sig", errors="strict") as f:
            gpx = gpxpy.parse(f)
    except Exception as e:  # gpxpy cannot read it: the test skips this file
        return {"path": path, "ok": False, "error": f"{type(e).__name__}: {e}"}
    points = sum(len(s.points) for t in gpx.tracks for s in t.segments)
    duration = sum((s.get_duration() or 0.0) for t in gpx.tracks for s in t.segments)
    length = sum((s.length_2d() or 0.0) for t in gpx.tracks for s in t.segments)
    return {"path": path, "ok": True, "points": points, "duration_s": duration, "length_2d_m": length}


for p in sys.argv[1:]:
    print(json.dumps(figures(p)))
