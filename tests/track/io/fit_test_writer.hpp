#pragma once
// A tiny FIT writer for the tests: definitions in either byte order (or any architecture
// byte), data messages with normal or compressed-timestamp headers, developer fields, and
// whole files with a 12- or 14-byte header and the CRCs (which the tests can then break).
// It writes what it is told, valid or not; it knows nothing of the profile.

#include <cmath>
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "track/io/fit_decoder.hpp"

namespace trailray::test::fit {

// Base type bytes of the FIT protocol.
enum : std::uint8_t {
  kEnum = 0x00,
  kSint8 = 0x01,
  kUint8 = 0x02,
  kSint16 = 0x83,
  kUint16 = 0x84,
  kSint32 = 0x85,
  kUint32 = 0x86,
  kString = 0x07,
  kFloat32 = 0x88,
  kUint32z = 0x8C,
  kByte = 0x0D,
};

struct FieldSpec {
  std::uint8_t number;
  std::uint8_t size;
  std::uint8_t base_type;
};

// One value: an integer written in the field's size and byte order, or bytes (strings, byte
// arrays) written as given and padded with NULs to the field's size.
struct Value {
  Value(std::uint64_t v) : integer(v) {}  // NOLINT: implicit on purpose, values read as lists
  Value(unsigned v) : integer(v) {}       // NOLINT
  Value(int v) : integer(static_cast<std::uint64_t>(static_cast<std::int64_t>(v))) {}  // NOLINT
  Value(std::int64_t v) : integer(static_cast<std::uint64_t>(v)) {}                    // NOLINT
  Value(const char* s) : bytes(s), is_bytes(true) {}                                   // NOLINT
  Value(std::string s) : bytes(std::move(s)), is_bytes(true) {}                        // NOLINT
  std::uint64_t integer = 0;
  std::string bytes;
  bool is_bytes = false;
};

inline std::int64_t semicircles(double degrees) { return std::llround(degrees * 2147483648.0 / 180.0); }
inline std::uint32_t fit_time(double unix_seconds) { return static_cast<std::uint32_t>(unix_seconds - 631065600.0); }

class Writer {
 public:
  // `architecture`: 0 little-endian, 1 big-endian; anything else is written as given (and read
  // as little-endian here).
  void define(std::uint8_t local, std::uint16_t global, std::vector<FieldSpec> fields,
              std::vector<FieldSpec> developer = {}, std::uint8_t architecture = 0) {
    const bool big = architecture == 1;
    data_ += static_cast<char>(0x40 | (developer.empty() ? 0 : 0x20) | (local & 0x0F));
    data_ += '\0';
    data_ += static_cast<char>(architecture);
    put(global, 2, big);
    data_ += static_cast<char>(fields.size());
    for (const FieldSpec& f : fields) put_spec(f);
    if (!developer.empty()) {
      data_ += static_cast<char>(developer.size());
      for (const FieldSpec& f : developer) put_spec(f);  // base_type stands for the developer index
    }
    locals_[local] = Local{big, fields, developer};
  }

  // A data message with a normal header; `developer_bytes` fill the developer fields.
  void data(std::uint8_t local, const std::vector<Value>& values, const std::string& developer_bytes = {}) {
    data_ += static_cast<char>(local & 0x0F);
    put_values(local, values, developer_bytes);
  }

  // A data message with a compressed-timestamp header (local types 0-3).
  void compressed(std::uint8_t local, std::uint8_t time_offset, const std::vector<Value>& values) {
    data_ += static_cast<char>(0x80 | (local & 0x03) << 5 | (time_offset & 0x1F));
    put_values(local, values, {});
  }

  void raw(const std::string& bytes) { data_ += bytes; }

  // The file: header (14 bytes with its CRC, or 12), the messages, the file CRC.
  std::string file(bool long_header = true) const {
    std::string out;
    out += static_cast<char>(long_header ? 14 : 12);
    out += static_cast<char>(0x20);  // protocol 2.0
    append_le(out, 2132, 2);         // profile version
    append_le(out, data_.size(), 4);
    out += ".FIT";
    if (long_header) append_le(out, track::fit::crc16(out), 2);
    out += data_;
    append_le(out, track::fit::crc16(out), 2);
    return out;
  }

  std::size_t size() const { return data_.size(); }

 private:
  struct Local {
    bool big_endian = false;
    std::vector<FieldSpec> fields, developer;
  };

  static void append_le(std::string& out, std::uint64_t v, std::size_t n) {
    for (std::size_t i = 0; i < n; ++i) out += static_cast<char>(i < 8 ? (v >> (8 * i)) & 0xFF : 0);
  }
  void put(std::uint64_t v, std::size_t n, bool big) {
    for (std::size_t i = 0; i < n; ++i) {
      const std::size_t shift = 8 * (big ? n - 1 - i : i);
      data_ += static_cast<char>(shift < 64 ? (v >> shift) & 0xFF : 0);
    }
  }
  void put_spec(const FieldSpec& f) {
    data_ += static_cast<char>(f.number);
    data_ += static_cast<char>(f.size);
    data_ += static_cast<char>(f.base_type);
  }
  void put_values(std::uint8_t local, const std::vector<Value>& values, const std::string& developer_bytes) {
    const Local& l = locals_.at(local);
    for (std::size_t i = 0; i < l.fields.size(); ++i) {
      const Value v = i < values.size() ? values[i] : Value(~std::uint64_t{0});
      if (v.is_bytes)
        data_ += (v.bytes + std::string(l.fields[i].size, '\0')).substr(0, l.fields[i].size);
      else
        put(v.integer, l.fields[i].size, l.big_endian);
    }
    std::size_t developer_size = 0;
    for (const FieldSpec& f : l.developer) developer_size += f.size;
    data_ += (developer_bytes + std::string(developer_size, '\0')).substr(0, developer_size);
  }

  std::string data_;
  std::map<std::uint8_t, Local> locals_;
};

}  // namespace trailray::test::fit
