#include "track/io/byte_source.hpp"

#include <zlib.h>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>
#include <algorithm>
#include <cerrno>
#include <cstring>

namespace trailray::track {
namespace {

class GzFileSource final : public ByteSource {
 public:
  GzFileSource(gzFile f, std::string path, std::string name) : ByteSource(std::move(path), std::move(name)), file_(f) {
    gzbuffer(file_, 256 * 1024);
  }
  ~GzFileSource() override { gzclose(file_); }

  std::ptrdiff_t read(char* out, std::size_t max) override {
    int n = gzread(file_, out, static_cast<unsigned>(std::min<std::size_t>(max, 1u << 30)));
    if (n < 0) {
      int code = 0;
      const char* msg = gzerror(file_, &code);
      error_ = code == Z_ERRNO ? std::strerror(errno) : (msg ? msg : "read error");
      if (code == Z_DATA_ERROR) error_ = "corrupt gzip data (" + error_ + ")";
      return -1;
    }
    // A gzip stream cut short ends like a plain file; the format reader then sees the cut.
    return n;
  }
  std::string error() const override { return error_; }

 private:
  gzFile file_;
  std::string error_;
};

// One read() (offset < 0) or pread() at `offset`, retried when a signal interrupts it.
std::ptrdiff_t read_fd(int fd, char* out, std::size_t max, std::int64_t offset, std::string& error) {
  for (;;) {
    const ssize_t n = offset < 0 ? ::read(fd, out, max) : ::pread(fd, out, max, offset);
    if (n >= 0) return n;
    if (errno == EINTR) continue;
    error = std::strerror(errno);
    return -1;
  }
}

// Bytes [begin, end) of an open file, through pread: parts of one file read independently.
class FileRangeSource final : public ByteSource {
 public:
  FileRangeSource(std::shared_ptr<const int> fd, std::int64_t begin, std::int64_t end, const std::string& path)
      : ByteSource(path, path), fd_(std::move(fd)), at_(begin), end_(end) {}

  std::ptrdiff_t read(char* out, std::size_t max) override {
    const std::size_t want = static_cast<std::size_t>(std::max<std::int64_t>(
        0, std::min<std::int64_t>(end_ - at_, static_cast<std::int64_t>(std::min<std::size_t>(max, 1u << 30)))));
    if (want == 0) return 0;
    const std::ptrdiff_t n = read_fd(*fd_, out, want, at_, error_);
    if (n > 0) at_ += n;
    return n;
  }
  std::string error() const override { return error_; }

 private:
  std::shared_ptr<const int> fd_;
  std::int64_t at_, end_;
  std::string error_;
};

// A plain (uncompressed) file: read() straight into the caller's buffer, without zlib's
// pass-through copy.
class PlainFileSource final : public ByteSource {
 public:
  PlainFileSource(int fd, std::string path)
      : ByteSource(path, path), fd_(new int(fd), [](const int* f) {
          close(*f);
          delete f;
        }) {}

  std::int64_t size() const override {
    struct stat st {};
    return fstat(*fd_, &st) == 0 && S_ISREG(st.st_mode) ? static_cast<std::int64_t>(st.st_size) : -1;
  }
  std::unique_ptr<ByteSource> range(std::int64_t begin, std::int64_t end) const override {
    return std::make_unique<FileRangeSource>(fd_, begin, end, path());
  }

  std::ptrdiff_t read(char* out, std::size_t max) override { return read_fd(*fd_, out, max, -1, error_); }
  std::string error() const override { return error_; }

 private:
  std::shared_ptr<const int> fd_;  // closed once this source and every range of it are gone
  std::string error_;
};

class MemorySource final : public ByteSource {
 public:
  MemorySource(std::string data, std::string name) : ByteSource(name, name), data_(std::move(data)) {}
  std::ptrdiff_t read(char* out, std::size_t max) override {
    std::size_t n = std::min(max, data_.size() - pos_);
    std::memcpy(out, data_.data() + pos_, n);
    pos_ += n;
    return static_cast<std::ptrdiff_t>(n);
  }
  std::string error() const override { return {}; }  // memory never fails to read

 private:
  std::string data_;
  std::size_t pos_ = 0;
};

bool is_gzip(const std::string& d) {
  return d.size() >= 2 && static_cast<unsigned char>(d[0]) == 0x1f && static_cast<unsigned char>(d[1]) == 0x8b;
}

// Decompresses as much as `in` holds: a stream cut short keeps what came before the cut, and
// the format reader then reports the cut.
std::string gunzip(const std::string& in) {
  std::string out;
  z_stream zs{};
  if (inflateInit2(&zs, 16 + MAX_WBITS) != Z_OK) return out;
  zs.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(in.data()));
  zs.avail_in = static_cast<uInt>(in.size());
  char buf[65536];
  int rc = Z_OK;
  while (rc == Z_OK) {
    zs.next_out = reinterpret_cast<Bytef*>(buf);
    zs.avail_out = sizeof buf;
    rc = inflate(&zs, Z_NO_FLUSH);
    out.append(buf, sizeof buf - zs.avail_out);
    if (rc == Z_BUF_ERROR && zs.avail_in == 0) break;  // cut short: keep what we have
  }
  inflateEnd(&zs);
  return out;
}

}  // namespace

