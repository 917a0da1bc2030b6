"""trailray.render: the command's picture as an array, its options in Python spelling, refused
as the command refuses them; Jupyter's pictures."""

import warnings

import numpy as np
import pytest

import trailray
from conftest import run_cli, shared, surface_pair_walk


def magenta(picture):
    r, g, b = (picture[:, :, i].astype(int) for i in range(3))
    return (r > 150) & (b > 150) & (g < 100) & (np.abs(r - b) < 60)


def flight():
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", trailray.TrailrayWarning)
        return trailray.read(shared("igc/goigc_0100_interlaken.igc"))


def test_a_flight_in_magenta_shows_magenta():
    f = flight()
    picture = trailray.render(f.tracks[0], size=(320, 200), color="#ff00ff", legend=False, labels=False)
    assert picture.shape == (200, 320, 4) and picture.dtype == np.uint8
    assert (picture[:, :, 3] == 255).all()
    covered = magenta(picture).mean()
    assert 0.003 < covered < 0.5
    # The same flight in green has no magenta: the colour is the one asked for.
    green = trailray.render(f.tracks[0], size=(320, 200), color="#00ff00", legend=False, labels=False)
    assert magenta(green).mean() < covered / 20


def test_the_picture_is_the_commands(tmp_path):
    path = shared("igc/goigc_0100_interlaken.igc")
    out = tmp_path / "cli.png"
    run_cli("render", path, "-o", out, "--size", "240x160", "--terrain", "none", "--imagery", "none",
            "--color-by", "vspeed", "--no-ssao")
    mine = trailray.render(path, size=(240, 160), color_by="vspeed", ssao=False)
    from_object = trailray.render(flight(), size=(240, 160), color_by="vspeed", ssao=False)
    assert np.array_equal(mine, from_object)
    assert out.read_bytes() == trailray.png(mine)


def test_terrain_from_a_dem_is_drawn():
    dem = shared("dem/interlaken_dhm25_wgs84.tif")
    f = flight()
    flat = trailray.render(f, size=(200, 120), legend=False)
    relief = trailray.render(f, terrain=dem, size=(200, 120), legend=False)
    # Hillshaded relief varies where the neutral ground is one grey.
    assert relief[:, :, :3].std() > flat[:, :, :3].std()


def test_a_surface_model_is_drawn_and_colours_by_cover(tmp_path):
    dtm, dsm, walk = surface_pair_walk(tmp_path)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", trailray.TrailrayWarning)
        ground = trailray.render(walk, terrain=dtm, size=(320, 180))
        canopy = trailray.render(walk, terrain=dtm, surface=dsm, size=(320, 180))
        cover = trailray.render(walk, terrain=dtm, surface=dsm, size=(320, 180), color_by="cover")
    assert not np.array_equal(ground, canopy)  # the trees are drawn
    # Under cover in its green, the two open ends in their yellow.
    rgb = cover[..., :3].astype(int)
    green = (rgb[..., 1] > rgb[..., 0] + 60) & (rgb[..., 1] > rgb[..., 2] + 40) & (rgb[..., 0] < 80)
    yellow = (rgb[..., 0] > 200) & (rgb[..., 1] > 150) & (rgb[..., 2] < 90)
    assert green.sum() > 30 and yellow.sum() > 5
    with pytest.raises(RuntimeError, match="--surface"):
        trailray.render(walk, terrain=dtm, color_by="cover", size=(64, 36))


def test_a_camera_and_no_tracks():
    picture = trailray.render(terrain=shared("dem/interlaken_dhm25_wgs84.tif"), size=(160, 100),
                              camera=dict(look_at=(46.68, 7.86, 600), distance=8000, heading=90, pitch=-30),
                              time="2024-07-14T12:00:00Z")
    assert picture.shape == (100, 160, 4)


def test_options_are_refused_as_the_command_refuses_them():
    t = flight().tracks[0]
    with pytest.raises(ValueError, match="--color-by"):
        trailray.render(t, color_by="colour")
    with pytest.raises(ValueError, match="--pixel-ratio"):
        trailray.render(t, pixel_ratio=100)
    with pytest.raises(TypeError, match="unexpected keyword argument 'sparkles'"):
        trailray.render(t, sparkles=True)
    with pytest.raises(TypeError, match="'output'"):
        trailray.render(t, output="x.png")
    with pytest.raises(TypeError, match="render\\(\\) draws Files, Tracks and paths"):
        trailray.render([t, 42.0])
    with pytest.raises(RuntimeError, match="absent.gpx"):
        trailray.render("/nonexistent/absent.gpx")


def test_jupyter_shows_files_and_tracks_as_png():
    f = flight()
    for shown in (f, f.tracks[0]):
        png = shown._repr_png_()
        assert png[:8] == b"\x89PNG\r\n\x1a\n" and len(png) > 1000
