#include "terrain/sources/url_template.hpp"

#include <cstdlib>
#include <optional>

#include "terrain/sources/tile_source.hpp"

namespace trailray::terrain {
namespace {

bool is_name_start(char c) { return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || c == '_'; }
bool is_name_char(char c) { return is_name_start(c) || (c >= '0' && c <= '9'); }

// A ${NAME} reference starting at text[pos] == '$' && text[pos + 1] == '{'.
struct VariableRef {
  std::string name;
  std::size_t end = 0;  // one past the '}'
  std::string error;    // set when malformed
};

VariableRef parse_variable(std::string_view text, std::size_t pos) {
  VariableRef ref;
  const std::size_t close = text.find('}', pos + 2);
  if (close == std::string_view::npos) {
    ref.error = "unclosed ${ at column " + std::to_string(pos + 1);
    return ref;
  }
  const std::string_view name = text.substr(pos + 2, close - pos - 2);
  bool valid = !name.empty() && is_name_start(name.front());
  for (char c : name) valid = valid && is_name_char(c);
  if (!valid) {
    // The name is quoted: it is what the user wrote in the template, never a value.
    ref.error = "bad variable name \"" + std::string(name) + "\" in ${...} at column " + std::to_string(pos + 1) +
                " (letters, digits and _)";
    return ref;
  }
  ref.name = std::string(name);
  ref.end = close + 1;
  return ref;
}

bool starts_with_ignoring_case(std::string_view text, std::string_view prefix) {
  if (text.size() < prefix.size()) return false;
  for (std::size_t i = 0; i < prefix.size(); ++i) {
    char c = text[i];
    if (c >= 'A' && c <= 'Z') c = static_cast<char>(c - 'A' + 'a');
    if (c != prefix[i]) return false;
  }
  return true;
}

std::vector<std::string> split_subdomains(std::string_view list) {
  std::vector<std::string> out;
  std::size_t start = 0;
  while (start <= list.size()) {
    std::size_t comma = list.find(',', start);
    if (comma == std::string_view::npos) comma = list.size();
    std::string_view item = list.substr(start, comma - start);
    while (!item.empty() && item.front() == ' ') item.remove_prefix(1);
    while (!item.empty() && item.back() == ' ') item.remove_suffix(1);
    if (!item.empty()) out.emplace_back(item);
    start = comma + 1;
  }
  return out;
}

ExpandedText expansion_error(std::string error) {
  ExpandedText out;
  out.error = std::move(error);
  return out;
}

}  // namespace

ExpandedText expand_environment(std::string_view text) {
  ExpandedText out;
  std::size_t pos = 0;
  while (pos < text.size()) {
    const std::size_t dollar = text.find("${", pos);
    if (dollar == std::string_view::npos) break;
    out.text.append(text.substr(pos, dollar - pos));
    VariableRef ref = parse_variable(text, dollar);
    if (!ref.error.empty()) return expansion_error(std::move(ref.error));
    const char* value = std::getenv(ref.name.c_str());
    if (value == nullptr) return expansion_error("environment variable " + ref.name + " is not set");
    out.text.append(value);
    if (*value != '\0') out.secrets.emplace_back(value);
    pos = ref.end;
  }
  if (pos < text.size()) out.text.append(text.substr(pos));
  return out;
}

std::string redact_secrets(std::string text, const std::vector<std::string>& secrets) {
  for (const std::string& secret : secrets) {
    if (secret.empty()) continue;
    for (std::size_t at = text.find(secret); at != std::string::npos; at = text.find(secret, at + 3)) {
      text.replace(at, secret.size(), "***");
    }
  }
  return text;
}

UrlTemplate::UrlTemplate(std::string_view text, std::string_view subdomains)
    : text_(text), subdomains_(split_subdomains(subdomains)) {
  auto fail = [&](const std::string& what) { throw SourceError("URL template \"" + text_ + "\": " + what); };
  if (!starts_with_ignoring_case(text, "http://") && !starts_with_ignoring_case(text, "https://")) {
    fail("not an http:// or https:// URL");
  }
  bool has_zoom = false, has_column = false, has_row = false, has_subdomain = false;
  std::string literal;
  auto flush_literal = [&] {
    if (!literal.empty()) parts_.push_back({PartKind::literal, std::move(literal)});
    literal.clear();
  };
  std::size_t pos = 0;
  while (pos < text.size()) {
    const char c = text[pos];
    if (c == '$' && pos + 1 < text.size() && text[pos + 1] == '{') {
      VariableRef ref = parse_variable(text, pos);
      if (!ref.error.empty()) fail(ref.error);
      flush_literal();
      bool known = false;
      for (const std::string& name : variables_) known = known || name == ref.name;
      if (!known) variables_.push_back(ref.name);
      parts_.push_back({PartKind::variable, std::move(ref.name)});
      pos = ref.end;
    } else if (c == '{') {
      const std::size_t close = text.find('}', pos);
      const std::size_t next_open = text.find('{', pos + 1);
      if (close == std::string_view::npos || (next_open != std::string_view::npos && next_open < close)) {
        fail("unclosed { at column " + std::to_string(pos + 1));
      }
      const std::string_view name = text.substr(pos + 1, close - pos - 1);
      PartKind kind = PartKind::literal;
      if (name == "z") {
        kind = PartKind::zoom;
        has_zoom = true;
      } else if (name == "x") {
        kind = PartKind::column;
        has_column = true;
      } else if (name == "y" || name == "-y") {
        kind = name == "y" ? PartKind::row_xyz : PartKind::row_tms;
        has_row = true;
      } else if (name == "s") {
        kind = PartKind::subdomain;
        has_subdomain = true;
      } else {
        fail("unknown placeholder {" + std::string(name) + "} at column " + std::to_string(pos + 1) +
             " (known: {z} {x} {y} {-y} {s}, and ${VAR} for environment variables)");
      }
      flush_literal();
      parts_.push_back({kind, {}});
      pos = close + 1;
    } else if (c == '}') {
      fail("unmatched } at column " + std::to_string(pos + 1));
    } else {
      literal.push_back(c);
      ++pos;
    }
  }
  flush_literal();
  if (!has_zoom) fail("no {z} placeholder");
  if (!has_column) fail("no {x} placeholder");
  if (!has_row) fail("no {y} or {-y} placeholder");
  if (has_subdomain && subdomains_.empty()) fail("uses {s} but the subdomain list is empty");
}

ExpandedText UrlTemplate::url_for(const TileId& tile) const {
  const std::string where = text_ + " " + to_string(tile) + ": ";
  const std::optional<std::uint32_t> tms_row = tms_y(tile);
  if (!tms_row) return expansion_error(where + "not a valid tile id");
  ExpandedText out;
  for (const Part& part : parts_) {
    switch (part.kind) {
      case PartKind::literal:
        out.text += part.text;
        break;
      case PartKind::zoom:
        out.text += std::to_string(tile.zoom);
        break;
      case PartKind::column:
        out.text += std::to_string(tile.x);
        break;
      case PartKind::row_xyz:
        out.text += std::to_string(tile.y);
        break;
      case PartKind::row_tms:
        out.text += std::to_string(*tms_row);
        break;
      case PartKind::subdomain:
        // Leaflet's choice, (x + y) mod n: neighbouring tiles alternate hosts, and a tile always
        // goes to the same one.
        out.text += subdomains_[(std::uint64_t{tile.x} + tile.y) % subdomains_.size()];
        break;
      case PartKind::variable: {
        const char* value = std::getenv(part.text.c_str());
        if (value == nullptr) return expansion_error(where + "environment variable " + part.text + " is not set");
        out.text += value;
        if (*value != '\0') out.secrets.emplace_back(value);
        break;
      }
    }
  }
  return out;
}

}  // namespace trailray::terrain
