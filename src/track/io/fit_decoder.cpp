#include "track/io/fit_decoder.hpp"

#include <array>
#include <cstdio>

#include "track/io/fit_profile.hpp"

namespace trailray::track::fit {
namespace {

constexpr std::size_t kMinHeader = 12;
constexpr std::uint8_t kCompressedHeader = 0x80;
constexpr std::uint8_t kDefinitionHeader = 0x40;
constexpr std::uint8_t kDeveloperDataFlag = 0x20;

SourcePosition at(std::size_t offset) { return SourcePosition{0, 0, static_cast<std::int64_t>(offset)}; }

std::string hex(unsigned v, int digits) {
  char buf[16];
  std::snprintf(buf, sizeof buf, "0x%0*X", digits, v);
  return buf;
}

std::uint16_t le16(std::string_view b, std::size_t i) {
  return static_cast<std::uint16_t>(static_cast<std::uint8_t>(b[i]) | static_cast<std::uint8_t>(b[i + 1]) << 8);
}

std::uint32_t le32(std::string_view b, std::size_t i) {
  return static_cast<std::uint32_t>(le16(b, i)) | static_cast<std::uint32_t>(le16(b, i + 2)) << 16;
}

struct FieldDefinition {
  std::uint8_t number = 0;
  std::uint8_t size = 0;
  std::uint8_t base_type = 0;
};

struct Definition {
  bool defined = false;
  bool big_endian = false;
  std::uint16_t global = 0;
  std::vector<FieldDefinition> fields;
  std::size_t developer_fields = 0;
  std::size_t size = 0;  // bytes of a data message: its fields and its developer fields
};

// Decodes the messages of one FIT file of the chain: [begin, end) of `bytes`.
class MessageDecoder {
 public:
  MessageDecoder(std::string_view bytes, WarningCollector& warnings, DecodeStats& stats,
                 const std::function<void(const Message&)>& on_message)
      : bytes_(bytes), warnings_(warnings), stats_(stats), on_message_(on_message) {}

  void run(std::size_t begin, std::size_t end) {
    end_ = end;
    std::size_t p = begin;
    while (p < end_) {
      const auto header = static_cast<std::uint8_t>(bytes_[p]);
      bool ok = false;
      if (header & kCompressedHeader)
        ok = data_message(p, (header >> 5) & 0x3, header & 0x1F);
      else if (header & kDefinitionHeader)
        ok = definition(p, header & 0x0F, (header & kDeveloperDataFlag) != 0);
      else
        ok = data_message(p, header & 0x0F, -1);
      if (!ok) return;
    }
  }

 private:
  // False (with a warning) when [p, p + n) is not inside this file's data.
  bool available(std::size_t start, std::size_t p, std::size_t n, const char* what) {
    if (p + n <= end_) return true;
    if (end_ == bytes_.size()) {
      stats_.cut = true;
      warnings_.add_single(at(start),
                           std::string("file cut inside a ") + what + ": the complete messages before it are kept");
    } else {
      warnings_.add_single(at(start), std::string("a ") + what + " runs past the end of the FIT data (byte " +
                                          std::to_string(end_) + "): the rest of this FIT file is skipped");
    }
    return false;
  }

  bool definition(std::size_t& p, unsigned local, bool developer) {
    const std::size_t start = p;
    if (!available(start, p + 1, 5, "definition message")) return false;
    const auto architecture = static_cast<std::uint8_t>(bytes_[p + 2]);
    if (architecture > 1) {
      // Every valid definition says 0 or 1: anything else means the framing is lost (in the
      // lezyne sample the bytes after the activity message are the remains of an older
      // recording). Reading on would take garbage for definitions and data, so this FIT file
      // ends here, keeping what came before (gpsbabel's recovery mode does the same).
      warnings_.add_single(at(start + 2), "definition message with architecture byte " + hex(architecture, 2) +
                                              " (neither 0, little-endian, nor 1, big-endian): the message framing "
                                              "is lost; the rest of this FIT file is skipped");
      return false;
    }
    const bool big_endian = architecture == 1;
    const auto lo = static_cast<std::uint8_t>(bytes_[p + 3]), hi = static_cast<std::uint8_t>(bytes_[p + 4]);
    const std::uint16_t global =
        big_endian ? static_cast<std::uint16_t>(lo << 8 | hi) : static_cast<std::uint16_t>(hi << 8 | lo);
    const std::size_t count = static_cast<std::uint8_t>(bytes_[p + 5]);
    p += 6;
    if (!available(start, p, count * 3, "definition message")) return false;
    Definition def;
    def.big_endian = big_endian;
    def.global = global;
    def.fields.reserve(count);
    for (std::size_t i = 0; i < count; ++i, p += 3) {
      FieldDefinition f{static_cast<std::uint8_t>(bytes_[p]), static_cast<std::uint8_t>(bytes_[p + 1]),
                        static_cast<std::uint8_t>(bytes_[p + 2])};
      const std::size_t type_size = base_type_size(f.base_type);
      if (type_size == 0 || f.size % type_size != 0 || f.size == 0) {
        ++stats_.mismatched_fields;
        warnings_.add("fit-field-size", at(p),
                      "field " + std::to_string(f.number) + " of message " + std::to_string(global) + " has size " +
                          std::to_string(f.size) + ", no multiple of its base type " + hex(f.base_type, 2) +
                          ": its bytes are skipped");
      }
      def.size += f.size;
      def.fields.push_back(f);
    }
    if (developer) {
      if (!available(start, p, 1, "definition message")) return false;
      def.developer_fields = static_cast<std::uint8_t>(bytes_[p]);
      ++p;
      if (!available(start, p, def.developer_fields * 3, "definition message")) return false;
      for (std::size_t i = 0; i < def.developer_fields; ++i, p += 3)
        def.size += static_cast<std::uint8_t>(bytes_[p + 1]);
    }
    def.defined = true;
    definitions_[local] = std::move(def);
    return true;
  }

