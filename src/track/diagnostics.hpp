#pragma once
// Errors and warnings that name the file and the position. Readers never throw through
// layers: they return a ReadResult carrying the value, the warnings and at most one error.

#include <cstdint>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "geo/threads.hpp"
#include "track/model.hpp"

namespace trailray::track {

// Where in the input something happened. line/column are 1-based (0 = unknown); byte_offset
// is 0-based into the (decompressed) input (-1 = unknown).
struct SourcePosition {
  std::int64_t line = 0;
  std::int64_t column = 0;
  std::int64_t byte_offset = -1;
};

struct Diagnostic {
  std::string file;  // display name: the path as given, or "<stdin>"
  SourcePosition position;
  std::string message;

  // "file:line:col: message", "file: byte N: message" or "file: message".
  std::string to_string() const;
};

// Collects repeated warnings of one kind into one line with a count and the first position,
// so a file with 10,000 bad points gives one readable warning, not 10,000.
class WarningCollector {
 public:
  explicit WarningCollector(std::string file) : file_(std::move(file)) {}

  // `kind` groups warnings; `message` describes one occurrence (used for the first one).
  void add(const std::string& kind, const SourcePosition& where, const std::string& message);
  // A one-off warning, never grouped.
  void add_single(const SourcePosition& where, const std::string& message);

  // Adds `later`'s warnings after these (a later part of the same file): a kind already here
  // adds its count, a new one comes after; every position passes through `shift`.
  void merge(const WarningCollector& later, const std::function<SourcePosition(SourcePosition)>& shift);

  std::size_t total() const;
  std::vector<Diagnostic> diagnostics() const;
  const std::string& file() const { return file_; }

 private:
  struct Group {
    std::size_t count = 0;
    SourcePosition first;
    std::string first_message;
    std::size_t order = 0;
  };
  std::string file_;
  std::map<std::string, Group> groups_;
  std::vector<Diagnostic> singles_;
  std::size_t next_order_ = 0;
};

struct ReadOptions {
  // Turn reader warnings (truncation, invalid points, bad records) into errors.
  bool strict = false;
  // IGC: which altitude becomes the point elevation.
  enum class IgcAltitude { Auto, Gnss, Pressure } igc_altitude = IgcAltitude::Auto;
  // A plain GPX file at least this big is read in two halves on two threads (same result).
  // Never by default where there are no threads (it would only add the joining).
  std::int64_t two_part_min_bytes = geo::kThreadsAvailable ? std::int64_t{8} << 20 : INT64_MAX;
  // KMZ: the most bytes the archive may have, and its KML entries may decompress to together
  // (a zip bomb is refused with an error instead of filling memory).
  std::int64_t kmz_max_bytes = std::int64_t{1} << 30;
};

struct ReadResult {
  TrackFile file;
  std::vector<Diagnostic> warnings;
  std::optional<Diagnostic> error;

  bool ok() const { return !error.has_value(); }
};

}  // namespace trailray::track
