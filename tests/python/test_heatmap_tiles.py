"""`trailray heatmap` to map tiles (.mbtiles, folders), heatmaps added to later, --of time and
thermals, and the heatmap drawn on the terrain by `render --overlay`: read back through GDAL,
SQLite and the pictures themselves."""

import json
import math
import sqlite3
import warnings

import numpy as np
import pytest
from osgeo import gdal

import trailray
from conftest import run_cli, shared

H = math.pi * 6378137.0


def flights():
    return [shared("igc/goigc_0100_interlaken.igc"), shared("gpx/gpxpy_Mojstrovka.gpx"),
            shared("igc/goigc_0192_kitzbuehel.igc")]


def tif_counts(path):
    """{(col, row): count} of a heatmap GeoTIFF on the global grid, and its cell."""
    d = gdal.Open(str(path))
    x0, dx, _, y0, _, _ = d.GetGeoTransform()
    col0, row0 = round((x0 + H) / dx), round((H - y0) / dx)
    a = d.GetRasterBand(1).ReadAsArray()
    return {(col0 + c, row0 + r): int(a[r, c]) for r, c in zip(*np.nonzero(a))}, dx


def test_mbtiles_hold_coloured_tiles_where_the_counts_are_and_the_counts_exactly(tmp_path):
    files = flights()
    code, printed, err = run_cli("heatmap", *files, "-o", tmp_path / "all.mbtiles", "--cell", 100, check=False)
    assert code == 0, err
    assert "tiles at zoom 0..11" in printed
    run_cli("heatmap", *files, "-o", tmp_path / "all.tif", "--cell", 100)
    cells, cell = tif_counts(tmp_path / "all.tif")
    db = sqlite3.connect(tmp_path / "all.mbtiles")
    meta = dict(db.execute("SELECT name, value FROM metadata"))
    assert meta["format"] == "png" and meta["minzoom"] == "0" and meta["maxzoom"] == "11"
    heat = json.loads(meta["trailray_heatmap"])
    assert heat["cell_m"] == 100 and heat["of"] == "tracks" and heat["tracks"] == 3 and heat["max"] == max(cells.values())
    zooms = dict(db.execute("SELECT zoom_level, COUNT(*) FROM tiles GROUP BY zoom_level"))
    assert sorted(zooms) == list(range(12))
    db.close()
    # GDAL opens them as a raster of the finest zoom in EPSG:3857.
    d = gdal.Open(str(tmp_path / "all.mbtiles"))
    assert d.GetSpatialRef().GetAuthorityCode(None) == "3857" and d.RasterCount == 4
    # Each tile of zoom 11 (76 m pixels, 100 m cells): a pixel is coloured exactly where the cell
    # under its centre was counted.
    db = sqlite3.connect(tmp_path / "all.mbtiles")
    tiles = db.execute("SELECT tile_column, tile_row, tile_data FROM tiles WHERE zoom_level = 11").fetchall()
    db.close()
    px = 2 * H / (256 * 2 ** 11)
    seen = set()
    for x, tms_y, data in tiles:
        y = 2 ** 11 - 1 - tms_y
        gdal.FileFromMemBuffer("/vsimem/tile.png", bytes(data))
        png = gdal.Open("/vsimem/tile.png")  # kept while its band is read (GDAL's Python needs it)
        alpha = png.GetRasterBand(4).ReadAsArray()
        png = None
        gdal.Unlink("/vsimem/tile.png")
        rows, cols = np.indices(alpha.shape)
        cx = np.floor(((x * 256 + cols + 0.5) * px) / cell).astype(np.int64)
        cy = np.floor(((y * 256 + rows + 0.5) * px) / cell).astype(np.int64)
        counted = np.array([(c, r) in cells for c, r in zip(cx.ravel(), cy.ravel())]).reshape(alpha.shape)
        assert np.array_equal(alpha > 0, counted)
        seen |= set(zip(cx[alpha > 0], cy[alpha > 0]))
    assert len(seen) > 0.9 * len(cells)  # nearly every cell shows (a few are narrower than a pixel)
    # The counts beside the tiles are the GeoTIFF's, cell for cell.
    again = trailray.Heatmap.read(tmp_path / "all.mbtiles")
    assert again.tracks == 3 and again.cell == 100
    rows_, cols_ = np.nonzero(again.counts)
    gx0, gy0 = round((again.geotransform[0] + H) / cell), round((H - again.geotransform[3]) / cell)
    assert {(gx0 + c, gy0 + r): int(again.counts[r, c]) for r, c in zip(rows_, cols_)} == cells


