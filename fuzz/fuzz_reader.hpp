#pragma once
// Shared body of the reader fuzzers: the input goes through the same steps as
// load_track_file() -- a ByteSource over the bytes (gzip detected there), a peek at the head,
// detect_format() on it, then one reader over the same source (so the peeked bytes are
// replayed) -- and the result is checked against the readers' documented contract.

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <string_view>

#include "track/io/byte_source.hpp"
#include "track/io/format_detect.hpp"
#include "track/io/readers.hpp"

namespace trailray::fuzz {

inline void check(bool ok, const char* what) {
  if (!ok) {
    std::fprintf(stderr, "fuzz: contract violated: %s\n", what);
    std::abort();
  }
}

inline void check_point(const track::TrackPoint& p) {
  // readers.hpp: points with invalid coordinates are dropped.
  check(track::valid_coordinates(p.lat, p.lon), "a point with invalid coordinates was kept");
}

inline void check_result(const track::ReadResult& r) {
  if (r.error) check(!r.error->message.empty(), "an error without a message");
  for (const auto& w : r.warnings) check(!w.message.empty(), "a warning without a message");
  for (const auto& t : r.file.tracks)
    for (const auto& s : t.segments)
      for (const auto& p : s.points) check_point(p);
  for (const auto& rt : r.file.routes)
    for (const auto& p : rt.points) check_point(p);
  for (const auto& w : r.file.waypoints) check_point(w.point);
}

// Options come from the input's length, not its bytes, so every byte stays file content and
// the same input always runs the same way.
inline track::ReadOptions options_for(std::size_t size) {
  track::ReadOptions o;
  o.strict = size % 5 == 3;
  // KMZ: inputs are at most a few MiB; a smaller budget than the default still catches a zip bomb
  // but keeps each run fast.
  o.kmz_max_bytes = 64 << 20;
  switch (size % 3) {
    case 0:
      o.igc_altitude = track::ReadOptions::IgcAltitude::Auto;
      break;
    case 1:
      o.igc_altitude = track::ReadOptions::IgcAltitude::Gnss;
      break;
    default:
      o.igc_altitude = track::ReadOptions::IgcAltitude::Pressure;
      break;
  }
  return o;
}

using Reader = track::ReadResult (*)(track::ByteSource&, const track::ReadOptions&);

inline int run_reader(const std::uint8_t* data, std::size_t size, Reader reader, const char* name) {
  std::string bytes(reinterpret_cast<const char*>(data), size);
  auto source = track::ByteSource::from_memory(std::move(bytes), name);
  if (!source) return 0;
  std::string_view head = source->peek(4096);
  (void)track::detect_format(head, name);
  (void)track::detect_format(head, "-");  // no name to fall back on: content only
  track::ReadResult result = reader(*source, options_for(size));
  check_result(result);
  if (result.error) (void)result.error->to_string();
  for (const auto& w : result.warnings) (void)w.to_string();
  return 0;
}

}  // namespace trailray::fuzz
