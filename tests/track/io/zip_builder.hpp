#pragma once
// Builds zip archives in memory for the KMZ tests, through libzip's writing side.

#include <zip.h>

#include <string>
#include <utility>
#include <vector>

namespace trailray::test {

// A zip of the entries (name, content) in this order, deflated; empty on failure.
inline std::string make_zip(const std::vector<std::pair<std::string, std::string>>& entries) {
  zip_error_t error;
  zip_error_init(&error);
  zip_source_t* target = zip_source_buffer_create(nullptr, 0, 0, &error);
  if (!target) return {};
  zip_source_keep(target);  // outlives the archive: the bytes are read from it after zip_close
  zip_t* archive = zip_open_from_source(target, ZIP_TRUNCATE, &error);
  std::string bytes;
  if (archive) {
    for (const auto& [name, content] : entries) {
      zip_source_t* data = zip_source_buffer_create(content.data(), content.size(), 0, &error);
      if (!data || zip_file_add(archive, name.c_str(), data, ZIP_FL_ENC_UTF_8) < 0) zip_source_free(data);
    }
    if (zip_close(archive) == 0 && zip_source_open(target) == 0) {
      char chunk[4096];
      for (zip_int64_t n; (n = zip_source_read(target, chunk, sizeof chunk)) > 0;)
        bytes.append(chunk, static_cast<std::size_t>(n));
      zip_source_close(target);
    }
  }
  zip_source_free(target);
  zip_error_fini(&error);
  return bytes;
}

}  // namespace trailray::test
