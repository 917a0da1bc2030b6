// KMZ reader: a zip archive of KML documents (Google Earth's packaging, with images beside
// them). Google Earth reads doc.kml when the archive has one; archives written by other tools
// name their KML otherwise, or hold several, so without a doc.kml every .kml entry is read, in
// the archive's order, into one file. Diagnostics name the entry: "x.kmz:track1.kml:12:5: ...".

#include <algorithm>
#include <cctype>
#include <string>
#include <vector>

#include "track/io/kml_document.hpp"
#include "track/io/readers.hpp"
#include "track/io/zip_archive.hpp"

namespace trailray::track {
namespace {

std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return s;
}

// A KML entry, not a folder nor the resource fork macOS adds beside each file
// ("__MACOSX/._doc.kml").
bool is_kml_entry(const std::string& name) {
  const std::string l = lower(name);
  if (!l.ends_with(".kml") || l.starts_with("__macosx/")) return false;
  const std::size_t slash = l.rfind('/');
  return l.compare(slash == std::string::npos ? 0 : slash + 1, 2, "._") != 0;
}

// The entries to read: doc.kml alone when the archive has one at its root, else every KML.
std::vector<std::size_t> kml_entries(const std::vector<std::string>& names) {
  std::vector<std::size_t> chosen;
  for (std::size_t i = 0; i < names.size(); ++i) {
    if (lower(names[i]) == "doc.kml") return {i};
    if (is_kml_entry(names[i])) chosen.push_back(i);
  }
  return chosen;
}

std::string listed(const std::vector<std::string>& names) {
  std::string s;
  for (std::size_t i = 0; i < names.size() && i < 5; ++i) s += (i ? ", " : "") + names[i].substr(0, 60);
  if (names.size() > 5) s += ", ...";
  return s;
}

// The whole archive: a zip is read from its end (the central directory), and the source may be
// a stream. False with `error` set on a read error or an archive over `limit` bytes.
bool read_all(ByteSource& source, std::int64_t limit, std::string& bytes, std::string& error) {
  std::vector<char> chunk(1 << 16);  // on the heap: WebAssembly stacks are small
  for (;;) {
    const std::ptrdiff_t n = source.next(chunk.data(), chunk.size());
    if (n < 0) {
      error = "cannot read: " + source.error();
      return false;
    }
    if (n == 0) return true;
    bytes.append(chunk.data(), static_cast<std::size_t>(n));
    if (static_cast<std::int64_t>(bytes.size()) > limit) {
      error = "archive larger than " + std::to_string(limit >> 20) + " MiB: not read";
      return false;
    }
  }
}

}  // namespace

ReadResult read_kmz(ByteSource& source, const ReadOptions& options) {
  ReadResult result;
  result.file.format = Format::Kmz;
  const std::string& file = source.display_name();
  std::string bytes, error;
  if (!read_all(source, options.kmz_max_bytes, bytes, error)) {
    result.error = Diagnostic{file, {}, error};
    return result;
  }
  std::unique_ptr<ZipArchive> archive = ZipArchive::open(std::move(bytes), options.kmz_max_bytes, error);
  if (!archive) {
    result.error = Diagnostic{file, {}, "not a readable zip archive (KMZ cut short or damaged?): " + error};
    return result;
  }
  const std::vector<std::string>& names = archive->entry_names();
  const std::vector<std::size_t> entries = kml_entries(names);
  if (entries.empty()) {
    result.error = Diagnostic{file,
                              {},
                              "no KML document inside the KMZ archive (" + std::to_string(names.size()) + " entries" +
                                  (names.empty() ? "" : ": " + listed(names)) + ")"};
    return result;
  }
  for (std::size_t index : entries) {
    const std::string entry_name = file + ":" + names[index];
    std::unique_ptr<ByteSource> entry = archive->open_entry(index, entry_name, error);
    if (!entry) {
      result.error = Diagnostic{entry_name, {}, "cannot read the entry: " + error};
      break;
    }
    WarningCollector warnings(entry_name);
    KmlDocumentRead read = read_kml_document(*entry, result.file, warnings);
    ReadResult entry_result;
    record_xml_outcome(read.outcome, read.complete_points, entry_result, warnings);
    for (Diagnostic& d : warnings.diagnostics()) result.warnings.push_back(std::move(d));
    if (entry_result.error) {
      result.error = std::move(entry_result.error);
      break;
    }
  }
  // As finish_read does for one collector: --strict turns the first warning into the error.
  if (options.strict && !result.error && !result.warnings.empty()) {
    result.error = result.warnings.front();
    result.error->message += " (--strict)";
  }
  return result;
}

}  // namespace trailray::track
