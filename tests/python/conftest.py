"""What the module's tests share: the real data (../shared/data), the command line to compare
with, and the files of every format. ctest sets TRAILRAY_SHARED_DATA, TRAILRAY_BINARY and
PYTHONPATH (tests/CMakeLists.txt)."""

import json
import os
import pathlib
import subprocess

import pytest

SHARED = pathlib.Path(os.environ.get("TRAILRAY_SHARED_DATA", pathlib.Path(__file__).parents[2] / ".." / "shared" / "data"))
BINARY = os.environ.get("TRAILRAY_BINARY", "")

# The track formats and where the shared data keeps them.
FORMAT_FOLDERS = {
    "gpx": ["gpx"],
    "igc": ["igc"],
    "tcx": ["tcx"],
    "fit": ["fit"],
    "kml": ["kml"],
    "geojson": ["geojson"],
}
TRACK_SUFFIXES = {".gpx", ".igc", ".tcx", ".fit", ".kml", ".kmz", ".geojson", ".gz"}


def shared(relative: str) -> pathlib.Path:
    """A path under ../shared/data, or the test skips with a clear message."""
    path = SHARED / relative
    if not path.exists():
        pytest.skip(f"shared test data absent: {path} (tests that read ../shared/data skip without it)")
    return path


def shared_track_files():
    """Every track file of the shared data, one per format folder entry (empty without the data)."""
    files = []
    for folders in FORMAT_FOLDERS.values():
        for folder in folders:
            root = SHARED / folder
            if root.is_dir():
                files += sorted(p for p in root.iterdir() if p.is_file() and p.suffix.lower() in TRACK_SUFFIXES
                                and not p.name.endswith(".expected.gpx"))
    return files


def run_cli(*args, check=True):
    """`trailray ARGS...` -> (exit status, stdout, stderr)."""
    assert BINARY, "TRAILRAY_BINARY is not set (ctest sets it)"
    done = subprocess.run([BINARY, *map(str, args)], capture_output=True, text=True, timeout=300)
    if check and done.returncode != 0:
        raise AssertionError(f"trailray {' '.join(map(str, args))} failed ({done.returncode}): {done.stderr}")
    return done.returncode, done.stdout, done.stderr


def cli_json(*args):
    """The JSON document a command prints (also when it exits 1 for a file it could not read)."""
    code, out, err = run_cli(*args, check=False)
    assert out, f"trailray {' '.join(map(str, args))} printed nothing ({code}): {err}"
    return json.loads(out)


def surface_pair_walk(folder: pathlib.Path, points: int = 41):
    """The shared lidar pair of one forest (dem/SURFACE_PAIR.json): its terrain and surface models,
    and a GPX of `points` points without elevations along its line, written into `folder`."""
    pair_file = shared("dem/SURFACE_PAIR.json")
    pair = json.loads(pair_file.read_text())
    (a_lat, a_lon), (b_lat, b_lon) = pair["line"]
    n = points - 1
    trkpts = "".join(f'<trkpt lat="{a_lat + (b_lat - a_lat) * i / n}" lon="{a_lon + (b_lon - a_lon) * i / n}"/>'
                     for i in range(points))
    walk = folder / "walk.gpx"
    walk.write_text(f'<gpx version="1.1" creator="t"><trk><trkseg>{trkpts}</trkseg></trk></gpx>')
    return str(pair_file.parent / pair["dtm"]), str(pair_file.parent / pair["dsm"]), walk
