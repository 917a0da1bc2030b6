// Placeholder until the TCX reader lands.
#include "track/io/readers.hpp"

namespace trailray::track {

ReadResult read_tcx(ByteSource& source, const ReadOptions&) {
  ReadResult r;
  r.file.format = Format::Tcx;
  r.error = Diagnostic{source.display_name(), {}, "TCX reader not implemented yet"};
  return r;
}

}  // namespace trailray::track
