"""trailray for Python: GPS and flight tracks read, measured, analysed and drawn in 3D on terrain.

    import trailray
    f = trailray.read("flight.igc")          # GPX, IGC, TCX, FIT, KML, KMZ, GeoJSON (gzip too)
    t = f.tracks[0]
    t.lat, t.lon, t.ele, t.time              # NumPy arrays over every point
    t.stats()["clean"]["distance_2d_m"]      # the numbers of `trailray stats --json`
    trailray.render(t, size=(800, 600))      # a picture, (h, w, 4) uint8

The same readers, statistics, analysis and renderer as the `trailray` command line, in C++;
the GIL is released while they work, so threads read and render in parallel.
"""

from __future__ import annotations

import os as _os
import warnings as _warnings
from typing import NamedTuple as _NamedTuple
from typing import Optional as _Optional
from typing import Union as _Union

import numpy as _np

from . import _core
from ._core import Airspaces, File, Segment, Task, Track
from ._heatmap import FileError, Heatmap, heatmap

__all__ = [
    "read",
    "render",
    "png",
    "score",
    "flight",
    "elevation",
    "Task",
    "Airspaces",
    "heatmap",
    "Heatmap",
    "FileError",
    "File",
    "Track",
    "Segment",
    "Waypoint",
    "ReadError",
    "TrailrayWarning",
]


class ReadError(ValueError):
    """A file that cannot be read. ``str()`` names the file and the position
    ("file:line:column: message"); ``path``, ``line`` and ``column`` give them apart
    (``line`` and ``column`` 0 where unknown)."""

    def __init__(self, message: str, path: str = "", line: int = 0, column: int = 0):
        super().__init__(message)
        self.path = path
        self.line = line
        self.column = column


class TrailrayWarning(UserWarning):
    """A reader's warning: something in the file was skipped or repaired (the file and the
    position are in the message). ``strict=True`` makes the first one a ReadError."""


class Waypoint(_NamedTuple):
    """A waypoint of a file: ``ele`` None without an elevation, ``time`` a numpy.datetime64 or None."""

    name: str
    lat: float
    lon: float
    ele: _Optional[float]
    time: _Optional[_np.datetime64]
    description: str
    symbol: str


_Source = _Union[str, "_os.PathLike[str]", bytes, bytearray, memoryview]


def read(source: _Source, format: _Optional[str] = None, igc_altitude: str = "auto", strict: bool = False) -> File:
    """Read a track file: a path (str or pathlib.Path; gzip-compressed or not) or its bytes.

    format: None detects it from the content (as the command line does); else one of gpx, igc,
        tcx, fit, kml, kmz, geojson.
    igc_altitude: which IGC altitude becomes ``ele``: "auto" (GNSS where the fix has one, else
        pressure), "gnss" or "pressure". Both stay in ``gnss_alt`` and ``pressure_alt``.
    strict: the reader's first warning is a ReadError instead of a warning.

    Raises ReadError (a ValueError) naming the file and the position when it cannot be read,
    and naming the file and the reason ("cannot open: No such file or directory") when it cannot
    be opened. Each reader warning is issued as a
    TrailrayWarning through the warnings module and kept in ``File.warnings``.
    """
    if isinstance(source, (bytearray, memoryview)):
        source = bytes(source)
    elif not isinstance(source, bytes):
        source = _os.fspath(source)
        if isinstance(source, bytes):
            source = _os.fsdecode(source)
        if not isinstance(source, str):
            raise TypeError(f"read() takes a path or bytes, not {type(source).__name__}")
    if format is not None:
        format = format.lower()
    file, error, warnings = _core.read_file(source, format, igc_altitude.lower(), bool(strict))
    for text, _path, _line, _column, _message in warnings:
        if error is None or text != error[0].replace(" (--strict)", ""):
            _warnings.warn(text, TrailrayWarning, stacklevel=2)
    if error is not None:
        text, path, line, column, _message = error
        raise ReadError(text.replace(" (--strict)", " (strict=True)"), path, line, column)
    return file


