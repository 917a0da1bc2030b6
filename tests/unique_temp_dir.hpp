#pragma once
// A fresh folder under the system's temporary folder whose name no other process can hold.
//
// Why not the process id: under node (the WebAssembly tests) every process's getpid() is 42, so
// two test processes that ctest runs side by side made the same "name-42-0" folder and wrote over
// each other's files. mkdtemp creates the folder itself and retries on a name already taken.

#include <stdlib.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <stdexcept>
#include <string>

namespace trailray::test {

inline std::filesystem::path make_unique_temp_dir(const std::string& prefix) {
  std::string pattern = (std::filesystem::temp_directory_path() / (prefix + "XXXXXX")).string();
  if (::mkdtemp(pattern.data()) == nullptr)
    throw std::runtime_error("cannot make a temporary folder " + pattern + ": " + std::strerror(errno));
  return pattern;
}

}  // namespace trailray::test
