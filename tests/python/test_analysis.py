"""score, flight, Task, Airspaces and elevation give the numbers of the commands' --json."""

import warnings

import numpy as np
import pytest

import trailray
from conftest import cli_json, shared, surface_pair_walk


def quietly(function, *args, **kwargs):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", trailray.TrailrayWarning)
        return function(*args, **kwargs)


SCORED = ["igc/xcscore_trifai-xcontest-452.21.igc", "igc/scoring/xcscore_flat-xcontest-106.82.igc",
          "igc/scoring/xcscore_freeflight-xcontest-66.46.igc", "igc/scoring/xcscore_tri.igc"]


@pytest.mark.parametrize("relative", SCORED)
@pytest.mark.parametrize("rules", ["xcontest", "ffvl"])
def test_score_is_the_commands(relative, rules):
    path = shared(relative)
    expected = cli_json("score", "--json", "--rules", rules, path)
    expected.pop("solve_seconds")
    assert trailray.score(path, rules=rules) == expected
    # A track read from the same log scores the same flight.
    track = quietly(trailray.read, path).tracks[0]
    assert trailray.score(track, rules=rules)["score"] == pytest.approx(expected["score"], abs=0.02)


def test_score_refuses_what_the_command_refuses():
    path = shared("igc/scoring/xcscore_tri.igc")
    with pytest.raises(ValueError, match="unknown rule set 'olc'"):
        trailray.score(path, rules="olc")
    with pytest.raises(ValueError, match="scoring needs at least 5"):
        trailray.score(trailray.read(b"AXXXtest\r\nHFDTE010624\r\nB1000004700000N01100000EA0100001000\r\n").tracks[0])


@pytest.mark.parametrize("relative", ["igc/goigc_0100_interlaken.igc", "igc/igclib_flight_with_middle_landing.igc",
                                      "gpx/gpxpy_Mojstrovka.gpx"])
def test_flight_is_the_commands(relative):
    path = shared(relative)
    expected = cli_json("flight", "--json", path)
    tracks = expected["files"][0]["tracks"] if "files" in expected else expected["tracks"]
    f = quietly(trailray.read, path)
    assert [trailray.flight(t) for t in f.tracks] == tracks


def test_task_is_the_commands():
    task_path, flight_path = shared("tasks/igclib_xctrack_1.xctsk"), shared("tasks/igclib_race_0090.igc")
    expected = cli_json("task", "--json", task_path, flight_path)
    task = trailray.Task.read(task_path)
    info = task.info()
    assert {k: v for k, v in info.items() if k != "flights"} == {k: v for k, v in expected.items() if k != "flights"}
    track = quietly(trailray.read, flight_path).tracks[0]
    assert quietly(task.check, track) == expected["flights"][0]
    with pytest.raises(trailray.ReadError, match="no task declaration"):
        trailray.Task.read(flight_path)


def test_airspaces_are_the_commands():
    airspace, flight_path = shared("airspace/openairrs_Switzerland.txt"), shared("igc/goigc_0100_interlaken.igc")
    expected = cli_json("check", "--json", "--airspace", airspace, flight_path)
    spaces = trailray.Airspaces.read(airspace)
    assert len(spaces) == 334 and len(spaces.names) == 334
    got = spaces.check(quietly(trailray.read, flight_path).tracks[0])
    assert got == expected["tracks"][0]
    # The GNSS mode compares every limit with the GNSS altitude, as --igc-altitude gnss does.
    gnss = cli_json("check", "--json", "--igc-altitude", "gnss", "--airspace", airspace, flight_path)["tracks"][0]
    assert spaces.check(quietly(trailray.read, flight_path, igc_altitude="gnss").tracks[0]) == gnss


def test_elevation_with_a_surface_model_is_the_commands(tmp_path):
    dtm, dsm, walk = surface_pair_walk(tmp_path)
    expected = cli_json("elevation", "--json", "--terrain", dtm, "--surface", dsm, str(walk))
    got = trailray.elevation(quietly(trailray.read, walk).tracks[0], dtm, surface=dsm)
    assert got["summary"] == expected["summary"]
    assert got["cover"] == [p["cover"] for p in expected["points"]]
    assert got["cover"][0] == "open" and got["cover"][20] == "covered"
    np.testing.assert_allclose(got["canopy"], got["surface"] - got["terrain"])
    assert 0.6 < got["summary"]["covered_share"] < 0.97


def test_elevation_is_the_commands():
    dem, path = shared("dem/interlaken_dhm25_wgs84.tif"), shared("igc/goigc_0100_interlaken.igc")
    expected = cli_json("elevation", "--json", "--terrain", dem, path)
    track = quietly(trailray.read, path).tracks[0]
    got = trailray.elevation(track, dem)
    assert got["summary"] == expected["summary"]
    points = expected["points"]
    assert len(got["terrain"]) == len(points) == len(track)
    np.testing.assert_allclose(got["terrain"], [p["terrain_m"] for p in points], atol=0.006)
    np.testing.assert_allclose(got["agl"], track.ele - got["terrain"])
    assert 500 < np.nanmin(got["terrain"]) < np.nanmax(got["terrain"]) < 2000