std::unique_ptr<ByteSource> ByteSource::open(const std::string& path, std::string& error) {
  if (path == "-") {
    int fd = dup(STDIN_FILENO);
    gzFile f = fd >= 0 ? gzdopen(fd, "rb") : nullptr;
    if (!f) {
      error = "cannot read standard input";
      if (fd >= 0) close(fd);
      return nullptr;
    }
    return std::unique_ptr<ByteSource>(new GzFileSource(f, path, "<stdin>"));
  }
  struct stat st {};
  if (stat(path.c_str(), &st) == 0 && S_ISDIR(st.st_mode)) {
    error = "is a directory";
    return nullptr;
  }
  int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) {
    error = std::strerror(errno);
    return nullptr;
  }
  unsigned char magic[2] = {0, 0};
  if (pread(fd, magic, 2, 0) == 2 && !(magic[0] == 0x1f && magic[1] == 0x8b))
    return std::unique_ptr<ByteSource>(new PlainFileSource(fd, path));
  gzFile f = gzdopen(fd, "rb");
  if (!f) {
    close(fd);
    error = "cannot open";
    return nullptr;
  }
  return std::unique_ptr<ByteSource>(new GzFileSource(f, path, path));
}

std::unique_ptr<ByteSource> ByteSource::from_memory(std::string data, std::string display_name) {
  if (is_gzip(data)) data = gunzip(data);
  return std::unique_ptr<ByteSource>(new MemorySource(std::move(data), std::move(display_name)));
}

std::string_view ByteSource::peek(std::size_t n) {
  while (peeked_.size() - peeked_pos_ < n) {
    char buf[4096];
    std::ptrdiff_t got = read(buf, std::min(sizeof buf, n - (peeked_.size() - peeked_pos_)));
    if (got <= 0) break;
    peeked_.append(buf, static_cast<std::size_t>(got));
  }
  std::string_view v(peeked_);
  v.remove_prefix(peeked_pos_);
  return v.substr(0, n);
}

std::ptrdiff_t ByteSource::next(char* out, std::size_t max) {
  if (peeked_pos_ < peeked_.size()) {
    std::size_t n = std::min(max, peeked_.size() - peeked_pos_);
    std::memcpy(out, peeked_.data() + peeked_pos_, n);
    peeked_pos_ += n;
    if (peeked_pos_ == peeked_.size()) {
      peeked_.clear();
      peeked_pos_ = 0;
    }
    return static_cast<std::ptrdiff_t>(n);
  }
  return read(out, max);
}

bool LineReader::fill() {
  if (eof_) return false;
  if (pos_ > 0) {
    consumed_ += static_cast<std::int64_t>(pos_);
    buf_.erase(0, pos_);
    pos_ = 0;
  }
  char chunk[65536];
  std::ptrdiff_t n = src_.next(chunk, sizeof chunk);
  if (n < 0) failed_ = true;
  if (n <= 0) {
    eof_ = true;
    return false;
  }
  buf_.append(chunk, static_cast<std::size_t>(n));
  return true;
}

bool LineReader::next(std::string_view& line) {
  current_.clear();
  cut_ = false;
  unterminated_ = false;
  line_offset_ = consumed_ + static_cast<std::int64_t>(pos_);
  bool any = false;
  for (;;) {
    if (pos_ >= buf_.size() && !fill()) {
      if (!any) return false;
      unterminated_ = true;
      break;
    }
    any = true;
    // A plain scan: libstdc++'s find_first_of calls memchr once per byte scanned.
    std::size_t end = std::string::npos;
    for (std::size_t k = pos_; k < buf_.size(); ++k) {
      if (buf_[k] == '\n' || buf_[k] == '\r') {
        end = k;
        break;
      }
    }
    std::size_t stop = end == std::string::npos ? buf_.size() : end;
    std::size_t room = max_line_ > current_.size() ? max_line_ - current_.size() : 0;
    if (stop - pos_ > room) cut_ = true;
    current_.append(buf_, pos_, std::min(stop - pos_, room));
    if (end == std::string::npos) {
      pos_ = buf_.size();
      continue;
    }
    pos_ = end + 1;
    if (buf_[end] == '\r') {
      if (pos_ >= buf_.size()) fill();
      if (pos_ < buf_.size() && buf_[pos_] == '\n') ++pos_;
    }
    break;
  }
  ++line_no_;
  line = current_;
  return true;
}

}  // namespace trailray::track
