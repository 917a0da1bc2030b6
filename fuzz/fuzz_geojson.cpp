// libFuzzer target: read_geojson over arbitrary bytes (see fuzz_reader.hpp).
#include "fuzz_reader.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return trailray::fuzz::run_reader(data, size, &trailray::track::read_geojson, "fuzz.geojson");
}
