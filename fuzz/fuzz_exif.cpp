// libFuzzer target: arbitrary bytes as a photo through read_photo_bytes (exiv2 underneath: JPEG
// and HEIC). The contract: a result whose values are in their documented ranges, or an error
// naming the photo; never an exception, a crash or a value out of range.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>

#include "track/photos/exif_reader.hpp"

namespace {

void check(bool ok, const char* what) {
  if (!ok) {
    std::fprintf(stderr, "fuzz: contract violated: %s\n", what);
    std::abort();
  }
}

bool nan_or_within(double v, double limit) { return std::isnan(v) || (std::isfinite(v) && std::abs(v) <= limit); }

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace trailray::track;
  const char* name = "fuzz.jpg";
  PhotoReadResult r;
  try {
    r = read_photo_bytes(data, size, name);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "fuzz: contract violated: read_photo_bytes threw: %s\n", e.what());
    std::abort();
  } catch (...) {
    check(false, "read_photo_bytes threw something");
  }
  check(r.photo.path == name, "the photo's path is not the name given");
  for (const auto& w : r.warnings) check(w.file == name && !w.message.empty(), "a warning without the file or a message");
  if (!r.ok()) {
    check(r.error->file == name && !r.error->message.empty(), "an error without the file or a message");
    return 0;
  }
  const PhotoMetadata& p = r.photo;
  check(std::isnan(p.lat_deg) == std::isnan(p.lon_deg), "a latitude without a longitude");
  check(nan_or_within(p.lat_deg, 90.0) && nan_or_within(p.lon_deg, 180.0), "a position off the Earth");
  check(!(p.lat_deg == 0.0 && p.lon_deg == 0.0), "the position 0, 0 kept");
  check(std::isnan(p.alt_m) || std::isfinite(p.alt_m), "an infinite altitude");
  // Years 1..9999 and a fraction below one second.
  check(nan_or_within(p.taken_local_s, 253402300800.0 + 1.0), "a time beyond year 9999");
  check(nan_or_within(p.gps_time_utc_s, 253402300800.0 + 86400.0), "a GPS time beyond year 9999");
  check(!p.offset_s || (*p.offset_s >= -14 * 3600 && *p.offset_s <= 14 * 3600), "a UTC offset beyond 14 hours");
  check(p.orientation >= 1 && p.orientation <= 8, "an orientation outside 1..8");
  check(p.width >= 0 && p.height >= 0, "a negative size");
  check(p.has_exif || (std::isnan(p.lat_deg) && std::isnan(p.taken_local_s)), "a position or time without EXIF");
  return 0;
}