def test_partial_heatmaps_add_up_exactly_and_disagreeing_ones_are_refused(tmp_path):
    files = flights()
    run_cli("heatmap", *files[:2], "-o", tmp_path / "part.mbtiles", "--cell", 80)
    run_cli("heatmap", files[2], "-o", str(tmp_path / "rest") + "/", "--cell", 80, "--zoom", "8-10")
    folder = tmp_path / "rest"
    assert (folder / "metadata.json").exists() and (folder / "counts").is_dir()
    assert sorted(p.name for p in folder.iterdir() if p.name.isdigit()) == ["10", "8", "9"]
    # The cell size is taken from the heatmaps added when --cell is not given.
    code, printed, err = run_cli("heatmap", tmp_path / "part.mbtiles", folder, "-o", tmp_path / "sum.tif", check=False)
    assert code == 0, err
    assert "3 tracks from 0 files and 2 heatmaps, 80 m cells" in printed
    run_cli("heatmap", *files, "-o", tmp_path / "together.tif", "--cell", 80)
    assert tif_counts(tmp_path / "sum.tif") == tif_counts(tmp_path / "together.tif")
    # A heatmap and more tracks.
    run_cli("heatmap", tmp_path / "part.mbtiles", files[2], "-o", tmp_path / "mixed.tif")
    assert tif_counts(tmp_path / "mixed.tif") == tif_counts(tmp_path / "together.tif")
    code, _, err = run_cli("heatmap", tmp_path / "part.mbtiles", "-o", tmp_path / "x.tif", "--cell", 50, check=False)
    assert code == 1 and "80 m" in err
    code, _, err = run_cli("heatmap", tmp_path / "part.mbtiles", "-o", tmp_path / "y.tif", "--of", "time", check=False)
    assert code == 1 and "counts tracks" in err
    # A damaged counts tile is an error naming the file, never a crash.
    db = sqlite3.connect(tmp_path / "part.mbtiles")
    db.execute("UPDATE trailray_counts SET data = x'00112233' WHERE rowid = 1")
    db.commit()
    db.close()
    code, _, err = run_cli("heatmap", tmp_path / "part.mbtiles", "-o", tmp_path / "z.tif", check=False)
    assert code == 1 and "part.mbtiles" in err and "damaged" in err
    code, _, err = run_cli("heatmap", files[0], "-o", tmp_path / "w.mbtiles", "--zoom", "9-3", check=False)
    assert code == 2 and "--zoom" in err
    # --force replaces a heatmap's folder, never another folder; an empty folder is filled.
    documents = tmp_path / "documents"
    documents.mkdir()
    (documents / "letter.txt").write_text("keep me")
    code, _, err = run_cli("heatmap", files[0], "-o", str(documents) + "/", "--force", check=False)
    assert code == 1 and "not a heatmap" in err and (documents / "letter.txt").read_text() == "keep me"
    empty = tmp_path / "empty"
    empty.mkdir()
    run_cli("heatmap", files[0], "-o", str(empty) + "/", "--zoom", "10")
    assert (empty / "metadata.json").exists()
    run_cli("heatmap", files[1], "-o", str(empty) + "/", "--zoom", "10", "--force")
    assert trailray.Heatmap.read(str(empty) + "/").tracks == 1


def test_time_spent_adds_up_to_the_tracks_duration(tmp_path):
    path = shared("igc/goigc_0100_interlaken.igc")
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", trailray.TrailrayWarning)
        t = trailray.read(path).tracks[0]
    seconds = 0.0
    for seg in t.segments:
        dt = np.diff(seg.time.astype("datetime64[ms]").astype(np.int64)) / 1000.0
        seconds += dt[dt > 0].sum()  # its steps are all short: no gap
    run_cli("heatmap", path, "-o", tmp_path / "time.tif", "--of", "time")
    cells, _ = tif_counts(tmp_path / "time.tif")
    run_cli("heatmap", path, "-o", tmp_path / "tracks.tif")
    track_cells, _ = tif_counts(tmp_path / "tracks.tif")
    assert set(cells) <= set(track_cells)
    # Whole seconds per cell: the sum is the duration to half a second per cell.
    assert abs(sum(cells.values()) - seconds) <= 0.5 * len(track_cells)
    # The same from Python, and thermals: a subset of the cells, where the flight circled.
    assert trailray.heatmap(path, of="time").counts.sum() == sum(cells.values())
    assert trailray.heatmap(path, of="thermals").counts.size == 0  # a glide down: no thermal
    circling = shared("igc/goigc_0192_kitzbuehel.igc")
    thermals, tracks = trailray.heatmap(circling, of="thermals"), trailray.heatmap(circling)
    assert thermals.of == "thermals" and thermals.counts.max() == 1
    assert 0 < np.count_nonzero(thermals.counts) < np.count_nonzero(tracks.counts) / 2


