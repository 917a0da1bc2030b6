#include "app/common/track_arguments.hpp"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <system_error>

#include <fmt/format.h>

namespace trailray::app {
namespace fs = std::filesystem;
namespace {

constexpr const char* kTrackExtensions = ".gpx .igc .tcx .fit .kml .kmz .geojson .json, also with .gz";

bool has_glob_characters(const std::string& s) { return s.find_first_of("*?[\\") != std::string::npos; }

// `[...]` at pattern[p] (p at '['): whether `c` is in the set; `end` gets the index past ']'.
// false with end = npos when the bracket is not closed (then '[' is an ordinary character).
bool set_matches(const std::string& pattern, std::size_t p, char c, std::size_t& end) {
  std::size_t i = p + 1;
  const bool negate = i < pattern.size() && (pattern[i] == '!' || pattern[i] == '^');
  if (negate) ++i;
  bool found = false;
  bool first = true;
  for (; i < pattern.size() && (pattern[i] != ']' || first); ++i, first = false) {
    if (i + 2 < pattern.size() && pattern[i + 1] == '-' && pattern[i + 2] != ']') {
      found = found || (pattern[i] <= c && c <= pattern[i + 2]);
      i += 2;
    } else {
      found = found || pattern[i] == c;
    }
  }
  if (i >= pattern.size()) {
    end = std::string::npos;
    return false;
  }
  end = i + 1;
  return found != negate;
}

// A display path joined as the user wrote it ("flights/a.igc", not "./flights/a.igc").
std::string joined(const std::string& base, const std::string& name) {
  if (base.empty()) return name;
  return base.back() == '/' ? base + name : base + "/" + name;
}

std::vector<std::string> sorted_listing(const std::string& folder, bool want_folders) {
  std::vector<std::string> names;
  std::error_code ec;
  fs::directory_iterator it(folder.empty() ? fs::path(".") : fs::path(folder), ec);
  if (ec) throw TrackArgumentError(fmt::format("{}: cannot list the folder: {}", folder, ec.message()));
  for (const fs::directory_entry& entry : it) {
    std::error_code type_ec;
    const bool is_folder = entry.is_directory(type_ec);
    if (want_folders || !is_folder) names.push_back(entry.path().filename().string());
  }
  std::sort(names.begin(), names.end());
  return names;
}

// The track files directly in `folder` (not hidden), sorted by name.
std::vector<std::string> folder_track_files(const std::string& folder) {
  std::vector<std::string> out;
  for (const std::string& name : sorted_listing(folder, false)) {
    std::error_code ec;
    const std::string path = joined(folder, name);
    if (name.front() != '.' && has_track_extension(name) && fs::is_regular_file(path, ec)) out.push_back(path);
  }
  return out;
}

// `base` and every folder below it (not hidden ones, nor their insides), the way `**` matches
// them; symbolic links to folders are not followed (a link to a parent would never end).
void add_folder_tree(const std::string& base, std::vector<std::string>& out) {
  out.push_back(base);
  std::error_code ec;
  if (!fs::is_directory(base.empty() ? fs::path(".") : fs::path(base), ec)) return;
  for (const std::string& name : sorted_listing(base, true)) {
    const std::string path = joined(base, name);
    if (name.front() != '.' && fs::is_directory(fs::symlink_status(path, ec))) add_folder_tree(path, out);
  }
}

// Every existing path matching the pattern, one component after the other, sorted by name.
std::vector<std::string> glob_paths(const std::string& pattern) {
  std::vector<std::string> found{""};
  std::size_t start = 0;
  if (!pattern.empty() && pattern.front() == '/') {
    found = {"/"};
    start = 1;
  }
  while (start <= pattern.size()) {
    std::size_t slash = pattern.find('/', start);
    if (slash == std::string::npos) slash = pattern.size();
    const std::string part = pattern.substr(start, slash - start);
    start = slash + 1;
    if (part.empty()) continue;  // "a//b", a trailing '/'
    std::vector<std::string> next;
    for (const std::string& base : found) {
      if (part == "**") {  // any number of folders, none included
        add_folder_tree(base, next);
        continue;
      }
      if (!has_glob_characters(part)) {
        std::error_code ec;
        const std::string path = joined(base, part);
        if (fs::exists(path, ec)) next.push_back(path);
        continue;
      }
      std::error_code ec;
      if (!fs::is_directory(base.empty() ? fs::path(".") : fs::path(base), ec)) continue;
      for (const std::string& name : sorted_listing(base, true))
        if (glob_name_matches(part, name)) next.push_back(joined(base, name));
    }
    found = std::move(next);
  }
  std::sort(found.begin(), found.end());
  found.erase(std::unique(found.begin(), found.end()), found.end());  // "**/**" reaches a folder twice
  return found;
}

void add_pattern(const std::string& pattern, std::vector<std::string>& out) {
  const std::vector<std::string> matches = glob_paths(pattern);
  if (matches.empty()) throw TrackArgumentError(fmt::format("{}: no file matches this pattern", pattern));
  const std::size_t before = out.size();
  for (const std::string& path : matches) {
    std::error_code ec;
    if (path.empty() || fs::is_directory(path, ec)) {  // "": the current folder, as `**` reaches it
      for (std::string& file : folder_track_files(path)) out.push_back(std::move(file));
    } else if (has_track_extension(fs::path(path).filename().string())) {
      out.push_back(path);
    }
  }
  if (out.size() == before)
    throw TrackArgumentError(fmt::format("{}: the pattern matches no track file ({})", pattern, kTrackExtensions));
}

}  // namespace

bool has_track_extension(const std::string& name) {
  std::string lower = name;
  for (char& c : lower) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (lower.size() > 3 && lower.ends_with(".gz")) lower.resize(lower.size() - 3);
  for (const char* ext : {".gpx", ".igc", ".tcx", ".fit", ".kml", ".kmz", ".geojson", ".json"})
    if (lower.size() > std::char_traits<char>::length(ext) && lower.ends_with(ext)) return true;
  return false;
}

bool glob_name_matches(const std::string& pattern, const std::string& name) {
  // A leading dot is only matched by a leading dot, as in a shell: `*` does not list hidden files.
  if (!name.empty() && name.front() == '.' && (pattern.empty() || pattern.front() != '.')) return false;
  std::size_t p = 0, n = 0;
  std::size_t star = std::string::npos, star_n = 0;  // the last '*' and where its run ends for now
  while (n < name.size()) {
    std::size_t set_end = 0;
    if (p < pattern.size() && pattern[p] == '*') {
      star = p++;
      star_n = n;
      continue;
    }
    if (p + 1 < pattern.size() && pattern[p] == '\\') {  // an escaped character is itself
      if (pattern[p + 1] == name[n]) {
        p += 2;
        ++n;
        continue;
      }
    } else if (p < pattern.size() && pattern[p] == '[') {
      if (set_matches(pattern, p, name[n], set_end)) {
        p = set_end;
        ++n;
        continue;
      }
      if (set_end == std::string::npos && name[n] == '[') {  // unclosed: a literal '['
        ++p;
        ++n;
        continue;
      }
    } else if (p < pattern.size() && (pattern[p] == '?' || pattern[p] == name[n])) {
      ++p;
      ++n;
      continue;
    }
    if (star == std::string::npos) return false;
    p = star + 1;  // the last '*' swallows one more character
    n = ++star_n;
  }
  while (p < pattern.size() && pattern[p] == '*') ++p;
  return p == pattern.size();
}

std::vector<std::string> expand_track_arguments(const std::vector<std::string>& arguments) {
  std::vector<std::string> out;
  for (const std::string& argument : arguments) {
    std::error_code ec;
    const fs::file_status status = argument == "-" ? fs::file_status{} : fs::status(argument, ec);
    if (fs::is_directory(status)) {
      std::vector<std::string> files = folder_track_files(argument);
      if (files.empty())
        throw TrackArgumentError(fmt::format("{}: the folder holds no track file ({})", argument, kTrackExtensions));
      for (std::string& f : files) out.push_back(std::move(f));
    } else if (argument != "-" && !fs::exists(status) && has_glob_characters(argument)) {
      add_pattern(argument, out);
    } else {
      out.push_back(argument);
    }
  }
  return out;
}

}  // namespace trailray::app
