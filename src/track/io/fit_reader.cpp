// Garmin FIT reader: the whole input is read into memory (FIT files are compact: hours of
// one-second records make a few MB), decoded (fit_decoder.cpp) and mapped onto the model
// (fit_track_builder.hpp says how).
#include <string>
#include <vector>

#include "track/io/fit_decoder.hpp"
#include "track/io/fit_track_builder.hpp"
#include "track/io/readers.hpp"

namespace trailray::track {

ReadResult read_fit(ByteSource& source, const ReadOptions& options) {
  ReadResult result;
  result.file.format = Format::Fit;
  WarningCollector warnings(source.display_name());
  std::string bytes;
  std::vector<char> buffer(1 << 16);  // on the heap: small stacks (WebAssembly) stay safe
  for (;;) {
    const std::ptrdiff_t n = source.next(buffer.data(), buffer.size());
    if (n < 0) {
      result.error = Diagnostic{
          source.display_name(), {0, 0, static_cast<std::int64_t>(bytes.size())}, "cannot read: " + source.error()};
      return result;
    }
    if (n == 0) break;
    bytes.append(buffer.data(), static_cast<std::size_t>(n));
  }
  fit::TrackBuilder builder(result.file, warnings);
  fit::DecodeStats stats;
  result.error = fit::decode(bytes, warnings, stats, [&](const fit::Message& m) { builder.add(m); });
  if (result.error) return result;
  builder.finish(stats);
  finish_read(result, warnings, options);
  return result;
}

}  // namespace trailray::track
