#pragma once
// Shared by the FIT tests: reading bytes with read_fit, a record definition and its values,
// and the points of a file in order.

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "fit_test_writer.hpp"
#include "track/io/byte_source.hpp"
#include "track/io/readers.hpp"

namespace trailray::test::fit {

inline track::ReadResult read_fit_bytes(const std::string& bytes, bool strict = false) {
  auto source = track::ByteSource::from_memory(bytes, "test.fit");
  track::ReadOptions options;
  options.strict = strict;
  return track::read_fit(*source, options);
}

inline std::vector<track::TrackPoint> all_points(const track::TrackFile& f) {
  std::vector<track::TrackPoint> out;
  for (const auto& t : f.tracks)
    for (const auto& s : t.segments) out.insert(out.end(), s.points.begin(), s.points.end());
  return out;
}

inline std::string metadata_field(const track::TrackFile& f, const std::string& key) {
  for (const auto& [k, v] : f.metadata.fields)
    if (k == key) return v;
  return {};
}

// Global message numbers used by the tests.
enum : std::uint16_t {
  kFileIdMsg = 0,
  kDeviceSettingsMsg = 2,
  kSessionMsg = 18,
  kLapMsg = 19,
  kRecordMsg = 20,
  kEventMsg = 21,
  kCourseMsg = 31,
  kCoursePointMsg = 32,
  kTimestampCorrelationMsg = 162,
};

// record: timestamp, lat, lon, altitude, heart rate, cadence, speed, power, temperature.
inline const std::vector<FieldSpec> kRecordFields = {{253, 4, kUint32}, {0, 4, kSint32}, {1, 4, kSint32},
                                                     {2, 2, kUint16},   {3, 1, kUint8},  {4, 1, kUint8},
                                                     {6, 2, kUint16},   {7, 2, kUint16}, {13, 1, kSint8}};

inline constexpr double kT0 = 1718000000.0;  // 2024-06-10T06:13:20Z

struct RecordValues {
  double time = kT0;
  double lat = 46.5;
  double lon = 7.5;
  double ele = 1000.0;
  int hr = 120;
  int cadence = 80;
  double speed = 3.5;
  int power = 200;
  int temperature = -5;
};

inline std::vector<Value> record(const RecordValues& r) {
  return {Value(std::uint64_t{fit_time(r.time)}),
          Value(semicircles(r.lat)),
          Value(semicircles(r.lon)),
          Value(static_cast<std::uint64_t>(std::llround((r.ele + 500.0) * 5.0))),
          Value(r.hr),
          Value(r.cadence),
          Value(static_cast<std::uint64_t>(std::llround(r.speed * 1000.0))),
          Value(r.power),
          Value(r.temperature)};
}

// A file with `n` records one second apart, moving north from 46.5N 7.5E.
inline std::string simple_activity(int n, bool big_endian = false, bool long_header = true) {
  Writer w;
  w.define(0, kRecordMsg, kRecordFields, {}, big_endian ? 1 : 0);
  for (int i = 0; i < n; ++i) {
    RecordValues r;
    r.time = kT0 + i;
    r.lat = 46.5 + 0.0001 * i;
    r.hr = 100 + i;
    w.data(0, record(r));
  }
  return w.file(long_header);
}

}  // namespace trailray::test::fit
