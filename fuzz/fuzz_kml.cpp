// libFuzzer target: read_kml, or read_kmz when the input is a zip (as load_track_file chooses
// from content), over arbitrary bytes (see fuzz_reader.hpp). One target for both, so that inputs
// grown from the KMZ seeds reach the zip side and the KML inside it.
#include <string_view>

#include "fuzz_reader.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view head(reinterpret_cast<const char*>(data), size < 4 ? size : 4);
  if (head == std::string_view("PK\x03\x04", 4))
    return trailray::fuzz::run_reader(data, size, &trailray::track::read_kmz, "fuzz.kmz");
  return trailray::fuzz::run_reader(data, size, &trailray::track::read_kml, "fuzz.kml");
}
