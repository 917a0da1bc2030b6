#pragma once
// Garmin FIT decoding below the profile: file headers and CRCs, chained files, definition
// and data messages with their local message types, both byte orders, compressed-timestamp
// headers and developer fields (skipped by size). Data messages reach a callback as raw
// fields; what they mean is the caller's business (fit_reader.cpp).
//
// Damage is never fatal past the first header: a CRC mismatch is a warning and the data
// stays; a cut file or a message that cannot be framed ends decoding with a warning, keeping
// every complete message before it.

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "track/diagnostics.hpp"

namespace trailray::track::fit {

// One field of a data message: its bytes as stored (byte order of its definition).
struct Field {
  std::uint8_t number = 0;
  std::uint8_t base_type = 0;  // the base type byte of the definition (0x84 = uint16, ...)
  std::string_view bytes;
};

struct Message {
  std::uint16_t global = 0;
  bool big_endian = false;
  std::int64_t offset = 0;  // byte offset of the record header in the input
  int file = 0;             // which FIT file of a chain (0 = the first)
  std::vector<Field> fields;
  // The message's time: its timestamp field (253) or a compressed-timestamp header.
  std::optional<std::uint32_t> timestamp;

  const Field* find(std::uint8_t number) const;
  // The first element of an integer field; nullopt when absent, invalid (0xFF.., 0x7F.., 0 for
  // the z types), not an integer type, or stored in a size that is no multiple of its type.
  std::optional<std::int64_t> integer(std::uint8_t number) const;
  // Like integer(), also for float32/float64 fields.
  std::optional<double> number(std::uint8_t number) const;
  // A string field up to its first NUL; empty when absent or invalid.
  std::string text(std::uint8_t number) const;
};

struct DecodeStats {
  int files = 0;                       // FIT files in the chain that had a valid header
  std::size_t messages = 0;            // data messages delivered
  std::size_t compressed_headers = 0;  // data messages with a compressed-timestamp header
  std::size_t developer_fields = 0;    // developer fields skipped (in data messages)
  std::size_t mismatched_fields = 0;   // fields whose size is no multiple of their base type
  bool cut = false;                    // the input ended inside a file or a message
};

// Decodes `bytes` (a whole FIT file, or several chained). Warnings go to `warnings` with byte
// offsets; an unreadable first header is returned as the error message (nullopt when the
// input is a FIT file). `on_message` sees every data message in file order.
std::optional<Diagnostic> decode(std::string_view bytes, WarningCollector& warnings, DecodeStats& stats,
                                 const std::function<void(const Message&)>& on_message);

// The FIT CRC-16 (polynomial 0xA001, reflected) of `bytes`, continuing from `crc`.
std::uint16_t crc16(std::string_view bytes, std::uint16_t crc = 0);

// Size in bytes of a base type (low five bits of the base type byte); 0 when unknown.
std::size_t base_type_size(std::uint8_t base_type);

}  // namespace trailray::track::fit
