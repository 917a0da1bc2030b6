#pragma once
// Track format from the content (first bytes), falling back to the file name.

#include <optional>
#include <string>
#include <string_view>

#include "track/model.hpp"

namespace trailray::track {

// `head` is the start of the decompressed content. Returns nullopt when neither the content
// nor the name identifies a supported format.
std::optional<Format> detect_format(std::string_view head, const std::string& path);

}  // namespace trailray::track
