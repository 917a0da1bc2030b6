#!/usr/bin/python3
"""The positions of KML and KMZ files as GDAL's OGR reads them (LIBKML driver, else KML).

The peer for trailray's KML/KMZ readers (tests/track/io/kml_conformance_test.cpp). For a KMZ
the KML entries are opened one by one through /vsizip/, chosen by trailray's rule (doc.kml when
the archive has one, else every .kml entry in the archive's order), because OGR reads only the
first KML of an archive.

Usage: ogr_kml_coordinates.py FILE...
Prints one JSON object per file: {"path", "ok", "drivers", "points": [[lon, lat], ...],
"lines": [[[lon, lat], ...], ...]} -- points from Point geometries, lines from LineStrings (a
MultiLineString or a geometry collection gives its parts), in OGR's order.
"""

import json
import sys

from osgeo import gdal, ogr

gdal.UseExceptions()


def kml_entries(path):
    if not path.lower().endswith(".kmz"):
        return [path]
    names = gdal.ReadDirRecursive("/vsizip/" + path) or []
    names = [n for n in names if not n.endswith("/")]
    for n in names:
        if n.lower() == "doc.kml":
            return ["/vsizip/" + path + "/" + n]
    def is_kml(n):
        low = n.lower()
        base = low.rsplit("/", 1)[-1]
        return low.endswith(".kml") and not low.startswith("__macosx/") and not base.startswith("._")
    return ["/vsizip/" + path + "/" + n for n in names if is_kml(n)]


def walk(geometry, points, lines):
    kind = ogr.GT_Flatten(geometry.GetGeometryType())
    if kind == ogr.wkbPoint:
        points.append([geometry.GetX(), geometry.GetY()])
    elif kind == ogr.wkbLineString:
        lines.append([[geometry.GetX(i), geometry.GetY(i)] for i in range(geometry.GetPointCount())])
    elif kind in (ogr.wkbMultiPoint, ogr.wkbMultiLineString, ogr.wkbGeometryCollection):
        for i in range(geometry.GetGeometryCount()):
            walk(geometry.GetGeometryRef(i), points, lines)


def read(path):
    out = {"path": path, "ok": False, "drivers": [], "points": [], "lines": []}
    entries = kml_entries(path)
    if not entries:
        return out
    for entry in entries:
        try:
            ds = ogr.Open(entry)
        except RuntimeError as e:
            out["error"] = str(e)
            return out
        if ds is None:
            return out
        out["drivers"].append(ds.GetDriver().GetName())
        for li in range(ds.GetLayerCount()):
            for feature in ds.GetLayer(li):
                g = feature.GetGeometryRef()
                if g is not None:
                    walk(g, out["points"], out["lines"])
    out["ok"] = True
    return out


for p in sys.argv[1:]:
    print(json.dumps(read(p)))
