#pragma once
// URL templates of tile servers, e.g.
//   https://{s}.tile.opentopomap.org/{z}/{x}/{y}.png
//   https://api.maptiler.com/tiles/terrain-rgb-v2/{z}/{x}/{y}.webp?key=${MAPTILER_KEY}
// Placeholders: {z} {x} {y} (XYZ row), {-y} (TMS row, from the south), {s} (a subdomain from a
// list, picked from x and y so that a tile always goes to the same host and its HTTP cache).
// ${VAR} is read from the environment when a URL is built, never when the template is parsed:
// API keys stay out of configuration files, and out of every message, since messages only ever
// show display(), the template as written.

#include <string>
#include <string_view>
#include <vector>

#include "terrain/tile.hpp"

namespace trailray::terrain {

// Text with its ${VAR} references replaced from the environment, and the values that went in
// (to be kept out of messages). `error` is set (naming the variable, never a value) when a
// variable is not set; the other fields are then empty.
struct ExpandedText {
  std::string text;
  std::vector<std::string> secrets;  // the non-empty values substituted
  std::string error;
};

// Expands ${VAR} (VAR = [A-Za-z_][A-Za-z0-9_]*) from the environment; any other '$' is kept.
// An unterminated or malformed ${...} is an error too.
ExpandedText expand_environment(std::string_view text);

// `text` with every occurrence of each secret replaced by "***": the last line of defence for
// strings built from expanded text (a library's error message that quotes a URL).
std::string redact_secrets(std::string text, const std::vector<std::string>& secrets);

class UrlTemplate {
 public:
  // Throws SourceError (naming the template and the column) for a template that is not http(s),
  // lacks {z}, {x} or a row ({y} or {-y}), has an unknown or unclosed {placeholder}, a malformed
  // ${VAR}, or uses {s} with an empty subdomain list. `subdomains` is comma-separated.
  explicit UrlTemplate(std::string_view text, std::string_view subdomains = "a,b,c");

  // The template as written, ${VAR} unexpanded: the only form that may appear in messages.
  const std::string& display() const { return text_; }

  // The names of the ${VAR} references, in order of first use.
  const std::vector<std::string>& environment_variables() const { return variables_; }
  const std::vector<std::string>& subdomains() const { return subdomains_; }

  // The URL of a tile, with the environment read now. `error` (already prefixed with display()
  // and the tile) for an invalid tile id or an unset variable.
  ExpandedText url_for(const TileId& tile) const;

 private:
  enum class PartKind { literal, zoom, column, row_xyz, row_tms, subdomain, variable };
  struct Part {
    PartKind kind;
    std::string text;  // the literal, or the variable's name
  };

  std::string text_;
  std::vector<Part> parts_;
  std::vector<std::string> variables_;
  std::vector<std::string> subdomains_;
};

}  // namespace trailray::terrain
