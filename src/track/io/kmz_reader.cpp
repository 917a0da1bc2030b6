// Placeholder until the KMZ reader lands (issue 14): every KMZ file is refused with a
// positioned error, like any unreadable file.
#include "track/io/readers.hpp"

namespace trailray::track {

ReadResult read_kmz(ByteSource& source, const ReadOptions& /*options*/) {
  ReadResult result;
  result.file.format = Format::Kmz;
  result.error = Diagnostic{source.display_name(), {}, "KMZ files are not read yet"};
  return result;
}

}  // namespace trailray::track
