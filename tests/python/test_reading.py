"""trailray.read: sources (str, pathlib.Path, bytes, gzip), options, errors that name the file and
the position, warnings through the warnings module, and strict reading."""

import gzip
import pathlib
import warnings

import numpy as np
import pytest

import trailray
from conftest import shared

GPX = b"""<?xml version="1.0"?>
<gpx version="1.1" creator="test"><trk><name>Walk</name><trkseg>
<trkpt lat="47.0" lon="11.0"><ele>1000</ele><time>2024-06-01T10:00:00Z</time></trkpt>
<trkpt lat="47.001" lon="11.0"><ele>1010</ele><time>2024-06-01T10:01:00Z</time></trkpt>
<trkpt lat="47.002" lon="11.0"><ele>1020</ele><time>2024-06-01T10:02:00Z</time></trkpt>
</trkseg></trk></gpx>
"""


def test_bytes_path_and_pathlib_read_alike(tmp_path):
    path = tmp_path / "walk.gpx"
    path.write_bytes(GPX)
    a, b, c = trailray.read(GPX), trailray.read(str(path)), trailray.read(path)
    assert a.path == "<bytes>" and b.path == str(path) and c.path == str(path)
    for f in (a, b, c):
        assert f.format == "gpx"
        t = f.tracks[0]
        assert t.name == "Walk" and len(t) == 3
        np.testing.assert_array_equal(t.lat, [47.0, 47.001, 47.002])
        np.testing.assert_array_equal(t.ele, [1000, 1010, 1020])
        assert t.time[1] == np.datetime64("2024-06-01T10:01:00", "ms")
    assert a.tracks[0].stats() == b.tracks[0].stats()


def test_gzip_and_a_forced_format(tmp_path):
    path = tmp_path / "walk.gpx.gz"
    path.write_bytes(gzip.compress(GPX))
    assert len(trailray.read(path).tracks[0]) == 3
    assert len(trailray.read(GPX, format="GPX").tracks[0]) == 3
    with pytest.raises(trailray.ReadError):
        trailray.read(GPX, format="igc")  # GPX text is no IGC: no B record, nothing to read
    with pytest.raises(ValueError, match="format 'shp'"):
        trailray.read(GPX, format="shp")


def test_a_broken_file_names_the_line_and_column(tmp_path):
    broken = GPX.replace(b'<trkpt lat="47.001" lon="11.0">', b'<trkpt lat="47.001" lon="11.0"<oops>')
    with pytest.raises(trailray.ReadError) as raised:
        trailray.read(broken)
    e = raised.value
    assert isinstance(e, ValueError)
    assert e.path == "<bytes>" and e.line == 4 and e.column > 0
    assert str(e).startswith(f"<bytes>:4:{e.column}: ")
    path = tmp_path / "broken.gpx"
    path.write_bytes(broken)
    with pytest.raises(trailray.ReadError, match=rf"^{path}:4:\d+: "):
        trailray.read(path)


def test_missing_empty_and_unknown_files_are_read_errors(tmp_path):
    with pytest.raises(trailray.ReadError, match="cannot open"):
        trailray.read(tmp_path / "absent.gpx")
    (tmp_path / "empty.gpx").write_bytes(b"")
    with pytest.raises(trailray.ReadError, match="empty"):
        trailray.read(tmp_path / "empty.gpx")
    with pytest.raises(trailray.ReadError, match="not a GPX, IGC"):
        trailray.read(b"hello, world\n")
    with pytest.raises(TypeError):
        trailray.read(42)


def test_warnings_are_python_warnings_and_strict_makes_them_errors():
    cut = GPX[: GPX.index(b"</trkseg>")]  # the file ends inside the document
    with pytest.warns(trailray.TrailrayWarning, match="cut short") as caught:
        f = trailray.read(cut)
    assert len(f.tracks[0]) == 3
    assert f.warnings and f.warnings[0] == str(caught[0].message)
    assert f.warnings[0].startswith("<bytes>:")
    with pytest.raises(trailray.ReadError, match=r"cut short.*\(strict=True\)"):
        trailray.read(cut, strict=True)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        trailray.read(GPX)  # a clean file warns nothing


