#!/usr/bin/python3
"""Heights of points on a raster's own grid, computed with GDAL's Python bindings alone.

The reference for trailray's GdalHeightSource::sample_native (tests/terrain/gdal/gdal_conformance_test.cpp);
written independently of trailray's code, from the rule stated in src/terrain/gdal/gdal_raster.hpp:

  1. WGS84 (EPSG:4326, longitude first) -> the raster's CRS with osr, then -> continuous pixel
     coordinates (px, py) by the inverse geotransform; pixel (i, j) is centred on (i + 0.5, j + 0.5).
  2. Outside [0, width] x [0, height], or a failed transformation: nan.
  3. Bilinear weights between the four nearest pixel centres.
  4. Pixels outside the raster, equal to nodata, or NaN are left out and the weights of the
     others renormalised; nan when no weight is left.
  5. raw * scale + offset.

Usage: gdal_heights.py RASTER POINTS   (POINTS: one "lat lon" per line, degrees)
Prints one height per input line, "%.6f" or "nan".
"""

import math
import sys

from osgeo import gdal, osr


def main():
    if len(sys.argv) != 3:
        sys.stderr.write("usage: gdal_heights.py RASTER POINTS\n")
        return 2
    raster_path, points_path = sys.argv[1], sys.argv[2]
    gdal.UseExceptions()
    osr.UseExceptions()

    dataset = gdal.Open(raster_path, gdal.GA_ReadOnly)
    band = dataset.GetRasterBand(1)
    width, height = dataset.RasterXSize, dataset.RasterYSize
    # The whole band as float64 (numpy): the conformance rasters are small.
    pixels = band.ReadAsArray().astype("float64")
    nodata = band.GetNoDataValue()
    scale = band.GetScale()
    offset = band.GetOffset()
    scale = 1.0 if scale is None or scale == 0.0 or not math.isfinite(scale) else scale
    offset = 0.0 if offset is None or not math.isfinite(offset) else offset

    inverse = gdal.InvGeoTransform(dataset.GetGeoTransform())

    wgs84 = osr.SpatialReference()
    wgs84.ImportFromEPSG(4326)
    wgs84.SetAxisMappingStrategy(osr.OAMS_TRADITIONAL_GIS_ORDER)
    raster_crs = dataset.GetSpatialRef().Clone()
    raster_crs.SetAxisMappingStrategy(osr.OAMS_TRADITIONAL_GIS_ORDER)
    transformation = osr.CoordinateTransformation(wgs84, raster_crs)

    def valid_pixel(col, row):
        if col < 0 or col >= width or row < 0 or row >= height:
            return None
        value = float(pixels[row, col])
        if math.isnan(value) or (nodata is not None and value == nodata):
            return None
        return value

    def height_at(lat, lon):
        try:
            x, y, _ = transformation.TransformPoint(lon, lat)
        except RuntimeError:
            return math.nan
        if not (math.isfinite(x) and math.isfinite(y)):
            return math.nan
        px, py = gdal.ApplyGeoTransform(inverse, x, y)
        if not (0.0 <= px <= width and 0.0 <= py <= height):
            return math.nan
        u, v = px - 0.5, py - 0.5
        col0, row0 = math.floor(u), math.floor(v)
        fx, fy = u - col0, v - row0
        total, weight_total = 0.0, 0.0
        for dy, wy in ((0, 1.0 - fy), (1, fy)):
            for dx, wx in ((0, 1.0 - fx), (1, fx)):
                value = valid_pixel(col0 + dx, row0 + dy)
                if value is None:
                    continue
                total += wx * wy * value
                weight_total += wx * wy
        if weight_total <= 0.0:
            return math.nan
        return total / weight_total * scale + offset

    out = []
    with open(points_path) as points:
        for line in points:
            fields = line.split()
            if len(fields) < 2:
                out.append("nan")
                continue
            h = height_at(float(fields[0]), float(fields[1]))
            out.append("nan" if math.isnan(h) else "%.6f" % h)
    sys.stdout.write("\n".join(out) + ("\n" if out else ""))
    return 0


if __name__ == "__main__":
    sys.exit(main())
