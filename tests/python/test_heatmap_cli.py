"""`trailray heatmap`: the GeoTIFF read back through GDAL (its grid, its georeferencing) and its
counts against an independent computation from the tracks' points."""

import math
import warnings

import numpy as np
import pytest
from osgeo import gdal

import trailray
from conftest import run_cli, shared

H = math.pi * 6378137.0


def mercator(lat, lon):
    lat = np.clip(lat, -85.051128779806592, 85.051128779806592)
    return np.radians(lon) * 6378137.0, np.log(np.tan(np.pi / 4 + np.radians(lat) / 2)) * 6378137.0


def crosses(ax, ay, bx, by, x0, y0):
    """Does the segment pass through the inside of the unit cell at (x0, y0)? (Liang-Barsky.)"""
    t0, t1 = 0.0, 1.0
    dx, dy = bx - ax, by - ay
    for p, q in ((-dx, ax - x0), (dx, x0 + 1 - ax), (-dy, ay - y0), (dy, y0 + 1 - ay)):
        if p == 0:
            if q <= 0:
                return False
            continue
        r = q / p
        if p < 0:
            t0 = max(t0, r)
        else:
            t1 = min(t1, r)
    return t0 < t1 or (dx == 0 and dy == 0)


def cells_of(track, cell):
    """The cells a track passes through: each segment's lines, steps over 10 km left out."""
    out = set()
    for seg in track.segments:
        if len(seg) == 0:
            continue
        x, y = mercator(seg.lat, seg.lon)
        gx, gy = (x + H) / cell, (H - y) / cell
        for i in range(len(gx)):
            j = min(i + 1, len(gx) - 1)
            ground = math.hypot(x[j] - x[i], y[j] - y[i]) * math.cos(math.radians((seg.lat[i] + seg.lat[j]) / 2))
            if ground > 10000:
                j = i
            for cx in range(math.floor(min(gx[i], gx[j])), math.floor(max(gx[i], gx[j])) + 1):
                for cy in range(math.floor(min(gy[i], gy[j])), math.floor(max(gy[i], gy[j])) + 1):
                    if crosses(gx[i], gy[i], gx[j], gy[j], cx, cy):
                        out.add((cx, cy))
    return out


def test_the_geotiff_holds_the_counts_where_the_tracks_are(tmp_path):
    files = [shared("igc/goigc_0100_interlaken.igc"), shared("gpx/gpxpy_Mojstrovka.gpx"),
             shared("igc/goigc_0192_kitzbuehel.igc")]
    out = tmp_path / "heat.tif"
    code, printed, err = run_cli("heatmap", *files, "-o", out, "--cell", 100, check=False)
    assert code == 0, err
    assert "3 tracks from 3 files" in printed
    d = gdal.Open(str(out))
    band = d.GetRasterBand(1)
    assert gdal.GetDataTypeName(band.DataType) == "UInt32"
    assert d.GetSpatialRef().GetAuthorityCode(None) == "3857"
    x0, dx, _, y0, _, dy = d.GetGeoTransform()
    assert dx == 100 and dy == -100
    # The grid is the global one: the corner lies on a cell border counted from the world's corner.
    assert abs((x0 + H) / 100 - round((x0 + H) / 100)) < 1e-6 and abs((H - y0) / 100 - round((H - y0) / 100)) < 1e-6
    counts = band.ReadAsArray()
    col0, row0 = round((x0 + H) / 100), round((H - y0) / 100)
    expected = {}
    for path in files:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", trailray.TrailrayWarning)
            for t in trailray.read(path).tracks:
                for c in cells_of(t, 100.0):
                    expected[c] = expected.get(c, 0) + 1
    got = {(col0 + c, row0 + r): int(counts[r, c]) for r, c in zip(*np.nonzero(counts))}
    assert got == expected


def test_a_bbox_a_bad_file_and_bad_options(tmp_path):
    good, broken = shared("igc/goigc_0100_interlaken.igc"), tmp_path / "broken.gpx"
    broken.write_text("this is no track file\n")
    out = tmp_path / "box.tif"
    code, printed, err = run_cli("heatmap", good, broken, "-o", out, "--bbox", "46.5,7.5,47.0,8.2", check=False)
    assert code == 1 and "broken.gpx" in err and "1 tracks from 1 files (1 could not be read)" in printed
    d = gdal.Open(str(out))
    x0, dx, _, y0, _, dy = d.GetGeoTransform()
    west, north = x0, y0
    east, south = x0 + dx * d.RasterXSize, y0 + dy * d.RasterYSize
    (bw, be), (bs, bn) = mercator(np.array([46.5, 47.0]), np.array([7.5, 8.2]))[0], mercator(np.array([46.5, 47.0]), np.array([7.5, 8.2]))[1]
    assert west <= bw < west + 50 and east - 50 < be <= east and south <= bs < south + 50 and north - 50 < bn <= north
    assert d.GetRasterBand(1).ReadAsArray().max() == 1
    assert run_cli("heatmap", good, "-o", out, check=False)[0] != 0  # exists: --force needed
    assert run_cli("heatmap", good, "-o", tmp_path / "x.png", check=False)[0] == 2
    assert run_cli("heatmap", good, "-o", tmp_path / "y.tif", "--bbox", "47,8,46,9", check=False)[0] == 2
    assert run_cli("heatmap", good, "-o", tmp_path / "z.tif", "--cell", 0, check=False)[0] == 2


def test_a_heatmap_too_large_for_memory_is_refused_with_a_way_out(tmp_path):
    # Flights from Brazil to New Zealand at 200 m cells: 144054x59103 cells, far over 1 GiB.
    folder = shared("igc")
    code, printed, err = run_cli("heatmap", folder, "-o", tmp_path / "world.tif", "--cell", 200, check=False)
    assert code == 1 and "--bbox" in err and not (tmp_path / "world.tif").exists()
    with pytest.raises(ValueError, match="bbox"):
        trailray.heatmap(folder, cell=200)
    assert trailray.heatmap(folder, cell=200, bbox=(46.0, 7.0, 48.0, 13.0)).tracks == 18
