// libFuzzer target: the OpenAir airspace reader over arbitrary bytes, then an infringement check
// of a short track through the first airspace's box (so the index and the geometry run on what
// the reader made). Contract: an error or a file, every kept airspace with at least two boundary
// points of valid coordinates, messages never empty, no crash, no endless arc.
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string_view>

#include "track/airspace/infringement.hpp"
#include "track/airspace/openair_reader.hpp"
#include "track/io/readers.hpp"

namespace {

void check(bool ok, const char* what) {
  if (!ok) {
    std::fprintf(stderr, "fuzz: contract violated: %s\n", what);
    std::abort();
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace trailray::track::airspace;
  trailray::track::ReadOptions options;
  options.strict = size % 5 == 3;  // from the length, so every byte stays file content
  const AirspaceReadResult r =
      read_openair(std::string_view(reinterpret_cast<const char*>(data), size), "fuzz.txt", options);
  if (r.error) check(!r.error->message.empty(), "an error without a message");
  for (const auto& w : r.warnings) check(!w.message.empty(), "a warning without a message");
  for (const auto& a : r.file.airspaces) {
    check(a.boundary.size() >= 2, "an airspace with fewer than 2 points was kept");
    for (const auto& p : a.boundary)
      check(trailray::track::valid_coordinates(p.lat, p.lon), "an invalid boundary point");
  }
  if (r.file.airspaces.empty()) return 0;
  // The first few airspaces only: a check over thousands of overlapping huge circles is slow by
  // nature (points x airspaces x vertices), not a bug.
  AirspaceFile few;
  for (std::size_t i = 0; i < r.file.airspaces.size() && i < 8; ++i) few.airspaces.push_back(r.file.airspaces[i]);
  const AirspaceIndex index(few);
  const BoundingBox& b = index.box(0);
  std::vector<CheckPoint> track;
  for (int i = 0; i <= 20; ++i) {
    const double f = i / 20.0;
    track.push_back({b.lat_min + (b.lat_max - b.lat_min) * f, b.lon_min + (b.lon_max - b.lon_min) * f, double(i),
                     100.0 * i, 100.0 * i, i % 2 ? 50.0 : trailray::track::kMissing});
  }
  for (const auto& f : find_infringements(index, {track})) {
    check(f.airspace < few.airspaces.size(), "an infringement of an unknown airspace");
    check(f.first_point <= f.last_point && f.last_point < track.size(), "infringement points out of range");
    check(!(f.exit_time < f.entry_time), "an exit before the entry");
  }
  return 0;
}
