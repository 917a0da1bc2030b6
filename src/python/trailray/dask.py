"""trailray on a Dask cluster: heatmaps of many files, and any per-file work.

    from distributed import Client
    client = Client("tcp://scheduler:8786")          # or Client() for the cores of this machine
    h = trailray.dask.heatmap("/shared/flights/", client=client, cell=50)
    h.write("season.tif")
    results = trailray.dask.map_files(lambda p: trailray.read(p).tracks[0].stats(), files, client=client)

Workers need trailray importable and the files on a path they all see (a shared folder).
"""

from __future__ import annotations

from typing import Any, Callable, List, NamedTuple, Optional, Sequence, Tuple

from . import _core
from ._heatmap import FileError, Heatmap, _check, count_files, expand_files

__all__ = ["heatmap", "map_files", "Failure"]


class Failure(NamedTuple):
    """What map_files gives for a file whose function raised: the file and the error, in words."""

    path: str
    error: str


def _client(client):
    if client is not None:
        return client
    from distributed import get_client

    return get_client()  # the default client of this process (raises ValueError without one)


def _merge(a, b):
    counts_a, errors_a = a
    counts_b, errors_b = b
    counts_a.merge(counts_b)
    return counts_a, list(errors_a) + list(errors_b)


def heatmap(files, client=None, partitions: Optional[int] = None, cell: float = 50.0, of: str = "tracks",
            bbox: Optional[Tuple[float, float, float, float]] = None, strict: bool = False) -> Heatmap:
    """trailray.heatmap on a cluster: the files split into ``partitions`` parts (default: four per
    worker thread), each counted on a worker into sparse count tiles, the parts summed exactly on
    the workers two by two (a tree: no machine ever holds every part), the sum gathered here.
    Returns the same Heatmap as trailray.heatmap (same grid, same extent, count for count).
    A worker lost in the middle loses nothing: Dask runs its parts again."""
    _check(cell, of)
    client = _client(client)
    paths = expand_files(files)
    if not paths:
        return Heatmap(_core.HeatmapCounts(float(cell), of), bbox, [])
    if partitions is None:
        threads = sum(client.nthreads().values()) or 1
        partitions = 4 * threads
    partitions = max(1, min(int(partitions), len(paths)))
    size = -(-len(paths) // partitions)
    chunks = [paths[i:i + size] for i in range(0, len(paths), size)]
    level = client.map(count_files, chunks, cell=float(cell), strict=bool(strict), of=of, pure=False)
    while len(level) > 1:
        pairs = [client.submit(_merge, level[i], level[i + 1], pure=False) for i in range(0, len(level) - 1, 2)]
        if len(level) % 2:
            pairs.append(level[-1])
        level = pairs
    counts, errors = level[0].result()
    order = {p: i for i, p in enumerate(paths)}
    return Heatmap(counts, bbox, sorted(errors, key=lambda e: order.get(e.path, 0)))


def _guarded(path: str, function: Callable[[str], Any]):
    try:
        return function(path)
    except Exception as e:  # a file's failure is its result; the others go on
        return Failure(path, f"{type(e).__name__}: {e}")


def map_files(function: Callable[[str], Any], files, client=None) -> List[Any]:
    """``function(path)`` for every file on the cluster's workers (stats, a score, a flight's
    analysis, a picture per file...), the results in the order of the files. A file whose function
    raises gives a Failure(path, error) in its place while the others go on."""
    client = _client(client)
    paths = expand_files(files)
    futures = client.map(_guarded, paths, function=function, pure=False)
    return client.gather(futures)