def test_the_overlay_changes_the_picture_where_the_tracks_are_and_nowhere_else(tmp_path):
    dem = shared("dem/interlaken_dhm25_wgs84.tif")
    # Three tracks along the same east-west line through the middle of the view.
    gpx = tmp_path / "line.gpx"
    points = "".join(f'<trkpt lat="46.705" lon="{7.835 + 0.0005 * i:.4f}"/>' for i in range(101))
    gpx.write_text('<?xml version="1.0"?><gpx version="1.1" creator="test" xmlns="http://www.topografix.com/GPX/1/1">'
                   f"<trk><trkseg>{points}</trkseg></trk></gpx>")
    run_cli("heatmap", gpx, gpx, gpx, "-o", tmp_path / "line.mbtiles")
    run_cli("heatmap", gpx, "-o", tmp_path / "line.tif")
    view = ["--terrain", dem, "--imagery", "none", "--look-at", "46.705,7.86,700", "--distance", 6000, "--pitch", -90,
            "--size", "320x200", "--no-shadows", "--no-ssao"]
    run_cli("render", *view, "--legend", "off", "-o", tmp_path / "plain.png")
    pictures = {}
    for source in ("line.mbtiles", "line.tif"):
        run_cli("render", *view, "--legend", "off", "--overlay", tmp_path / source, "-o", tmp_path / (source + ".png"))
        pictures[source] = gdal.Open(str(tmp_path / (source + ".png"))).ReadAsArray()[:3].astype(int)
    plain = gdal.Open(str(tmp_path / "plain.png")).ReadAsArray()[:3].astype(int)
    for source, picture in pictures.items():
        changed = np.abs(picture - plain).sum(axis=0) > 6
        rows, cols = np.nonzero(changed)
        assert len(rows) > 100, source
        # Top-down, north up: the line is the middle row; 100 m cells at 6 km are a few pixels tall.
        assert np.all(np.abs(rows - 100) <= 6), (source, rows.min(), rows.max())
        # It runs from 7.835 to 7.885 E, 3.8 km: half the picture's width about its centre.
        assert 70 <= cols.min() < 100 and 220 < cols.max() <= 250, (source, cols.min(), cols.max())
    # With the legend on, its colour bar says what the overlay counts.
    code, _, err = run_cli("render", *view, "--overlay", tmp_path / "line.mbtiles", "-o", tmp_path / "legend.png",
                           check=False)
    assert code == 0, err
    with_legend = gdal.Open(str(tmp_path / "legend.png")).ReadAsArray()[:3].astype(int)
    corner = np.abs(with_legend - pictures["line.mbtiles"]).sum(axis=0)[120:, :110]
    assert (corner > 30).sum() > 500  # the panel in the bottom-left corner
    code, _, err = run_cli("render", *view, "--overlay", tmp_path / "missing.mbtiles", "-o", tmp_path / "m.png",
                           check=False)
    assert code != 0 and "missing.mbtiles" in err


def test_python_writes_the_same_tiles(tmp_path):
    files = flights()
    h = trailray.heatmap(files, cell=100)
    h.write(tmp_path / "py.mbtiles", zoom=(5, 9))
    db = sqlite3.connect(tmp_path / "py.mbtiles")
    assert dict(db.execute("SELECT name, value FROM metadata"))["maxzoom"] == "9"
    db.close()
    again = trailray.Heatmap.read(tmp_path / "py.mbtiles")
    assert np.array_equal(again.counts, h.counts) and again.geotransform == h.geotransform
    with pytest.raises(ValueError):
        h.write(tmp_path / "x.png")
    with pytest.raises(ValueError):
        trailray.heatmap(files, of="speed")
