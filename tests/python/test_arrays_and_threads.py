"""Arrays are views on the reader's memory (no copy per access, even for a million points), stay
valid after the File is gone, cannot be written; reading and rendering in threads gives what one
after the other gives."""

import concurrent.futures
import gc
import resource
import warnings

import numpy as np
import pytest

import trailray
from conftest import shared, shared_track_files


def igc_of(points: int) -> bytes:
    """An IGC flight of `points` one-second fixes climbing slowly north."""
    lines = ["AXXX test", "HFDTE010624"]
    for i in range(points):
        s = 36000 + i
        lat_thousandths = 47 * 60000 + i % 600000 // 10
        lines.append("B%02d%02d%02d%02d%05dN%03d%05dEA%05d%05d" % (
            s // 3600 % 24, s // 60 % 60, s % 60, lat_thousandths // 60000, lat_thousandths % 60000, 11, 0,
            1000 + i % 2000, 1010 + i % 2000))
    return ("\r\n".join(lines) + "\r\n").encode()


def max_rss_kb() -> int:
    return resource.getrusage(resource.RUSAGE_SELF).ru_maxrss


def test_a_million_points_are_viewed_not_copied():
    track = trailray.read(igc_of(1_000_000)).tracks[0]
    assert len(track) == 1_000_000
    lat = track.lat
    # A strided view on the 64-byte points: no data of its own, its base the reader's memory.
    assert not lat.flags.owndata and lat.strides == (64,) and lat.dtype == np.float64
    assert track.ele.strides == (64,) and track.gnss_alt.strides == (64,)
    assert not lat.flags.writeable
    with pytest.raises(ValueError):
        lat[0] = 0.0
    before = max_rss_kb()
    total = 0.0
    for _ in range(200):  # 200 accesses of 8 MB arrays: copies would add 1.6 GB
        total += track.lat[-1] + track.lon[-1] + track.ele[-1]
    assert max_rss_kb() - before < 50_000
    assert track.lat is track.lat  # the same array object each time
    t = track.time  # computed once (seconds to datetime64) and kept
    assert t is track.time and t[1] - t[0] == np.timedelta64(1000, "ms")


def test_arrays_outlive_their_file():
    f = trailray.read(igc_of(1000))
    lat = f.tracks[0].lat
    expected = lat.copy()
    del f
    gc.collect()
    np.testing.assert_array_equal(lat, expected)


def test_several_segments_are_joined_once():
    t = trailray.read(shared("gpx/gpxstudio_with_tracks_and_segments.gpx")).tracks
    many = next(x for x in t if len([s for s in x.segments if len(s)]) > 1)
    np.testing.assert_array_equal(many.lat, np.concatenate([s.lat for s in many.segments]))
    assert many.lat is many.lat
    # Reached again through the file, it is the same Track with the same joined arrays.
    f = trailray.read(shared("gpx/gpxstudio_with_tracks_and_segments.gpx"))
    i = next(i for i, x in enumerate(f.tracks) if len([s for s in x.segments if len(s)]) > 1)
    assert f.tracks[i] is f.tracks[i] and f.tracks[i].lat is f.tracks[i].lat
    assert f.tracks[i].segments[0] is f.tracks[i].segments[0]
    f.tracks.clear()  # a list of its own: the file's tracks stay
    assert len(f.tracks) == len(t)
    for s in many.segments:
        assert s.lat.strides == (64,) or len(s) == 0


def everything(path):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", trailray.TrailrayWarning)
        try:
            f = trailray.read(path)
        except trailray.ReadError as e:
            return str(e)
    return [(t.stats(), t.lat.copy(), t.cleaned().ele.copy()) for t in f.tracks]


def same(a, b):
    if isinstance(a, str) or isinstance(b, str):
        return a == b
    return len(a) == len(b) and all(
        sa == sb and np.array_equal(la, lb) and np.array_equal(ea, eb, equal_nan=True)
        for (sa, la, ea), (sb, lb, eb) in zip(a, b))


def test_threads_read_what_one_after_the_other_reads():
    shared("igc")
    files = shared_track_files()
    one_by_one = [everything(p) for p in files]
    with concurrent.futures.ThreadPoolExecutor(max_workers=4) as pool:
        parallel = list(pool.map(everything, files))
    assert all(same(a, b) for a, b in zip(one_by_one, parallel))


def test_threads_render_what_one_after_the_other_renders():
    flights = [trailray.read(igc_of(n)).tracks[0] for n in (300, 600, 900)]

    def picture(track):
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", trailray.TrailrayWarning)
            return trailray.render(track, size=(160, 100), shadows=False)

    one_by_one = [picture(t) for t in flights]
    with concurrent.futures.ThreadPoolExecutor(max_workers=3) as pool:
        parallel = list(pool.map(picture, flights))
    for a, b in zip(one_by_one, parallel):
        assert np.array_equal(a, b)
