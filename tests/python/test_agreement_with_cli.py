"""trailray.read and Track.stats give what the command line gives, on the shared files of every
format: the statistics of `stats --json` key for key, the points of `convert --format csv`, and
the same error for a file the command line cannot read."""

import csv
import io
import math
import warnings

import numpy as np
import pytest

import trailray
from conftest import cli_json, run_cli, shared, shared_track_files

FILES = shared_track_files()


def test_the_shared_data_has_every_format():
    shared("gpx")
    formats = set()
    for path in FILES:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", trailray.TrailrayWarning)
            try:
                formats.add(trailray.read(path).format)
            except trailray.ReadError:
                pass
    assert formats >= {"gpx", "igc", "tcx", "fit", "kml", "kmz", "geojson"}


def read_quietly(path):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", trailray.TrailrayWarning)
        return trailray.read(path)


@pytest.mark.parametrize("path", FILES, ids=lambda p: p.name)
def test_statistics_equal_stats_json(path):
    document = cli_json("stats", "--json", path)
    expected = document["files"][0]
    if "error" in expected:
        with pytest.raises(trailray.ReadError) as raised:
            read_quietly(path)
        assert str(raised.value) == expected["error"]
        return
    f = read_quietly(path)
    assert f.format == expected["format"]
    assert len(f.routes) == expected["routes"]
    assert len(f.waypoints) == expected["waypoints"]
    # The reader's own warnings come first in the command's list (cleaning's follow).
    assert f.warnings == expected["warnings"][: len(f.warnings)]
    assert len(f.tracks) == len(expected["tracks"])
    for track, want in zip(f.tracks, expected["tracks"]):
        assert track.stats() == want


def csv_rows(path):
    code, out, err = run_cli("convert", path, "-o", "-", "--format", "csv", check=False)
    assert code == 0, err
    return list(csv.DictReader(io.StringIO(out)))


def number(text):
    return float(text) if text != "" else math.nan


@pytest.mark.parametrize("path", FILES, ids=lambda p: p.name)
def test_points_equal_convert_csv(path):
    if "error" in cli_json("stats", "--json", path)["files"][0]:
        # No points to compare: neither reads it (test_statistics_equal_stats_json compares the errors).
        with pytest.raises(trailray.ReadError):
            read_quietly(path)
        return
    f = read_quietly(path)
    rows = csv_rows(path)
    for kind, tracks in (("track", f.tracks), ("route", f.routes)):
        for index, track in enumerate(tracks, start=1):
            mine = [r for r in rows if r["kind"] == kind and r["track"] and int(r["track"]) == index]
            assert len(track) == len(mine)
            assert len(track.lat) == len(track.lon) == len(track.ele) == len(track.time) == len(track)
            np.testing.assert_array_equal(track.lat, [float(r["lat"]) for r in mine])
            np.testing.assert_array_equal(track.lon, [float(r["lon"]) for r in mine])
            np.testing.assert_allclose(track.ele, [number(r["ele"]) for r in mine], rtol=0, atol=0,
                                       equal_nan=True)
            times = np.array([np.datetime64(r["time"].rstrip("Z"), "ms") if r["time"] else np.datetime64("NaT")
                              for r in mine], dtype="datetime64[ms]")
            assert (np.isnat(times) == np.isnat(track.time)).all()
            both = ~np.isnat(times)
            # The CSV writes whole seconds unless the time has a fraction.
            assert (np.abs((track.time[both] - times[both]).astype(np.int64)) <= 500).all()
            if kind == "track" and track.channel("hr") is not None:
                np.testing.assert_allclose(track.hr, [number(r["hr"]) for r in mine], rtol=1e-6, equal_nan=True)
            segments = [int(r["segment"]) for r in mine if r["segment"]]
            nonempty = [s for s in track.segments if len(s)]
            assert len(set(segments)) == len(nonempty) or kind == "route"


def test_metrics_are_the_color_by_values():
    path = shared("igc/goigc_0100_interlaken.igc")
    track = read_quietly(path).tracks[0].cleaned()
    m = track.metrics()
    for name in ("speed", "vspeed", "slope", "altitude", "time", "distance", "elapsed"):
        assert m[name].shape == (len(track),), name
    # altitude is the elevation drawn; distance grows along the track and ends at the clean 2D distance.
    np.testing.assert_array_equal(m["altitude"], track.ele.astype(np.float32).astype(np.float64))
    assert np.all(np.diff(m["distance"]) >= 0)
    assert m["distance"][-1] == pytest.approx(read_quietly(path).tracks[0].stats()["clean"]["distance_2d_m"], rel=1e-9)
    assert 5 < np.nanmedian(m["speed"]) < 100  # a paraglider, km/h
