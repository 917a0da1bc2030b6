// Placeholder until the FIT reader lands (issue 14): every FIT file is refused with a
// positioned error, like any unreadable file.
#include "track/io/readers.hpp"

namespace trailray::track {

ReadResult read_fit(ByteSource& source, const ReadOptions& /*options*/) {
  ReadResult result;
  result.file.format = Format::Fit;
  result.error = Diagnostic{source.display_name(), {}, "FIT files are not read yet"};
  return result;
}

}  // namespace trailray::track
