"""trailray.heatmap: how many tracks passed through each cell of a Web Mercator grid, as
`trailray heatmap` counts them, for a list of files on this machine (trailray.dask.heatmap: on a
cluster)."""

from __future__ import annotations

import concurrent.futures as _futures
import os as _os
import tempfile as _tempfile
from typing import List, NamedTuple, Optional, Sequence, Tuple

import numpy as _np

from . import _core


def expand_files(files) -> List[str]:
    """Paths as the command line takes them (the same code): a file, a folder (its track files,
    sorted, not its subfolders), a pattern ('flights/*.igc'), or a list of those. A pattern or a
    folder that gives no track file raises FileNotFoundError naming it."""
    items = [files] if isinstance(files, (str, bytes, _os.PathLike)) else list(files)
    return _core.expand_track_arguments([_os.fsdecode(_os.fspath(item)) for item in items])


# The counts are made whole in memory (4 bytes a cell), as the command's GeoTIFF: at most 1 GiB.
_MAX_CELLS = 1 << 28


class FileError(NamedTuple):
    """A file that could not be read: counted nowhere."""

    path: str
    error: str


def _check(cell: float, of: str) -> None:
    if of not in ("tracks", "thermals", "time"):
        raise ValueError(f"of={of!r}: heatmaps count 'tracks', 'thermals' (flights climbing there) or 'time' (seconds)")
    if not (1 <= cell <= 100000):
        raise ValueError(f"cell {cell} is not in 1..100000 metres")


def count_files(paths: Sequence[str], cell: float = 50.0, strict: bool = False,
                of: str = "tracks") -> Tuple[_core.HeatmapCounts, List[FileError]]:
    """The counts of some files, read one after the other (the GIL released), and their errors."""
    counts = _core.HeatmapCounts(float(cell), of)
    errors = []
    for p in paths:
        error = counts.add_file(p, strict)
        if error is not None:
            errors.append(FileError(p, error))
    return counts, errors


class Heatmap:
    """Counts per cell of a Web Mercator grid (EPSG:3857): of tracks, of flights climbing in a
    thermal (of="thermals") or of seconds spent (of="time").

    counts: (rows, columns) uint32 array, the northern row first.
    geotransform: GDAL's six numbers (x0, cell, 0, y0, 0, -cell) in EPSG:3857 metres.
    cell: the cell size in Mercator metres; of: what is counted; tracks: how many were counted;
    errors: the files that could not be read (FileError: path, error), counted nowhere.
    """

    def __init__(self, counts: _core.HeatmapCounts, bbox=None, errors: Sequence[FileError] = ()):
        self.cell = counts.cell
        self.of = counts.of
        self.tracks = counts.tracks
        self.errors = list(errors)
        self.window = counts.window_of(*bbox) if bbox is not None else counts.extent()
        self._counts = counts.cropped(self.window) if bbox is not None else counts
        col0, row0, col1, row1 = self.window
        if (col1 - col0) * (row1 - row0) > _MAX_CELLS:
            raise ValueError(f"{col1 - col0}x{row1 - row0} cells is more than one heatmap holds here ({_MAX_CELLS} "
                             "cells, 1 GiB): a larger cell, or a bbox around the tracks you want")
        if col1 > col0 and row1 > row0:
            self.counts = counts.raster(self.window)
        else:
            self.counts = _np.zeros((0, 0), dtype=_np.uint32)
        self.geotransform = tuple(counts.geotransform(self.window))

    def __repr__(self) -> str:
        rows, cols = self.counts.shape
        most = int(self.counts.max()) if self.counts.size else 0
        return (f"<trailray.Heatmap of {self.of}: {self.tracks} tracks, {self.cell:g} m cells, {cols}x{rows}, "
                f"at most {most}>")

    @classmethod
    def read(cls, path) -> "Heatmap":
        """The heatmap a tile output (.mbtiles or folder, of ``trailray heatmap`` or ``write``)
        carries: its exact counts, to look at or to add to (``trailray heatmap A.mbtiles more/``)."""
        return cls(_core.read_heatmap_counts(_os.fspath(path)))

    def write(self, path, zoom: Optional[Tuple[int, int]] = None, colormap: str = "warm", scale: str = "log") -> None:
        """Written atomically, replacing what was there. path ending in .tif: the counts as a
        GeoTIFF (one band, UInt32, EPSG:3857). .mbtiles or a folder (a name ending in /):
        coloured XYZ tiles (zoom: (min, max), default 0 to the zoom whose pixels match the cell;
        colormap as ``--colormap``; scale "log" or "linear") with the exact counts beside them,
        as ``trailray heatmap -o`` writes them."""
        if self.counts.size == 0:
            raise ValueError("an empty heatmap (nothing counted) has no picture to write")
        path = _os.fspath(path)
        if not path.lower().endswith((".tif", ".tiff")):
            low, high = zoom if zoom is not None else (0, None)
            self._counts.write_tiles(path, int(low), None if high is None else int(high), colormap, scale)
            return
        data = _core.encode_count_geotiff(self.counts, list(self.geotransform), self.of)
        folder = _os.path.dirname(_os.path.abspath(path))
        fd, temporary = _tempfile.mkstemp(prefix="." + _os.path.basename(path) + ".", dir=folder)
        try:
            with _os.fdopen(fd, "wb") as f:
                f.write(data)
                f.flush()
                _os.fsync(f.fileno())
            _os.replace(temporary, path)
        except BaseException:
            if _os.path.exists(temporary):
                _os.unlink(temporary)
            raise


def heatmap(files, cell: float = 50.0, of: str = "tracks", bbox: Optional[Tuple[float, float, float, float]] = None,
            strict: bool = False, threads: Optional[int] = None) -> Heatmap:
    """How many tracks passed through each cell, as ``trailray heatmap`` counts them.

    files: a path, a folder, a pattern or a list of them (as the command line takes them).
    cell: Mercator metres (50 m on the equator; times cos(latitude) on the ground).
    of: "tracks" (tracks through a cell), "thermals" (flights climbing in a thermal there, as
    ``trailray flight`` finds them) or "time" (seconds spent there).
    bbox: (min_lat, min_lon, max_lat, max_lon) for the window, else the tracks' extent.
    threads: files are read on this many threads (default: every core), each file freed once counted.
    A file that cannot be read is counted nowhere and listed in ``Heatmap.errors``.
    """
    _check(cell, of)
    paths = expand_files(files)
    threads = max(1, min(threads or _os.cpu_count() or 1, len(paths) or 1))
    chunks = [paths[i::threads] for i in range(threads)]
    with _futures.ThreadPoolExecutor(max_workers=threads) as pool:
        parts = list(pool.map(lambda chunk: count_files(chunk, cell, strict, of), chunks))
    total = _core.HeatmapCounts(float(cell), of)
    errors = []
    for counts, errs in parts:
        total.merge(counts)
        errors += errs
    order = {p: i for i, p in enumerate(paths)}
    errors.sort(key=lambda e: order.get(e.path, 0))
    return Heatmap(total, bbox, errors)
