// Placeholder until the IGC reader lands.
#include "track/io/readers.hpp"

namespace trailray::track {

ReadResult read_igc(ByteSource& source, const ReadOptions&) {
  ReadResult r;
  r.file.format = Format::Igc;
  r.error = Diagnostic{source.display_name(), {}, "IGC reader not implemented yet"};
  return r;
}

}  // namespace trailray::track
