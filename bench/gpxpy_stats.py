#!/usr/bin/python3
"""The gpxpy side of bench/stats_speed.sh: parse one GPX file and compute what
`trailray stats` reports first -- 2D length and duration. Run with Debian's /usr/bin/python3
(python3-gpxpy)."""
import sys

import gpxpy

with open(sys.argv[1], encoding="utf-8") as f:
    gpx = gpxpy.parse(f)
points = sum(len(s.points) for t in gpx.tracks for s in t.segments)
print("points %d length_2d %.1f m duration %.0f s" % (points, gpx.length_2d(), gpx.get_duration() or 0.0))