def _track_to_pandas(self: Track):
    """The points as a pandas DataFrame: lat, lon, ele, time, the recorded channels present, and
    ``segment`` (the segment's index). Needs pandas (Debian: python3-pandas)."""
    try:
        import pandas as pd
    except ImportError as e:  # pragma: no cover - depends on the machine
        raise ImportError("Track.to_pandas() needs pandas (Debian: apt install python3-pandas)") from e
    columns = {"lat": self.lat, "lon": self.lon, "ele": self.ele, "time": pd.to_datetime(self.time, utc=True)}
    for name in self.channels:
        columns[name] = self.channel(name)
    columns["segment"] = _np.repeat(_np.arange(len(self.segments)), [len(s) for s in self.segments])
    return pd.DataFrame(columns)


Track.to_pandas = _track_to_pandas


def _words(value) -> str:
    """A value as the command line writes it: (lat, lon, alt) -> "lat,lon,alt"."""
    if isinstance(value, (tuple, list)):
        return ",".join(_words(v) for v in value)
    return str(value)


def render(
    tracks=(),
    terrain: _Optional[str] = None,
    imagery: _Optional[str] = None,
    size=(1920, 1080),
    color_by: _Optional[str] = None,
    color=None,
    camera=None,
    **style,
) -> _np.ndarray:
    """A picture of tracks on the terrain, as ``trailray render`` draws it (headless, through EGL).

    tracks: a File, a Track, a path (a track file, a folder of them, a pattern), or a list of them.
        Paths are read first, in order, then the Files and Tracks.
    terrain: an elevation source as ``--terrain`` takes it (a raster file, a tile folder, an
        .mbtiles file, an http(s) URL template); None draws the tracks over a neutral ground.
    imagery: the ground's colour as ``--imagery`` takes it; None: a tint by height.
    size: (width, height) in pixels.
    color_by: solid, speed, vspeed, slope, altitude, agl, hr, cadence, power, time, phase,
        density, thermals, cover (with surface=).
    color: '#rrggbb', or a list of them, one per track.
    camera: None frames the tracks; dict(look_at=(lat, lon, alt), distance=m, heading=deg,
        pitch=deg, fov=deg); or (lat, lon, alt, heading, pitch) for the camera itself.
    **style: any other option of ``trailray render``, in Python spelling: width="8m",
        colormap="viridis", shadows=False (--no-shadows), snow=True, legend=False
        (--legend off), curtain=True, time="2024-06-18T12:00:00Z", airspace=[path, ...],
        min_distance=5, timeout=60, pixel_ratio=2, surface="dsm.tif" (--surface: the canopy drawn,
        cut away along the tracks under cover), ...

    Returns an (height, width, 4) uint8 array of sRGB pixels, top row first. The renderer's
    warnings are issued as TrailrayWarning. Raises ValueError for an option the command would
    refuse (the message names the option), and RuntimeError for a file or terrain that cannot
    be read.
    """
    items = tracks if isinstance(tracks, (list, tuple)) else [tracks]
    paths, objects = [], []
    for item in items:
        if isinstance(item, (File, Track)):
            objects.append(item)
        elif isinstance(item, (str, _os.PathLike)):
            paths.append(_os.fspath(item))
        else:
            raise TypeError(f"render() draws Files, Tracks and paths, not {type(item).__name__}")
    options = dict(style)
    options["size"] = f"{int(size[0])}x{int(size[1])}" if isinstance(size, (tuple, list)) else str(size)
    options["terrain"] = "none" if terrain is None else _os.fspath(terrain)
    options["imagery"] = "none" if imagery is None else _os.fspath(imagery)
    if color_by is not None:
        options["color_by"] = color_by
    if color is not None:
        options["color"] = [color] if isinstance(color, str) else list(color)
    if isinstance(camera, dict):
        options.update(camera)
    elif camera is not None:
        options["camera"] = camera
    # Values the command line writes as one word: a place "lat,lon,alt", a span "near:far".
    for key, separator in (("look_at", ","), ("camera", ","), ("occlusion_fade", ":"), ("range", ":")):
        if isinstance(options.get(key), (tuple, list)):
            options[key] = separator.join(str(v) for v in options[key])
    # Options that take several files (each a repeated option); labels=False is --no-labels.
    for key in ("airspace", "labels"):
        value = options.get(key)
        if isinstance(value, (str, _os.PathLike)):
            options[key] = [_os.fspath(value)]
        elif value is not None and not isinstance(value, bool):
            options[key] = [_os.fspath(v) for v in value]
    picture, warnings = _core.render(paths, objects, options)
    for text in warnings:
        if terrain is None and text.startswith("no terrain source covers the view"):
            continue  # asked for: terrain=None is the neutral ground
        _warnings.warn(text, TrailrayWarning, stacklevel=2)
    return picture


