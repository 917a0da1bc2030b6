#include "track/io/zip_archive.hpp"

#include <zip.h>

#include <utility>

namespace trailray::track {
namespace {

class ZipEntrySource final : public ByteSource {
 public:
  ZipEntrySource(zip_file_t* file, std::string name, std::int64_t& used, std::int64_t budget)
      : ByteSource(name, name), file_(file), used_(used), budget_(budget) {}
  ~ZipEntrySource() override { zip_fclose(file_); }
  ZipEntrySource(const ZipEntrySource&) = delete;
  ZipEntrySource& operator=(const ZipEntrySource&) = delete;

  std::ptrdiff_t read(char* out, std::size_t max) override {
    if (!error_.empty()) return -1;
    const zip_int64_t n = zip_fread(file_, out, max);
    if (n < 0) {
      error_ = std::string("damaged zip entry: ") + zip_file_strerror(file_);
      return -1;
    }
    used_ += n;
    if (used_ > budget_) {
      error_ = "the archive's KML decompresses to more than " + std::to_string(budget_ >> 20) +
               " MiB (a zip bomb?): not read further";
      return -1;
    }
    return static_cast<std::ptrdiff_t>(n);
  }
  std::string error() const override { return error_; }

 private:
  zip_file_t* file_;
  std::int64_t& used_;
  std::int64_t budget_;
  std::string error_;
};

}  // namespace

std::unique_ptr<ZipArchive> ZipArchive::open(std::string bytes, std::int64_t decompressed_budget, std::string& error) {
  std::unique_ptr<ZipArchive> archive(new ZipArchive());
  archive->bytes_ = std::move(bytes);
  archive->budget_ = decompressed_budget;
  zip_error_t ze;
  zip_error_init(&ze);
  zip_source_t* source = zip_source_buffer_create(archive->bytes_.data(), archive->bytes_.size(), 0, &ze);
  if (source) {
    archive->zip_ = zip_open_from_source(source, ZIP_RDONLY, &ze);
    if (!archive->zip_) zip_source_free(source);  // on success the archive owns it
  }
  if (!archive->zip_) {
    error = zip_error_strerror(&ze);
    zip_error_fini(&ze);
    return nullptr;
  }
  zip_error_fini(&ze);
  const zip_int64_t count = zip_get_num_entries(archive->zip_, 0);
  for (zip_int64_t i = 0; i < count; ++i) {
    const char* name = zip_get_name(archive->zip_, static_cast<zip_uint64_t>(i), 0);
    archive->names_.emplace_back(name ? name : "");
  }
  return archive;
}

ZipArchive::~ZipArchive() {
  if (zip_) zip_discard(zip_);  // read-only: nothing to write back
}

std::unique_ptr<ByteSource> ZipArchive::open_entry(std::size_t index, std::string display_name, std::string& error) {
  zip_file_t* file = zip_fopen_index(zip_, index, 0);
  if (!file) {
    error = zip_strerror(zip_);
    return nullptr;
  }
  return std::make_unique<ZipEntrySource>(file, std::move(display_name), used_, budget_);
}

}  // namespace trailray::track
