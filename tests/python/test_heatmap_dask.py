"""trailray.heatmap on one machine and trailray.dask on a LocalCluster of two worker processes
(127.0.0.1, bounded in time, stopped by the test): the counts of the command line, count for
count, also when a worker is killed in the middle; per-file work with failures kept per file."""

import logging
import os
import signal
import time
import warnings

import numpy as np
import pytest
from osgeo import gdal

import trailray
import trailray.dask
from conftest import run_cli, shared

import distributed  # noqa: E402 (setup.sh installs python3-distributed)


@pytest.fixture(scope="module")
def client():
    cluster = distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True, host="127.0.0.1",
                                       dashboard_address=":0", silence_logs=logging.ERROR, death_timeout=60)
    c = distributed.Client(cluster, timeout=60)
    try:
        yield c
    finally:
        c.close(timeout=30)
        cluster.close(timeout=30)


def cli_counts(tmp_path, files, cell):
    out = tmp_path / f"cli-{cell}.tif"
    code, printed, err = run_cli("heatmap", *files, "-o", out, "--cell", cell, check=False)
    assert code == 0, err
    d = gdal.Open(str(out))
    return d.GetRasterBand(1).ReadAsArray(), d.GetGeoTransform()


def flights():
    return [shared("igc/goigc_0100_interlaken.igc"), shared("igc/goigc_0192_kitzbuehel.igc"),
            shared("gpx/gpxpy_Mojstrovka.gpx"), shared("igc/igclib_napret.igc")]


def test_one_machine_counts_as_the_command_line(tmp_path):
    files = flights()
    counts, transform = cli_counts(tmp_path, files, 100)
    h = trailray.heatmap(files, cell=100)
    assert h.tracks == 4 and not h.errors
    assert np.array_equal(h.counts, counts) and h.geotransform == transform
    h.write(tmp_path / "py.tif")
    assert np.array_equal(gdal.Open(str(tmp_path / "py.tif")).GetRasterBand(1).ReadAsArray(), counts)
    with pytest.raises(ValueError, match="thermals"):
        trailray.heatmap(files, of="speed")  # the message names what heatmaps count


def test_the_cluster_counts_as_the_command_line(tmp_path, client):
    files = flights()
    counts, transform = cli_counts(tmp_path, files, 100)
    broken = tmp_path / "broken.gpx"
    broken.write_text("no track here\n")
    h = trailray.dask.heatmap(files + [broken], client=client, partitions=3, cell=100)
    assert np.array_equal(h.counts, counts) and h.geotransform == transform
    assert h.tracks == 4
    assert [e.path for e in h.errors] == [str(broken)] and "broken.gpx" in h.errors[0].error
    # The other measures travel through the cluster too (pickled with their counts).
    for of in ("time", "thermals"):
        on_cluster = trailray.dask.heatmap(files, client=client, partitions=3, cell=100, of=of)
        here = trailray.heatmap(files, cell=100, of=of)
        assert on_cluster.of == of and np.array_equal(on_cluster.counts, here.counts) and on_cluster.counts.sum() > 0


def test_a_worker_killed_in_the_middle_loses_nothing(tmp_path, client):
    files = [str(p) for p in flights()] * 30  # 120 parts of one file each: the cluster is busy a while
    expected = trailray.heatmap(files, cell=200)
    pids = client.run(os.getpid)
    victim = sorted(pids)[0]
    done = {}

    import threading

    def run():
        done["heatmap"] = trailray.dask.heatmap(files, client=client, partitions=len(files), cell=200)

    runner = threading.Thread(target=run)
    runner.start()
    deadline = time.monotonic() + 60
    while not client.processing().get(victim) and runner.is_alive() and time.monotonic() < deadline:
        time.sleep(0.01)
    assert runner.is_alive(), "the heatmap finished before a worker could be killed"
    os.kill(pids[victim], signal.SIGKILL)
    runner.join(timeout=120)
    assert not runner.is_alive()
    h = done["heatmap"]
    assert h.tracks == expected.tracks == len(files)
    assert np.array_equal(h.counts, expected.counts) and h.geotransform == expected.geotransform
    client.wait_for_workers(2, timeout=60)  # the nanny starts a new one


def test_map_files_keeps_the_order_and_each_failure(tmp_path, client):
    broken = tmp_path / "broken.gpx"
    broken.write_text("no track here\n")
    files = [str(p) for p in flights()]
    paths = files[:2] + [str(broken)] + files[2:]

    def distance(path):
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            return trailray.read(path).tracks[0].stats()["clean"]["distance_2d_m"]

    results = trailray.dask.map_files(distance, paths, client=client)
    assert len(results) == 5
    assert isinstance(results[2], trailray.dask.Failure) and results[2].path == str(broken)
    assert "ReadError" in results[2].error
    here = [distance(p) for p in files]
    assert results[:2] + results[3:] == here
