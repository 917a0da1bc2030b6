#include "track/io/points_csv.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <optional>
#include <vector>

#include "track/io/byte_source.hpp"
#include "track/io/load.hpp"
#include "track/io/parse_util.hpp"
#include "track/io/readers.hpp"

namespace trailray::track {
namespace {

std::string lower(std::string_view s) {
  std::string out(s);
  for (char& c : out) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return out;
}

// The fields of one line; a quoted field keeps its separators and turns "" into ".
std::vector<std::string> split_fields(std::string_view line, char separator) {
  std::vector<std::string> fields(1);
  bool quoted = false;
  for (std::size_t i = 0; i < line.size(); ++i) {
    const char c = line[i];
    if (quoted) {
      if (c != '"')
        fields.back() += c;
      else if (i + 1 < line.size() && line[i + 1] == '"')
        fields.back() += line[++i];
      else
        quoted = false;
    } else if (c == '"' && trim(fields.back()).empty()) {
      fields.back().clear();
      quoted = true;
    } else if (c == separator) {
      fields.emplace_back();
    } else {
      fields.back() += c;
    }
  }
  return fields;
}

// The header's first separator; a header of one column has none (and is refused later).
char separator_of(std::string_view header) {
  const std::size_t at = header.find_first_of(",;\t");
  return at == std::string_view::npos ? ',' : header[at];
}

struct Columns {
  std::optional<std::size_t> name, lat, lon, ele, desc;
};

std::optional<std::size_t>* column_for(Columns& c, const std::string& title) {
  static const std::array<std::pair<const char*, int>, 12> kTitles{{{"name", 0},
                                                                    {"lat", 1},
                                                                    {"latitude", 1},
                                                                    {"lon", 2},
                                                                    {"lng", 2},
                                                                    {"longitude", 2},
                                                                    {"ele", 3},
                                                                    {"elevation", 3},
                                                                    {"alt", 3},
                                                                    {"altitude", 3},
                                                                    {"desc", 4},
                                                                    {"description", 4}}};
  for (const auto& [text, which] : kTitles)
    if (title == text) {
      std::optional<std::size_t>* all[] = {&c.name, &c.lat, &c.lon, &c.ele, &c.desc};
      return all[which];
    }
  return nullptr;
}

// Splits text into lines ("\n", "\r\n" or "\r"), numbering them from 1.
class Lines {
 public:
  explicit Lines(std::string_view text) : text_(text) {}
  bool next(std::string_view& line) {
    if (at_ >= text_.size()) return false;
    ++number_;
    const std::size_t end = text_.find_first_of("\r\n", at_);
    line = text_.substr(at_, end == std::string_view::npos ? std::string_view::npos : end - at_);
    at_ = end == std::string_view::npos ? text_.size() : end + 1;
    if (end != std::string_view::npos && text_[end] == '\r' && at_ < text_.size() && text_[at_] == '\n') ++at_;
    return true;
  }
  std::int64_t number() const { return number_; }

 private:
  std::string_view text_;
  std::size_t at_ = 0;
  std::int64_t number_ = 0;
};

bool skipped(std::string_view line) {
  const std::string_view t = trim(line);
  return t.empty() || t.front() == '#';
}

}  // namespace

ReadResult read_points_csv(std::string_view text, const std::string& name) {
  ReadResult result;
  const auto fail = [&](std::int64_t line, const std::string& message) {
    result.file.waypoints.clear();
    result.error = Diagnostic{name, {line, 0, -1}, message};
    return result;
  };
  // A UTF-8 byte order mark (spreadsheets write one) is not part of the first title.
  if (text.substr(0, 3) == "\xEF\xBB\xBF") text.remove_prefix(3);
  Lines lines(text);
  std::string_view line;
  while (lines.next(line) && skipped(line)) {
  }
  if (lines.number() == 0 || skipped(line)) return fail(0, "no header row (name, lat, lon, ele columns)");
  const char separator = separator_of(line);
  Columns columns;
  const std::vector<std::string> titles = split_fields(line, separator);
  for (std::size_t i = 0; i < titles.size(); ++i)
    if (auto* column = column_for(columns, lower(trim(titles[i])))) {
      if (column->has_value())
        return fail(lines.number(), "the header names column '" + std::string(trim(titles[i])) + "' twice");
      *column = i;
    }
  if (!columns.lat || !columns.lon)
    return fail(lines.number(),
                "the header row must name a lat (latitude) and a lon (longitude) column, e.g. name,lat,lon,ele");
  // Fields missing at the end of a row are empty; the coordinates must be there.
  const std::size_t needed = std::max(*columns.lat, *columns.lon) + 1;
  while (lines.next(line)) {
    if (skipped(line)) continue;
    const std::vector<std::string> fields = split_fields(line, separator);
    const std::int64_t at = lines.number();
    const auto field = [&](const std::optional<std::size_t>& column) -> std::string_view {
      return column && *column < fields.size() ? trim(fields[*column]) : std::string_view{};
    };
    if (fields.size() < needed)
      return fail(at,
                  "has " + std::to_string(fields.size()) + " fields: the coordinates need " + std::to_string(needed));
    const auto lat = parse_double(field(columns.lat));
    const auto lon = parse_double(field(columns.lon));
    if (!lat || !lon) return fail(at, "latitude and longitude must be numbers (degrees)");
    if (!valid_coordinates(*lat, *lon))
      return fail(at, "latitude must be within -90..90 and longitude within -180..180 degrees");
    Waypoint w;
    w.point.lat = *lat;
    w.point.lon = *lon;
    const std::string_view ele = field(columns.ele);
    if (!ele.empty()) {
      const auto value = parse_double(ele);
      if (!value) return fail(at, "elevation '" + std::string(ele) + "' is not a number (metres; empty for none)");
      w.point.ele = *value;
    }
    w.name = std::string(field(columns.name));
    w.description = std::string(field(columns.desc));
    result.file.waypoints.push_back(std::move(w));
  }
  return result;
}

bool is_points_csv_path(const std::string& path) {
  std::string p = lower(path);
  if (p.size() > 3 && p.ends_with(".gz")) p.resize(p.size() - 3);
  return p.ends_with(".csv") || p.ends_with(".tsv") || p.ends_with(".txt");
}

ReadResult load_points_file(const std::string& path, const ReadOptions& options) {
  if (!is_points_csv_path(path)) return load_track_file(path, options);
  ReadResult result;
  std::string open_error;
  auto source = ByteSource::open(path, open_error);
  if (!source) {
    result.error = Diagnostic{path, {}, "cannot open: " + open_error};
    return result;
  }
  std::string text;
  std::array<char, 65536> buffer{};
  for (;;) {
    const std::ptrdiff_t n = source->next(buffer.data(), buffer.size());
    if (n < 0) {
      result.error = Diagnostic{path, {}, "cannot read: " + source->error()};
      return result;
    }
    if (n == 0) break;
    text.append(buffer.data(), static_cast<std::size_t>(n));
  }
  return read_points_csv(text, path);
}

}  // namespace trailray::track