def png(picture: _np.ndarray) -> bytes:
    """An (h, w, 4) uint8 sRGB picture (as render() returns) as PNG bytes: ``open("a.png", "wb").write(png(p))``."""
    return _core.png(picture)


def _repr_png_(self) -> bytes:
    """Jupyter shows a File or a Track as a picture: 800x500, over a neutral ground (no terrain
    is fetched), coloured by speed."""
    with _warnings.catch_warnings():
        _warnings.simplefilter("ignore", TrailrayWarning)
        return png(render(self, size=(800, 500), color_by="speed" if _has_times(self) else None))


def _has_times(item) -> bool:
    tracks = item.tracks + item.routes if isinstance(item, File) else [item]
    return any(len(t) and not _np.isnat(t.time).all() for t in tracks)


File._repr_png_ = _repr_png_
Track._repr_png_ = _repr_png_


def score(flight, rules: str = "xcontest", distance: str = "fcc", trim: bool = True, all_types: bool = False) -> dict:
    """The cross-country score of a flight, as ``trailray score --json`` gives it.

    flight: a path to an IGC file (its B records as the command reads them: the same score to the
        last digit) or a Track (its timed points, one fix per second).
    rules: xcontest, ffvl, fai, fai-oar, fai-cylinders, xcleague.
    distance: "fcc" (the FCC ellipsoidal formula, as igc-xc-score) or "geodesic" (exact WGS84).
    trim: score only the detected flight (launch to landing), not the whole log.
    all_types: optimise every flight type to its own optimum (by_type's "exact" true everywhere).

    Returns a dict: score, distance_km, type, turnpoints, legs, ... and by_type. Raises ValueError for
    unknown rules or fewer than 5 fixes, ReadError for a file that cannot be read.
    """
    if not isinstance(flight, Track):
        flight = _os.fspath(flight)
    return _core.score(flight, rules, distance, bool(trim), bool(all_types))


def flight(track: Track) -> dict:
    """The flight analysis of a track, as a track of ``trailray flight --json``: its flights (take-off
    and landing, circling and gliding phases, thermals with climb rates, glides with glide ratios,
    wind per altitude band), or ``note`` saying why there is none."""
    return _core.flight(track)


def elevation(track: Track, terrain: str, terrain_zoom: _Optional[int] = None, surface: _Optional[str] = None) -> dict:
    """The terrain under every point of a track, as ``trailray elevation --json`` measures it.

    terrain: an elevation source as ``--terrain`` takes it (a raster file, a tile folder, an
        .mbtiles file, an http(s) URL template, one remote raster).
    surface: a surface model (canopy and buildings) as ``--surface`` takes it, beside the terrain.
    Returns {"terrain": heights (float64, NaN without data), "agl": ele - terrain, "source": the
    source's name, "summary": mean/median offset, rmse, points below ground, ...}; with a surface
    also "surface", "canopy" (surface - terrain) arrays, "cover" (a list of "open", "covered",
    "below_ground" or None per point), "surface_source", and the summary's "covered_share".
    """
    return _core.elevation(track, _os.fspath(terrain), terrain_zoom,
                           None if surface is None else _os.fspath(surface))
