#!/usr/bin/python3
"""A terrain model and a surface model of one made-up place, for tests/app/pictures/surface_render_cli_test.cpp.

Flat ground at 600 m, 400 x 200 pixels of 0.00005 degrees from 46.700-46.710 N, 7.850-7.870 E
(EPSG:4326): in its west half a forest block 20 m tall (the surface only), in its east half an
east-west ridge 150 m high (both models). Writes ground.tif and surface.tif into the folder given.

Usage: surface_scene.py FOLDER
"""

import sys, numpy as np
from osgeo import gdal, osr
out = sys.argv[1]
w, h, px = 400, 200, 0.00005
lon0, lat0 = 7.850, 46.710
lon = lon0 + (np.arange(w) + 0.5) * px
lat = lat0 - (np.arange(h) + 0.5) * px
LON, LAT = np.meshgrid(lon, lat)
ground = 600.0 + 150.0 * np.exp(-((LAT - 46.7035) / 0.0006) ** 2) * ((LON > 7.861) & (LON < 7.869))
forest = (LON > 7.851) & (LON < 7.859) & (LAT > 46.701) & (LAT < 46.709)
surface = ground + 20.0 * forest
srs = osr.SpatialReference(); srs.ImportFromEPSG(4326)
for name, data in (("ground", ground), ("surface", surface)):
    ds = gdal.GetDriverByName("GTiff").Create(f"{out}/{name}.tif", w, h, 1, gdal.GDT_Float32)
    ds.SetGeoTransform((lon0, px, 0, lat0, 0, -px)); ds.SetProjection(srs.ExportToWkt())
    ds.GetRasterBand(1).WriteArray(data.astype(np.float32)); ds = None