  // `time_offset` is the 5-bit offset of a compressed-timestamp header, -1 for a normal one.
  bool data_message(std::size_t& p, unsigned local, int time_offset) {
    const std::size_t start = p;
    const Definition& def = definitions_[local];
    if (!def.defined) {
      // Without a definition the message's length is unknown: nothing after it can be framed.
      warnings_.add_single(at(start), "data message of local type " + std::to_string(local) +
                                          ", which has no definition: the rest of this FIT file is skipped");
      return false;
    }
    ++p;
    if (!available(start, p, def.size, "data message")) return false;
    Message m;
    m.global = def.global;
    m.big_endian = def.big_endian;
    m.offset = static_cast<std::int64_t>(start);
    m.file = stats_.files - 1;
    m.fields.reserve(def.fields.size());
    for (const FieldDefinition& f : def.fields) {
      m.fields.push_back(Field{f.number, f.base_type, bytes_.substr(p, f.size)});
      p += f.size;
    }
    p = start + 1 + def.size;  // developer fields: skipped
    stats_.developer_fields += def.developer_fields;
    if (time_offset >= 0) {
      // The offset is the low five bits of the time; the rest comes from the last full
      // timestamp, rolling over when the offset is below the last time's low bits.
      ++stats_.compressed_headers;
      const auto offset = static_cast<std::uint32_t>(time_offset);
      std::uint32_t t = (last_timestamp_ & ~std::uint32_t{0x1F}) + offset;
      if (offset < (last_timestamp_ & 0x1F)) t += 0x20;
      last_timestamp_ = t;
      m.timestamp = t;
    } else if (auto t = m.integer(kFieldTimestamp)) {
      last_timestamp_ = static_cast<std::uint32_t>(*t);
      m.timestamp = last_timestamp_;
    }
    ++stats_.messages;
    on_message_(m);
    return true;
  }

  std::string_view bytes_;
  WarningCollector& warnings_;
  DecodeStats& stats_;
  const std::function<void(const Message&)>& on_message_;
  std::size_t end_ = 0;
  std::array<Definition, 16> definitions_;
  std::uint32_t last_timestamp_ = 0;
};

}  // namespace

std::optional<Diagnostic> decode(std::string_view bytes, WarningCollector& warnings, DecodeStats& stats,
                                 const std::function<void(const Message&)>& on_message) {
  std::size_t pos = 0;
  while (pos < bytes.size()) {
    const std::size_t remaining = bytes.size() - pos;
    const std::size_t header_size = static_cast<std::uint8_t>(bytes[pos]);
    const bool is_header = remaining >= kMinHeader && header_size >= kMinHeader && bytes.substr(pos + 8, 4) == ".FIT";
    if (!is_header) {
      if (stats.files == 0) return Diagnostic{warnings.file(), at(pos), "not a FIT file: no '.FIT' file header"};
      warnings.add_single(at(pos), std::to_string(remaining) + " bytes after FIT file " + std::to_string(stats.files) +
                                       " are not a FIT file header: ignored");
      break;
    }
    if (header_size > remaining) {
      if (stats.files == 0) return Diagnostic{warnings.file(), at(pos), "file cut inside the FIT file header"};
      stats.cut = true;
      warnings.add_single(at(pos), "file cut inside the header of chained FIT file " + std::to_string(stats.files + 1));
      break;
    }
    ++stats.files;
    if (header_size >= 14) {
      const std::uint16_t stored = le16(bytes, pos + 12);
      const std::uint16_t computed = crc16(bytes.substr(pos, 12));
      if (stored != 0 && stored != computed)  // 0: the writer did not compute one
        warnings.add(
            "fit-header-crc", at(pos + 12),
            "FIT header CRC mismatch (stored " + hex(stored, 4) + ", computed " + hex(computed, 4) + "): data kept");
    }
    const std::size_t begin = pos + header_size;
    const std::uint32_t data_size = le32(bytes, pos + 4);
    std::size_t end = begin + data_size;
    bool cut = false;
    if (data_size == 0 && bytes.size() > begin) {
      // A writer that never finished the file (a crash, a dead battery) leaves the size 0:
      // read to the end of the input, where the data may stop in mid-message.
      warnings.add_single(at(pos + 4), "the FIT header gives no data size (an unfinished file): read to the end");
      end = bytes.size();
      cut = true;
    } else if (end > bytes.size()) {
      cut = stats.cut = true;
      warnings.add_single(at(pos + 4), "file cut: the FIT header announces " + std::to_string(end - begin) +
                                           " data bytes, " + std::to_string(bytes.size() - begin) +
                                           " are present; the complete messages are kept");
      end = bytes.size();
    }
    MessageDecoder(bytes, warnings, stats, on_message).run(begin, end);
    if (cut) break;
    if (end + 2 > bytes.size()) {
      stats.cut = true;
      warnings.add_single(at(end), "file cut: the FIT file CRC is missing");
      break;
    }
    const std::uint16_t stored = le16(bytes, end);
    const std::uint16_t computed = crc16(bytes.substr(pos, end - pos));
    if (stored != computed)
      warnings.add("fit-file-crc", at(end),
                   "FIT file CRC mismatch (stored " + hex(stored, 4) + ", computed " + hex(computed, 4) +
                       "): the data is kept as read");
    pos = end + 2;
  }
  if (stats.files == 0) return Diagnostic{warnings.file(), at(0), "file is empty"};
  return std::nullopt;
}

}  // namespace trailray::track::fit
