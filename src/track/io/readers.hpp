#pragma once
// One reader per format. Each reads the whole source, never throws, and returns the file's
// content with counted warnings, or an error naming the position. Points with invalid
// coordinates (NaN, |lat|>90, |lon|>180) are dropped with a warning; a cut file keeps every
// complete point before the cut, with a warning (an error under ReadOptions::strict).

#include <optional>

#include "track/diagnostics.hpp"
#include "track/io/byte_source.hpp"

namespace trailray::track {

ReadResult read_gpx(ByteSource& source, const ReadOptions& options);
// read_gpx's path for big plain files: both halves at once, joined; nullopt when the file is
// not suited or the halves do not join (read_gpx then reads it in one pass).
std::optional<ReadResult> read_gpx_in_halves(ByteSource& source, const ReadOptions& options);
ReadResult read_igc(ByteSource& source, const ReadOptions& options);
ReadResult read_tcx(ByteSource& source, const ReadOptions& options);
// Garmin FIT (binary; fit_reader.cpp).
ReadResult read_fit(ByteSource& source, const ReadOptions& options);
// KML, and KMZ (a zip holding KML files).
ReadResult read_kml(ByteSource& source, const ReadOptions& options);
ReadResult read_kmz(ByteSource& source, const ReadOptions& options);
ReadResult read_geojson(ByteSource& source, const ReadOptions& options);

// True when lat/lon are finite and within WGS84 range.
inline bool valid_coordinates(double lat, double lon) {
  return lat >= -90.0 && lat <= 90.0 && lon >= -180.0 && lon <= 180.0;  // false for NaN
}

// Shared tail of every reader: applies `strict` (first warning becomes the error) and fills
// result.warnings from the collector.
void finish_read(ReadResult& result, const WarningCollector& warnings, const ReadOptions& options);

}  // namespace trailray::track
