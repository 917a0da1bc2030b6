#pragma once
// A zip archive held in memory and read through libzip (for KMZ): the names of its entries, and
// an entry's bytes as a ByteSource that decompresses while it is read. The entries read from one
// archive share a budget of decompressed bytes, counted as they come (the sizes an archive
// declares are not trusted), so a zip bomb ends in a read error instead of filling memory.

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "track/io/byte_source.hpp"

struct zip;  // libzip's zip_t, kept out of this header

namespace trailray::track {

class ZipArchive {
 public:
  // The archive in `bytes`; nullptr with `error` set when it is not a readable zip archive.
  static std::unique_ptr<ZipArchive> open(std::string bytes, std::int64_t decompressed_budget, std::string& error);
  ~ZipArchive();
  ZipArchive(const ZipArchive&) = delete;
  ZipArchive& operator=(const ZipArchive&) = delete;

  // The entries' names in the archive's order (folders end in '/').
  const std::vector<std::string>& entry_names() const { return names_; }

  // Entry `index` as a source named `display_name`; nullptr with `error` set when it cannot be
  // opened (encrypted, unknown compression). The source must not outlive the archive. Its read()
  // fails once the archive's entries together have given more than the budget, and on a
  // damaged entry (libzip checks each entry's CRC at its end).
  std::unique_ptr<ByteSource> open_entry(std::size_t index, std::string display_name, std::string& error);

 private:
  ZipArchive() = default;

  std::string bytes_;  // the buffer libzip reads from
  ::zip* zip_ = nullptr;
  std::vector<std::string> names_;
  std::int64_t budget_ = 0;
  std::int64_t used_ = 0;  // decompressed bytes handed out by all entries so far
};

}  // namespace trailray::track
