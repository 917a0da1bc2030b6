#!/usr/bin/python3
"""Prints gpxpy's figures for each GPX file given, one JSON object per line:
{"path", "ok", "points", "duration_s", "length_2d_m", "gpxpy_blind_segments", "error"}.

gpxpy's segment duration looks for a timestamp only in the first two and the last two points
(GPXTrackSegment.get_duration). Where a segment has timed points but none there, gpxpy says
"unknown" while trailray (and the issue's definition: last minus first timestamp) measures
it. For those segments, duration_s uses the first and last timed point of gpxpy's own parse,
and gpxpy_blind_segments counts them so the test can say so.
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
    duration, blind = 0.0, 0
    for t in gpx.tracks:
        for s in t.segments:
            d = s.get_duration()
            timed = [p.time for p in s.points if p.time]
            if d is None and len(timed) >= 2:
                blind += 1
                d = (timed[-1] - timed[0]).total_seconds()
            duration += d or 0.0
    length = sum((s.length_2d() or 0.0) for t in gpx.tracks for s in t.segments)
    return {"path": path, "ok": True, "points": points, "duration_s": duration, "length_2d_m": length,
            "gpxpy_blind_segments": blind}


for p in sys.argv[1:]:
    print(json.dumps(figures(p)))
