#!/usr/bin/env python3
"""Benchmark: heatmaps of many generated tracks (issue "heatmaps on Dask"). Prints figures, never
fails for time.

Generates TRACKS random walks of POINTS points (10 m steps, spread over 30 km x 30 km near
Innsbruck) into FILES gzip-compressed GPX files, then times, RUNS times each, interleaved:
  trailray heatmap (the command line, whole process, with its peak memory),
  trailray.heatmap (Python, one process, every core),
  trailray.dask.heatmap on a LocalCluster of 1 worker process, then of 2 (one thread each),
and prints the medians, the ratios, and what a million tracks would cost at the measured rate.

  PYTHONPATH=build/python /usr/bin/python3 bench/heatmap_speed.py [--tracks 10000] [--points 1000]
      [--files 100] [--cell 50] [--runs 3] [--binary build/src/app/trailray] [--keep DIR]
"""

import argparse
import gzip
import logging
import math
import os
import random
import statistics
import subprocess
import sys
import tempfile
import time


def generate(folder, tracks, points, files):
    rng = random.Random(7)
    per_file = -(-tracks // files)
    made = 0
    for f in range(files):
        with gzip.open(os.path.join(folder, f"tracks-{f:05d}.gpx.gz"), "wt", compresslevel=1) as out:
            out.write('<?xml version="1.0"?>\n<gpx version="1.1" creator="heatmap_speed.py">\n')
            for _ in range(min(per_file, tracks - made)):
                lat, lon = 47.1 + rng.uniform(-0.135, 0.135), 11.4 + rng.uniform(-0.2, 0.2)
                heading = rng.uniform(0, 2 * math.pi)
                rows = []
                for _ in range(points):
                    heading += rng.gauss(0, 0.3)
                    lat += 10 * math.cos(heading) / 111320
                    lon += 10 * math.sin(heading) / (111320 * math.cos(math.radians(lat)))
                    rows.append(f'<trkpt lat="{lat:.6f}" lon="{lon:.6f}"/>')
                out.write("<trk><trkseg>" + "".join(rows) + "</trkseg></trk>\n")
                made += 1
            out.write("</gpx>\n")


def timed(function):
    start = time.perf_counter()
    result = function()
    return time.perf_counter() - start, result


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--tracks", type=int, default=10000)
    parser.add_argument("--points", type=int, default=1000)
    parser.add_argument("--files", type=int, default=100)
    parser.add_argument("--cell", type=float, default=50.0)
    parser.add_argument("--runs", type=int, default=3)
    parser.add_argument("--binary", default="build/src/app/trailray")
    parser.add_argument("--keep", help="generate into (or reuse) this folder")
    a = parser.parse_args()

    import trailray
    import trailray.dask
    import distributed

    folder = a.keep or tempfile.mkdtemp(prefix="trailray-heatmap-bench-")
    os.makedirs(folder, exist_ok=True)
    if not any(n.endswith(".gpx.gz") for n in os.listdir(folder)):
        t, _ = timed(lambda: generate(folder, a.tracks, a.points, a.files))
        print(f"bench: generated {a.tracks} tracks of {a.points} points in {a.files} files in {t:.1f} s")
    size = sum(os.path.getsize(os.path.join(folder, n)) for n in os.listdir(folder))
    print(f"bench: host {os.cpu_count()} cores, load {' '.join(open('/proc/loadavg').read().split()[:3])}")
    print(f"bench: {folder}: {len(os.listdir(folder))} files, {size / 2**20:.0f} MiB gzip, cell {a.cell:g} m, "
          f"{a.runs} runs each, medians")

    out = os.path.join(tempfile.mkdtemp(), "heat.tif")
    times = {"cli": [], "python": [], "dask 1 worker": [], "dask 2 workers": []}
    peak_kib = []
    clusters = {}
    for name, workers in (("dask 1 worker", 1), ("dask 2 workers", 2)):
        cluster = distributed.LocalCluster(n_workers=workers, threads_per_worker=1, processes=True, host="127.0.0.1",
                                           dashboard_address=":0", silence_logs=logging.ERROR)
        clusters[name] = (cluster, distributed.Client(cluster))
    reference = None
    try:
        for _ in range(a.runs):
            t, done = timed(lambda: subprocess.run(["/usr/bin/time", "-f", "%M", a.binary, "heatmap", folder, "-o", out,
                                                    "--cell", str(a.cell), "--force"], capture_output=True, text=True))
            if done.returncode != 0:
                sys.exit(f"bench: trailray heatmap failed: {done.stderr}")
            times["cli"].append(t)
            peak_kib.append(int(done.stderr.strip().splitlines()[-1]))
            t, h = timed(lambda: trailray.heatmap(folder, cell=a.cell))
            times["python"].append(t)
            reference = h
            for name, (_, client) in clusters.items():
                t, hd = timed(lambda: trailray.dask.heatmap(folder, client=client, cell=a.cell))
                times[name].append(t)
                assert (hd.counts == h.counts).all(), f"{name}: counts differ"
    finally:
        for cluster, client in clusters.values():
            client.close()
            cluster.close()

    m = {k: statistics.median(v) for k, v in times.items()}
    tracks = reference.tracks
    print(f"{'':24} {'median s':>9} {'tracks/s':>10}")
    for k, v in m.items():
        print(f"{k:24} {v:9.2f} {tracks / v:10.0f}")
    print(f"cli peak memory {statistics.median(peak_kib) / 1024:.0f} MiB; grid {reference.counts.shape[1]}x"
          f"{reference.counts.shape[0]} cells, at most {int(reference.counts.max())} tracks in a cell")
    print(f"dask: 2 workers / 1 worker time {m['dask 2 workers'] / m['dask 1 worker']:.2f}; "
          f"cli / python {m['cli'] / m['python']:.2f}")
    per_track = m["cli"] / tracks
    print(f"a million tracks of {a.points} points at the command's rate: {per_track * 1e6 / 60:.1f} min on this "
          f"{os.cpu_count()}-core machine (the reading is most of it: divide by the machines of a cluster)")


if __name__ == "__main__":
    main()
