#pragma once
// The IGC reader's parser, internal to it: fed the file line by line, it parses the records
// into one track (igc_records.cpp) and assembles the points' dates and elevations at the end
// (igc_reader.cpp, which also states the rules).

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "track/diagnostics.hpp"
#include "track/model.hpp"

namespace trailray::track::detail {

constexpr std::size_t kBaseLength = 35;  // a B record without extensions

struct Extension {
  char code[4] = {};
  std::size_t start = 0;  // 0-based index into the B record
  std::size_t end = 0;    // one past the last byte
  std::string_view name() const { return std::string_view(code, 3); }
};

struct RawAltitude {
  std::int32_t pressure = 0;
  std::int32_t gnss = 0;
  bool fix_3d = false;
};

class IgcParser {
 public:
  IgcParser(ReadResult& result, WarningCollector& warnings, const ReadOptions& options)
      : file_(result.file), warnings_(warnings), options_(options) {}

  void line(std::string_view s, std::int64_t line_no, std::int64_t offset, bool last_unterminated);
  void long_line(std::int64_t line_no, std::int64_t offset);
  // After the last line: dates, elevations, the not-IGC check. False when it is not IGC.
  bool finish(ReadResult& result, const std::string& name);

  std::vector<TrackPoint>& points() { return file_.tracks.front().segments.front().points; }

 private:
  SourcePosition at(std::size_t column) const {
    return SourcePosition{line_no_, static_cast<std::int64_t>(column), offset_ + static_cast<std::int64_t>(column) - 1};
  }

  std::size_t expected_b_length() const {
    std::size_t n = kBaseLength;
    for (const Extension& e : extensions_) n = std::max(n, e.end);
    return n;
  }

  void drop(const char* kind, std::size_t column, const std::string& why) {
    warnings_.add(kind, at(column), why + ": fix dropped");
  }

  void b_record(std::string_view s);
  void i_record(std::string_view s);
  void a_record(std::string_view s);
  void h_record(std::string_view s);
  // "DDMMYY" or "DDMMYY,NN" (flight number), from HFDTE010123 or HFDTEDATE:010123,01.
  void date_record(std::string_view v);
  void assign_elevation();

  TrackFile& file_;
  WarningCollector& warnings_;
  const ReadOptions& options_;
  std::vector<Extension> extensions_;
  std::vector<RawAltitude> altitudes_;
  std::optional<long long> date_days_;
  std::int64_t line_no_ = 0;
  std::int64_t offset_ = 0;
  std::size_t b_lines_ = 0;
  long long day_ = 0;
  double prev_tod_ = 0.0;
  bool have_prev_ = false;
  bool seen_a_ = false;
  bool seen_h_ = false;
  bool pressure_present_ = false;
  bool gnss_present_ = false;
};

}  // namespace trailray::track::detail