def test_igc_altitude_picks_the_elevation_and_keeps_both():
    path = shared("igc/goigc_0100_interlaken.igc")
    gnss = trailray.read(path, igc_altitude="gnss").tracks[0]
    pressure = trailray.read(path, igc_altitude="pressure").tracks[0]
    np.testing.assert_array_equal(gnss.ele, gnss.gnss_alt.astype(np.float64))
    np.testing.assert_array_equal(pressure.ele, pressure.pressure_alt.astype(np.float64))
    np.testing.assert_array_equal(gnss.pressure_alt, pressure.pressure_alt)
    assert set(gnss.channels) == {"gnss_alt", "pressure_alt"}
    assert gnss.hr is None
    with pytest.raises(ValueError, match="igc_altitude"):
        trailray.read(path, igc_altitude="baro")


def test_the_reader_never_changes_its_input(tmp_path):
    path = tmp_path / "walk.gpx"
    path.write_bytes(GPX)
    before = path.stat().st_mtime_ns
    trailray.read(path).tracks[0].cleaned().stats()
    assert path.read_bytes() == GPX and path.stat().st_mtime_ns == before


def test_routes_waypoints_and_metadata():
    f = trailray.read(shared("gpx/gpxstudio_with_routes.gpx"))
    assert f.routes and all(r.is_route for r in f.routes)
    assert not any(t.is_route for t in f.tracks)
    w = trailray.read(shared("gpx/gpxstudio_with_waypoint.gpx")).waypoints
    assert w and isinstance(w[0], trailray.Waypoint) and -90 <= w[0].lat <= 90
    md = trailray.read(shared("igc/goigc_0100_interlaken.igc")).metadata
    assert md["fields"] and isinstance(md["fields"], dict)


def test_to_pandas_has_one_row_per_point():
    import pandas  # noqa: F401 (optional for users; setup.sh installs it for the tests)
    t = trailray.read(shared("gpx/gpxstudio_with_hr.gpx")).tracks[0]
    df = t.to_pandas()
    assert len(df) == len(t)
    assert {"lat", "lon", "ele", "time", "hr", "segment"} <= set(df.columns)
    assert str(df["time"].dtype).startswith("datetime64")
    np.testing.assert_array_equal(df["hr"].to_numpy(), t.hr)


def test_hostile_bytes_give_a_file_or_a_read_error():
    """Cut and corrupted files of every format: a File or a ReadError, never a crash."""
    from conftest import shared_track_files

    shared("gpx")
    rng = np.random.default_rng(7)
    for path in shared_track_files()[::3]:
        data = path.read_bytes()[:200_000]
        for _ in range(6):
            cut = data[: int(rng.integers(0, len(data) + 1))]
            noisy = bytearray(cut)
            for i in rng.integers(0, max(len(noisy), 1), size=min(len(noisy), 20)):
                noisy[i] = int(rng.integers(0, 256))
            for blob in (cut, bytes(noisy)):
                with warnings.catch_warnings():
                    warnings.simplefilter("ignore", trailray.TrailrayWarning)
                    try:
                        f = trailray.read(blob)
                    except trailray.ReadError as e:
                        assert str(e).startswith("<bytes>")
                        continue
                for t in f.tracks + f.routes:
                    assert len(t.lat) == len(t) and len(t.time) == len(t)
                    t.stats()


def test_bytes_that_are_not_utf8_become_replacement_characters():
    # A GPX that says UTF-8 and is not (the reader keeps the bytes), and an IGC header in Latin-1
    # (the IGC reader decodes it).
    gpx = trailray.read(GPX.replace(b"<name>Walk</name>", b"<name>W\xffalk \xe9t\xe9</name>"))
    assert gpx.tracks[0].name == "W\ufffdalk \ufffdt\ufffd"
    assert "\ufffd" in repr(gpx.tracks[0])
    assert gpx.tracks[0].stats()["name"] == gpx.tracks[0].name
    igc = (b"AXXXtest\r\nHFDTE010624\r\nHFPLTPILOT:J\xfcrg M\xfcller\r\n"
           + b"".join(b"B10%02d004700000N01100000EA0100001000\r\n" % s for s in range(10)))
    assert trailray.read(igc).metadata["fields"]["pilot"] == "J\u00fcrg M\u00fcller"
