#!/usr/bin/python3
"""Benchmark: reading a GPX file and computing its statistics from Python, trailray against gpxpy.

trailray: `trailray.read(path)` then `stats()` of every track. gpxpy: `gpxpy.parse()` then, per
track, `length_3d()`, `get_duration()`, `get_uphill_downhill()` and `get_moving_data()` --
roughly the same work: distance, duration, climb, moving time. Runs are interleaved (trailray,
gpxpy, trailray, ...) so that the machine's drift falls on both alike; medians are printed.
Prints figures and never judges them; exits non-zero only when the file is missing.

    PYTHONPATH=build/python /usr/bin/python3 bench/python_read_speed.py [FILE.gpx] [--runs N]

FILE defaults to the largest GPX in ../shared/data/gpx; N to 7. Use Debian's /usr/bin/python3
(python3-numpy, python3-gpxpy) and a Release build of the module.
"""
import argparse
import os
import platform
import statistics
import sys
import time
import warnings
from pathlib import Path

import gpxpy
import numpy
import trailray

SHARED_GPX = Path(__file__).resolve().parent.parent.parent / "shared" / "data" / "gpx"


def largest_gpx(folder):
    files = sorted(folder.glob("*.gpx"), key=lambda p: p.stat().st_size, reverse=True)
    return files[0] if files else None


def with_trailray(path):
    for track in trailray.read(path).tracks:
        track.stats()


def with_gpxpy(path):
    with open(path, encoding="utf-8") as f:
        gpx = gpxpy.parse(f)
    for track in gpx.tracks:
        track.length_3d()
        track.get_duration()
        track.get_uphill_downhill()
        track.get_moving_data()


def milliseconds(work, path):
    start = time.perf_counter()
    work(path)
    return (time.perf_counter() - start) * 1e3


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("file", nargs="?", type=Path, help="a GPX file (default: the largest in %s)" % SHARED_GPX)
    parser.add_argument("--runs", type=int, default=7, help="runs of each tool (default 7)")
    args = parser.parse_args()
    path = args.file or largest_gpx(SHARED_GPX)
    if path is None or not path.is_file():
        sys.exit("bench: no GPX file: %s not found" % (path or "%s/*.gpx" % SHARED_GPX))

    # A reader warning (something repaired) would print once per run; it is not what is measured.
    warnings.simplefilter("ignore", trailray.TrailrayWarning)
    points = sum(len(t) for t in trailray.read(path).tracks)
    print("bench: host %d cores, load %.2f %.2f %.2f" % ((os.cpu_count(),) + os.getloadavg()))
    print("bench: Python %s, NumPy %s, gpxpy %s, trailray module %s"
          % (platform.python_version(), numpy.__version__, gpxpy.__version__, os.path.dirname(trailray.__file__)))
    print("bench: %s, %d bytes, %d track points" % (path.name, path.stat().st_size, points))

    tools = {"trailray": with_trailray, "gpxpy": with_gpxpy}
    for work in tools.values():
        work(path)  # warm-up: the file in the page cache, the modules' lazy imports done
    times = {name: [] for name in tools}
    for _ in range(args.runs):
        for name, work in tools.items():
            times[name].append(milliseconds(work, path))
    median = {name: statistics.median(t) for name, t in times.items()}

    print("bench: medians of %d interleaved runs, read + statistics in one Python process" % args.runs)
    for name in tools:
        print("%-9s %10.1f ms" % (name, median[name]))
    print("gpxpy/trailray %.1fx" % (median["gpxpy"] / median["trailray"]))


if __name__ == "__main__":
    main()
