#pragma once
// Helpers shared by the tests: where the real data lives, temporary files.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "unique_temp_dir.hpp"

namespace trailray::test {

inline std::filesystem::path shared_data() { return std::filesystem::path(TRAILRAY_SHARED_DATA); }

// Path of a file under ../shared/data, or skips the current test with a clear message.
#define TRAILRAY_REQUIRE_DATA(var, relative)                                      \
  const std::filesystem::path var = ::trailray::test::shared_data() / (relative); \
  if (!std::filesystem::exists(var))                                              \
    GTEST_SKIP() << "shared test data absent: " << var.string() << " (tests that read ../shared/data skip without it)";

// A file in a fresh temporary folder, removed at scope end.
class TempFile {
 public:
  explicit TempFile(const std::string& name, const std::string& content = {}) {
    dir_ = make_unique_temp_dir("trailray-test-");
    path_ = dir_ / name;
    std::ofstream(path_, std::ios::binary) << content;
  }
  ~TempFile() {
    std::error_code ec;
    std::filesystem::remove_all(dir_, ec);
  }
  TempFile(const TempFile&) = delete;
  TempFile& operator=(const TempFile&) = delete;
  const std::filesystem::path& path() const { return path_; }
  std::string str() const { return path_.string(); }

 private:
  std::filesystem::path dir_, path_;
};

}  // namespace trailray::test
