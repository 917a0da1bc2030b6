#!/usr/bin/python3
"""Writes a big synthetic GPX track for the benchmark, formatted like a Garmin Connect export.

    /usr/bin/python3 bench/make_big_gpx.py OUTPUT.gpx [--points N]     (default N = 120000)

A long bike ride recorded every second (with a few auto-pause gaps): lat/lon in exact decimal
expansions of Garmin semicircles, elevation as exact float32 expansions, times with
milliseconds, heart rate and cadence in a Garmin TrackPointExtension (ns3:), two-space
indentation, one element per line -- the layout of `alpinemaps_husarentempel.gpx` in
shared/data, about 390 bytes a point. Deterministic: a fixed seed, stdlib only, the same bytes
on every run. SYNTHETIC data (creator says so); never commit the output.
"""

import math
import random
import struct
import sys
from datetime import datetime, timedelta, timezone
from decimal import Decimal

SEED = 1009
START = datetime(2023, 6, 17, 3, 58, 12, tzinfo=timezone.utc)
SEMI = 180.0 / 2.0 ** 31  # degrees per Garmin semicircle


def exact(x):
    """The exact decimal expansion of a binary float, as Garmin Connect prints it."""
    s = format(Decimal(x), "f")
    if "." in s:
        s = s.rstrip("0").rstrip(".")
    return s if s not in ("-0", "") else "0"


def as_float32(x):
    return struct.unpack("<f", struct.pack("<f", x))[0]


def semicircle_degrees(deg):
    return round(deg / SEMI) * SEMI


def main():
    args = sys.argv[1:]
    if not args or args[0].startswith("-"):
        sys.exit("usage: make_big_gpx.py OUTPUT.gpx [--points N]")
    out_path = args[0]
    points = 120000
    if len(args) >= 3 and args[1] == "--points":
        points = int(args[2])

    rng = random.Random(SEED)
    lat, lon = 47.05, 8.30  # central Switzerland
    heading = 40.0
    heading_rate = 0.0
    t = 0.0
    hr = 95.0
    speed = 0.0
    # Terrain: a fixed sum of waves over the distance ridden, 300-1400 m.
    waves = [(rng.uniform(2000.0, 40000.0), rng.uniform(0, 2 * math.pi), rng.uniform(20.0, 180.0))
             for _ in range(12)]
    dist = 0.0

    def terrain(d):
        return 850.0 + sum(a * math.sin(2 * math.pi * d / wl + ph) for wl, ph, a in waves)

    head = (
        '<?xml version="1.0" encoding="UTF-8"?>\n'
        '<gpx creator="trailray bench/make_big_gpx.py (synthetic)" version="1.1"\n'
        '  xsi:schemaLocation="http://www.topografix.com/GPX/1/1 http://www.topografix.com/GPX/11.xsd"\n'
        '  xmlns:ns3="http://www.garmin.com/xmlschemas/TrackPointExtension/v1"\n'
        '  xmlns="http://www.topografix.com/GPX/1/1"\n'
        '  xmlns:xsi="http://www.w3.org/2001/XMLSchema-instance"'
        ' xmlns:ns2="http://www.garmin.com/xmlschemas/GpxExtensions/v3">\n'
        '  <metadata>\n'
        '    <link href="connect.garmin.com">\n'
        '      <text>Garmin Connect</text>\n'
        '    </link>\n'
        '    <time>%s</time>\n'
        '  </metadata>\n'
        '  <trk>\n'
        '    <name>Synthetic benchmark ride</name>\n'
        '    <type>cycling</type>\n'
        '    <trkseg>\n' % START.strftime("%Y-%m-%dT%H:%M:%S.000Z"))

    chunks = [head]
    buf = []
    m_per_deg_lat = 111132.0
    for i in range(points):
        grade = (terrain(dist + 5.0) - terrain(dist - 5.0)) / 10.0
        # Speed: ~30 km/h on the flat, slower uphill, faster downhill; a slow start.
        target = max(2.5, min(17.0, 8.3 - 60.0 * grade + rng.gauss(0.0, 0.3)))
        speed += (target - speed) * 0.08
        heading_rate = 0.97 * heading_rate + rng.gauss(0.0, 0.35)
        heading = (heading + heading_rate) % 360.0
        step = speed  # 1 s
        dist += step
        lat += step * math.cos(math.radians(heading)) / m_per_deg_lat
        lon += step * math.sin(math.radians(heading)) / (m_per_deg_lat * math.cos(math.radians(lat)))
        ele = terrain(dist) + rng.gauss(0.0, 0.15)
        effort = 0.6 * speed + 900.0 * max(0.0, grade * speed / 8.0)
        hr += (min(185.0, 100.0 + 4.0 * effort) - hr) * 0.03
        cad = 0 if grade < -0.04 and rng.random() < 0.7 else int(82 + rng.gauss(0.0, 4.0))
        # Auto-pause: now and then a stop of 1-5 minutes leaves a gap in the times.
        t += 1.0
        if rng.random() < 0.0004:
            t += rng.uniform(60.0, 300.0)
            hr = max(90.0, hr - 35.0)
            speed = 0.0
        when = START + timedelta(seconds=t)
        buf.append(
            '      <trkpt lat="%s" lon="%s">\n'
            '        <ele>%s</ele>\n'
            '        <time>%s.000Z</time>\n'
            '        <extensions>\n'
            '          <ns3:TrackPointExtension>\n'
            '            <ns3:hr>%d</ns3:hr>\n'
            '            <ns3:cad>%d</ns3:cad>\n'
            '          </ns3:TrackPointExtension>\n'
            '        </extensions>\n'
            '      </trkpt>\n'
            % (exact(semicircle_degrees(lat)), exact(semicircle_degrees(lon)), exact(as_float32(ele)),
               when.strftime("%Y-%m-%dT%H:%M:%S"), int(round(hr + rng.gauss(0.0, 1.0))), cad))
        if len(buf) >= 4096:
            chunks.append("".join(buf))
            buf = []
    chunks.append("".join(buf))
    chunks.append('    </trkseg>\n  </trk>\n</gpx>\n')
    with open(out_path, "w", encoding="utf-8", newline="\n") as f:
        for c in chunks:
            f.write(c)


if __name__ == "__main__":
    main()
