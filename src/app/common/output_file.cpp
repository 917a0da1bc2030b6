#include "app/common/output_file.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <stdexcept>

namespace trailray::app {
namespace {

std::runtime_error failure(const std::string& output, const std::string& why, int error = 0) {
  return std::runtime_error(output + ": " + why + (error != 0 ? std::string(": ") + std::strerror(error) : ""));
}

// A name in the target's folder that no other writer (another process, or this one) uses.
std::filesystem::path temporary_path(const std::filesystem::path& target) {
  static std::atomic<unsigned> counter{0};
  std::filesystem::path p = target;
  p.replace_filename("." + target.filename().string() + ".tmp-" + std::to_string(::getpid()) + "-" +
                     std::to_string(counter++));
  return p;
}

}  // namespace

void check_output_path(const std::string& output, const std::vector<std::string>& inputs, bool force) {
  struct stat out {};
  if (::stat(output.c_str(), &out) != 0) return;  // nothing there yet (or unreachable: writing will say)
  for (const std::string& in : inputs) {
    struct stat st {};
    if (in != "-" && ::stat(in.c_str(), &st) == 0 && st.st_dev == out.st_dev && st.st_ino == out.st_ino)
      throw failure(output, "is the input file " + in + " (trailray never modifies its input)");
  }
  if (S_ISDIR(out.st_mode)) throw failure(output, "is a folder, not a file");
  if (S_ISREG(out.st_mode) && !force) throw failure(output, "already exists (--force replaces it)");
}

void write_file_atomically(const std::string& output, const std::function<void(std::ostream&)>& write) {
  const std::filesystem::path target(output);
  struct stat st {};
  if (::stat(output.c_str(), &st) == 0 && !S_ISREG(st.st_mode) && !S_ISDIR(st.st_mode)) {
    // /dev/null, a named pipe, a terminal: written into, never renamed over (that would replace
    // the device itself).
    std::ofstream stream(target, std::ios::binary);
    if (!stream) throw failure(output, "cannot open for writing", errno);
    write(stream);
    stream.flush();
    if (!stream) throw failure(output, "cannot write", errno);
    return;
  }
  const std::filesystem::path temporary = temporary_path(target);
  const int fd = ::open(temporary.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
  if (fd < 0) throw failure(output, "cannot create a temporary file in its folder", errno);
  ::close(fd);
  auto remove_temporary = [&temporary] { ::unlink(temporary.c_str()); };
  try {
    {
      std::ofstream stream(temporary, std::ios::binary | std::ios::trunc);
      if (!stream) throw failure(output, "cannot open the temporary file", errno);
      write(stream);
      stream.flush();
      if (!stream) throw failure(output, "cannot write (disk full?)", errno);
    }
    replace_with_temporary(temporary.string(), output);
  } catch (...) {
    remove_temporary();
    throw;
  }
}

std::string temporary_path_next_to(const std::string& output) {
  return temporary_path(std::filesystem::path(output)).string();
}

void replace_with_temporary(const std::string& temporary, const std::string& output) {
  try {
    // The data on disk before the name points at it, so a crash cannot leave an empty file.
    const int sync_fd = ::open(temporary.c_str(), O_RDONLY | O_CLOEXEC);
    if (sync_fd < 0 || ::fsync(sync_fd) != 0) {
      const int error = errno;
      if (sync_fd >= 0) ::close(sync_fd);
      throw failure(output, "cannot flush the temporary file to disk", error);
    }
    ::close(sync_fd);
    if (::rename(temporary.c_str(), output.c_str()) != 0)
      throw failure(output, "cannot rename the temporary file over it", errno);
  } catch (...) {
    ::unlink(temporary.c_str());
    throw;
  }
}

}  // namespace trailray::app
